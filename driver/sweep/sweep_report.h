// report.html and the VTK charts of a sweep (reports::write_report), or, when charts cannot
// be drawn (no X display, or a build without VTK), the reason.
#pragma once

#include <map>
#include <string>

#include "results/sweep_table.h"

namespace skinsim::driver {

struct SweepReportOutcome {
  std::string report_path;  // "" when no report was written
  bool charts_drawn = false;
  std::string note;  // why charts or the report are missing ("" if nothing is)
  // An attempt to open a display that never answered is still inside Xlib: the process must
  // end with std::_Exit, not by returning from main (reports::abandoned_display_attempts).
  bool display_attempt_pending = false;
};

// What `sweep --truth` adds to the page (driver/truth/truth_report.h makes it): its section, placed
// after the recommendation, and per group the truth image the slider and crops show.
struct ReportTruth {
  std::string section;
  std::map<std::string, std::string> images;
};

// Adds the comparison panels to `table` and writes results.json and results.csv
// (finish_sweep_data), the thumbnails and out_dir/report.html, with the charts when
// `charts` is set and an X display is available; without a display the report is written
// without charts and `note` says how to get them (run under `xvfb-run -a` or pass
// --no-charts). Throws reports::ReportError on write failures.
SweepReportOutcome write_sweep_report(results::SweepTable& table, const std::string& out_dir,
                                      bool charts, const ReportTruth& truth = {});

}  // namespace skinsim::driver
