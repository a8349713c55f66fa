#pragma once
// How a study subcommand (sweep, validate, calibrate, convergence) ends: its body's exit code, or the exit code of
// what it threw, with the message on stderr: an InputError is the user's input (kExitInputError), anything else
// an error of the run or its outputs (kExitOutputError). CLI11 ends a subcommand's callback by an exception
// that carries the code (also on success: main() must not go on).
#include <iostream>

#include <CLI/CLI.hpp>

#include "io/input_error.hpp"
#include "run/run_options.hpp"

namespace mpmcut {

template <class Body>
[[noreturn]] void finish_command(Body&& body) {
  int code = 0;
  try {
    code = body();
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    code = kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    code = kExitOutputError;
  }
  throw CLI::RuntimeError(code);
}

}  // namespace mpmcut
