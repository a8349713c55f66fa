#pragma once
// The check every directory option of the command line shares: an empty path ("--out ''", a variable that was
// never set) is refused rather than taken as "the default" or the current directory.
#include <string>

#include <CLI/CLI.hpp>

namespace mpmcut {

inline CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](const std::string& path) -> std::string {
        return path.empty() ? "an empty path; give a directory (leave the option out for its default)" : "";
      },
      "PATH");
}

}  // namespace mpmcut
