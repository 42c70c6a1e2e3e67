// Frame time vs quality: the chart a lead uses to pick a configuration.
#include <fmt/format.h>
#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlotPoints.h>
#include <vtkTable.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "reports/chart_canvas.h"
#include "reports/charts.h"
#include "reports/error.h"
#include "reports/knob_order.h"
#include "reports/pareto.h"
#include "reports/recommendation.h"

namespace skinsim::reports {

namespace {

bool matches(const results::ConfigResult& row, const std::map<std::string, std::string>& filter) {
  return std::all_of(filter.begin(), filter.end(),
                     [&](const auto& kv) { return knob_value(row, kv.first) == kv.second; });
}

std::string default_metric_label(const TradeoffSpec& spec) {
  return spec.metric + (spec.higher_is_better ? " (higher is better)" : " (lower is better)");
}

std::string default_title(const TradeoffSpec& spec) {
  std::string title = "Frame time vs " + spec.metric + ": one line per " + spec.series_knob;
  if (!spec.order_knob.empty()) title += " across " + spec.order_knob;
  return title;
}

// Rows of the group that do not differ visibly from its best configuration (ConfigResult::
// vs_best; the best itself included).
bool ties_with_best(const results::ConfigResult& r) {
  return r.vs_best && !r.vs_best->visible;
}

// ---------------------------------------------------------------- what the chart shows

// The rows the chart plots: those the filter keeps that have both knobs and the metric.
std::vector<results::ConfigResult> chart_rows(const results::SweepTable& table,
                                              const TradeoffSpec& spec,
                                              const std::string& path_stem) {
  std::vector<results::ConfigResult> rows;
  for (const results::ConfigResult& r : table.rows) {
    if (matches(r, spec.filter) && on_tradeoff_chart(r, spec) && r.quality.count(spec.metric)) {
      rows.push_back(r);
    }
  }
  if (rows.empty()) {
    throw ReportError(
        "trade-off chart " + path_stem + ": no configuration with knob " + spec.series_knob +
        (spec.order_knob.empty() ? "" : " and " + spec.order_knob) + " has quality metric '" +
        spec.metric + "'" + (spec.filter.empty() ? "" : " (after the knob filter)"));
  }
  return rows;
}

// The rows' groups, in order of first appearance. Lines join configurations of one group
// only: a millisecond on one device or framing is not one on another (recommendation.h).
std::vector<std::string> chart_groups(const std::vector<results::ConfigResult>& rows) {
  std::vector<std::string> groups;
  for (const results::ConfigResult& r : rows) {
    if (std::find(groups.begin(), groups.end(), r.group) == groups.end()) groups.push_back(r.group);
  }
  return groups;
}

struct Axes {
  bool log_x = false;
  double x_min = 0.0, x_max = 0.0, y_lo = 0.0, y_hi = 0.0;
};

Axes chart_axes(const std::vector<results::ConfigResult>& rows, const TradeoffSpec& spec,
                double budget_ms) {
  double y_lo = INFINITY, y_hi = -INFINITY, x_lo = budget_ms, x_hi = budget_ms;
  for (const results::ConfigResult& r : rows) {
    y_lo = std::min(y_lo, r.quality.at(spec.metric));
    y_hi = std::max(y_hi, r.quality.at(spec.metric));
    x_lo = std::min(x_lo, r.frame_ms_low);
    x_hi = std::max(x_hi, r.frame_ms_high);
  }
  Axes a;
  const AxisRange x_range = cost_axis_range(x_lo, x_hi, 0.5);
  a.log_x = x_range.log;
  a.x_min = x_range.lo;
  a.x_max = x_range.hi;
  const AxisRange y_range = quality_axis_range(y_lo, y_hi, spec.higher_is_better);
  a.y_lo = y_range.lo;
  a.y_hi = y_range.hi;
  return a;
}

struct Series {
  std::string name;
  std::vector<double> x, y;  // frame ms, metric
  std::string value;         // of the series knob: the line's label on the chart
};

// One line per group and value of the series knob, its points in order of the order knob
// (or of frame time without one).
std::vector<Series> knob_series(const std::vector<results::ConfigResult>& rows,
                                const std::vector<std::string>& groups, const TradeoffSpec& spec) {
  std::set<std::string, decltype(&knob_value_less)> values(&knob_value_less);
  for (const results::ConfigResult& r : rows) values.insert(knob_value(r, spec.series_knob));
  std::vector<Series> out;
  for (const std::string& group : groups) {
    for (const std::string& value : values) {
      std::vector<const results::ConfigResult*> members;
      for (const results::ConfigResult& r : rows) {
        if (r.group == group && knob_value(r, spec.series_knob) == value) members.push_back(&r);
      }
      if (members.empty()) continue;
      std::stable_sort(members.begin(), members.end(), [&](const auto* a, const auto* b) {
        if (spec.order_knob.empty()) return a->frame_ms < b->frame_ms;
        return knob_value_less(knob_value(*a, spec.order_knob), knob_value(*b, spec.order_knob));
      });
      Series s{
          (groups.size() > 1 ? group + ": " : std::string()) + spec.series_knob + " = " + value,
          {},
          {},
          value};
      for (const results::ConfigResult* r : members) {
        s.x.push_back(r->frame_ms);
        s.y.push_back(r->quality.at(spec.metric));
      }
      out.push_back(std::move(s));
    }
  }
  return out;
}

// Configurations that differ visibly from their group's best.
Series visibly_different(const std::vector<results::ConfigResult>& rows, const TradeoffSpec& spec) {
  Series s{"visibly different from the best", {}, {}, {}};
  for (const results::ConfigResult& r : rows) {
    if (r.vs_best && r.vs_best->visible) {
      s.x.push_back(r.frame_ms);
      s.y.push_back(r.quality.at(spec.metric));
    }
  }
  return s;
}

// Each group's Pareto front: a front through two devices' points would trade one device's
// milliseconds for another's (recommendation.h).
std::vector<Series> pareto_fronts(const std::vector<results::ConfigResult>& rows,
                                  const std::vector<std::string>& groups,
                                  const TradeoffSpec& spec) {
  std::vector<Series> fronts;
  for (const std::string& group : groups) {
    std::vector<results::ConfigResult> members;
    std::copy_if(rows.begin(), rows.end(), std::back_inserter(members),
                 [&](const results::ConfigResult& r) { return r.group == group; });
    Series s{"Pareto front", {}, {}, {}};
    for (std::size_t i : pareto_front(members, spec.metric, spec.higher_is_better)) {
      s.x.push_back(members[i].frame_ms);
      s.y.push_back(members[i].quality.at(spec.metric));
    }
    fronts.push_back(std::move(s));
  }
  return fronts;
}

// ---------------------------------------------------------------- drawing

// Behind the lines: per group, the band of configurations that do not differ visibly from
// the group's best.
void draw_tie_bands(vtkChartXY* chart, const std::vector<results::ConfigResult>& rows,
                    const std::vector<std::string>& groups, const TradeoffSpec& spec,
                    const Axes& axes, const ChartOptions& options) {
  for (const std::string& group : groups) {
    double lo = INFINITY, hi = -INFINITY;
    for (const results::ConfigResult& r : rows) {
      if (r.group != group || !ties_with_best(r)) continue;
      lo = std::min(lo, r.quality.at(spec.metric));
      hi = std::max(hi, r.quality.at(spec.metric));
    }
    if (lo > hi) continue;
    // A wide translucent line over the chart's width, as tall as the rows' values spread (in
    // pixels of the plot area, about 80% of the chart's height) and at least 10 px.
    const double plot_px = 0.8 * options.height;
    const double thickness = std::max(10.0, (hi - lo) / (axes.y_hi - axes.y_lo) * plot_px);
    vtkPlotPoints* band = add_series(
        chart,
        (groups.size() > 1 ? group + ": " : std::string()) + "not visibly different from the best",
        {axes.x_min, axes.x_max}, {(lo + hi) / 2.0, (lo + hi) / 2.0}, {89, 161, 79},
        vtkPen::SOLID_LINE);
    band->SetColor(89, 161, 79, 70);
    band->SetWidth(static_cast<float>(thickness));
    band->SetMarkerStyle(vtkPlotPoints::NONE);
  }
}

// Frame time ranges over the profile's uncertain figures, as horizontal error bars.
void draw_time_ranges(vtkChartXY* chart, const std::vector<results::ConfigResult>& rows,
                      const TradeoffSpec& spec) {
  bool first_range = true;
  for (const results::ConfigResult& r : rows) {
    const double y = r.quality.at(spec.metric);
    add_range_bar(chart, "frame ms range", r.frame_ms_low, r.frame_ms_high, y, first_range);
    first_range = false;
  }
}

// The report's recommendations (one per group of comparable configurations), marked where
// this chart plots them, under one legend entry (the report names them). Their rule needs a
// lower-is-better metric.
void draw_recommendations(vtkChartXY* chart, const results::SweepTable& table,
                          const TradeoffSpec& spec) {
  if (spec.higher_is_better) return;
  bool first = true;
  for (const Recommendation& rec : recommend(table, spec.metric)) {
    if (!rec.chosen) continue;
    const results::ConfigResult& r = table.rows[*rec.chosen];
    if (!matches(r, spec.filter) || !on_tradeoff_chart(r, spec)) continue;
    vtkPlotPoints* mark = add_series(chart, "recommended", {r.frame_ms},
                                     {r.quality.at(spec.metric)}, {200, 0, 0}, vtkPen::NO_PEN);
    mark->SetMarkerStyle(vtkPlotPoints::DIAMOND);
    mark->SetMarkerSize(26.0);
    mark->SetLegendVisibility(first);
    first = false;
  }
}

void style_axes(vtkChartXY* chart, const TradeoffSpec& spec, const Axes& axes,
                const ChartOptions& options) {
  vtkAxis* x_axis = chart->GetAxis(vtkAxis::BOTTOM);
  style_axis(x_axis, axes.log_x ? "frame time (ms, log scale)" : "frame time (ms)", options);
  x_axis->SetBehavior(vtkAxis::FIXED);
  x_axis->SetLogScale(axes.log_x);
  x_axis->SetRange(axes.x_min, axes.x_max);
  vtkAxis* y_axis = chart->GetAxis(vtkAxis::LEFT);
  style_axis(y_axis, spec.metric_label.empty() ? default_metric_label(spec) : spec.metric_label,
             options);
  y_axis->SetBehavior(vtkAxis::FIXED);
  y_axis->SetRange(axes.y_lo, axes.y_hi);
}

}  // namespace

bool on_tradeoff_chart(const results::ConfigResult& row, const TradeoffSpec& spec) {
  return !knob_value(row, spec.series_knob).empty() &&
         (spec.order_knob.empty() || !knob_value(row, spec.order_knob).empty());
}

std::string budget_label(double budget_ms) {
  return fmt::format("{:.1f} ms ({:.0f} fps)", budget_ms, 1000.0 / budget_ms);
}

ChartFiles write_tradeoff_chart(const results::SweepTable& table, const TradeoffSpec& spec,
                                const std::string& path_stem, const ChartOptions& options) {
  const std::vector<results::ConfigResult> rows = chart_rows(table, spec, path_stem);
  const std::vector<std::string> groups = chart_groups(rows);
  const Axes axes = chart_axes(rows, spec, table.budget_ms);
  const std::vector<Series> lines = knob_series(rows, groups, spec);
  const Series visible = visibly_different(rows, spec);
  const std::vector<Series> fronts = pareto_fronts(rows, groups, spec);

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, spec.title.empty() ? default_title(spec) : spec.title, options);
  draw_tie_bands(chart, rows, groups, spec, axes, options);
  draw_time_ranges(chart, rows, spec);
  // The front's squares under the lines, larger than their points: a configuration on the
  // front shows its own colour framed in black instead of hiding under the square.
  for (const Series& front : fronts) {
    vtkPlotPoints* pareto =
        add_series(chart, front.name, front.x, front.y, {20, 20, 20}, vtkPen::DOT_LINE);
    pareto->SetMarkerStyle(vtkPlotPoints::SQUARE);
    pareto->SetMarkerSize(22.0);
    pareto->SetWidth(3.0);
    pareto->SetLegendVisibility(&front == &fronts.front());
  }
  std::size_t colour = 0;
  for (const Series& s : lines) {
    add_series(chart, s.name, s.x, s.y, palette_colour(colour++), vtkPen::SOLID_LINE);
  }
  if (!visible.x.empty()) {
    vtkPlotPoints* cross =
        add_series(chart, visible.name, visible.x, visible.y, {20, 20, 20}, vtkPen::NO_PEN);
    cross->SetMarkerStyle(vtkPlotPoints::CROSS);
    cross->SetMarkerSize(18.0);
  }
  draw_recommendations(chart, table, spec);
  // Each line named at its last point, over everything else: the legend alone leaves a reader
  // matching nine colours to points.
  std::vector<PointLabel> labels;
  std::vector<std::array<double, 2>> points;
  for (const Series& s : lines) {
    labels.push_back({s.x.back(), s.y.back(), s.value});  // right of the line's other points
    for (std::size_t i = 0; i < s.x.size(); ++i) points.push_back({s.x[i], s.y[i]});
  }
  add_point_labels(chart, labels, points, options);
  add_vertical_line(chart, table.budget_ms, axes.y_lo, axes.y_hi,
                    "budget " + budget_label(table.budget_ms), {200, 0, 0});
  style_axes(chart, spec, axes, options);
  place_legend_outside(chart, options);
  return save_chart(view, path_stem, options);
}

}  // namespace skinsim::reports
