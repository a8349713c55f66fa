// libFuzzer target: the case-file parser must turn any bytes into either a Scene or an
// InputError with a message, never a crash, hang, sanitizer report or other exception.
// Built by `make fuzz` (clang, -fsanitize=fuzzer,address,undefined); seeds: cases/*.toml.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/run_estimate.hpp"
#include "io/input_error.hpp"
#include "run/case_loading.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const mpmcut::Case c = mpmcut::parse_case(text, "fuzz.toml");
    const mpmcut::Scene& scene = c.scene;
    // The estimate runs on every accepted scene before allocation: it must not crash either, and
    // its refusal is an InputError like any other.
    mpmcut::check_run_fits(scene, mpmcut::estimate_run(scene), 1e12);
  } catch (const mpmcut::InputError&) {
    // The user's error, reported as such: fine. Anything else escapes and libFuzzer reports it.
  }
  return 0;
}
