#pragma once
// The allowed values of a number: an interval, either end open or closed, with its unit and an
// optional note ("0 = automatic"). Declared once per key: a physics model's parameter table
// (physics/parameter_table.hpp) or the input reader of a section (io/), and every message and
// document about that key is made from it.
#include <string>
#include <string_view>

namespace mpmcut {

struct Range {
  double min = 0.0, max = 0.0;
  bool min_open = false, max_open = false;
  std::string_view unit;  // "m", "K", "" for a ratio
  std::string_view note;  // e.g. "0 = automatic"
  bool contains(double x) const {
    return (min_open ? x > min : x >= min) && (max_open ? x < max : x <= max);
  }
  std::string interval() const;  // "(0, 1]"
  std::string text() const;      // "in (0, 1] m (0 = automatic)"
  // Shorthands for the usual shapes: (lo, hi], [lo, hi], (lo, hi), [lo, hi).
  static constexpr Range open_closed(double lo, double hi, std::string_view unit = "", std::string_view note = "") {
    return {lo, hi, true, false, unit, note};
  }
  static constexpr Range closed(double lo, double hi, std::string_view unit = "", std::string_view note = "") {
    return {lo, hi, false, false, unit, note};
  }
  static constexpr Range open(double lo, double hi, std::string_view unit = "", std::string_view note = "") {
    return {lo, hi, true, true, unit, note};
  }
  static constexpr Range closed_open(double lo, double hi, std::string_view unit = "", std::string_view note = "") {
    return {lo, hi, false, true, unit, note};
  }
};

}  // namespace mpmcut
