// Charts of a sequence (`skinsim run --sequence`): frame time over the sequence with its
// uncertainty range and the frame budget, and where each frame's time goes as stacked
// per-pass areas. VTK, offscreen, like the sweep's charts (charts.h: an X display is checked
// first; files are written atomically).
#pragma once

#include <string>
#include <vector>

#include "reports/charts.h"

namespace skinsim::reports {

struct SequenceSeries {
  std::string title;           // e.g. "push-in, 60 frames at 30 fps, ipad4"
  std::vector<double> time_s;  // per frame
  std::vector<double> frame_ms;
  std::vector<double> low_ms;  // the frame's range over the profile's uncertain figures
  std::vector<double> high_ms;
  std::vector<std::string> pass_names;       // in frame order
  std::vector<std::vector<double>> pass_ms;  // [pass][frame], 0 where a frame lacks the pass
  double budget_ms = 33.3;                   // the frame interval
  // With a reference: each frame's FLIP against it (quality_label names the metric), and the
  // temporal error of each step into frame 1, 2, ... (one fewer than the frames).
  std::string quality_label;
  std::vector<double> quality;
  std::vector<double> temporal_error;
};

// Frame ms against time (s), its low and high range as thin lines, the budget as a dashed
// horizontal line. Throws ReportError if there are no frames.
ChartFiles write_sequence_frame_chart(const SequenceSeries& series, const std::string& path_stem,
                                      const ChartOptions& options = {});

// Each pass's ms against time, stacked (they add up to the frame ms), coloured by pass as in
// the sweep's charts, with the budget line.
ChartFiles write_sequence_pass_chart(const SequenceSeries& series, const std::string& path_stem,
                                     const ChartOptions& options = {});

// Each frame's FLIP against its reference and the temporal error of each step, against time.
// Throws ReportError if the series has no quality.
ChartFiles write_sequence_quality_chart(const SequenceSeries& series, const std::string& path_stem,
                                        const ChartOptions& options = {});

}  // namespace skinsim::reports
