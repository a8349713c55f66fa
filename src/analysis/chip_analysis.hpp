#pragma once
// Chip analysis of one instant of an orthogonal cut: which particles are the chip, its pieces, its
// free-surface profile and segmentation, the shear-band angle, the chip thickness ratio and the
// shear angle it implies, and the peak temperatures of the primary shear zone and the tool-chip
// interface. A pure function of the particles and the cut's geometry, so that it runs the same on
// the final in-memory state (run/chip_observer.hpp) and on a snapshot of an old run
// (`mpmcut analyze`). Definitions, thresholds and limitations: docs/analysis.md.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "analysis/chip_profile.hpp"
#include "contact/rigid_polygon.hpp"
#include "core/particles.hpp"
#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

// Thresholds of the analysis, in units of the uncut chip thickness t0 and of the particle
// spacing d = h / particles_per_cell. The defaults are the documented ones (docs/analysis.md).
struct ChipThresholds {
  double chip_plastic_strain = 0.1;        // a particle above the machined surface with more has been cut
  double surface_margin_spacings = 1.0;    // the chip lies this many d above the machined surface
  double link_spacings = 1.5;              // neighbour distance for pieces and bands, in d
  double significant_piece_t0_squared = 0.25;  // a piece counts when its particles cover >= this * t0^2
  std::size_t min_piece_particles = 10;        // ... and it has at least this many particles
  double profile_start_t0 = 1.5;           // the profile starts this many t0 up the rake face (past the root)
  double max_chip_thickness_t0 = 6.0;     // the profile looks this far across the chip
  double prominence_t0 = 0.1;              // peak/valley prominence, in t0 ...
  double prominence_spacings = 1.5;        // ... and at least this many d (one particle is not a tooth)
  double min_pitch_t0 = 0.25;              // teeth closer than this many t0 along the chip are one tooth ...
  double min_pitch_cells = 2.0;            // ... and closer than this many h (the grid cannot resolve them)
  double narrow_excursion_cells = 1.0;     // thickness excursions this many h wide or narrower are not teeth
  // A one-piece chip's free end was cut while the tool entered: the tail of the profile holding the
  // chip of this many t0 of travel (area entry_travel_t0 t0^2) is left out of the segmentation metrics.
  double entry_travel_t0 = kEntryTravelT0;
  double serrated_degree = 0.1;            // Gs at or above: serrated (one piece) ...
  std::size_t serrated_min_segments = 2;   // ... with at least this many teeth (a repeating pattern)
  // Reporting margin: a one-piece chip whose Gs lies within this of serrated_degree, or that is as deep
  // as a serrated one but shows fewer teeth, is classified "marginal": the type may flip with the grid.
  double marginal_degree_band = 0.1;
  double band_strain_percentile = 0.8;     // band particles: plastic strain above this percentile of the chip ...
  double band_strain_over_median = 1.5;    // ... and above this multiple of the chip's median
  double band_tool_distance_cells = 1.5;   // bands ignore the secondary shear zone within this many h of the tool
  double band_min_length_t0 = 0.5;         // a band cluster needs >= this * t0 / d particles ...
  double band_min_elongation = 3.0;        // ... and a principal axis ratio sqrt(l1/l2) >= this
  double band_min_angle_to_chip_deg = 30.0;// ... and must cross the chip at least this steeply
  double shear_zone_depth_t0 = 3.0;        // primary shear zone region: within this * t0 ahead of the rake face
  double shear_zone_overshoot_t0 = 0.25;   // ... and up to this * t0 above the uncut surface
  double interface_distance_cells = 1.0;   // tool-chip interface: within this many h of the tool
  double resolved_cells_per_feed = 8.0;    // fewer cells across t0: segments are not resolved (a note says so)
  // A chip thinner than t0 / this (t0/tc above it: a shear angle above 63 deg at a 0 deg rake; Ti-6Al-4V chips
  // measure t0/tc 0.6-1.0) is not a chip's steady profile but a short or under-resolved cut's: "marginal".
  double max_plausible_thickness_ratio = 2.0;
};

// The geometry of the cut at the analysed instant.
struct ChipAnalysisSetup {
  double uncut_chip_thickness_m = 0.0;  // t0
  double cutting_speed_m_per_s = 0.0;   // V
  double rake_angle_deg = 0.0;          // alpha
  double cell_size_m = 0.0;             // h
  int particles_per_cell = 2;           // per direction; particle spacing d = h / this
  double machined_surface_y_m = 0.0;    // y of the machined surface (lowest point of the cutting edge)
  Vec2 tool_velocity_m_per_s = Vec2::Zero();
  RigidPolygon tool;                    // outline at the analysed instant
  std::vector<double> max_damage;       // per material id: D at which a particle is fully failed
  int workpiece_body = 0;               // body id of the workpiece particles
  double time_s = 0.0;                  // of the analysed state (reported only)
  double tool_travel_m = 0.0;           // reported only
  ChipThresholds thresholds;

  double particle_spacing_m() const { return cell_size_m / particles_per_cell; }
};

// From a scene built by the cutting preset from `cutting` (the tool is rigid_bodies[0], the
// workpiece body 0) with the tool displaced by `tool_displacement_m` from its start. Throws
// std::invalid_argument when the scene lacks the workpiece or the tool.
ChipAnalysisSetup chip_analysis_setup(const Scene& scene, const CuttingParameters& cutting,
                                      const Vec2& tool_displacement_m, double time_s);

struct PeakTemperature {
  std::optional<double> max_K;          // empty: no particle in the region
  std::optional<Vec2> position_m;       // where
  std::size_t particles = 0;            // in the region
};

struct ChipAnalysis {
  // The instant
  double time_s = 0.0;
  double tool_travel_m = 0.0;
  // The chip
  std::size_t chip_particles = 0;
  double chip_mass_kg_per_m = 0.0;
  std::string classification;           // none, continuous, serrated, discontinuous
  // "clear", or "marginal" where the classification sits at a threshold (classification_note says which)
  std::string classification_confidence;
  std::string classification_note;
  double cells_per_feed = 0.0;          // t0 / h: how well the grid resolves the chip
  std::string resolution_note;          // non-empty when t0/h is below the resolved threshold
  std::size_t pieces = 0;               // significant pieces
  std::vector<std::size_t> piece_particles;  // particles per significant piece, largest first
  std::size_t fragment_particles = 0;   // chip particles in pieces too small to count (incl. failed ones)
  std::size_t significant_piece_particles = 0;  // the size threshold used
  // Free-surface profile and segmentation
  ChipProfile profile;
  Segmentation segmentation;
  double prominence_m = 0.0;
  double min_pitch_m = 0.0;                          // neighbouring teeth closer than this are merged
  double narrow_width_m = 0.0;                       // excursions this wide or narrower are removed
  // Leading profile samples the segmentation, thickness ratio and pitch are measured on: all of them,
  // or those before the entry chip's tail (ChipThresholds::entry_travel_t0).
  std::size_t steady_samples = 0;
  std::string profile_note;                          // non-empty when the entry chip was not left out whole
  std::optional<double> chip_thickness_ratio;        // r = t0 / t_c, t_c = mean profile thickness
  // The same part of the chip by its area: chip area across those samples / their length (area_mean_thickness),
  // and t0 over it. Equal to the profile's mean where the chip is whole; larger where cross-sections stop at
  // open cracks (the profile then measures the ligament).
  std::optional<double> area_mean_thickness_m;
  // Why t_A was left out, where it was (its own note: profile_note marks a state whose entry chip was not left out,
  // and such a state is not a steady one).
  std::string area_mean_thickness_note;
  std::optional<double> chip_thickness_ratio_from_area;
  std::optional<double> shear_angle_from_ratio_deg;  // tan phi = r cos a / (1 - r sin a)
  std::optional<double> chip_velocity_m_per_s;       // V r (continuity)
  std::optional<double> chip_velocity_from_particles_m_per_s;  // mass-mean speed along the rake face
  std::optional<double> segmentation_frequency_Hz;   // V_chip / pitch
  // Shear bands
  std::vector<double> shear_band_angles_deg;         // per band, from the cutting direction
  std::optional<double> shear_band_angle_deg;        // their mean
  std::optional<double> band_strain_threshold;       // plastic strain above which a particle is in a band
  // Temperatures
  std::optional<double> max_temperature_K;           // all particles
  PeakTemperature primary_shear_zone;
  PeakTemperature tool_chip_interface;
};

// The shear angle implied by a chip thickness ratio r = t0/t_c and a rake angle alpha (Merchant's
// geometry, Merchant 1945: r = sin phi / cos(phi - alpha)), in degrees.
double shear_angle_from_chip_ratio_deg(double chip_ratio, double rake_angle_deg);

// Which particles are the chip (see docs/analysis.md): true per particle.
std::vector<char> chip_particles(const Particles& p, const ChipAnalysisSetup& setup);

ChipAnalysis analyze_chip(const Particles& p, const ChipAnalysisSetup& setup);

// A value, or null where it is undefined (the chip objects' convention).
nlohmann::json optional_json(const std::optional<double>& v);

// summary.json's "chip" and "temperature" objects (units in key names; undefined values null).
nlohmann::json chip_json(const ChipAnalysis& a);
nlohmann::json temperature_json(const ChipAnalysis& a);

// One-paragraph human summary with units, for the terminal.
std::string chip_summary_text(const ChipAnalysis& a);

}  // namespace mpmcut
