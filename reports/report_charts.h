// The set of charts report.html shows, drawn into the report directory.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "reports/html_report.h"

namespace skinsim::reports {

struct ReportFigure {
  std::string png;  // file name relative to the report directory
  std::string svg;  // "" if not written
  std::string caption;
};

// Whether the report draws the trade-off chart of `spec`'s knobs: its series knob takes two or
// more values over the rows it plots. A knob swept over one value makes a chart of one line
// (one point per line when it is the order knob of another chart) that repeats, under the
// wrong name, the chart of the knob that was swept; one technique in frame-time order would
// join unrelated configurations.
bool tradeoff_chart_worth_drawing(const results::SweepTable& table, const TradeoffSpec& spec);

// The one unit that bounds every tile of the heat map, if there is one (then the report
// names it in the cost map's caption instead of drawing a map of one colour); nullopt if the
// tiles differ or the map has no bottleneck entries.
std::optional<std::string> single_tile_bottleneck(const results::TileHeatmap& heatmap);

// Draws the charts that fit the data (trade-offs for each grouping that is worth drawing, energy vs
// quality if a row has the quality metric, per-pass bars, tile maps if the sweep has a heat map
// (the bottleneck map only if its tiles differ), DRAM by cause for `dram_row` if it has causes)
// into `dir`. Throws ReportError if charts cannot be drawn (e.g. no X display).
std::vector<ReportFigure> draw_report_charts(const results::SweepTable& table,
                                             const std::string& dir, const ReportOptions& options,
                                             const results::ConfigResult* dram_row);

}  // namespace skinsim::reports
