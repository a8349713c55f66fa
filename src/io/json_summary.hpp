#pragma once
// summary.json, written whole and atomically (temporary + rename) so that a reader never sees a
// half-written file. See result_directory.hpp for the "status" convention.
#include <filesystem>

#include <nlohmann/json.hpp>

namespace mpmcut {

// Values of summary.json's "status" key.
namespace run_status {
inline constexpr const char* running = "running";          // written at start; a crash leaves it
inline constexpr const char* complete = "complete";
inline constexpr const char* failed = "failed";            // an error stopped the run
inline constexpr const char* interrupted = "interrupted";  // SIGINT/SIGTERM; may be restarted
}  // namespace run_status

// Writes `value` pretty-printed (2-space indent) to `file` atomically. NaN and infinity become
// null (JSON has no such numbers). Throws std::runtime_error naming the path on failure.
void write_json_atomically(const std::filesystem::path& file, const nlohmann::json& value);

// Reads and parses `file`; throws std::runtime_error naming the path when it is missing or
// not valid JSON.
nlohmann::json read_json(const std::filesystem::path& file);

}  // namespace mpmcut
