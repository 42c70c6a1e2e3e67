// A sweep over a sequence (`skinsim sweep --sequence`): each configuration plays the whole
// sequence, and its row carries the frame-time distribution and temporal stability. The row's
// frame_ms (and its range) is the sequence's p95 frame time, so the recommendation holds the p95
// frame to the budget; its image and quality are those of one frame shared by every
// configuration (shown_frame), so the frames compared across configurations show the same view.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace skinsim::results {

struct ConfigResult;

struct SequenceSummary {
  std::string name;  // the preset or the sequence file's name
  int frames = 0;
  double fps = 0.0;
  int shown_frame = 0;  // the frame whose image and quality the row shows
  // A nearest-rank statistic of the frame times, with the same statistic of the frames' low
  // and high ends (the profile's uncertain figures all fast or all slow).
  struct Stat {
    double ms = 0.0, low = 0.0, high = 0.0;
  };
  Stat p50, p95, max;
  std::vector<double> frame_ms;  // every frame's, in order (the report draws them)
  // tLP-with-FLIP between consecutive frames against the reference's (docs/sequences.md);
  // absent when the sequence has one frame.
  std::optional<double> temporal_mean_error;
  std::optional<double> temporal_max_error;
  // The sequence as a VP9 WebM, or its frames' directory when ffmpeg was absent (relative to
  // the sweep directory; "" if neither).
  std::string video;
  std::string frames_dir;
};

void to_json(nlohmann::json& j, const SequenceSummary& v);
// Throws ResultsError naming `where` and the field on a missing or mistyped field.
SequenceSummary parse_sequence_summary(const nlohmann::json& j, const std::string& where);

// The row reports the sequence: frame_ms and its range become the p95's.
void apply_sequence_summary(ConfigResult& row, const SequenceSummary& summary);

}  // namespace skinsim::results
