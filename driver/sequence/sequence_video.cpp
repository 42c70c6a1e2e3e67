#include "driver/sequence/sequence_video.h"

#include <fmt/format.h>

#include <vector>

#include "driver/frame/truth_process.h"
#include "util/user_error.h"

namespace skinsim::driver {

VideoOutcome encode_sequence_video(const std::filesystem::path& frames_dir, double fps,
                                   const std::filesystem::path& webm) {
  VideoOutcome outcome;
  if (!program_exists("ffmpeg")) {
    outcome.note = "ffmpeg is not installed (not found in PATH): no video; the frames are kept";
    return outcome;
  }
  const std::filesystem::path partial = webm.string() + ".partial";
  const std::filesystem::path log = webm.string() + ".log";
  std::filesystem::remove(log);
  // Realtime deadline: a 60-frame 2048x1536 sequence encodes in seconds, where the default
  // "good" deadline takes minutes; the video is for looking at motion, not archiving. One
  // encoder thread: the same bytes on any host.
  const std::vector<std::string> argv = {"ffmpeg",
                                         "-nostdin",
                                         "-hide_banner",
                                         "-loglevel",
                                         "error",
                                         "-y",
                                         "-framerate",
                                         fmt::format("{}", fps),
                                         "-i",
                                         (frames_dir / "%04d.png").string(),
                                         "-vf",
                                         "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                         "-c:v",
                                         "libvpx-vp9",
                                         "-pix_fmt",
                                         "yuv420p",
                                         "-b:v",
                                         "0",
                                         "-crf",
                                         "30",
                                         "-deadline",
                                         "realtime",
                                         "-cpu-used",
                                         "8",
                                         "-threads",
                                         "1",
                                         "-f",
                                         "webm",
                                         partial.string()};
  int status = 0;
  try {
    status = run_program(argv, log);
  } catch (const UserError& e) {
    outcome.note = fmt::format("{}: no video; the frames are kept", e.what());
    return outcome;
  }
  if (status != 0) {
    std::filesystem::remove(partial);
    outcome.note = fmt::format(
        "ffmpeg failed (exit {}; its messages: {}): no video; the frames "
        "are kept",
        status, log.string());
    return outcome;
  }
  std::filesystem::rename(partial, webm);
  std::filesystem::remove(log);
  outcome.encoded = true;
  return outcome;
}

}  // namespace skinsim::driver
