#pragma once
// Does the fracture work of a run correspond to real new surface? The damage dissipation of the
// crack band model is G_f per unit crack area (theory_materials.md §6), so each particle's
// dissipation divided by its own G_f (fixed at initiation, rate-dependent) is the crack length it
// stands for; the sum is the run's equivalent crack length (per unit thickness: a length). Beside it,
// the real new surface of a cut: the machined surface (one crack line as long as the tool travel)
// plus the cracks the chip analysis sees (the gullets between segments, the separations between
// pieces). Where the two differ, the damage is smeared rather than a crack. docs/analysis.md.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "analysis/chip_analysis.hpp"
#include "core/particles.hpp"

namespace mpmcut {

// Sum over particles of damage_dissipation / fracture_energy, m (per m of thickness). A particle with
// G_f = 0 (instantaneous failure, no crack-band energy) adds nothing.
double equivalent_crack_length_m(const Particles& p);

// Particles on a boundary of the cloud (free surface, crack face, contact face): the mean offset of
// the neighbours within `radius` is more than `offset_fraction` x `spacing` (0 on a full lattice,
// about 0.8 spacing on a flat face), or the particle has no neighbour. radius 0: 2 spacings.
std::vector<char> boundary_particles(const std::vector<Vec2>& x, double spacing, double radius = 0.0,
                                     double offset_fraction = 0.3);

// Where the damage dissipation of a cut sits, J/m and the crack length it stands for, m.
struct DissipationRegion {
  std::string name;
  std::string definition;
  double dissipation_J_per_m = 0.0;
  double crack_length_m = 0.0;
  std::size_t particles = 0;       // in the region
  std::size_t failed_particles = 0;  // of which fully damaged
};

struct FractureAccounting {
  double ledger_damage_dissipation_J_per_m = 0.0;    // the energy ledger's total (all particles ever)
  double particle_damage_dissipation_J_per_m = 0.0;  // sum over the particles still in the run
  double equivalent_crack_length_m = 0.0;            // sum of dissipation / G_f over those particles
  // Dissipation of particles that left the domain (ledger - particles), and its crack length at the
  // dissipation-weighted mean G_f of the others.
  double removed_dissipation_J_per_m = 0.0;
  double removed_crack_length_m = 0.0;
  // Real new surface: machined surface + segment gullets + piece separations.
  double machined_surface_length_m = 0.0;
  std::vector<double> segment_crack_lengths_m;
  std::vector<double> piece_separation_lengths_m;
  double new_surface_length_m = 0.0;
  std::vector<DissipationRegion> regions;  // a partition of the particles still in the run
  double total_equivalent_crack_length_m() const { return equivalent_crack_length_m + removed_crack_length_m; }
};

// The two surfaces a cut makes, each beside the damage that should have made it: the chip's own cracks
// (gullets + piece separations) against the equivalent crack length of the chip's regions (free-surface
// layer, interior, fragments) and of the removed particles (which leave as debris of the chip); the
// machined surface against that of the workpiece region. The one overall ratio mixes the two: in a cut
// whose machined surface forms by the tool's contact rather than by damage, a chip full of smeared
// damage can still show a ratio near 1.
struct SurfaceBalance {
  double chip_equivalent_crack_length_m = 0.0;
  double chip_crack_length_m = 0.0;  // gullets + separations
  double workpiece_equivalent_crack_length_m = 0.0;
  double machined_surface_length_m = 0.0;
};
SurfaceBalance surface_balance(const FractureAccounting& f);

// The crack lengths of the chip analysis: per valley of the profile, the depth of the gullet (the mean
// thickness of the peaks beside it minus its own), and per significant piece beyond the first, a
// separation line as long as the chip is thick (mean peak height, else mean thickness, else t0).
void chip_crack_lengths(const ChipAnalysis& a, double uncut_chip_thickness_m, std::vector<double>& segment_cracks_m,
                        std::vector<double>& piece_separations_m);

// The accounting of a cut at the analysed instant. `ledger_damage_dissipation` is the energy
// ledger's total (Simulation::energy().damage_dissipation), which includes removed particles.
FractureAccounting account_fracture(const Particles& p, const ChipAnalysisSetup& setup, const ChipAnalysis& chip,
                                    double ledger_damage_dissipation_J_per_m);

// The tool's work split into the ledger's terms, as fractions of the work (remainder = 1 - the sum:
// numerical dissipation of MUSL and contact, and energy of removed particles).
struct EnergyPartition {
  double tool_work_J_per_m = 0.0;
  double plastic = 0.0, damage = 0.0, friction = 0.0, kinetic = 0.0, elastic = 0.0, viscous = 0.0, remainder = 0.0;
};
EnergyPartition energy_partition(double tool_work, double plastic, double damage, double friction, double kinetic,
                                 double elastic, double viscous);

// summary.json's "fracture" object (units in the key names).
nlohmann::json fracture_json(const FractureAccounting& f, const EnergyPartition& e);
std::string fracture_summary_text(const FractureAccounting& f, const EnergyPartition& e);

}  // namespace mpmcut
