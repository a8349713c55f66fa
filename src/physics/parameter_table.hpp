#pragma once
// A physics model's parameters, each declared once: its TOML key, unit, allowed range, whether a
// full material definition must give it, when the model uses it, and one line of documentation.
// The default is the initializer of the field in the model's parameter struct, next to the table.
// Everything else is made from these tables (physics/material_parameters.hpp): the validation
// both the input reader and the physics constructors apply, the [[material]] reader and writer
// (io/material_keys.hpp) and the key table of docs/input.md (`mpmcut keys --markdown`).
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/range.hpp"

namespace mpmcut {

// When a parameter is used: always, or only with one of the material's switches. A parameter that
// is not in use may also hold 0 (its default; the expanded scene.toml writes it back), so that a
// wrong value does not hide until the switch is turned on; a flag that is not in use must be false.
enum class InUse { Always, JohnsonCook, MieGruneisen, Damage, RateDependentFractureEnergy, TanhSoftening };

template <class P>
struct Parameter {
  enum class Kind { Number, Flag, Choice };
  std::string_view key;
  Kind kind = Kind::Number;
  double P::*number = nullptr;        // Kind::Number
  bool P::*flag = nullptr;            // Kind::Flag
  std::vector<std::string_view> options;  // Kind::Choice: the values' names, in the enum's order
  int (*get_option)(const P&) = nullptr;   // Kind::Choice: the field as an index into options
  void (*set_option)(P&, int) = nullptr;
  std::string_view unit;  // "-" for a ratio; empty for flags and choices
  Range range;            // numbers: allowed while in use (its unit is `unit`)
  // The range's lower end is another parameter of the same struct (melting above room temperature).
  double P::*min_from = nullptr;
  std::string_view min_from_key;
  InUse use = InUse::Always;
  bool required = false;  // a full definition (not from a library set) must give it while in use
  std::string_view doc;
  // Which ends of the range are caps: bounds of plausibility (beyond every engineering material by
  // an order of magnitude, docs/reliability.md) that keep wave speeds, time steps and energies
  // representable, rather than limits of the model. The input reader enforces the whole range; a
  // physics constructor the range without its caps, so that a test may drive a model with, say, a
  // 10^4 times stiffer driver. By default the upper end is a cap and the lower end a limit.
  bool min_is_cap = false, max_is_cap = true;
  // Written into an expanded scene only when it differs from its default: keys added after run records
  // were made leave the scene text of every run that does not use them as it was (studies/run_records).
  bool written_only_if_set = false;

  Parameter used_with(InUse u) && { use = u; return std::move(*this); }
  Parameter required_key() && { required = true; return std::move(*this); }
  Parameter model_limit_above() && { max_is_cap = false; return std::move(*this); }
  Parameter capped_below() && { min_is_cap = true; return std::move(*this); }
  Parameter written_if_set() && { written_only_if_set = true; return std::move(*this); }
  Parameter above(double P::*field, std::string_view key_of_field) && {
    min_from = field;
    min_from_key = key_of_field;
    return std::move(*this);
  }
  // The range at these parameter values (with the lower end taken from min_from).
  Range range_at(const P& p) const {
    Range r = range;
    if (min_from) r.min = p.*min_from;
    return r;
  }
};

// A condition between parameters of one model that no single range expresses (A + B > 0).
template <class P>
struct ParameterRule {
  std::string_view key;      // the key a violation is reported at
  InUse use = InUse::Always;
  bool (*holds)(const P&) = nullptr;
  std::string_view allowed;  // "positive when jc_A = 0 ..." (the message says "must be <allowed>")
};

template <class P>
struct ParameterTable {
  std::string_view model;  // what the parameters are of, e.g. "Johnson-Cook flow stress"
  std::vector<Parameter<P>> parameters;
  std::vector<ParameterRule<P>> rules;
};

// Row builders. The unit "-" (a ratio) is not repeated in messages.
template <class P>
Parameter<P> number(std::string_view key, double P::*field, std::string_view unit, Range range,
                    std::string_view doc) {
  range.unit = unit == "-" ? std::string_view() : unit;
  Parameter<P> p;
  p.key = key;
  p.kind = Parameter<P>::Kind::Number;
  p.number = field;
  p.unit = unit;
  p.range = range;
  p.doc = doc;
  return p;
}

template <class P>
Parameter<P> flag(std::string_view key, bool P::*field, std::string_view doc) {
  Parameter<P> p;
  p.key = key;
  p.kind = Parameter<P>::Kind::Flag;
  p.flag = field;
  p.doc = doc;
  return p;
}

// Field: the enum member (e.g. &DamageParameters::damage_evolution); `options` name its values in
// order (0, 1, ...).
template <class P, auto Field>
Parameter<P> choice(std::string_view key, std::vector<std::string_view> options, std::string_view doc) {
  using E = std::remove_cvref_t<decltype(std::declval<P&>().*Field)>;
  Parameter<P> p;
  p.key = key;
  p.kind = Parameter<P>::Kind::Choice;
  p.options = std::move(options);
  p.get_option = [](const P& x) { return static_cast<int>(x.*Field); };
  p.set_option = [](P& x, int i) { x.*Field = static_cast<E>(i); };
  p.doc = doc;
  return p;
}

}  // namespace mpmcut
