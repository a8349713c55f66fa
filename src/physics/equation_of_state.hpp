#pragma once
// Pressure of a solid: the volumetric half of the constitutive update (theory_materials.md §3).
// Pressure is positive in compression (p = -tr(sigma)/3).
//
//   Linear (hypoelastic):  p_{n+1} = p_n - K dEps_v,   dEps_v = tr(D) dt
//   Mie-Grueneisen (Hugoniot reference, LS-DYNA/Karamelo form with a = 0), mu = rho/rho0 - 1:
//     mu > 0:  p = rho0 c0^2 mu [1 + (1 - Gamma0/2) mu] / [1 - (s - 1) mu]^2 + Gamma0 E
//     mu <= 0: p = rho0 c0^2 mu + Gamma0 E
//     E = rho0 c_v (T - T_r): thermal energy per unit reference volume above room temperature
//   Bulk viscosity (von Neumann-Richtmyer, Abaqus/Explicit form, compression only, dEps_v/dt < 0):
//     q = b1 rho c L |epsdot_v| + rho (b2 L epsdot_v)^2,   L = cell size, c = current wave speed
#include "physics/material_parameters.hpp"

namespace mpmcut {

class EquationOfStateModel {
 public:
  // Throws std::invalid_argument when the chosen law's constants are unusable.
  explicit EquationOfStateModel(const MaterialParameters& params);

  // Pressure at the end of the step, Pa. Linear: incremental from old_pressure_Pa. Mie-Grueneisen:
  // total form p(rho, T); old_pressure_Pa and the strain increment are not used.
  double pressure(double old_pressure_Pa, double volumetric_strain_increment, double density,
                  double temperature_K) const;

  // Tangent bulk modulus rho dp/drho at the current density (Hugoniot part only for MG), Pa.
  double bulk_modulus(double density) const;

  // Artificial bulk viscosity, Pa (>= 0; zero unless compressing and enabled).
  double bulk_viscosity(double density, double volumetric_strain_rate, double length_m, double sound_speed) const;
  bool has_bulk_viscosity() const { return b1_ > 0.0 || b2_ > 0.0; }

  EquationOfState kind() const { return kind_; }

 private:
  EquationOfState kind_;
  double K_;                   // linear bulk modulus, Pa
  double rho0_, rho0_c0sq_;    // MG reference density and rho0 c0^2
  double a_, b_;              // MG: 1 - Gamma0/2, s - 1
  double thermal_;             // MG: Gamma0 rho0 c_v, Pa/K
  double room_temperature_;
  double b1_, b2_;
};

}  // namespace mpmcut
