// Charts of a sweep, drawn with VTK's 2D chart classes offscreen and saved as PNG and SVG.
// Every function checks for an X display first (see display_check.h) and throws ReportError
// naming the problem instead of letting VTK abort; files are written atomically.
#pragma once

#include <map>
#include <string>

#include "results/sweep_table.h"

namespace skinsim::reports {

struct ChartOptions {
  int width = 1600;  // pixels
  int height = 1000;
  bool write_svg = true;  // vector copy through VTK's GL2PS exporter
  int title_font_size = 30;
  int axis_title_font_size = 24;
  int label_font_size = 19;
  int legend_font_size = 19;
};

// Paths written: <stem>.png and, if requested, <stem>.svg ("" when not written).
struct ChartFiles {
  std::string png;
  std::string svg;
};

// What a trade-off chart plots: frame time (x) against one quality metric (y).
struct TradeoffSpec {
  std::string metric = "flip_skin";           // key of ConfigResult::quality
  bool higher_is_better = false;              // FLIP: lower is better; SSIM/PSNR: higher
  std::string metric_label;                   // y axis title; "" = metric name and direction
  std::string series_knob = "lut";            // one polyline per distinct value of this knob
  std::string order_knob = "scale";           // points along a polyline in this knob's order
                                              // ("" = in frame-time order)
  std::map<std::string, std::string> filter;  // only rows whose knobs have these values
  std::string title;                          // "" = generated from the knobs
};

// Whether a row is plotted on the trade-off chart of `spec`'s knobs: it has the series knob
// and the order knob, if any (a sweep leaves out of a row the knobs its technique does not
// use, and such a row has no place on a line ordered by that knob).
bool on_tradeoff_chart(const results::ConfigResult& row, const TradeoffSpec& spec);

// Frame time vs quality, one polyline per series_knob value, the Pareto front of the plotted
// rows highlighted, the recommended configuration (pareto_knee over every row of the table)
// marked if the chart plots it, and the frame budget as a vertical line labelled e.g.
// "33.3 ms (30 fps)". Throws ReportError if no row on the chart has the metric.
ChartFiles write_tradeoff_chart(const results::SweepTable& table, const TradeoffSpec& spec,
                                const std::string& path_stem, const ChartOptions& options = {});

// Horizontal stacked bars of per-pass ms, one bar per configuration, coloured by pass; each
// bar's label names the configuration's dominant bottleneck. Budget drawn as a vertical line.
ChartFiles write_pass_stack_chart(const results::SweepTable& table, const std::string& path_stem,
                                  const ChartOptions& options = {});

// Heat map of ms per tile over the frame, with a colour bar. PNG only (see ChartFiles.svg):
// Debian's libgl2ps cannot embed the raster map in SVG.
ChartFiles write_tile_cost_heatmap(const results::TileHeatmap& heatmap,
                                   const std::string& path_stem, const ChartOptions& options = {});

// The bottleneck unit of every tile, one colour per unit, with a legend bar naming them.
// PNG only, like the heat map.
// Throws ReportError if the heat map has no bottleneck entries.
ChartFiles write_tile_bottleneck_map(const results::TileHeatmap& heatmap,
                                     const std::string& path_stem,
                                     const ChartOptions& options = {});

// DRAM traffic of one configuration, one stacked bar per pass split by cause, in MB (10^6 B).
ChartFiles write_dram_by_cause_chart(const results::ConfigResult& row, const std::string& path_stem,
                                     const ChartOptions& options = {});

// The quality metric a chart plots on its y axis.
struct QualityAxis {
  std::string metric = "flip_skin";  // key of ConfigResult::quality
  bool higher_is_better = false;
  std::string label;  // the axis title
};

// Dynamic energy per frame (x, mJ) vs quality: each group's configurations (a device,
// resolution, light and framing: ConfigResult::group) in a colour of their own with the
// group's Pareto front of energy vs quality dotted through them, each energy's range (the
// profile's energy figures at their minima and maxima) as a grey bar, configurations over the
// frame budget crossed, and each group's recommended configuration (chosen by frame time and
// quality, recommendation.h) as a diamond. Throws ReportError if no row has the metric.
ChartFiles write_energy_chart(const results::SweepTable& table, const QualityAxis& quality,
                              const std::string& path_stem, const ChartOptions& options = {});

// The "33.3 ms (30 fps)" text used for the budget line.
std::string budget_label(double budget_ms);

}  // namespace skinsim::reports
