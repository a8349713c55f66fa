#pragma once
// Named material parameter sets (Ti-6Al-4V Johnson–Cook sets with their sources, generic elastic
// materials), read from materials/*.toml. The built-in library is compiled into the program.
// A library file has the same [[material]] tables as a case file; see docs/materials.md.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "solver/scene.hpp"
#include "io/toml_reader.hpp"

namespace mpmcut {

class MaterialLibrary {
 public:
  // Adds every [[material]] of a library file; a set may start from an earlier one (`library = ...`).
  // Throws InputError (naming `source_name`) for invalid or duplicate sets.
  void add_file(std::string_view toml_text, const std::string& source_name);
  // Adds one set, e.g. a case file's, so that a later [[material]] of the same file may start from it. A set of
  // the same name as an earlier one shadows it in find() (a case may redefine a library set's name).
  void add(MaterialParameters set) { sets_.push_back(std::move(set)); }

  const MaterialParameters* find(std::string_view set_name) const;  // nullptr if unknown
  std::vector<std::string> names() const;                           // in file order
  const std::vector<MaterialParameters>& sets() const { return sets_; }

 private:
  std::vector<MaterialParameters> sets_;
};

// The library built from materials/*.toml at compile time (parsed once, on first use).
const MaterialLibrary& builtin_material_library();

// Reads and validates one [[material]] table (case file or library file). With `library = "<set>"`
// it starts from that set of `library` and every other key overrides; otherwise it is a full
// definition. The keys and their rules are the physics models' parameter tables (io/material_keys.hpp);
// fracture_toughness K_IC is converted to fracture_energy G_f = K_IC^2 (1 - nu^2) / E.
// `later_names`: the sets defined further down the same file, which `library` cannot reach yet (the error says so).
MaterialParameters read_material(TableReader& table, const MaterialLibrary& library,
                                 const std::vector<std::string>& later_names = {});

// Reads every [[material]] of a case file, in order, into `library` (each may start from a library set or from an
// earlier set of the file, and shadows a library set of its name) and returns them. `check`, when given, is
// called with each set's table and the set read, for the caller's own checks. A name defined twice in the file
// is an error at the second definition.
std::vector<MaterialParameters> read_case_materials(
    TableReader& top, MaterialLibrary& library,
    const std::function<void(TableReader&, const MaterialParameters&)>& check = {});

}  // namespace mpmcut
