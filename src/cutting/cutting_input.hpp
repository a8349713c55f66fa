#pragma once
// The [cutting] section of a case file (process parameters that build a whole scene) and the
// [cutting_process] record that an expanded cutting scene carries (docs/cutting.md).
#include <ostream>
#include <string_view>

#include "cutting/cutting_parameters.hpp"
#include "io/toml_reader.hpp"

namespace mpmcut {

// Reads and validates every key of a [cutting] (or [cutting_process]) table.
CuttingParameters read_cutting_parameters(TableReader& t);

// Writes the parameters as a TOML table named `table_name`, every key explicit.
void write_cutting_parameters(const CuttingParameters& c, std::ostream& out, std::string_view table_name);

}  // namespace mpmcut
