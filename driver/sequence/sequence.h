// A sequence: frames played at a frame rate, each frame the run's configuration with some
// knobs moved along a path (a track per knob). The built-in presets animate scenes that have no
// animation of their own through the framing and light knobs (pipeline/lighting.h):
//
//   push-in      camera_distance_m from 2.8 to 0.35 (60 frames at 30 fps)
//   head-turn    the head turns 90 degrees: camera_yaw_deg and light_azimuth_deg both move by
//                +90 from the run's values, so the light stays fixed in the world while the
//                face turns under it (60 frames at 30 fps)
//   light-orbit  light_azimuth_deg once round the head (120 frames at 30 fps; the last frame
//                stops one step short of the first, so the sequence loops)
//   animation[:NAME]  the glTF scene's own animation NAME (default: its first) at 30 fps, from
//                0 s to its last keyframe (sequence_animation.h)
//
// A sequence file (TOML, docs/sequences.md) has a [sequence] table naming a preset or its own
// tracks.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"
#include "util/user_error.h"

namespace skinsim::scene {
struct NodeAnimation;
}

namespace skinsim::driver {

class SequenceError : public UserError {
 public:
  using UserError::UserError;
};

// One knob along the sequence: linearly from `from` to `to`, or (relative) from the run's own
// value to that value plus `by`.
struct SequenceTrack {
  std::string knob;  // a knob name (pipeline::config_field_names)
  bool relative = false;
  double from = 0.0;  // absolute tracks
  double to = 0.0;
  double by = 0.0;  // relative tracks
};

struct Sequence {
  std::string name;
  int frames = 0;
  double fps = 0.0;
  // A closed path (an orbit): frame i is at i / frames of the way, so the last frame is one
  // step before the first and the sequence plays as a loop; otherwise i / (frames - 1), so the
  // first and last frames are the path's ends.
  bool loops = false;
  std::vector<SequenceTrack> tracks;
  // `--sequence animation[:NAME]`: the scene's own glTF animation (sequence_animation.h),
  // `animation` its name ("" = the file's first); frames 0 until fitted to its duration and
  // `animation_clip` empty until read (attach_animation).
  bool animated = false;
  std::string animation;
  std::shared_ptr<const scene::NodeAnimation> animation_clip;

  double time_s(int frame) const { return frame / fps; }
  // How far along the path frame `frame` is, 0..1.
  double progress(int frame) const;
};

const std::vector<std::string>& sequence_preset_names();

// The most frames a sequence may have (an hour at 30 fps; more is a typo).
inline constexpr int kMaxSequenceFrames = 108000;

// A preset by name, or a sequence file (a path ending in .toml); throws SequenceError naming
// --sequence (or the file and field) on bad input. `frames` and `fps`, when > 0, replace the
// sequence's own (--frames, --fps); 0 keeps them.
Sequence load_sequence(const std::string& name_or_file, int frames, double fps);
Sequence parse_sequence_file(const std::string& text, const std::filesystem::path& path);

// Checks the tracks against the run's configuration: each knob exists and is numeric, a
// track's knob is not also set on the command line where that would be overwritten (an absolute
// track on a knob the run gave a value). Throws SequenceError naming the knob.
void check_sequence(const Sequence& sequence, const pipeline::PipelineConfig& config);

// The configuration of frame `frame`: `config` with every track's knob at its value there.
// Angles about the up axis (camera_yaw_deg, light_azimuth_deg) are wrapped into [-180, 180];
// a relative light_azimuth_deg the run did not set starts from the scene's key light.
pipeline::PipelineConfig sequence_frame_config(const Sequence& sequence, int frame,
                                               const pipeline::PipelineConfig& config,
                                               const pipeline::GpuScene& scene);

}  // namespace skinsim::driver
