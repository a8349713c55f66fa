#include "run/case_loading.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "cutting/cutting_case.hpp"
#include "io/embedded_text.hpp"
#include "io/scene_parser.hpp"
#include "io/scene_writer.hpp"
#include "io/toml_reader.hpp"
#include "solver/fixed_step_limit.hpp"

namespace mpmcut {

namespace {

Case embedded_case(std::string_view path, const std::vector<std::string>& overrides, const char* what) {
  for (const EmbeddedText& file : embedded_texts())
    if (file.path == path) return parse_case(file.text, "built-in " + std::string(file.path), overrides);
  throw InputError(std::string("the built-in ") + what + " is missing from this build");
}

// The explicit update is stable for dt <= cell / (wave speed + fastest velocity). The simulation checks a fixed step
// against that with its particles; here it is checked from the scene, so that --check and load_case refuse it at the
// key instead of the run after its result directory was made.
void check_fixed_time_step(TableReader& top, const Scene& s) {
  const double fixed = s.solver.fixed_time_step;
  if (fixed <= 0.0) return;
  double wave_speed = 0.0, speed = 0.0;
  for (const BodySpec& b : s.bodies) {
    wave_speed = std::max(wave_speed, s.materials.at(s.material_index(b.material)).p_wave_speed());
    speed = std::max(speed, b.velocity.norm());
  }
  for (const RigidBodySpec& r : s.rigid_bodies) speed = std::max(speed, r.velocity.norm());
  // Mass scaling slows the waves by the square root of the inertia factor.
  const double limit =
      s.grid.cell_size / (wave_speed / std::sqrt(std::max(1.0, s.solver.mass_scaling_factor)) + speed);
  if (!(fixed > limit * (1.0 + 1e-12))) return;
  top.table("solver").fail("fixed_time_step", "= " + fixed_step_beyond_stability(fixed, limit, s.solver.cfl));
}

}  // namespace

Case parse_case(std::string_view toml_text, const std::string& source_name, const std::vector<std::string>& overrides) {
  const CaseTree tree = parse_case_tree(toml_text, source_name, overrides);
  TableReader top(tree.root, "", tree.source);
  Case c;
  if (top.has("cutting")) {
    c = read_cutting_case(top);
  } else {
    c.scene = read_scene_tables(top);
    read_cutting_process(top, c);
  }
  top.reject_unknown_keys();
  check_fixed_time_step(top, c.scene);
  c.scene.source_file = source_name;
  return c;
}

Case load_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return parse_case(read_case_text(file), file.string(), overrides);
}

Case load_cutting_result_scene(const std::filesystem::path& dir, std::string_view needs_cut) {
  if (!std::filesystem::is_directory(dir))
    throw InputError(fmt::format("result directory '{}' does not exist (or is not a directory)", dir.string()));
  if (!std::filesystem::exists(dir / "summary.json") || !std::filesystem::exists(dir / "scene.toml"))
    throw InputError(
        fmt::format("'{}' is not a result directory of mpmcut run (no summary.json and scene.toml)", dir.string()));
  Case loaded;
  try {
    loaded = load_case(dir / "scene.toml");
  } catch (const InputError& e) {
    throw InputError(fmt::format("cannot read the run's scene: {}", e.what()));
  }
  if (!loaded.cutting)
    throw InputError(fmt::format("'{}' is not a cutting run (its scene.toml has no [cutting_process] record): {}",
                                 dir.string(), needs_cut));
  return loaded;
}

Case default_cutting_case(const std::vector<std::string>& overrides) {
  return embedded_case("cases/ti64_default.toml", overrides, "default case");
}

Case default_elastic_demo_case(const std::vector<std::string>& overrides) {
  return embedded_case("cases/elastic_demo.toml", overrides, "demo case");
}

void write_scene(const Case& c, std::ostream& out) {
  write_scene_tables(c.scene, out);
  write_cutting_process(c, out);
}

std::string scene_text(const Case& c) {
  std::ostringstream out;
  write_scene(c, out);
  return out.str();
}

std::uint64_t scene_hash(const Case& c) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64
  for (const unsigned char ch : scene_text(c)) {
    h ^= ch;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace mpmcut
