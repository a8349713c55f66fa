#pragma once
// Atomic file replacement: write everything to a temporary file in the same directory, then
// rename it over the target. A reader (or a crash) therefore sees either the old complete file
// or the new complete file, never a half-written one. rename() is atomic only within one file
// system, which is why the temporary lives next to the target.
#include <filesystem>
#include <functional>
#include <ostream>

namespace mpmcut {

// Calls `write(stream)` on a binary stream to "<file>.tmp-<pid>", checks the stream, then renames
// it to `file`. On any failure the temporary is removed and std::runtime_error names the path
// and the system error.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);

}  // namespace mpmcut
