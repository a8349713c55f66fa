#include "analysis/fracture_accounting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "analysis/chip_pieces.hpp"

namespace mpmcut {

namespace {

// Points bucketed in square cells of side `cell`, for neighbour searches within `cell`.
class Buckets {
 public:
  Buckets(const std::vector<Vec2>& x, double cell) : x_(x), cell_(cell) {
    for (std::size_t i = 0; i < x.size(); ++i) map_[key(x[i])].push_back(i);
  }
  template <class F>
  void near(const Vec2& y, F&& f) const {
    const auto [cx, cy] = cell_of(y);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = map_.find(pack(cx + dx, cy + dy));
        if (it == map_.end()) continue;
        for (std::size_t j : it->second) f(j);
      }
  }

 private:
  std::pair<std::int64_t, std::int64_t> cell_of(const Vec2& y) const {
    return {static_cast<std::int64_t>(std::floor(y.x() / cell_)), static_cast<std::int64_t>(std::floor(y.y() / cell_))};
  }
  static std::uint64_t pack(std::int64_t a, std::int64_t b) {
    return (static_cast<std::uint64_t>(a) << 32) ^ (static_cast<std::uint64_t>(b) & 0xffffffffULL);
  }
  std::uint64_t key(const Vec2& y) const {
    const auto [a, b] = cell_of(y);
    return pack(a, b);
  }
  const std::vector<Vec2>& x_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> map_;
};

bool fully_damaged(const Particles& p, std::size_t i, const ChipAnalysisSetup& s) {
  const auto m = static_cast<std::size_t>(p.material[i]);
  return m < s.max_damage.size() && p.damage[i] >= s.max_damage[m] - 1e-12;
}

double crack_length_of(const Particles& p, std::size_t i) {
  return p.fracture_energy[i] > 0.0 ? p.damage_dissipation[i] / p.fracture_energy[i] : 0.0;
}

}  // namespace

double equivalent_crack_length_m(const Particles& p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) sum += crack_length_of(p, i);
  return sum;
}

std::vector<char> boundary_particles(const std::vector<Vec2>& x, double spacing, double radius,
                                     double offset_fraction) {
  if (!(radius > 0.0)) radius = 2.0 * spacing;
  const Buckets buckets(x, radius);
  const double r2 = radius * radius;
  std::vector<char> out(x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    Vec2 offset = Vec2::Zero();
    std::size_t n = 0;
    buckets.near(x[i], [&](std::size_t j) {
      const Vec2 d = x[j] - x[i];
      if (j == i || d.squaredNorm() >= r2) return;
      offset += d;
      ++n;
    });
    out[i] = n == 0 || (offset / static_cast<double>(n)).norm() > offset_fraction * spacing;
  }
  return out;
}

void chip_crack_lengths(const ChipAnalysis& a, double t0, std::vector<double>& segment_cracks,
                        std::vector<double>& piece_separations) {
  segment_cracks.clear();
  piece_separations.clear();
  // The gullets of the whole chip, the entry's included: all of it is new surface.
  const Segmentation whole = measure_segmentation(a.profile, a.prominence_m, a.min_pitch_m, a.narrow_width_m);
  const std::vector<double>& y = whole.thickness_m;
  const ProfileExtrema& e = whole.extrema;
  for (std::size_t v : e.valleys) {
    // The peaks on either side of the valley (the extrema alternate).
    double sum = 0.0;
    int n = 0;
    const auto after = std::upper_bound(e.peaks.begin(), e.peaks.end(), v);
    if (after != e.peaks.end()) sum += y[*after], ++n;
    if (after != e.peaks.begin()) sum += y[*(after - 1)], ++n;
    if (n > 0 && sum / n > y[v]) segment_cracks.push_back(sum / n - y[v]);
  }
  const Segmentation& g = whole;
  const double thickness = g.peak_height_m ? *g.peak_height_m : g.mean_thickness_m ? *g.mean_thickness_m : t0;
  for (std::size_t k = 1; k < a.pieces; ++k) piece_separations.push_back(thickness);
}

FractureAccounting account_fracture(const Particles& p, const ChipAnalysisSetup& s, const ChipAnalysis& chip,
                                    double ledger) {
  FractureAccounting f;
  f.ledger_damage_dissipation_J_per_m = ledger;
  double weighted_gf = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    f.particle_damage_dissipation_J_per_m += p.damage_dissipation[i];
    f.equivalent_crack_length_m += crack_length_of(p, i);
    weighted_gf += p.damage_dissipation[i] * p.fracture_energy[i];
  }
  f.removed_dissipation_J_per_m = std::max(ledger - f.particle_damage_dissipation_J_per_m, 0.0);
  if (f.particle_damage_dissipation_J_per_m > 0.0 && weighted_gf > 0.0)
    f.removed_crack_length_m =
        f.removed_dissipation_J_per_m / (weighted_gf / f.particle_damage_dissipation_J_per_m);

  f.machined_surface_length_m = s.tool_travel_m;
  chip_crack_lengths(chip, s.uncut_chip_thickness_m, f.segment_crack_lengths_m, f.piece_separation_lengths_m);
  f.new_surface_length_m = f.machined_surface_length_m;
  for (double l : f.segment_crack_lengths_m) f.new_surface_length_m += l;
  for (double l : f.piece_separation_lengths_m) f.new_surface_length_m += l;

  // --- Regions ------------------------------------------------------------------------------------
  const double d = s.particle_spacing_m(), h = s.cell_size_m;
  const std::vector<char> is_chip = chip_particles(p, s);
  std::vector<std::size_t> work;  // workpiece particles
  std::vector<Vec2> x;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.body[i] == s.workpiece_body) work.push_back(i), x.push_back(p.position[i]);
  // Chip pieces as the chip analysis finds them: a particle of a small piece is debris.
  std::vector<std::size_t> chip_index;
  std::vector<Vec2> chip_x;
  std::vector<char> bonds;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (is_chip[i]) chip_index.push_back(i), chip_x.push_back(p.position[i]), bonds.push_back(!fully_damaged(p, i, s));
  std::vector<char> fragment(p.size(), 0);
  if (!chip_x.empty()) {
    const Pieces pieces = find_pieces(chip_x, s.thresholds.link_spacings * d, bonds);
    for (std::size_t k = 0; k < chip_index.size(); ++k)
      fragment[chip_index[k]] = pieces.size[static_cast<std::size_t>(pieces.label[k])] < chip.significant_piece_particles;
  }
  // The boundary of the workpiece's particle cloud, less the faces against the tool (contact, not free).
  const std::vector<char> boundary = boundary_particles(x, d);
  std::vector<Vec2> free_boundary;
  Vec2 normal;
  for (std::size_t k = 0; k < work.size(); ++k)
    if (boundary[k] && s.tool.signed_distance(x[k], normal) > h) free_boundary.push_back(x[k]);
  const Buckets near_free(free_boundary, h);
  const auto within_a_cell_of_free_surface = [&](const Vec2& y) {
    bool hit = false;
    near_free.near(y, [&](std::size_t j) { hit = hit || (free_boundary[j] - y).squaredNorm() <= h * h; });
    return hit;
  };

  f.regions = {{"workpiece", "workpiece particles that are not chip: the machined surface layer and the chip root "
                             "below it (docs/analysis.md)"},
               {"chip_free_surface_layer", "chip particles of significant pieces within one cell of a free "
                                           "boundary of the particle cloud (not against the tool): free surface, "
                                           "gullets, crack faces"},
               {"chip_interior", "the other chip particles of significant pieces: shear bands, segment cores, the "
                                 "layer along the rake face"},
               {"chip_fragments", "chip particles in pieces too small to count: debris and isolated failed particles"}};
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] != s.workpiece_body) continue;
    std::size_t r = 0;
    if (is_chip[i]) r = fragment[i] ? 3 : within_a_cell_of_free_surface(p.position[i]) ? 1 : 2;
    DissipationRegion& g = f.regions[r];
    g.dissipation_J_per_m += p.damage_dissipation[i];
    g.crack_length_m += crack_length_of(p, i);
    ++g.particles;
    if (fully_damaged(p, i, s)) ++g.failed_particles;
  }
  return f;
}

SurfaceBalance surface_balance(const FractureAccounting& f) {
  SurfaceBalance b;
  for (const DissipationRegion& r : f.regions)
    (r.name == "workpiece" ? b.workpiece_equivalent_crack_length_m : b.chip_equivalent_crack_length_m) +=
        r.crack_length_m;
  b.chip_equivalent_crack_length_m += f.removed_crack_length_m;
  for (double l : f.segment_crack_lengths_m) b.chip_crack_length_m += l;
  for (double l : f.piece_separation_lengths_m) b.chip_crack_length_m += l;
  b.machined_surface_length_m = f.machined_surface_length_m;
  return b;
}

EnergyPartition energy_partition(double work, double plastic, double damage, double friction, double kinetic,
                                 double elastic, double viscous) {
  EnergyPartition e;
  e.tool_work_J_per_m = work;
  if (!(work > 0.0)) return e;
  e.plastic = plastic / work;
  e.damage = damage / work;
  e.friction = friction / work;
  e.kinetic = kinetic / work;
  e.elastic = elastic / work;
  e.viscous = viscous / work;
  e.remainder = 1.0 - (e.plastic + e.damage + e.friction + e.kinetic + e.elastic + e.viscous);
  return e;
}

nlohmann::json fracture_json(const FractureAccounting& f, const EnergyPartition& e) {
  nlohmann::json j;
  j["damage_dissipation_J_per_m"] = f.ledger_damage_dissipation_J_per_m;
  j["equivalent_crack_length_mm"] = f.total_equivalent_crack_length_m() * 1e3;
  j["new_surface_length_mm"] = f.new_surface_length_m * 1e3;
  j["crack_length_ratio"] =
      f.new_surface_length_m > 0.0 ? nlohmann::json(f.total_equivalent_crack_length_m() / f.new_surface_length_m)
                                   : nlohmann::json(nullptr);
  j["equivalent_crack_length_of_particles_mm"] = f.equivalent_crack_length_m * 1e3;
  j["removed_damage_dissipation_J_per_m"] = f.removed_dissipation_J_per_m;
  j["removed_equivalent_crack_length_mm"] = f.removed_crack_length_m * 1e3;
  j["machined_surface_length_mm"] = f.machined_surface_length_m * 1e3;
  nlohmann::json seg = nlohmann::json::array(), sep = nlohmann::json::array();
  for (double l : f.segment_crack_lengths_m) seg.push_back(l * 1e3);
  for (double l : f.piece_separation_lengths_m) sep.push_back(l * 1e3);
  j["segment_crack_lengths_mm"] = seg;
  j["piece_separation_lengths_mm"] = sep;
  nlohmann::json regions = nlohmann::json::object();
  for (const DissipationRegion& r : f.regions)
    regions[r.name] = {{"damage_dissipation_J_per_m", r.dissipation_J_per_m},
                       {"equivalent_crack_length_mm", r.crack_length_m * 1e3},
                       {"particles", r.particles},
                       {"failed_particles", r.failed_particles},
                       {"definition", r.definition}};
  j["regions"] = regions;
  const SurfaceBalance b = surface_balance(f);
  const auto ratio = [](double a, double c) { return c > 0.0 ? nlohmann::json(a / c) : nlohmann::json(nullptr); };
  j["chip"] = {{"equivalent_crack_length_mm", b.chip_equivalent_crack_length_m * 1e3},
               {"crack_length_mm", b.chip_crack_length_m * 1e3},
               {"crack_length_ratio", ratio(b.chip_equivalent_crack_length_m, b.chip_crack_length_m)},
               {"definition", "damage of the chip's regions and of removed particles, as crack length, against the "
                              "chip's own cracks (gullets + piece separations)"}};
  j["workpiece"] = {{"equivalent_crack_length_mm", b.workpiece_equivalent_crack_length_m * 1e3},
                    {"machined_surface_length_mm", b.machined_surface_length_m * 1e3},
                    {"crack_length_ratio", ratio(b.workpiece_equivalent_crack_length_m, b.machined_surface_length_m)},
                    {"definition", "damage of the workpiece region, as crack length, against the machined surface"}};
  j["energy_partition"] = {{"tool_work_J_per_m", e.tool_work_J_per_m},
                           {"plastic", e.plastic},
                           {"damage", e.damage},
                           {"friction", e.friction},
                           {"kinetic", e.kinetic},
                           {"elastic", e.elastic},
                           {"viscous", e.viscous},
                           {"remainder", e.remainder}};
  j["definition"] = "docs/analysis.md";
  return j;
}

std::string fracture_summary_text(const FractureAccounting& f, const EnergyPartition& e) {
  std::string s = fmt::format(
      "fracture: damage dissipation {:.3g} J/m = a crack of {:.3f} mm (dissipation / G_f); real new surface {:.3f} mm "
      "(machined {:.3f} mm, {} gullet(s), {} separation(s))\n",
      f.ledger_damage_dissipation_J_per_m, f.total_equivalent_crack_length_m() * 1e3, f.new_surface_length_m * 1e3,
      f.machined_surface_length_m * 1e3, f.segment_crack_lengths_m.size(), f.piece_separation_lengths_m.size());
  s += "  where (crack mm):";
  for (const DissipationRegion& r : f.regions) s += fmt::format(" {} {:.3f};", r.name, r.crack_length_m * 1e3);
  s += fmt::format(" removed {:.3f}\n", f.removed_crack_length_m * 1e3);
  const SurfaceBalance b = surface_balance(f);
  s += fmt::format("  chip: damage = {:.3f} mm of crack against {:.3f} mm of its own cracks; workpiece: {:.3f} mm against "
                   "{:.3f} mm of machined surface\n",
                   b.chip_equivalent_crack_length_m * 1e3, b.chip_crack_length_m * 1e3,
                   b.workpiece_equivalent_crack_length_m * 1e3, b.machined_surface_length_m * 1e3);
  s += fmt::format(
      "  tool work {:.3g} J/m: plastic {:.1f} %, damage {:.1f} %, friction {:.1f} %, kinetic {:.1f} %, elastic {:.1f} "
      "%, viscous {:.1f} %, remainder {:.1f} %\n",
      e.tool_work_J_per_m, 100 * e.plastic, 100 * e.damage, 100 * e.friction, 100 * e.kinetic, 100 * e.elastic,
      100 * e.viscous, 100 * e.remainder);
  return s;
}

}  // namespace mpmcut
