#include "analysis/chip_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <stdexcept>

#include <fmt/core.h>

namespace mpmcut {

namespace {

// The cross-section of the chip through `station` along the unit normal `n`: the run of point
// offsets along n (within `half_width` of the line) without a gap wider than `gap` that lies
// nearest the station. False when no point lies in the slab.
struct Section {
  double inner = 0.0, outer = 0.0;  // offsets along n of the run's ends
  std::vector<std::size_t> members; // indices (into the near list) of the run's points
};
bool cross_section(const std::vector<Vec2>& near, const Vec2& station, const Vec2& n, double half_width,
                   double reach, double gap, std::vector<std::pair<double, std::size_t>>& offsets, Section& out) {
  const Vec2 t(-n.y(), n.x());
  offsets.clear();
  for (std::size_t k = 0; k < near.size(); ++k) {
    const Vec2 r = near[k] - station;
    if (std::abs(r.dot(t)) <= half_width && std::abs(r.dot(n)) <= reach) offsets.emplace_back(r.dot(n), k);
  }
  if (offsets.empty()) return false;
  std::sort(offsets.begin(), offsets.end());
  std::size_t nearest = 0;
  for (std::size_t k = 1; k < offsets.size(); ++k)
    if (std::abs(offsets[k].first) < std::abs(offsets[nearest].first)) nearest = k;
  std::size_t lo = nearest, hi = nearest;
  while (lo > 0 && offsets[lo].first - offsets[lo - 1].first <= gap) --lo;
  while (hi + 1 < offsets.size() && offsets[hi + 1].first - offsets[hi].first <= gap) ++hi;
  out.inner = offsets[lo].first;
  out.outer = offsets[hi].first;
  out.members.clear();
  for (std::size_t k = lo; k <= hi; ++k) out.members.push_back(offsets[k].second);
  return true;
}

// The chip's inner surface near `station`, as a straight line fitted through the innermost point
// (smallest offset along n) of each particle-spacing-wide bin along t within `radius`: returns
// false with fewer than three bins, else the line's offset at the station and its slope.
bool fit_inner_surface(const std::vector<Vec2>& near, const Vec2& station, const Vec2& t, const Vec2& n,
                       double radius, double bin, double& offset, double& slope) {
  const int bins = static_cast<int>(std::ceil(radius / bin));
  std::vector<double> innermost(2 * bins + 1, std::numeric_limits<double>::infinity());
  for (const Vec2& x : near) {
    const Vec2 r = x - station;
    const double along = r.dot(t), across = r.dot(n);
    if (std::abs(along) > radius || std::abs(across) > radius) continue;
    const int k = std::clamp(static_cast<int>(std::floor(along / bin)) + bins, 0, 2 * bins);
    innermost[k] = std::min(innermost[k], across);
  }
  double s1 = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k <= 2 * bins; ++k) {
    if (!std::isfinite(innermost[k])) continue;
    const double x = (k - bins + 0.5) * bin, y = innermost[k];
    s1 += 1; sx += x; sy += y; sxx += x * x; sxy += x * y;
  }
  const double det = s1 * sxx - sx * sx;
  if (s1 < 3 || !(det > 0.0)) return false;
  slope = (s1 * sxy - sx * sy) / det;
  offset = (sy - slope * sx) / s1;
  return true;
}

}  // namespace

ChipProfile trace_chip_profile(const std::vector<Vec2>& points, const Vec2& start, const Vec2& direction,
                               const Vec2& into_chip, double step, double particle_spacing, double max_thickness,
                               double smoothing_length) {
  if (!(step > 0.0) || !(particle_spacing > 0.0) || !(max_thickness > 0.0))
    throw std::invalid_argument(fmt::format(
        "trace_chip_profile: step {}, particle spacing {} and max thickness {} must be > 0", step, particle_spacing,
        max_thickness));
  ChipProfile profile;
  profile.spacing_m = step;
  const double gap = 2.5 * particle_spacing;
  // A walk cannot be longer than the chip's particles laid end to end; this also ends loops.
  const std::size_t max_stations = points.size() * static_cast<std::size_t>(std::ceil(particle_spacing / step)) + 8;
  // Station at which each point was first part of a cross-section: a walk that comes back to
  // points it measured long ago has left the chip's end and is circling; it stops there.
  constexpr std::size_t unseen = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> first_seen(points.size(), unseen);
  const std::size_t recent = static_cast<std::size_t>(std::ceil(4.0 * particle_spacing / step)) + 1;

  Vec2 station = start, t = direction.normalized(), n = into_chip.normalized();
  std::vector<Vec2> near;
  std::vector<std::size_t> near_index;
  std::vector<std::pair<double, std::size_t>> offsets;
  int misses = 0;
  while (profile.thickness_m.size() < max_stations) {
    near.clear();
    near_index.clear();
    for (std::size_t i = 0; i < points.size(); ++i)
      if ((points[i] - station).squaredNorm() <= max_thickness * max_thickness) {
        near.push_back(points[i]);
        near_index.push_back(i);
      }
    // The chip's direction is that of its inner surface (smooth: it was against the rake face;
    // the teeth are on the outer side): fit it over +-smoothing_length/2 and measure across it.
    double offset = 0.0, slope = 0.0;
    if (fit_inner_surface(near, station, t, n, 0.5 * smoothing_length, particle_spacing, offset, slope)) {
      const Vec2 t_new = (t + slope * n).normalized();
      Vec2 n_new(-t_new.y(), t_new.x());
      if (n_new.dot(n) < 0.0) n_new = -n_new;
      station += offset * n;
      t = t_new;
      n = n_new;
    }
    Section best;
    const bool found = cross_section(near, station, n, particle_spacing, max_thickness, gap, offsets, best);
    if (!found) {
      if (++misses == 3) break;
      profile.thickness_m.push_back(0.0);
      profile.inner_m.push_back(station);
      profile.tangent.push_back(t);
      station += step * t;
      continue;
    }
    misses = 0;
    const std::size_t here = profile.thickness_m.size();
    std::size_t old = 0;
    for (std::size_t k : best.members) {
      std::size_t& seen = first_seen[near_index[k]];
      if (seen == unseen) seen = here;
      if (seen + recent < here) ++old;
    }
    if (2 * old > best.members.size()) break;
    profile.thickness_m.push_back(best.outer - best.inner + particle_spacing);
    profile.inner_m.push_back(station + best.inner * n);
    profile.tangent.push_back(t);
    station = station + best.inner * n + step * t;  // one step on from the inner surface
  }
  // Trailing gaps and single particles are the end of the chip, not part of it.
  while (!profile.thickness_m.empty() && profile.thickness_m.back() < 1.5 * particle_spacing) {
    profile.thickness_m.pop_back();
    profile.inner_m.pop_back();
    profile.tangent.pop_back();
  }
  return profile;
}

ProfileExtrema find_profile_extrema(const std::vector<double>& y, double prominence) {
  if (!(prominence > 0.0))
    throw std::invalid_argument(fmt::format("find_profile_extrema: prominence {} must be > 0", prominence));
  ProfileExtrema out;
  const std::size_t n = y.size();
  if (n < 3) return out;
  enum class Leg { Unknown, Rising, Falling };
  Leg leg = Leg::Unknown;
  std::size_t top = 0, bottom = 0;  // running maximum and minimum of the current leg
  const auto interior = [n](std::size_t i) { return i > 0 && i + 1 < n; };
  for (std::size_t i = 1; i < n; ++i) {
    if (leg != Leg::Falling && y[i] > y[top]) top = i;
    if (leg != Leg::Rising && y[i] < y[bottom]) bottom = i;
    if (leg != Leg::Falling && y[top] - y[i] >= prominence) {
      if (interior(top)) out.peaks.push_back(top);
      leg = Leg::Falling;
      bottom = i;
    } else if (leg != Leg::Rising && y[i] - y[bottom] >= prominence) {
      if (interior(bottom)) out.valleys.push_back(bottom);
      leg = Leg::Rising;
      top = i;
    }
  }
  return out;
}

void merge_close_extrema(const std::vector<double>& y, ProfileExtrema& extrema, std::size_t min_spacing) {
  struct Extremum {
    std::size_t index;
    bool peak;
  };
  std::vector<Extremum> seq;
  for (std::size_t k : extrema.peaks) seq.push_back({k, true});
  for (std::size_t k : extrema.valleys) seq.push_back({k, false});
  std::sort(seq.begin(), seq.end(), [](const Extremum& a, const Extremum& b) { return a.index < b.index; });
  for (;;) {
    // Of the neighbours of one kind closer than min_spacing (seq[j], seq[j + 2]; they alternate),
    // merge first the pair whose merge removes the smallest excursion: the depth of the notch between
    // two peaks below the lower one, or the height of the spike between two valleys above the higher
    // one. A flicker is then removed and the tooth's true crest and valley are kept.
    std::size_t chosen = seq.size();
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j + 2 < seq.size(); ++j) {
      if (seq[j + 2].index - seq[j].index >= min_spacing) continue;
      const double a = y[seq[j].index], mid = y[seq[j + 1].index], b = y[seq[j + 2].index];
      const double excursion = seq[j].peak ? std::min(a, b) - mid : mid - std::max(a, b);
      if (excursion < smallest) {
        smallest = excursion;
        chosen = j;
      }
    }
    if (chosen == seq.size()) break;
    const Extremum& a = seq[chosen];
    const Extremum& b = seq[chosen + 2];
    // Keep the more extreme of the two: the higher peak, the lower valley.
    const bool keep_first = a.peak ? y[a.index] >= y[b.index] : y[a.index] <= y[b.index];
    seq.erase(seq.begin() + static_cast<std::ptrdiff_t>(chosen + 1));  // the extremum between them
    seq.erase(seq.begin() + static_cast<std::ptrdiff_t>(keep_first ? chosen + 1 : chosen));
  }
  extrema.peaks.clear();
  extrema.valleys.clear();
  for (const Extremum& e : seq) (e.peak ? extrema.peaks : extrema.valleys).push_back(e.index);
}

void remove_narrow_excursions(std::vector<double>& y, double prominence, std::size_t max_width) {
  const std::size_t n = y.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    for (std::size_t w = 1; w <= max_width && i + w < n; ++w) {
      const double left = y[i - 1], right = y[i + w];
      // A flicker returns to where it left; a saw-tooth's drop does not (it falls from a crest and climbs
      // the next tooth's flank, whose first samples may lie p above the valley on a steep tooth).
      if (std::abs(right - left) >= prominence) continue;
      bool below = true, above = true;
      for (std::size_t k = i; k < i + w; ++k) {
        below = below && y[k] <= std::min(left, right) - prominence;
        above = above && y[k] >= std::max(left, right) + prominence;
      }
      if (!below && !above) continue;
      for (std::size_t k = i; k < i + w; ++k)
        y[k] = left + (right - left) * static_cast<double>(k - i + 1) / static_cast<double>(w + 1);
      i += w - 1;  // the loop's ++i moves on to the right neighbour
      break;
    }
  }
}

std::size_t samples_before_tail_area(const ChipProfile& profile, double area) {
  std::size_t k = profile.thickness_m.size();
  double tail = 0.0;
  while (k > 0 && tail < area) tail += profile.thickness_m[--k] * profile.spacing_m;
  return tail < area ? 0 : k;
}

std::optional<double> area_mean_thickness(const ChipProfile& profile, std::size_t samples,
                                          const std::vector<Vec2>& points, double particle_spacing, double window,
                                          const Vec2& into_chip) {
  const std::size_t n = std::min(samples, profile.thickness_m.size());
  if (n == 0 || profile.inner_m.size() < profile.thickness_m.size() ||
      profile.tangent.size() < profile.thickness_m.size())
    return std::nullopt;
  const std::size_t all = profile.thickness_m.size();
  const double step = profile.spacing_m;
  // The walk keeps the handedness of its normal: n = sign (-t_y, t_x) at every station.
  const Vec2& t0 = profile.tangent.front();
  const double hand = into_chip.dot(Vec2(-t0.y(), t0.x())) < 0.0 ? -1.0 : 1.0;
  const std::size_t half_window = static_cast<std::size_t>(std::floor(0.5 * window / step));
  // reach: the thickest cross-section within the window; curvature: the inner surface's, > 0 where the chip
  // curls towards its free side (the tangent turns towards n), from the turn of the tangent over the window.
  std::vector<double> reach(all, 0.0), curvature(all, 0.0);
  for (std::size_t k = 0; k < all; ++k) {
    const std::size_t lo = k > half_window ? k - half_window : 0, hi = std::min(all - 1, k + half_window);
    reach[k] = *std::max_element(profile.thickness_m.begin() + lo, profile.thickness_m.begin() + hi + 1);
    const Vec2& t = profile.tangent[k];
    if (hi > lo)
      curvature[k] = hand * (profile.tangent[hi] - profile.tangent[lo]).dot(Vec2(-t.y(), t.x())) /
                     (static_cast<double>(hi - lo) * step);
  }
  double area = 0.0;
  for (const Vec2& x : points) {
    std::size_t owner = all;
    double nearest = step, offset = 0.0;  // a point farther than one step along from every station belongs to none
    for (std::size_t k = 0; k < all; ++k) {
      const Vec2& t = profile.tangent[k];
      const Vec2 r = x - profile.inner_m[k];
      const double along = r.dot(t), across = hand * r.dot(Vec2(-t.y(), t.x()));
      if (across < -particle_spacing || across > reach[k]) continue;
      if ((k == 0 && along < -0.5 * step) || (k + 1 == all && along > 0.5 * step)) continue;
      if (std::abs(along) < nearest) {
        nearest = std::abs(along);
        owner = k;
        offset = across;
      }
    }
    // Where the chip curls, a station's slab narrows (widens) across the chip by the factor 1 - curvature x
    // offset: a point there stands for that much more (less) thickness per length of inner surface.
    if (owner < n) area += 1.0 / std::max(0.2, 1.0 - curvature[owner] * offset);
  }
  return area * particle_spacing * particle_spacing / (static_cast<double>(n) * step);
}

double profile_area(const ChipProfile& profile) {
  double area = 0.0;
  for (double t : profile.thickness_m) area += t * profile.spacing_m;
  return area;
}

Segmentation measure_segmentation(const ChipProfile& profile, double prominence, double min_pitch,
                                  double narrow_width) {
  Segmentation s;
  s.thickness_m = profile.thickness_m;
  std::vector<double>& t = s.thickness_m;
  if (narrow_width > 0.0 && profile.spacing_m > 0.0) {
    const auto width = static_cast<std::size_t>(std::floor(narrow_width / profile.spacing_m + 1e-9));
    remove_narrow_excursions(t, prominence, std::max<std::size_t>(1, width));
  }
  double sum = 0.0, max = 0.0;
  std::size_t filled = 0;
  for (double v : t) {
    if (v > 0.0) {
      sum += v;
      ++filled;
    }
    max = std::max(max, v);
  }
  if (filled == 0) return s;
  s.mean_thickness_m = sum / static_cast<double>(filled);
  s.max_thickness_m = max;

  s.extrema = find_profile_extrema(t, prominence);
  if (min_pitch > 0.0 && profile.spacing_m > 0.0)
    merge_close_extrema(t, s.extrema, static_cast<std::size_t>(std::ceil(min_pitch / profile.spacing_m - 1e-9)));
  const auto mean_at = [&t](const std::vector<std::size_t>& idx) {
    double m = 0.0;
    for (std::size_t k : idx) m += t[k];
    return m / static_cast<double>(idx.size());
  };
  const std::vector<std::size_t>& peaks = s.extrema.peaks;
  const std::vector<std::size_t>& valleys = s.extrema.valleys;
  if (!peaks.empty() && !valleys.empty()) {
    s.segments = peaks.size();
    s.peak_height_m = mean_at(peaks);
    s.valley_height_m = mean_at(valleys);
    s.degree = (*s.peak_height_m - *s.valley_height_m) / *s.peak_height_m;
  } else {
    // No thickness variation beyond the prominence: flat at this resolution.
    s.peak_height_m = s.mean_thickness_m;
    s.valley_height_m = s.mean_thickness_m;
    s.degree = 0.0;
  }
  if (peaks.size() >= 2)
    s.pitch_m = profile.spacing_m * static_cast<double>(peaks.back() - peaks.front()) /
                static_cast<double>(peaks.size() - 1);
  return s;
}

}  // namespace mpmcut
