#include "io/directory_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include <fmt/core.h>

namespace mpmcut {

DirectoryLock DirectoryLock::acquire(const std::filesystem::path& dir) {
  // Close-on-exec: a plotter the run starts must not inherit (and keep) the lock.
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
    throw std::runtime_error(fmt::format("result directory '{}': cannot open it to lock it: {}", dir.string(),
                                         std::strerror(errno)));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK)
      throw std::runtime_error(fmt::format(
          "result directory '{}' is in use: another run (mpmcut run or resume, or a Python Run) is writing into it "
          "now; wait for it to end or choose another --out",
          dir.string()));
    return DirectoryLock();  // a file system that cannot lock (some network ones): the run goes on without it
  }
  return DirectoryLock(fd);
}

DirectoryLock::DirectoryLock(DirectoryLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

DirectoryLock& DirectoryLock::operator=(DirectoryLock&& other) noexcept {
  if (this != &other) {
    release();
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

DirectoryLock::~DirectoryLock() { release(); }

void DirectoryLock::release() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor of the open file drops the flock
  fd_ = -1;
}

}  // namespace mpmcut
