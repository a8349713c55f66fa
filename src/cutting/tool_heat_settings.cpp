#include "cutting/tool_heat_settings.hpp"

#include <fmt/format.h>

namespace mpmcut {

std::optional<ToolHeatConflict> tool_heat_conflict(const ToolHeatChoice& c, std::string_view prefix) {
  const auto key = [&](const ToolHeatKey& k) { return fmt::format("{}{}", prefix, k.key); };
  if (c.tool_heat_transfer_coefficient > 0.0 && !c.conduction)
    return ToolHeatConflict{kToolHeatTransferCoefficient.key, c.tool_heat_transfer_coefficient,
                            fmt::format("0 unless {}conduction = true", prefix)};
  if (c.tool_conductivity > 0.0) {
    if (!(c.tool_heat_transfer_coefficient > 0.0))
      return ToolHeatConflict{kToolConductivity.key, c.tool_conductivity,
                              fmt::format("0 unless {} > 0 (the heat enters the tool through it)",
                                          key(kToolHeatTransferCoefficient))};
    // A conducting tool takes its part of the frictional heat by conduction from the workpiece's surface: a share
    // given to it as well would count it twice.
    if (c.friction_heat_share != 1.0)
      return ToolHeatConflict{kToolConductivity.key, c.tool_conductivity,
                              fmt::format("0 unless {} = 1 (a conducting tool takes its part of the frictional heat by "
                                          "conduction from the workpiece's surface)",
                                          key(kFrictionHeatShare))};
  } else if (c.tool_volumetric_heat_capacity != 0.0) {
    return ToolHeatConflict{kToolVolumetricHeatCapacity.key, c.tool_volumetric_heat_capacity,
                            fmt::format("0 unless {} > 0 (only a conducting tool stores heat)", key(kToolConductivity))};
  }
  return std::nullopt;
}

}  // namespace mpmcut
