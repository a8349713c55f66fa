// Case file -> Scene (docs/input.md): the shipped cases parse, every validation rule gives an
// InputError naming file:line:column and the key, --set overrides, library sets with per-key
// overrides, and write_scene -> parse_case round trips.
#include <gtest/gtest.h>

#include "../support/parse_errors.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/material_library.hpp"
#include "run/case_loading.hpp"
#include "io/scene_writer.hpp"
#include "io/whole_file.hpp"

namespace mpmcut {

namespace {

// The scene of a case: most tests here are about the scene tables (the cutting process a case may
// carry is checked where it matters, see SceneWriter and the cutting_speed tests).
Scene parse_scene(std::string_view text, const std::string& name, const std::vector<std::string>& overrides = {}) {
  return parse_case(text, name, overrides).scene;
}
Scene load_scene(const std::filesystem::path& file) { return load_case(file).scene; }

// Field-wise equality of everything a case file describes. (Scene::cutting, set only by the
// cutting preset, is not part of the case-file format.) On failure prints both as TOML.
void expect_same_scene(const Scene& a, const Scene& b) {
  const bool same = a.title == b.title && a.source_file == b.source_file && a.grid == b.grid &&
                    a.boundaries == b.boundaries && a.thermal == b.thermal && a.solver == b.solver &&
                    a.output == b.output && a.body_force == b.body_force && a.materials == b.materials &&
                    a.bodies == b.bodies && a.rigid_bodies == b.rigid_bodies;
  if (same) return;
  std::ostringstream ta, tb;
  write_scene(Case{a}, ta);
  write_scene(Case{b}, tb);
  ADD_FAILURE() << "scenes differ:\n" << ta.str() << "\n--- versus ---\n" << tb.str();
}

const std::filesystem::path kCases = std::filesystem::path(MPMCUT_SOURCE_DIR) / "cases";

// A small valid case that the error tests break in one place each.
const std::string kBase = R"(title = "base"

[grid]
cell_size = 0.1
min = [0.0, 0.0]
max = [1.0, 1.0]

[solver]
end_time = 1.0

[[material]]
name = "m"
library = "elastic-unit"

[[body]]
name = "b"
material = "m"
rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }
)";

// kBase with `from` replaced by `to` (which must occur).
std::string edit(const std::string& from, const std::string& to, std::string text = kBase) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' not in the case";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// 1-based line of the first occurrence of `marker`.
int line_of(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << marker << "' not in the case";
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// The InputError message that parsing `text` gives ("" if it parses).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return testing::parse_error_of(text, overrides);
}

// Expects an error at `line` (of `marker`) that contains every one of `parts`.
void expect_error(const std::string& text, const std::string& marker, std::initializer_list<std::string> parts,
                  const std::vector<std::string>& overrides = {}) {
  const std::string message = error_of(text, overrides);
  ASSERT_FALSE(message.empty()) << "no InputError for:\n" << text;
  EXPECT_TRUE(message.starts_with("case.toml:" + std::to_string(line_of(text, marker)) + ":")) << message;
  for (const auto& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

// ---------------------------------------------------------------------------------------------

TEST(SceneParser, EveryShippedCaseParses) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kCases)) {
    if (entry.path().extension() != ".toml") continue;
    if (entry.path().parent_path().filename() == "calibration") continue;  // mpmcut calibrate configs, not cases
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(load_scene(entry.path()));
    ++count;
  }
  EXPECT_GE(count, 3);
}

// docs/input.md's complete example must stay valid.
TEST(SceneParser, DocumentedExampleParses) {
  std::ifstream in(std::filesystem::path(MPMCUT_SOURCE_DIR) / "docs" / "input.md");
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto section = doc.find("## A complete example");
  ASSERT_NE(section, std::string::npos);
  const auto begin = doc.find("```toml\n", section) + 8;
  const auto end = doc.find("```", begin);
  const Scene s = parse_scene(doc.substr(begin, end - begin), "docs/input.md");
  EXPECT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.rigid_bodies.size(), 1u);
  EXPECT_NEAR(s.materials[0].fracture_energy, 23.5e3, 0.1e3);
}

TEST(SceneParser, BaseCaseParsesWithDefaults) {
  const Scene s = parse_scene(kBase, "case.toml");
  EXPECT_EQ(s.title, "base");
  EXPECT_EQ(s.source_file, "case.toml");
  EXPECT_DOUBLE_EQ(s.grid.cell_size, 0.1);
  EXPECT_EQ(s.solver.scheme, TimeScheme::MUSL);
  EXPECT_EQ(s.solver.shape_function, ShapeFunctionKind::UGimp);
  EXPECT_DOUBLE_EQ(s.solver.cfl, 0.4);
  EXPECT_EQ(s.boundaries.left, BoundaryKind::Free);
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].particles_per_cell, 2);
  EXPECT_DOUBLE_EQ(s.bodies[0].temperature, s.materials[0].room_temperature);
  EXPECT_TRUE(s.rigid_bodies.empty());
  EXPECT_FALSE(s.thermal.left.has_value());
}

TEST(SceneParser, CollidingDisksIsSulsky1994) {
  const Scene s = load_scene(kCases / "colliding_disks.toml");
  EXPECT_DOUBLE_EQ(s.grid.cell_size, 0.05);
  EXPECT_DOUBLE_EQ(s.solver.end_time, 3.0);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_DOUBLE_EQ(s.materials[0].youngs_modulus, 1000.0);
  EXPECT_DOUBLE_EQ(s.materials[0].poisson_ratio, 0.3);
  EXPECT_DOUBLE_EQ(s.materials[0].density, 1000.0);
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].shape.kind, ShapeKind::Disk);
  EXPECT_EQ(s.bodies[0].shape.disk.center, Vec2(0.2, 0.2));
  EXPECT_EQ(s.bodies[1].shape.disk.center, Vec2(0.8, 0.8));
  EXPECT_DOUBLE_EQ(s.bodies[1].shape.disk.radius, 0.2);
  EXPECT_EQ(s.bodies[0].velocity, Vec2(0.1, 0.1));
  EXPECT_EQ(s.bodies[1].velocity, Vec2(-0.1, -0.1));
  // Kinetic energy 2 * (1/2) rho pi r^2 |v|^2 = 2.513 J per unit thickness (Sulsky 1994 disks).
  const double ke = 2 * 0.5 * 1000.0 * std::numbers::pi * 0.04 * 0.02;
  EXPECT_NEAR(ke, 2.513, 1e-3);
}

TEST(SceneParser, VibratingBarIsFixedFree) {
  const Scene s = load_scene(kCases / "vibrating_bar.toml");
  EXPECT_EQ(s.boundaries.left, BoundaryKind::Fixed);
  EXPECT_EQ(s.boundaries.right, BoundaryKind::Free);
  EXPECT_DOUBLE_EQ(s.materials[0].youngs_modulus, 100.0);
  EXPECT_DOUBLE_EQ(s.materials[0].density, 1.0);
  EXPECT_DOUBLE_EQ(s.materials[0].poisson_ratio, 0.0);
  EXPECT_DOUBLE_EQ(s.bodies[0].shape.rectangle.max.x() - s.bodies[0].shape.rectangle.min.x(), 25.0);
}

TEST(SceneParser, BuiltInDemoIsTheShippedCaseAndSmall) {
  Scene builtin = default_elastic_demo_case().scene;
  Scene shipped = load_scene(kCases / "elastic_demo.toml");
  builtin.source_file = shipped.source_file;
  expect_same_scene(builtin, shipped);
  // 2-5k particles: disk area over the particle spacing (h / ppc) squared.
  const BodySpec& b = builtin.bodies.at(0);
  const double spacing = builtin.grid.cell_size / b.particles_per_cell;
  const double particles = std::numbers::pi * b.shape.disk.radius * b.shape.disk.radius / (spacing * spacing);
  EXPECT_GT(particles, 2000.0);
  EXPECT_LT(particles, 5000.0);
  EXPECT_DOUBLE_EQ(default_elastic_demo_case({"solver.end_time=0.1"}).scene.solver.end_time, 0.1);
}

TEST(SceneParser, IntegersAreAcceptedAsNumbers) {
  const Scene s = parse_scene(edit("end_time = 1.0", "end_time = 2"), "case.toml");
  EXPECT_DOUBLE_EQ(s.solver.end_time, 2.0);
}

// --- validation -------------------------------------------------------------------------------

// A shape between the particle sub-grid's points (spacing 0.05 here) got no particle and the run went on without it.
TEST(SceneValidation, ABodyThatGetsNoParticleIsAnError) {
  const std::string sheet = kBase + "[[body]]\nname = \"sheet\"\nmaterial = \"m\"\n"
                                    "rectangle = { min = [0.6, 0.6], max = [0.9, 0.61] }\n";
  expect_error(sheet, "rectangle = { min = [0.6", {"key 'body[1].rectangle'", "body \"sheet\" gets no particle"});
  expect_error(edit("rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }", "disk = { center = [0.5, 0.5], radius = 0.01 }"),
               "disk", {"key 'body[0].disk'", "gets no particle", "spacing grid.cell_size / particles_per_cell = 0.05 m"});
  // One sub-grid point is enough: a sheet across a row of them.
  EXPECT_EQ(error_of(kBase + "[[body]]\nname = \"sheet\"\nmaterial = \"m\"\n"
                             "rectangle = { min = [0.6, 0.62], max = [0.9, 0.63] }\n"),
            "");
}

// Both bodies' particles would sit in the shared area (twice the mass); a body inside a rigid one is expelled in a
// step. Touching is fine.
TEST(SceneValidation, BodiesThatOverlapAtTheStartAreAnError) {
  expect_error(kBase + "[[body]]\nname = \"b2\"\nmaterial = \"m\"\nrectangle = { min = [0.3, 0.3], max = [0.6, 0.6] }\n",
               "min = [0.3, 0.3]", {"key 'body[1].rectangle'", "body \"b2\" overlaps body \"b\""});
  EXPECT_EQ(error_of(kBase + "[[body]]\nname = \"b2\"\nmaterial = \"m\"\n"
                             "rectangle = { min = [0.4, 0.2], max = [0.6, 0.4] }\n"),
            "");
  // Both ways round: the coarser body (1 particle per cell) has no point inside the finer sheet before it, but the
  // sheet's points lie inside it (it passed when the sheet came first).
  const std::string sheet_then_block =
      edit("rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }",
           "particles_per_cell = 4\nrectangle = { min = [0.16, 0.2], max = [0.19, 0.8] }") +
      "[[body]]\nname = \"block\"\nmaterial = \"m\"\nparticles_per_cell = 1\n"
      "rectangle = { min = [0.1, 0.2], max = [0.4, 0.8] }\n";
  expect_error(sheet_then_block, "min = [0.1, 0.2]", {"body \"block\" overlaps body \"b\"", "a particle of \"b\""});
  // Touching is not overlapping, also where the shared outline runs through particle positions: two triangles
  // splitting a square along its diagonal (either vertex order; round-off put diagonal points in both), two
  // rectangles sharing an edge on a particle row (1 particle per cell: rows at 0.05 + 0.1 k).
  for (const char* second : {"[[0.1, 0.1], [0.9, 0.9], [0.1, 0.9]]", "[[0.1, 0.1], [0.1, 0.9], [0.9, 0.9]]"}) {
    const std::string triangles =
        edit("rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }", "polygon = [[0.1, 0.1], [0.9, 0.1], [0.9, 0.9]]") +
        "[[body]]\nname = \"b2\"\nmaterial = \"m\"\npolygon = " + second + "\n";
    EXPECT_EQ(error_of(triangles, {"grid.cell_size=0.02"}), "") << second;
  }
  EXPECT_EQ(error_of(edit("rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }",
                          "particles_per_cell = 1\nrectangle = { min = [0.2, 0.25], max = [0.4, 0.45] }") +
                     "[[body]]\nname = \"b2\"\nmaterial = \"m\"\nparticles_per_cell = 1\n"
                     "rectangle = { min = [0.2, 0.45], max = [0.4, 0.65] }\n"),
            "");
  const std::string wall = "[[rigid_body]]\nname = \"wall\"\npolygon = [[{}, 0.0], [0.9, 0.0], [0.9, 1.0], [{}, 1.0]]\n";
  const auto with_wall = [&](const char* x) { return kBase + fmt::format(fmt::runtime(wall), x, x); };
  expect_error(with_wall("0.3"), "polygon = [[0.3",
               {"key 'rigid_body[0].polygon'", "rigid body \"wall\" overlaps body \"b\" at the start"});
  EXPECT_EQ(error_of(with_wall("0.4")), "");
  // The rounding radius grows the shape: 0.04 m left of a wall at 0.41 reaches the body's last particles at 0.375.
  expect_error(with_wall("0.41") + "rounding_radius = 0.04\n", "polygon = [[0.41", {"overlaps body \"b\""});
}

// Penalty springs act where a particle's domain reaches into a rigid body: a particle closer to the outline than its
// domain's half width (here 0.025 m) at the start would be shot out at the first step (a block laid on a plate turned
// against the grid flew off it). Node contact takes such a start; penalty contact wants the gap.
TEST(SceneValidation, PenaltyContactRefusesDomainsReachingIntoARigidBodyAtTheStart) {
  const std::string wall = "[[rigid_body]]\nname = \"wall\"\npolygon = [[{}, 0.0], [0.9, 0.0], [0.9, 1.0], [{}, 1.0]]\n";
  const auto with_wall = [&](const char* x, bool penalty) {
    const std::string base = penalty ? edit("end_time = 1.0", "end_time = 1.0\ncontact_detection = \"penalty\"") : kBase;
    return base + fmt::format(fmt::runtime(wall), x, x);
  };
  EXPECT_EQ(error_of(with_wall("0.39", false)), "");  // the last particles at 0.375: 0.015 m from the wall
  expect_error(with_wall("0.39", true), "polygon = [[0.39",
               {"key 'rigid_body[0].polygon'", "rigid body \"wall\" reaches into the particle domains of body \"b\"",
                "0.015 m from the outline, less than the domain's half width 0.025 m", "gap of at least 0.025 m",
                "contact_detection = \"node\""});
  EXPECT_EQ(error_of(with_wall("0.4", true)), "");  // domains touching the wall
  expect_error(with_wall("0.3", true), "polygon = [[0.3", {"rigid body \"wall\" overlaps body \"b\" at the start"});
}

// An adiabatic cut's expanded scene keeps its far-field side temperature with conduction off: it must read back
// (resume, analyze and plot read it; a check refusing side temperatures without conduction broke them).
TEST(SceneValidation, AnAdiabaticCutsSceneReadsBack) {
  const Case adiabatic = default_cutting_case({"cutting.conduction=false", "cutting.cut_length=0.1e-3"});
  EXPECT_NO_THROW(parse_case(scene_text(adiabatic), "scene.toml", {}));
}

// Frictional heat into a material without heat capacity made the temperature infinite at the first contact.
TEST(SceneValidation, FrictionalHeatNeedsASpecificHeat) {
  const std::string wall = kBase + "[[rigid_body]]\nname = \"wall\"\npolygon = [[0.5, 0.0], [0.9, 0.0], [0.9, 1.0], "
                                   "[0.5, 1.0]]\nfriction = 0.3\n";
  expect_error(edit("library = \"elastic-unit\"", "library = \"elastic-unit\"\nspecific_heat = 0.0", wall), "friction = 0.3",
               {"key 'rigid_body[0].friction'", "material \"m\" of body \"b\" has no specific_heat",
                "friction_heat_share = 0"});
  EXPECT_EQ(error_of(edit("library = \"elastic-unit\"", "library = \"elastic-unit\"\nspecific_heat = 0.0",
                          wall + "friction_heat_share = 0.0\n")),
            "");
  EXPECT_EQ(error_of(wall), "");  // elastic-unit's specific heat is 1 J/(kg K)
  // A rigid body that cannot reach the body in the run (boxes swept at the initial velocities, two cells wide) does
  // not need its heat capacity; moving towards it, it does.
  const std::string far = kBase + "[[rigid_body]]\nname = \"wall\"\npolygon = [[0.85, 0.0], [0.95, 0.0], [0.95, 1.0], "
                                  "[0.85, 1.0]]\nfriction = 0.3\n";
  const std::string no_heat_capacity = "library = \"elastic-unit\"\nspecific_heat = 0.0";
  EXPECT_EQ(error_of(edit("library = \"elastic-unit\"", no_heat_capacity, far)), "");
  expect_error(edit("library = \"elastic-unit\"", no_heat_capacity, far + "velocity = [-0.5, 0.0]\n"), "friction = 0.3",
               {"has no specific_heat"});
  // A body at rest that another body can push into the rigid body needs it too (every body may travel as far as the
  // fastest one): the run made the pad's temperature NaN at step 280.
  const std::string hammer = "[[material]]\nname = \"hot\"\nlibrary = \"elastic-unit\"\n[[body]]\nname = \"hammer\"\n"
                             "material = \"hot\"\nrectangle = { min = [0.0, 0.2], max = [0.1, 0.4] }\n";
  EXPECT_EQ(error_of(edit("library = \"elastic-unit\"", no_heat_capacity, far + hammer)), "");
  expect_error(edit("library = \"elastic-unit\"", no_heat_capacity, far + hammer + "velocity = [0.2, 0.0]\n"),
               "friction = 0.3", {"material \"m\" of body \"b\" has no specific_heat"});
}

TEST(SceneValidation, ParticlesPerCellOutOfRange) {
  const std::string text = edit("rectangle =", "particles_per_cell = 0\nrectangle =");
  expect_error(text, "particles_per_cell",
               {"case.toml:" + std::to_string(line_of(text, "particles_per_cell")) +
                    ":22: key 'body[0].particles_per_cell': must be in [1, 8] per direction, got 0",
                "got 0"});
  expect_error(edit("rectangle =", "particles_per_cell = 2.5\nrectangle ="), "particles_per_cell",
               {"must be an integer", "got 2.5"});
}

// The lattice keys are bounded, and the check that a body gets particles looks at its own lattice: a square 0.04
// across between two rows of the grid's sub-grid (spacing 0.05) holds none of its points, but moved onto the square
// the lattice puts one in it.
TEST(SceneValidation, LatticeKeysAreBoundedAndTheSeedChecksSeeTheBodysLattice) {
  expect_error(edit("rectangle =", "lattice_angle_deg = 95.0\nrectangle ="), "lattice_angle_deg",
               {"key 'body[0].lattice_angle_deg'", "must be in [-90, 90] deg, got 95"});
  expect_error(edit("rectangle =", "lattice_origin = [0.0, 2000.0]\nrectangle ="), "lattice_origin",
               {"key 'body[0].lattice_origin'", "2000"});
  const std::string sliver = "[[body]]\nname = \"s\"\nmaterial = \"m\"\n"
                             "rectangle = { min = [0.53, 0.53], max = [0.57, 0.57] }\n";
  expect_error(kBase + sliver, "rectangle = { min = [0.53", {"body \"s\" gets no particle"});
  EXPECT_EQ(error_of(kBase + sliver + "lattice_origin = [0.53, 0.53]\n"), "");
  EXPECT_EQ(error_of(kBase + sliver + "lattice_origin = [0.53, 0.53]\nlattice_angle_deg = 30.0\n"), "");
}

TEST(SceneValidation, UnknownKeysSuggestTheClosest) {
  expect_error(edit("end_time = 1.0", "end_time = 1.0\ncfll = 0.3"), "cfll",
               {"key 'solver.cfll'", "unknown key", "did you mean 'cfl'?"});
  expect_error(edit("[solver]", "[solvr]"), "title",
               {"top level: missing required table [solver] (is 'solvr' a misspelling?)"});
  expect_error(edit("library = \"elastic-unit\"", "library = \"elastic-unit\"\nyoungs_modulos = 3.0"),
               "youngs_modulos", {"key 'material[0].youngs_modulos'", "did you mean 'youngs_modulus'?"});
  expect_error(edit("max = [0.4, 0.4] }", "max = [0.4, 0.4], mid = 1 }"), "rectangle",
               {"key 'body[0].rectangle.mid'", "did you mean 'min'?"});
  expect_error(kBase + "zzz_completely_different = 1\n", "zzz_", {"known keys here:"});
  // A key read under its own name is no misspelling of a missing one (a missing jc_m suggested the jc_A beside it).
  const std::string jc = edit("library = \"elastic-unit\"",
                              "model = \"johnson_cook\"\ndensity = 4430.0\nyoungs_modulus = 1.1e11\npoisson_ratio = 0.34\n"
                              "specific_heat = 526.0\nmelting_temperature = 1878.0\njc_A = 8.6e8\njc_B = 3.3e8\n"
                              "jc_n = 0.34\njc_C = 0.012");
  const std::string missing_m = error_of(jc);
  EXPECT_NE(missing_m.find("missing required key 'jc_m'"), std::string::npos) << missing_m;
  EXPECT_EQ(missing_m.find("misspelling"), std::string::npos) << missing_m;
}

TEST(SceneValidation, WrongTypes) {
  expect_error(edit("cell_size = 0.1", "cell_size = \"big\""), "cell_size",
               {"key 'grid.cell_size'", "must be a number", "got \"big\" (a string)"});
  expect_error(edit("min = [0.0, 0.0]", "min = [0.0]"), "min = [0.0]", {"key 'grid.min'", "[x, y]"});
  expect_error(edit("[grid]", "grid = 3\n[gridx]"), "grid = 3", {"key 'grid'", "must be a table"});
  expect_error(edit("[[body]]", "[body]"), "[body]", {"key 'body'", "[[body]] entries"});
}

TEST(SceneValidation, NonPositiveSizes) {
  expect_error(edit("cell_size = 0.1", "cell_size = 0"), "cell_size", {"key 'grid.cell_size'", "must be in [1e-09, 100] m", "got 0"});
  expect_error(edit("cell_size = 0.1", "cell_size = 2.0"), "cell_size",
               {"key 'grid.cell_size'", "at most the domain size (1 x 1)", "got 2.0"});
  expect_error(edit("max = [1.0, 1.0]", "max = [1.0, -1.0]"), "max = [1.0, -1.0]",
               {"key 'grid.max'", "greater than grid.min"});
  expect_error(edit("rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }", "disk = { center = [0.5, 0.5], radius = -1 }"),
               "disk", {"key 'body[0].disk.radius'", "got -1"});
  expect_error(edit("max = [0.4, 0.4] }", "max = [0.1, 0.4] }"), "rectangle",
               {"key 'body[0].rectangle.max'", "greater than min"});
}

TEST(SceneValidation, MaterialConstants) {
  const std::string full = edit("library = \"elastic-unit\"",
                                "density = 1000.0\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.3");
  expect_error(edit("density = 1000.0", "density = -1000.0", full), "density",
               {"key 'material[0].density'", "must be in (0, 100000] kg/m^3", "got -1000.0"});
  expect_error(edit("youngs_modulus = 1.0e6", "youngs_modulus = -1.0", full), "youngs_modulus",
               {"key 'material[0].youngs_modulus'", "got -1.0"});
  expect_error(edit("poisson_ratio = 0.3", "poisson_ratio = 0.5", full), "poisson_ratio",
               {"key 'material[0].poisson_ratio'", "in (-1, 0.5)", "got 0.5"});
  // A library set with an override that makes it invalid.
  expect_error(edit("library = \"elastic-unit\"", "library = \"elastic-unit\"\npoisson_ratio = -1.5"), "poisson_ratio",
               {"key 'material[0].poisson_ratio'"});
  // Missing required keys of a full definition name the [[material]] table.
  expect_error(edit("poisson_ratio = 0.3", "", full), "[[material]]",
               {"table 'material[0]'", "missing required key 'poisson_ratio'"});
}

TEST(SceneValidation, JohnsonCookMeltingAboveRoomTemperature) {
  expect_error(edit("library = \"elastic-unit\"", "library = \"ti64-seo-2005\"\nmelting_temperature = 250.0"),
               "melting_temperature",
               {"key 'material[0].melting_temperature'", "must be in (293, 10000] K (above room_temperature)", "got 250.0"});
  // Also when a full JC definition leaves out jc_A.
  const std::string jc = edit("library = \"elastic-unit\"",
                              "model = \"johnson_cook\"\ndensity = 1.0\nyoungs_modulus = 1.0\npoisson_ratio = 0.3\n"
                              "jc_B = 1.0\njc_n = 1.0\njc_C = 0.0\njc_m = 1.0\nmelting_temperature = 1000.0\n"
                              "specific_heat = 1.0");
  expect_error(jc, "[[material]]", {"table 'material[0]'", "missing required key 'jc_A'"});
}

TEST(SceneValidation, ChoicesListTheAllowedValues) {
  expect_error(edit("end_time = 1.0", "end_time = 1.0\nscheme = \"usf\""), "scheme",
               {"key 'solver.scheme'", "\"musl\" | \"usl\"", "got \"usf\""});
  expect_error(edit("[solver]", "[boundaries]\nleft = \"sticky\"\n[solver]"), "sticky",
               {"key 'boundaries.left'", "\"free\" | \"fixed\" | \"roller\""});
}

TEST(SceneValidation, RangesOfSolverAndThermal) {
  expect_error(edit("end_time = 1.0", "end_time = 1.0\ncfl = 1.5"), "cfl", {"key 'solver.cfl'", "(0, 1]"});
  expect_error(edit("end_time = 1.0", "end_time = 1.0\nflip_fraction = -0.1"), "flip", {"key 'solver.flip_fraction'"});
  expect_error(edit("end_time = 1.0", "end_time = -1.0"), "end_time", {"key 'solver.end_time'", "must be in (0, 1000] s"});
  expect_error(kBase + "[[rigid_body]]\nname = \"tool\"\npolygon = [[0, 0], [1, 0], [0, 1]]\nfriction = -0.1\n",
               "friction", {"key 'rigid_body[0].friction'", "must be in [0, 2]"});
  expect_error(kBase + "[[rigid_body]]\nname = \"tool\"\npolygon = [[0, 0], [1, 0], [0, 1]]\nfriction_heat_share = 1.5\n",
               "friction_heat_share", {"key 'rigid_body[0].friction_heat_share'", "must be in [0, 1]"});
  // The heat a rigid body takes is part of the conduction update: without conduction it is an error.
  expect_error(kBase + "[[rigid_body]]\nname = \"tool\"\npolygon = [[0, 0], [1, 0], [0, 1]]\nheat_transfer_coefficient = 1e5\n",
               "heat_transfer_coefficient", {"key 'rigid_body[0].heat_transfer_coefficient'", "thermal.conduction = true"});
  expect_error(edit("[solver]", "[thermal]\nleft = -5.0\n[solver]"), "left = -5", {"key 'thermal.left'", "must be in (0, 10000] K"});
  expect_error(edit("rectangle =", "temperature = 0\nrectangle ="), "temperature", {"key 'body[0].temperature'"});
}

// A conducting rigid body needs the heat transfer coefficient its heat enters by, a held face (else a steady body
// heats without bound), edges that exist, and an averaging time when steady (rho c = 0).
TEST(SceneValidation, ConductingRigidBody) {
  const std::string conducting = edit("[solver]", "[thermal]\nconduction = true\n[solver]") +
                                 "[[rigid_body]]\nname = \"tool\"\npolygon = [[0.6, 0.6], [0.9, 0.6], [0.6, 0.9]]\n";
  expect_error(conducting + "conductivity = 50\nvolumetric_heat_capacity = 3e6\nheld_faces = [1]\n", "conductivity",
               {"key 'rigid_body[0].conductivity'", "heat_transfer_coefficient > 0"});
  const std::string touching = conducting + "heat_transfer_coefficient = 1e6\n";
  expect_error(touching + "conductivity = 50\nvolumetric_heat_capacity = 3e6\n", "conductivity",
               {"key 'rigid_body[0].conductivity'", "held_faces"});
  expect_error(touching + "conductivity = 50\nvolumetric_heat_capacity = 3e6\nheld_faces = [1, 3]\n", "held_faces",
               {"key 'rigid_body[0].held_faces'", "integers in [0, 2]", "got 3"});
  expect_error(touching + "conductivity = 50\nheld_faces = [1]\n", "[[rigid_body]]",
               {"key 'rigid_body[0].heat_averaging_time'", "> 0 s for a steady conducting body"});
  expect_error(touching + "conductivity = 50\nvolumetric_heat_capacity = 3e6\nheat_averaging_time = 1e-5\nheld_faces = [1]\n",
               "heat_averaging_time", {"key 'rigid_body[0].heat_averaging_time'", "0 for a transient body"});
  expect_error(touching + "held_faces = [1]\n", "held_faces", {"key 'rigid_body[0].held_faces'", "conductivity > 0"});
  expect_error(touching + "friction = 0.3\nfriction_heat_share = 0.5\nconductivity = 50\nvolumetric_heat_capacity = 3e6\nheld_faces = [1]\n",
               "conductivity", {"key 'rigid_body[0].conductivity'", "friction_heat_share = 1"});
  EXPECT_EQ(error_of(touching + "conductivity = 50\nheat_averaging_time = 1e-5\nheld_faces = [1]\n"), "");
}

TEST(SceneValidation, ShapeMustLieInsideTheGrid) {
  expect_error(edit("max = [0.4, 0.4] }", "max = [1.4, 0.4] }"), "rectangle",
               {"key 'body[0].rectangle'", "inside the grid domain [0, 0] to [1, 1]"});
  expect_error(edit("rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }", "disk = { center = [0.1, 0.5], radius = 0.2 }"),
               "disk", {"key 'body[0].disk'", "bounding box [-0.1"});
}

TEST(SceneValidation, ExactlyOneShape) {
  expect_error(edit("rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }", ""), "[[body]]",
               {"table 'body[0]'", "exactly one shape", "got 0"});
  expect_error(edit("rectangle =", "disk = { center = [0.5, 0.5], radius = 0.1 }\nrectangle ="), "[[body]]",
               {"exactly one shape", "got 2"});
}

TEST(SceneValidation, BodyNeedsAnExistingMaterial) {
  expect_error(edit("material = \"m\"", "material = \"steel\""), "material = \"steel\"",
               {"key 'body[0].material'", "no [[material]] named \"steel\"", "defined materials: \"m\""});
}

TEST(SceneValidation, DuplicateNames) {
  expect_error(kBase + "[[material]]\nname = \"m\"\nlibrary = \"elastic-steel\"\n", "name = \"m\"\nlibrary = \"elastic-s",
               {"key 'material[1].name'", "duplicate material name \"m\""});
  const std::string twice = kBase + "[[body]]\nname = \"b\"\nmaterial = \"m\"\ndisk = { center = [0.7, 0.7], radius = 0.1 }\n";
  expect_error(twice, "name = \"b\"\nmaterial = \"m\"\ndisk", {"key 'body[1].name'", "duplicate body name \"b\""});
  expect_error(kBase + "[[rigid_body]]\nname = \"b\"\npolygon = [[0, 0], [1, 0], [0, 1]]\n", "name = \"b\"\npolygon",
               {"key 'rigid_body[0].name'", "duplicate body name"});
}

// A [[material]] of a case may start from an earlier set of the same file (validate --material-key writes a set
// "trial" that starts from the --material-file set the case carries); a later set is not yet known, and the error
// says so (it read "no material set").
TEST(SceneParser, ACaseSetMayStartFromAnEarlierSetOfTheFile) {
  const Scene s = parse_scene(kBase + "[[material]]\nname = \"m2\"\nlibrary = \"m\"\nyoungs_modulus = 3.0\n", "case.toml");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_DOUBLE_EQ(s.materials[1].youngs_modulus, 3.0);
  EXPECT_DOUBLE_EQ(s.materials[1].density, s.materials[0].density);
  EXPECT_DOUBLE_EQ(s.materials[1].poisson_ratio, s.materials[0].poisson_ratio);
  expect_error(edit("library = \"elastic-unit\"", "library = \"later\"") +
                   "[[material]]\nname = \"later\"\nlibrary = \"elastic-unit\"\n",
               "library = \"later\"",
               {"key 'material[0].library'", "material set \"later\" is defined further down this file",
                "move \"later\" up"});
  // The cutting preset's workpiece, too: a set of the file, changed from another set of the file.
  const std::string cut = "[[material]]\nname = \"fitted\"\nlibrary = \"ti64-cutting\"\njc_B = 440e6\n"
                          "[[material]]\nname = \"trial\"\nlibrary = \"fitted\"\njc_C = 0.035\n"
                          "[cutting]\nmaterial = \"trial\"\ncutting_speed = 2.0\n"
                          "uncut_chip_thickness = 0.1e-3\ncut_length = 0.1e-3\ncell_size = 20e-6\n";
  const Scene cutting = parse_case(cut, "case.toml").scene;
  const auto trial = std::find_if(cutting.materials.begin(), cutting.materials.end(),
                                  [](const MaterialParameters& m) { return m.name == "trial"; });
  ASSERT_NE(trial, cutting.materials.end());
  EXPECT_DOUBLE_EQ(trial->jc_B, 440e6);   // from the file's set
  EXPECT_DOUBLE_EQ(trial->jc_C, 0.035);   // changed
  EXPECT_DOUBLE_EQ(trial->jc_A, builtin_material_library().find("ti64-cutting")->jc_A);  // from the library
  // A name the file defines twice is an error there too (it may shadow a library set's name once).
  const std::string twice = "[[material]]\nname = \"ti64-cutting\"\nlibrary = \"ti64-cutting\"\njc_B = 440e6\n" + cut +
                            "[[material]]\nname = \"fitted\"\nlibrary = \"ti64-cutting\"\n";
  const std::string message = error_of(twice);
  const auto second = twice.rfind("name = \"fitted\"");
  const auto line = 1 + std::count(twice.begin(), twice.begin() + static_cast<std::ptrdiff_t>(second), '\n');
  EXPECT_TRUE(message.starts_with("case.toml:" + std::to_string(line) + ":")) << message;
  EXPECT_NE(message.find("key 'material[3].name'"), std::string::npos) << message;
  EXPECT_NE(message.find("duplicate material name \"fitted\""), std::string::npos) << message;
}

TEST(SceneValidation, UnknownLibrarySetListsTheAvailableOnes) {
  expect_error(edit("elastic-unit", "ti64-johnson-1958"), "library",
               {"key 'material[0].library'", "no material set \"ti64-johnson-1958\"", "available sets:",
                "\"ti64-johnson-1985\"", "\"elastic-steel\""});
}

TEST(SceneValidation, RequiredKeysAndTables) {
  const std::string no_end = edit("end_time = 1.0", "cfl = 0.5");
  expect_error(no_end, "[solver]", {"table 'solver'", "missing required key 'end_time'"});
  expect_error(edit("[solver]\nend_time = 1.0\n", ""), "title", {"top level", "missing required table [solver]"});
  expect_error(edit("cell_size = 0.1\n", ""), "[grid]", {"table 'grid'", "missing required key 'cell_size'"});
  expect_error(edit("name = \"b\"\n", ""), "[[body]]", {"table 'body[0]'", "missing required key 'name'"});
}

TEST(SceneValidation, NoBodies) {
  const std::string text = kBase.substr(0, kBase.find("[[body]]"));
  expect_error(text, "title", {"top level", "no [[body]] entries"});
}

TEST(SceneValidation, DegeneratePolygons) {
  const std::string rect = "rectangle = { min = [0.2, 0.2], max = [0.4, 0.4] }";
  expect_error(edit(rect, "polygon = [[0.1, 0.1], [0.5, 0.5], [0.9, 0.9]]"), "polygon",
               {"key 'body[0].polygon'", "zero area"});
  expect_error(edit(rect, "polygon = [[0.1, 0.1], [0.5, 0.5]]"), "polygon", {"at least 3 vertices, got 2"});
  // A bow tie: edges 0-1 and 2-3 cross.
  expect_error(edit(rect, "polygon = [[0.1, 0.1], [0.9, 0.9], [0.9, 0.1], [0.1, 0.9]]"), "polygon",
               {"not simple", "edge 0-1 crosses edge 2-3"});
  expect_error(edit(rect, "polygon = [[0.1, 0.1], [0.1, 0.1], [0.9, 0.1], [0.1, 0.9]]"), "polygon", {"repeats"});
  expect_error(kBase + "[[rigid_body]]\nname = \"tool\"\npolygon = [[0, 0], [1, 1], [2, 2]]\n", "polygon = [[0, 0]",
               {"key 'rigid_body[0].polygon'", "zero area"});
}

TEST(SceneValidation, TomlSyntaxErrorHasLineAndColumn) {
  const std::string message = error_of(edit("cell_size = 0.1", "cell_size = = 0.1"));
  EXPECT_TRUE(message.starts_with("case.toml:4:")) << message;
  EXPECT_NE(message.find("TOML syntax error"), std::string::npos) << message;
}

TEST(SceneValidation, MissingFileNamesThePath) {
  try {
    load_scene("/nonexistent/dir/case.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/case.toml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_scene(kCases), InputError);  // a directory
  // The reason, for the readers that only get "could not read" back (calibration, measurement and material files).
  EXPECT_EQ(unreadable_reason("/nonexistent/dir/case.toml"), "no such file");
  EXPECT_EQ(unreadable_reason(kCases), "a directory, not a file");
}

// --- overrides --------------------------------------------------------------------------------

TEST(SceneOverrides, SetValuesOfEveryKind) {
  const Scene s = parse_scene(kBase, "case.toml",
                              {"solver.cfl=0.3", "body[0].velocity=[1.0, -2]", "solver.scheme=usl",
                               "title=a bare string", "thermal.left=300", "thermal.conduction=true",
                               "material[0].specific_heat=1e3", "output.vtu=false",
                               "material[0].youngs_modulus=2e3", "body.0.particles_per_cell=4"});
  EXPECT_DOUBLE_EQ(s.solver.cfl, 0.3);
  EXPECT_EQ(s.bodies[0].velocity, Vec2(1.0, -2.0));
  EXPECT_EQ(s.solver.scheme, TimeScheme::USL);
  EXPECT_EQ(s.title, "a bare string");
  ASSERT_TRUE(s.thermal.left.has_value());
  EXPECT_DOUBLE_EQ(*s.thermal.left, 300.0);
  EXPECT_FALSE(s.output.vtu);
  EXPECT_DOUBLE_EQ(s.materials[0].youngs_modulus, 2000.0);
  EXPECT_EQ(s.bodies[0].particles_per_cell, 4);
}

TEST(SceneOverrides, ReplaceAWholeShape) {
  const Scene s = parse_scene(kBase, "case.toml", {"body[0].rectangle={min = [0.1, 0.1], max = [0.9, 0.5]}"});
  EXPECT_EQ(s.bodies[0].shape.rectangle.max, Vec2(0.9, 0.5));
}

TEST(SceneOverrides, UnknownKeysAndBadValuesNameTheOverride) {
  std::string m = error_of(kBase, {"solver.cfll=0.3"});
  EXPECT_TRUE(m.starts_with("case.toml: --set 'solver.cfll=0.3': key 'solver.cfll': unknown key")) << m;
  EXPECT_NE(m.find("did you mean 'cfl'?"), std::string::npos) << m;
  m = error_of(kBase, {"thermall.left=300"});
  EXPECT_TRUE(m.starts_with("case.toml: --set 'thermall.left=300': key 'thermall': unknown key")) << m;
  m = error_of(kBase, {"solver.cfl=2"});
  EXPECT_TRUE(m.starts_with("case.toml: --set 'solver.cfl=2': key 'solver.cfl': must be in (0, 1] (Courant number), got 2")) << m;
  m = error_of(kBase, {"solver.scheme=usf"});
  EXPECT_NE(m.find("--set 'solver.scheme=usf'"), std::string::npos) << m;
  m = error_of(kBase, {"body[3].velocity=[0, 0]"});
  EXPECT_NE(m.find("index 3 is out of range: 'body' has 1 entries"), std::string::npos) << m;
  m = error_of(kBase, {"solver.cfl"});
  EXPECT_NE(m.find("expected key=value"), std::string::npos) << m;
  EXPECT_EQ(m.find("case file"), std::string::npos) << m;
  // `run --set KEY=V case.toml`: CLI11 gives the case file to --set.
  m = error_of(kBase, {"cases/ti64_quick.toml"});
  EXPECT_NE(m.find("expected key=value (is it the case file? Give the case file before --set"), std::string::npos) << m;
  m = error_of(kBase, {"title.x=1"});
  EXPECT_NE(m.find("'title' is not a table"), std::string::npos) << m;
  // A key set twice: the error is of the value that stands, the last override's (it named the first).
  m = error_of(kBase, {"solver.scheme=\"usl\"", "solver.scheme=usf"});
  EXPECT_NE(m.find("--set 'solver.scheme=usf'"), std::string::npos) << m;
}

// A cut of a library set has no [[material]] array: the error says how to override the set's keys.
TEST(SceneOverrides, AMaterialOverrideOnACutOfALibrarySetSaysHowToMakeOne) {
  const std::string cut = "[cutting]\nmaterial = \"ti64-cutting\"\ncutting_speed = 20.0\nuncut_chip_thickness = 0.1e-3\n";
  const std::string m = error_of(cut, {"material[0].jc_A=1e9"});
  EXPECT_NE(m.find("'material' is not an array in the case; this case cuts the library set \"ti64-cutting\""),
            std::string::npos) << m;
  EXPECT_NE(m.find("library = \"ti64-cutting\""), std::string::npos) << m;
  EXPECT_EQ(error_of(kBase, {"rigid_body[0].friction=0.1"}).find("library set"), std::string::npos);
}

// --- materials in scenes ----------------------------------------------------------------------

TEST(SceneMaterials, LibrarySetWithPerKeyOverride) {
  const Scene s = parse_scene(edit("library = \"elastic-unit\"", "library = \"ti64-lesuer-2000\"\njc_A = 1.0e9\ndamage = false"),
                              "case.toml");
  const MaterialParameters& m = s.materials.at(0);
  const MaterialParameters& set = *builtin_material_library().find("ti64-lesuer-2000");
  EXPECT_EQ(m.name, "m");
  EXPECT_EQ(m.citation, set.citation);
  EXPECT_DOUBLE_EQ(m.jc_A, 1.0e9);
  EXPECT_FALSE(m.damage_enabled);
  EXPECT_DOUBLE_EQ(m.jc_B, set.jc_B);
  EXPECT_DOUBLE_EQ(m.fracture_energy, set.fracture_energy);
  EXPECT_EQ(m.model, MaterialModel::JohnsonCook);
}

TEST(SceneMaterials, FractureToughnessBecomesFractureEnergy) {
  // K_IC = 65 MPa sqrt(m), E = 113.8 GPa, nu = 0.342: G_f = K^2 (1 - nu^2) / E (plane strain).
  const Scene s = parse_scene(
      edit("library = \"elastic-unit\"", "library = \"ti64-johnson-1985\"\nfracture_toughness = 55.0e6"), "case.toml");
  EXPECT_NEAR(s.materials[0].fracture_energy, 55e6 * 55e6 * (1 - 0.342 * 0.342) / 113.8e9, 1e-6);
  EXPECT_NEAR(s.materials[0].fracture_energy, 23.5e3, 0.1e3);
  expect_error(edit("library = \"elastic-unit\"",
                    "library = \"ti64-johnson-1985\"\nfracture_energy = 1.0\nfracture_toughness = 55.0e6"),
               "fracture_toughness", {"key 'material[0].fracture_toughness'", "not both"});
  expect_error(edit("library = \"elastic-unit\"", "library = \"ti64-johnson-1985\"\nfracture_energy = 0"),
               "fracture_energy", {"key 'material[0].fracture_energy'", "when damage = true"});
}

// A converted key out of its range is reported at the key the user gave, with the keys the conversion read: a
// modulus in GPa made the fracture energy 1e9 times too large, reported at fracture_energy, a key not written.
TEST(SceneMaterials, AToughnessGivingAnImpossibleEnergyIsReportedAtItsKeyWithTheModulus) {
  expect_error(edit("library = \"elastic-unit\"",
                    "library = \"ti64-johnson-1985\"\nyoungs_modulus = 113.8\nfracture_toughness = 65.0e6"),
               "fracture_toughness",
               {"key 'material[0].fracture_toughness'", "youngs_modulus = 113.8 Pa", "fracture_energy = 3.278e+13 J/m^2",
                "check the units"});
}

// A full definition names what its switches need: damage = true needs D1 and D2 (left out, the failure strain
// was 0, clamped silently to min_failure_strain), eos = "mie_gruneisen" needs mg_c0 (it said "got 0").
TEST(SceneMaterials, AFullDefinitionNeedsTheKeysItsSwitchesUse) {
  const std::string full = R"(name = "m"
model = "johnson_cook"
density = 4430.0
youngs_modulus = 113.8e9
poisson_ratio = 0.34
specific_heat = 526.0
melting_temperature = 1878.0
jc_A = 1.0e9
jc_B = 1.0e9
jc_n = 0.3
jc_C = 0.01
jc_m = 1.0
reference_strain_rate = 1.0
)";
  const auto with = [&](const std::string& more) { return edit("name = \"m\"\nlibrary = \"elastic-unit\"\n", full + more); };
  EXPECT_NO_THROW(parse_scene(with(""), "case.toml"));
  expect_error(with("damage = true\nfracture_energy = 1.0e4\njc_D2 = 0.3\n"), "[[material]]",
               {"missing required key 'jc_D1'", "needed by damage = true"});
  EXPECT_NO_THROW(parse_scene(with("damage = true\nfracture_energy = 1.0e4\njc_D1 = -0.09\njc_D2 = 0.25\n"), "case.toml"));
  expect_error(with("eos = \"mie_gruneisen\"\nmg_s = 1.2\n"), "[[material]]",
               {"missing required key 'mg_c0'", "needed by eos = \"mie_gruneisen\""});
}

// A value a library set brings that the case's switch forbids is reported as the set's, and a flag as a flag.
TEST(SceneMaterials, ALibrarySetsValueThatNoLongerFitsSaysWhereItCameFrom) {
  expect_error(edit("library = \"elastic-unit\"", "library = \"ti64-johnson-1985\"\nmodel = \"elastic\""), "[[material]]",
               {"must be false unless model = \"johnson_cook\", got true from the library set \"ti64-johnson-1985\"",
                "give damage in this [[material]]"});
}

TEST(SceneMaterials, ConductionNeedsHeatCapacity) {
  const std::string text = edit("library = \"elastic-unit\"",
                                "density = 1.0\nyoungs_modulus = 1.0\npoisson_ratio = 0.0\nspecific_heat = 0.0");
  expect_error(edit("[solver]", "[thermal]\nconduction = true\n[solver]", text), "specific_heat",
               {"key 'material[0].specific_heat'", "thermal.conduction"});
}

// --- shapes -----------------------------------------------------------------------------------

TEST(SceneShapes, ContainTheRightPoints) {
  const std::string text = kBase +
                           "[[body]]\nname = \"d\"\nmaterial = \"m\"\ndisk = { center = [0.7, 0.7], radius = 0.1 }\n"
                           "[[body]]\nname = \"L\"\nmaterial = \"m\"\n"
                           "polygon = [[0.5, 0.0], [1.0, 0.0], [1.0, 0.2], [0.7, 0.2], [0.7, 0.5], [0.5, 0.5], [0.5, 0.0]]\n";
  const Scene s = parse_scene(text, "case.toml");
  const Shape& rect = s.bodies[0].shape;
  EXPECT_TRUE(rect.contains({0.3, 0.3}));
  EXPECT_FALSE(rect.contains({0.5, 0.3}));
  const Shape& disk = s.bodies[1].shape;
  EXPECT_TRUE(disk.contains({0.75, 0.75}));
  EXPECT_FALSE(disk.contains({0.79, 0.79}));  // inside the bounding box, outside the circle
  const Shape& ell = s.bodies[2].shape;
  EXPECT_EQ(ell.polygon.vertices.size(), 6u);  // the repeated closing vertex is dropped
  EXPECT_TRUE(ell.contains({0.6, 0.4}));
  EXPECT_TRUE(ell.contains({0.9, 0.1}));
  EXPECT_FALSE(ell.contains({0.9, 0.4}));  // in the notch of the L
  EXPECT_FALSE(ell.contains({0.4, 0.1}));
}

// --- writer -----------------------------------------------------------------------------------

Case round_trip(const Case& c) {
  std::ostringstream out;
  write_scene(c, out);
  return parse_case(out.str(), c.scene.source_file);
}
Scene round_trip(const Scene& s) { return round_trip(Case{s}).scene; }

TEST(SceneWriter, RoundTripsEveryShippedCase) {
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kCases)) {
    if (entry.path().extension() != ".toml") continue;
    if (entry.path().parent_path().filename() == "calibration") continue;  // mpmcut calibrate configs, not cases
    SCOPED_TRACE(entry.path().string());
    const Case c = load_case(entry.path());
    const Case back = round_trip(c);
    expect_same_scene(back.scene, c.scene);
    EXPECT_EQ(back.cutting, c.cutting);  // the [cutting_process] record of a cut
  }
}

TEST(SceneWriter, RoundTripsEveryField) {
  const std::string text = kBase + R"(
[[material]]
name = "ti"
library = "ti64-seo-2005"
eos = "mie_gruneisen"
damage_evolution = "exponential"
strain_rate_smoothing_time = 1.0e-7
citation = "quote \" and backslash \\ here"

[[body]]
name = "tri"
material = "ti"
polygon = [[0.5, 0.5], [0.9, 0.5], [0.7, 0.9]]
particles_per_cell = 3
lattice_angle_deg = 12.5
lattice_origin = [0.5, 0.5]
velocity = [0.1, -0.3]
temperature = 500.0

[[rigid_body]]
name = "tool"
polygon = [[1.0, 0.0], [2.0, 0.0], [2.0, 1.0]]
velocity = [-1.0, 0.0]
friction = 0.35
friction_heat_share = 0.4
heat_transfer_coefficient = 1.0e5
temperature = 350.0
rounding_radius = 0.05

[[rigid_body]]
name = "holder"
polygon = [[2.5, 0.0], [3.0, 0.0], [3.0, 1.0]]
heat_transfer_coefficient = 1.0e6
conductivity = 50.0
heat_averaging_time = 1.0e-5
held_faces = [1, 2]
)";
  const Scene s = parse_scene(text, "case.toml",
                              {"thermal.conduction=true", "thermal.top=300.5", "thermal.left=1.0e-3",
                               "boundaries.bottom=roller", "boundaries.left=fixed", "solver.shape_function=linear",
                               "solver.scheme=usl", "solver.max_steps=123", "solver.fixed_time_step=1.0e-9",
                               "solver.flip_fraction=0.95", "solver.remove_escaping_particles=true", "output.snapshot_interval=0.1", "output.vtu=false",
                               "body_force=[0.1, -9.81]", "title=\"round trip\""});
  ASSERT_EQ(s.rigid_bodies.size(), 2u);
  EXPECT_DOUBLE_EQ(s.rigid_bodies[0].rounding_radius, 0.05);
  EXPECT_EQ(s.rigid_bodies[1].held_faces, (std::vector<int>{1, 2}));
  EXPECT_TRUE(s.solver.remove_escaping_particles);
  ASSERT_TRUE(s.thermal.top.has_value());
  EXPECT_FALSE(s.thermal.bottom.has_value());
  const Scene back = round_trip(s);
  EXPECT_EQ(back.materials, s.materials);
  EXPECT_EQ(back.bodies, s.bodies);
  EXPECT_EQ(back.rigid_bodies, s.rigid_bodies);
  EXPECT_EQ(back.thermal, s.thermal);
  EXPECT_EQ(back.solver, s.solver);
  expect_same_scene(back, s);
}

// A cut of an elastic workpiece forms no chip (a coarse 20 m/s cut of elastic-steel ran to Fc 6100 N/mm and 21000 K):
// the preset refuses it at the material key and names the sets that can be cut.
TEST(SceneParser, CuttingAnElasticWorkpieceIsAnInputError) {
  const std::string cut = "[cutting]\nmaterial = \"elastic-steel\"\ncutting_speed = 20.0\n"
                          "uncut_chip_thickness = 0.1e-3\ncut_length = 0.1e-3\ncell_size = 20e-6\n";
  expect_error(cut, "material =", {"cutting.material", "elastic-steel", "is elastic", "\"ti64-cutting\""});
  EXPECT_EQ(error_of(cut).find("\"elastic-unit\""), std::string::npos) << "an elastic set offered for cutting";
}

// An expanded cut's scene edited away from its [cutting_process] record would be reported as the process it no
// longer is (a tool moved at 40 m/s was summarised as 20 m/s): the record and the scene must agree.
TEST(SceneParser, AnExpandedCutWhoseToolOrEndTimeNoLongerMatchesItsRecordIsAnInputError) {
  const std::string cut = "[cutting]\nmaterial = \"ti64-cutting\"\ncutting_speed = 20.0\n"
                          "uncut_chip_thickness = 0.1e-3\ncut_length = 0.1e-3\ncell_size = 20e-6\n";
  std::ostringstream expanded;
  write_scene(parse_case(cut, "case.toml"), expanded);
  EXPECT_EQ(error_of(expanded.str()), "");  // as written, it reads back
  const std::string faster = error_of(expanded.str(), {"rigid_body[0].velocity=[-40.0, 0.0]"});
  for (const char* part : {"cutting_process", "(-40, 0) m/s", "cutting_speed = 20 m/s"})
    EXPECT_NE(faster.find(part), std::string::npos) << part << " not in: " << faster;
  const std::string shorter = error_of(expanded.str(), {"solver.end_time=2e-6"});
  for (const char* part : {"solver.end_time = 2e-06 s", "cut_length / cutting_speed = 5e-06 s"})
    EXPECT_NE(shorter.find(part), std::string::npos) << part << " not in: " << shorter;
}

// A workpiece too small for its cut names the key, its value and the least it may be, at the key's line.
TEST(SceneParser, AWorkpieceTooSmallForItsCutIsAnErrorAtItsKey) {
  const std::string cut = "[cutting]\nmaterial = \"ti64-cutting\"\ncutting_speed = 20.0\n"
                          "uncut_chip_thickness = 0.1e-3\ncut_length = 0.2e-3\ncell_size = 20e-6\n";
  expect_error(cut + "workpiece_length = 0.1e-3\n", "workpiece_length =",
               {"cutting.workpiece_length = 0.0001 m", "at least cut_length + 2 cells = 0.00024 m"});
  expect_error(cut + "workpiece_height = 0.12e-3\n", "workpiece_height =",
               {"cutting.workpiece_height = 0.00012 m", "uncut_chip_thickness + 2 cells = 0.00014 m"});
}

// A speed set on the command line replaces the file's speed in either spelling (sweep --speeds on a
// case written in m/min), and the other way round.
TEST(SceneOverrides, CuttingSpeedReplacesTheOtherSpelling) {
  const std::string cut = "[cutting]\nmaterial = \"ti64-johnson-1985\"\ncutting_speed_m_per_min = 100.0\n"
                          "uncut_chip_thickness = 0.1e-3\ncut_length = 0.1e-3\ncell_size = 20e-6\n";
  EXPECT_DOUBLE_EQ(parse_case(cut, "case.toml", {"cutting.cutting_speed=5"}).cutting->cutting_speed, 5.0);
  const std::string si = "[cutting]\nmaterial = \"ti64-johnson-1985\"\ncutting_speed = 2.0\n"
                         "uncut_chip_thickness = 0.1e-3\ncut_length = 0.1e-3\ncell_size = 20e-6\n";
  EXPECT_DOUBLE_EQ(parse_case(si, "case.toml", {"cutting.cutting_speed_m_per_min=120"}).cutting->cutting_speed, 2.0);
  // Both in the file itself is still an error.
  EXPECT_NE(error_of(si + "cutting_speed_m_per_min = 120\n").find("not both"), std::string::npos);
}

TEST(SceneWriter, RoundTripsEveryContactDetection) {
  // Every name the writer knows (and validate --contact-detection offers) is one the parser reads back.
  for (const std::string& detection : contact_detection_names()) {
    SCOPED_TRACE(detection);
    const Scene s = parse_scene(kBase, "case.toml", {"solver.contact_detection=\"" + detection + "\""});
    EXPECT_EQ(round_trip(s).solver.contact_detection, s.solver.contact_detection);
  }
  EXPECT_EQ(parse_scene(kBase, "case.toml", {"solver.contact_detection=\"gap\""}).solver.contact_detection,
            ContactDetection::Gap);
  // The penalty's stiffness travels with it; the other detections' scenes do not carry the key, so the
  // scene text of a run without it stays what it was before the key existed (committed run records match).
  const Scene penalty = parse_scene(kBase, "case.toml",
                                    {"solver.contact_detection=\"penalty\"", "solver.penalty_stiffness=0.5"});
  EXPECT_EQ(round_trip(penalty).solver.contact_detection, ContactDetection::Penalty);
  EXPECT_DOUBLE_EQ(round_trip(penalty).solver.penalty_stiffness, 0.5);
  std::ostringstream node_text;
  write_scene(Case{parse_scene(kBase, "case.toml")}, node_text);
  EXPECT_EQ(node_text.str().find("penalty_stiffness"), std::string::npos);
}

// The nodal volumetric average is read, written back only when on (committed scenes keep their text), and a name
// it does not know is refused with the ones it does.
TEST(SceneWriter, RoundTripsTheVolumetricAverage) {
  const Scene nodal = parse_scene(kBase, "case.toml", {"solver.volumetric_average=\"nodal\""});
  EXPECT_EQ(nodal.solver.volumetric_average, VolumetricAverage::Nodal);
  EXPECT_EQ(round_trip(nodal).solver.volumetric_average, VolumetricAverage::Nodal);
  const Scene off = parse_scene(kBase, "case.toml");
  EXPECT_EQ(off.solver.volumetric_average, VolumetricAverage::Off);
  std::ostringstream off_text;
  write_scene(Case{off}, off_text);
  EXPECT_EQ(off_text.str().find("volumetric_average"), std::string::npos);
  const std::string e = error_of(kBase, {"solver.volumetric_average=\"bbar\""});
  EXPECT_NE(e.find("volumetric_average"), std::string::npos) << e;
  EXPECT_NE(e.find("nodal"), std::string::npos) << e;
}

}  // namespace
}  // namespace mpmcut
