#pragma once
// The directory a run writes into. Everything a run produces goes inside it; nothing outside.
//
// Convention that keeps a half-written run from looking complete: the program writes
// summary.json with "status": "running" before the first step, and rewrites it at the end with
// "complete", "failed" or "interrupted" (see run_status in json_summary.hpp). A run killed hard
// therefore leaves "running" behind, and only "complete" means every output is final.
// summary.json is also how open() recognises a directory it may clear with force.
#include <filesystem>
#include <string_view>
#include <utility>

#include "io/directory_lock.hpp"

namespace mpmcut {

class ResultDirectory {
 public:
  // Prepares `dir` for a new run and returns it:
  //  - missing: created (with parents);
  //  - existing and empty: used as is;
  //  - existing and non-empty: std::runtime_error "result directory 'X' already exists; use
  //    --force to overwrite", unless `force`; with `force` its contents are deleted, but only if
  //    it holds a summary.json (so that a mistyped --out cannot wipe an unrelated directory).
  // The directory is locked (io/directory_lock.hpp) before anything in it is deleted: one that another run is
  // writing into is refused, not cleared. Then checks that a file can be written in it. Errors name the path and
  // the system error.
  static ResultDirectory open(const std::filesystem::path& dir, bool force);

  const std::filesystem::path& root() const { return root_; }
  // Path of an output file inside the directory, e.g. path("summary.json").
  std::filesystem::path path(std::string_view name) const { return root_ / name; }
  // The directory's lock, for whoever writes into it from now on (held until released or destroyed).
  DirectoryLock take_lock() { return std::move(lock_); }

 private:
  ResultDirectory(std::filesystem::path root, DirectoryLock lock) : root_(std::move(root)), lock_(std::move(lock)) {}
  std::filesystem::path root_;
  DirectoryLock lock_;
};

}  // namespace mpmcut
