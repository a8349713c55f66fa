#include "app/analyze_command.hpp"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "app/path_option.hpp"
#include "analysis/chip_analysis.hpp"
#include "run/run_case.hpp"
#include "io/directory_lock.hpp"
#include "io/input_error.hpp"
#include "analysis/chip_over_time.hpp"
#include "run/run_outputs.hpp"
#include "run/run_summary.hpp"
#include "io/pvd_writer.hpp"
#include "run/case_loading.hpp"
#include "io/vtu_reader.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

namespace {

// A user-facing problem with the arguments or the directory: message, exit code 2.
struct AnalyzeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// Another run writes into the directory: exit code 4, as for `run` and `resume` into a directory in use.
struct DirectoryInUse : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The snapshot files of a run in time order: from particles.pvd, which lists exactly the
// snapshots that were completed.
std::vector<PvdSeries::Entry> snapshots_of(const fs::path& dir) {
  const fs::path index = dir / "particles.pvd";
  if (!fs::exists(index))
    throw AnalyzeError(fmt::format("'{}' has no particles.pvd: the run wrote no snapshots (output.vtu = false?)",
                                   dir.string()));
  std::vector<PvdSeries::Entry> entries = PvdSeries::read(index).entries();
  if (entries.empty()) throw AnalyzeError(fmt::format("'{}' lists no snapshots", index.string()));
  return entries;
}

// `choice` is "last" or the snapshot number N of snapshots/particles_N.vtu (0 = first).
PvdSeries::Entry pick_snapshot(const std::vector<PvdSeries::Entry>& entries, const std::string& choice) {
  if (choice == "last") return entries.back();
  const long n = snapshot_number(choice);
  if (n < 0) throw AnalyzeError(fmt::format("--snapshot '{}': expected a snapshot number (0, 1, ...) or 'last'", choice));
  for (const PvdSeries::Entry& e : entries)
    if (snapshot_index(fs::path(e.file).filename().string()) == n) return e;
  throw AnalyzeError(fmt::format("--snapshot {}: no such snapshot; this run has {} ({} to {})", n, entries.size(),
                                 fs::path(entries.front().file).filename().string(),
                                 fs::path(entries.back().file).filename().string()));
}

int analyze(const fs::path& dir, const std::string& snapshot) {
  Case loaded;
  try {
    loaded = load_cutting_result_scene(dir, "the chip analysis needs the cut's parameters");
  } catch (const InputError& e) {
    throw AnalyzeError(e.what());
  }
  // The analysis is merged into summary.json: not while a run writes into the directory (its last snapshot then is
  // an early state, and the run's own summary would overwrite the merge or be overwritten by it).
  DirectoryLock lock;
  try {
    lock = DirectoryLock::acquire(dir);
  } catch (const std::runtime_error& e) {
    throw DirectoryInUse(fmt::format("{} (mpmcut analyze: run it once that run has finished or stopped)", e.what()));
  }
  const fs::path summary_file = dir / "summary.json";
  RunSummary summary = read_summary(summary_file);

  const std::vector<PvdSeries::Entry> entries = snapshots_of(dir);
  const PvdSeries::Entry entry = pick_snapshot(entries, snapshot);
  const fs::path vtu = dir / entry.file;
  const VtuSnapshot snap = read_particles_vtu(vtu);
  // The tool moves at its prescribed velocity from t = 0 (cutting_scene.cpp).
  const Scene& scene = loaded.scene;
  const Vec2 displacement = scene.rigid_bodies.at(0).velocity * snap.time_s;
  const ChipAnalysis a =
      analyze_chip(snap.particles, chip_analysis_setup(scene, *loaded.cutting, displacement, snap.time_s));

  std::cout << fmt::format("{} ({})\n", dir.string(), entry.file) << chip_summary_text(a);
  // The run's own samples over its steady window (analysed while it ran; a snapshot gives one instant).
  if (const auto over_time = summary.sections.find("chip_over_time"); over_time != summary.sections.end())
    std::cout << chip_over_time_text(*over_time);
  // summary.json describes the run's final state (its fracture, energy and temperature sections too): an earlier
  // snapshot's analysis is shown, not merged (it replaced the final chip, so that plot then drew the last snapshot
  // beside another one's chip numbers).
  if (entry.file != entries.back().file) {
    std::cout << fmt::format("not merged into {}: it describes the final state ({}); this is {}\n",
                             summary_file.string(), fs::path(entries.back().file).filename().string(),
                             fs::path(entry.file).filename().string());
    return kExitComplete;
  }
  nlohmann::json chip = chip_json(a), temperature = temperature_json(a);
  chip["source"] = entry.file;
  temperature["source"] = entry.file;
  summary.sections["chip"] = chip;
  summary.sections["temperature"] = temperature;
  write_summary(summary_file, summary);
  std::cout << fmt::format("results merged into {} (\"chip\", \"temperature\")\n", summary_file.string());
  return kExitComplete;
}

}  // namespace

int analyze_result_directory(const fs::path& dir, const std::string& snapshot) {
  try {
    return analyze(dir, snapshot);
  } catch (const AnalyzeError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const DirectoryInUse& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitOutputError;
  } catch (const std::exception& e) {
    // Unreadable snapshot or summary, unwritable directory: the messages name the file.
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

void add_analyze_command(CLI::App& app) {
  struct Options {
    std::string dir;
    std::string snapshot = "last";
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "analyze", "Chip analysis of a cutting run's snapshot (morphology, segmentation, shear angle, temperatures); "
                 "merges the results of the last snapshot into its summary.json");
  cmd->add_option("result_dir", options->dir, "Result directory of a cutting run")->required()->check(non_empty_path());
  cmd->add_option("--snapshot", options->snapshot, "Snapshot number N (snapshots/particles_N.vtu) or 'last'")
      ->capture_default_str();
  cmd->callback([options] { throw CLI::RuntimeError(analyze_result_directory(options->dir, options->snapshot)); });
}

}  // namespace mpmcut
