// Where each configuration's frame time goes: stacked per-pass bars.
#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkColorSeries.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkPlotBar.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>

#include "reports/chart_canvas.h"
#include "reports/charts.h"
#include "reports/error.h"

namespace skinsim::reports {

ChartFiles write_pass_stack_chart(const results::SweepTable& table, const std::string& path_stem,
                                  const ChartOptions& options) {
  if (table.rows.empty()) throw ReportError("pass chart " + path_stem + ": the sweep has no rows");
  std::vector<std::vector<results::PassCost>> merged;
  for (const results::ConfigResult& r : table.rows) merged.push_back(merged_passes(r));
  const std::vector<std::string> names = pass_order(table);
  if (names.empty()) throw ReportError("pass chart " + path_stem + ": no row has passes");

  // Row 0 at the top: bar i sits at y = n - 1 - i.
  const std::size_t n = table.rows.size();
  vtkNew<vtkTable> data;
  std::vector<double> position(n);
  std::vector<std::string> labels(n);
  double x_hi = table.budget_ms;
  for (std::size_t i = 0; i < n; ++i) {
    position[i] = static_cast<double>(n - 1 - i);
    const std::string bottleneck = dominant_bottleneck(table.rows[i]);
    labels[i] = (table.rows[i].label.empty() ? table.rows[i].id : table.rows[i].label) + " (" +
                (bottleneck.empty() ? "?" : bottleneck) + ")";
    double total = 0.0;
    for (const results::PassCost& p : merged[i]) total += p.ms;
    x_hi = std::max(x_hi, total);
  }
  data->AddColumn(make_column("position", position));
  for (const std::string& name : names) {
    std::vector<double> ms(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      for (const results::PassCost& p : merged[i]) {
        if (p.name == name) ms[i] = p.ms;
      }
    }
    data->AddColumn(make_column(name, ms));
  }

  auto view = make_chart_view(options);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  style_chart(chart, "Frame time by pass; (unit) = bottleneck of the costliest pass", options);

  auto* bars = vtkPlotBar::SafeDownCast(chart->AddPlot(vtkChart::BAR));
  bars->SetOrientation(vtkPlotBar::HORIZONTAL);
  bars->SetInputData(data, "position", names[0]);
  for (std::size_t k = 1; k < names.size(); ++k) {
    bars->SetInputArray(static_cast<int>(k + 1), names[k]);  // extra y arrays stack
  }
  vtkNew<vtkColorSeries> colours;
  colours->ClearColors();
  vtkNew<vtkStringArray> legend;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Rgb c = pass_colour(names[k], names);
    colours->AddColor(vtkColor3ub(c[0], c[1], c[2]));
    legend->InsertNextValue(names[k]);
  }
  bars->SetColorSeries(colours);
  bars->SetLabels(legend);
  bars->SetWidth(0.7f);
  // The legend lists only the bar plot's series, so the budget line is named in the axis title.
  add_vertical_line(chart, table.budget_ms, -0.6, static_cast<double>(n) - 0.4,
                    "budget " + budget_label(table.budget_ms), {200, 0, 0});

  vtkAxis* value_axis = chart->GetAxis(vtkAxis::BOTTOM);
  style_axis(value_axis,
             "frame time (ms); dashed red line: budget " + budget_label(table.budget_ms), options);
  value_axis->SetBehavior(vtkAxis::FIXED);
  value_axis->SetRange(0.0, x_hi * 1.05);
  vtkAxis* config_axis = chart->GetAxis(vtkAxis::LEFT);
  style_axis(config_axis, "", options);
  config_axis->SetBehavior(vtkAxis::FIXED);
  config_axis->SetRange(-0.6, static_cast<double>(n) - 0.4);
  set_ticks(config_axis, position, labels);
  config_axis->SetGridVisible(false);

  place_legend_outside(chart, options);
  return save_chart(view, path_stem, options);
}

}  // namespace skinsim::reports
