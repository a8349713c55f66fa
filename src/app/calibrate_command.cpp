#include "app/calibrate_command.hpp"

#include <filesystem>
#include <iostream>
#include <thread>

#include <fmt/format.h>

#include "app/command_exit.hpp"
#include "app/plot_command.hpp"
#include "app/path_option.hpp"
#include "app/progress_option.hpp"
#include "io/input_error.hpp"
#include "run/run_options.hpp"
#include "studies/calibration.hpp"
#include "studies/task_farm.hpp"

namespace mpmcut {

namespace {

namespace fs = std::filesystem;

struct CalibrateOptions {
  std::string config_file;
  std::string out_dir;
  int jobs = 0;
  double progress_interval_s = kDefaultProgressIntervalS;
  bool force = false;
  bool no_plots = false;
};

int calibrate(const CalibrateOptions& o) {
  CalibrationConfig config;
  fs::path out;
  try {
    // Everything is checked before anything runs.
    config = read_calibration_config(o.config_file, embedded_tool_file(kBuiltinForcesFile));
    out = o.out_dir.empty() ? fs::path("results") / ("calibration_" + fs::path(o.config_file).stem().string())
                            : fs::path(o.out_dir);
    // A directory that holds no calibration.toml is not a calibration's: neither written into nor (--force)
    // deleted, so that a mistyped --out cannot wipe or litter unrelated files.
    std::error_code ec;
    if (fs::exists(out) && !fs::is_directory(out))
      throw InputError(fmt::format("--out {}: a file of that name exists, not a directory; choose another --out",
                                   out.string()));
    if (fs::exists(out) && !fs::is_empty(out, ec) && !fs::exists(out / "calibration.toml"))
      throw InputError(fmt::format("--out {}: the directory is not empty and holds no calibration.toml, so it is not "
                                   "a calibration's result directory; refusing to {} it. Choose another --out",
                                   out.string(), o.force ? "delete" : "write into"));
    if (o.force) fs::remove_all(out);
    const int jobs = o.jobs > 0 ? o.jobs
                                : std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / config.threads);
    const int code = run_calibration(config, out, jobs, o.progress_interval_s);
    if (code == 130) return code;
    if (!o.no_plots) {
      std::string why;
      if (!python_plotting_available(false, why))
        std::cerr << "warning: no calibration plots: " << why << "\n";
      else if (const int plot = run_python_tool("plot_calibration.py", {out.string()}); plot != 0)
        std::cerr << "warning: plot_calibration.py failed (exit status " << plot << ")\n";
    }
    return code;
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit material parameters (and the tool friction) to measured cutting forces with NLopt: "
                   "evaluations.csv, best_material.toml, calibration.md, plots (docs/calibration.md)");
  cmd->add_option("config", o->config_file, "Calibration file (TOML), e.g. cases/calibration/ti64_klippel_forces.toml")
      ->required();
  cmd->add_option("-o,--out", o->out_dir, "Result directory (default: results/calibration_<config name>); an "
                                          "existing one with the same configuration is resumed")
      ->check(non_empty_path());
  cmd->add_option("-j,--jobs", o->jobs, "Runs at the same time (default: cores / threads of each run)")
      ->check(CLI::Range(1, 1024));
  add_progress_option(cmd, o->progress_interval_s);
  cmd->add_flag("-f,--force", o->force, "Delete the result directory first (no resume)");
  cmd->add_flag("--no-plots", o->no_plots, "Only the tables");
  cmd->callback([o]() { finish_command([&] { return run_study([&] { return calibrate(*o); }); }); });
}

}  // namespace mpmcut
