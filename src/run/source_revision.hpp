#pragma once
// The git revision of the sources this program was built from ("git describe --always --dirty", a
// "-dirty" suffix for uncommitted changes; "unknown" when built outside a git checkout). Every run
// records it in summary.json, so that results kept across sessions (run records, --keep-complete)
// show which code made them.
namespace mpmcut {

const char* source_revision();

}  // namespace mpmcut
