#pragma once
// --progress-every of the study commands (sweep, validate, calibrate): checked as the command line is read.
#include <string>

#include <CLI/CLI.hpp>

#include "io/input_error.hpp"
#include "studies/progress_interval.hpp"

namespace mpmcut {

inline void add_progress_option(CLI::App* command, double& interval_s) {
  command
      ->add_option_function<std::string>(
          "--progress-every", [&interval_s](const std::string& text) { interval_s = parse_progress_interval(text); },
          "How often a line on the running cases' progress is printed: a wall time (30s, 5min, 1h) or off "
          "(default: 10min; every case also reports when it ends)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            try {
              parse_progress_interval(text);
              return "";
            } catch (const InputError& e) {
              return e.what();
            }
          },
          "DURATION"));
}

}  // namespace mpmcut
