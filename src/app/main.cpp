// mpmcut: the command-line program. Parses the command line, loads the case, and hands over to
// run_case / resume_case / run_benchmark. Errors in the input are the user's: a clear message, exit code 2.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/analyze_command.hpp"
#include "app/bench_command.hpp"
#include "app/plot_command.hpp"
#include "app/sweep_command.hpp"
#include "app/calibrate_command.hpp"
#include "app/convergence_command.hpp"
#include "app/keys_command.hpp"
#include "app/validate_command.hpp"
#include "run/run_case.hpp"
#include "app/stop_signal.hpp"
#include "app/path_option.hpp"
#include "io/run_estimate.hpp"
#include "io/input_error.hpp"
#include "cutting/cutting_case.hpp"
#include "run/case_loading.hpp"
#include "run/run_summary.hpp"
#include "run/start_warnings.hpp"

namespace {

using namespace mpmcut;

// A signal that came after the last step: the results are complete, but the program stops there (no pictures)
// with the documented code. Else a complete cut gets its pictures (chip fields, forces) as `mpmcut plot` draws
// them; a missing or failing plotter is a warning, never a failed run.
int with_pictures(int code, bool cutting, bool no_plots, const std::string& out_dir) {
  if (code == kExitComplete && program_stop_token().stop_requested()) {
    std::cerr << "interrupted after the run completed: results complete, pictures not drawn\n";
    return kExitInterrupted;
  }
  if (code == kExitComplete && cutting && no_plots) {
    // Pictures drawn before (by `mpmcut plot` on the interrupted run) would now show an earlier state.
    int pictures = 0;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(out_dir, ec))
      if (entry.path().extension() == ".png") ++pictures;
    if (pictures > 0)
      std::cerr << "note: the " << pictures << " .png picture(s) in " << out_dir
                << " were drawn before this run ended and are not redrawn (--no-plots): mpmcut plot " << out_dir
                << " draws them for the final state\n";
  }
  if (code == kExitComplete && cutting && !no_plots) {
    std::string why;
    if (!python_plotting_available(true, why))
      std::cerr << "warning: no pictures (" << why << "); the results are complete\n";
    else if (const int plot = run_python_tool("plot_result.py", {out_dir, "--snapshots", "last"}); plot != 0)
      std::cerr << "warning: plot_result.py failed (exit status " << plot << "); the results are complete\n";
  }
  return code;
}

// Whether the run in `dir` is a cut (its summary has the cutting results); false where it cannot be read.
bool is_cutting_run(const std::string& dir) {
  try {
    return read_summary(std::filesystem::path(dir) / "summary.json").is_cutting_run();
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mpmcut;
  // First thing: a Ctrl-C or SIGTERM while the case is still being parsed must stop the program too.
  install_stop_handlers();
  CLI::App app{"mpmcut: material point method simulation of high-speed orthogonal metal cutting (2D plane strain)"};
  app.set_version_flag("--version", std::string("mpmcut ") + MPMCUT_VERSION);
  app.require_subcommand(1);

  std::string case_file;
  RunOptions run_options;
  run_options.stop = &program_stop_token();
  std::string out_dir;
  std::vector<std::string> overrides;
  bool no_progress = false;
  CLI::App* run = app.add_subcommand("run", "Run a case file (or the built-in default case when none is given)");
  run->add_option("case", case_file, "Case file (TOML), see docs/input.md; default: the built-in Ti-6Al-4V cut (cases/ti64_default.toml)");
  run->add_option("-o,--out", out_dir, "Result directory (default: results/<case name>)")->check(non_empty_path());
  run->add_option("-t,--threads", run_options.threads, "OpenMP threads (default: all cores)")->check(CLI::Range(1, kMaxThreads));
  run->add_option("-s,--set", overrides, "Override an input key, e.g. --set solver.cfl=0.3 (repeatable)");
  run->add_flag("-f,--force", run_options.force, "Overwrite an existing result directory");
  bool keep_complete = false;
  run->add_flag("--keep-complete", keep_complete,
                "For studies run in parts: if the result directory holds the complete run of the same scene, keep it "
                "(exit 0); if it holds an unfinished one with a checkpoint, resume it; else run afresh (as --force)");
  run->add_flag("--no-progress", no_progress, "Do not print progress");
  bool fixed_threads = false;
  run->add_flag("--fixed-threads", fixed_threads,
                "Always use --threads threads (default: the fastest of 1..threads, re-timed every 10 s, so that a busy "
                "core does not slow the run down; results are the same either way)");
  bool no_plots = false;
  run->add_flag("--no-plots", no_plots, "Do not draw the PNG pictures at the end of a cutting run");
  bool check_only = false;
  run->add_flag("--check", check_only,
                "Only parse and validate the case and estimate its memory and step count, then exit "
                "(0: it would start; 2: input error); writes nothing");
  // Checkpoints (docs/reliability.md): a step count or a wall time.
  const auto checkpoint_check = [](const std::string& text) -> std::string {
    try {
      parse_checkpoint_interval(text);
      return {};
    } catch (const InputError& e) {
      // CLI11 puts the option's name in front already.
      std::string message = e.what();
      const std::string own = "--checkpoint-every ";
      if (message.starts_with(own)) message.erase(0, own.size());
      return message;
    }
  };
  std::string checkpoint_every = "30min";
  run->add_option("--checkpoint-every", checkpoint_every,
                  "Write a restart checkpoint every N steps (5000, 5000steps) or after a wall time (600s, 10min, 2h); "
                  "off (or 0) = only on SIGINT/SIGTERM (default: 30min)")
      ->check(checkpoint_check);

  RunOptions resume_options;
  resume_options.stop = &program_stop_token();
  std::string resume_dir;
  std::string resume_checkpoint_every = "30min";
  bool resume_no_progress = false;
  CLI::App* resume = app.add_subcommand(
      "resume", "Continue a stopped run (killed, interrupted, failed to write) from its last valid checkpoint");
  resume->add_option("result_dir", resume_dir, "Result directory of the run")->required()->check(non_empty_path());
  resume->add_option("-t,--threads", resume_options.threads, "OpenMP threads (default: those of the original run)")
      ->check(CLI::Range(1, kMaxThreads));
  resume->add_option("--checkpoint-every", resume_checkpoint_every, "As for run (default: that of the original run)")
      ->check(checkpoint_check);
  resume->add_flag("-f,--force", resume_options.force,
                   "Also resume a complete run (recomputes from its last checkpoint to the end)");
  resume->add_flag("--no-progress", resume_no_progress, "Do not print progress");
  bool resume_no_plots = false;
  resume->add_flag("--no-plots", resume_no_plots, "Do not draw the PNG pictures at the end of a cutting run");

  BenchOptions bench_options;
  CLI::App* bench = app.add_subcommand(
      "bench", "Measure particle-steps per second: elastic block, all-plastic Ti-6Al-4V block, the default cut");
  bench->add_option("--particles", bench_options.particles, "Approximate particle count")->check(CLI::Range(100L, 100000000L));
  bench->add_option("--steps", bench_options.steps, "Timed steps")->check(CLI::Range(1, 1000000));
  bench->add_option("--threads", bench_options.threads, "Thread counts to measure, e.g. 1,2 or 1 2 (default: 1 2)")
      ->delimiter(',')->check(CLI::Range(1, kMaxThreads));
  bench->add_option("--case", bench_options.which, "Which benchmark: elastic, plastic, cutting or all (default: all)")
      ->check(CLI::IsMember({"elastic", "plastic", "cutting", "all"}));
  bench->add_option("--cutting-steps", bench_options.cutting_steps, "Timed steps of the cutting case per thread count")
      ->check(CLI::Range(1, 1000000));
  bench->add_flag("--background-load", bench_options.background_load,
                  "Keep one core busy with a spinning process while measuring (a machine doing other work)");

  add_plot_command(app);
  add_sweep_command(app);
  add_convergence_command(app);
  add_validate_command(app);
  add_calibrate_command(app);
  add_analyze_command(app);
  add_keys_command(app);

  // A first word that is no command (a typing error, a case file without `run`) gets the list of commands, not
  // CLI11's "A subcommand is required".
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    const CLI::App& commands = app;
    for (const CLI::App* sub : commands.get_subcommands([](const CLI::App*) { return true; }))
      names.push_back(sub->get_name());
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::cerr << fmt::format("error: '{}' is not a command of mpmcut; the commands are: {} (mpmcut --help; a case "
                               "file runs with `mpmcut run FILE`)\n",
                               argv[1], fmt::join(names, ", "));
      return kExitInputError;
    }
  }

  // No arguments: the list of commands rather than CLI11's bare "A subcommand is required".
  if (argc <= 1) {
    std::cerr << app.help() << "\nerror: give a command, e.g. `mpmcut run` (the built-in default cut)\n";
    return kExitInputError;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {  // a subcommand's own exit code (its callback ran)
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    // A bad option or value is an input error like a bad case file: exit code 2 (docs/reliability.md),
    // not CLI11's own codes; --help and --version exit 0.
    return app.exit(e) == 0 ? 0 : kExitInputError;
  }

  if (*bench) return run_benchmark(bench_options);
  if (*resume) {
    resume_options.out_dir = resume_dir;
    resume_options.progress = !resume_no_progress;
    resume_options.checkpoint_every = parse_checkpoint_interval(resume_checkpoint_every);
    resume_options.checkpoint_every_given = resume->count("--checkpoint-every") > 0;
    return with_pictures(resume_case(resume_options), is_cutting_run(resume_dir), resume_no_plots, resume_dir);
  }

  Case c;
  try {
    // Without a case file: the built-in Ti-6Al-4V cut (cases/ti64_default.toml); --set applies to it.
    c = case_file.empty() ? default_cutting_case(overrides) : load_case(case_file, overrides);
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
  if (check_only) {
    const RunEstimate e = estimate_run(c.scene);
    const double available = available_memory_bytes();
    try {
      check_run_fits(c.scene, e, available, run_size_keys(c));
    } catch (const InputError& error) {
      std::cerr << "error: " << error.what() << "\n";
      return kExitInputError;
    }
    // The steps count the mass scaling in: say so (a 0.2 m/s cut's 6.4e3 steps are those of a x9729 inertia).
    const SolverSpec& solver = c.scene.solver;
    const std::string scaling =
        solver.mass_scaling_target_time_step > 0.0
            ? fmt::format(" (mass scaling to a time step of {:.3g} s)", solver.mass_scaling_target_time_step)
        : solver.mass_scaling_factor > 1.0
            ? fmt::format(" (mass scaling: inertia x {:.4g}, time step x {:.3g})", solver.mass_scaling_factor,
                          std::sqrt(solver.mass_scaling_factor))
            : std::string();
    std::cout << fmt::format("{}: valid; about {:.3g} particles, {:.3g} grid nodes, {} of memory ({} available), "
                             "{:.3g} steps{}\n",
                             case_file.empty() ? "built-in default case" : case_file, e.particles, e.grid_nodes,
                             format_bytes(e.bytes), format_bytes(available), e.steps, scaling);
    if (c.cutting) std::cerr << cut_start_warning_lines(*c.cutting, c.scene);  // what the run would say at its start
    return kExitComplete;
  }
  if (out_dir.empty()) {
    const std::string name = case_file.empty() ? "default" : std::filesystem::path(case_file).stem().string();
    out_dir = "results/" + name;
  }
  run_options.out_dir = out_dir;
  run_options.progress = !no_progress;
  run_options.tune_threads = !fixed_threads;
  run_options.checkpoint_every = parse_checkpoint_interval(checkpoint_every);
  int code = -1;
  if (keep_complete) {
    switch (existing_run(out_dir, c)) {
      case ExistingRun::Complete:
        std::cerr << "kept: " << out_dir << " already holds the complete run of this scene\n";
        return kExitComplete;
      case ExistingRun::Resumable:
        std::cerr << "resuming the unfinished run of this scene in " << out_dir << "\n";
        code = resume_case(run_options);
        break;
      case ExistingRun::Outdated:
        std::cerr << "rerunning: the run in " << out_dir << " is outdated (" << outdated_run_reason(out_dir, c) << ")\n";
        run_options.force = true;
        break;
      case ExistingRun::None:
        run_options.force = true;
        break;
    }
  }
  if (code < 0) code = run_case(c, run_options);
  return with_pictures(code, c.cutting.has_value(), no_plots, out_dir);
}
