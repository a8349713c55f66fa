// The VTU reader: refuses files that are not ours or are truncated. That it reads back every
// field flagged kVtuRead bit-exactly is tested field by field in test_particle_fields.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/vtu_reader.hpp"
#include "io/vtu_writer.hpp"

namespace mpmcut {
namespace {

namespace fs = std::filesystem;

class VtuReader : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("mpmcut_test_vtu_reader_") + info->name() + "_" +
                                        std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Every field differs per particle and holds values with full mantissas.
Particles sample(int n) {
  Particles p;
  for (int i = 0; i < n; ++i) {
    const double u = 1.0 / (3.0 + i);
    p.add(Vec2(1e-3 * u, 2e-3 * std::sqrt(u)), Vec2(1.0 + u, -2.0 * i), 0.5 + u, 0.25 * u, 300.0 + std::sqrt(2.0) * i,
          i % 2, i % 3);
    p.stress[i] = {1e6 * u, 2e6 + i, -3e6 * u, 4e5 * i};
    p.effective_stress[i] = {5e6 * u, 6e6 * i, 7e6 + u, 8e6 * u};
    p.plastic_strain[i] = 0.1 * i + u;
    p.plastic_strain_rate[i] = 1e4 * u;
    p.damage_initiation[i] = 0.3 * u;
    p.damage[i] = 0.01 * i * u;
    p.plastic_displacement[i] = 1e-7 * u;
    p.fracture_energy[i] = 1.5e4 * u;
    p.damage_dissipation[i] = 2e-3 * u;
    p.deformation_gradient[i] << 1.0 + 0.1 * u, 0.02, 0.0, 1.0 - 0.03 * u;
    p.volume[i] = p.initial_volume[i] * p.deformation_gradient[i].determinant();
    p.velocity_gradient[i] << 1.0 * u, 2.0, 3.0 + u, 4.0 + i;
  }
  return p;
}

TEST_F(VtuReader, EmptySnapshotRoundTrips) {
  write_particles_vtu(Particles{}, dir_ / "e.vtu", 0.5);
  const VtuSnapshot s = read_particles_vtu(dir_ / "e.vtu");
  EXPECT_EQ(s.particles.size(), 0u);
  EXPECT_EQ(s.time_s, 0.5);
}

TEST_F(VtuReader, RejectsTruncatedFile) {
  write_particles_vtu(sample(50), dir_ / "p.vtu", 1.0);
  std::ifstream in(dir_ / "p.vtu", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string full = text.str();
  for (std::size_t keep : {full.size() - 40, full.size() / 2}) {
    std::ofstream(dir_ / "cut.vtu", std::ios::binary) << full.substr(0, keep);
    try {
      read_particles_vtu(dir_ / "cut.vtu");
      FAIL() << "a file cut to " << keep << " bytes was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("cut.vtu"), std::string::npos) << e.what();
    }
  }
}

TEST_F(VtuReader, RejectsFilesThatAreNotOurs) {
  std::ofstream(dir_ / "text.vtu") << "hello\n";
  EXPECT_THROW(read_particles_vtu(dir_ / "text.vtu"), std::runtime_error);
  std::ofstream(dir_ / "poly.vtu") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" byte_order=\"LittleEndian\" "
                                      "header_type=\"UInt64\">\n</VTKFile>\n";
  EXPECT_THROW(read_particles_vtu(dir_ / "poly.vtu"), std::runtime_error);
  EXPECT_THROW(read_particles_vtu(dir_ / "missing.vtu"), std::runtime_error);
}

TEST_F(VtuReader, RejectsAMissingArray) {
  write_particles_vtu(sample(3), dir_ / "p.vtu", 1.0);
  std::ifstream in(dir_ / "p.vtu", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  s.replace(s.find("Name=\"temperature_K\""), 20, "Name=\"temperature_C\"");
  std::ofstream(dir_ / "renamed.vtu", std::ios::binary) << s;
  try {
    read_particles_vtu(dir_ / "renamed.vtu");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("temperature_K"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mpmcut
