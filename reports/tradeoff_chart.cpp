// Frame time vs quality: the chart a lead uses to pick a configuration.
#include <fmt/format.h>
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkTable.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "reports/chart_canvas.h"
#include "reports/charts.h"
#include "reports/error.h"
#include "reports/knob_order.h"
#include "reports/pareto.h"
#include "reports/recommendation.h"

namespace skinsim::reports {

namespace {

bool matches(const ConfigResult& row, const std::map<std::string, std::string>& filter) {
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

// Adds a line-with-markers plot of (x, y) named `name`; a single point is a marker only
// (VTK refuses to draw a line through fewer than two points).
vtkPlotPoints* add_series(vtkChartXY* chart, const std::string& name, const std::vector<double>& x,
                          const std::vector<double>& y, const Rgb& colour, int line_type) {
  if (x.size() < 2) line_type = vtkPen::NO_PEN;
  vtkNew<vtkTable> table;
  table->AddColumn(make_column("frame_ms", x));
  table->AddColumn(make_column(name, y));
  auto* plot = vtkPlotPoints::SafeDownCast(
      chart->AddPlot(line_type == vtkPen::NO_PEN ? vtkChart::POINTS : vtkChart::LINE));
  plot->SetInputData(table, 0, 1);
  plot->SetColor(colour[0], colour[1], colour[2], 255);
  plot->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  plot->SetMarkerSize(10.0);
  plot->SetWidth(2.5);
  plot->GetPen()->SetLineType(line_type);
  return plot;
}

}  // namespace

bool on_tradeoff_chart(const ConfigResult& row, const TradeoffSpec& spec) {
  return !knob_value(row, spec.series_knob).empty() &&
         (spec.order_knob.empty() || !knob_value(row, spec.order_knob).empty());
}

std::string budget_label(double budget_ms) {
  return fmt::format("{:.1f} ms ({:.0f} fps)", budget_ms, 1000.0 / budget_ms);
}

ChartFiles write_tradeoff_chart(const SweepTable& table, const TradeoffSpec& spec,
                                const std::string& path_stem, const ChartOptions& options) {
  std::vector<ConfigResult> rows;
  for (const ConfigResult& r : table.rows) {
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
  std::set<std::string, decltype(&knob_value_less)> series(&knob_value_less);
  for (const ConfigResult& r : rows) series.insert(knob_value(r, spec.series_knob));

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, spec.title.empty() ? default_title(spec) : spec.title, options);

  double y_lo = INFINITY, y_hi = -INFINITY, x_lo = table.budget_ms, x_hi = table.budget_ms;
  std::size_t colour = 0;
  for (const std::string& value : series) {
    std::vector<const ConfigResult*> members;
    for (const ConfigResult& r : rows) {
      if (knob_value(r, spec.series_knob) == value && r.quality.count(spec.metric)) {
        members.push_back(&r);
      }
    }
    std::stable_sort(members.begin(), members.end(), [&](const auto* a, const auto* b) {
      if (spec.order_knob.empty()) return a->frame_ms < b->frame_ms;
      return knob_value_less(knob_value(*a, spec.order_knob), knob_value(*b, spec.order_knob));
    });
    std::vector<double> x, y;
    for (const ConfigResult* r : members) {
      x.push_back(r->frame_ms);
      y.push_back(r->quality.at(spec.metric));
      y_lo = std::min(y_lo, y.back());
      y_hi = std::max(y_hi, y.back());
      x_lo = std::min(x_lo, x.back());
      x_hi = std::max(x_hi, x.back());
    }
    const std::string name = spec.series_knob + " = " + value;
    add_series(chart, name, x, y, palette_colour(colour++), vtkPen::SOLID_LINE);
  }

  std::vector<double> front_x, front_y;
  for (std::size_t i : pareto_front(rows, spec.metric, spec.higher_is_better)) {
    front_x.push_back(rows[i].frame_ms);
    front_y.push_back(rows[i].quality.at(spec.metric));
  }
  vtkPlotPoints* front =
      add_series(chart, "Pareto front", front_x, front_y, {20, 20, 20}, vtkPen::DOT_LINE);
  front->SetMarkerStyle(vtkPlotPoints::SQUARE);
  front->SetMarkerSize(16.0);
  front->SetWidth(3.0);

  // The report's recommendations (one per group of comparable configurations), marked where
  // this chart plots them. Their rule needs a lower-is-better metric.
  if (!spec.higher_is_better) {
    const std::vector<Recommendation> recommendations = recommend(table, spec.metric);
    for (const Recommendation& rec : recommendations) {
      if (!rec.chosen) continue;
      const ConfigResult& r = table.rows[*rec.chosen];
      if (!matches(r, spec.filter) || !on_tradeoff_chart(r, spec)) continue;
      const std::string name = recommendations.size() > 1 ? rec.group + ": " + r.label : r.label;
      vtkPlotPoints* mark = add_series(chart, "recommended: " + name, {r.frame_ms},
                                       {r.quality.at(spec.metric)}, {200, 0, 0}, vtkPen::NO_PEN);
      mark->SetMarkerStyle(vtkPlotPoints::DIAMOND);
      mark->SetMarkerSize(26.0);
    }
  }

  const double pad = y_hi > y_lo ? 0.08 * (y_hi - y_lo) : std::max(1e-3, 0.05 * std::abs(y_hi));
  y_lo -= pad;
  y_hi += pad;
  add_vertical_line(chart, table.budget_ms, y_lo, y_hi, "budget " + budget_label(table.budget_ms),
                    {200, 0, 0});

  vtkAxis* x_axis = chart->GetAxis(vtkAxis::BOTTOM);
  style_axis(x_axis, "frame time (ms)", options);
  x_axis->SetBehavior(vtkAxis::FIXED);
  const double x_pad = 0.06 * (x_hi - x_lo) + 0.5;
  x_axis->SetRange(std::max(0.0, x_lo - x_pad), x_hi + x_pad);
  vtkAxis* y_axis = chart->GetAxis(vtkAxis::LEFT);
  style_axis(y_axis, spec.metric_label.empty() ? default_metric_label(spec) : spec.metric_label,
             options);
  y_axis->SetBehavior(vtkAxis::FIXED);
  y_axis->SetRange(y_lo, y_hi);

  chart->SetShowLegend(true);
  chart->GetLegend()->SetLabelSize(options.legend_font_size);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(spec.higher_is_better ? vtkChartLegend::BOTTOM
                                                                 : vtkChartLegend::TOP);
  return save_chart(view, path_stem, options);
}

}  // namespace skinsim::reports
