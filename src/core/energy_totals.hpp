#pragma once
// The run's energy ledger, J per m of thickness (docs/cutting.md, "Energy balance").
namespace mpmcut {

// Global energies. Dissipated terms accumulate from t = 0.
struct EnergyTotals {
  double kinetic = 0.0;
  double elastic = 0.0;
  double plastic_work = 0.0;
  double heat = 0.0;               // plastic heating + frictional heating
  double damage_dissipation = 0.0;
  double friction = 0.0;           // frictional work at rigid contacts
  double viscous = 0.0;            // work of the artificial bulk viscosity (shocks), >= 0
  double external_work = 0.0;      // work by rigid bodies + body force
  // Algorithmic energy changes, so that the ledger closes (docs/cutting.md, "Energy balance"):
  double transfer_dissipation = 0.0;   // kinetic energy the FLIP/PIC blend removes in G2P, >= 0 in practice
  double contact_safeguard = 0.0;      // kinetic energy the rigid-body push-out safeguard removes, >= 0
  double removed_energy = 0.0;         // kinetic + elastic energy of particles removed from the domain
  double initial = 0.0;                // kinetic + elastic at t = 0
};

// (kinetic + elastic + every dissipated or removed term) - (initial + external work): zero for a
// ledger that accounts for every joule.
inline double energy_balance_residual(const EnergyTotals& e) {
  return e.kinetic + e.elastic + e.plastic_work + e.damage_dissipation + e.friction + e.viscous +
         e.transfer_dissipation + e.contact_safeguard + e.removed_energy - e.initial - e.external_work;
}

}  // namespace mpmcut
