// Long runs that survive (docs/reliability.md), tested through the real command line as a user
// meets them: kill -9 then resume, Ctrl-C then resume, corrupt checkpoints, --force, an
// unwritable directory, a write that fails (file-size limit), and bit-identical results.
//
// The case: a Ti-6Al-4V block (Johnson-Cook plasticity, damage, conduction) pushed by a rounded
// rigid punch with friction: ~1.9k particles, ~630 steps, so every particle field, the rigid-body
// state and all energy terms change during the run. About 0.6 s per run on one thread.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <fstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli.hpp"

namespace mpmcut::testing {
namespace {

constexpr const char* kPunchCase = R"toml(
title = "Reliability test: Ti-6Al-4V block pushed by a rigid punch"
[grid]
cell_size = 40.0e-6
min = [0.0, 0.0]
max = [2.0e-3, 1.0e-3]
[boundaries]
left = "fixed"
bottom = "fixed"
[solver]
end_time = 1.5e-6
[output]
snapshot_interval = 0.25e-6
[thermal]
conduction = true
bottom = 300.0
[[material]]
name = "ti64"
library = "ti64-johnson-1985"
fracture_toughness = 55.0e6
[[body]]
name = "workpiece"
material = "ti64"
rectangle = { min = [0.0, 0.0], max = [1.5e-3, 0.5e-3] }
particles_per_cell = 2
temperature = 300.0
[[rigid_body]]
name = "punch"
polygon = [[0.6e-3, 0.5e-3], [1.0e-3, 0.5e-3], [1.0e-3, 0.9e-3], [0.6e-3, 0.9e-3]]
rounding_radius = 10.0e-6
velocity = [0.0, -100.0]
friction = 0.35
)toml";

class LongRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("mpmcut_reliability_") + info->name() + "_" +
                                        std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    case_file_ = dir_ / "punch.toml";
    write_file(case_file_, kPunchCase);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);  // kept for inspection when a test fails
  }

  fs::path out(const std::string& name) const { return dir_ / name; }

  // mpmcut run <case> --out <dir> --no-progress [--threads 1] <extra...>
  CliResult run(const std::string& name, std::vector<std::string> extra = {}, long fsize_limit = 0) {
    std::vector<std::string> args{"run", case_file_.string(), "--out", out(name).string(), "--no-progress"};
    if (std::find(extra.begin(), extra.end(), "--threads") == extra.end()) args.insert(args.end(), {"--threads", "1"});
    args.insert(args.end(), extra.begin(), extra.end());
    std::string log = name + ".log";
    std::replace(log.begin(), log.end(), '/', '_');
    return run_mpmcut(args, dir_ / log, fsize_limit);
  }
  CliResult resume(const std::string& name, std::vector<std::string> extra = {}, long fsize_limit = 0) {
    std::vector<std::string> args{"resume", out(name).string(), "--no-progress"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_mpmcut(args, dir_ / (name + ".resume.log"), fsize_limit);
  }

  // The reference: the same case run straight through.
  void run_reference() {
    const CliResult r = run("reference");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }

  // Starts a run with a checkpoint every 100 steps and, as soon as checkpoints/latest names
  // step >= `step`, sends `signal`. Returns the run's exit code.
  int run_and_signal(const std::string& name, long step, int signal) {
    const pid_t pid = spawn_mpmcut({"run", case_file_.string(), "--out", out(name).string(), "--no-progress",
                                    "--threads", "1", "--checkpoint-every", "100steps"},
                                   {dir_ / (name + ".log")});
    int code = -1;
    const bool reached = wait_until([&] { return latest_checkpoint_step(out(name)) >= step || exited(pid, code); });
    if (code >= 0) {
      ADD_FAILURE() << "the run ended (exit " << code << ") before it could be signalled:\n"
                    << read_file(dir_ / (name + ".log"));
      return code;
    }
    EXPECT_TRUE(reached) << "no checkpoint at step " << step << " within 60 s";
    ::kill(pid, signal);
    return wait_exit_code(pid);
  }

  fs::path dir_;
  fs::path case_file_;
};

// SIGKILL at an arbitrary moment after the checkpoint of step 300 (of ~630): the directory stays
// "running", `resume` continues from the last checkpoint, and every output (history, rigid
// forces, PVD, every VTU snapshot, scene) is bit-identical to the uninterrupted run.
TEST_F(LongRuns, KillNineThenResumeIsBitIdentical) {
  run_reference();
  EXPECT_EQ(run_and_signal("killed", 300, SIGKILL), 128 + SIGKILL);
  EXPECT_EQ(summary_status(out("killed")), "running");
  const CliResult r = resume("killed");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("resuming"), std::string::npos) << r.output;
  EXPECT_EQ(summary_status(out("killed")), "complete");
  expect_identical_outputs(out("reference"), out("killed"));
  const std::string history = read_file(out("killed") / "history.csv");
  const std::string summary = read_file(out("killed") / "summary.json");
  const auto k = summary.find("\"steps\": ");
  ASSERT_NE(k, std::string::npos) << summary;
  EXPECT_EQ(std::count(history.begin(), history.end(), '\n'), std::stol(summary.substr(k + 9)) + 2)
      << "header + t=0 row + one row per step: no duplicate or missing rows";
}

// SIGINT: the run finishes its step, writes a checkpoint and the outputs so far, marks
// summary.json "interrupted" and exits with 130; resume completes it bit-identically.
TEST_F(LongRuns, SigintCheckpointsAndResumeIsBitIdentical) {
  run_reference();
  EXPECT_EQ(run_and_signal("interrupted", 200, SIGINT), 130);
  EXPECT_EQ(summary_status(out("interrupted")), "interrupted");
  const std::string log = read_file(dir_ / "interrupted.log");
  EXPECT_NE(log.find("mpmcut resume"), std::string::npos) << "the message should say how to continue:\n" << log;
  // The interruption checkpoint is at the step where the run stopped, not at a multiple of 100.
  const std::string summary = read_file(out("interrupted") / "summary.json");
  EXPECT_NE(summary.find("last_checkpoint"), std::string::npos) << summary;
  EXPECT_NE(summary.find("stopped on request: SIGINT (Ctrl-C) at step"), std::string::npos) << summary;
  const CliResult r = resume("interrupted");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(summary_status(out("interrupted")), "complete");
  expect_identical_outputs(out("reference"), out("interrupted"));
}

// A truncated and a bit-flipped newest checkpoint are each rejected with a clear message and
// the previous checkpoint is used; the result is still bit-identical.
TEST_F(LongRuns, CorruptNewestCheckpointFallsBackToPrevious) {
  run_reference();
  EXPECT_EQ(run_and_signal("truncated", 300, SIGKILL), 128 + SIGKILL);
  const long newest = latest_checkpoint_step(out("truncated"));
  ASSERT_GE(newest, 300);
  fs::copy(out("truncated"), out("flipped"), fs::copy_options::recursive);
  const std::string name = "checkpoint_" + std::to_string(newest) + ".bin";

  const fs::path truncated = out("truncated") / "checkpoints" / name;
  fs::resize_file(truncated, fs::file_size(truncated) - 1000);
  CliResult r = resume("truncated");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("is truncated"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("falling back to the previous valid checkpoint"), std::string::npos) << r.output;
  expect_identical_outputs(out("reference"), out("truncated"));

  const fs::path flipped = out("flipped") / "checkpoints" / name;
  std::string bytes = read_file(flipped);
  bytes[bytes.size() / 2] ^= 0x10;  // one bit in the middle of the particle data
  write_file(flipped, bytes);
  r = resume("flipped");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("is corrupt: payload CRC mismatch"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("falling back"), std::string::npos) << r.output;
  expect_identical_outputs(out("reference"), out("flipped"));
}

// A write that fails (here: the file-size limit makes it fail with EFBIG, as a full disk fails
// with ENOSPC) is a clear output error with exit code 4, not a crash by SIGXFSZ; the checkpoints
// are untouched, and once the cause is gone, resume completes the run bit-identically.
TEST_F(LongRuns, WriteErrorKeepsLastCheckpointAndResumeCompletes) {
  run_reference();
  EXPECT_EQ(run_and_signal("limited", 200, SIGKILL), 128 + SIGKILL);
  std::map<std::string, std::string> checkpoints_before;
  for (const auto& e : fs::directory_iterator(out("limited") / "checkpoints"))
    checkpoints_before[e.path().filename().string()] = read_file(e.path());

  // 100 kB: smaller than a snapshot (~600 kB) and a checkpoint (~470 kB), larger than the CSVs.
  CliResult r = resume("limited", {}, 100 * 1024);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is intact"), std::string::npos) << r.output;
  EXPECT_EQ(summary_status(out("limited")), "failed");
  std::map<std::string, std::string> checkpoints_after;
  for (const auto& e : fs::directory_iterator(out("limited") / "checkpoints"))
    checkpoints_after[e.path().filename().string()] = read_file(e.path());
  EXPECT_TRUE(checkpoints_before == checkpoints_after) << "the failed run changed the checkpoints";

  r = resume("limited");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_identical_outputs(out("reference"), out("limited"));
}

// The first snapshot cannot be written (50 kB: summary.json and scene.toml fit, a ~600 kB snapshot does not): the
// directory said "running" without a message and looked like a run in progress.
TEST_F(LongRuns, AWriteErrorAtTheFirstSnapshotMarksTheRunFailed) {
  const CliResult r = run("first", {}, 50 * 1024);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  EXPECT_EQ(summary_status(out("first")), "failed");
  const nlohmann::json summary = nlohmann::json::parse(read_file(out("first") / "summary.json"));
  EXPECT_NE(summary.value("message", "").find("output error"), std::string::npos) << summary.dump(2);
}

// A history interval that does not divide the end time (0.4 of 1.5 us) left the final state without a row.
TEST_F(LongRuns, TheHistoryEndsWithARowAtTheEndTime) {
  const CliResult r = run("history", {"--set", "output.history_interval=0.4e-6", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream rows(read_file(out("history") / "history.csv"));
  std::vector<double> times;
  for (std::string line; std::getline(rows, line);)
    if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) times.push_back(std::stod(line));
  ASSERT_EQ(times.size(), 5u);  // 0, 0.4, 0.8, 1.2 and 1.5 us
  EXPECT_NEAR(times.back(), 1.5e-6, 1e-15);
}

// A directory option given as an empty path ran into results/<case> (run) or the current directory: refused.
TEST_F(LongRuns, AnEmptyDirectoryOptionIsRefused) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", case_file_.string(), "--out", ""}, {"resume", ""}, {"analyze", ""},
        {"plot", ""}, {"sweep", case_file_.string(), "--speeds", "1", "--out", ""}, {"convergence", ""},
        {"calibrate", case_file_.string(), "--out", ""}, {"validate", "--records", ""}}) {
    const CliResult r = run_mpmcut(args, dir_ / "empty.log");
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.output;
    EXPECT_NE(r.output.find("an empty path"), std::string::npos) << args[0] << ": " << r.output;
  }
}

// An existing result directory is not overwritten without --force; with --force it is, but
// only if it is an mpmcut result (has summary.json).
TEST_F(LongRuns, ExistingResultDirectoryNeedsForce) {
  CliResult r = run("forced", {"--set", "solver.max_steps=5"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string history = read_file(out("forced") / "history.csv");
  r = run("forced", {"--set", "solver.max_steps=10"});
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("already exists; use --force"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(out("forced") / "history.csv"), history) << "the refused run changed the directory";
  r = run("forced", {"--set", "solver.max_steps=10", "--force"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_file(out("forced") / "history.csv"), history);

  fs::create_directories(out("not_a_result"));
  write_file(out("not_a_result") / "thesis.tex", "precious");
  r = run("not_a_result", {"--set", "solver.max_steps=5", "--force"});
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("is not an mpmcut result; --force does not delete"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(out("not_a_result") / "thesis.tex"), "precious");
  // Without --force it says at once that --force would not help (it suggested --force, which then refused).
  r = run("not_a_result", {"--set", "solver.max_steps=5"});
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("is not an mpmcut result; --force does not delete"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("use --force"), std::string::npos) << r.output;
}

// An output directory that cannot be created (a path under a regular file; the tests may run
// as root, for whom a read-only directory is writable) is a clear error, exit code 4.
TEST_F(LongRuns, UnwritableOutputDirectoryIsAClearError) {
  write_file(out("plain_file"), "x");
  const CliResult r = run("plain_file/results", {"--set", "solver.max_steps=5"});
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("plain_file"), std::string::npos) << "the message should name the path:\n" << r.output;
  EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
}

// resume refuses what it cannot continue faithfully, each with a message that says why.
TEST_F(LongRuns, ResumeRefusesCompleteRunsChangedScenesAndNonResults) {
  CliResult r = run("done", {"--set", "solver.max_steps=30", "--checkpoint-every", "10"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = resume("done");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("its run is complete"), std::string::npos) << r.output;
  r = resume("done", {"--force"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // Without a checkpoint --force cannot help either: the refusal says so (it suggested --force).
  r = run("no_checkpoint", {"--set", "solver.max_steps=30", "--checkpoint-every", "off"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = resume("no_checkpoint");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("kept no checkpoint"), std::string::npos) << r.output;

  // A scene.toml edited after the run: the checkpoint's scene hash no longer matches.
  std::string scene = read_file(out("done") / "scene.toml");
  const auto k = scene.find("cfl = ");
  ASSERT_NE(k, std::string::npos) << scene;
  scene.replace(k, scene.find('\n', k) - k, "cfl = 0.3");
  write_file(out("done") / "scene.toml", scene);
  r = resume("done", {"--force"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("scene.toml differs"), std::string::npos) << r.output;

  r = resume("no_such_directory");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no such result directory"), std::string::npos) << r.output;
}

// A run made by an older model of its scene (solver/model_version.hpp) is not kept, resumed or continued. The
// punch with penalty contact and friction is of model version 1 (the friction spring's slip from the grid); its
// summary with the version taken out stands for a run made before that change; the same punch with node
// detection is of version 0, so its runs of any age stay current.
TEST_F(LongRuns, RunsOfAnOlderModelOfTheirSceneAreRunAgainNotKeptOrResumed) {
  // Penalty contact needs a gap between the punch and the particles' domains at the start.
  const std::vector<std::string> penalty{
      "--set", "solver.contact_detection=penalty", "--set", "solver.max_steps=30", "--checkpoint-every", "10", "--set",
      "rigid_body[0].polygon=[[0.6e-3, 0.52e-3], [1.0e-3, 0.52e-3], [1.0e-3, 0.9e-3], [0.6e-3, 0.9e-3]]"};
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), penalty.begin(), penalty.end());
    return extra;
  };
  auto model_version = [&](const std::string& name) {
    const nlohmann::json s = nlohmann::json::parse(read_file(out(name) / "summary.json"));
    return s.contains("model_version") ? s["model_version"].get<int>() : -1;
  };
  auto forget_model_version = [&](const std::string& name) {
    nlohmann::json s = nlohmann::json::parse(read_file(out(name) / "summary.json"));
    s.erase("model_version");
    write_file(out(name) / "summary.json", s.dump(2));
  };
  CliResult r = run("penalty", penalty);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(model_version("penalty"), 1);
  r = run("penalty", with({"--keep-complete"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("already holds the complete run"), std::string::npos) << r.output;

  // Made before the change: run again from the start (and then current), not kept.
  forget_model_version("penalty");
  r = run("penalty", with({"--keep-complete"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("is outdated (made by model version 0 of this scene; since then: version 1 (08f9ca5): "
                          "penalty contact"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("already holds"), std::string::npos) << r.output;
  EXPECT_EQ(model_version("penalty"), 1);
  // Nor continued from its checkpoint: the refusal says how to run it again.
  forget_model_version("penalty");
  r = resume("penalty", {"--force"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("made by model version 0 of its scene"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--force"), std::string::npos) << r.output;

  // Node detection: version 0, a summary without the key is as current as one with it.
  r = run("node", {"--set", "solver.max_steps=30", "--checkpoint-every", "10"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(model_version("node"), 0);
  forget_model_version("node");
  r = run("node", {"--set", "solver.max_steps=30", "--checkpoint-every", "10", "--keep-complete"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("already holds the complete run"), std::string::npos) << r.output;
}

// A cut interrupted inside its steady window and resumed: the forces observer's sums (steady-window means, the
// rake face's forces, slip speed and frictional work, the edge and flank's) travel in the checkpoint, so the
// summary's tool results equal the uninterrupted run's to the last digit. The tool conducts heat (steady): its
// field and averaged heat input travel too (tool_heat.tool_temperature, tool_temperature.csv), and the resumed run
// reads the conducting tool's inputs back from the result's scene.toml (the summary's `cutting` inputs).
TEST_F(LongRuns, CutResumedInsideItsSteadyWindowKeepsTheToolResults) {
  // The tiny cut's steady window starts at half of its travel.
  std::string text = read_file(fs::path(MPMCUT_TEST_DIR) / "support" / "cases" / "tiny_cut.toml");
  text.replace(text.find("[cutting]\n"), 10,
               "[cutting]\ntool_heat_transfer_coefficient = 1e6\ntool_conductivity = 86.0\n");
  std::ofstream(case_file_) << text;
  const CliResult ref = run("reference", {"--no-plots"});
  ASSERT_EQ(ref.exit_code, 0) << ref.output;
  // Its 0.1 mm of travel gives no chip of twice the entry chip's area: the console says so beside the forces.
  EXPECT_NE(ref.output.find("warning: chip statistics over time: no state's chip held twice the entry chip"),
            std::string::npos)
      << ref.output;
  const nlohmann::json expected = nlohmann::json::parse(read_file(out("reference") / "summary.json"));
  const long steps = expected.at("steps").get<long>();
  // Interrupt inside the window, at a checkpoint past 70 % of the steps.
  EXPECT_EQ(run_and_signal("interrupted", steps * 7 / 10, SIGINT), 130);
  // A picture drawn of the interrupted state (mpmcut plot) is not redrawn by resume --no-plots: it says so.
  std::ofstream(out("interrupted") / "forces.png") << "drawn before the resume";
  const CliResult r = resume("interrupted", {"--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 .png picture(s) in " + out("interrupted").string() + " were drawn before this run ended"),
            std::string::npos)
      << r.output;
  const nlohmann::json actual = nlohmann::json::parse(read_file(out("interrupted") / "summary.json"));
  ASSERT_TRUE(expected.contains("rake_face")) << expected.dump(2);
  ASSERT_TRUE(expected["rake_face"].contains("friction_work_per_travel_N_per_mm")) << expected.dump(2);
  ASSERT_TRUE(expected["edge_and_flank"].contains("edge_arc")) << expected.dump(2);  // the split survives a resume
  ASSERT_TRUE(expected["tool_heat"].contains("tool_temperature")) << expected.dump(2);
  EXPECT_EQ(expected["cutting"].at("tool_conductivity_W_per_mK"), 86.0);
  for (const char* key : {"mean_cutting_force_N_per_mm", "mean_thrust_force_N_per_mm", "tool_chip_contact_length_m",
                          "rake_face", "edge_and_flank", "tool_heat", "steady_window", "cutting"})
    EXPECT_EQ(actual.at(key), expected.at(key)) << key;
  EXPECT_EQ(read_file(out("interrupted") / "tool_temperature.csv"), read_file(out("reference") / "tool_temperature.csv"));
}

// P2G is coloured by strips of grid rows in a fixed order and every sum over particles uses
// fixed chunks, so the results do not depend on the thread count (and repeat exactly). Gravity
// is switched on so that the body-force work is part of the comparison.
// The number of snapshots does not change the results: with history every end/120 and snapshots every end/20,
// end/10, end/5 or end/2 (the cutting preset's history and a user's choice of snapshots), the snapshot times are
// history times, and the steps land on the same times whatever the snapshot count (their running sums differed
// in the last bits, and the serrated cut at 381.3 m/min gave Fc 185.5 or 186.9 N/mm with 20 or 2 snapshots).
TEST_F(LongRuns, ResultsDoNotDependOnTheNumberOfSnapshots) {
  const double end = 1.5e-6;
  const auto run_with = [&](int snapshots) {
    const std::string name = "snapshots_" + std::to_string(snapshots);
    const CliResult r = run(name, {"--set", fmt::format("output.history_interval={:.17g}", end / 120), "--set",
                                   fmt::format("output.snapshot_interval={:.17g}", end / snapshots)});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_file(out(name) / "history.csv");
  };
  const std::string reference = run_with(20);
  ASSERT_FALSE(reference.empty());
  for (int snapshots : {2, 5, 10}) EXPECT_EQ(run_with(snapshots), reference) << snapshots << " snapshots";
}

TEST_F(LongRuns, ResultsAreIdenticalAcrossThreadCounts) {
  const std::vector<std::string> gravity{"--set", "body_force=[0.0, -1.0e9]", "--set", "solver.max_steps=150"};
  std::vector<std::string> two = gravity;
  two.insert(two.end(), {"--threads", "2"});
  CliResult r = run("one_thread", gravity);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run("two_threads", two);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_identical_outputs(out("one_thread"), out("two_threads"));
}

}  // namespace
}  // namespace mpmcut::testing
