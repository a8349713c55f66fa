#pragma once
// Restart files: everything a run needs to continue bit-identically after it was stopped
// (SIGINT/SIGTERM, SIGKILL, a crash, a full disk). docs/reliability.md describes the format
// and the guarantees; this header is the one place that reads and writes it.
//
// A checkpoint holds the complete simulation state (every particle array and the solver's
// RestartState: clock, last dt, rigid-body states, energy totals, removed-particle counters, the
// conduction sub-cycle state), the run loop's state (next
// output times, snapshot counter, the PVD entries, byte lengths of the CSV files at that
// moment, each observer's own state) and a hash of the expanded scene, so that a directory
// whose scene.toml was changed is refused.
//
// File layout (little-endian):
//   header, 32 bytes: magic "MPMCUTCK" | u32 format version | u32 header size (32)
//                     | u64 payload size | u32 CRC-32 of the payload | u32 CRC-32 of the 28 bytes before
//   payload:          named sections, each u32 name length | name | u64 data length | data
// The file size must be exactly header + payload size; with both CRCs this detects truncation,
// bit flips and files that are not checkpoints, each with its own message.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/particles.hpp"
#include "solver/restart_state.hpp"
#include "solver/scene.hpp"
#include "solver/simulation.hpp"
#include "io/pvd_writer.hpp"

namespace mpmcut {

// A checkpoint that cannot be used: missing, truncated, corrupted, from another format
// version or another scene. what() says which file and why.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Byte length of one output file at checkpoint time (path relative to the result directory).
struct FileLength {
  std::string relative_path;
  std::uint64_t bytes = 0;
  bool operator==(const FileLength&) const = default;
};

// The run loop's part of a checkpoint (app/run_case.cpp fills and reads it).
struct RunLoopState {
  double next_snapshot_s = 0.0;         // next VTU snapshot time
  double next_history_s = 0.0;          // next history row time
  int snapshot_count = 0;               // snapshots written so far (the next file's number)
  double last_snapshot_time_s = -1.0;   // time of the latest snapshot
  std::vector<PvdSeries::Entry> pvd;    // the index entries so far
  std::vector<FileLength> files;        // CSV files and their lengths
  std::vector<std::string> observer_states;  // RunObserver::checkpoint_state(), in order
  double wall_time_s = 0.0;             // wall time spent so far (informational, not used by the step)
  int threads = 0;                      // OpenMP threads of the run that wrote it (resume's default)
  int checkpoint_kind = 0;              // the run's --checkpoint-every (resume's default):
  double checkpoint_value = 0.0;        //   CheckpointInterval::Kind as int and its value
  std::string case_file;                // Scene::source_file of the original run (for summary.json)
  std::string mpmcut_version;           // program version that wrote it
};

// A decoded checkpoint: the simulation state as plain data plus the run loop's state.
struct Checkpoint {
  std::uint64_t scene_hash = 0;
  RestartState state;  // clock, rigid bodies, energies, removed particles, conduction sub-cycle
  Particles particles;
  RunLoopState loop;

  // Puts the simulation state into `sim`, which must have been built from the same scene
  // (same rigid bodies); throws CheckpointError when it does not fit.
  void restore(Simulation& sim) &&;
};

// 2: EnergyTotals::viscous; 3: Particles::fracture_energy; 4: Particles::damage_dissipation;
// 5: EnergyTotals' algorithmic terms (FLIP/PIC blend, contact safeguard, removed) and initial energy.
// Particle fields are sections named after the field (core/particle_fields.hpp): a new one needs no
// new version, a file without it is refused by name.
inline constexpr std::uint32_t kCheckpointFormatVersion = 5;

// scene_hash(): run/case_loading.hpp (the expanded scene includes records of layers above io).

// Writes a checkpoint of `sim` to `file` (the whole file: header and payload) and fsyncs it.
// Not atomic by itself; CheckpointStore::write is. Throws std::runtime_error naming the file
// and the system error (e.g. "No space left on device", "File too large").
void write_checkpoint_file(const std::filesystem::path& file, const Simulation& sim, std::uint64_t scene_hash,
                           const RunLoopState& loop);

// Reads and verifies one checkpoint file; throws CheckpointError ("... is truncated: 1234 of
// 5678 bytes", "... is corrupt: payload CRC mismatch", ...).
Checkpoint read_checkpoint_file(const std::filesystem::path& file);
// The same from bytes in memory (tests, fuzzing); `name` is used in messages.
Checkpoint decode_checkpoint(std::string_view bytes, const std::string& name);

// The checkpoints/ folder of a result directory:
//   checkpoints/checkpoint_<step>.bin   the restart files (the newest two are kept)
//   checkpoints/latest                  one line: the file name of the newest complete one
class CheckpointStore {
 public:
  explicit CheckpointStore(const std::filesystem::path& result_dir);

  // Writes checkpoints/checkpoint.tmp, fsyncs it, renames it to checkpoint_<step>.bin, fsyncs
  // the folder, replaces `latest` the same way, and only then deletes checkpoints older than the
  // previous one. A crash at any point leaves the previous checkpoint and pointer usable.
  // Returns the new file.
  std::filesystem::path write(const Simulation& sim, std::uint64_t scene_hash, const RunLoopState& loop);

  struct Loaded {
    Checkpoint checkpoint;
    std::filesystem::path file;
    std::vector<std::string> rejected;  // one line per newer checkpoint that could not be used
  };
  // The newest usable checkpoint: the one `latest` names, else the others newest first. Throws
  // CheckpointError when none is usable (the message lists each file and why).
  Loaded load_newest_valid() const;

  // Existing checkpoint files, newest (highest step) first.
  std::vector<std::filesystem::path> list() const;
  // Tells the store which checkpoint a resumed run started from, so that the next write keeps it
  // as "the previous one".
  void set_previous(const std::filesystem::path& file) { previous_ = file; }

  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_;
  std::filesystem::path previous_;  // newest file written or loaded by this store
};

}  // namespace mpmcut
