#pragma once
// Ductile damage: Johnson-Cook initiation and Hillerborg (fracture-energy) evolution
// (Johnson & Cook 1985; Hillerborg, Modeer & Petersson 1976; theory_materials.md §5).
//
// Initiation:  eps_f = [D1 + D2 exp(D3 eta)] [1 + D4 ln epsdot*] [1 + D5 T*],  eps_f >= min_failure_strain,
//              eta = -p/q (tension positive), epsdot* floored at 1, T* clamped to [0, 1];
//              omega += d(eps_p)/eps_f while omega < 1 (frozen once it reaches 1).
// Evolution after initiation:  u_pl += L (d(eps_p) + d(eps_open))  (L = cell size; eps_open: the
//              volumetric opening of the tensile cut-off, see johnson_cook.hpp)
//              linear:       D = u_pl/u_f,  u_f = 2 G_f/sigma_y0  (sigma_y0 = flow stress at initiation)
//              exponential:  D = 1 - exp(-int sigma_y du_pl / G_f)  (sigma_y undamaged)
//              G_f is fixed per particle at initiation from its plastic strain rate there:
//              G_f(rate) = G_b + (G_f,low - G_b) / (1 + (rate/rate_t)^n), or G_f,low when rate_t = 0
//              (a ductile-to-brittle transition of the shear fracture; theory_materials.md §5.6).
//              D <= max_damage; D = max_damage means fully failed.
// Degradation: sigma = k s - p_eff I,  p_eff = p if p >= 0 (compression kept) else (1 - D) p;
//              k = 1 - D (1 - phi), phi = min(1, sqrt(3) mu_c p / q) for p > 0, else 0: a closed crack's faces
//              carry Coulomb friction (mu_c = crack_friction; mu_c = 0 gives k = 1 - D). The cracked part D phi s
//              is a Coulomb slider: it stores D phi^2 s:s/(4G) and dissipates the rest of its work (heat);
//              failed: sigma = phi s - max(p, 0) I (s = 0 without crack friction).
#include <numbers>

#include "physics/material_parameters.hpp"
#include "core/tensor.hpp"

namespace mpmcut {

// The per-particle damage variables (mirrors the Particles arrays of the same names).
struct DamageState {
  double initiation = 0.0;               // omega, -
  double damage = 0.0;                   // D, -
  double plastic_displacement = 0.0;     // u_pl since initiation, m
  double initiation_yield_stress = 0.0;  // sigma_y0, Pa
  double fracture_energy = 0.0;          // G_f of this particle, fixed at initiation, J/m^2
};

// What one plastic increment did to the damage state.
struct DamageStep {
  double strain_before_initiation = 0.0;  // part of d(eps_p) spent while omega < 1
  double strain_after_initiation = 0.0;   // part spent after initiation (drives u_pl)
  double damage_before = 0.0;             // D at the start of the increment
  bool initiated_now = false;             // omega crossed 1 in this increment
  bool failed = false;                    // D reached max_damage (now or before)
};

class JohnsonCookDamage {
 public:
  // Throws std::invalid_argument when damage is enabled with unusable constants.
  explicit JohnsonCookDamage(const MaterialParameters& params);

  bool enabled() const { return enabled_; }
  double max_damage() const { return max_damage_; }
  // Ductile fracture (initiation and softening by plastic flow) needs eta above the cut-off
  // (Bao & Wierzbicki 2005; theory_materials.md §5.7).
  bool fracture_possible(double triaxiality) const { return triaxiality > triaxiality_cutoff_; }
  bool failed(double damage) const { return enabled_ && damage >= max_damage_; }

  bool has_crack_friction() const { return crack_friction_ > 0.0; }
  // phi of the degradation above: the share of the undamaged deviator (von Mises q, Pa) that a closed crack's
  // friction carries under the pressure p (Pa, compression positive): min(1, sqrt(3) mu_c p / q), 0 when open.
  double closed_crack_share(double pressure, double q) const {
    if (!(crack_friction_ > 0.0 && pressure > 0.0)) return 0.0;
    const double limit = std::numbers::sqrt3 * crack_friction_ * pressure;
    return limit < q ? limit / q : 1.0;
  }

  // JC failure strain. log_rate_ratio = max(ln(epsdot/epsdot0), 0), homologous_temperature in [0, 1].
  double failure_strain(double triaxiality, double log_rate_ratio, double homologous_temperature) const;

  // G_f at a plastic strain rate (1/s), J/m^2: the material's fracture_energy when it does not
  // depend on rate, else the ductile-to-brittle transition law above.
  double fracture_energy(double plastic_strain_rate) const;

  // u_f = 2 G_f / sigma_y0 of the linear law, m.
  static double failure_displacement(double fracture_energy, double initiation_yield_stress) {
    return 2.0 * fracture_energy / initiation_yield_stress;
  }

  // Advances omega, u_pl and D over a plastic increment d_eps_p > 0. failure_strain is used only
  // while omega < 1; the increment is split exactly at omega = 1 so that initiation happens at
  // eps_p = eps_f for a constant eps_f. flow_stress = current undamaged sigma_y; length = L;
  // plastic_strain_rate sets G_f when initiation happens in this increment.
  DamageStep advance(DamageState& state, double d_eps_p, double failure_strain, double flow_stress,
                     double length_m, double plastic_strain_rate) const;

  // Crack opening after initiation (mode I): the volumetric strain d_opening that the tensile
  // cut-off of JohnsonCookMaterial turned into opening drives u_pl as plastic strain does,
  // u_pl += L d_opening, at the stress sigma_y0. Does nothing before initiation or after failure.
  DamageStep open(DamageState& state, double d_opening, double length_m) const;

 private:
  // u_pl += du and the damage law; `stress` is the undamaged stress that works through du.
  void evolve(DamageState& state, double du, double stress, DamageStep& step) const;

  bool enabled_;
  double D1_, D2_, D3_, D4_, D5_;
  double min_failure_strain_;
  double triaxiality_cutoff_;
  DamageEvolution evolution_;
  double fracture_energy_;          // G_f (low-rate value when rate-dependent), J/m^2
  double brittle_fracture_energy_;  // G_b, J/m^2
  double transition_rate_;          // rate_t, 1/s (0: rate-independent)
  double transition_exponent_;      // n
  double max_damage_;
  double crack_friction_;  // mu_c
};

// k = 1 - D (1 - phi) of the degradation above: the share of its undamaged deviator that a damaged, not failed,
// particle carries, phi its closed crack's share (JohnsonCookDamage::closed_crack_share). Its equivalent shear is
// (1 - D) q/sqrt(3) + D min(q/sqrt(3), mu_c p): the intact part and the closed crack's friction.
inline double deviator_share(double damage, double closed_crack_share) {
  return 1.0 - damage * (1.0 - closed_crack_share);
}

// eta = -p/q (tension positive; pressure p positive in compression); 0 when q = 0.
inline double stress_triaxiality(double pressure, double q) { return q > 0.0 ? -pressure / q : 0.0; }

// The Cauchy stress carried by a damaged particle from its undamaged deviator and pressure; deviator_share is
// deviator_share above (1 - D without crack friction), for a failed particle the closed crack's share
// phi (0 without crack friction).
PlaneStrainTensor degraded_stress(const PlaneStrainTensor& effective_deviator, double pressure, double damage,
                                  double deviator_share, bool failed);

}  // namespace mpmcut
