#pragma once
// The report of `mpmcut validate`: every reported condition against its measurement, as validation.md (goals,
// errors, speed trends, assumptions, the comparison) and CSV tables that the plots (tools/plot_validation.py) read.

#include <cstddef>
#include <filesystem>
#include <vector>

#include "app/validation_conditions.hpp"

namespace mpmcut::validation {

// What the report says of this invocation besides the conditions.
struct ReportContext {
  const Options& options;
  const ConditionRunSettings& settings;
  const ForceData& data;
  std::filesystem::path out;
  std::size_t runs_launched = 0;  // runs this invocation started
  bool completed = true;          // false: interrupted by a stop signal
};

// Writes validation_runs.csv, validation_measured.csv, validation.csv, validation_errors.csv, validation_trends.csv,
// validation_goals.csv and validation.md into context.out, over the reported conditions (Condition::origin set).
void write_validation_report(const std::vector<Condition>& conditions, const ReportContext& context);

}  // namespace mpmcut::validation
