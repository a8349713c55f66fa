#pragma once
// How far the running cases of a study have got, for a periodic line on the console: a study of hour-long runs
// (validate, calibrate, sweep) would otherwise print nothing between one case's end and the next.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mpmcut {

// The share of its simulated time a run in `dir` has done, in [0, 1]: the time of the last row of history.csv over
// end_time_s of the summary.json the run writes at its start; none before both exist.
std::optional<double> run_fraction_done(const std::filesystem::path& dir);

// The result directory a child run writes (the value of its --out / -o argument); empty if it has none.
std::filesystem::path result_dir_of_args(const std::vector<std::string>& args);

// One running case as the progress line shows it.
struct RunningCase {
  std::string name;
  double wall_s = 0.0;                  // since this study started it
  std::optional<double> fraction;       // run_fraction_done now
  std::optional<double> remaining_s;    // estimated from the progress made since it was first seen
};

// "running: a 62 % (34 min, ~21 min left), b 5 % (3 min)"; cases without progress yet show their wall time only.
std::string progress_report_line(const std::vector<RunningCase>& cases);

}  // namespace mpmcut
