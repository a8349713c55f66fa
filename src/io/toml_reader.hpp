#pragma once
// Reading one TOML table with everything a good error message needs. All input is read through a
// TableReader, which
//  - knows the dotted path of its table ("body[1]") and where each value is (file:line:column),
//  - records every key the schema asks about, so that any other key is reported as unknown,
//    with the closest known key suggested (typos must not be silently ignored),
//  - turns a wrong type or an out-of-range value into an InputError that says what is allowed.
// Integers are accepted where numbers are expected (1 -> 1.0). Every number must be finite (nan and
// +-inf are never a physical value), and each key declares its physical range (Range) where it is read.
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "core/range.hpp"
#include "core/tensor.hpp"
#include "io/input_error.hpp"

namespace mpmcut {

// Where the values came from. Values set by a --set override have no position in the file, so
// messages about them name the override instead.
struct InputSource {
  std::string name;  // the file name as given, e.g. "cases/demo.toml"
  struct Override {
    std::string key_path;  // canonical dotted path, e.g. "body[0].velocity"
    std::string text;      // as the user typed it, e.g. "body.0.velocity=[1, 0]"
  };
  std::vector<Override> overrides;
};

// Parses TOML text; a syntax error becomes an InputError "name:line:col: TOML syntax error: ...".
toml::table parse_toml(std::string_view text, const std::string& source_name);

// The user-facing name of a TOML value's type ("a string", "an integer", ...).
std::string describe_type(const toml::node& node);
// A value as it would be written in TOML (tables and long arrays abbreviated).
std::string describe_value(const toml::node& node);
// The shortest text that reads back as the same double, always a TOML float (5000.0, -1e-06, inf).
std::string toml_float(double x);

class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, std::shared_ptr<const InputSource> source);

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;  // "solver" + "cfl" -> "solver.cfl"
  bool has(std::string_view key);                     // also declares the key as known
  const toml::node* node(std::string_view key);       // nullptr if absent; declares the key

  // Typed getters: an absent key gives the fallback, a wrong type throws. Each declares the key.
  double number(std::string_view key, double fallback);
  // A number checked against its range (the fallback too: a default or inherited value is checked).
  double number(std::string_view key, double fallback, const Range& range);
  long integer(std::string_view key, long fallback, const Range& range);
  Vec2 vec2(std::string_view key, const Vec2& fallback, const Range& component_range);
  std::optional<double> optional_number(std::string_view key);
  long integer(std::string_view key, long fallback);
  bool boolean(std::string_view key, bool fallback);
  std::string string(std::string_view key, const std::string& fallback);
  Vec2 vec2(std::string_view key, const Vec2& fallback);
  std::vector<Vec2> points(std::string_view key);  // [[x, y], ...]; empty if absent
  template <class E>
  E choice(std::string_view key, std::initializer_list<std::pair<std::string_view, E>> options, E fallback);

  // Sub-tables: absent -> nullopt (optional_table) or an error (table).
  std::optional<TableReader> optional_table(std::string_view key);
  TableReader table(std::string_view key);
  // [[key]] entries (also accepts an inline array of tables); empty if absent.
  std::vector<TableReader> array_of_tables(std::string_view key);

  // Errors. A present key is located at its value; an absent one at this table.
  void require_key(std::string_view key, std::string_view what);  // error if absent
  // If !ok: "<loc>: key '<path>': must be <allowed>, got <value>". `value` is used only when the
  // key is absent from this table (e.g. inherited from a library set or a default).
  void check(std::string_view key, bool ok, std::string_view allowed, double value);
  void check(std::string_view key, double value, const Range& range);  // "must be in (0, 1] m, got ..."
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  [[noreturn]] void fail_table(std::string_view message) const;  // about this table as a whole
  std::string location(std::string_view key) const;              // "file:line:col" or the override
  std::string table_location() const;

  // Throws for the first key present in the table that no getter asked about.
  void reject_unknown_keys() const;

 private:
  const toml::node* find(std::string_view key) const;
  std::string location_of(const toml::source_region& region, const std::string& key_path) const;
  [[noreturn]] void fail_type(std::string_view key, std::string_view expected) const;
  std::string misspelling_hint(std::string_view key) const;

  const toml::table* table_;
  std::string path_;
  std::shared_ptr<const InputSource> source_;
  std::vector<std::string> known_;
};

template <class E>
E TableReader::choice(std::string_view key, std::initializer_list<std::pair<std::string_view, E>> options,
                      E fallback) {
  const std::string text = string(key, "");
  if (text.empty() && !has(key)) return fallback;
  std::string allowed;
  for (const auto& [name, value] : options) {
    if (name == text) return value;
    if (!allowed.empty()) allowed += " | ";
    allowed.append("\"").append(name).append("\"");
  }
  fail(key, "must be one of " + allowed + ", got \"" + text + '"');
}

}  // namespace mpmcut
