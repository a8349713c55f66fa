#pragma once
// An exclusive lock on a result directory for as long as a run writes into it, so that a second run, resume or
// Python Run aimed at the same directory (with --force it would delete the first one's files while they are
// written) is refused instead of mixing two runs' outputs. An advisory flock(2) on the directory itself: nothing is
// written into the directory for it, and the kernel drops it when the process ends, however it ends.
#include <filesystem>

namespace mpmcut {

class DirectoryLock {
 public:
  // Locks the existing directory `dir`; std::runtime_error naming it when another process (or another open
  // run of this one) holds the lock, or when it cannot be opened. Where the file system cannot lock at all
  // (some network file systems), an unheld lock: the run goes on unprotected rather than not at all.
  static DirectoryLock acquire(const std::filesystem::path& dir);

  DirectoryLock() = default;
  DirectoryLock(DirectoryLock&& other) noexcept;
  DirectoryLock& operator=(DirectoryLock&& other) noexcept;
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  ~DirectoryLock();

  bool held() const { return fd_ >= 0; }
  void release();

 private:
  explicit DirectoryLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace mpmcut
