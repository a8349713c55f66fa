#include "run/case_loading.hpp"

#include <sstream>

#include <fmt/format.h>

#include "cutting/cutting_case.hpp"
#include "io/embedded_text.hpp"
#include "io/scene_parser.hpp"
#include "io/scene_writer.hpp"
#include "io/toml_reader.hpp"

namespace mpmcut {

namespace {

Case embedded_case(std::string_view path, const std::vector<std::string>& overrides, const char* what) {
  for (const EmbeddedText& file : embedded_texts())
    if (file.path == path) return parse_case(file.text, "built-in " + std::string(file.path), overrides);
  throw InputError(std::string("the built-in ") + what + " is missing from this build");
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
