#include "analysis/chip_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "analysis/chip_pieces.hpp"
#include "cutting/tool_geometry.hpp"

namespace mpmcut {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The rake-face frame: origin where the (grown) rake face meets the machined surface, u along
// the rake face away from the edge, n its normal into the chip. For a 0 deg rake, u = +y, n = -x.
struct RakeFrame {
  Vec2 origin, u, n;
  Vec2 local(const Vec2& x) const { return Vec2((x - origin).dot(u), (x - origin).dot(n)); }
};

RakeFrame rake_frame(const ChipAnalysisSetup& s) {
  const FaceDirections rake = rake_face_directions(s.rake_angle_deg);  // as the preset builds the rake face
  RakeFrame f;
  f.u = rake.along;
  f.n = rake.normal;
  // The cutting edge: the lowest vertex of the tool's core polygon (leftmost on a tie); the
  // grown rake face is the core's rake line moved r along n.
  const std::vector<Vec2>& v = s.tool.vertices();
  Vec2 edge = v.at(0);
  for (const Vec2& p : v)
    if (p.y() < edge.y() || (p.y() == edge.y() && p.x() < edge.x())) edge = p;
  const Vec2 on_face = edge + s.tool.rounding_radius() * f.n;
  const double along = (s.machined_surface_y_m - on_face.y()) / f.u.y();
  f.origin = on_face + along * f.u;
  return f;
}

bool fully_damaged(const Particles& p, std::size_t i, const ChipAnalysisSetup& s) {
  const auto m = static_cast<std::size_t>(p.material[i]);
  if (m >= s.max_damage.size()) return false;
  return p.damage[i] >= s.max_damage[m] - 1e-12;
}

// Angle of a band direction from the cutting direction, degrees in [0, 180): the band is oriented
// upwards and measured from -x (the direction from the cutting edge towards the uncut material),
// so a primary shear plane from the edge up to the free surface ahead of the tool has angle phi.
double band_angle_deg(Vec2 d) {
  if (d.y() < 0.0 || (d.y() == 0.0 && d.x() > 0.0)) d = -d;
  return std::atan2(d.y(), -d.x()) / kDeg;
}

void peak_in(PeakTemperature& peak, const Particles& p, std::size_t i) {
  ++peak.particles;
  if (!peak.max_K || p.temperature[i] > *peak.max_K) {
    peak.max_K = p.temperature[i];
    peak.position_m = p.position[i];
  }
}

}  // namespace

ChipAnalysisSetup chip_analysis_setup(const Scene& scene, const CuttingParameters& c, const Vec2& tool_displacement_m,
                                      double time_s) {
  if (scene.rigid_bodies.empty() || scene.bodies.empty())
    throw std::invalid_argument("chip analysis: a cutting scene needs the workpiece (body 0) and the tool (rigid body 0)");
  ChipAnalysisSetup s;
  s.uncut_chip_thickness_m = c.uncut_chip_thickness;
  s.cutting_speed_m_per_s = c.cutting_speed;
  s.rake_angle_deg = c.rake_angle_deg;
  s.cell_size_m = scene.grid.cell_size;
  s.particles_per_cell = scene.bodies[0].particles_per_cell;
  const RigidBodySpec& tool = scene.rigid_bodies[0];
  Polygon moved = tool.polygon;
  for (Vec2& v : moved.vertices) v += tool_displacement_m;
  s.tool = RigidPolygon(moved, tool.rounding_radius);
  s.tool_velocity_m_per_s = tool.velocity;
  // The preset puts the tool's lowest point on the machined surface (tool_geometry.hpp).
  double core_min_y = std::numeric_limits<double>::infinity();
  for (const Vec2& v : moved.vertices) core_min_y = std::min(core_min_y, v.y());
  s.machined_surface_y_m = core_min_y - tool.rounding_radius;
  // Without damage no particle can fail: a threshold above any D.
  for (const MaterialParameters& m : scene.materials) s.max_damage.push_back(m.damage_enabled ? m.max_damage : 2.0);
  s.workpiece_body = 0;
  s.time_s = time_s;
  s.tool_travel_m = -tool_displacement_m.x();
  return s;
}

double shear_angle_from_chip_ratio_deg(double r, double rake_angle_deg) {
  const double a = rake_angle_deg * kDeg;
  return std::atan2(r * std::cos(a), 1.0 - r * std::sin(a)) / kDeg;
}

std::vector<char> chip_particles(const Particles& p, const ChipAnalysisSetup& s) {
  const ChipThresholds& th = s.thresholds;
  const double d = s.particle_spacing_m();
  const double y_min = s.machined_surface_y_m + th.surface_margin_spacings * d;
  // Above the uncut surface by half a particle spacing: a particle there has moved (the top row of
  // the workpiece starts d/2 below the surface).
  const double y_moved = s.machined_surface_y_m + s.uncut_chip_thickness_m + 0.5 * d;
  std::vector<char> chip(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] != s.workpiece_body) continue;
    const double y = p.position[i].y();
    chip[i] = y > y_min && (p.plastic_strain[i] > th.chip_plastic_strain || y > y_moved);
  }
  return chip;
}

namespace {

// Whether a one-piece chip's type sits at a threshold: near serrated_degree, or deep enough to be serrated
// but with fewer teeth than the rule asks (a pitch longer than the analysed profile can hold twice).
void classify_confidence(ChipAnalysis& a, const ChipThresholds& th) {
  a.classification_confidence = "clear";
  if (a.classification != "serrated" && a.classification != "continuous") return;
  if (!a.segmentation.degree) {
    // One piece, but no profile to measure (a short cut, a chip still at the root): "continuous" says only that
    // it is one piece (it was "clear" with every chip measure empty).
    a.classification_confidence = "marginal";
    a.classification_note = fmt::format(
        "the chip is one piece, but its profile could not be measured ({} thickness samples): \"continuous\" here "
        "says only that it is one piece, whether it is serrated is not known; a longer cut gives the chip a profile",
        a.profile.thickness_m.size());
    return;
  }
  if (a.chip_thickness_ratio && *a.chip_thickness_ratio > th.max_plausible_thickness_ratio) {
    // Impossible for a steady chip: the profile is the entry chip's or the grid's (t0/tc 4.6 at 4 cells across t0
    // over 60 um of cut was "clear").
    a.classification_confidence = "marginal";
    a.classification_note = fmt::format(
        "the measured chip is thinner than t0 / {:g} (t0/tc = {:.2f}): not a steady chip's profile (too short a cut, "
        "or too few cells across t0: {:.1f}); its thickness, shear angle and type are not reliable",
        th.max_plausible_thickness_ratio, *a.chip_thickness_ratio, a.cells_per_feed);
    return;
  }
  const double gs = *a.segmentation.degree;
  if (a.classification == "continuous" && gs >= th.serrated_degree) {
    a.classification_confidence = "marginal";
    a.classification_note = fmt::format(
        "segmentation degree {:.2f} is at or above the serrated threshold {:g}, but the profile shows {} tooth(s) "
        "where {} are needed: the pitch may be longer than the analysed chip",
        gs, th.serrated_degree, a.segmentation.segments, th.serrated_min_segments);
  } else if (std::abs(gs - th.serrated_degree) < th.marginal_degree_band) {
    a.classification_confidence = "marginal";
    a.classification_note =
        fmt::format("segmentation degree {:.2f} is within {:g} of the serrated threshold {:g}: weakly segmented", gs,
                    th.marginal_degree_band, th.serrated_degree);
  }
}

}  // namespace

ChipAnalysis analyze_chip(const Particles& p, const ChipAnalysisSetup& s) {
  const ChipThresholds& th = s.thresholds;
  const double t0 = s.uncut_chip_thickness_m, h = s.cell_size_m, d = s.particle_spacing_m();
  if (!(t0 > 0.0) || !(h > 0.0) || s.particles_per_cell < 1)
    throw std::invalid_argument(fmt::format(
        "analyze_chip: need t0 > 0, h > 0 and particles_per_cell >= 1, got {}, {}, {}", t0, h, s.particles_per_cell));
  const RakeFrame frame = rake_frame(s);
  const double cos_a = std::cos(s.rake_angle_deg * kDeg);

  ChipAnalysis a;
  a.time_s = s.time_s;
  a.tool_travel_m = s.tool_travel_m;

  // --- The chip and its pieces -------------------------------------------------------------
  const std::vector<char> is_chip = chip_particles(p, s);
  std::vector<std::size_t> chip;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (is_chip[i]) chip.push_back(i);
  a.chip_particles = chip.size();
  std::vector<Vec2> x(chip.size()), local(chip.size());
  std::vector<char> bonds(chip.size());
  for (std::size_t k = 0; k < chip.size(); ++k) {
    const std::size_t i = chip[k];
    a.chip_mass_kg_per_m += p.mass[i];
    x[k] = p.position[i];
    local[k] = frame.local(p.position[i]);
    bonds[k] = !fully_damaged(p, i, s);
  }
  const Pieces pieces = find_pieces(x, th.link_spacings * d, bonds);
  a.significant_piece_particles = std::max<std::size_t>(
      th.min_piece_particles,
      static_cast<std::size_t>(std::ceil(th.significant_piece_t0_squared * (t0 / d) * (t0 / d))));
  for (std::size_t size : pieces.size) {
    if (size >= a.significant_piece_particles) {
      a.piece_particles.push_back(size);
    } else {
      a.fragment_particles += size;
    }
  }
  a.pieces = a.piece_particles.size();

  // --- Profile and segmentation --------------------------------------------------------------
  // From half an uncut chip thickness above the uncut surface's height on the rake face: below it
  // lies the chip root, where the chip is still being formed (the primary shear zone, the bend of
  // the free surface) and has no thickness of its own.
  a.prominence_m = std::max(th.prominence_t0 * t0, th.prominence_spacings * d);
  {
    const double s0 = th.profile_start_t0 * t0 / cos_a;
    a.profile = trace_chip_profile(x, frame.origin + s0 * frame.u, frame.u, frame.n, 0.5 * h, d,
                                   th.max_chip_thickness_t0 * t0, t0);
    a.profile.start_m = s0;
  }
  a.min_pitch_m = std::max(th.min_pitch_t0 * t0, th.min_pitch_cells * h);
  a.narrow_width_m = th.narrow_excursion_cells * h;
  // A one-piece chip's free end is the chip cut while the tool entered: it tapers from the workpiece's
  // edge and its shape is not the cut's (a smooth chip's tapered end was counted as a deep tooth). By
  // volume constancy the chip of e t0 of travel holds the area e t0^2; that tail is left out, but never
  // more than half the profile's area: a short cut (4 t0 of travel) would otherwise keep about one t0 of
  // chip, too little to show two teeth of a chip that the pictures show serrated. A broken chip's profile
  // ends at a fracture, not at the entry, and is measured whole.
  a.steady_samples = a.profile.thickness_m.size();
  if (a.pieces <= 1 && a.steady_samples > 0) {
    const double entry_area = th.entry_travel_t0 * t0 * t0;
    const double half_area = 0.5 * profile_area(a.profile);
    const std::size_t kept = samples_before_tail_area(a.profile, std::min(entry_area, half_area));
    if (kept >= 3) {
      a.steady_samples = kept;
      if (half_area < entry_area)
        a.profile_note = fmt::format(
            "a short cut: the chip holds less than twice the chip of the tool's entry ({:g} t0 of travel), so "
            "only its free half ({:.1f} t0^2) is left out and the measured part may include the end of the "
            "entry chip",
            th.entry_travel_t0, half_area / (t0 * t0));
    } else {
      a.profile_note = fmt::format(
          "the chip holds little more than the chip of the tool's entry ({:g} t0 of travel): its profile is "
          "measured whole, so the segmentation describes the entry chip",
          th.entry_travel_t0);
    }
  }
  {
    ChipProfile steady = a.profile;
    steady.thickness_m.resize(a.steady_samples);
    steady.inner_m.resize(a.steady_samples);
    steady.tangent.resize(a.steady_samples);
    a.segmentation = measure_segmentation(steady, a.prominence_m, a.min_pitch_m, a.narrow_width_m);
  }
  a.area_mean_thickness_m = area_mean_thickness(a.profile, a.steady_samples, x, d, t0, frame.n);
  // An area mean cannot exceed the thickest cross-section it averages over (a particle reaches at most d beyond
  // it): where it does, the curvature weighting of a tightly curled short chip ran away (t_A 201 um beside cross-
  // sections of at most 118 um at a 30 deg rake over 0.15 mm of cut). Left out rather than reported.
  const std::size_t measured = std::min(a.steady_samples, a.profile.thickness_m.size());
  const double thickest = measured > 0 ? *std::max_element(a.profile.thickness_m.begin(),
                                                           a.profile.thickness_m.begin() + measured)
                                       : 0.0;
  if (a.area_mean_thickness_m && *a.area_mean_thickness_m > thickest + 2.0 * d) {
    a.area_mean_thickness_note = fmt::format("the thickness by area (t_A {:.3g} um) exceeds the thickest cross-section "
                                             "it averages over ({:.3g} um): a chip curled too tightly for its area "
                                             "rule; t_A is left out",
                                             *a.area_mean_thickness_m * 1e6, thickest * 1e6);
    a.area_mean_thickness_m.reset();
  }
  if (a.area_mean_thickness_m && *a.area_mean_thickness_m > 0.0)
    a.chip_thickness_ratio_from_area = t0 / *a.area_mean_thickness_m;
  else
    a.area_mean_thickness_m.reset();
  if (a.segmentation.mean_thickness_m) {
    const double r = t0 / *a.segmentation.mean_thickness_m;
    a.chip_thickness_ratio = r;
    a.shear_angle_from_ratio_deg = shear_angle_from_chip_ratio_deg(r, s.rake_angle_deg);
    a.chip_velocity_m_per_s = s.cutting_speed_m_per_s * r;
    if (a.segmentation.pitch_m) a.segmentation_frequency_Hz = *a.chip_velocity_m_per_s / *a.segmentation.pitch_m;
  }
  {
    double mass = 0.0, momentum = 0.0;
    for (std::size_t k = 0; k < chip.size(); ++k) {
      // The chip just above the root, still on the rake face.
      if (local[k].x() < a.profile.start_m || local[k].x() > a.profile.start_m + 2.0 * t0) continue;
      if (local[k].y() < 0.0 || local[k].y() > th.max_chip_thickness_t0 * t0) continue;
      const std::size_t i = chip[k];
      mass += p.mass[i];
      momentum += p.mass[i] * (p.velocity[i] - s.tool_velocity_m_per_s).dot(frame.u);
    }
    if (mass > 0.0) a.chip_velocity_from_particles_m_per_s = momentum / mass;
  }

  // --- Classification ------------------------------------------------------------------------
  a.cells_per_feed = t0 / s.cell_size_m;
  if (a.cells_per_feed < th.resolved_cells_per_feed)
    a.resolution_note = fmt::format(
        "t0 is {:.1f} cells: below {:g} cells across the uncut chip, shear bands and segments are not resolved and "
        "a serrated profile can be particle roughness; read the classification as indicative",
        a.cells_per_feed, th.resolved_cells_per_feed);
  if (a.chip_particles < a.significant_piece_particles) {
    a.classification = "none";
  } else if (a.pieces >= 2) {
    a.classification = "discontinuous";
  } else if (a.segmentation.degree && *a.segmentation.degree >= th.serrated_degree &&
             a.segmentation.segments >= th.serrated_min_segments) {
    a.classification = "serrated";
  } else {
    a.classification = "continuous";
  }
  classify_confidence(a, th);

  // --- Shear bands ---------------------------------------------------------------------------
  if (!chip.empty()) {
    std::vector<double> strain(chip.size());
    for (std::size_t k = 0; k < chip.size(); ++k) strain[k] = p.plastic_strain[chip[k]];
    std::vector<double> sorted = strain;
    std::sort(sorted.begin(), sorted.end());
    const auto quantile = [&sorted](double q) {
      return sorted[static_cast<std::size_t>(std::floor(q * static_cast<double>(sorted.size() - 1)))];
    };
    const double threshold = std::max(quantile(th.band_strain_percentile), th.band_strain_over_median * quantile(0.5));
    a.band_strain_threshold = threshold;
    std::vector<Vec2> band;
    Vec2 normal;
    for (std::size_t k = 0; k < chip.size(); ++k) {
      if (strain[k] <= threshold) continue;
      if (s.tool.signed_distance(x[k], normal) < th.band_tool_distance_cells * h) continue;
      band.push_back(x[k]);
    }
    const Pieces clusters = find_pieces(band, th.link_spacings * d);
    const std::size_t min_band = std::max<std::size_t>(3, static_cast<std::size_t>(std::ceil(th.band_min_length_t0 * t0 / d)));
    for (std::size_t c = 0; c < clusters.size.size() && clusters.size[c] >= min_band; ++c) {
      Vec2 mean = Vec2::Zero();
      std::size_t n = 0;
      for (std::size_t k = 0; k < band.size(); ++k)
        if (clusters.label[k] == static_cast<int>(c)) {
          mean += band[k];
          ++n;
        }
      mean /= static_cast<double>(n);
      Mat2 cov = Mat2::Zero();
      for (std::size_t k = 0; k < band.size(); ++k)
        if (clusters.label[k] == static_cast<int>(c)) cov += (band[k] - mean) * (band[k] - mean).transpose();
      const Eigen::SelfAdjointEigenSolver<Mat2> eig(cov);
      const double small = std::max(eig.eigenvalues()(0), 0.0), large = eig.eigenvalues()(1);
      // A line of particles one spacing wide has a minor variance of about d^2/12, never zero.
      if (large < th.band_min_elongation * th.band_min_elongation * std::max(small, d * d / 12.0)) continue;
      const Vec2 axis = eig.eigenvectors().col(1);
      // Unroll a curled chip: express the band in the chip's local frame (tangent, normal) at the
      // nearest profile station and map that frame onto the rake face's (u, n), where the band
      // was formed. Near the root, in contact with the rake face, this changes nothing.
      Vec2 tangent = frame.u, normal = frame.n;
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < a.profile.inner_m.size(); ++k) {
        const double dist = (a.profile.inner_m[k] - mean).squaredNorm();
        if (dist < nearest) {
          nearest = dist;
          tangent = a.profile.tangent[k];
        }
      }
      normal = Vec2(-tangent.y(), tangent.x());
      if (normal.dot(frame.n) < 0.0 && tangent.dot(frame.u) > 0.0) normal = -normal;
      if (nearest == std::numeric_limits<double>::infinity()) normal = frame.n;
      const double along = axis.dot(tangent), across = axis.dot(normal);
      // A cluster that runs along the chip is the secondary shear zone on its inner surface, not a band.
      if (std::abs(across) < std::sin(th.band_min_angle_to_chip_deg * kDeg)) continue;
      a.shear_band_angles_deg.push_back(band_angle_deg(along * frame.u + across * frame.n));
    }
    if (!a.shear_band_angles_deg.empty()) {
      double sum = 0.0;
      for (double angle : a.shear_band_angles_deg) sum += angle;
      a.shear_band_angle_deg = sum / static_cast<double>(a.shear_band_angles_deg.size());
    }
  }

  // --- Temperatures ---------------------------------------------------------------------------
  const double s_top = t0 / cos_a + th.shear_zone_overshoot_t0 * t0;
  const double interface = th.interface_distance_cells * h;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!a.max_temperature_K || p.temperature[i] > *a.max_temperature_K) a.max_temperature_K = p.temperature[i];
    if (p.body[i] != s.workpiece_body) continue;
    Vec2 normal;
    const double distance = s.tool.signed_distance(p.position[i], normal);
    // Rake face and the front of the edge: the tool's outward normal there points against the cut.
    if (distance <= interface && normal.x() <= 0.0) peak_in(a.tool_chip_interface, p, i);
    const Vec2 q = frame.local(p.position[i]);
    if (q.x() > 0.0 && q.x() <= s_top && q.y() > interface && q.y() <= th.shear_zone_depth_t0 * t0)
      peak_in(a.primary_shear_zone, p, i);
  }
  return a;
}

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

namespace {

nlohmann::json peak_json(const PeakTemperature& t) {
  nlohmann::json j;
  j["max_K"] = optional_json(t.max_K);
  j["position_m"] = t.position_m ? nlohmann::json{t.position_m->x(), t.position_m->y()} : nlohmann::json(nullptr);
  j["particles"] = t.particles;
  return j;
}

}  // namespace

nlohmann::json chip_json(const ChipAnalysis& a) {
  const Segmentation& g = a.segmentation;
  nlohmann::json j;
  j["time_s"] = a.time_s;
  j["tool_travel_m"] = a.tool_travel_m;
  j["classification"] = a.classification;
  j["classification_confidence"] = a.classification_confidence;
  if (!a.classification_note.empty()) j["classification_note"] = a.classification_note;
  j["cells_across_uncut_chip"] = a.cells_per_feed;
  j["resolution_note"] = a.resolution_note.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.resolution_note);
  j["particles"] = a.chip_particles;
  j["mass_kg_per_m"] = a.chip_mass_kg_per_m;
  j["pieces"] = a.pieces;
  j["piece_particles"] = a.piece_particles;
  j["fragment_particles"] = a.fragment_particles;
  j["segments"] = g.segments;
  j["peak_height_m"] = optional_json(g.peak_height_m);
  j["valley_height_m"] = optional_json(g.valley_height_m);
  j["mean_thickness_m"] = optional_json(g.mean_thickness_m);
  j["max_thickness_m"] = optional_json(g.max_thickness_m);
  j["segmentation_degree"] = optional_json(g.degree);
  j["pitch_m"] = optional_json(g.pitch_m);
  j["segmentation_frequency_Hz"] = optional_json(a.segmentation_frequency_Hz);
  j["chip_thickness_ratio"] = optional_json(a.chip_thickness_ratio);
  j["area_mean_thickness_m"] = optional_json(a.area_mean_thickness_m);
  j["area_mean_thickness_note"] =
      a.area_mean_thickness_note.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.area_mean_thickness_note);
  j["chip_thickness_ratio_from_area"] = optional_json(a.chip_thickness_ratio_from_area);
  j["shear_angle_from_ratio_deg"] = optional_json(a.shear_angle_from_ratio_deg);
  j["chip_velocity_m_per_s"] = optional_json(a.chip_velocity_m_per_s);
  j["chip_velocity_from_particles_m_per_s"] = optional_json(a.chip_velocity_from_particles_m_per_s);
  j["shear_band_angle_deg"] = optional_json(a.shear_band_angle_deg);
  j["shear_band_angles_deg"] = a.shear_band_angles_deg;
  j["profile"] = {{"start_m", a.profile.start_m},
                  {"spacing_m", a.profile.spacing_m},
                  {"samples", a.profile.thickness_m.size()},
                  {"steady_samples", a.steady_samples},
                  {"steady_end_m", a.steady_samples > 0 ? nlohmann::json(a.profile.position_m(a.steady_samples - 1))
                                                        : nlohmann::json(nullptr)},
                  {"note", a.profile_note.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.profile_note)},
                  {"peak_positions_m", nlohmann::json::array()},
                  {"valley_positions_m", nlohmann::json::array()},
                  {"thickness_m", a.profile.thickness_m}};
  for (std::size_t k : g.extrema.peaks) j["profile"]["peak_positions_m"].push_back(a.profile.position_m(k));
  for (std::size_t k : g.extrema.valleys) j["profile"]["valley_positions_m"].push_back(a.profile.position_m(k));
  j["thresholds"] = {{"prominence_m", a.prominence_m},
                     {"min_pitch_m", a.min_pitch_m},
                     {"narrow_width_m", a.narrow_width_m},
                     {"significant_piece_particles", a.significant_piece_particles},
                     {"band_plastic_strain", optional_json(a.band_strain_threshold)}};
  j["definition"] = "docs/analysis.md";
  return j;
}

nlohmann::json temperature_json(const ChipAnalysis& a) {
  return {{"time_s", a.time_s},
          {"max_K", optional_json(a.max_temperature_K)},
          {"primary_shear_zone", peak_json(a.primary_shear_zone)},
          {"tool_chip_interface", peak_json(a.tool_chip_interface)},
          {"definition", "docs/analysis.md"}};
}

std::string chip_summary_text(const ChipAnalysis& a) {
  const auto um = [](const std::optional<double>& v) { return v ? fmt::format("{:.1f} um", *v * 1e6) : std::string("-"); };
  const auto num = [](const std::optional<double>& v, const char* f) {
    return v ? fmt::format(fmt::runtime(f), *v) : std::string("-");
  };
  const Segmentation& g = a.segmentation;
  std::string s = fmt::format("chip at t = {:.4g} s (tool travel {:.1f} um): {}{}, {} particles, {} piece(s)\n",
                              a.time_s, a.tool_travel_m * 1e6, a.classification,
                              a.classification_confidence == "marginal" ? " (marginal: " + a.classification_note + ")" : "",
                              a.chip_particles, a.pieces);
  s += fmt::format("  thickness: mean {} (by area {}), peaks {}, valleys {}; segmentation degree Gs {}; {} segment(s), "
                   "pitch {}\n",
                   um(g.mean_thickness_m), um(a.area_mean_thickness_m), um(g.peak_height_m), um(g.valley_height_m), num(g.degree, "{:.2f}"),
                   g.segments, um(g.pitch_m));
  s += fmt::format("  chip thickness ratio r {}, shear angle from r {} deg, shear-band angle {} deg ({} band(s))\n",
                   num(a.chip_thickness_ratio, "{:.2f}"), num(a.shear_angle_from_ratio_deg, "{:.1f}"),
                   num(a.shear_band_angle_deg, "{:.1f}"), a.shear_band_angles_deg.size());
  s += fmt::format("  chip velocity {} m/s (continuity), {} m/s (particles); segmentation frequency {}\n",
                   num(a.chip_velocity_m_per_s, "{:.2f}"), num(a.chip_velocity_from_particles_m_per_s, "{:.2f}"),
                   a.segmentation_frequency_Hz ? fmt::format("{:.3g} MHz", *a.segmentation_frequency_Hz * 1e-6)
                                               : std::string("-"));
  s += fmt::format("  temperature: max {} K, primary shear zone {} K, tool-chip interface {} K\n",
                   num(a.max_temperature_K, "{:.0f}"), num(a.primary_shear_zone.max_K, "{:.0f}"),
                   num(a.tool_chip_interface.max_K, "{:.0f}"));
  if (a.steady_samples > 0 && a.steady_samples < a.profile.thickness_m.size())
    s += fmt::format("  profile: {:.0f} to {:.0f} um along the chip measured; the entry chip beyond, to {:.0f} um, left out\n",
                     a.profile.start_m * 1e6, a.profile.position_m(a.steady_samples - 1) * 1e6,
                     a.profile.position_m(a.profile.thickness_m.size() - 1) * 1e6);
  if (!a.profile_note.empty()) s += "  note: " + a.profile_note + "\n";
  if (!a.area_mean_thickness_note.empty()) s += "  note: " + a.area_mean_thickness_note + "\n";
  if (!a.resolution_note.empty()) s += "  note: " + a.resolution_note + "\n";
  return s;
}

}  // namespace mpmcut
