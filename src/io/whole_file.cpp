#include "io/whole_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace mpmcut {

std::optional<std::string> read_whole_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return std::nullopt;
  return bytes;
}

std::string unreadable_reason(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return "no such file";
  if (std::filesystem::is_directory(file, ec)) return "a directory, not a file";
  if (!std::filesystem::is_regular_file(file, ec)) return "not a regular file";
  std::ifstream in(file, std::ios::binary);
  return in ? "a read failed" : std::strerror(errno);
}

}  // namespace mpmcut
