#include "io/toml_reader.hpp"
#include "io/edit_distance.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

namespace mpmcut {

toml::table parse_toml(std::string_view text, const std::string& source_name) {
  try {
    return toml::parse(text, std::string_view(source_name));
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", source_name, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}


namespace {

// True if `prefix` is `path` or an ancestor of it ("body[0]" of "body[0].velocity").
bool is_path_prefix(std::string_view prefix, std::string_view path) {
  return path.starts_with(prefix) &&
         (path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[');
}

}  // namespace

std::string describe_type(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date/time";
  }
}

std::string toml_float(double x) {
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // 'n': inf, nan
  return s;
}

std::string describe_value(const toml::node& node) {
  if (node.is_table()) return "a table";
  if (auto s = node.value_exact<std::string>()) return "\"" + *s + "\"";
  // -1e-06, not toml++'s -9.9999999999999995e-07.
  if (auto d = node.value_exact<double>()) return toml_float(*d);
  // Element by element, on one line ("[0.5, nan]"; toml++ printed nested arrays over several lines).
  if (const toml::array* a = node.as_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < a->size(); ++i) text += (i > 0 ? ", " : "") + describe_value(*a->get(i));
    text += "]";
    if (text.size() > 60) text = fmt::format("{} of {} elements", describe_type(node), a->size());
    return text;
  }
  std::ostringstream os;  // integers, booleans, dates: short
  node.visit([&](const auto& v) { os << v; });
  return os.str();
}

TableReader::TableReader(const toml::table& table, std::string path, std::shared_ptr<const InputSource> source)
    : table_(&table), path_(std::move(path)), source_(std::move(source)) {}

std::string TableReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const toml::node* TableReader::find(std::string_view key) const { return table_->get(key); }

const toml::node* TableReader::node(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  return find(key);
}

bool TableReader::has(std::string_view key) { return node(key) != nullptr; }

std::string TableReader::location_of(const toml::source_region& region, const std::string& path) const {
  if (region.begin) {
    // Values parsed from a --set override carry the override text as their "file".
    if (region.path && region.path->starts_with("--set ")) return source_->name + ": " + *region.path;
    return fmt::format("{}:{}:{}", source_->name, region.begin.line, region.begin.column);
  }
  // No position: a value or table an override made (the last override of a key is the one whose value stands).
  for (auto o = source_->overrides.rbegin(); o != source_->overrides.rend(); ++o)
    if (is_path_prefix(path, o->key_path) || is_path_prefix(o->key_path, path))
      return source_->name + ": --set '" + o->text + "'";
  return source_->name;
}

std::string TableReader::location(std::string_view key) const {
  const toml::node* n = find(key);
  return n ? location_of(n->source(), key_path(key)) : table_location();
}

std::string TableReader::table_location() const { return location_of(table_->source(), path_); }

void TableReader::fail(std::string_view key, std::string_view message) const {
  throw InputError(location(key) + ": key '" + key_path(key) + "': " + std::string(message));
}

void TableReader::fail_table(std::string_view message) const {
  const std::string where = path_.empty() ? "top level" : "table '" + path_ + "'";
  throw InputError(table_location() + ": " + where + ": " + std::string(message));
}

void TableReader::fail_type(std::string_view key, std::string_view expected) const {
  const toml::node& n = *find(key);
  fail(key, fmt::format("must be {}, got {} ({})", expected, describe_value(n), describe_type(n)));
}

// " (is 'solvr' a misspelling?)" when a present key is close to the missing `key`.
// A present key that was read under its own name is no misspelling (a missing jc_m suggested the jc_A beside it).
std::string TableReader::misspelling_hint(std::string_view key) const {
  for (const auto& [present, value] : *table_)
    if (std::find(known_.begin(), known_.end(), present.str()) == known_.end() &&
        levenshtein(present.str(), key) <= std::max<std::size_t>(2, key.size() / 3))
      return fmt::format(" (is '{}' a misspelling?)", present.str());
  return "";
}

void TableReader::require_key(std::string_view key, std::string_view what) {
  if (!has(key)) fail_table(fmt::format("missing required key '{}' ({}){}", key, what, misspelling_hint(key)));
}

void TableReader::check(std::string_view key, bool ok, std::string_view allowed, double value) {
  if (ok) return;
  const toml::node* n = find(key);
  fail(key, fmt::format("must be {}, got {}", allowed, n ? describe_value(*n) : fmt::format("{}", value)));
}

void TableReader::check(std::string_view key, double value, const Range& range) {
  check(key, range.contains(value), range.text(), value);
}

double TableReader::number(std::string_view key, double fallback) {
  return optional_number(key).value_or(fallback);
}

double TableReader::number(std::string_view key, double fallback, const Range& range) {
  const double x = number(key, fallback);
  check(key, x, range);
  return x;
}

std::optional<double> TableReader::optional_number(std::string_view key) {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (auto i = n->value_exact<int64_t>()) return static_cast<double>(*i);
  if (auto d = n->value_exact<double>()) {
    // nan and inf are valid TOML but never a physical value; downstream they hang loops (an end
    // time of inf) or overflow sizes (a cut length of inf), so they are refused for every key.
    if (!std::isfinite(*d)) fail(key, fmt::format("must be a finite number, got {}", describe_value(*n)));
    return *d;
  }
  fail_type(key, "a number");
}

long TableReader::integer(std::string_view key, long fallback) {
  const toml::node* n = node(key);
  if (n == nullptr) return fallback;
  if (auto i = n->value_exact<int64_t>()) return static_cast<long>(*i);
  fail_type(key, "an integer");
}

long TableReader::integer(std::string_view key, long fallback, const Range& range) {
  const long x = integer(key, fallback);
  check(key, static_cast<double>(x), range);
  return x;
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  const toml::node* n = node(key);
  if (n == nullptr) return fallback;
  if (auto b = n->value_exact<bool>()) return *b;
  fail_type(key, "a boolean (true or false)");
}

std::string TableReader::string(std::string_view key, const std::string& fallback) {
  const toml::node* n = node(key);
  if (n == nullptr) return fallback;
  if (auto s = n->value_exact<std::string>()) return *s;
  fail_type(key, "a string");
}

namespace {
std::optional<Vec2> as_vec2(const toml::node& n) {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->size() != 2) return std::nullopt;
  Vec2 v;
  for (int k = 0; k < 2; ++k) {
    const toml::node& c = *a->get(k);
    if (auto i = c.value_exact<int64_t>()) v[k] = static_cast<double>(*i);
    else if (auto d = c.value_exact<double>(); d && std::isfinite(*d)) v[k] = *d;  // nan/inf: never a coordinate
    else return std::nullopt;
  }
  return v;
}
}  // namespace

Vec2 TableReader::vec2(std::string_view key, const Vec2& fallback) {
  const toml::node* n = node(key);
  if (n == nullptr) return fallback;
  if (auto v = as_vec2(*n)) return *v;
  fail_type(key, "a pair of finite numbers [x, y]");
}

Vec2 TableReader::vec2(std::string_view key, const Vec2& fallback, const Range& component_range) {
  const Vec2 v = vec2(key, fallback);
  for (int k = 0; k < 2; ++k)
    if (!component_range.contains(v[k]))
      fail(key, fmt::format("each component must be {}, got [{}, {}]", component_range.text(), v.x(), v.y()));
  return v;
}

std::vector<Vec2> TableReader::points(std::string_view key) {
  const toml::node* n = node(key);
  std::vector<Vec2> result;
  if (n == nullptr) return result;
  const toml::array* a = n->as_array();
  if (a == nullptr) fail_type(key, "an array of points [[x, y], ...] of finite numbers");
  for (const toml::node& p : *a) {
    auto v = as_vec2(p);
    if (!v) fail_type(key, "an array of points [[x, y], ...] of finite numbers");
    result.push_back(*v);
  }
  return result;
}

std::optional<TableReader> TableReader::optional_table(std::string_view key) {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_table()) fail_type(key, "a table");
  return TableReader(*n->as_table(), key_path(key), source_);
}

TableReader TableReader::table(std::string_view key) {
  auto t = optional_table(key);
  if (!t) fail_table(fmt::format("missing required table [{}]{}", key_path(key), misspelling_hint(key)));
  return *t;
}

std::vector<TableReader> TableReader::array_of_tables(std::string_view key) {
  const toml::node* n = node(key);
  std::vector<TableReader> result;
  if (n == nullptr) return result;
  const toml::array* a = n->as_array();
  const std::string expected = fmt::format("an array of tables ([[{}]] entries)", key);
  if (a == nullptr) fail_type(key, expected);
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = a->get(i)->as_table();
    if (t == nullptr) fail_type(key, expected);
    result.emplace_back(*t, fmt::format("{}[{}]", key_path(key), i), source_);
  }
  return result;
}

void TableReader::reject_unknown_keys() const {
  for (const auto& [key, value] : *table_) {
    const std::string_view name = key.str();
    if (std::find(known_.begin(), known_.end(), name) != known_.end()) continue;
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
    for (const auto& k : known_) {
      const std::size_t d = levenshtein(name, k);
      if (d < best_distance) best_distance = d, best = k;
    }
    std::string hint;
    if (!best.empty()) {
      hint = "; did you mean '" + best + "'?";
    } else {
      std::vector<std::string> sorted = known_;
      std::sort(sorted.begin(), sorted.end());
      for (const auto& k : sorted) hint += (hint.empty() ? "; known keys here: " : ", ") + k;
    }
    const std::string where = path_.empty() ? "at top level" : "in table '" + path_ + "'";
    // Point at the key itself; a key inserted by an override has no position, its value may.
    const toml::source_region& where_key = key.source().begin ? key.source() : value.source();
    throw InputError(location_of(where_key, key_path(name)) + ": key '" + key_path(name) + "': unknown key " + where +
                     hint);
  }
}

}  // namespace mpmcut
