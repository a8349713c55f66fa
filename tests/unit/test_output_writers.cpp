// Output layer: VTU snapshots (layout, values, readable by meshio), the PVD index, CSV files
// (header, rows, restart append), summary.json, atomic replacement and the result directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/particles.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_writer.hpp"
#include "io/json_summary.hpp"
#include "io/progress.hpp"
#include "io/pvd_writer.hpp"
#include "io/result_directory.hpp"
#include "io/vtu_writer.hpp"

namespace mpmcut {
namespace {

namespace fs = std::filesystem;

// A fresh, empty directory per test, removed afterwards.
class OutputWriters : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("mpmcut_test_io_") + info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path dir_;
};

std::string read_text(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Particles whose every field differs per particle, so that mixed-up arrays show.
Particles sample_particles(int n) {
  Particles p;
  for (int i = 0; i < n; ++i) {
    p.add(Vec2(1e-3 * i, 2e-3 * i), Vec2(1.0 + i, -2.0 * i), 0.5 + i, 0.25, 300.0 + i, i % 2,
          i % 3);
    p.stress[i] = {1e6 * i, 2e6, -3e6, 4e5 * i};
    p.effective_stress[i] = {5e6, 6e6 * i, 7e6, 8e6};
    p.plastic_strain[i] = 0.1 * i;
    p.damage[i] = 0.01 * i;
    p.deformation_gradient[i] << 1.0 + 0.1 * i, 0.0, 0.0, 1.0;
    p.initial_volume[i] = 0.25 / (1.0 + 0.1 * i);  // V = det F V0, as a run keeps them
    p.velocity_gradient[i] << 1.0, 2.0, 3.0, 4.0 + i;
  }
  return p;
}

// The raw appended arrays of a VTU written by us, keyed by Name: each block is a UInt64 byte
// count followed by the bytes. Checks that the blocks tile the appended section exactly.
std::map<std::string, std::string> appended_arrays(const std::string& text) {
  const std::size_t start = text.find("encoding=\"raw\">");
  EXPECT_NE(start, std::string::npos);
  const std::size_t data = text.find('_', start) + 1;
  const std::size_t end = text.rfind("\n  </AppendedData>");
  std::map<std::string, std::string> arrays;
  const std::regex decl(R"re(Name="([^"]+)"[^>]*offset="(\d+)")re");
  const std::string xml = text.substr(0, start);
  std::size_t covered = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), decl); it != std::sregex_iterator();
       ++it) {
    const std::size_t offset = std::stoull((*it)[2].str());
    EXPECT_EQ(offset, covered) << "arrays must be consecutive";
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, text.data() + data + offset, sizeof bytes);
    arrays[(*it)[1].str()] = text.substr(data + offset + sizeof bytes, bytes);
    covered = offset + sizeof bytes + bytes;
  }
  EXPECT_EQ(data + covered, end) << "appended section has unclaimed bytes";
  return arrays;
}

template <class T>
std::vector<T> as(const std::string& bytes) {
  std::vector<T> v(bytes.size() / sizeof(T));
  std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
  return v;
}

TEST_F(OutputWriters, VtuHeaderDeclaresEveryParticleAndField) {
  const Particles p = sample_particles(5);
  const fs::path file = dir_ / "particles.vtu";
  write_particles_vtu(p, file, 1.5e-6);
  const std::string text = read_text(file);
  EXPECT_EQ(text.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"", 0), 0u);
  EXPECT_NE(text.find("byte_order=\"LittleEndian\""), std::string::npos);
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"5\" NumberOfCells=\"5\">"), std::string::npos);
  for (const VtuFieldInfo& f : vtu_point_fields()) {
    const std::string components =
        f.components == 1 ? "" : " NumberOfComponents=\"" + std::to_string(f.components) + "\"";
    EXPECT_NE(text.find("Name=\"" + f.name + "\"" + components + " format"), std::string::npos)
        << f.name;
  }
  EXPECT_EQ(text.substr(text.size() - 30), "\n  </AppendedData>\n</VTKFile>\n");
}

TEST_F(OutputWriters, VtuAppendedDataHoldsTheParticleValues) {
  const int n = 4;
  const Particles p = sample_particles(n);
  const fs::path file = dir_ / "particles.vtu";
  write_particles_vtu(p, file, 2.5e-3);
  auto arrays = appended_arrays(read_text(file));

  EXPECT_EQ(as<double>(arrays["TimeValue"]), std::vector<double>{2.5e-3});
  EXPECT_EQ(as<double>(arrays["time_s"]), std::vector<double>{2.5e-3});
  const auto points = as<double>(arrays["Points"]);
  ASSERT_EQ(points.size(), 3u * n);
  EXPECT_DOUBLE_EQ(points[3 * 3 + 1], 6e-3);  // y of particle 3
  EXPECT_EQ(points[3 * 3 + 2], 0.0);
  EXPECT_EQ(as<std::int32_t>(arrays["offsets"]), (std::vector<std::int32_t>{1, 2, 3, 4}));
  EXPECT_EQ(arrays["types"], std::string(n, '\x01'));  // VTK_VERTEX

  const auto stress = as<double>(arrays["stress_Pa"]);  // xx yy zz xy yz xz
  ASSERT_EQ(stress.size(), 6u * n);
  EXPECT_EQ(stress[6 * 2 + 0], 2e6);
  EXPECT_EQ(stress[6 * 2 + 2], -3e6);
  EXPECT_EQ(stress[6 * 2 + 3], 8e5);
  EXPECT_EQ(stress[6 * 2 + 4], 0.0);
  EXPECT_DOUBLE_EQ(as<double>(arrays["pressure_Pa"])[2], -(2e6 + 2e6 - 3e6) / 3.0);
  EXPECT_DOUBLE_EQ(as<double>(arrays["von_mises_stress_Pa"])[1], p.stress[1].von_mises());
  EXPECT_EQ(as<double>(arrays["temperature_K"])[3], 303.0);
  EXPECT_DOUBLE_EQ(as<double>(arrays["density_kg_per_m3"])[1], 1.5 / 0.25);
  EXPECT_EQ(as<std::int32_t>(arrays["body_id"]), (std::vector<std::int32_t>{0, 1, 0, 1}));
  EXPECT_EQ(as<std::int32_t>(arrays["material_id"]), (std::vector<std::int32_t>{0, 1, 2, 0}));
  EXPECT_DOUBLE_EQ(as<double>(arrays["deformation_jacobian_J"])[2], 1.2);
  const auto L = as<double>(arrays["velocity_gradient_per_s"]);
  ASSERT_EQ(L.size(), 9u * n);
  EXPECT_EQ(L[9 * 1 + 1], 2.0);  // L_xy = dvx/dy
  EXPECT_EQ(L[9 * 1 + 3], 3.0);  // L_yx
  EXPECT_EQ(L[9 * 1 + 4], 5.0);
}

TEST_F(OutputWriters, VtuIsReadByMeshio) {
  const int n = 7;
  const fs::path file = dir_ / "particles.vtu";
  write_particles_vtu(sample_particles(n), file, 0.0);
  const std::string cmd = std::string("/usr/bin/python3 ") + MPMCUT_TEST_DIR +
                          "/python/vtu_roundtrip_check.py '" + file.string() + "' " +
                          std::to_string(n);
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

TEST_F(OutputWriters, AtomicWritesLeaveNoTemporaryFiles) {
  write_particles_vtu(sample_particles(3), dir_ / "a.vtu", 0.0);
  write_particles_vtu(sample_particles(3), dir_ / "a.vtu", 1.0);  // replaces
  PvdSeries series;
  series.add(0.0, "a.vtu");
  series.write(dir_ / "particles.pvd");
  write_json_atomically(dir_ / "summary.json", {{"status", run_status::running}});
  EXPECT_EQ(files(), (std::vector<std::string>{"a.vtu", "particles.pvd", "summary.json"}));
}

TEST_F(OutputWriters, FailedAtomicWriteKeepsTheOldFile) {
  write_json_atomically(dir_ / "summary.json", {{"status", "running"}});
  // A writer that throws halfway must leave the previous complete file and no temporary.
  EXPECT_THROW(write_file_atomically(dir_ / "summary.json",
                                     [](std::ostream& out) {
                                       out << "{\"status\": ";
                                       throw std::runtime_error("simulated failure");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_json(dir_ / "summary.json")["status"], "running");
  EXPECT_EQ(files(), std::vector<std::string>{"summary.json"});
}

TEST_F(OutputWriters, PvdListsSnapshotsInOrderAndReadsBack) {
  PvdSeries series;
  series.add(0.0, "particles_000000.vtu");
  series.add(1e-6, "particles_000001.vtu");
  series.add(2.5e-6, "a&b.vtu");
  series.write(dir_ / "particles.pvd");
  const std::string text = read_text(dir_ / "particles.pvd");
  EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_NE(text.find("timestep=\"1e-06\" group=\"\" part=\"0\" file=\"particles_000001.vtu\""),
            std::string::npos);
  EXPECT_NE(text.find("file=\"a&amp;b.vtu\""), std::string::npos);

  PvdSeries back = PvdSeries::read(dir_ / "particles.pvd");
  ASSERT_EQ(back.entries().size(), 3u);
  EXPECT_EQ(back.entries()[1].time_s, 1e-6);
  EXPECT_EQ(back.entries()[2].file, "a&b.vtu");
  back.drop_after(1e-6);
  EXPECT_EQ(back.entries().size(), 2u);
}

TEST_F(OutputWriters, CsvWritesHeaderAndFullPrecisionRows) {
  const fs::path file = dir_ / "history.csv";
  {
    CsvWriter csv(file, {"time_s", "kinetic_energy_J_per_m"});
    csv.row({0.1, 1.0 / 3.0});
    const std::vector<double> values{2e-7, -4.5};
    csv.row(values);
    EXPECT_THROW(csv.row({1.0}), std::invalid_argument);
  }
  EXPECT_EQ(read_text(file),
            "time_s,kinetic_energy_J_per_m\n0.1,0.3333333333333333\n2e-07,-4.5\n");
  EXPECT_EQ(std::stod("0.3333333333333333"), 1.0 / 3.0);  // shortest form round-trips
}

TEST_F(OutputWriters, CsvAppendChecksHeaderAndDropsPartialRow) {
  const fs::path file = dir_ / "forces.csv";
  { CsvWriter csv(file, {"time_s", "force_N_per_m"}); csv.row({1.0, 2.0}); }
  // A crash while writing the next row leaves a partial line behind.
  { std::ofstream(file, std::ios::app) << "2,3.5"; }
  {
    CsvWriter csv(file, {"time_s", "force_N_per_m"}, CsvWriter::Mode::Append);
    csv.row({2.0, 4.0});
  }
  EXPECT_EQ(read_text(file), "time_s,force_N_per_m\n1,2\n2,4\n");
  EXPECT_THROW(CsvWriter(file, {"time_s", "other_N"}, CsvWriter::Mode::Append),
               std::runtime_error);
  // Appending to a file that does not exist yet writes the header.
  { CsvWriter csv(dir_ / "new.csv", {"a_m"}, CsvWriter::Mode::Append); csv.row({1.0}); }
  EXPECT_EQ(read_text(dir_ / "new.csv"), "a_m\n1\n");
  EXPECT_THROW(CsvWriter(dir_ / "bad.csv", {"a,b"}), std::invalid_argument);
}

TEST_F(OutputWriters, JsonRoundTripAndClearErrors) {
  nlohmann::json summary = {{"status", run_status::complete}, {"particles", 42},
                            {"cutting_force_N_per_mm", 0.125}};
  write_json_atomically(dir_ / "summary.json", summary);
  EXPECT_EQ(read_json(dir_ / "summary.json"), summary);
  { std::ofstream(dir_ / "broken.json") << "{\"status\": "; }
  EXPECT_THROW(read_json(dir_ / "broken.json"), std::runtime_error);
  EXPECT_THROW(read_json(dir_ / "missing.json"), std::runtime_error);
}

TEST_F(OutputWriters, ResultDirectoryRefusesNonEmptyWithoutForce) {
  const fs::path out = dir_ / "run";
  ResultDirectory first = ResultDirectory::open(out, false);  // created
  EXPECT_TRUE(fs::is_directory(out));
  EXPECT_EQ(first.path("summary.json"), out / "summary.json");
  first.take_lock().release();  // as when its run has ended
  EXPECT_NO_THROW(ResultDirectory::open(out, false));  // empty: fine
  write_json_atomically(first.path("summary.json"), {{"status", "complete"}});
  { std::ofstream(first.path("history.csv")) << "time_s\n"; }
  fs::create_directories(out / "snapshots");
  { std::ofstream(out / "snapshots" / "p.vtu") << "x"; }
  try {
    ResultDirectory::open(out, false);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("already exists; use --force to overwrite"),
              std::string::npos)
        << e.what();
  }
  ResultDirectory::open(out, true);
  EXPECT_TRUE(fs::is_empty(out));
}

// Two runs aimed at one directory (two Python Runs, or a run and a `run --force`) mixed their outputs, the
// second deleting the first's files while they were written: the directory is locked while a run writes into it.
TEST_F(OutputWriters, ResultDirectoryInUseByAnotherRunIsRefusedNotCleared) {
  const fs::path out = dir_ / "busy";
  ResultDirectory first = ResultDirectory::open(out, false);
  write_json_atomically(first.path("summary.json"), {{"status", "running"}});
  { std::ofstream(first.path("history.csv")) << "time_s\n"; }
  try {
    ResultDirectory::open(out, true);
    ADD_FAILURE() << "a directory in use was opened";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is in use"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(out / "history.csv")) << "the running run's file was deleted";
  EXPECT_THROW(DirectoryLock::acquire(out), std::runtime_error);  // a resume is refused too
  DirectoryLock held = first.take_lock();
  EXPECT_TRUE(held.held());
  held.release();
  EXPECT_NO_THROW(ResultDirectory::open(out, true));  // once it has ended
  EXPECT_TRUE(fs::is_empty(out));
}

TEST_F(OutputWriters, ResultDirectoryForceSparesDirectoriesThatAreNotResults) {
  { std::ofstream(dir_ / "thesis.tex") << "precious"; }
  EXPECT_THROW(ResultDirectory::open(dir_, true), std::runtime_error);
  EXPECT_TRUE(fs::exists(dir_ / "thesis.tex"));
}

TEST_F(OutputWriters, ResultDirectoryUnderARegularFileIsAClearError) {
  { std::ofstream(dir_ / "plain_file") << "x"; }
  try {
    ResultDirectory::open(dir_ / "plain_file" / "run", false);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("plain_file/run"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Not a directory"), std::string::npos) << msg;
  }
  EXPECT_THROW(ResultDirectory::open(dir_ / "plain_file", true), std::runtime_error);
}

TEST_F(OutputWriters, ResultDirectoryWithoutWritePermissionIsAClearError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can write anywhere";
  const fs::path locked = dir_ / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  try {
    ResultDirectory::open(locked, false);
    ADD_FAILURE() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not writable"), std::string::npos) << e.what();
  }
  fs::permissions(locked, fs::perms::owner_all);
}

TEST(Progress, PlainModePrintsAboutEveryTenPercent) {
  std::ostringstream out;
  Progress progress(1e-3, out, /*terminal=*/false);
  for (long step = 1; step <= 1000; ++step) progress.update(step * 1e-6, step, 1e-6);
  progress.finish("complete");
  const std::string text = out.str();
  long lines = std::count(text.begin(), text.end(), '\n');
  EXPECT_GE(lines, 10);
  EXPECT_LE(lines, 12);
  EXPECT_NE(text.find("100.0 %"), std::string::npos) << text;
  EXPECT_NE(text.find("complete: t = 1 ms, 1000 steps"), std::string::npos) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos);
}

TEST(Progress, TerminalModeRedrawsOneLine) {
  std::ostringstream out;
  Progress progress(1.0, out, /*terminal=*/true);
  progress.update(0.5, 10, 0.05);
  progress.finish("complete");
  const std::string text = out.str();
  EXPECT_NE(text.find("\r["), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;
}

TEST(Progress, HumanUnits) {
  EXPECT_EQ(Progress::format_wall_time(0.42), "0.4 s");
  EXPECT_EQ(Progress::format_wall_time(45.2), "45 s");
  EXPECT_EQ(Progress::format_wall_time(185), "3 min 05 s");
  EXPECT_EQ(Progress::format_wall_time(7440), "2 h 04 min");
  EXPECT_EQ(Progress::format_sim_time(1.234e-3), "1.234 ms");
  EXPECT_EQ(Progress::format_sim_time(2.5e-6), "2.5 us");
  EXPECT_EQ(Progress::format_sim_time(3e-9), "3 ns");
  EXPECT_EQ(Progress::format_sim_time(2.0), "2 s");
}

}  // namespace
}  // namespace mpmcut
