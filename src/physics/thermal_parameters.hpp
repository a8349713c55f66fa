#pragma once
// A material's thermal properties: heat capacity and conduction, plastic heating, and the room and
// melting temperatures of the Johnson-Cook laws. The struct and its parameter table.
#include "physics/parameter_table.hpp"

namespace mpmcut {

struct ThermalParameters {
  double specific_heat = 0.0;         // c, J/(kg K)
  double thermal_conductivity = 0.0;  // k, W/(m K)
  double taylor_quinney = 0.9;        // chi: fraction of plastic work turned into heat, -
  double room_temperature = 298.0;    // T_r, K
  double melting_temperature = 0.0;   // T_m, K

  bool operator==(const ThermalParameters&) const = default;
};

inline const ParameterTable<ThermalParameters>& thermal_parameter_table() {
  using P = ThermalParameters;
  static const ParameterTable<P> table{
      "thermal properties",
      {
          number("specific_heat", &P::specific_heat, "J/(kg K)",
                 Range::open_closed(0.0, 1e5, "", "positive for johnson_cook: plastic heating"),
                 "c; also > 0 with thermal.conduction")
              .used_with(InUse::JohnsonCook)
              .required_key(),
          number("thermal_conductivity", &P::thermal_conductivity, "W/(m K)", Range::closed(0.0, 1e4), "k"),
          number("taylor_quinney", &P::taylor_quinney, "-", Range::closed(0.0, 1.0),
                 "fraction of plastic work turned into heat")
              .model_limit_above(),
          number("room_temperature", &P::room_temperature, "K", Range::open(0.0, 1e4),
                 "T_r of Johnson-Cook (also the default body temperature)"),
          number("melting_temperature", &P::melting_temperature, "K",
                 Range::open_closed(0.0, 1e4, "", "above room_temperature"), "T_m of Johnson-Cook")
              .above(&P::room_temperature, "room_temperature")
              .used_with(InUse::JohnsonCook)
              .required_key(),
      },
      {}};
  return table;
}

}  // namespace mpmcut
