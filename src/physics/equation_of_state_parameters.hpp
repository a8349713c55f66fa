#pragma once
// The pressure model (equation_of_state.hpp) and the artificial bulk viscosity: the struct and its
// parameter table.
#include "physics/parameter_table.hpp"

namespace mpmcut {

enum class EquationOfState { Linear, MieGruneisen };

struct EquationOfStateParameters {
  EquationOfState eos = EquationOfState::Linear;
  double mg_c0 = 0.0;      // Mie-Grueneisen bulk sound speed, m/s
  double mg_s = 0.0;       // Hugoniot slope s, -
  double mg_gamma0 = 0.0;  // Grueneisen coefficient, -
  double bulk_viscosity_linear = 0.0;     // b1, - (0 = off)
  double bulk_viscosity_quadratic = 0.0;  // b2, -

  bool operator==(const EquationOfStateParameters&) const = default;
};

inline const ParameterTable<EquationOfStateParameters>& equation_of_state_parameter_table() {
  using P = EquationOfStateParameters;
  static const ParameterTable<P> table{
      "equation of state",
      {
          choice<P, &P::eos>("eos", {"linear", "mie_gruneisen"}, "pressure model"),
          number("mg_c0", &P::mg_c0, "m/s", Range::open_closed(0.0, 1e5, "", "with eos = \"mie_gruneisen\""),
                 "bulk sound speed c_0")
              .used_with(InUse::MieGruneisen)
              .required_key(),
          number("mg_s", &P::mg_s, "-", Range::closed(0.0, 10.0), "Hugoniot slope s").used_with(InUse::MieGruneisen),
          number("mg_gamma0", &P::mg_gamma0, "-", Range::closed(0.0, 10.0), "Grueneisen Gamma_0")
              .used_with(InUse::MieGruneisen),
          number("bulk_viscosity_linear", &P::bulk_viscosity_linear, "-", Range::closed(0.0, 10.0),
                 "b_1 of the artificial bulk viscosity (0 = off)"),
          number("bulk_viscosity_quadratic", &P::bulk_viscosity_quadratic, "-", Range::closed(0.0, 10.0), "b_2"),
      },
      {}};
  return table;
}

}  // namespace mpmcut
