// Every numeric input is bounded (docs/reliability.md, "Input ranges"): non-finite values are
// refused for every key, each key has a physical range, temperatures stay below the melting
// point, and a run that cannot fit in memory or cannot finish is refused before allocation.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/run_estimate.hpp"
#include "../support/parse_errors.hpp"
#include "io/input_error.hpp"
#include "io/material_library.hpp"
#include "run/case_loading.hpp"
#include "run/run_case.hpp"
#include "solver/simulation.hpp"

namespace mpmcut {
namespace {

const std::string kDisk = R"(title = "disk"
[grid]
cell_size = 0.1
min = [0.0, 0.0]
max = [2.0, 2.0]
[solver]
end_time = 1.0
[[material]]
name = "m"
library = "elastic-unit"
[[body]]
name = "b"
material = "m"
disk = { center = [1.0, 1.0], radius = 0.3 }
)";

// The InputError message of parsing with overrides; "" if it parses.
std::string error_of(const std::string& text, const std::vector<std::string>& overrides) {
  return testing::parse_error_of(text, overrides);
}

std::string cutting_error(const std::vector<std::string>& overrides) {
  try {
    default_cutting_case(overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(InputBounds, NonFiniteValuesAreRefusedForEveryKindOfKey) {
  for (const char* value : {"inf", "-inf", "nan", "+inf"}) {
    for (const std::string key : {"solver.end_time", "solver.cfl", "grid.cell_size", "body[0].temperature"}) {
      const std::string m = error_of(kDisk, {key + "=" + value});
      EXPECT_NE(m.find("key '" + key + "'"), std::string::npos) << m;
      EXPECT_NE(m.find("finite"), std::string::npos) << m;
    }
    // Inside pairs and polygons, too.
    EXPECT_NE(error_of(kDisk, {std::string("body[0].velocity=[0, ") + value + "]"}).find("finite"), std::string::npos);
    EXPECT_NE(error_of(kDisk, {std::string("grid.max=[") + value + ", 2]"}).find("finite"), std::string::npos);
  }
}

// The issue's reports: each one hung or failed at step 1 before.
TEST(InputBounds, IssueReportsAreInputErrorsNamingKeyRangeAndValue) {
  std::string m = cutting_error({"cutting.cut_length=inf"});
  EXPECT_NE(m.find("key 'cutting.cut_length': must be a finite number, got inf"), std::string::npos) << m;
  m = cutting_error({"cutting.cut_length=1e308"});
  EXPECT_NE(m.find("key 'cutting.cut_length': must be in (0, 1] m, got 1e+308"), std::string::npos) << m;
  m = cutting_error({"cutting.width_of_cut=inf"});
  EXPECT_NE(m.find("key 'cutting.width_of_cut'"), std::string::npos) << m;
  m = cutting_error({"cutting.initial_temperature=1e308"});
  EXPECT_NE(m.find("key 'cutting.initial_temperature': must be in (0, 10000) K, got 1e+308"), std::string::npos) << m;
  // Below the melting point of the workpiece material (ti64-cutting: 1878 K).
  m = cutting_error({"cutting.initial_temperature=1900"});
  EXPECT_NE(m.find("must be in (0, 1878) K (below the melting temperature), got 1900"), std::string::npos) << m;
  EXPECT_EQ(cutting_error({"cutting.initial_temperature=1800"}), "");
  // One message states the whole range of the edge radius (it was "[0, 1] m" below zero and the
  // t0 bound above), and a value prints as the shortest text that reads back the same.
  m = cutting_error({"cutting.edge_radius=-1e-6"});
  EXPECT_NE(m.find("key 'cutting.edge_radius': must be a length >= 0 m and below 10 uncut chip thicknesses"),
            std::string::npos) << m;
  EXPECT_NE(m.find("got -1e-06"), std::string::npos) << m;
  m = cutting_error({"cutting.cell_size=1e-300"});
  EXPECT_NE(m.find("key 'cutting.cell_size': must be 0 (= t0/10) or a length in [1e-9, uncut_chip_thickness/2 = 5e-05] m"),
            std::string::npos) << m;
  // The default cell t0/10 below 1 nm too (a 5 nm cut ran, and its scene.toml did not read back).
  m = cutting_error({"cutting.uncut_chip_thickness=5e-9", "cutting.cell_size=0", "cutting.edge_radius=0"});
  EXPECT_NE(m.find("key 'cutting.cell_size': is 0, i.e. t0/10 = 5e-10 m, below the grid's 1 nm"), std::string::npos)
      << m;
  m = cutting_error({"cutting.friction=2.1"});
  EXPECT_TRUE(m.ends_with("got 2.1")) << m;
  m = error_of(kDisk, {"solver.end_time=1e308"});
  EXPECT_NE(m.find("key 'solver.end_time': must be in (0, 1000] s, got 1e+308"), std::string::npos) << m;
  // The location: file and line for a value in the file, the override for a --set.
  const std::string text = std::string(kDisk).replace(kDisk.find("end_time = 1.0"), 14, "end_time = 5e3");
  m = error_of(text, {});
  EXPECT_TRUE(m.starts_with("case.toml:7:12: key 'solver.end_time': must be in (0, 1000] s, got 5000.0")) << m;
}

TEST(InputBounds, UpperBoundsOfLengthsSpeedsFactorsAndMaterials) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"body[0].velocity=[2e4, 0]", "key 'body[0].velocity': each component must be in [-10000, 10000] m/s"},
      {"solver.contact_distance_cells=100", "must be in [0, 10] cells"},
      {"solver.max_steps=10000000000000", "must be in [0, 1e+12] steps"},
      {"material[0].density=1e9", "key 'material[0].density': must be in (0, 100000] kg/m^3"},
      {"material[0].youngs_modulus=1e20", "must be in (0, 1e+13] Pa"},
      {"body[0].temperature=1e5", "key 'body[0].temperature': must be in (0, 10000] K"},
      {"grid.max=[2e3, 2]", "key 'grid.max': each component must be in [-1000, 1000] m"},
  };
  for (const auto& [override, expected] : cases) {
    const std::string m = error_of(kDisk, {override});
    EXPECT_NE(m.find(expected), std::string::npos) << override << " -> " << m;
  }
}

TEST(InputBounds, MemoryEstimateRefusesWhatDoesNotFit) {
  const Scene scene = parse_case(kDisk, "case.toml", {"grid.cell_size=1e-4"}).scene;
  const RunEstimate e = estimate_run(scene);
  // 20 000 x 20 000 cells; the disk of radius 0.3 at 2 particles per cell: pi 0.09 / (5e-5)^2.
  EXPECT_NEAR(e.grid_nodes, 20007.0 * 20007.0, 1.0);
  EXPECT_NEAR(e.particles, 3.14159 * 0.09 / 2.5e-9, 0.01 * e.particles);
  try {
    check_run_fits(scene, e, 1e9);  // a machine with 1 GB
    ADD_FAILURE() << "a 120 GB run was accepted on a 1 GB machine";
  } catch (const InputError& err) {
    const std::string m = err.what();
    EXPECT_NE(m.find("the run needs about"), std::string::npos) << m;
    EXPECT_NE(m.find("GiB of memory"), std::string::npos) << m;
    EXPECT_NE(m.find("grid.cell_size"), std::string::npos) << m;
  }
  EXPECT_NO_THROW(check_run_fits(scene, e, 1e12));
  // The real machine: the estimate of a shipped-size case fits.
  EXPECT_NO_THROW(check_run_fits(parse_case(kDisk, "case.toml", {}).scene));
}

TEST(InputBounds, StepEstimateRefusesRunsThatCannotFinish) {
  // Steps land on every output time: a tiny snapshot interval is a tiny step.
  const Scene tiny = parse_case(kDisk, "case.toml", {"output.snapshot_interval=1e-300"}).scene;
  EXPECT_GT(estimate_run(tiny).steps, kMaxSteps);
  EXPECT_THROW(check_run_fits(tiny, estimate_run(tiny), 1e12), InputError);
  const Scene fixed = parse_case(kDisk, "case.toml", {"solver.fixed_time_step=1e-12", "solver.end_time=1"}).scene;
  EXPECT_THROW(check_run_fits(fixed, estimate_run(fixed), 1e12), InputError);
  // max_steps caps the count.
  const Scene capped = parse_case(kDisk, "case.toml", {"solver.fixed_time_step=1e-12", "solver.max_steps=10"}).scene;
  EXPECT_EQ(estimate_run(capped).steps, 10.0);
  EXPECT_NO_THROW(check_run_fits(capped, estimate_run(capped), 1e12));
}

// A fixed step beyond the wave-speed limit blew the colliding disks up (energy residual -626) and was reported as
// a particle leaving the grid: it is an input error at the key (so `run --check` and Python's load_case refuse it
// too, not the run after making its result directory), and a scene built in code is refused by the simulation.
TEST(InputBounds, AFixedTimeStepBeyondStabilityIsRefusedWithTheLimit) {
  const std::string m = error_of(kDisk, {"solver.fixed_time_step=0.5"});
  EXPECT_NE(m.find("key 'solver.fixed_time_step': = 0.5 s exceeds the stability limit"), std::string::npos) << m;
  EXPECT_NE(m.find("at most"), std::string::npos) << m;
  Scene unstable = parse_case(kDisk, "case.toml", {"solver.fixed_time_step=0.01"}).scene;
  unstable.solver.fixed_time_step = 0.5;
  try {
    Simulation sim(unstable);
    ADD_FAILURE() << "a fixed step of 0.5 s was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("solver.fixed_time_step = 0.5 s exceeds the stability limit"), std::string::npos)
        << message;
    EXPECT_NE(message.find("at most"), std::string::npos) << message;
  }
  // With a Mie-Grueneisen EOS the wave speed is that of its bulk sound speed c0 (the check used E and nu alone and
  // refused steps the run itself takes).
  // A step between the limit from E and nu (6.1 km/s) and the one from c0 = 4000 m/s (5.4 km/s) is accepted with the
  // EOS and refused without it.
  MaterialParameters mg = *builtin_material_library().find("ti64-johnson-1985");
  mg.eos = EquationOfState::MieGruneisen;
  mg.mg_c0 = 4000.0;
  Scene with_eos = parse_case(kDisk, "case.toml", {"solver.fixed_time_step=0.01"}).scene;
  with_eos.materials[0] = mg;
  with_eos.materials[0].name = "m";
  const double h = with_eos.grid.cell_size;
  MaterialParameters linear = mg;
  linear.eos = EquationOfState::Linear;
  ASSERT_LT(h / linear.p_wave_speed(), 0.95 * h / mg.p_wave_speed());
  with_eos.solver.fixed_time_step = 0.95 * h / mg.p_wave_speed();
  EXPECT_NO_THROW(Simulation{with_eos});
  Scene without_eos = with_eos;
  without_eos.materials[0] = linear;
  EXPECT_THROW(Simulation{without_eos}, std::invalid_argument);
  // The elastic model has no equation of state: an `eos` on an elastic set does not change its wave speed (a tiny
  // c0 gave a step three times too long and an energy residual of +997 %).
  MaterialParameters elastic = *builtin_material_library().find("elastic-unit");
  MaterialParameters elastic_mg = elastic;
  elastic_mg.eos = EquationOfState::MieGruneisen;
  elastic_mg.mg_c0 = 0.01;
  EXPECT_DOUBLE_EQ(elastic_mg.p_wave_speed(), elastic.p_wave_speed());
  // elastic-unit (E = 1000 Pa, rho = 1000 kg/m^3): c ~ 1 m/s, so 0.01 s is well inside the limit of ~0.08 s.
  EXPECT_NO_THROW(Simulation(parse_case(kDisk, "case.toml", {"solver.fixed_time_step=0.01"}).scene));
}

// A thread count the OpenMP runtime cannot take crashed it (segfault at 100000 from Python): refused instead.
TEST(InputBounds, ThreadCountsOutsideOneTo1024AreRefused) {
  for (const int threads : {-1, kMaxThreads + 1, 100000})
    EXPECT_THROW(set_threads(threads), std::invalid_argument) << threads;
  EXPECT_EQ(set_threads(1), 1);
  EXPECT_GE(set_threads(0), 1);  // 0: all cores
}

}  // namespace
}  // namespace mpmcut
