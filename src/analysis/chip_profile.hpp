#pragma once
// The chip's free-surface profile and its segmentation (saw-tooth) metrics.
//
// The profile is the chip's local thickness as a function of the distance along the chip: the
// distance from the chip's inner surface (on the rake face while it is in contact) to its outer,
// free surface, measured normal to the inner surface at stations a fixed arc length apart along it
// (trace_chip_profile). Peaks and valleys of this line give the segmentation degree
// Gs = (H - h)/H (H: mean peak height, h: mean valley height) and the pitch (mean peak spacing),
// as in the experimental literature on serrated Ti-6Al-4V chips. docs/analysis.md has the details.
#include <cstddef>
#include <optional>
#include <vector>

#include "core/tensor.hpp"

namespace mpmcut {

struct ChipProfile {
  double start_m = 0.0;              // arc length of the first sample, m (from the cutting edge)
  double spacing_m = 0.0;            // between samples, m
  std::vector<double> thickness_m;   // per sample; 0 where no particle lies in the window (a gap)
  std::vector<Vec2> inner_m;         // per sample: the point on the chip's inner surface, m
  std::vector<Vec2> tangent;         // per sample: unit direction of the chip there (along the walk)
  double position_m(std::size_t k) const { return start_m + spacing_m * static_cast<double>(k); }
};

// Walks along the chip and measures its thickness every `step` of arc length along its inner
// surface, so that a chip that curls away from the tool is measured across, not in projection.
// Start: `start` on the inner surface (the rake face at the height of the uncut surface), heading
// `direction` (along the rake face, away from the edge), `into_chip` the unit normal towards the
// chip's free side. At each station the inner surface is fitted by a straight line through the
// innermost point of each particle-spacing bin within +-smoothing_length/2 along the chip; the
// station moves onto that line and the walk turns to its direction. The cross-section along the
// line's normal is the run of point offsets (points within one particle spacing of the normal,
// at most max_thickness away) without a gap wider than 2.5 particle spacings that lies nearest the
// station, and thickness = its length + particle_spacing (each particle stands for a square of
// that side). The next station is one step on from the cross-section's inner end. Slabs without
// points give thickness 0 (a gap); three in a row, or coming back to particles measured earlier
// (a walk circling past the chip's end), end the walk.
ChipProfile trace_chip_profile(const std::vector<Vec2>& points, const Vec2& start, const Vec2& direction,
                               const Vec2& into_chip, double step, double particle_spacing, double max_thickness,
                               double smoothing_length);

// Peaks and valleys in alternation, found by hysteresis ("zig-zag"): a running maximum becomes a
// peak once the line has fallen `prominence` below it, a running minimum a valley once the line
// has risen `prominence` above it. Every reported extremum therefore differs from the extrema
// beside it by at least `prominence`, so a bump of one particle does not count. The first and last
// samples never count: the profile is cut there, they are not turning points.
struct ProfileExtrema {
  std::vector<std::size_t> peaks;    // sample indices, increasing
  std::vector<std::size_t> valleys;  // sample indices, increasing
};
ProfileExtrema find_profile_extrema(const std::vector<double>& y, double prominence);

// Teeth narrower than `min_spacing` samples are flicker, not segments: on a fine particle cloud the
// cross-section at a tooth's crest or at a crack can jump by more than the prominence from one
// station to the next, and the zig-zag then reports a peak-valley-peak within a few samples.
// Wherever two consecutive peaks (or valleys) lie closer than min_spacing, the lower peak (the
// higher valley) and the extremum between them are dropped, the pair whose merge removes the
// smallest excursion first (so a flicker goes, not the tooth's real crest or valley), until every
// pair of neighbours of one kind is at least min_spacing apart. Peaks and valleys still alternate
// and every remaining extremum still differs from its neighbours by at least the prominence.
void merge_close_extrema(const std::vector<double>& y, ProfileExtrema& extrema, std::size_t min_spacing);

// A cross-section that crosses a particle-row gap inside the chip (or picks up a loose particle at
// the free surface) measures a thickness far from its neighbours' for one or two stations. Such an
// excursion is narrower than a cell, which the grid cannot carry as a tooth. Every run of at most
// `max_width` samples that lies at least `prominence` below both samples beside it (or at least
// `prominence` above both), and whose two neighbours differ by less than `prominence` (it returns to
// where it left), is replaced by the straight line between those two samples; runs that touch the first
// or last sample stay. A real tooth's valley, wider than a cell, is kept, and so is a steep saw-tooth's
// valley, which lies between a crest and the next tooth's flank.
void remove_narrow_excursions(std::vector<double>& y, double prominence, std::size_t max_width);

// The number of leading samples left when the profile's tail holding `area` of chip (the sum of
// thickness x spacing from the last sample back, m^2 per m of width) is cut off; 0 when the tail
// takes it all. Used to leave out the chip cut during the tool's entry (docs/analysis.md).
std::size_t samples_before_tail_area(const ChipProfile& profile, double area);
// The chip area the profile holds: the sum of thickness x spacing (m^2 per m of width).
double profile_area(const ChipProfile& profile);

// The chip's mean thickness by its area, as a chip weighed and measured in length would give it: the area
// of the points that lie across the first `samples` stations, divided by their length samples x spacing.
// Each point stands for a square of side particle_spacing and belongs to the station nearest to it along
// the chip (smallest offset along that station's tangent, at most one step; the first and last stations
// reach only half a step outwards), if it lies across that station's inner surface, from one spacing
// inside it to the thickest cross-section within +-window/2 along the chip. A cross-section stops at an
// open crack (it measures the ligament), while the segment beyond the crack is counted here; another turn
// of a curled chip farther out is not. Where the chip curls, a point counts as the thickness it stands for
// across its station (its area over the slab's width there, which shrinks with the inner surface's
// curvature times its offset), so that a curled chip of thickness T reads T. `into_chip`: the unit normal towards the chip's free side at the
// first station, as given to trace_chip_profile. Empty without stations or with samples = 0.
std::optional<double> area_mean_thickness(const ChipProfile& profile, std::size_t samples,
                                          const std::vector<Vec2>& points, double particle_spacing, double window,
                                          const Vec2& into_chip);

struct Segmentation {
  std::vector<double> thickness_m;         // the line measured: the profile without its narrow excursions
  ProfileExtrema extrema;                  // indices into thickness_m (and the profile)
  std::size_t segments = 0;                // number of peaks; 0 without a peak and valley pair
  std::optional<double> peak_height_m;     // H: mean thickness at the peaks
  std::optional<double> valley_height_m;   // h: mean thickness at the valleys
  std::optional<double> mean_thickness_m;  // mean over the samples that hold chip material
  std::optional<double> max_thickness_m;
  // Gs = (H - h)/H; 0 when the profile has no peak and valley pair (no thickness variation
  // beyond the prominence): such a chip is not segmented at this resolution.
  std::optional<double> degree;
  std::optional<double> pitch_m;           // mean distance between consecutive peaks (>= 2 peaks)
};
// Excursions narrower than narrow_width (m) removed (remove_narrow_excursions; 0 keeps them), then
// extrema by prominence (find_profile_extrema), then teeth closer than min_pitch (m) along the chip
// merged (merge_close_extrema; 0 keeps them all); every metric is of the cleaned line. Empty
// profile: every optional empty.
Segmentation measure_segmentation(const ChipProfile& profile, double prominence, double min_pitch = 0.0,
                                  double narrow_width = 0.0);

}  // namespace mpmcut
