#pragma once
// The keys of a [[material]] table, made from the physics models' parameter tables
// (physics/material_parameters.hpp): reading them, reporting a broken rule at its key in the file,
// writing them back, and their reference table in docs/input.md (`mpmcut keys --markdown`).
#include <map>
#include <ostream>
#include <string>
#include <string_view>

#include "io/toml_reader.hpp"
#include "physics/material_parameters.hpp"

namespace mpmcut {

// Reads every parameter key present in `t` into `m` (absent keys keep m's values), then the
// alternative keys (fracture_toughness). With `full_definition` (not from a library set), the keys
// a table marks as required must be present, for the material's model. Does not validate.
void read_material_keys(TableReader& t, MaterialParameters& m, bool full_definition);

// The first broken rule of `m` (parameter_problems) as an InputError at its key in `t`.
void check_material_keys(TableReader& t, const MaterialParameters& m);

// "key = value" lines for every parameter, in table order.
void write_material_keys(const MaterialParameters& m, std::ostream& out);

// The unit of a numeric [[material]] key as the reference table writes it ("Pa", "J/m^2"); empty for a ratio
// ("-") and for a key that is not a numeric parameter.
std::string material_key_unit(std::string_view key);

// Every numeric [[material]] key with its value in `m`, written-if-set keys at their default included (the keys a
// calibration may free or fix).
std::map<std::string, double> numeric_material_keys(const MaterialParameters& m);

// The markdown table of every [[material]] key: unit, default, allowed values, meaning.
std::string material_keys_markdown();

}  // namespace mpmcut
