#include "io/result_directory.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/core.h>

namespace mpmcut {

namespace {
namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& dir, const std::string& what, const std::error_code& ec) {
  throw std::runtime_error(
      fmt::format("result directory '{}': {}: {}", dir.string(), what, ec.message()));
}

// Only for a directory that holds an mpmcut result (ResultDirectory::open checks its summary.json first).
void clear_contents(const fs::path& dir) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    fs::remove_all(e.path(), ec);
    if (ec) fail(dir, fmt::format("cannot remove '{}'", e.path().string()), ec);
  }
  if (ec) fail(dir, "cannot list its contents", ec);
}

// Writing a file is the only reliable test (permissions, read-only mounts, ACLs, quotas).
void check_writable(const fs::path& dir) {
  const fs::path probe = dir / ".mpmcut-write-probe";
  {
    std::ofstream out(probe);
    out << "probe\n";
    out.close();
    if (!out) {
      throw std::runtime_error(fmt::format("result directory '{}' is not writable: {}",
                                           dir.string(), std::strerror(errno)));
    }
  }
  std::error_code ec;
  fs::remove(probe, ec);
  if (ec) fail(dir, "cannot remove the write probe", ec);
}
}  // namespace

ResultDirectory ResultDirectory::open(const fs::path& dir, bool force) {
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) fail(dir, "cannot access it", ec);

  DirectoryLock lock;
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) {
      throw std::runtime_error(
          fmt::format("result directory '{}' exists and is not a directory", dir.string()));
    }
    lock = DirectoryLock::acquire(dir);
    const bool empty = fs::is_empty(dir, ec);
    if (ec) fail(dir, "cannot list its contents", ec);
    if (!empty) {
      // A directory that --force would not clear either is told so at once, with or without --force.
      if (!fs::exists(dir / "summary.json"))
        throw std::runtime_error(fmt::format(
            "result directory '{}' exists, is not empty and has no summary.json, so it is not an mpmcut result; "
            "--force does not delete such a directory's contents. Choose another --out.",
            dir.string()));
      if (!force) {
        throw std::runtime_error(fmt::format(
            "result directory '{}' already exists; use --force to overwrite", dir.string()));
      }
      clear_contents(dir);
    }
  } else {
    fs::create_directories(dir, ec);
    if (ec) fail(dir, "cannot create it", ec);
    lock = DirectoryLock::acquire(dir);
  }
  check_writable(dir);
  return ResultDirectory(dir, std::move(lock));
}

}  // namespace mpmcut
