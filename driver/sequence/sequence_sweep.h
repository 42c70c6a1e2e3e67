// One configuration of a sweep over a sequence (`skinsim sweep --sequence`,
// results/sequence_summary.h): the sequence played with the sweep's pass memo and its per-frame
// references kept in refs/ (shared by the configurations with the same reference knobs), the
// frames written and encoded to a video, and what the configuration's row needs.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "driver/sequence/sequence_run.h"
#include "image/image.h"
#include "results/sequence_summary.h"

namespace skinsim::driver {

// The frame whose image and quality a configuration's row shows: the last (push-in's
// close-up), the same view in every configuration so their frames can be compared.
int shown_frame(const Sequence& sequence);

// What a stored configuration's fingerprint holds of the sequence, so a stored result of
// another sequence (or other frames, fps, tracks) is not taken for this one's.
nlohmann::json sequence_fingerprint(const Sequence& sequence);

struct PlayedConfig {
  FrameResult cost_frame;    // the frame at the p95 rank: counters and timing, no images
  image::Image shown_image;  // shown_frame's image
  results::SequenceSummary summary;
  std::string video_note;  // why there is no video, if there is none
};

// Plays `sequence` for a resolved configuration `id`: its frames into `dir`/configs/<id>_frames/
// and encoded to configs/<id>.webm (sequence_video.h; the frames are kept only when the video
// could not be made). `animated`: the scene at each frame's time, for an animated sequence
// (run_sequence).
PlayedConfig play_sweep_config(const pipeline::GpuScene& scene, const Sequence& sequence,
                               const pipeline::PipelineConfig& resolved,
                               const gpu_model::DeviceProfile& device, int threads,
                               sim::PassMemo& memo, const SequenceReferences& references,
                               const std::filesystem::path& dir, const std::string& id,
                               const SceneAtTime& animated = {});

}  // namespace skinsim::driver
