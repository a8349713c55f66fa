#pragma once
// Johnson-Cook thermo-visco-plasticity with JC damage initiation and Hillerborg evolution,
// plane strain, hypoelastic with the Jaumann rate (references in docs/references.md; theory in
// docs/theory_materials.md, which maps every equation to the function below that implements it).
#include "physics/damage.hpp"
#include "physics/equation_of_state.hpp"
#include "physics/flow_stress.hpp"
#include "physics/material.hpp"

namespace mpmcut {

class JohnsonCookMaterial final : public Material {
 public:
  // Validates the parameters (std::invalid_argument with the offending values) and caches constants.
  explicit JohnsonCookMaterial(const MaterialParameters& params);

  ConstitutiveIncrement update(Particles& p, std::size_t i, const Mat2& L,
                               const StepContext& ctx) const override;
  // sqrt((K(rho) + 4G/3)/rho) at the current density of the particle's solid, m exp(crack_opening)/V (K the
  // EOS tangent; damaged: the deviator's share k (damage.hpp) on G, and 1 - D on K in tension); failed or molten:
  // sqrt(K/max(rho, rho0)) (no shear stiffness; an opened crack does not shrink the time step).
  double wave_speed(const Particles& p, std::size_t i) const override;
  // (1 - D (1 - phi^2)) s:s/(4G) + p^2/(2K) (phi the closed crack's share of damage.hpp; tensile p^2 scaled by
  // 1-D; failed: compression only), times V.
  double elastic_energy(const Particles& p, std::size_t i) const override;

  // The smoothed plastic strain rate shared by the flow law and the damage law: backward Euler of
  // tau d(epsdot)/dt = d(eps_p)/dt - epsdot, i.e. (tau epsdot_old + d_eps_p)/(tau + dt);
  // tau = strain_rate_smoothing_time, and tau = 0 gives d_eps_p/dt.
  double smoothed_rate(double old_rate, double plastic_increment, double dt) const {
    return (smoothing_time_ * old_rate + plastic_increment) / (smoothing_time_ + dt);
  }

  // Result of the plastic corrector: everything is evaluated at the returned increment, so
  // q_trial - 3G*plastic_increment == flow_stress to the solver tolerance.
  struct ReturnMapping {
    double plastic_increment = 0.0;  // d(eps_p)
    double flow_stress = 0.0;        // sigma_y(eps_p + d, rate, temperature), Pa
    double rate = 0.0;               // smoothed rate used, 1/s
    double temperature = 0.0;        // end-of-step temperature used (implicit adiabatic heating), K
    double log_rate_ratio = 0.0;     // max(ln(rate/epsdot0), 0) (only filled when C != 0)
    int iterations = 0;
  };
  // Solves r(x) = q_trial - 3G x - sigma_y(eps_p + x, rate(x), T(x)) = 0 for x in [0, q_trial/3G]
  // with Newton safeguarded by bisection, |r| <= 1e-12 q_trial; rate(x) = smoothed_rate(old_rate, x, dt),
  // T(x) = T0 + heat_per_work (q_trial - 3G x) x with heat_per_work = chi (1 - D)/(rho c).
  // Requires q_trial > sigma_y(eps_p, rate(0), T0).
  ReturnMapping return_mapping(double q_trial, double plastic_strain, double old_rate, double temperature_K,
                               double heat_per_work, double dt) const;

  const JohnsonCookFlowStress& flow_stress() const { return flow_; }
  const EquationOfStateModel& equation_of_state() const { return eos_; }
  const JohnsonCookDamage& damage_model() const { return damage_; }
  double shear_modulus() const { return G_; }

 private:
  // The closed crack's share phi (damage.hpp) of particle i's stored undamaged deviator; 0 without crack friction.
  double closed_crack_share(const Particles& p, std::size_t i) const;

  JohnsonCookFlowStress flow_;
  EquationOfStateModel eos_;
  JohnsonCookDamage damage_;
  double G_, two_G_, three_G_;
  double smoothing_time_;
  double taylor_quinney_;  // chi
  double heat_per_work_;   // chi/c: temperature rise = heat_per_work_ * w / rho, J/kg per J/m^3 -> K
  double sure_elastic_q_;  // q_trial below this is elastic at T <= T_r without evaluating sigma_y (A, or A D(T_r) with the TANH softening)
  double room_temperature_;
};

}  // namespace mpmcut
