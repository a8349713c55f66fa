#pragma once
// `mpmcut keys --markdown`: the reference table of the [[material]] keys, made from the physics
// models' parameter tables; docs/input.md holds its output (py.test_input_keys_doc checks that).
#include <CLI/CLI.hpp>

namespace mpmcut {

void add_keys_command(CLI::App& app);

}  // namespace mpmcut
