// A sweep's results as one table: the finished configurations read back from configs/, the
// heat map, sensitivity and assumptions of the recommended configuration, written as
// results.json and results.csv.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/sweep/sweep_spec.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

// Rows for the configurations of `configs` that are finished in `out_dir` with the fingerprint
// run_sweep expects (`fingerprints`, SweepRunSummary::fingerprints), in expansion order;
// unfinished ones and another sweep's results stored under the same ids are left out. Each row
// is compared with its group's best configurations (sweep_comparisons.h). The heat map,
// sensitivity and assumptions come from the first group's recommended row
// (reports::recommend), else the first row. The comparison panels come with the data files
// (finish_sweep_data), which the report makes while its charts draw.
results::SweepTable assemble_sweep_table(const SweepSpec& spec,
                                         const std::vector<SweepConfig>& configs,
                                         const std::map<std::string, nlohmann::json>& fingerprints,
                                         const std::string& out_dir);

// Adds what each group's recommended configuration looks like beside the reference and the
// best (sweep_crops.h: the crops and their images in out_dir/compare/, listed in
// table.panels; with each group's truth image from `truth_images` when it has one), then
// writes the table (write_sweep_data).
void finish_sweep_data(results::SweepTable& table, const std::string& out_dir,
                       const std::map<std::string, std::string>& truth_images = {});

// Removes out_dir/report.html (a sweep directory's, so skinsim wrote it): beside tables it
// does not show (an interrupted sweep's, an empty merge's) it would show another sweep.
void remove_stale_report(const std::string& out_dir);

// out_dir/results.json and out_dir/results.csv, atomically.
void write_sweep_data(const results::SweepTable& table, const std::string& out_dir);

}  // namespace skinsim::driver
