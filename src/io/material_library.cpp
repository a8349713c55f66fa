#include "io/material_library.hpp"

#include <cmath>
#include <algorithm>

#include <fmt/format.h>

#include "io/embedded_text.hpp"
#include "io/material_keys.hpp"

namespace mpmcut {

namespace {

std::string list_names(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + ("\"" + n + "\"");
  return text.empty() ? "(none)" : text;
}

}  // namespace

// The names of a file's [[material]] tables, in order ("" where a table has none: its own error comes later).
std::vector<std::string> set_names(std::vector<TableReader>& tables) {
  std::vector<std::string> names;
  for (TableReader& t : tables) {
    const toml::node* n = t.node("name");
    names.push_back(n && n->is_string() ? n->value_or(std::string()) : std::string());
  }
  return names;
}

MaterialParameters read_material(TableReader& t, const MaterialLibrary& library,
                                 const std::vector<std::string>& later_names) {
  MaterialParameters m;
  t.require_key("name", "the name bodies use to refer to this material");
  const bool from_library = t.has("library");
  std::string base_name;
  if (from_library) {
    base_name = t.string("library", "");
    const MaterialParameters* base = library.find(base_name);
    if (base == nullptr && std::find(later_names.begin(), later_names.end(), base_name) != later_names.end())
      t.fail("library", fmt::format("material set \"{}\" is defined further down this file: a [[material]] can "
                                    "start from a library set or from a set defined above it; move \"{}\" up",
                                    base_name, base_name));
    if (base == nullptr)
      t.fail("library", fmt::format("no material set \"{}\"; available sets: {}", base_name, list_names(library.names())));
    m = *base;
  }
  m.name = t.string("name", "");
  t.check("name", !m.name.empty(), "a non-empty string", 0.0);
  // A set changed from a library set keeps its citation: naming the changed keys there would change the scene.toml
  // of every calibration trial and validate --material-key set, and their complete runs would no longer be
  // recognised (run/run_case.cpp, existing_run).
  m.citation = t.string("citation", m.citation);
  read_material_keys(t, m, !from_library);
  // After all keys are read, so that inherited (library) values are checked too.
  check_material_keys(t, m);
  t.reject_unknown_keys();
  return m;
}

std::vector<MaterialParameters> read_case_materials(
    TableReader& top, MaterialLibrary& library, const std::function<void(TableReader&, const MaterialParameters&)>& check) {
  std::vector<MaterialParameters> sets;
  std::vector<TableReader> tables = top.array_of_tables("material");
  const std::vector<std::string> names = set_names(tables);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    TableReader& t = tables[i];
    MaterialParameters m = read_material(t, library, std::vector<std::string>(names.begin() + i + 1, names.end()));
    if (std::any_of(sets.begin(), sets.end(), [&](const MaterialParameters& s) { return s.name == m.name; }))
      t.fail("name", fmt::format("duplicate material name \"{}\" (an earlier [[material]] of this file has it)", m.name));
    if (check) check(t, m);
    library.add(m);
    sets.push_back(std::move(m));
  }
  return sets;
}

void MaterialLibrary::add_file(std::string_view toml_text, const std::string& source_name) {
  toml::table root = parse_toml(toml_text, source_name);
  auto source = std::make_shared<InputSource>(InputSource{source_name, {}});
  TableReader file(root, "", source);
  std::vector<TableReader> tables = file.array_of_tables("material");
  const std::vector<std::string> names = set_names(tables);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    TableReader& t = tables[i];
    MaterialParameters m = read_material(t, *this, std::vector<std::string>(names.begin() + i + 1, names.end()));
    if (find(m.name) != nullptr) t.fail("name", fmt::format("duplicate material set \"{}\"", m.name));
    sets_.push_back(std::move(m));
  }
  file.reject_unknown_keys();
}

const MaterialParameters* MaterialLibrary::find(std::string_view set_name) const {
  // The latest definition of a name wins (add(): a case's set over the library's).
  for (auto m = sets_.rbegin(); m != sets_.rend(); ++m)
    if (m->name == set_name) return &*m;
  return nullptr;
}

std::vector<std::string> MaterialLibrary::names() const {
  std::vector<std::string> result;
  for (const auto& m : sets_) result.push_back(m.name);
  return result;
}

const MaterialLibrary& builtin_material_library() {
  static const MaterialLibrary library = [] {
    MaterialLibrary lib;
    for (const EmbeddedText& file : embedded_texts())
      if (file.path.starts_with("materials/")) lib.add_file(file.text, std::string(file.path));
    return lib;
  }();
  return library;
}

}  // namespace mpmcut
