// results.json on disk: the sweep's table (results/sweep_table.h) and the findings the reports
// draw from its rows (knob_verdicts.h), which read_sweep_json skips.
#pragma once

#include <string>

#include "results/sweep_table.h"

namespace skinsim::reports {

// Validates the table and writes it atomically; throws ResultsError naming the field at fault.
void write_sweep_json(const results::SweepTable& table, const std::string& path);

}  // namespace skinsim::reports
