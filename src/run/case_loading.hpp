#pragma once
// A case file -> a validated Case (cutting/case.hpp: the scene and, for a cut, its process), and a
// Case -> its expanded case text: the one place that puts the
// generic scene tables (io/scene_parser.hpp) and the cutting preset's sections
// (cutting/cutting_case.hpp) together. A case with [cutting] is expanded by the preset; any other
// is read table by table (and may carry a [cutting_process] record). docs/input.md documents every key.
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "cutting/case.hpp"
#include "io/input_error.hpp"

namespace mpmcut {

// `overrides` are the command line's --set strings, "key.path=value", applied before validation
// (io/scene_parser.hpp, parse_case_tree). Every problem is an InputError naming file:line:column.
Case load_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
Case parse_case(std::string_view toml_text, const std::string& source_name,
                const std::vector<std::string>& overrides = {});

// The scene of a cutting run's result directory, read back for the commands that work on one (analyze, plot).
// Throws InputError with the reason when `dir` is not a directory, not a result of `mpmcut run` (no summary.json
// and scene.toml), its scene.toml does not read, or it is not a cut (no [cutting_process] record: `needs_cut`
// says what needs a cut, e.g. "the chip analysis needs the cut's parameters").
Case load_cutting_result_scene(const std::filesystem::path& dir, std::string_view needs_cut);

// The built-in demo (cases/elastic_demo.toml, compiled in): an elastic disk dropped onto a
// frictionless floor, ~3k particles, a few seconds of run time. Used by `mpmcut run` without a case;
// takes --set overrides like a case file.
Case default_elastic_demo_case(const std::vector<std::string>& overrides = {});

// The default run of `mpmcut run` without a case file (cases/ti64_default.toml, compiled in):
// Ti-6Al-4V at 20 m/s, uncut chip thickness 0.1 mm.
Case default_cutting_case(const std::vector<std::string>& overrides = {});

// The expanded scene: every key explicit, with the [cutting_process] record of a cut; parses back
// to an equal Case (scene.toml of a run).
void write_scene(const Case& c, std::ostream& out);
std::string scene_text(const Case& c);

// Hash (64-bit FNV-1a) of the expanded scene as write_scene() prints it: equal for scenes that
// are equal, whatever file they came from. Checkpoints carry it (io/checkpoint.hpp).
std::uint64_t scene_hash(const Case& c);

}  // namespace mpmcut
