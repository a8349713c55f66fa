#include "cutting/cutting_case.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "cutting/cutting_input.hpp"
#include "cutting/cutting_scene.hpp"
#include "io/material_library.hpp"
#include "io/scene_parser.hpp"

namespace mpmcut {

namespace {

// The workpiece material of a [cutting] case: a [[material]] of the file, else a library set. A set of the file
// may start from a library set or from an earlier set of the file (`library = ...`).
MaterialParameters cutting_material(TableReader& top, TableReader& cutting, const CuttingParameters& params) {
  const std::string& name = params.material;
  MaterialLibrary library = builtin_material_library();
  read_case_materials(top, library);
  // The file's last set of that name, else the library's (find(): the latest definition wins).
  const MaterialParameters* m = library.find(name);
  if (m != nullptr) {
    // An elastic workpiece cannot yield: no chip forms, the tool's work goes into friction and elastic waves (a
    // coarse 20 m/s cut of elastic-steel: Fc 6100 N/mm, 21000 K at the contact), and every result would mislead.
    if (m->model != MaterialModel::JohnsonCook) {
      std::string plastic;
      for (const auto& n : library.names())
        if (const MaterialParameters* s = library.find(n); s && s->model == MaterialModel::JohnsonCook)
          plastic += (plastic.empty() ? "" : ", ") + ("\"" + n + "\"");
      cutting.fail("material", fmt::format("the set \"{}\" is elastic (model = \"elastic\"): a workpiece that cannot "
                                           "yield forms no chip; cut a model = \"johnson_cook\" set: {}",
                                           name, plastic));
    }
    // The workpiece starts solid: at or above the melting point the flow stress is zero.
    cutting.check("initial_temperature", params.initial_temperature, temperature_range(*m));
    return *m;
  }
  std::string known;
  for (const auto& n : builtin_material_library().names()) known += (known.empty() ? "" : ", ") + ("\"" + n + "\"");
  cutting.fail("material", fmt::format("no [[material]] and no library set named \"{}\"; library sets: {}", name, known));
}

}  // namespace

Case read_cutting_case(TableReader& top) {
  for (const char* key : {"grid", "body", "rigid_body", "boundaries", "thermal", "body_force", "cutting_process"})
    if (top.has(key))
      top.fail(key, "not allowed in a [cutting] case, which builds its own grid, bodies, tool and boundaries; "
                    "to edit those, run the case once and edit the expanded scene.toml in its result directory");
  TableReader cutting = top.table("cutting");
  const CuttingParameters params = read_cutting_parameters(cutting);
  const MaterialParameters material = cutting_material(top, cutting, params);
  Scene scene;
  try {
    scene = build_cutting_scene(params, material);
  } catch (const CuttingKeyError& e) {
    cutting.fail(e.key, e.what());
  } catch (const std::invalid_argument& e) {
    cutting.fail_table(e.what());
  }
  scene.title = top.string("title", scene.title);
  if (auto t = top.optional_table("solver")) scene.solver = read_solver(*t, scene.solver);
  scene.output = read_output(top.optional_table("output"), scene.output);
  return {scene, params};
}

void read_cutting_process(TableReader& top, Case& c) {
  // An expanded cutting scene remembers its process, so that its force outputs are written.
  if (auto t = top.optional_table("cutting_process")) {
    c.cutting = read_cutting_parameters(*t);
    if (c.scene.rigid_bodies.empty()) t->fail_table("[cutting_process] needs the tool as the first [[rigid_body]]");
    // The record's speed and cut length set the force window, the mass scaling's reference speed and the chip's
    // kinematics in the results: a scene edited away from them would be reported as the process it no longer is.
    const CuttingParameters& p = *c.cutting;
    const Vec2 tool_velocity = c.scene.rigid_bodies.front().velocity;
    const double tolerance = 1e-9;
    if ((tool_velocity - Vec2(-p.cutting_speed, 0.0)).norm() > tolerance * p.cutting_speed)
      t->fail_table(fmt::format(
          "the tool (the first [[rigid_body]]) moves at ({:g}, {:g}) m/s, but the process it records cuts at "
          "cutting_speed = {:g} m/s, i.e. velocity = [{:g}, 0.0]: change the speed in the [cutting] case and run it "
          "again (its scene then has both), or edit cutting_process.cutting_speed together with the tool's velocity",
          tool_velocity.x(), tool_velocity.y(), p.cutting_speed, -p.cutting_speed));
    const double end_time = p.cut_length / p.cutting_speed;
    if (std::abs(c.scene.solver.end_time - end_time) > tolerance * end_time)
      t->fail_table(fmt::format(
          "solver.end_time = {:g} s, but the process it records ends at cut_length / cutting_speed = {:g} s: change "
          "cut_length in the [cutting] case and run it again, or edit cutting_process.cut_length together with "
          "solver.end_time",
          c.scene.solver.end_time, end_time));
  }
}

void write_cutting_process(const Case& c, std::ostream& out) {
  if (!c.cutting) return;
  out << "\n# The process this scene was built from (the tool is the first rigid body); it makes the run\n"
         "# write forces.csv and the cutting results. Edit the scene above, not this record.";
  write_cutting_parameters(*c.cutting, out, "cutting_process");
}

RunSizeKeys run_size_keys(const Case& c) {
  if (!c.cutting) return {};
  return {"cutting.cell_size, cutting.cut_length, cutting.uncut_chip_thickness", "cutting.cut_length / cutting_speed",
          "cutting.cell_size"};
}

}  // namespace mpmcut
