// What a sweep over a sequence shows in results.csv and the report (results/sequence_summary.h
// holds the summary itself).
#pragma once

#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

// results.csv's sequence columns (frame_ms.p50 ... temporal_max_error) for a row, empty cells
// where it has no sequence; names first. Empty when no row has a sequence.
std::vector<std::string> sequence_csv_columns(const results::SweepTable& table);
std::vector<std::string> sequence_csv_cells(const results::SweepTable& table,
                                            const results::ConfigResult& row);

// The report's section on the sequence: that the recommendation used the p95 frame time, each
// configuration's frame-time distribution against the budget (an inline SVG strip), its
// temporal stability and video. "" when no row has a sequence.
std::string sequence_sweep_section(const results::SweepTable& table);

}  // namespace skinsim::reports
