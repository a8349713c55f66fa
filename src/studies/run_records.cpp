#include "studies/run_records.hpp"

#include <fstream>
#include <iterator>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/whole_file.hpp"
#include "run/run_case.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

const std::vector<std::string>& run_record_files() {
  // summary.json last: its status "complete" is what marks a run (or a record) complete, so a copy
  // interrupted half-way never looks complete.
  static const std::vector<std::string> files{"scene.toml", "forces.csv", "summary.json"};
  return files;
}

namespace {

std::string read_whole(const fs::path& file) {
  std::optional<std::string> text = read_whole_file(file);
  if (!text) throw std::runtime_error("cannot read " + file.string());
  return std::move(*text);
}

// Copies the record files present in `from` into `to` (created), each atomically, summary.json last.
void copy_record_files(const fs::path& from, const fs::path& to) {
  fs::create_directories(to);
  std::error_code ec;
  for (const std::string& name : run_record_files()) {
    if (!fs::exists(from / name, ec)) continue;
    const std::string text = read_whole(from / name);
    write_file_atomically(to / name, [&](std::ostream& s) { s << text; });
  }
}

}  // namespace

bool restore_run_record(const fs::path& record, const fs::path& run_dir, const Case& c) {
  if (existing_run(record, c) != ExistingRun::Complete) return false;
  if (existing_run(run_dir, c) == ExistingRun::Complete) return false;
  // An interrupted or foreign run in run_dir goes: the record is a complete run of this scene.
  fs::remove_all(run_dir);
  copy_record_files(record, run_dir);
  return true;
}

bool save_run_record(const fs::path& run_dir, const fs::path& record) {
  std::error_code ec;
  if (fs::exists(record / "scene.toml", ec) && read_whole(record / "scene.toml") != read_whole(run_dir / "scene.toml"))
    return false;
  copy_record_files(run_dir, record);
  return true;
}

}  // namespace mpmcut
