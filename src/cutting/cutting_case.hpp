#pragma once
// The cutting sections of a case file (docs/input.md, docs/cutting.md): [cutting], the preset that
// builds a whole scene from process parameters, and [cutting_process], the record of that process
// which an expanded cutting scene carries so that its force and chip outputs are written.
// run/case_loading.hpp dispatches between a [cutting] case and a generic one.
#include <ostream>

#include "cutting/case.hpp"
#include "io/run_estimate.hpp"
#include "io/toml_reader.hpp"

namespace mpmcut {

// A [cutting] case: the preset builds grid, workpiece, tool, boundaries and outputs from the
// process parameters; [solver] and [output] may still adjust the numerics. The caller rejects
// the unknown keys of `top` afterwards.
Case read_cutting_case(TableReader& top);

// [cutting_process] of an expanded scene into c.cutting (absent: nothing).
void read_cutting_process(TableReader& top, Case& c);

// The [cutting_process] record of a case built by the preset (none: nothing).
void write_cutting_process(const Case& c, std::ostream& out);

// The keys that set the run's size for check_run_fits' messages: the [cutting] keys for a cut.
RunSizeKeys run_size_keys(const Case& c);

}  // namespace mpmcut
