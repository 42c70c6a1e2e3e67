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

// The chart's legend to the right of the plot area, never over the data (VTK reserves a
// border for a legend that is not inline).
void place_legend_outside(vtkChartXY* chart, const ChartOptions& options);

// Renders the view and writes <stem>.png (and <stem>.svg if options.write_svg).
ChartFiles save_chart(vtkContextView* view, const std::string& path_stem,
                      const ChartOptions& options);

}  // namespace skinsim::reports
