#pragma once
// Johnson-Cook flow stress (Johnson & Cook 1983; theory_materials.md §2):
//
//   sigma_y = [A + B eps_p^n] [1 + C ln(epsdot*)] [1 - T*^m],
//   epsdot* = max(epsdot/epsdot0, 1),   T* = clamp((T - T_r)/(T_m - T_r), 0, 1).
//
// The rate term is floored at epsdot* = 1 (no rate effect below epsdot0, as in Abaqus), so ln(0)
// never occurs; T* is clamped at 0 below room temperature (pow of a negative base is NaN for a
// non-integer m) and at 1, where the strength is zero (melt).
//
// With flow_softening = "tanh" (Calamaz et al. 2008, Sima & Oezel 2010; theory_materials.md 2.5) the
// hardening term is damped at large strain and a temperature-dependent softening factor multiplies it:
//
//   sigma_y = [A + B eps^n exp(-eps^a)] [1 + C ln(epsdot*)] [1 - T*^m] W,
//   W = D + (1 - D) tanh(1/(eps + S)^c)^s,   D = 1 - (T/T_m)^d,   S = (T/T_m)^b,
//
// so that a hot band that has flowed far carries less stress: the strain softening behind the
// adiabatic shear bands of serrated titanium chips.
#include "physics/material_parameters.hpp"

namespace mpmcut {

// sigma_y and its partial derivatives at one state.
struct FlowStressValue {
  double stress = 0.0;         // sigma_y, Pa
  double d_strain = 0.0;       // d sigma_y / d eps_p, Pa
  double d_rate = 0.0;         // d sigma_y / d epsdot_p, Pa s
  double d_temperature = 0.0;  // d sigma_y / d T, Pa/K
  double log_rate_ratio = 0.0; // max(ln(epsdot/epsdot0), 0), filled only when C != 0 (saves a log);
                               // reused by the damage-initiation law
};

class JohnsonCookFlowStress {
 public:
  // Reads A, B, n, C, m, epsdot0, T_r, T_m; throws std::invalid_argument when they are unusable.
  explicit JohnsonCookFlowStress(const MaterialParameters& params);

  // T* clamped to [0, 1].
  double homologous_temperature(double temperature_K) const;
  // max(ln(epsdot/epsdot0), 0): the floored logarithm shared by flow and damage.
  double log_rate_ratio(double plastic_strain_rate) const;

  double hardening(double plastic_strain) const;           // A + B eps^n (TANH: x exp(-eps^a)), Pa
  double rate_factor(double plastic_strain_rate) const;    // 1 + C ln(epsdot*) >= 1
  double thermal_factor(double temperature_K) const;       // 1 - T*^m in [0, 1]
  // W of the TANH softening in [D, 1]; 1 without it.
  double softening_factor(double plastic_strain, double temperature_K) const;

  double yield_stress(double plastic_strain, double plastic_strain_rate, double temperature_K) const;
  // Yield stress with its partial derivatives (used by the Newton solve of the return mapping).
  FlowStressValue evaluate(double plastic_strain, double plastic_strain_rate, double temperature_K) const;

  // T >= T_m: zero strength, zero deviator.
  bool melted(double temperature_K) const { return temperature_K >= melting_temperature_; }

  double initial_yield_stress() const { return A_; }
  // A stress below which a state at or below room temperature is surely elastic at any strain and rate:
  // A, times D(T_r) with the TANH softening (H >= A, the rate factor >= 1, W >= D(T) >= D(T_r) there).
  double elastic_limit_at_room_temperature() const;
  bool softens() const { return tanh_softening_; }
  bool rate_dependent() const { return rate_dependent_; }

 private:
  double A_, B_, n_, C_, m_;
  double reference_rate_, inverse_reference_rate_;
  double room_temperature_, melting_temperature_, inverse_temperature_range_;
  bool hardening_is_linear_;  // n == 1: no pow
  bool rate_dependent_;       // C != 0: otherwise no log
  bool thermal_is_linear_;    // m == 1: no pow
  bool tanh_softening_;       // flow_softening = "tanh"
  double tanh_a_, tanh_b_, tanh_c_, tanh_d_, tanh_s_;

  // W and its partial derivatives dW/deps, dW/dT.
  struct Softening {
    double factor = 1.0, d_strain = 0.0, d_temperature = 0.0;
  };
  Softening softening(double plastic_strain, double temperature_K) const;
};

}  // namespace mpmcut
