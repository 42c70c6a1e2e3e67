// report.html: the page a lead reads in two minutes: device and scene, one sentence per
// swept knob (knob_verdicts.h), the recommended configuration and why, the charts, a
// per-configuration table, frame and error-map thumbnails, and the model's assumptions with their
// sensitivity.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "reports/charts.h"
#include "reports/html_text.h"
#include "results/sweep_table.h"

namespace skinsim::reports {

struct ReportOptions {
  std::string title = "skinsim: skin rendering cost/quality sweep";
  std::string quality_metric = "flip_skin";  // drives the Pareto front and the recommendation
  bool higher_is_better = false;
  std::string metric_label = "FLIP mean over skin (lower is better)";
  // Trade-off charts to draw, as (series knob, order knob) pairs; a pair is drawn only if the
  // series knob has 2+ values (tradeoff_chart_worth_drawing). Default: one line
  // per LUT size across scales, one per scale across LUT sizes, one per technique.
  std::vector<std::pair<std::string, std::string>> tradeoff_groupings = {
      {"lut", "scale"}, {"scale", "lut"}, {"technique", ""}};
  bool draw_charts = true;  // false: no VTK, no display needed (the CLI's --no-charts)
  ChartOptions chart;
  bool write_data_files = true;  // also write results.json and results.csv beside the page
  // Work run on another thread while the charts draw (VTK draws on this thread, on one core),
  // and finished before the page is assembled: the sweep makes its comparison panels (which
  // the page shows) and thumbnails (which it links) there. Its exception, if any, is the
  // report's.
  std::function<void()> alongside_charts;
  // `sweep --truth` (driver/truth/truth_report.h): HTML placed after the recommendation, and per
  // group its truth image, one of the comparison slider's frames.
  std::string after_recommendation;
  std::map<std::string, std::string> truth_images;
};

// Writes dir/report.html (creating dir), and with draw_charts the chart PNG/SVG files it
// shows. Returns the path of report.html. Throws ReportError (e.g. no X display while charts
// are requested, or an unwritable directory) with the reason.
std::string write_report(const results::SweepTable& table, const std::string& dir,
                         const ReportOptions& options = {});

// Every local file that dir/report.html links to (src/href) but that does not exist, as the
// link text (URL-decoded). External links (http:, https:, mailto:, data:, #anchors) are not
// checked. Throws ReportError if dir/report.html cannot be read.
std::vector<std::string> missing_report_links(const std::string& dir);

}  // namespace skinsim::reports
