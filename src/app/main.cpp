// mpmcut: the command-line program. Parses the command line, loads the case, and hands over to
// run_case / run_benchmark. Errors in the input are the user's: a clear message, exit code 2.
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/bench_command.hpp"
#include "app/run_case.hpp"
#include "io/input_error.hpp"
#include "io/scene_parser.hpp"

int main(int argc, char** argv) {
  using namespace mpmcut;
  CLI::App app{"mpmcut: material point method simulation of high-speed orthogonal metal cutting (2D plane strain)"};
  app.set_version_flag("--version", std::string("mpmcut ") + MPMCUT_VERSION);
  app.require_subcommand(1);

  std::string case_file;
  RunOptions run_options;
  std::string out_dir;
  std::vector<std::string> overrides;
  bool no_progress = false;
  CLI::App* run = app.add_subcommand("run", "Run a case file (or the built-in default case when none is given)");
  run->add_option("case", case_file, "Case file (TOML), see docs/input.md");
  run->add_option("-o,--out", out_dir, "Result directory (default: results/<case name>)");
  run->add_option("-t,--threads", run_options.threads, "OpenMP threads (default: all cores)")->check(CLI::Range(1, 1024));
  run->add_option("-s,--set", overrides, "Override an input key, e.g. --set solver.cfl=0.3 (repeatable)");
  run->add_flag("-f,--force", run_options.force, "Overwrite an existing result directory");
  run->add_flag("--no-progress", no_progress, "Do not print progress");

  BenchOptions bench_options;
  CLI::App* bench = app.add_subcommand("bench", "Measure particle-steps per second on a standard elastic block");
  bench->add_option("--particles", bench_options.particles, "Approximate particle count")->check(CLI::Range(100L, 100000000L));
  bench->add_option("--steps", bench_options.steps, "Timed steps")->check(CLI::Range(1, 1000000));
  bench->add_option("--threads", bench_options.threads, "Thread counts to measure (default: 1 2)");

  CLI11_PARSE(app, argc, argv);

  if (*bench) return run_benchmark(bench_options);

  Scene scene;
  try {
    scene = case_file.empty() ? default_elastic_demo_scene() : load_scene(case_file, overrides);
    if (case_file.empty() && !overrides.empty()) {
      std::cerr << "error: --set needs a case file; the built-in default case takes no overrides\n";
      return kExitInputError;
    }
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
  if (out_dir.empty()) {
    const std::string name = case_file.empty() ? "default" : std::filesystem::path(case_file).stem().string();
    out_dir = "results/" + name;
  }
  run_options.out_dir = out_dir;
  run_options.progress = !no_progress;
  return run_case(scene, run_options);
}
