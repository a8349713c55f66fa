#pragma once
// Reading a whole file into memory, the one way every reader of a case, data, summary or
// checkpoint file does it. The caller words the error: what the file was for is known only there.
#include <filesystem>
#include <optional>
#include <string>

namespace mpmcut {

// The file's bytes, unchanged (binary mode); std::nullopt when it cannot be opened or a read
// fails (errno then says why).
std::optional<std::string> read_whole_file(const std::filesystem::path& file);

// Why `file` cannot be read, for a message: "no such file", "a directory, not a file", or the system's reason
// (e.g. "Permission denied").
std::string unreadable_reason(const std::filesystem::path& file);

}  // namespace mpmcut
