// The particle field registry (core/particle_fields.hpp) and what is derived from it: every
// member of Particles is registered; add, resize, permute and the one-particle record handle
// every field; every checkpointed field round-trips bit-exactly through a checkpoint; every field
// flagged for VTU is in the snapshot under <name>_<unit> and, where flagged, read back bit-exactly.
// Each particle of each field holds its own value, so a field that is skipped or mixed up shows.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <type_traits>

#include "core/particles.hpp"
#include "solver/simulation.hpp"
#include "io/checkpoint.hpp"
#include "run/case_loading.hpp"
#include "io/vtu_field_layout.hpp"
#include "io/vtu_reader.hpp"
#include "io/vtu_writer.hpp"

namespace mpmcut {
namespace {

namespace fs = std::filesystem;

// Component c of field k at particle i: positive, full mantissa, different for every (k, i, c).
double sample(int k, std::size_t i, int c) {
  return (k + 1) + 0.01 * static_cast<double>(i) + 1.0 / (3.0 + 0.37 * k + 1.1 * static_cast<double>(i) + 0.13 * c);
}

template <class T>
T value_of(int k, std::size_t i) {
  if constexpr (std::is_same_v<T, double>) {
    return sample(k, i, 0);
  } else if constexpr (std::is_same_v<T, Vec2>) {
    return Vec2(sample(k, i, 0), sample(k, i, 1));
  } else if constexpr (std::is_same_v<T, Mat2>) {
    Mat2 m;  // small off-diagonals: det > 0, as the VTU reader requires of F
    m << sample(k, i, 0), 0.1 * sample(k, i, 1), 0.1 * sample(k, i, 2), sample(k, i, 3);
    return m;
  } else if constexpr (std::is_same_v<T, PlaneStrainTensor>) {
    return {sample(k, i, 0), sample(k, i, 1), sample(k, i, 2), sample(k, i, 3)};
  } else {
    static_assert(std::is_same_v<T, std::int32_t>);
    return static_cast<std::int32_t>(100000 * (k + 1) + i);
  }
}

template <class T>
bool same_bits(const T& a, const T& b) {
  static_assert(std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec2> || std::is_same_v<T, Mat2>);
  return std::memcmp(static_cast<const void*>(&a), static_cast<const void*>(&b), sizeof(T)) == 0;
}

// Calls fn(field, k) with the field's position k in the registry.
template <class Fn>
void for_each_numbered_field(Fn&& fn) {
  int k = 0;
  for_each_particle_field([&](const auto& f) { fn(f, k++); });
}

// n particles, every field of particle i at value_of(k, i).
Particles filled(std::size_t n) {
  Particles p;
  p.resize(n);
  for_each_numbered_field([&](const auto& f, int k) {
    using T = typename std::decay_t<decltype(f)>::value_type;
    for (std::size_t i = 0; i < n; ++i) (p.*f.array)[i] = value_of<T>(k, i);
  });
  return p;
}

// Particle `at` of every field holds value_of(k, from(at)); reports the first field that does not.
template <class From>
void expect_rows(const Particles& p, std::size_t n, From from, unsigned only_flag = 0) {
  for_each_numbered_field([&](const auto& f, int k) {
    using T = typename std::decay_t<decltype(f)>::value_type;
    if (!f.info.has(only_flag)) return;
    const auto& a = p.*f.array;
    ASSERT_EQ(a.size(), n) << f.info.name;
    for (std::size_t at = 0; at < n; ++at)
      ASSERT_TRUE(same_bits(a[at], value_of<T>(k, from(at)))) << f.info.name << " at particle " << at;
  });
}

TEST(ParticleFields, RegistryCoversEveryMemberOfParticles) {
  // The arrays of the registry, by their place in Particles, must tile it: a member added to the
  // struct but not to MPMCUT_PARTICLE_FIELDS leaves a gap (and a static_assert fails first).
  const Particles p;
  std::vector<std::size_t> offsets;
  std::set<std::string> names, outputs;
  for_each_particle_field([&](const auto& f) {
    offsets.push_back(static_cast<std::size_t>(reinterpret_cast<const char*>(&(p.*f.array)) -
                                               reinterpret_cast<const char*>(&p)));
    EXPECT_TRUE(names.insert(std::string(f.info.name)).second) << "registered twice: " << f.info.name;
    EXPECT_TRUE(outputs.insert(f.info.output_name()).second) << "output name used twice: " << f.info.output_name();
    using T = typename std::decay_t<decltype(f)>::value_type;
    EXPECT_EQ(f.info.kind, field_kind_of<T>()) << f.info.name;
    if (f.info.has(kVtuRead)) EXPECT_TRUE(f.info.has(kVtu)) << f.info.name << ": read back but never written";
    if (f.info.has(kVtuOptional)) EXPECT_TRUE(f.info.has(kVtuRead)) << f.info.name;
    EXPECT_FALSE(f.info.meaning.empty()) << f.info.name;
  });
  std::sort(offsets.begin(), offsets.end());
  for (std::size_t k = 0; k < offsets.size(); ++k) EXPECT_EQ(offsets[k], k * sizeof(std::vector<double>));
  EXPECT_EQ(offsets.size() * sizeof(std::vector<double>), sizeof(Particles));
  EXPECT_EQ(particle_field_infos().size(), offsets.size());
}

TEST(ParticleFields, AddAndResizeGrowEveryFieldWithItsInitialValue) {
  Particles p;
  p.add(Vec2(1.0, 2.0), Vec2(3.0, 4.0), 5.0, 6.0, 7.0, 8, 9);
  p.resize(3);
  const ParticleRow initial;
  for_each_particle_field([&](const auto& f) {
    const auto& a = p.*f.array;
    ASSERT_EQ(a.size(), 3u) << f.info.name;
    for (std::size_t i = 1; i < 3; ++i) EXPECT_TRUE(same_bits(a[i], initial.*f.value)) << f.info.name;
  });
  // What add() sets; every other field of particle 0 is at its initial value.
  const ParticleRow r = p.row(0);
  EXPECT_EQ(r.position, Vec2(1.0, 2.0));
  EXPECT_EQ(r.velocity, Vec2(3.0, 4.0));
  EXPECT_EQ(r.mass, 5.0);
  EXPECT_EQ(r.volume, 6.0);
  EXPECT_EQ(r.initial_volume, 6.0);
  EXPECT_EQ(r.temperature, 7.0);
  EXPECT_EQ(r.body, 8);
  EXPECT_EQ(r.material, 9);
  EXPECT_EQ(r.deformation_gradient, Mat2::Identity());
  EXPECT_EQ(r.stress.von_mises(), 0.0);
  p.resize(1);
  EXPECT_EQ(p.size(), 1u);
  for_each_particle_field([&](const auto& f) { EXPECT_EQ((p.*f.array).size(), 1u) << f.info.name; });
}

TEST(ParticleFields, PermuteKeepsEveryFieldsRowsTogether) {
  const std::size_t n = 13;
  Particles p = filled(n);
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = (5 * k + 3) % n;  // a permutation (5 and 13 coprime)
  p.permute(order);
  expect_rows(p, n, [&](std::size_t at) { return order[at]; });
  // A shorter order drops the particles it does not name (removal of escaped particles).
  Particles q = filled(n);
  const std::vector<std::size_t> keep = {0, 2, 3, 7, 12};
  q.permute(keep);
  expect_rows(q, keep.size(), [&](std::size_t at) { return keep[at]; });
}

TEST(ParticleFields, RowAndSetRowCarryEveryField) {
  const Particles p = filled(6);
  Particles q;
  q.resize(6);
  for (std::size_t i = 0; i < 6; ++i) q.set_row(5 - i, p.row(i));
  expect_rows(q, 6, [](std::size_t at) { return 5 - at; });
  Particles r;
  for (std::size_t i = 0; i < 6; ++i) r.add(p.row(i));
  expect_rows(r, 6, [](std::size_t at) { return at; });
}

// A scene to build a Simulation for the checkpoint writer; its particles are replaced.
constexpr const char* kElasticBlock = R"toml(
[grid]
cell_size = 1.0e-3
min = [0.0, 0.0]
max = [4.0e-3, 4.0e-3]
[solver]
end_time = 1.0e-6
[[material]]
name = "steel"
model = "elastic"
density = 7800.0
youngs_modulus = 2.0e11
poisson_ratio = 0.3
[[body]]
name = "block"
material = "steel"
rectangle = { min = [1.0e-3, 1.0e-3], max = [3.0e-3, 3.0e-3] }
)toml";

class ParticleFieldFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mpmcut_test_particle_fields_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string text_of(const fs::path& file) const {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

TEST_F(ParticleFieldFiles, CheckpointRoundTripsEveryCheckpointedFieldBitExact) {
  const Scene scene = parse_case(kElasticBlock, "fields.toml").scene;
  Simulation sim(scene);
  const std::size_t n = 17;
  sim.particles() = filled(n);
  write_checkpoint_file(dir_ / "c.bin", sim, scene_hash(Case{scene}), RunLoopState{});
  const Checkpoint c = read_checkpoint_file(dir_ / "c.bin");
  expect_rows(c.particles, n, [](std::size_t at) { return at; }, kCheckpoint);
  // Every checkpointed field has its own section (u32 name length | name) under its registered name.
  const std::string bytes = text_of(dir_ / "c.bin");
  for_each_particle_field([&](const auto& f) {
    const std::string key = "particles." + std::string(f.info.name);
    const std::uint32_t length = static_cast<std::uint32_t>(key.size());
    const std::string head = std::string(reinterpret_cast<const char*>(&length), sizeof length) + key;
    EXPECT_EQ(bytes.find(head) != std::string::npos, f.info.has(kCheckpoint)) << f.info.name;
  });
}

// The checkpoint `bytes` without its section `name`, header (payload size, both CRCs) made to fit:
// what an mpmcut without that field would have written.
std::string without_section(const std::string& bytes, const std::string& name) {
  std::string payload;
  for (std::size_t at = 32; at < bytes.size();) {
    std::uint32_t length = 0;
    std::uint64_t data = 0;
    std::memcpy(&length, bytes.data() + at, sizeof length);
    std::memcpy(&data, bytes.data() + at + 4 + length, sizeof data);
    const std::size_t end = at + 4 + length + 8 + data;
    if (bytes.compare(at + 4, length, name) != 0 || length != name.size()) payload += bytes.substr(at, end - at);
    at = end;
  }
  std::string header = bytes.substr(0, 32);
  const std::uint64_t size = payload.size();
  const auto crc = [](const std::string& b, std::size_t n) {
    return static_cast<std::uint32_t>(crc32_z(crc32_z(0, nullptr, 0), reinterpret_cast<const Bytef*>(b.data()), n));
  };
  const std::uint32_t payload_crc = crc(payload, payload.size());
  std::memcpy(header.data() + 16, &size, sizeof size);
  std::memcpy(header.data() + 24, &payload_crc, sizeof payload_crc);
  const std::uint32_t header_crc = crc(header, 28);
  std::memcpy(header.data() + 28, &header_crc, sizeof header_crc);
  return header + payload;
}

TEST_F(ParticleFieldFiles, CheckpointWithoutAFieldIsRefusedByItsName) {
  const Scene scene = parse_case(kElasticBlock, "fields.toml").scene;
  Simulation sim(scene);
  write_checkpoint_file(dir_ / "c.bin", sim, scene_hash(Case{scene}), RunLoopState{});
  const std::string bytes = text_of(dir_ / "c.bin");
  ASSERT_NO_THROW(decode_checkpoint(without_section(bytes, "no such section"), "resealed"));
  for_each_particle_field([&](const auto& f) {
    if (!f.info.has(kCheckpoint)) return;
    const std::string field(f.info.name);
    try {
      decode_checkpoint(without_section(bytes, "particles." + field), "old.bin");
      ADD_FAILURE() << "a checkpoint without " << field << " was accepted";
    } catch (const CheckpointError& e) {
      EXPECT_NE(std::string(e.what()).find("no particle field '" + field + "'"), std::string::npos) << e.what();
    }
  });
}

TEST_F(ParticleFieldFiles, VtuHoldsEveryWrittenFieldUnderItsNameAndUnit) {
  const std::size_t n = 9;
  write_particles_vtu(filled(n), dir_ / "p.vtu", 0.25);
  const std::string text = text_of(dir_ / "p.vtu");
  const std::string header = text.substr(0, text.find("<AppendedData"));
  std::set<std::string> listed;
  for (const VtuFieldInfo& v : vtu_point_fields()) listed.insert(v.name);
  for_each_particle_field([&](const auto& f) {
    const std::string name = vtu_array_name(f.info);
    const int c = vtu_components(f.info.kind);
    const std::string declared = "Name=\"" + name + "\"" +
                                 (c == 1 ? std::string() : " NumberOfComponents=\"" + std::to_string(c) + "\"");
    if (f.info.has(kVtu)) {
      EXPECT_NE(header.find(declared), std::string::npos) << f.info.name << " should be written as " << declared;
      if (f.info.unit.size() > 0 && name != "Points") EXPECT_TRUE(name.ends_with("_" + std::string(f.info.unit)));
      if (vtu_point_data(f.info)) EXPECT_EQ(listed.count(name), 1u) << name << " missing from vtu_point_fields()";
    } else {
      EXPECT_EQ(header.find("Name=\"" + name + "\""), std::string::npos) << f.info.name << " is not flagged kVtu";
    }
  });
}

TEST_F(ParticleFieldFiles, VtuReaderReadsBackEveryFlaggedFieldBitExact) {
  const std::size_t n = 11;
  const Particles p = filled(n);
  write_particles_vtu(p, dir_ / "p.vtu", 0.5);
  const Particles q = read_particles_vtu(dir_ / "p.vtu").particles;
  expect_rows(q, n, [](std::size_t at) { return at; }, kVtuRead);
  // The others: rebuilt from J = V/V0 (F, V0) or at their initial value.
  const ParticleRow initial;
  for_each_particle_field([&](const auto& f) {
    if (f.info.has(kVtuRead) || f.info.name == "deformation_gradient" || f.info.name == "initial_volume") return;
    for (std::size_t i = 0; i < n; ++i) EXPECT_TRUE(same_bits((q.*f.array)[i], initial.*f.value)) << f.info.name;
  });
  for (std::size_t i = 0; i < n; ++i) {
    const double J = p.volume[i] / p.initial_volume[i];
    EXPECT_NEAR(q.deformation_gradient[i].determinant(), J, 1e-15 * J);
    EXPECT_NEAR(q.initial_volume[i], p.volume[i] / J, 1e-15 * q.initial_volume[i]);
  }
}

TEST_F(ParticleFieldFiles, SnapshotWithoutAnOptionalFieldReadsItsInitialValue) {
  // A snapshot from before a kVtuOptional field existed: rename its array (same length, so the
  // offsets stay) and the reader gives the initial value, every other field as written.
  const std::size_t n = 5;
  const Particles p = filled(n);
  write_particles_vtu(p, dir_ / "p.vtu", 0.5);
  std::string text = text_of(dir_ / "p.vtu");
  std::set<std::string> optional;
  for_each_particle_field([&](const auto& f) {
    if (!f.info.has(kVtuOptional)) return;
    optional.insert(std::string(f.info.name));
    const std::string name = "Name=\"" + vtu_array_name(f.info) + "\"";
    text.replace(text.find(name), name.size(), "Name=\"" + std::string(name.size() - 7, 'x') + "\"");
  });
  if (optional.empty()) GTEST_SKIP() << "no field is flagged kVtuOptional";
  std::ofstream(dir_ / "old.vtu", std::ios::binary) << text;
  const Particles q = read_particles_vtu(dir_ / "old.vtu").particles;
  const ParticleRow initial;
  for_each_numbered_field([&](const auto& f, int k) {
    using T = typename std::decay_t<decltype(f)>::value_type;
    if (!f.info.has(kVtuRead)) return;
    const bool missing = optional.count(std::string(f.info.name)) > 0;
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_TRUE(same_bits((q.*f.array)[i], missing ? initial.*f.value : value_of<T>(k, i))) << f.info.name;
  });
}

}  // namespace
}  // namespace mpmcut
