#pragma once
// Process parameters of an orthogonal cut, as a machining engineer states them. The cutting
// preset turns them into a Scene (cutting_scene.hpp); the solver never sees them.
#include <string>

namespace mpmcut {

struct CuttingParameters {
  std::string material;              // a [[material]] of the case or a library set name
  double cutting_speed = 0.0;        // V, m/s (the tool moves at -V along x)
  double uncut_chip_thickness = 0.0; // t0 (feed), m
  double width_of_cut = 1e-3;        // b, m: converts forces per unit width into N
  double cut_length = 0.0;           // tool travel, m
  double workpiece_length = 0.0;     // m; 0 = cut_length + 4 t0 + 10 cells
  double workpiece_height = 0.0;     // m; 0 = 4 t0
  double rake_angle_deg = 0.0;       // alpha, degrees (positive: sharper tool)
  double clearance_angle_deg = 11.0; // gamma, degrees
  double edge_radius = 5e-6;         // r, m
  double tool_length = 0.0;          // along the machined surface, m; 0 = max(3 t0, 0.3 mm)
  double tool_height = 0.0;          // above the cutting edge, m; 0 = max(4 t0, 0.4 mm)
  double friction = 0.35;            // Coulomb mu, tool-chip, -
  double friction_heat_share = 1.0;  // share of the frictional heat that goes into the workpiece (rest: tool), -
  double tool_heat_transfer_coefficient = 0.0;  // W/(m^2 K) tool-workpiece; 0 = adiabatic tool surface
  double tool_temperature = 298.0;   // K, the tool's (uniform, constant; a conducting tool's start and held faces); [cutting] default: initial_temperature
  // A conducting tool (docs/cutting.md "Contact" item 7): its conductivity, W/(m K) (0 = the tool stays at
  // tool_temperature), and its volumetric heat capacity, J/(m^3 K) (0 = a steady tool: the field its heat input,
  // averaged over kSteadyToolAveragingFraction of the cut, settles to; > 0 = transient from tool_temperature).
  double tool_conductivity = 0.0;
  double tool_volumetric_heat_capacity = 0.0;
  double initial_temperature = 298.0;// K
  double cell_size = 0.0;            // h, m; 0 = t0 / 10
  int particles_per_cell = 2;        // per direction
  bool conduction = true;            // heat conduction in the workpiece
  double chip_room = 0.0;            // free space above the workpiece for the chip, m; 0 = automatic
  int snapshots = 20;                // VTU snapshots over the cut
  // Mass scaling of the workpiece's inertia (docs/mass_scaling.md): 0 = automatic (the factor that
  // brings the inertia number rho f V^2 / A up to mass_scaling_inertia_number, 1 above the speed
  // where that is already reached), else the factor itself (1 = off).
  double mass_scaling = 0.0;                  // f, -
  double mass_scaling_inertia_number = 2e-3;  // target of the automatic factor, -
  double steady_start_fraction = 0.4;// steady window starts after this fraction of the cut (and after min(kEntryTravelT0 t0, 0.6 cut))

  bool operator==(const CuttingParameters&) const = default;
};

// The entry transient, in uncut chip thicknesses of tool travel: while the tool enters the workpiece
// the first chip forms from its edge. The force's steady window starts after it at the earliest
// (steady_window_start_travel) and the chip cut during it is left out of the segmentation metrics
// (ChipThresholds::entry_travel_t0, docs/analysis.md).
inline constexpr double kEntryTravelT0 = 3.0;

// A steady conducting tool follows its heat input averaged over this fraction of the cut's duration: long against
// a conduction update (the exchange stays stable), short against the entry transient (the steady window, from 0.4
// of the cut, sees the tool of the cut's own heat input).
inline constexpr double kSteadyToolAveragingFraction = 0.05;

}  // namespace mpmcut
