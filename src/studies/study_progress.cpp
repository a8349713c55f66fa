#include "studies/study_progress.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "run/run_summary.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

namespace {

// The first field of the last complete line of a CSV file, read from its tail only (history.csv may hold a row per
// step: hundreds of MB).
std::optional<double> last_row_first_number(const fs::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return std::nullopt;
  const std::streamoff size = in.tellg();
  const std::streamoff tail = std::min<std::streamoff>(size, 8192);
  in.seekg(size - tail);
  std::string text(static_cast<std::size_t>(tail), '\0');
  in.read(text.data(), tail);
  // Drop a row being written (no newline yet), then take the last line.
  const auto end = text.rfind('\n');
  if (end == std::string::npos) return std::nullopt;
  text.resize(end);
  const auto start = text.rfind('\n');
  const std::string line = start == std::string::npos ? text : text.substr(start + 1);
  char* stop = nullptr;
  const double x = std::strtod(line.c_str(), &stop);
  if (stop == line.c_str() || (*stop != ',' && *stop != '\0') || !std::isfinite(x)) return std::nullopt;  // the header
  return x;
}

std::string minutes_text(double s) {
  return s < 90.0 ? fmt::format("{:.0f} s", s) : s < 5400.0 ? fmt::format("{:.0f} min", s / 60.0)
                                                              : fmt::format("{:.1f} h", s / 3600.0);
}

}  // namespace

std::optional<double> run_fraction_done(const fs::path& dir) {
  double end_time = 0.0;
  try {
    end_time = read_summary(dir / "summary.json").end_time_s;
  } catch (const std::exception&) {  // not written yet, or being rewritten at this moment
    return std::nullopt;
  }
  const std::optional<double> t = last_row_first_number(dir / "history.csv");
  if (!t || !(end_time > 0.0)) return std::nullopt;
  return std::clamp(*t / end_time, 0.0, 1.0);
}

fs::path result_dir_of_args(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--out" || args[i] == "-o") return args[i + 1];
  return {};
}

std::string progress_report_line(const std::vector<RunningCase>& cases) {
  std::string line = "running:";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const RunningCase& c = cases[i];
    line += fmt::format("{} {}", i == 0 ? "" : ",", c.name);
    if (c.fraction) line += fmt::format(" {:.0f} %", 100.0 * *c.fraction);
    line += " (" + minutes_text(c.wall_s);
    if (c.remaining_s) line += ", ~" + minutes_text(*c.remaining_s) + " left";
    line += ")";
  }
  return line;
}

}  // namespace mpmcut
