#include "reports/report_charts.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <set>

namespace skinsim::reports {

namespace {

ReportFigure relative(const ChartFiles& files, const std::string& caption) {
  namespace fs = std::filesystem;
  return {fs::path(files.png).filename().string(),
          files.svg.empty() ? std::string() : fs::path(files.svg).filename().string(), caption};
}

bool has_dram_causes(const results::ConfigResult& row) {
  return std::any_of(row.passes.begin(), row.passes.end(),
                     [](const results::PassCost& p) { return !p.dram_bytes_by_cause.empty(); });
}

}  // namespace

std::optional<std::string> single_tile_bottleneck(const results::TileHeatmap& heatmap) {
  const std::vector<std::string>& units = heatmap.bottleneck;
  if (units.empty() ||
      std::adjacent_find(units.begin(), units.end(), std::not_equal_to<>()) != units.end()) {
    return std::nullopt;
  }
  return units.front();
}

bool tradeoff_chart_worth_drawing(const results::SweepTable& table, const TradeoffSpec& spec) {
  std::set<std::string> values;  // of the series knob over the rows the chart plots
  for (const results::ConfigResult& r : table.rows) {
    if (on_tradeoff_chart(r, spec) && r.quality.count(spec.metric)) {
      values.insert(knob_value(r, spec.series_knob));
    }
  }
  return values.size() >= 2;
}

std::vector<ReportFigure> draw_report_charts(const results::SweepTable& table,
                                             const std::string& dir, const ReportOptions& options,
                                             const results::ConfigResult* dram_row) {
  std::vector<ReportFigure> figures;
  const std::string stem = dir + "/";
  for (const auto& [series, order] : options.tradeoff_groupings) {
    TradeoffSpec spec;
    spec.metric = options.quality_metric;
    spec.higher_is_better = options.higher_is_better;
    spec.metric_label = options.metric_label;
    spec.series_knob = series;
    spec.order_knob = order;
    if (!tradeoff_chart_worth_drawing(table, spec)) continue;
    const std::string caption =
        "Frame time vs " + options.metric_label + ", one line per " + series +
        (order.empty() ? "" : " across " + order + " (the configurations that use both)") +
        ". Grey bars: frame-time range over the profile's uncertain figures; squares: each "
        "group's Pareto front; diamond: recommended; dashed red: frame budget.";
    figures.push_back(relative(
        write_tradeoff_chart(table, spec, stem + "tradeoff_by_" + series, options.chart), caption));
  }
  if (std::any_of(table.rows.begin(), table.rows.end(), [&](const results::ConfigResult& r) {
        return r.quality.count(options.quality_metric) > 0;
      })) {
    figures.push_back(relative(
        write_energy_chart(table,
                           {options.quality_metric, options.higher_is_better, options.metric_label},
                           stem + "energy_vs_quality", options.chart),
        "Dynamic energy per frame vs " + options.metric_label +
            ", one colour per device group; dotted: each group's Pareto front of energy vs "
            "quality; grey bars: energy range (the profile's energy figures at their minima and "
            "maxima); crosses: over the frame budget; diamond: recommended (by frame time and "
            "quality)."));
  }
  figures.push_back(relative(
      write_pass_stack_chart(table, stem + "pass_times", options.chart),
      "Modelled time of each pass per configuration; the unit in parentheses is the bottleneck "
      "of the configuration's costliest pass. Dashed red: frame budget."));
  if (table.heatmap) {
    const std::optional<std::string> one_unit = single_tile_bottleneck(*table.heatmap);
    figures.push_back(
        relative(write_tile_cost_heatmap(*table.heatmap, stem + "tile_cost", options.chart),
                 "Modelled cost per " + std::to_string(table.heatmap->tile_size) +
                     " px tile of the " + table.heatmap->pass_name + " pass over the frame." +
                     (one_unit ? " Every tile is bound by " + *one_unit + "." : "")));
    if (!table.heatmap->bottleneck.empty() && !one_unit) {
      figures.push_back(relative(
          write_tile_bottleneck_map(*table.heatmap, stem + "tile_bottleneck", options.chart),
          "Unit that bounds each tile of the " + table.heatmap->pass_name + " pass."));
    }
  }
  if (dram_row && has_dram_causes(*dram_row)) {
    figures.push_back(
        relative(write_dram_by_cause_chart(*dram_row, stem + "dram_by_cause", options.chart),
                 "DRAM traffic per pass by cause for " + dram_row->label + "."));
  }
  return figures;
}

}  // namespace skinsim::reports
