#include "app/convergence_command.hpp"

#include <filesystem>
#include <iostream>
#include <memory>

#include "app/command_exit.hpp"
#include "app/path_option.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "run/run_options.hpp"
#include "studies/grid_convergence_report.hpp"

namespace mpmcut {

namespace {

namespace fs = std::filesystem;

int run_convergence(const fs::path& dir) {
  const GridConvergenceReport r = grid_convergence_report(dir / "sweep.csv");
  if (r.conditions == 0) {
    std::cerr << "error: " << (dir / "sweep.csv").string()
              << ": no condition has three complete resolutions (cells_per_feed); run the sweep with e.g. "
                 "--cells-per-feed 12,16,24\n";
    return kExitInputError;
  }
  r.table.write_csv(dir / "grid_convergence.csv");
  write_file_atomically(dir / "grid_convergence.md", [&](std::ostream& s) {
    s << "# Grid convergence of " << (dir / "sweep.csv").string() << "\n\n" << r.markdown;
  });
  std::cout << r.markdown << "wrote " << (dir / "grid_convergence.csv").string() << " and "
            << (dir / "grid_convergence.md").string() << "\n";
  return 0;
}

}  // namespace

void add_convergence_command(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  CLI::App* c = app.add_subcommand(
      "convergence",
      "Richardson extrapolation of a resolution sweep (mpmcut sweep --cells-per-feed with three or more values) "
      "from its sweep.csv: observed order, extrapolated value and GCI of Fc, Ft, t0/tc and the energy partition "
      "per condition; writes grid_convergence.csv and grid_convergence.md into the directory");
  c->add_option("dir", *dir, "Sweep directory (holds sweep.csv)")->required()->check(non_empty_path());
  c->callback([dir]() { finish_command([&] { return run_convergence(*dir); }); });
}

}  // namespace mpmcut
