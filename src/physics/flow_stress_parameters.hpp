#pragma once
// The Johnson-Cook flow stress constants (flow_stress.hpp) and the smoothing of the plastic strain
// rate it sees: the struct and its parameter table.
#include "physics/parameter_table.hpp"

namespace mpmcut {

// Optional strain softening of the flow stress at large strain and high temperature (flow_stress.hpp).
enum class FlowSoftening { None, Tanh };

// sigma_y = (A + B eps^n)(1 + C ln(epsdot/epsdot0))(1 - T*^m), optionally with the TANH terms
struct FlowStressParameters {
  double jc_A = 0.0;                   // Pa
  double jc_B = 0.0;                   // Pa
  double jc_n = 1.0;                   // -
  double jc_C = 0.0;                   // -
  double jc_m = 1.0;                   // -
  double reference_strain_rate = 1.0;  // epsdot0, 1/s
  // Time scale of the exponential moving average of the plastic strain rate, s (0: no smoothing)
  double strain_rate_smoothing_time = 0.0;
  // TANH softening (Calamaz et al. 2008; Sima & Oezel 2010), all dimensionless; 0 while not in use:
  // sigma_y = [A + B eps^n exp(-eps^a)] R Theta [D + (1 - D) tanh(1/(eps + S)^c)^s],
  // D = 1 - (T/T_m)^d, S = (T/T_m)^b.
  FlowSoftening flow_softening = FlowSoftening::None;
  double tanh_a = 0.0;
  double tanh_b = 0.0;
  double tanh_c = 0.0;
  double tanh_d = 0.0;
  double tanh_s = 0.0;

  bool operator==(const FlowStressParameters&) const = default;
};

inline const ParameterTable<FlowStressParameters>& flow_stress_parameter_table() {
  using P = FlowStressParameters;
  static const ParameterTable<P> table{
      "Johnson-Cook flow stress",
      {
          number("jc_A", &P::jc_A, "Pa", Range::closed(0.0, 1e11), "yield stress A")
              .used_with(InUse::JohnsonCook)
              .required_key(),
          number("jc_B", &P::jc_B, "Pa", Range::closed(0.0, 1e11), "hardening modulus B")
              .used_with(InUse::JohnsonCook)
              .required_key(),
          number("jc_n", &P::jc_n, "-", Range::open_closed(0.0, 10.0), "hardening exponent n")
              .used_with(InUse::JohnsonCook)
              .required_key(),
          number("jc_C", &P::jc_C, "-", Range::closed(0.0, 10.0), "strain-rate coefficient C")
              .used_with(InUse::JohnsonCook)
              .required_key(),
          number("jc_m", &P::jc_m, "-", Range::open_closed(0.0, 10.0), "thermal-softening exponent m")
              .used_with(InUse::JohnsonCook)
              .required_key(),
          number("reference_strain_rate", &P::reference_strain_rate, "1/s", Range::open_closed(0.0, 1e12),
                 "epsdot_0")
              .used_with(InUse::JohnsonCook),
          number("strain_rate_smoothing_time", &P::strain_rate_smoothing_time, "s", Range::closed(0.0, 1.0),
                 "time scale of the moving average of the plastic strain rate; 0 = none"),
          choice<P, &P::flow_softening>("flow_softening", {"none", "tanh"},
                                        "strain softening of the flow stress at large strain and high temperature: "
                                        "none (Johnson-Cook), or the TANH terms of Calamaz et al. 2008 / Sima & Oezel "
                                        "2010 (docs/theory_materials.md 2.5)")
              .written_if_set(),
          number("tanh_a", &P::tanh_a, "-", Range::open_closed(0.0, 10.0),
                 "a: the hardening term B eps^n is damped by exp(-eps^a)")
              .used_with(InUse::TanhSoftening)
              .required_key()
              .written_if_set(),
          number("tanh_b", &P::tanh_b, "-", Range::open_closed(0.0, 50.0), "b: S = (T/T_m)^b")
              .used_with(InUse::TanhSoftening)
              .required_key()
              .written_if_set(),
          number("tanh_c", &P::tanh_c, "-", Range::open_closed(0.0, 10.0), "c: tanh(1/(eps + S)^c)")
              .used_with(InUse::TanhSoftening)
              .required_key()
              .written_if_set(),
          number("tanh_d", &P::tanh_d, "-", Range::open_closed(0.0, 10.0),
                 "d: D = 1 - (T/T_m)^d, the share of the flow stress that does not soften")
              .used_with(InUse::TanhSoftening)
              .required_key()
              .written_if_set(),
          number("tanh_s", &P::tanh_s, "-", Range::open_closed(0.0, 10.0),
                 "s: exponent of the tanh term (1 in Calamaz et al. 2008)")
              .used_with(InUse::TanhSoftening)
              .required_key()
              .written_if_set(),
      },
      {
          {"jc_B", InUse::JohnsonCook, [](const P& p) { return p.jc_A + p.jc_B > 0.0; },
           "positive when jc_A = 0 (a yield stress A + B > 0)"},
      }};
  return table;
}

}  // namespace mpmcut
