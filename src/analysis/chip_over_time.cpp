#include "analysis/chip_over_time.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace mpmcut {

namespace {

std::optional<double> number_of(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? std::optional<double>(j[key].get<double>()) : std::nullopt;
}

nlohmann::json sample_json(const ChipSample& s) {
  return {{"time_s", s.time_s},
          {"tool_travel_m", s.tool_travel_m},
          {"classification", s.classification},
          {"segments", s.segments},
          {"steady", s.steady},
          {"segmentation_degree", optional_json(s.segmentation_degree)},
          {"pitch_m", optional_json(s.pitch_m)},
          {"mean_thickness_m", optional_json(s.mean_thickness_m)},
          {"area_mean_thickness_m", optional_json(s.area_mean_thickness_m)}};
}

// Mean, min and max of one quantity over the samples that have it.
nlohmann::json statistics(const std::vector<ChipSample>& samples, std::optional<double> ChipSample::*field) {
  std::vector<double> v;
  for (const ChipSample& s : samples)
    if (s.*field) v.push_back(*(s.*field));
  if (v.empty()) return {{"mean", nullptr}, {"min", nullptr}, {"max", nullptr}, {"samples", 0}};
  double sum = 0.0;
  for (double x : v) sum += x;
  return {{"mean", sum / static_cast<double>(v.size())},
          {"min", *std::min_element(v.begin(), v.end())},
          {"max", *std::max_element(v.begin(), v.end())},
          {"samples", v.size()}};
}

}  // namespace

ChipSample chip_sample(const ChipAnalysis& a) {
  ChipSample s;
  s.time_s = a.time_s;
  s.tool_travel_m = a.tool_travel_m;
  s.classification = a.classification;
  s.segments = a.segmentation.segments;
  s.steady = a.profile_note.empty() && a.steady_samples > 0;
  s.segmentation_degree = a.segmentation.degree;
  s.pitch_m = a.segmentation.pitch_m;
  s.mean_thickness_m = a.segmentation.mean_thickness_m;
  s.area_mean_thickness_m = a.area_mean_thickness_m;
  return s;
}

bool ChipSampling::due(double tool_travel_m, const std::vector<ChipSample>& taken) const {
  if (tool_travel_m < first_travel_m) return false;
  // Next at first + k interval (not last + interval), so that the samples do not drift with the history cadence.
  const double next = first_travel_m + interval_m * static_cast<double>(taken.size());
  return taken.empty() || tool_travel_m >= next - 1e-9 * interval_m;
}

nlohmann::json chip_over_time_json(const std::vector<ChipSample>& samples, const ChipSampling& sampling) {
  nlohmann::json j;
  j["first_tool_travel_m"] = sampling.first_travel_m;
  j["tool_travel_interval_m"] = sampling.interval_m;
  std::vector<ChipSample> steady;
  for (const ChipSample& s : samples)
    if (s.steady) steady.push_back(s);
  j["steady_samples"] = steady.size();
  j["note"] = steady.empty() && !samples.empty()
                  ? nlohmann::json("no state's chip held twice the entry chip (3 t0^2 of profile area), so every one "
                                   "still measured part of it: the cut is too short for statistics over time (a "
                                   "longer cut_length gives them); the samples are listed, not averaged")
                  : nlohmann::json(nullptr);
  std::map<std::string, int> types;
  for (const ChipSample& s : steady) ++types[s.classification];
  j["classifications"] = types;
  j["segmentation_degree"] = statistics(steady, &ChipSample::segmentation_degree);
  j["pitch_m"] = statistics(steady, &ChipSample::pitch_m);
  j["mean_thickness_m"] = statistics(steady, &ChipSample::mean_thickness_m);
  j["area_mean_thickness_m"] = statistics(steady, &ChipSample::area_mean_thickness_m);
  j["samples"] = nlohmann::json::array();
  for (const ChipSample& s : samples) j["samples"].push_back(sample_json(s));
  j["definition"] = "docs/analysis.md";
  return j;
}

std::string chip_over_time_text(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("samples") || !j["samples"].is_array() || j["samples"].empty()) return {};
  if (!j.contains("steady_samples") || !j["steady_samples"].is_number() || j["steady_samples"].get<int>() == 0)
    return fmt::format("  over the steady window ({} states): none past the entry chip, no statistics (a longer cut "
                       "gives them)\n",
                       j["samples"].size());
  const auto range = [&](const char* key, double scale, const char* unit, const char* format) {
    if (!j.contains(key) || !j[key].is_object() || !j[key]["mean"].is_number()) return std::string("-");
    const auto f = [&](const char* k) { return fmt::format(fmt::runtime(format), j[key][k].get<double>() * scale); };
    return fmt::format("{}{} ({}-{})", f("mean"), unit, f("min"), f("max"));
  };
  return fmt::format("  over the steady window ({} states past the entry chip): Gs {}, thickness {} (by area {})\n",
                     j["steady_samples"].get<int>(),
                     range("segmentation_degree", 1.0, "", "{:.2f}"), range("mean_thickness_m", 1e6, " um", "{:.1f}"),
                     range("area_mean_thickness_m", 1e6, " um", "{:.1f}"));
}

std::string chip_samples_text(const std::vector<ChipSample>& samples) {
  nlohmann::json j = nlohmann::json::array();
  for (const ChipSample& s : samples) j.push_back(sample_json(s));
  return j.dump();
}

std::vector<ChipSample> chip_samples_from_text(std::string_view text) {
  std::vector<ChipSample> samples;
  if (text.empty()) return samples;  // a checkpoint written before the samples were kept
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_array()) throw std::runtime_error("chip samples: the checkpoint's text is not a list of samples");
  for (const nlohmann::json& e : j) {
    if (!e.is_object() || !e.contains("time_s") || !e.contains("tool_travel_m") || !e.contains("classification"))
      throw std::runtime_error("chip samples: a sample without time_s, tool_travel_m or classification");
    ChipSample s;
    s.time_s = e["time_s"].get<double>();
    s.tool_travel_m = e["tool_travel_m"].get<double>();
    s.classification = e["classification"].get<std::string>();
    s.segments = e.value("segments", std::size_t{0});
    s.steady = e.value("steady", false);
    s.segmentation_degree = number_of(e, "segmentation_degree");
    s.pitch_m = number_of(e, "pitch_m");
    s.mean_thickness_m = number_of(e, "mean_thickness_m");
    s.area_mean_thickness_m = number_of(e, "area_mean_thickness_m");
    samples.push_back(s);
  }
  return samples;
}

}  // namespace mpmcut
