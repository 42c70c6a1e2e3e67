// results.csv: one row per configuration, for spreadsheets and scripts.
#pragma once

#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

// Column names, in order: id, label, every knob (sorted by name), frame_ms (and its _low,
// _high range), fps, dram_bytes, energy_mj (mJ per frame, and its _low, _high range), then per
// pass (in first-appearance order over the rows; same-named passes of a row merged as
// merged_passes does) "<pass>.ms" and "<pass>.bottleneck",
// then every quality metric (sorted by name). Throws ReportError if two columns collide.
std::vector<std::string> sweep_csv_columns(const results::SweepTable& table);

// The whole CSV text (RFC 4180 quoting, "\n" line ends). Cells a row lacks are empty.
std::string sweep_csv(const results::SweepTable& table);

// A number as a CSV cell: the shortest text that reads back to the same double.
std::string csv_number(double v);

// Writes sweep_csv(table) to `path` atomically.
void write_sweep_csv(const results::SweepTable& table, const std::string& path);

// Quotes a field if it holds a comma, a double quote, CR or LF (RFC 4180 section 2).
std::string csv_field(const std::string& text);

}  // namespace skinsim::reports
