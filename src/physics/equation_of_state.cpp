#include "physics/equation_of_state.hpp"

namespace mpmcut {

EquationOfStateModel::EquationOfStateModel(const MaterialParameters& p)
    : kind_(p.eos),
      K_(p.bulk_modulus()),
      rho0_(p.density),
      rho0_c0sq_(p.density * p.mg_c0 * p.mg_c0),
      a_(1.0 - 0.5 * p.mg_gamma0),
      b_(p.mg_s - 1.0),
      thermal_(p.mg_gamma0 * p.density * p.specific_heat),
      room_temperature_(p.room_temperature),
      b1_(p.bulk_viscosity_linear),
      b2_(p.bulk_viscosity_quadratic) {
  require_valid(p, equation_of_state_parameter_table(), elastic_parameter_table());
}

double EquationOfStateModel::pressure(double old_pressure, double dEv, double density, double T) const {
  if (kind_ == EquationOfState::Linear) return old_pressure - K_ * dEv;
  const double mu = density / rho0_ - 1.0;
  const double E = thermal_ * (T - room_temperature_);  // Gamma0 * E
  if (mu <= 0.0) return rho0_c0sq_ * mu + E;
  const double den = 1.0 - b_ * mu;
  return rho0_c0sq_ * mu * (1.0 + a_ * mu) / (den * den) + E;
}

double EquationOfStateModel::bulk_modulus(double density) const {
  if (kind_ == EquationOfState::Linear) return K_;
  const double mu = density / rho0_ - 1.0;
  // rho dp/drho = (1 + mu) dp/dmu
  if (mu <= 0.0) return (1.0 + mu) * rho0_c0sq_;
  const double den = 1.0 - b_ * mu;
  const double dp_dmu = rho0_c0sq_ * ((1.0 + 2.0 * a_ * mu) * den + 2.0 * b_ * mu * (1.0 + a_ * mu)) / (den * den * den);
  return (1.0 + mu) * dp_dmu;
}

double EquationOfStateModel::bulk_viscosity(double density, double rate_v, double length, double c) const {
  if (rate_v >= 0.0) return 0.0;  // compression only: no viscous tension
  const double l_rate = length * rate_v;
  return density * (b1_ * c * (-l_rate) + b2_ * b2_ * l_rate * l_rate);
}

}  // namespace mpmcut
