#include "app/keys_command.hpp"

#include <iostream>
#include <string>

#include "io/material_keys.hpp"

namespace mpmcut {

void add_keys_command(CLI::App& app) {
  CLI::App* keys = app.add_subcommand(
      "keys", "Print the [[material]] keys of the case file (unit, default, allowed values, meaning) as a markdown "
              "table, the one in docs/input.md");
  static bool markdown = false;
  keys->add_flag("--markdown", markdown, "Markdown table (the default and only format; accepted for scripts that name it)");
  keys->callback([]() {
    std::cout << material_keys_markdown();
    throw CLI::RuntimeError(0);  // the subcommand is done, main() must not go on
  });
}

}  // namespace mpmcut
