#include "io/json_summary.hpp"

#include <fstream>
#include <stdexcept>

#include <fmt/core.h>

#include "io/atomic_file.hpp"

namespace mpmcut {

void write_json_atomically(const std::filesystem::path& file, const nlohmann::json& value) {
  // Replace invalid UTF-8 (e.g. from a file name) instead of throwing halfway through a run.
  const std::string text = value.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  write_file_atomically(file, [&](std::ostream& out) { out << text << '\n'; });
}

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(fmt::format("cannot read '{}'", file.string()));
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(fmt::format("'{}' is not valid JSON: {}", file.string(), e.what()));
  }
}

}  // namespace mpmcut
