#pragma once
// Cutting and thrust forces from the tool's contact impulses: forces.csv during the run and
// the steady-state means in summary.json.
#include <cmath>
#include <filesystem>
#include <optional>

#include "core/tensor.hpp"
#include "cutting/cutting_parameters.hpp"
#include "io/csv_writer.hpp"
#include "io/run_observer.hpp"

namespace mpmcut {

// A steady window whose two halves' mean forces differ by more than this gets a warning.
inline constexpr double kSteadyDriftWarningPercent = 10.0;

// The flat rake face's force on the tool in the (cutting, thrust) directions, from its normal force
// (pushing the tool along the face's inward normal) and its friction force (positive up the face), for a
// rake angle in degrees (the face of cutting/tool_geometry.cpp). The tool force less this is what the
// edge arc and the flank carry (summary.json edge_and_flank, split into edge_arc and flank).
inline Vec2 rake_face_force_on_tool(double normal, double friction, double rake_angle_deg) {
  const double a = rake_angle_deg * 3.14159265358979323846 / 180.0;
  return normal * Vec2(std::cos(a), -std::sin(a)) + friction * Vec2(std::sin(a), std::cos(a));
}

// Sign conventions: the tool moves along -x. The cutting force F_c is the force along the
// cutting velocity needed to push the tool (= x component of the material's force on the
// tool); the thrust force F_t is normal to the machined surface, positive when the material
// pushes the tool away from the workpiece (+y). Per unit width: N/m, reported in N/mm.
class CuttingForcesObserver final : public RunObserver {
 public:
  CuttingForcesObserver(const CuttingParameters& c, const std::filesystem::path& result_dir, bool append = false);
  void after_step(const Simulation& sim) override;
  void at_history(const Simulation& sim) override;
  void flush() override { csv_.flush(); }
  void at_finish(const Simulation& sim, nlohmann::json& summary) override;
  // Restarts: the row filter's and the steady window's state (io/checkpoint.hpp).
  std::string checkpoint_state() const override;
  void restore_checkpoint_state(std::string_view state) override;

 private:
  void write_tool_temperature(const Simulation& sim, nlohmann::json& summary) const;

  CuttingParameters c_;
  std::filesystem::path result_dir_;
  CsvWriter csv_;
  double last_row_time_ = 0.0;
  Vec2 last_row_impulse_ = Vec2::Zero();
  double steady_start_time_ = 0.0;
  std::optional<Vec2> steady_start_impulse_;
  double steady_mid_time_ = 0.0;  // s: the window's midpoint, planned from the cut length, then when reached
  std::optional<Vec2> steady_mid_impulse_;
  // Rake-face contact (from the contact records of every step): sums since the last row and over
  // the steady window. Impulses on the tool in N s/m, length x time in m s.
  struct RakeSums {
    double time = 0.0;             // s
    double length_time = 0.0;      // contact length x dt, m s
    double normal = 0.0;           // normal impulse on the flat rake face, N s/m
    double friction = 0.0;         // friction impulse along the rake face (chip dragging the tool up), N s/m
    double sliding_normal = 0.0;   // part of `normal` taken at nodes that slide (Coulomb limit)
    double safeguard_normal = 0.0; // part of `normal` from the particle safeguard (no friction there)
    double friction_work = 0.0;    // frictional dissipation on the flat rake face, J/m
    double tool_friction_work = 0.0;  // ... anywhere on the tool (rake face, edge arc, flank), J/m
    // The rest of the contact, by where it acts: impulses on the tool from the normal and the friction part
    // of each contact, on the edge arc and on the flank, N s/m; the flank's contact length x dt, m s.
    Vec2 edge_normal = Vec2::Zero(), edge_friction = Vec2::Zero();
    Vec2 flank_normal = Vec2::Zero(), flank_friction = Vec2::Zero();
    double flank_length_time = 0.0;
    // Heat into the tool, J/m: conducted into its heat sink (tool_heat_transfer_coefficient), and the frictional
    // heat the workpiece does not take (friction_heat_share < 1).
    double tool_heat = 0.0;
    void add(const RakeSums& o);
  };
  RakeSums row_sums_, steady_sums_;
  bool friction_work_known_ = true;  // false after resuming a checkpoint written before the friction-work sums
  bool region_split_known_ = true;   // false after resuming one written before the edge/flank split
  bool tool_heat_known_ = true;      // false after resuming one written before the tool-heat sums
  double run_tool_heat_ = 0.0;       // heat into the tool since the start of the run, J/m
  double last_contact_length_ = 0.0;  // m, last step
};


}  // namespace mpmcut
