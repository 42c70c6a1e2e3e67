// `--sequence animation[:NAME]`: a glTF scene's own animation (scene/gltf_animation.h) drives
// the sequence. The file is read once (scene::PosedGltf) and each frame's scene is it posed
// with the animated nodes (meshes, and the camera when its node moves) at the frame's time,
// 0 s to the last keyframe.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "driver/frame/scene_source.h"
#include "driver/sequence/sequence.h"
#include "pipeline/gpu_scene.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_loader.h"

namespace skinsim::driver {

// For an animated `sequence`: reads its animation from `source`'s file into
// sequence.animation_clip and, unless --frames gave them, fits the frames to it: one at 0 s and
// one every 1/fps up to its last keyframe (one frame for a still one). Nothing for another
// sequence. Throws SequenceError for the built-in head (it has no animation) and
// scene::SceneError naming the file and field.
void attach_animation(Sequence& sequence, const SceneSource& source);

class AnimatedScene {
 public:
  // `sequence` with its animation attached (attach_animation).
  AnimatedScene(const SceneSource& source, float aspect, const Sequence& sequence);

  // The scene at `time_s`, posed again when the time changes; valid until the next call.
  const pipeline::GpuScene& at(double time_s);
  // The scene at `time_s`, the caller's to keep.
  scene::Scene pose(double time_s) { return file_.pose(animation_.get(), time_s); }

 private:
  std::shared_ptr<const scene::NodeAnimation> animation_;
  scene::PosedGltf file_;
  double time_s_ = -1.0;
  std::unique_ptr<scene::Scene> scene_;
  std::unique_ptr<pipeline::GpuScene> gpu_;  // refers to *scene_
};

// The scene a frame at `time_s` shows, for keying what is kept of it (a sweep's references):
// `scene` (scene_fingerprint) with, for an animated sequence, the animation and the time, so
// frames of different poses never share a reference.
nlohmann::json posed_scene_fingerprint(const nlohmann::json& scene, const Sequence& sequence,
                                       double time_s);

}  // namespace skinsim::driver
