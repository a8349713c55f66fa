// The checkpoint file (io/checkpoint.hpp) in-process: a restored simulation continues
// bit-identically, every truncation and every sampled bit flip is rejected with its reason,
// the scene hash tells scenes apart, and the --checkpoint-every syntax.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "run/run_case.hpp"
#include "solver/simulation.hpp"
#include "io/checkpoint.hpp"
#include "io/input_error.hpp"
#include "run/case_loading.hpp"

namespace mpmcut {
namespace {

namespace fs = std::filesystem;

// Small but complete: JC plasticity with damage, conduction, a rigid punch with friction that conducts heat (a
// steady body held on its top), gravity.
constexpr const char* kCase = R"toml(
body_force = [0.0, -1.0e9]
[grid]
cell_size = 50.0e-6
min = [0.0, 0.0]
max = [1.0e-3, 0.6e-3]
[boundaries]
bottom = "fixed"
[solver]
end_time = 1.0e-6
[thermal]
conduction = true
[[material]]
name = "ti64"
library = "ti64-johnson-1985"
fracture_toughness = 55.0e6
[[body]]
name = "block"
material = "ti64"
rectangle = { min = [0.0, 0.0], max = [0.8e-3, 0.3e-3] }
[[rigid_body]]
name = "punch"
polygon = [[0.3e-3, 0.3e-3], [0.5e-3, 0.3e-3], [0.5e-3, 0.5e-3], [0.3e-3, 0.5e-3]]
velocity = [0.0, -150.0]
friction = 0.3
heat_transfer_coefficient = 1.0e7
temperature = 600.0
conductivity = 50.0
heat_averaging_time = 1.0e-8
held_faces = [2]
)toml";

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(static_cast<const void*>(a.data()), static_cast<const void*>(b.data()),
                                             a.size() * sizeof(T)) == 0;
}

bool same_state(const Simulation& a, const Simulation& b) {
  bool same = true;
  for_each_particle_field([&](const auto& f) {
    same = same && same_bytes(a.particles().*f.array, b.particles().*f.array);
  });
  same = same && std::memcmp(&a.energy(), &b.energy(), sizeof(EnergyTotals)) == 0;
  same = same && a.time() == b.time() && a.step_count() == b.step_count() && a.last_dt() == b.last_dt();
  const RestartState &sa = a.restart_state(), &sb = b.restart_state();
  same = same && sa.conduction.elapsed == sb.conduction.elapsed && sa.conduction.steps == sb.conduction.steps &&
         sa.removed_particles == sb.removed_particles && sa.removed_mass == sb.removed_mass;
  for (std::size_t r = 0; same && r < a.rigid_bodies().size(); ++r) {
    const RigidBodyState &s = a.rigid_bodies()[r], &t = b.rigid_bodies()[r];
    same = s.displacement == t.displacement && s.force == t.force && s.impulse == t.impulse &&
           s.step_impulse == t.step_impulse && s.work == t.work && same_bytes(s.temperature_field, t.temperature_field) &&
           same_bytes(s.heat_input_average, t.heat_input_average);
  }
  return same;
}

class CheckpointFormat : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = fs::temp_directory_path() / ("mpmcut_checkpoint_format_" + std::to_string(::getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".bin");
    scene_ = parse_case(kCase, "test.toml").scene;
  }
  void TearDown() override { fs::remove(file_); }

  std::string bytes_after(int steps, RunLoopState loop = {}) {
    Simulation sim(scene_);
    for (int k = 0; k < steps; ++k) sim.step();
    write_checkpoint_file(file_, sim, scene_hash(Case{scene_}), loop);
    std::ifstream in(file_, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  fs::path file_;
  Scene scene_;
};

// Checkpoint after 23 steps (the particle sort runs every 20), restore into a fresh simulation,
// then 37 more steps on both: every particle array, energy, clock and rigid-body state is equal
// to the bit.
TEST_F(CheckpointFormat, RestoredSimulationContinuesBitIdentically) {
  Simulation straight(scene_);
  for (int k = 0; k < 23; ++k) straight.step();
  RunLoopState loop;
  loop.next_snapshot_s = 1.25e-7;
  loop.snapshot_count = 3;
  loop.pvd = {{0.0, "snapshots/particles_000000.vtu"}, {1e-7, "snapshots/particles_000001.vtu"}};
  loop.files = {{"history.csv", 12345}};
  loop.observer_states = {std::string("\0\1\2", 3)};
  loop.case_file = "case.toml";
  write_checkpoint_file(file_, straight, scene_hash(Case{scene_}), loop);
  Checkpoint c = read_checkpoint_file(file_);
  EXPECT_EQ(c.state.step, 23);
  EXPECT_EQ(c.scene_hash, scene_hash(Case{scene_}));
  EXPECT_EQ(c.loop.snapshot_count, 3);
  EXPECT_EQ(c.loop.next_snapshot_s, 1.25e-7);
  ASSERT_EQ(c.loop.pvd.size(), 2u);
  EXPECT_EQ(c.loop.pvd[1].file, "snapshots/particles_000001.vtu");
  EXPECT_EQ(c.loop.files, loop.files);
  EXPECT_EQ(c.loop.observer_states, loop.observer_states);
  EXPECT_EQ(c.loop.case_file, "case.toml");

  Simulation resumed(scene_);
  std::move(c).restore(resumed);
  ASSERT_TRUE(same_state(straight, resumed)) << "the restored state differs from the saved one";
  for (int k = 0; k < 37; ++k) {
    straight.step();
    resumed.step();
  }
  EXPECT_TRUE(same_state(straight, resumed)) << "the continuation differs after 37 steps";
  EXPECT_GT(straight.energy().plastic_work, 0.0) << "the case should exercise plasticity";
  const std::vector<double>& punch = straight.rigid_bodies()[0].temperature_field;
  ASSERT_FALSE(punch.empty());
  EXPECT_LT(*std::min_element(punch.begin(), punch.end()), 600.0 - 1e-6) << "the punch should lose heat to the block";
}

TEST_F(CheckpointFormat, EveryTruncationIsRejected) {
  const std::string bytes = bytes_after(3);
  ASSERT_NO_THROW(decode_checkpoint(bytes, "whole"));
  // Every length in the header, then a sample through the payload, and one byte short.
  std::vector<std::size_t> lengths;
  for (std::size_t n = 0; n <= 40; ++n) lengths.push_back(n);
  for (std::size_t n = 41; n < bytes.size(); n += 997) lengths.push_back(n);
  lengths.push_back(bytes.size() - 1);
  for (const std::size_t n : lengths) {
    try {
      decode_checkpoint(std::string_view(bytes).substr(0, n), "cut");
      ADD_FAILURE() << "a checkpoint cut to " << n << " of " << bytes.size() << " bytes was accepted";
    } catch (const CheckpointError& e) {
      const std::string m = e.what();
      EXPECT_TRUE(m.find("truncated") != std::string::npos || m.find("not an mpmcut checkpoint") != std::string::npos)
          << "length " << n << ": " << m;
    }
  }
  // A longer file is wrong too (e.g. two checkpoints written into one file).
  EXPECT_THROW(decode_checkpoint(bytes + "x", "long"), CheckpointError);
}

TEST_F(CheckpointFormat, BitFlipsAreRejected) {
  const std::string bytes = bytes_after(3);
  std::size_t tried = 0;
  for (std::size_t byte = 0; byte < bytes.size(); byte += (byte < 64 ? 1 : 389)) {
    for (int bit = 0; bit < 8; bit += (byte < 64 ? 1 : 3)) {
      std::string bad = bytes;
      bad[byte] = static_cast<char>(bad[byte] ^ (1 << bit));
      EXPECT_THROW(decode_checkpoint(bad, "flipped"), CheckpointError) << "byte " << byte << " bit " << bit;
      ++tried;
    }
  }
  EXPECT_GT(tried, 600u);
}

TEST_F(CheckpointFormat, MessagesSayWhatIsWrong) {
  const std::string bytes = bytes_after(1);
  const auto message = [](const std::string& b) {
    try {
      decode_checkpoint(b, "x.bin");
    } catch (const CheckpointError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("hello, world, this is not a checkpoint").find("not an mpmcut checkpoint"), std::string::npos);
  EXPECT_NE(message(bytes.substr(0, bytes.size() - 10)).find("is truncated"), std::string::npos);
  std::string flipped = bytes;
  flipped[bytes.size() - 3] ^= 1;
  EXPECT_NE(message(flipped).find("payload CRC mismatch"), std::string::npos);
  std::string header = bytes;
  header[17] ^= 1;  // payload length
  EXPECT_NE(message(header).find("header CRC mismatch"), std::string::npos);
  EXPECT_THROW(read_checkpoint_file("/nonexistent/checkpoint_1.bin"), CheckpointError);
}

TEST_F(CheckpointFormat, SceneHashTellsScenesApart) {
  Scene other = scene_;
  EXPECT_EQ(scene_hash(Case{other}), scene_hash(Case{scene_}));
  other.source_file = "elsewhere.toml";  // where it came from does not matter
  EXPECT_EQ(scene_hash(Case{other}), scene_hash(Case{scene_}));
  other.solver.cfl = 0.3;
  EXPECT_NE(scene_hash(Case{other}), scene_hash(Case{scene_}));
}

TEST_F(CheckpointFormat, SceneHashTellsCuttingProcessesApart) {
  // The process travels beside the scene (cutting/case.hpp), but scene.toml records it, so the hash
  // that a resume checks covers it: a resume must not continue a cut at another speed.
  const Case cut{scene_, CuttingParameters{}};
  EXPECT_NE(scene_hash(cut), scene_hash(Case{scene_}));
  Case faster = cut;
  faster.cutting->cutting_speed = cut.cutting->cutting_speed + 10.0;
  EXPECT_NE(scene_hash(faster), scene_hash(cut));
}

TEST_F(CheckpointFormat, RestoreRefusesAnotherScene) {
  write_checkpoint_file(file_, Simulation(scene_), scene_hash(Case{scene_}), {});
  Scene no_punch = scene_;
  no_punch.rigid_bodies.clear();
  Simulation sim(no_punch);
  EXPECT_THROW(read_checkpoint_file(file_).restore(sim), CheckpointError);
}

// The simulation itself refuses a restart state whose rigid bodies are not its scene's (it would
// index its rigid geometry out of bounds).
TEST_F(CheckpointFormat, SimulationRefusesARestartStateWithOtherRigidBodies) {
  Scene no_punch = scene_;
  no_punch.rigid_bodies.clear();
  const RestartState without = Simulation(no_punch).restart_state();
  Simulation sim(scene_);
  EXPECT_THROW(sim.restore(without), std::invalid_argument);
  RestartState later = sim.restart_state();
  later.step = 7;
  later.conduction.steps = 3;
  sim.restore(later);
  EXPECT_EQ(sim.step_count(), 7);
  EXPECT_EQ(sim.restart_state().conduction.steps, 3);
}

TEST(CheckpointInterval, ParsesStepsAndWallTimes) {
  using K = CheckpointInterval::Kind;
  const auto check = [](const char* text, K kind, double value) {
    const CheckpointInterval c = parse_checkpoint_interval(text);
    EXPECT_EQ(c.kind, kind) << text;
    EXPECT_EQ(c.value, value) << text;
  };
  check("5000", K::Steps, 5000);
  check("5000steps", K::Steps, 5000);
  check("5000 steps", K::Steps, 5000);
  check("600s", K::WallSeconds, 600);
  check("10min", K::WallSeconds, 600);
  check("1.5h", K::WallSeconds, 5400);
  check("0.5 s", K::WallSeconds, 0.5);
  check("off", K::Off, 0);
  check("0", K::Off, 0);
  for (const char* bad : {"", "-5", "10 parsecs", "1.5steps", "steps", "1e400"}) {
    EXPECT_THROW(parse_checkpoint_interval(bad), InputError) << "'" << bad << "'";
  }
  try {
    parse_checkpoint_interval("10 parsecs");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown unit 'parsecs'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mpmcut
