#pragma once
// TOML case file -> validated Scene: the generic tables ([grid], [[material]], [[body]],
// [[rigid_body]], [solver], [output], [thermal], [boundaries]). Sections that a layer above owns
// (the cutting preset's [cutting] and [cutting_process], cutting/cutting_case.hpp) are read there,
// with the readers below; run/case_loading.hpp puts the two together and is what callers use.
// docs/input.md documents every key. Every problem is an InputError whose message names
// file:line:column, the full key path, what is allowed and what was given.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "solver/scene.hpp"
#include "io/input_error.hpp"
#include "io/toml_reader.hpp"

namespace mpmcut {

// A case file as a TOML tree, with the command line's --set strings, "key.path=value", applied
// before validation:
//   solver.cfl=0.3   body[0].velocity=[1.0, 0.0]   material[1].jc_A=1.0e9   solver.scheme=usl
// Array entries are addressed as name[i] (name.i is accepted too). The value is parsed as a TOML
// value; if it does not parse it is taken as a bare string. Keys outside the schema are errors
// (reported when the tree is read). `source` records the overrides for the error messages.
struct CaseTree {
  toml::table root;
  std::shared_ptr<InputSource> source;
};
CaseTree parse_case_tree(std::string_view toml_text, const std::string& source_name,
                         const std::vector<std::string>& overrides = {});

// The text of a case file; an InputError when it is missing or unreadable.
std::string read_case_text(const std::filesystem::path& file);

// The generic scene tables of `top`. Unknown keys are left for the caller to reject
// (top.reject_unknown_keys()) after it has read the sections it owns.
Scene read_scene_tables(TableReader& top);

// Single tables, for presets that build the rest of the scene themselves. `base`: the values a key
// takes when absent; [solver] end_time is required unless the base has one.
SolverSpec read_solver(TableReader t, SolverSpec base = {});
OutputSpec read_output(std::optional<TableReader> t, OutputSpec base = {});

// A temperature below the material's melting point (where it has one).
Range temperature_range(const MaterialParameters& m);

}  // namespace mpmcut
