#pragma once
// TOML case file -> validated Scene. The one place that reads case files; docs/input.md documents
// every key. Every problem is an InputError whose message names file:line:column, the full key
// path, what is allowed and what was given.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene.hpp"
#include "io/input_error.hpp"

namespace mpmcut {

// `overrides` are the command line's --set strings, "key.path=value", applied before validation:
//   solver.cfl=0.3   body[0].velocity=[1.0, 0.0]   material[1].jc_A=1.0e9   solver.scheme=usl
// Array entries are addressed as name[i] (name.i is accepted too). The value is parsed as a TOML
// value; if it does not parse it is taken as a bare string. Keys outside the schema are errors.
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
Scene parse_scene(std::string_view toml_text, const std::string& source_name,
                  const std::vector<std::string>& overrides = {});

// The built-in demo (cases/elastic_demo.toml, compiled in): an elastic disk dropped onto a
// frictionless floor, ~3k particles, a few seconds of run time. Used by `mpmcut run` without a case;
// takes --set overrides like a case file.
Scene default_elastic_demo_scene(const std::vector<std::string>& overrides = {});

// The default run of `mpmcut run` without a case file (cases/ti64_default.toml, compiled in):
// Ti-6Al-4V at 20 m/s, uncut chip thickness 0.1 mm.
Scene default_cutting_scene(const std::vector<std::string>& overrides = {});

}  // namespace mpmcut
