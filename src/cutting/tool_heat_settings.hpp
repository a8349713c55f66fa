#pragma once
// The [cutting] keys of the tool's heat: their bounds and the conditions between them, in one place. The case reader
// (cutting_input.cpp), `validate`'s options and `calibrate`'s [runs] check against these, so that all three allow the
// same values and a study refuses a bad combination before any run, with the message the case reader would give.
#include <optional>
#include <string>
#include <string_view>

#include "core/range.hpp"

namespace mpmcut {

struct ToolHeatKey {
  std::string_view key;  // [cutting] key
  Range range;
};

inline constexpr ToolHeatKey kFrictionHeatShare{"friction_heat_share",
                                                Range::closed(0.0, 1.0, "", "share of the frictional heat into the workpiece")};
inline constexpr ToolHeatKey kToolHeatTransferCoefficient{
    "tool_heat_transfer_coefficient", Range::closed(0.0, 1e9, "W/(m^2 K)", "0 = adiabatic tool surface")};
inline constexpr ToolHeatKey kToolTemperature{"tool_temperature", Range::open(0.0, 1e4, "K")};
inline constexpr ToolHeatKey kToolConductivity{"tool_conductivity",
                                               Range::closed(0.0, 1e4, "W/(m K)", "0 = the tool stays at tool_temperature")};
inline constexpr ToolHeatKey kToolVolumetricHeatCapacity{
    "tool_volumetric_heat_capacity", Range::closed(0.0, 1e9, "J/(m^3 K)", "rho c of a conducting tool; 0 = a steady tool")};

// The values that the conditions between the keys look at (unset keys at their defaults).
struct ToolHeatChoice {
  double friction_heat_share = 1.0;
  double tool_heat_transfer_coefficient = 0.0;
  double tool_conductivity = 0.0;
  double tool_volumetric_heat_capacity = 0.0;
  bool conduction = true;  // heat conduction in the workpiece ([cutting] conduction)
};

// The first condition between the keys that `c` breaks: the key to blame, its value and what it allows, naming the
// other keys after `prefix` ("cutting." in a case file, "runs." in a calibration's configuration).
struct ToolHeatConflict {
  std::string_view key;
  double value = 0.0;
  std::string allowed;
};
std::optional<ToolHeatConflict> tool_heat_conflict(const ToolHeatChoice& c, std::string_view prefix = "");

}  // namespace mpmcut
