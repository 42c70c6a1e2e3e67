// A sequence's frames as a video for the reports: Debian's ffmpeg (found in PATH) encodes
// <frames>/0000.png, 0001.png, ... to a VP9 WebM, which browsers play in a <video> element.
// Without ffmpeg the frames are all there is, and the caller says so.
#pragma once

#include <filesystem>
#include <string>

namespace skinsim::driver {

struct VideoOutcome {
  bool encoded = false;
  std::string note;  // why there is no video (ffmpeg absent, or failed: its log)
};

// Encodes the frames at `fps` into `webm`, written atomically (a partial file is never left
// under that name). Frames of odd width or height are padded by a black pixel (VP9's 4:2:0).
VideoOutcome encode_sequence_video(const std::filesystem::path& frames_dir, double fps,
                                   const std::filesystem::path& webm);

}  // namespace skinsim::driver
