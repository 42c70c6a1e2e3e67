// A run's page for its sequence (`skinsim run --sequence`): sequence.html with the video of
// the frames (sequence_video.h), the frame-time distribution and temporal stability, and the
// sequence charts when they were drawn.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "driver/sequence/sequence_run.h"

namespace skinsim::driver {

struct SequencePage {
  std::vector<std::string> written;  // file names in the run directory
  std::string note;                  // why there is no video, if there is none
};

// `frames_dir` holds the frames (relative to `dir`); `charts` are the chart files drawn there.
SequencePage write_sequence_page(const std::filesystem::path& dir, const std::string& frames_dir,
                                 const Sequence& sequence, const SequenceResult& result,
                                 const std::string& title, const std::vector<std::string>& charts);

}  // namespace skinsim::driver
