// The set of charts report.html shows, drawn into the report directory.
#pragma once

#include <string>
#include <vector>

#include "reports/html_report.h"

namespace skinsim::reports {

struct ReportFigure {
  std::string png;  // file name relative to the report directory
  std::string svg;  // "" if not written
  std::string caption;
};

// Draws the charts that fit the data (trade-offs for each grouping whose series knob has two or
// more values, or one value and an order knob with two or more, energy vs quality if a row has
// the quality metric, per-pass bars, tile maps if the sweep has a heat map, DRAM by cause for
// `dram_row` if it has causes) into `dir`. Throws ReportError if charts cannot be drawn (e.g. no X
// display).
std::vector<ReportFigure> draw_report_charts(const results::SweepTable& table,
                                             const std::string& dir, const ReportOptions& options,
                                             const results::ConfigResult* dram_row);

}  // namespace skinsim::reports
