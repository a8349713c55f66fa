#pragma once
// The .pvd time-series index that makes ParaView open all VTU snapshots as one animation.
// The index is rewritten (atomically) after every snapshot, so it always lists exactly the
// snapshots that exist, even if the run dies later.
#include <filesystem>
#include <string>
#include <vector>

namespace mpmcut {

class PvdSeries {
 public:
  struct Entry {
    double time_s;
    std::string file;  // relative to the directory of the .pvd, e.g. "particles_000012.vtu"
  };

  // Reads an index written by write() (for restarts); throws std::runtime_error when the file
  // cannot be read. Entries keep their order.
  static PvdSeries read(const std::filesystem::path& index_file);

  void add(double time_s, std::string relative_file) {
    entries_.push_back({time_s, std::move(relative_file)});
  }
  // Drops entries later than `time_s` (a restart from a checkpoint at that time rewrites them).
  void drop_after(double time_s);
  // Writes the whole index to `index_file` atomically.
  void write(const std::filesystem::path& index_file) const;

  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace mpmcut
