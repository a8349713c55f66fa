#include "io/material_keys.hpp"

#include <optional>
#include <vector>

#include <fmt/format.h>

namespace mpmcut {

namespace {

template <class P>
void read_table(TableReader& t, const ParameterTable<P>& table, MaterialParameters& m) {
  P& p = m;
  for (const Parameter<P>& row : table.parameters) {
    switch (row.kind) {
      case Parameter<P>::Kind::Number: p.*row.number = t.number(row.key, p.*row.number); break;
      case Parameter<P>::Kind::Flag: p.*row.flag = t.boolean(row.key, p.*row.flag); break;
      case Parameter<P>::Kind::Choice: {
        const std::string text = t.string(row.key, "");
        if (text.empty() && !t.has(row.key)) break;
        std::string allowed;
        bool found = false;
        for (std::size_t i = 0; i < row.options.size() && !found; ++i) {
          if (row.options[i] == text) row.set_option(p, static_cast<int>(i)), found = true;
          allowed += fmt::format("{}\"{}\"", allowed.empty() ? "" : " | ", row.options[i]);
        }
        if (!found) t.fail(row.key, "must be one of " + allowed + ", got \"" + text + '"');
        break;
      }
    }
  }
}

template <class P>
void require_table_keys(TableReader& t, const ParameterTable<P>& table, const MaterialParameters& m) {
  for (const Parameter<P>& row : table.parameters)
    if (row.required && in_use(row.use, m))
      t.require_key(row.key, row.use == InUse::Always ? std::string(row.unit) : fmt::format("needed by {}", describe(row.use)));
}

template <class P>
void write_table(const ParameterTable<P>& table, const MaterialParameters& m, std::ostream& out) {
  const P& p = m;
  const P defaults{};
  for (const Parameter<P>& row : table.parameters) {
    if (row.written_only_if_set) {
      const bool is_default = row.kind == Parameter<P>::Kind::Number ? p.*row.number == defaults.*row.number
                              : row.kind == Parameter<P>::Kind::Flag ? p.*row.flag == defaults.*row.flag
                                                                     : row.get_option(p) == row.get_option(defaults);
      if (is_default) continue;
    }
    out << row.key << " = ";
    switch (row.kind) {
      case Parameter<P>::Kind::Number: out << toml_float(p.*row.number); break;
      case Parameter<P>::Kind::Flag: out << (p.*row.flag ? "true" : "false"); break;
      case Parameter<P>::Kind::Choice: out << '"' << row.options.at(row.get_option(p)) << '"'; break;
    }
    out << "\n";
  }
}

// Markdown-safe: a '|' would end the cell.
std::string cell(std::string_view text) {
  std::string s;
  for (const char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
  return s;
}

template <class P>
void markdown_rows(const ParameterTable<P>& table, std::string& out) {
  const P defaults{};
  for (const Parameter<P>& row : table.parameters) {
    std::string unit = row.unit.empty() ? "" : std::string(row.unit);
    std::string fallback, allowed;
    switch (row.kind) {
      case Parameter<P>::Kind::Number: {
        fallback = fmt::format("{:g}", defaults.*row.number);
        Range r = row.range;
        allowed = r.interval();
        if (row.min_from) allowed = fmt::format("{}`{}`, {:g}{}", r.min_open ? '(' : '[', row.min_from_key, r.max, r.max_open ? ')' : ']');
        if (row.use != InUse::Always) allowed += fmt::format(" with {} (else also 0)", describe(row.use));
        if (!row.range.note.empty()) allowed += fmt::format(" ({})", row.range.note);
        break;
      }
      case Parameter<P>::Kind::Flag:
        unit = "bool";
        fallback = defaults.*row.flag ? "`true`" : "`false`";
        if (row.use != InUse::Always) allowed = fmt::format("`true` only with {}", describe(row.use));
        break;
      case Parameter<P>::Kind::Choice:
        fallback = fmt::format("`\"{}\"`", row.options.at(row.get_option(defaults)));
        for (std::string_view o : row.options) allowed += fmt::format("{}`\"{}\"`", allowed.empty() ? "" : ", ", o);
        break;
    }
    if (row.required)
      fallback = row.use == InUse::Always ? "**required**" : fmt::format("**required** with {}", describe(row.use));
    for (const ParameterRule<P>& rule : table.rules)
      if (rule.key == row.key) allowed += fmt::format("; {}", rule.allowed);
    out += fmt::format("| `{}` | {} | {} | {} | {} |\n", row.key, cell(unit), cell(fallback), cell(allowed), cell(row.doc));
    for (const AlternativeKey& a : alternative_keys())
      if (a.replaces == row.key)
        out += fmt::format("| `{}` | {} | – | {}; not together with `{}` | {} |\n", a.key, cell(a.unit),
                           a.range.interval(), a.replaces, cell(a.doc));
  }
}

}  // namespace

void read_material_keys(TableReader& t, MaterialParameters& m, bool full_definition) {
  for_each_parameter_table([&](const auto& table) { read_table(t, table, m); });
  if (full_definition) for_each_parameter_table([&](const auto& table) { require_table_keys(t, table, m); });
  for (const AlternativeKey& a : alternative_keys()) {
    const std::optional<double> value = t.optional_number(a.key);
    if (!value) continue;
    if (t.has(a.replaces)) t.fail(a.key, fmt::format("give {} or {}, not both", a.replaces, a.key));
    t.check(a.key, *value, a.range);
    const double converted = a.convert(*value, m);
    for_each_parameter_table([&]<class P>(const ParameterTable<P>& table) {
      for (const Parameter<P>& row : table.parameters) {
        if (row.key != a.replaces || !row.number) continue;
        // Reported here, at the key the user gave, with what the conversion read: a modulus in GPa gives a
        // fracture energy 1e9 times too large, which the replaced key's own check would blame on a key not written.
        if (const Range r = row.range_at(m); in_use(row.use, m) && !r.contains(converted))
          t.fail(a.key, fmt::format("{} = {:g} {} with this material's {} gives {} = {:.4g} {}, which must be {}: "
                                    "check the units of these keys",
                                    a.key, *value, a.unit, a.inputs(m), a.replaces, converted, row.unit, r.text()));
        static_cast<P&>(m).*row.number = converted;
      }
    });
  }
}

void check_material_keys(TableReader& t, const MaterialParameters& m) {
  const std::vector<ParameterProblem> problems = parameter_problems(m);
  if (problems.empty()) return;
  const ParameterProblem& p = problems.front();
  // A value this table did not give came from its library set (a set's damage = true after model = "elastic").
  if (!t.has(p.key) && t.has("library"))
    t.fail(p.key, fmt::format("must be {}, got {} from the library set \"{}\": give {} in this [[material]]", p.allowed,
                              shown_value(p), t.string("library", ""), p.key));
  t.check(p.key, false, p.allowed, p.value);
}

void write_material_keys(const MaterialParameters& m, std::ostream& out) {
  for_each_parameter_table([&](const auto& table) { write_table(table, m, out); });
}

std::string material_key_unit(std::string_view key) {
  std::string unit;
  for_each_parameter_table([&]<class P>(const ParameterTable<P>& table) {
    for (const Parameter<P>& row : table.parameters)
      if (row.key == key && row.number && row.unit != "-") unit = std::string(row.unit);
  });
  for (const AlternativeKey& a : alternative_keys())
    if (a.key == key && a.unit != "-") unit = std::string(a.unit);
  return unit;
}

std::map<std::string, double> numeric_material_keys(const MaterialParameters& m) {
  std::map<std::string, double> keys;
  for_each_parameter_table([&]<class P>(const ParameterTable<P>& table) {
    const P& p = m;
    for (const Parameter<P>& row : table.parameters)
      if (row.kind == Parameter<P>::Kind::Number) keys[std::string(row.key)] = p.*row.number;
  });
  return keys;
}

std::string material_keys_markdown() {
  std::string out =
      "| key | unit | default | allowed | meaning |\n"
      "|---|---|---|---|---|\n"
      "| `name` | string | **required** | non-empty, unique | what bodies refer to |\n"
      "| `library` | string | – | a set name | start from this library set |\n"
      "| `citation` | string | `\"\"` (library: the set's) | | where the numbers come from |\n";
  for_each_parameter_table([&](const auto& table) { markdown_rows(table, out); });
  return out;
}

}  // namespace mpmcut
