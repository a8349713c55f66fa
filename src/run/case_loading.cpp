#include "run/case_loading.hpp"

#include <sstream>

#include "cutting/cutting_case.hpp"
#include "io/embedded_text.hpp"
#include "io/scene_parser.hpp"
#include "io/scene_writer.hpp"
#include "io/toml_reader.hpp"

namespace mpmcut {

namespace {

Scene embedded_case(std::string_view path, const std::vector<std::string>& overrides, const char* what) {
  for (const EmbeddedText& file : embedded_texts())
    if (file.path == path) return parse_scene(file.text, "built-in " + std::string(file.path), overrides);
  throw InputError(std::string("the built-in ") + what + " is missing from this build");
}

}  // namespace

Scene parse_scene(std::string_view toml_text, const std::string& source_name, const std::vector<std::string>& overrides) {
  const CaseTree tree = parse_case_tree(toml_text, source_name, overrides);
  TableReader top(tree.root, "", tree.source);
  Scene scene;
  if (top.has("cutting")) {
    scene = read_cutting_case(top);
  } else {
    scene = read_scene_tables(top);
    read_cutting_process(top, scene);
  }
  top.reject_unknown_keys();
  scene.source_file = source_name;
  return scene;
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return parse_scene(read_case_text(file), file.string(), overrides);
}

Scene default_cutting_scene(const std::vector<std::string>& overrides) {
  return embedded_case("cases/ti64_default.toml", overrides, "default case");
}

Scene default_elastic_demo_scene(const std::vector<std::string>& overrides) {
  return embedded_case("cases/elastic_demo.toml", overrides, "demo case");
}

void write_scene(const Scene& scene, std::ostream& out) {
  write_scene_tables(scene, out);
  write_cutting_process(scene, out);
}

std::string scene_text(const Scene& scene) {
  std::ostringstream out;
  write_scene(scene, out);
  return out.str();
}

std::uint64_t scene_hash(const Scene& scene) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64
  for (const unsigned char c : scene_text(scene)) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace mpmcut
