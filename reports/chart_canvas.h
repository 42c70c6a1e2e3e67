// Shared plumbing of the chart functions: an offscreen VTK context view of the requested size,
// common styling (fonts, palette, axis titles) and saving the rendered view as PNG and SVG.
// Internal to reports/; the public API is charts.h.
#pragma once

#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

#include "reports/charts.h"
#include "reports/palette.h"

class vtkAxis;
class vtkChart;
class vtkChartXY;
class vtkContextView;
class vtkPlotPoints;

namespace skinsim::reports {

// An offscreen context view of options.width x options.height on a white background.
// Throws ReportError (before any VTK window exists) if there is no X display.
vtkSmartPointer<vtkContextView> make_chart_view(const ChartOptions& options);

// Title and font sizes for a chart; axis titles (with units) for an XY chart.
void style_chart(vtkChart* chart, const std::string& title, const ChartOptions& options);
void style_axis(vtkAxis* axis, const std::string& title, const ChartOptions& options);

// A vtkDoubleArray column of the given name and values.
vtkSmartPointer<vtkDoubleArray> make_column(const std::string& name,
                                            const std::vector<double>& values);

// Custom tick marks at `positions` with text `labels` (same length).
void set_ticks(vtkAxis* axis, const std::vector<double>& positions,
               const std::vector<std::string>& labels);

// A vertical line x = at spanning [y_lo, y_hi] with the given legend text, added to `chart`.
void add_vertical_line(vtkChartXY* chart, double at, double y_lo, double y_hi,
                       const std::string& legend, const Rgb& colour);

// A line-with-markers plot of (x, y) named `name` (its legend text), circles of 10 px; a
// single point is a marker only (VTK refuses to draw a line through fewer than two points).
// `line_type` is a vtkPen line type (vtkPen::NO_PEN: markers only).
vtkPlotPoints* add_series(vtkChartXY* chart, const std::string& name, const std::vector<double>& x,
                          const std::vector<double>& y, const Rgb& colour, int line_type);

struct PointLabel {
  double x = 0.0, y = 0.0;  // a point of the chart's data
  std::string text;
};

// Texts written beside their points in the label font, none over another or over a marker at
// the points `avoid` (the chart's data): each right of its point (left where it would leave
// the plot area), moved up or down a line at a time, nearest first, until clear, with a thin
// line to its point when moved. No marker, no legend entry.
void add_point_labels(vtkChartXY* chart, const std::vector<PointLabel>& labels,
                      const std::vector<std::array<double, 2>>& avoid, const ChartOptions& options);

// A light grey horizontal bar from x_lo to x_hi at height y (a value's range), with `legend`
// shown only if `in_legend` (so that many bars take one legend entry).
void add_range_bar(vtkChartXY* chart, const std::string& legend, double x_lo, double x_hi, double y,
                   bool in_legend);

struct AxisRange {
  double lo = 0.0;
  double hi = 1.0;
  bool log = false;
};

// An axis of a cost (ms, mJ) whose values span [lo, hi]: log scale when they span more than
// 10x, so cheap candidates do not collapse into one blob next to an expensive technique; else
// linear with a margin of 6% of the span plus `pad` (in the axis's unit), never below 0.
AxisRange cost_axis_range(double lo, double hi, double pad);

// An axis of a quality metric whose values span [lo, hi]: at least 10% of the largest value,
// centred on the data, so differences of a fraction of a percent (frames 60 dB apart) stay
// flat instead of filling the chart (the charts mark which differences are visible); never
// below 0 for an error (lower is better).
AxisRange quality_axis_range(double lo, double hi, bool higher_is_better);

// The chart's legend to the right of the plot area, never over the data (VTK reserves a
// border for a legend that is not inline).
void place_legend_outside(vtkChartXY* chart, const ChartOptions& options);

// Renders the view and writes <stem>.png (and <stem>.svg if options.write_svg).
ChartFiles save_chart(vtkContextView* view, const std::string& path_stem,
                      const ChartOptions& options);

}  // namespace skinsim::reports
