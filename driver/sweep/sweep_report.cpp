#include "driver/sweep/sweep_report.h"

#include "driver/sweep/sweep_results.h"
#include "driver/sweep/sweep_thumbnails.h"
#include "reports/display_check.h"
#include "reports/html_report.h"
#include "reports/recommendation.h"

namespace skinsim::driver {

SweepReportOutcome write_sweep_report(results::SweepTable& table, const std::string& out_dir,
                                      bool charts, const ReportTruth& truth) {
  SweepReportOutcome outcome;
  if (table.rows.empty()) {
    finish_sweep_data(table, out_dir);
    remove_stale_report(out_dir);
    outcome.note = "no finished configuration: no report";
    return outcome;
  }
  std::string why;
  if (charts && !reports::charts_available(&why)) {
    outcome.note = why;
    charts = false;
  }
  reports::ReportOptions options;
  options.quality_metric = reports::recommend_metric(table.rows);
  if (options.quality_metric == "flip_frame") {
    options.metric_label =
        "FLIP mean over the frame (lower is better; the reference shows no skin)";
  }
  options.higher_is_better = false;
  options.draw_charts = charts;
  options.write_data_files = false;  // write_sweep_data writes results.json / results.csv
  options.after_recommendation = truth.section;
  options.truth_images = truth.images;
  // VTK draws the charts on this thread, on one core, for a second or two; the comparison
  // panels (two FLIP maps and their crops) and the thumbnails take the other cores meanwhile.
  // The charts read the rows, the panels only add table.panels, which the page shows and
  // results.json keeps: both are written once the panels are in.
  options.alongside_charts = [&] {
    finish_sweep_data(table, out_dir, truth.images);
    write_thumbnails(table, out_dir);
  };
  outcome.report_path = reports::write_report(table, out_dir, options);
  outcome.charts_drawn = charts;
  outcome.display_attempt_pending = reports::abandoned_display_attempts() > 0;
  return outcome;
}

}  // namespace skinsim::driver
