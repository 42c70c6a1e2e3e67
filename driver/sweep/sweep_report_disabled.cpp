// write_sweep_report for builds configured with -DSKINSIM_BUILD_REPORTS=OFF (no VTK).
#include "driver/sweep/sweep_report.h"
#include "driver/sweep/sweep_results.h"

namespace skinsim::driver {

SweepReportOutcome write_sweep_report(results::SweepTable& table, const std::string& out_dir, bool,
                                      const ReportTruth& truth) {
  finish_sweep_data(table, out_dir, truth.images);
  // A report.html from a build with the report library would not show these tables.
  remove_stale_report(out_dir);
  SweepReportOutcome outcome;
  outcome.note =
      "this build has no charts or report.html (configured with -DSKINSIM_BUILD_REPORTS=OFF); "
      "results.json and results.csv hold the results";
  return outcome;
}

}  // namespace skinsim::driver
