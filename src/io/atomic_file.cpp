#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include <fmt/core.h>

namespace mpmcut {

namespace {
std::filesystem::path temporary_for(const std::filesystem::path& file) {
  // The pid keeps two processes writing the same target from sharing a temporary.
  return std::filesystem::path(file).concat(fmt::format(".tmp-{}", ::getpid()));
}
}  // namespace

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path tmp = temporary_for(file);
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw std::runtime_error(
          fmt::format("cannot create '{}': {}", tmp.string(), std::strerror(errno)));
    }
    write(out);
    out.close();  // flushes; a full disk shows up here
    if (!out) {
      throw std::runtime_error(
          fmt::format("cannot write '{}': {}", tmp.string(), std::strerror(errno)));
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
      throw std::runtime_error(fmt::format("cannot rename '{}' to '{}': {}", tmp.string(),
                                           file.string(), ec.message()));
    }
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

}  // namespace mpmcut
