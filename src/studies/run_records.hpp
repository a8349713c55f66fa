#pragma once
// Run records: the few small text files of a complete run that a study needs to report it again
// (scene.toml, summary.json, forces.csv). A directory of records can be committed with the study's report,
// so that a study spread over sessions or machines keeps its complete runs when the result directories
// (pictures, checkpoints) are gone: `validate --records DIR`.
#include <filesystem>
#include <string>
#include <vector>

#include "cutting/case.hpp"

namespace mpmcut {

// The files of a record, in the run directory and in the record directory alike.
const std::vector<std::string>& run_record_files();

// If `record` holds a complete run of exactly the scene `c` and `run_dir` does not, replaces `run_dir` by
// the record's files and returns true. A record of another scene (another resolution, material, code
// version that writes the scene differently) is ignored.
bool restore_run_record(const std::filesystem::path& record, const std::filesystem::path& run_dir, const Case& c);

// Writes the record files of the complete run in `run_dir` to `record` (each file atomically; a file the run
// does not have is left out) and returns true. A record of another scene is kept, not replaced (it may be
// another study's committed result): returns false.
bool save_run_record(const std::filesystem::path& run_dir, const std::filesystem::path& record);

}  // namespace mpmcut
