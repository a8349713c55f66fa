// `mpmcut convergence DIR` as a user runs it on a sweep directory: the Richardson table of a resolution
// sweep from its sweep.csv, and clear errors (exit 2) where it cannot be made.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "cli.hpp"

namespace mpmcut::testing {
namespace {

// A sweep.csv as `mpmcut sweep --cells-per-feed` writes it (the columns the report reads, plus others).
// Fc = 150 + 2 h/um exactly (first order), Ft = 40 + 0.5 (h/um)^2 (second order); one condition at
// N = 8, 12, 16, 24 and another with only two resolutions.
std::string sweep_csv(const std::vector<int>& resolutions_of_second) {
  std::string s =
      "case,speed_m_per_s,speed_m_per_min,feed_mm,cell_size_um,cells_per_feed,mass_scaling_factor,status,"
      "mean_cutting_force_N_per_mm,mean_thrust_force_N_per_mm,force_window,chip_thickness_ratio,damage_fraction,"
      "friction_fraction,message\n";
  const auto row = [&](double v, int n, const char* status) {
    const double h_um = 100.0 / n;
    s += fmt::format("v{}_n{},{},{},0.1,{:.3g},{},1,{},{},{},steady window,0.8,0.2,{},\n", v, n, v, 60 * v, h_um, n,
                     status, 150.0 + 2.0 * h_um, 40.0 + 0.5 * h_um * h_um, 0.1 + 0.001 * h_um);
  };
  for (int n : {8, 12, 16, 24}) row(20, n, "complete");
  row(20, 32, "failed");  // not complete: not one of the three finest
  for (int n : resolutions_of_second) row(5, n, "complete");
  return s;
}

TEST(ConvergenceCommand, WritesTheRichardsonTableOfTheThreeFinestResolutions) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mpmcut_convergence_{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_file(dir / "sweep.csv", sweep_csv({8, 16}));
  const CliResult r = run_mpmcut({"convergence", dir.string()}, dir / "log.txt");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string csv = read_file(dir / "grid_convergence.csv");
  // One condition (V = 20 m/s) with three complete resolutions: 12, 16, 24 (32 failed, 5 m/s has two).
  EXPECT_NE(csv.find("20,0.1,Fc,N/mm,\"12, 16, 24\""), std::string::npos) << csv;
  EXPECT_EQ(csv.find("\n5,"), std::string::npos) << csv;
  // Fc is exactly first order in h: p = 1.00, extrapolated 150; Ft second order: p = 2.00, 40.
  EXPECT_NE(csv.find("monotonic,-2.6,1.00,yes,150,+5.6,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",2.00,yes,40,"), std::string::npos) << csv;
  EXPECT_NE(read_file(dir / "grid_convergence.md").find("Celik"), std::string::npos);
  fs::remove_all(dir);
}

TEST(ConvergenceCommand, ExplainsWhatIsMissingAndExitsTwo) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mpmcut_convergence_bad_{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  CliResult r = run_mpmcut({"convergence", dir.string()}, dir / "log.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("sweep.csv: cannot read"), std::string::npos) << r.output;

  write_file(dir / "sweep.csv", "case,speed_m_per_s,status\nv1,1,complete\n");
  r = run_mpmcut({"convergence", dir.string()}, dir / "log.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("missing column(s) 'feed_mm'"), std::string::npos) << r.output;

  std::string two = sweep_csv({});
  two = two.substr(0, two.find("v20_n8"));  // header only, then two resolutions of one condition
  two += "a,20,1200,0.1,12.5,8,1,complete,160,50,steady window,0.8,0.2,0.1,\n"
         "b,20,1200,0.1,8.33,12,1,complete,158,48,steady window,0.8,0.2,0.1,\n";
  write_file(dir / "sweep.csv", two);
  r = run_mpmcut({"convergence", dir.string()}, dir / "log.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no condition has three complete resolutions"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "grid_convergence.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mpmcut::testing
