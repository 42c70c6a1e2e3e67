// A sweep's results as one table: the finished configurations read back from configs/, the
// heat map, sensitivity and assumptions of the recommended configuration, written as
// results.json and results.csv.
#pragma once

#include <string>
#include <vector>

#include "driver/sweep_spec.h"
#include "reports/sweep_table.h"

namespace skinsim::driver {

// The quality metric that picks the recommended configuration (lower is better).
inline constexpr const char* kRecommendMetric = "flip_skin";

// Rows for the configurations of `configs` that are finished in `out_dir` (in expansion
// order; unfinished ones are left out). The heat map, sensitivity and assumptions come from
// the recommended row (reports::pareto_knee on flip_skin within the budget), else the first.
reports::SweepTable assemble_sweep_table(const SweepSpec& spec,
                                         const std::vector<SweepConfig>& configs,
                                         const std::string& out_dir);

// out_dir/results.json and out_dir/results.csv, atomically.
void write_sweep_data(const reports::SweepTable& table, const std::string& out_dir);

}  // namespace skinsim::driver
