// The charts of a played sequence in a run's directory (reports/sequence_charts.h):
// sequence_frame_ms.png, sequence_passes.png and, when every frame was measured against its
// reference, sequence_quality.png; each with an .svg copy.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "driver/sequence/sequence_run.h"

namespace skinsim::driver {

struct SequenceChartsOutcome {
  std::vector<std::string> written;  // file names in `dir`
  std::string note;                  // why no charts were drawn (no X display, no VTK build)
  // An attempt to open the display is still pending: end the process with std::_Exit once
  // its files are written (reports::abandoned_display_attempts).
  bool display_attempt_pending = false;
};

// `title` names the sequence's scene and device for the charts' titles.
SequenceChartsOutcome write_sequence_charts(const Sequence& sequence, const SequenceResult& result,
                                            const std::string& title,
                                            const std::filesystem::path& dir);

}  // namespace skinsim::driver
