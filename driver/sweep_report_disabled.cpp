// write_sweep_report for builds configured with -DSKINSIM_BUILD_REPORTS=OFF (no VTK).
#include "driver/sweep_report.h"

namespace skinsim::driver {

SweepReportOutcome write_sweep_report(const reports::SweepTable&, const std::string&, bool) {
  SweepReportOutcome outcome;
  outcome.note =
      "this build has no charts or report.html (configured with -DSKINSIM_BUILD_REPORTS=OFF); "
      "results.json and results.csv hold the results";
  return outcome;
}

}  // namespace skinsim::driver
