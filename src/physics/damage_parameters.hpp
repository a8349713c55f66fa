#pragma once
// Johnson-Cook damage initiation and Hillerborg evolution with a rate-dependent fracture energy
// (damage.hpp): the struct and its parameter table.
#include "physics/parameter_table.hpp"

namespace mpmcut {

enum class DamageEvolution { Linear, Exponential };

struct DamageParameters {
  // Initiation: eps_f = (D1 + D2 exp(D3 eta))(1 + D4 ln epsdot*)(1 + D5 T*)
  bool damage_enabled = false;
  double jc_D1 = 0.0, jc_D2 = 0.0, jc_D3 = 0.0, jc_D4 = 0.0, jc_D5 = 0.0;
  double min_failure_strain = 0.01;  // clamp for eps_f, -
  // No ductile fracture at or below this stress triaxiality eta = -p/q: neither initiation nor softening
  // advance there (Bao & Wierzbicki 2005: -1/3). theory_materials.md §5.7.
  double damage_triaxiality_cutoff = -1.0 / 3.0;
  // Hillerborg evolution after initiation
  DamageEvolution damage_evolution = DamageEvolution::Linear;
  double fracture_energy = 0.0;  // G_f, J/m^2 (or from K_IC); the low-rate value when rate-dependent
  // Ductile-to-brittle transition of the fracture energy with the plastic strain rate at initiation:
  // G_f(rate) = G_b + (G_f - G_b) / (1 + (rate/rate_t)^n)   (theory_materials.md §5.6)
  double fracture_energy_brittle = 0.0;          // G_b, J/m^2 (high-rate limit)
  double fracture_transition_strain_rate = 0.0;  // rate_t, 1/s (0: G_f does not depend on rate)
  double fracture_transition_exponent = 2.0;     // n, -
  double max_damage = 0.999;  // D at which a particle counts as fully failed, -
  // Coulomb coefficient across a closed crack: a damaged particle under compression p keeps, of the shear its
  // damage takes away, up to crack_friction * p (theory_materials.md §5.8). 0: a damaged particle keeps only
  // (1 - D) of its shear whatever the pressure.
  double crack_friction = 0.0;  // mu_c, -

  bool operator==(const DamageParameters&) const = default;
};

inline const ParameterTable<DamageParameters>& damage_parameter_table() {
  using P = DamageParameters;
  const Range D = Range::closed(-100.0, 100.0);
  static const ParameterTable<P> table{
      "Johnson-Cook damage initiation and Hillerborg evolution",
      {
          flag("damage", &P::damage_enabled, "JC damage initiation + Hillerborg evolution")
              .used_with(InUse::JohnsonCook),
          // D1 and D2 set the failure strain's level: left out, it would be 0, clamped silently to min_failure_strain.
          number("jc_D1", &P::jc_D1, "-", D, "eps_f = (D1 + D2 exp(D3 eta))(1 + D4 ln epsdot*)(1 + D5 T*)")
              .capped_below()
              .used_with(InUse::Damage)
              .required_key(),
          number("jc_D2", &P::jc_D2, "-", D, "D2").capped_below().used_with(InUse::Damage).required_key(),
          number("jc_D3", &P::jc_D3, "-", D, "D3").capped_below(),
          number("jc_D4", &P::jc_D4, "-", D, "D4").capped_below(),
          number("jc_D5", &P::jc_D5, "-", D, "D5").capped_below(),
          number("min_failure_strain", &P::min_failure_strain, "-",
                 Range::open_closed(0.0, 100.0, "", "eps_f clamp; with D1 < 0 eps_f can reach 0"),
                 "lower clamp of eps_f")
              .used_with(InUse::Damage),
          number("damage_triaxiality_cutoff", &P::damage_triaxiality_cutoff, "-", D,
                 "eta_c: plastic flow at eta <= eta_c neither initiates nor softens (Bao & Wierzbicki 2005; "
                 "theory_materials.md §5.7)")
              .capped_below(),
          choice<P, &P::damage_evolution>("damage_evolution", {"linear", "exponential"}, "softening after initiation"),
          // G_f = 0 is Abaqus' "instantaneous failure", which it warns causes dynamic instabilities.
          number("fracture_energy", &P::fracture_energy, "J/m^2",
                 Range::open_closed(0.0, 1e8, "", "positive when damage = true; or give fracture_toughness K_IC"),
                 "G_f (the low-rate value when rate-dependent)")
              .used_with(InUse::Damage),
          number("fracture_energy_brittle", &P::fracture_energy_brittle, "J/m^2",
                 Range::open_closed(0.0, 1e8, "",
                                    "the high-rate fracture energy, when fracture_transition_strain_rate > 0"),
                 "G_b, the high-rate limit of a rate-dependent G_f")
              .used_with(InUse::RateDependentFractureEnergy),
          number("fracture_transition_strain_rate", &P::fracture_transition_strain_rate, "1/s",
                 Range::closed(0.0, 1e12, "", "0 = fracture energy independent of rate"),
                 "epsdot_t: G_f(rate) = G_b + (G_f - G_b)/(1 + (rate/epsdot_t)^n), rate = plastic strain rate at "
                 "initiation, fixed per particle (theory_materials.md §5.6)"),
          number("fracture_transition_exponent", &P::fracture_transition_exponent, "-", Range::open_closed(0.0, 100.0),
                 "n, sharpness of that ductile-to-brittle step")
              .used_with(InUse::RateDependentFractureEnergy),
          number("max_damage", &P::max_damage, "-", Range::open_closed(0.0, 1.0),
                 "D at which a particle counts as failed")
              .model_limit_above(),
          number("crack_friction", &P::crack_friction, "-",
                 Range::closed(0.0, 10.0, "", "0 = a damaged particle's shear is (1 - D) of the undamaged shear"),
                 "mu_c: a damaged particle under compression p keeps, of the shear its damage takes away, up to "
                 "mu_c p: Coulomb friction across its closed crack (theory_materials.md §5.8)")
              .used_with(InUse::Damage)
              .written_if_set(),
      },
      {}};
  return table;
}

}  // namespace mpmcut
