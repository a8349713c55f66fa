#pragma once
// The chip analysis repeated over the steady part of a cut. One instant's segmentation degree, pitch and
// thickness are not stable numbers: two runs of one serrated cut that differ only by round-off read Gs 0.56 and
// 0.19 at their final states (docs/calibration.md). The chip observer (run/chip_observer.hpp) analyses the chip
// every `interval` of tool travel from the force's steady window on; this file keeps those samples and reports
// their mean and range (summary.json "chip_over_time", docs/analysis.md).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "analysis/chip_analysis.hpp"

namespace mpmcut {

struct ChipSample {
  double time_s = 0.0;
  double tool_travel_m = 0.0;
  std::string classification;
  std::size_t segments = 0;
  // Whether the analysis left the whole entry chip out (no profile note): only such states describe the steady
  // chip. Until the profile holds twice the entry chip's 3 t0^2 (about 6 t0 of travel) the measured part still
  // includes the end of the entry chip, which is thicker (docs/analysis.md).
  bool steady = false;
  std::optional<double> segmentation_degree, pitch_m, mean_thickness_m, area_mean_thickness_m;
};
ChipSample chip_sample(const ChipAnalysis& a);

// When the next sample is due: from `first_travel_m` of tool travel on, every `interval_m`.
struct ChipSampling {
  double first_travel_m = 0.0;
  double interval_m = 0.0;
  bool due(double tool_travel_m, const std::vector<ChipSample>& taken) const;
};

// summary.json's "chip_over_time": the samples, and per quantity its mean, min and max over the steady samples
// that have it (null without any), and how many steady samples had each chip type; a note where none is steady.
nlohmann::json chip_over_time_json(const std::vector<ChipSample>& samples, const ChipSampling& sampling);

// One line for the terminal: the number of states, Gs, t_c and t_A as mean (min–max); empty without samples.
std::string chip_over_time_text(const nlohmann::json& chip_over_time);

// The samples as text and back, for checkpoints (exact: doubles round-trip). Throws std::runtime_error on text
// that is not such a list.
std::string chip_samples_text(const std::vector<ChipSample>& samples);
std::vector<ChipSample> chip_samples_from_text(std::string_view text);

}  // namespace mpmcut
