#include "cutting/cutting_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cutting/tool_geometry.hpp"
#include "solver/simulation.hpp"
#include "cutting/cutting_scene.hpp"

namespace mpmcut {

namespace {
constexpr double kPerMm = 1e-3;  // N/m -> N/mm
constexpr int kStateSize = 41;  // doubles in the checkpoint state
constexpr int kStateSizeBeforeRegionSplit = 28;
constexpr int kStateSizeBeforeToolHeat = 38;

std::vector<std::string> force_columns() {
  return {"time_s",
          "cutting_force_N_per_mm",
          "thrust_force_N_per_mm",
          "cutting_force_raw_N_per_mm",
          "thrust_force_raw_N_per_mm",
          "cutting_force_N",
          "thrust_force_N",
          "tool_displacement_m",
          "tool_chip_contact_length_m",
          "rake_normal_force_N_per_mm",
          "rake_friction_force_N_per_mm"};
}

// The faces of the tool the preset built (cutting/tool_geometry.cpp) at its current position: the rake face's
// direction up the face and outward normal, the flank's direction away from the edge (rising at the clearance
// angle) and outward normal, the centre of the edge arc, and the tool tip (lowest point of the cutting edge, on
// the machined surface).
struct ToolFrame {
  Vec2 up, normal, flank_dir, flank_normal, arc_centre, tip;
  double edge_radius;
};
ToolFrame tool_frame(const CuttingParameters& c, const Simulation& sim) {
  const RigidBodySpec& tool = sim.scene().rigid_bodies[0];
  const FaceDirections rake = rake_face_directions(c.rake_angle_deg), flank = flank_directions(c.clearance_angle_deg);
  ToolFrame f;
  f.up = rake.along;
  f.normal = rake.normal;
  f.flank_dir = flank.along;
  f.flank_normal = flank.normal;
  f.edge_radius = tool.rounding_radius;
  // Core vertex 0 is the centre of the edge arc (the sharp edge when r = 0).
  f.arc_centre = tool.polygon.vertices[0] + sim.rigid_bodies()[0].displacement;
  f.tip = f.arc_centre - Vec2(0.0, tool.rounding_radius);
  return f;
}

// A contact whose normal is within ~2.6 degrees of a face's lies on that face (not on the edge arc between).
constexpr double kOnFaceCosine = 0.999;

// The steady-window mean force on the tool of one region from its normal and friction impulse sums, N/mm.
nlohmann::json region_forces(const Vec2& normal, const Vec2& friction, double time) {
  const Vec2 n = normal / time * kPerMm, t = friction / time * kPerMm, sum = n + t;
  return {{"cutting_force_N_per_mm", sum.x()},
          {"thrust_force_N_per_mm", sum.y()},
          {"normal_part", {{"cutting_force_N_per_mm", n.x()}, {"thrust_force_N_per_mm", n.y()}}},
          {"friction_part", {{"cutting_force_N_per_mm", t.x()}, {"thrust_force_N_per_mm", t.y()}}}};
}
}  // namespace

CuttingForcesObserver::CuttingForcesObserver(const CuttingParameters& c, const std::filesystem::path& result_dir,
                                             bool append)
    : c_(c),
      result_dir_(result_dir),
      csv_(result_dir / "forces.csv", force_columns(), append ? CsvWriter::Mode::Append : CsvWriter::Mode::Create) {
  steady_start_time_ = steady_window_start_travel(c) / c.cutting_speed;
  steady_mid_time_ = 0.5 * (steady_start_time_ + c.cut_length / c.cutting_speed);
}

void CuttingForcesObserver::RakeSums::add(const RakeSums& o) {
  time += o.time;
  length_time += o.length_time;
  normal += o.normal;
  friction += o.friction;
  sliding_normal += o.sliding_normal;
  safeguard_normal += o.safeguard_normal;
  friction_work += o.friction_work;
  tool_friction_work += o.tool_friction_work;
  edge_normal += o.edge_normal;
  edge_friction += o.edge_friction;
  flank_normal += o.flank_normal;
  flank_friction += o.flank_friction;
  flank_length_time += o.flank_length_time;
  tool_heat += o.tool_heat;
}

void CuttingForcesObserver::after_step(const Simulation& sim) {
  // Rake-face contact of this step. Contact length: the largest distance from the tool tip, along the
  // rake face, of a place where the contact pushed the material away from the tool (a contact node's
  // mass-weighted material position, or a particle the safeguard moved) on the rake side of the tool
  // (normal within 90 degrees of the rake face's). Rake forces: only the flat face above the edge arc.
  // Every other contact is on the flank (normal along the flank's, past the arc) or on the edge arc.
  const ToolFrame f = tool_frame(c_, sim);
  RakeSums step;
  step.time = sim.last_dt();
  double length = 0.0, flank_length = 0.0;
  for (const ContactRecord& rec : sim.contact_records()) {
    if (rec.rigid_body != 0) continue;
    step.tool_friction_work += rec.friction_work;
    const double dpn = rec.impulse.dot(rec.normal);  // > 0: pushes the material away from the tool
    const double along = (rec.position - f.tip).dot(f.up);
    const bool on_rake_face = along > f.edge_radius && rec.normal.dot(f.normal) >= kOnFaceCosine;
    const bool rake = on_rake_face && dpn > 0.0;
    if (!on_rake_face) {
      const Vec2 normal_part = -dpn * rec.normal, friction_part = -rec.impulse - normal_part;  // on the tool
      const double along_flank = (rec.position - f.arc_centre).dot(f.flank_dir);
      if (along_flank > 0.0 && rec.normal.dot(f.flank_normal) >= kOnFaceCosine) {
        step.flank_normal += normal_part;
        step.flank_friction += friction_part;
        if (dpn > 0.0) flank_length = std::max(flank_length, along_flank);
      } else {
        step.edge_normal += normal_part;
        step.edge_friction += friction_part;
      }
    }
    if (dpn <= 0.0 || rec.normal.dot(f.normal) <= 0.0) continue;
    length = std::max(length, along);
    if (!rake) continue;  // edge arc, not the face
    step.normal += dpn;
    step.friction -= rec.impulse.dot(f.up);  // on the tool: + when the chip drags it up the face
    step.friction_work += rec.friction_work;
    if (rec.sliding) step.sliding_normal += dpn;
    if (rec.pass == 2) step.safeguard_normal += dpn;
  }
  step.length_time = length * step.time;
  step.flank_length_time = flank_length * step.time;
  step.tool_heat = sim.last_step_heat_to_rigid_bodies() + (1.0 - c_.friction_heat_share) * step.tool_friction_work;
  run_tool_heat_ += step.tool_heat;
  last_contact_length_ = length;
  row_sums_.add(step);
  if (steady_start_impulse_) steady_sums_.add(step);
  // The impulse at the start of the steady window, for an exact time average over it.
  if (!steady_start_impulse_ && sim.time() >= steady_start_time_) {
    steady_start_impulse_ = sim.rigid_bodies()[0].impulse;
    steady_start_time_ = sim.time();
  }
}

void CuttingForcesObserver::at_history(const Simulation& sim) {
  const RigidBodyState& tool = sim.rigid_bodies()[0];
  const double t = sim.time();
  // Filtered: the mean force since the previous row (impulse difference over time), which
  // averages the step-to-step contact noise without lag beyond one row interval.
  Vec2 filtered = tool.force;
  if (t > last_row_time_) filtered = (tool.impulse - last_row_impulse_) / (t - last_row_time_);
  last_row_time_ = t;
  last_row_impulse_ = tool.impulse;
  // The impulse at the first row past the window's middle, to compare the means of its two halves
  // (is the window steady?); on a row, so that forces.csv splits the same way.
  if (steady_start_impulse_ && !steady_mid_impulse_ && t >= steady_mid_time_ && t > steady_start_time_) {
    steady_mid_impulse_ = tool.impulse;
    steady_mid_time_ = t;
  }
  // Contact length and rake-face forces: time means since the previous row, like the filtered force.
  const RakeSums& r = row_sums_;
  const double length = r.time > 0.0 ? r.length_time / r.time : last_contact_length_;
  const double rn = r.time > 0.0 ? r.normal / r.time : 0.0, rf = r.time > 0.0 ? r.friction / r.time : 0.0;
  row_sums_ = RakeSums{};
  csv_.row({t, filtered.x() * kPerMm, filtered.y() * kPerMm, tool.force.x() * kPerMm, tool.force.y() * kPerMm,
            filtered.x() * c_.width_of_cut, filtered.y() * c_.width_of_cut, 0.0 - tool.displacement.x(), length,
            rn * kPerMm, rf * kPerMm});
}

std::string CuttingForcesObserver::checkpoint_state() const {
  const Vec2 start = steady_start_impulse_.value_or(Vec2::Zero());
  const Vec2 mid = steady_mid_impulse_.value_or(Vec2::Zero());
  const RakeSums& a = row_sums_;
  const RakeSums& b = steady_sums_;
  const double v[kStateSize] = {last_row_time_, last_row_impulse_.x(), last_row_impulse_.y(), steady_start_time_,
                                steady_start_impulse_ ? 1.0 : 0.0, start.x(), start.y(),
                                a.time, a.length_time, a.normal, a.friction, a.sliding_normal, a.safeguard_normal,
                                b.time, b.length_time, b.normal, b.friction, b.sliding_normal, b.safeguard_normal,
                                last_contact_length_,
                                steady_mid_time_, steady_mid_impulse_ ? 1.0 : 0.0, mid.x(), mid.y(),
                                a.friction_work, a.tool_friction_work, b.friction_work,
                                friction_work_known_ ? b.tool_friction_work : -1.0,
                                region_split_known_ ? 1.0 : 0.0,
                                b.edge_normal.x(), b.edge_normal.y(), b.edge_friction.x(), b.edge_friction.y(),
                                b.flank_normal.x(), b.flank_normal.y(), b.flank_friction.x(), b.flank_friction.y(),
                                b.flank_length_time,
                                tool_heat_known_ ? 1.0 : 0.0, b.tool_heat, run_tool_heat_};
  return std::string(reinterpret_cast<const char*>(v), sizeof v);
}

void CuttingForcesObserver::restore_checkpoint_state(std::string_view state) {
  // A checkpoint written before the rake-face sums (7 values) resumes with those sums at zero, one
  // written before the window's midpoint (20 values) without the steadiness check, one written before
  // the friction-work sums (24 values) without them (summary.json then leaves them out), one written before the
  // edge/flank split (28 values) without it, one written before the tool-heat sums (38 values) without those.
  // Only the steady window's split and tool heat are kept (forces.csv has neither).
  double v[kStateSize] = {};
  if (state.size() != sizeof v && state.size() != 7 * sizeof(double) && state.size() != 20 * sizeof(double) &&
      state.size() != 24 * sizeof(double) && state.size() != kStateSizeBeforeRegionSplit * sizeof(double) &&
      state.size() != kStateSizeBeforeToolHeat * sizeof(double))
    throw std::runtime_error("forces observer: checkpoint state has " + std::to_string(state.size()) +
                             " bytes, expected " + std::to_string(sizeof v));
  std::memcpy(v, state.data(), state.size());
  row_sums_ = {v[7], v[8], v[9], v[10], v[11], v[12], v[24], v[25]};
  steady_sums_ = {v[13], v[14], v[15], v[16], v[17], v[18], v[26], std::max(v[27], 0.0)};
  last_contact_length_ = v[19];
  last_row_time_ = v[0];
  last_row_impulse_ = Vec2(v[1], v[2]);
  steady_start_time_ = v[3];
  steady_start_impulse_.reset();
  if (v[4] != 0.0) steady_start_impulse_ = Vec2(v[5], v[6]);
  // An older state has no friction-work sums: they are complete only if its steady window had not begun.
  friction_work_known_ = state.size() >= kStateSizeBeforeRegionSplit * sizeof(double) ? v[27] >= 0.0 : v[4] == 0.0;
  region_split_known_ = state.size() >= kStateSizeBeforeToolHeat * sizeof(double) ? v[28] != 0.0 : v[4] == 0.0;
  // Before the tool-heat sums: the run's total is lost (unknown), the window's too if it had begun.
  tool_heat_known_ = state.size() == sizeof v && v[38] != 0.0;
  steady_sums_.tool_heat = v[39];
  run_tool_heat_ = v[40];
  steady_sums_.edge_normal = Vec2(v[29], v[30]);
  steady_sums_.edge_friction = Vec2(v[31], v[32]);
  steady_sums_.flank_normal = Vec2(v[33], v[34]);
  steady_sums_.flank_friction = Vec2(v[35], v[36]);
  steady_sums_.flank_length_time = v[37];
  steady_mid_impulse_.reset();
  if (state.size() >= 24 * sizeof(double)) {
    steady_mid_time_ = v[20];
    if (v[21] != 0.0) steady_mid_impulse_ = Vec2(v[22], v[23]);
  } else if (steady_start_impulse_ && last_row_time_ >= steady_mid_time_) {
    steady_mid_time_ = std::numeric_limits<double>::infinity();  // the midpoint has passed unrecorded
  }
}

// A conducting tool's field at the end: its hottest cell in summary.json (tool_heat.tool_temperature) and every
// cell in tool_temperature.csv, at the tool's final position.
void CuttingForcesObserver::write_tool_temperature(const Simulation& sim, nlohmann::json& summary) const {
  const RigidBodyState& tool = sim.rigid_bodies()[0];
  const BodyConduction& cells = sim.rigid_body_heat().body(0);
  CsvWriter csv(result_dir_ / "tool_temperature.csv", {"x_m", "y_m", "temperature_K", "held"});
  int hottest = -1;
  for (int c = 0; c < cells.cell_count(); ++c) {
    if (cells.kind(c) == BodyCell::Outside) continue;
    const Vec2 x = cells.cell_centre(c) + tool.displacement;
    csv.row({x.x(), x.y(), tool.temperature_field[c], cells.kind(c) == BodyCell::Held ? 1.0 : 0.0});
    if (hottest < 0 || tool.temperature_field[c] > tool.temperature_field[hottest]) hottest = c;
  }
  csv.flush();
  const RigidBodySpec& spec = sim.scene().rigid_bodies[0];
  const Vec2 at = cells.cell_centre(hottest) + tool.displacement;
  summary["tool_heat"]["tool_temperature"] = {
      {"max_K", tool.temperature_field[hottest]},
      {"max_at_m", {at.x(), at.y()}},
      {"conductivity_W_per_mK", spec.conductivity},
      {"mode", spec.volumetric_heat_capacity > 0.0 ? "transient" : "steady"},
      {"volumetric_heat_capacity_J_per_m3K", spec.volumetric_heat_capacity},
      {"heat_averaging_time_s", spec.heat_averaging_time},
      {"cells", "tool_temperature.csv"},
      {"definition",
       "the conducting tool's temperature field at the end of the run (its cells in tool_temperature.csv, at the "
       "tool's final position; held = 1 where the tool is held at tool_temperature, its back and top): steady = the "
       "field its heat input, averaged over heat_averaging_time, settles to; transient = from tool_temperature with "
       "its heat capacity"}};
}

void CuttingForcesObserver::at_finish(const Simulation& sim, nlohmann::json& summary) {
  const RigidBodyState& tool = sim.rigid_bodies()[0];
  nlohmann::json inputs = {{"material", c_.material},
                           {"cutting_speed_m_per_s", c_.cutting_speed},
                           {"cutting_speed_m_per_min", c_.cutting_speed * 60.0},
                           {"uncut_chip_thickness_m", c_.uncut_chip_thickness},
                           {"width_of_cut_m", c_.width_of_cut},
                           {"cut_length_m", c_.cut_length},
                           {"rake_angle_deg", c_.rake_angle_deg},
                           {"clearance_angle_deg", c_.clearance_angle_deg},
                           {"edge_radius_m", c_.edge_radius},
                           {"friction", c_.friction},
                           {"friction_heat_share", c_.friction_heat_share},
                           {"tool_heat_transfer_coefficient_W_per_m2K", c_.tool_heat_transfer_coefficient},
                           {"tool_temperature_K", c_.tool_temperature},
                           {"initial_temperature_K", c_.initial_temperature},
                           {"cell_size_m", sim.grid().h},
                           {"particles_per_cell", c_.particles_per_cell}};
  if (c_.tool_conductivity > 0.0) {
    inputs["tool_conductivity_W_per_mK"] = c_.tool_conductivity;
    inputs["tool_volumetric_heat_capacity_J_per_m3K"] = c_.tool_volumetric_heat_capacity;
  }
  summary["cutting"] = inputs;
  if (steady_start_impulse_ && sim.time() > steady_start_time_) {
    const Vec2 mean = (tool.impulse - *steady_start_impulse_) / (sim.time() - steady_start_time_);
    summary["mean_cutting_force_N_per_mm"] = mean.x() * kPerMm;
    summary["mean_thrust_force_N_per_mm"] = mean.y() * kPerMm;
    summary["mean_cutting_force_N"] = mean.x() * c_.width_of_cut;
    summary["mean_thrust_force_N"] = mean.y() * c_.width_of_cut;
    const RakeSums& r = steady_sums_;
    if (r.time > 0.0) {
      summary["tool_chip_contact_length_m"] = r.length_time / r.time;
      summary["tool_chip_contact_length_mm"] = 1e3 * r.length_time / r.time;
      summary["rake_face"] = {
          {"normal_force_N_per_mm", r.normal / r.time * kPerMm},
          {"friction_force_N_per_mm", r.friction / r.time * kPerMm},
          {"friction_to_normal_ratio", r.normal > 0.0 ? r.friction / r.normal : 0.0},
          {"friction_coefficient", c_.friction},
          {"sliding_share_of_normal_force", r.normal > 0.0 ? r.sliding_normal / r.normal : 0.0},
          {"safeguard_share_of_normal_force", r.normal > 0.0 ? r.safeguard_normal / r.normal : 0.0},
          {"definition",
           "steady-window means over the flat rake face (above the edge arc) of the contact impulses on the tool: "
           "normal force, friction force along the face (positive when the chip drags the tool up the face) and "
           "their ratio, which is the friction coefficient where the chip slides. Contact length: time mean of the "
           "largest distance from the tool tip, along the rake face, of a contact node (its material position), "
           "penalty-contact particle or safeguarded particle at which the contact pushed the material away from the "
           "tool"}};
      // The rest of the tool force is carried by the edge arc and the flank (clearance face).
      const Vec2 rake_force = rake_face_force_on_tool(r.normal / r.time, r.friction / r.time, c_.rake_angle_deg);
      summary["edge_and_flank"] = {
          {"cutting_force_N_per_mm", (mean.x() - rake_force.x()) * kPerMm},
          {"thrust_force_N_per_mm", (mean.y() - rake_force.y()) * kPerMm},
          {"definition",
           "steady-window mean tool force less the flat rake face's normal and friction force (rake_face), in the "
           "cutting and thrust directions: what the edge arc and the flank carry"}};
      if (region_split_known_) {
        // Where on the tool that force acts, and how much of it is the contacts' normal push (ploughing under the
        // edge, the machined surface springing back against the flank) or their friction.
        nlohmann::json& ef = summary["edge_and_flank"];
        ef["edge_arc"] = region_forces(r.edge_normal, r.edge_friction, r.time);
        ef["flank"] = region_forces(r.flank_normal, r.flank_friction, r.time);
        ef["flank"]["contact_length_m"] = r.flank_length_time / r.time;
        ef["flank"]["contact_length_mm"] = 1e3 * r.flank_length_time / r.time;
        const Vec2 rest = mean - rake_force - (r.edge_normal + r.edge_friction + r.flank_normal + r.flank_friction) / r.time;
        ef["unattributed"] = {{"cutting_force_N_per_mm", rest.x() * kPerMm}, {"thrust_force_N_per_mm", rest.y() * kPerMm}};
        ef["definition"] = ef["definition"].get<std::string>() +
            ". edge_arc and flank: the same means of the contact impulses on the tool on the edge arc and on the flank "
            "(a contact whose tool normal is within 2.6 degrees of the flank's, past the arc), each split into its "
            "normal_part (the contact's push along the tool's normal) and friction_part (along the surface); "
            "flank.contact_length: time mean of the largest distance along the flank, from the end of the arc, at "
            "which the contact pushed the material; unattributed: edge_and_flank less the two (contacts on the rake "
            "face that pulled, and any tool force outside the contact records), near zero";
      }
      // Where the frictional work is done: per unit tool travel (J/m per m = N/m), so that it compares with
      // the friction force; its ratio to the friction force is the force-weighted slip speed.
      if (friction_work_known_) {
        const double travel = r.time * c_.cutting_speed;
        summary["rake_face"]["friction_work_per_travel_N_per_mm"] = r.friction_work / travel * kPerMm;
        // Defined where the chip drags the tool up the face; at a strongly negative rake material also flows down
        // it, the net friction impulse is not the sum of the slipping parts' and the ratio means nothing (it was
        // 0 m/s beside 1.4 N/mm of frictional work at -44.9 deg).
        summary["rake_face"]["mean_slip_speed_m_per_s"] =
            r.friction > 0.0 ? nlohmann::json(r.friction_work / r.friction) : nlohmann::json(nullptr);
        summary["edge_and_flank"]["friction_work_per_travel_N_per_mm"] =
            (r.tool_friction_work - r.friction_work) / travel * kPerMm;
        summary["rake_face"]["definition"] =
            summary["rake_face"]["definition"].get<std::string>() +
            ". friction_work_per_travel: the frictional dissipation on the face over the steady window divided by "
            "the tool's travel in it (edge_and_flank: the tool's other frictional dissipation); mean_slip_speed: "
            "that dissipation divided by the friction impulse, the friction-force-weighted slip speed of the chip "
            "on the face (sticking counts as zero slip); null where the net friction does not drag the tool up the face "
            "(material flowing down a strongly negative rake face)";
      }
    }
    if (tool_heat_known_ && r.time > 0.0) {
      // The tool's share of the heat: over the steady window, against the tool's work there (mean Fc x travel).
      const double work = mean.x() * r.time * c_.cutting_speed;
      summary["tool_heat"] = {
          {"heat_into_tool_J_per_m", run_tool_heat_},
          {"steady_window_heat_into_tool_J_per_m", r.tool_heat},
          {"steady_window_share_of_tool_work", work > 0.0 ? nlohmann::json(r.tool_heat / work) : nlohmann::json(nullptr)},
          {"tool_heat_transfer_coefficient_W_per_m2K", c_.tool_heat_transfer_coefficient},
          {"friction_heat_share", c_.friction_heat_share},
          {"definition",
           "heat that flowed from the workpiece into the tool (through tool_heat_transfer_coefficient: into its heat "
           "sink at tool_temperature, or into a conducting tool's field, tool_temperature below) plus the frictional "
           "heat the workpiece does not take ((1 - friction_heat_share) of the frictional work): over the whole run, "
           "and over the steady window, there also as a share of the tool's work (mean cutting force x travel); 0 for "
           "an adiabatic tool"}};
    }
    if (!tool.temperature_field.empty()) write_tool_temperature(sim, summary);
    summary["steady_window"] = {{"start_time_s", steady_start_time_},
                                {"end_time_s", sim.time()},
                                {"start_tool_travel_m", steady_start_time_ * c_.cutting_speed},
                                {"end_tool_travel_m", -tool.displacement.x()},
                                {"definition", "mean of the contact force over the tool travel after the chip has "
                                               "formed: " + steady_window_rule_text()}};
    if (const std::string w = steady_window_warning(c_); !w.empty()) summary["steady_window"]["warning"] = w;
    if (steady_mid_impulse_ && sim.time() > steady_mid_time_) {
      // Second half's mean minus the first half's, relative to the window's mean: a force that still
      // drifts (a transient longer than the cut) shows here, not in the mean.
      const Vec2 first = (*steady_mid_impulse_ - *steady_start_impulse_) / (steady_mid_time_ - steady_start_time_);
      const Vec2 second = (tool.impulse - *steady_mid_impulse_) / (sim.time() - steady_mid_time_);
      // Relative to the force's own mean, or to half the resultant where that is larger: a force near zero (the
      // thrust of a sharp positive rake, 7 -> 8.5 N/mm beside Fc 121 N/mm) does not read as drifting (+17 %).
      const double scale = 0.5 * mean.norm();
      const auto percent = [&](double a, double b, double m) {
        const double of = std::max(std::abs(m), scale);
        return of > 0.0 ? 100.0 * (b - a) / of : 0.0;
      };
      const double fc = percent(first.x(), second.x(), mean.x()), ft = percent(first.y(), second.y(), mean.y());
      nlohmann::json drift = {
          {"cutting_force_percent", fc},
          {"thrust_force_percent", ft},
          {"split_time_s", steady_mid_time_},
          {"definition", "mean force over the second half of the steady window minus that over its first half, in % "
                         "of the window's mean of that force, or of half the mean resultant force where that is "
                         "larger (a force near zero)"}};
      if (std::max(std::abs(fc), std::abs(ft)) > kSteadyDriftWarningPercent) {
        const bool cutting = std::abs(fc) >= std::abs(ft);
        drift["warning"] = fmt::format(
            "the {} force goes from {:.3g} to {:.3g} N/mm between the halves of the steady window ({:+.0f} % of {}): "
            "the cut has not reached a steady state; a longer cut (cutting.cut_length) gives a mean that is less tied "
            "to its length",
            cutting ? "cutting" : "thrust", (cutting ? first.x() : first.y()) * kPerMm,
            (cutting ? second.x() : second.y()) * kPerMm, cutting ? fc : ft,
            std::abs(cutting ? mean.x() : mean.y()) >= scale ? "its mean" : "half the mean resultant force");
      }
      summary["steady_window"]["drift"] = drift;
    }
  } else {
    summary["mean_cutting_force_N_per_mm"] = nullptr;
    summary["mean_thrust_force_N_per_mm"] = nullptr;
    summary["steady_window"] = {{"definition", "not reached: the run ended before the steady window began"}};
  }
}

}  // namespace mpmcut
