#include "physics/flow_stress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mpmcut {

JohnsonCookFlowStress::JohnsonCookFlowStress(const MaterialParameters& p)
    : A_(p.jc_A),
      B_(p.jc_B),
      n_(p.jc_n),
      C_(p.jc_C),
      m_(p.jc_m),
      reference_rate_(p.reference_strain_rate),
      inverse_reference_rate_(0.0),
      room_temperature_(p.room_temperature),
      melting_temperature_(p.melting_temperature),
      inverse_temperature_range_(0.0),
      hardening_is_linear_(p.jc_n == 1.0),
      rate_dependent_(p.jc_C != 0.0),
      thermal_is_linear_(p.jc_m == 1.0),
      tanh_softening_(p.flow_softening == FlowSoftening::Tanh),
      tanh_a_(p.tanh_a),
      tanh_b_(p.tanh_b),
      tanh_c_(p.tanh_c),
      tanh_d_(p.tanh_d),
      tanh_s_(p.tanh_s) {
  require_valid(p, flow_stress_parameter_table(), thermal_parameter_table());
  inverse_reference_rate_ = 1.0 / reference_rate_;
  inverse_temperature_range_ = 1.0 / (melting_temperature_ - room_temperature_);
}

double JohnsonCookFlowStress::homologous_temperature(double T) const {
  const double t = (T - room_temperature_) * inverse_temperature_range_;
  return t <= 0.0 ? 0.0 : (t >= 1.0 ? 1.0 : t);
}

double JohnsonCookFlowStress::log_rate_ratio(double rate) const {
  const double r = rate * inverse_reference_rate_;
  return r > 1.0 ? std::log(r) : 0.0;  // floor epsdot* >= 1 (also catches rate = 0 and NaN-free)
}

double JohnsonCookFlowStress::hardening(double eps) const {
  if (eps <= 0.0 || B_ == 0.0) return A_;
  const double damping = tanh_softening_ ? std::exp(-std::pow(eps, tanh_a_)) : 1.0;
  return A_ + B_ * (hardening_is_linear_ ? eps : std::pow(eps, n_)) * damping;
}

JohnsonCookFlowStress::Softening JohnsonCookFlowStress::softening(double eps, double T) const {
  Softening w;
  if (!tanh_softening_) return w;
  const double tau = std::clamp(T / melting_temperature_, 0.0, 1.0);  // absolute T/T_m, as published
  const double tau_d = std::pow(tau, tanh_d_);
  const double D = 1.0 - tau_d;
  const double S = std::pow(tau, tanh_b_);
  const double x = (eps > 0.0 ? eps : 0.0) + S;
  // u = x^-c: beyond u = 20, tanh(u) = 1 in double precision and W = 1 with zero slopes (also guards
  // x = 0 and an overflowing power).
  const double u = x > 0.0 ? std::pow(x, -tanh_c_) : std::numeric_limits<double>::infinity();
  if (!(u < 20.0)) return w;
  const double g = std::tanh(u);
  const double G = std::pow(g, tanh_s_);
  const double dG_dx = tanh_s_ * G / g * (1.0 - g * g) * (-tanh_c_ * u / x);
  w.factor = D + (1.0 - D) * G;
  w.d_strain = eps > 0.0 ? (1.0 - D) * dG_dx : 0.0;
  if (tau > 0.0 && tau < 1.0) {
    const double dD_dT = -tanh_d_ * tau_d / tau / melting_temperature_;
    const double dS_dT = tanh_b_ * S / tau / melting_temperature_;
    w.d_temperature = dD_dT * (1.0 - G) + (1.0 - D) * dG_dx * dS_dT;
  }
  return w;
}

double JohnsonCookFlowStress::softening_factor(double eps, double T) const { return softening(eps, T).factor; }

double JohnsonCookFlowStress::elastic_limit_at_room_temperature() const {
  if (!tanh_softening_) return A_;
  return A_ * (1.0 - std::pow(std::clamp(room_temperature_ / melting_temperature_, 0.0, 1.0), tanh_d_));
}

double JohnsonCookFlowStress::rate_factor(double rate) const {
  return rate_dependent_ ? 1.0 + C_ * log_rate_ratio(rate) : 1.0;
}

double JohnsonCookFlowStress::thermal_factor(double T) const {
  const double t = homologous_temperature(T);
  if (t <= 0.0) return 1.0;
  if (t >= 1.0) return 0.0;
  return 1.0 - (thermal_is_linear_ ? t : std::pow(t, m_));
}

double JohnsonCookFlowStress::yield_stress(double eps, double rate, double T) const {
  const double y = hardening(eps) * rate_factor(rate) * thermal_factor(T);
  return tanh_softening_ ? y * softening_factor(eps, T) : y;
}

FlowStressValue JohnsonCookFlowStress::evaluate(double eps, double rate, double T) const {
  FlowStressValue v;
  // Strain hardening H and dH/deps. With n < 1 the slope is infinite at eps = 0; the return
  // mapping never asks for it there (it brackets), but report +inf rather than a NaN.
  double H = A_, dH = 0.0;
  if (B_ != 0.0) {
    if (hardening_is_linear_) {
      H += B_ * (eps > 0.0 ? eps : 0.0);
      dH = B_;
    } else if (eps > 0.0) {
      const double en = std::pow(eps, n_);
      H += B_ * en;
      dH = n_ * B_ * en / eps;
    } else {
      dH = n_ < 1.0 ? std::numeric_limits<double>::infinity() : (n_ == 1.0 ? B_ : 0.0);
    }
  }
  // TANH damping of the hardening term: B eps^n exp(-eps^a), slope B eps^n E (n/eps - a eps^(a-1)).
  if (tanh_softening_ && B_ != 0.0 && eps > 0.0) {
    const double ea = std::pow(eps, tanh_a_);
    const double E = std::exp(-ea);
    const double Ben = H - A_;  // B eps^n
    H = A_ + Ben * E;
    dH = E * (dH - Ben * tanh_a_ * ea / eps);
  }
  // Rate factor R and dR/depsdot (zero on the floor).
  double R = 1.0, dR = 0.0;
  if (rate_dependent_) {
    const double r = rate * inverse_reference_rate_;
    if (r > 1.0) {
      v.log_rate_ratio = std::log(r);
      R = 1.0 + C_ * v.log_rate_ratio;
      dR = C_ / rate;
    }
  }
  // Thermal factor Theta and dTheta/dT (zero outside 0 < T* < 1).
  double Th = 1.0, dTh = 0.0;
  const double t = (T - room_temperature_) * inverse_temperature_range_;
  if (t >= 1.0) {
    Th = 0.0;
  } else if (t > 0.0) {
    if (thermal_is_linear_) {
      Th = 1.0 - t;
      dTh = -inverse_temperature_range_;
    } else {
      const double tm = std::pow(t, m_);
      Th = 1.0 - tm;
      dTh = -m_ * tm / t * inverse_temperature_range_;
    }
  }
  const Softening W = softening(eps, T);
  v.stress = H * R * Th * W.factor;
  v.d_strain = (dH * W.factor + H * W.d_strain) * R * Th;
  v.d_rate = H * dR * Th * W.factor;
  v.d_temperature = H * R * (dTh * W.factor + Th * W.d_temperature);
  if (Th == 0.0) v.d_strain = 0.0;  // avoid inf * 0 at eps = 0 in the melt
  return v;
}

}  // namespace mpmcut
