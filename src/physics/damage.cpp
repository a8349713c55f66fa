#include "physics/damage.hpp"

#include <cmath>
#include <limits>

namespace mpmcut {

JohnsonCookDamage::JohnsonCookDamage(const MaterialParameters& p)
    : enabled_(p.damage_enabled),
      D1_(p.jc_D1),
      D2_(p.jc_D2),
      D3_(p.jc_D3),
      D4_(p.jc_D4),
      D5_(p.jc_D5),
      min_failure_strain_(p.min_failure_strain),
      triaxiality_cutoff_(p.damage_triaxiality_cutoff),
      evolution_(p.damage_evolution),
      fracture_energy_(p.fracture_energy),
      brittle_fracture_energy_(p.fracture_energy_brittle),
      transition_rate_(p.fracture_transition_strain_rate),
      transition_exponent_(p.fracture_transition_exponent),
      max_damage_(p.max_damage),
      crack_friction_(p.crack_friction) {
  require_valid(p, damage_parameter_table());
}

double JohnsonCookDamage::failure_strain(double eta, double log_rate_ratio, double t_star) const {
  double ef = D1_ + D2_ * std::exp(D3_ * eta);
  if (D4_ != 0.0) ef *= 1.0 + D4_ * log_rate_ratio;
  if (D5_ != 0.0) ef *= 1.0 + D5_ * t_star;
  // D1 < 0 (Ti-6Al-4V) makes eps_f <= 0 at high triaxiality: clamp to a small positive strain.
  return ef >= min_failure_strain_ ? ef : min_failure_strain_;  // (a NaN also falls back to the minimum)
}

double JohnsonCookDamage::fracture_energy(double rate) const {
  if (!(transition_rate_ > 0.0)) return fracture_energy_;
  const double x = rate > 0.0 ? std::pow(rate / transition_rate_, transition_exponent_) : 0.0;
  return brittle_fracture_energy_ + (fracture_energy_ - brittle_fracture_energy_) / (1.0 + x);
}

DamageStep JohnsonCookDamage::advance(DamageState& s, double d_eps, double eps_f, double flow_stress,
                                      double length, double rate) const {
  DamageStep step;
  step.damage_before = s.damage;
  if (s.damage >= max_damage_) {
    step.failed = true;
    return step;
  }
  if (!(d_eps > 0.0)) return step;
  double after = d_eps;
  if (s.initiation < 1.0) {
    const double d_omega = d_eps / eps_f;
    if (s.initiation + d_omega < 1.0) {
      s.initiation += d_omega;
      step.strain_before_initiation = d_eps;
      return step;
    }
    // omega crosses 1 inside the increment: split it so that initiation sits at omega = 1 exactly.
    const double before = d_eps * (1.0 - s.initiation) / d_omega;
    step.strain_before_initiation = before;
    after = d_eps - before;
    s.initiation = 1.0;
    s.initiation_yield_stress = flow_stress;
    s.plastic_displacement = 0.0;
    s.fracture_energy = fracture_energy(rate);
    step.initiated_now = true;
    if (s.fracture_energy <= 0.0) {  // G_f = 0: instantaneous failure (not recommended, but defined)
      s.damage = max_damage_;
      step.strain_after_initiation = after;
      step.failed = true;
      return step;
    }
  }
  step.strain_after_initiation = after;
  evolve(s, length * after, flow_stress, step);
  return step;
}

DamageStep JohnsonCookDamage::open(DamageState& s, double d_opening, double length) const {
  DamageStep step;
  step.damage_before = s.damage;
  step.failed = s.damage >= max_damage_;
  if (step.failed || !(d_opening > 0.0) || s.initiation < 1.0) return step;
  step.strain_after_initiation = d_opening;
  evolve(s, length * d_opening, s.initiation_yield_stress, step);
  return step;
}

void JohnsonCookDamage::evolve(DamageState& s, double du, double stress, DamageStep& step) const {
  s.plastic_displacement += du;
  double D;
  if (evolution_ == DamageEvolution::Linear) {
    D = s.plastic_displacement * s.initiation_yield_stress * 0.5 / s.fracture_energy;  // u_pl / u_f
  } else {
    // 1 - D = exp(-W/G_f) with W = int sigma_y du_pl: multiply the intact fraction by exp(-dW/G_f),
    // so no extra state is needed for W.
    D = 1.0 - (1.0 - s.damage) * std::exp(-stress * du / s.fracture_energy);
  }
  if (D >= max_damage_) {
    D = max_damage_;
    step.failed = true;
  }
  s.damage = D > s.damage ? D : s.damage;  // never heals
}

PlaneStrainTensor degraded_stress(const PlaneStrainTensor& s, double pressure, double D, double deviator_share,
                                  bool failed) {
  if (failed) {  // compression only, and the closed crack's friction (share phi, 0 without it)
    const double pc = pressure > 0.0 ? pressure : 0.0;
    const double k = deviator_share;
    return {k * s.xx - pc, k * s.yy - pc, k * s.zz - pc, k * s.xy};
  }
  const double keep = deviator_share;
  const double pe = pressure >= 0.0 ? pressure : (1.0 - D) * pressure;
  return {keep * s.xx - pe, keep * s.yy - pe, keep * s.zz - pe, keep * s.xy};
}

}  // namespace mpmcut
