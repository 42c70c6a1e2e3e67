// `--sequence animation[:NAME]`: a glTF scene's own animation (scene/gltf_animation.h) drives
// the sequence. Each frame's scene is the file loaded with its animated nodes (meshes, and the
// camera when its node moves) posed at the frame's time, 0 s to the last keyframe.
#pragma once

#include <memory>
#include <string>

#include "driver/scene_source.h"
#include "driver/sequence.h"
#include "pipeline/gpu_scene.h"
#include "scene/gltf_animation.h"

namespace skinsim::driver {

class AnimatedScene {
 public:
  // Reads the animation `sequence.animation` of `source`'s file. Throws SequenceError for the
  // built-in head (it has no animation) and scene::SceneError naming the file and field.
  AnimatedScene(const SceneSource& source, float aspect, const Sequence& sequence);

  // The scene at `time_s`, loaded again when the time changes; valid until the next call.
  const pipeline::GpuScene& at(double time_s);
  const scene::NodeAnimation& animation() const { return animation_; }

 private:
  SceneSource source_;
  float aspect_;
  scene::NodeAnimation animation_;
  double time_s_ = -1.0;
  std::unique_ptr<scene::Scene> scene_;
  std::unique_ptr<pipeline::GpuScene> gpu_;  // refers to *scene_
};

// Unless --frames gave them, the frames that play the animation at the sequence's rate: one at
// 0 s and one every 1/fps up to its last keyframe (one frame for a still one).
void fit_to_animation(Sequence& sequence, const scene::NodeAnimation& animation);

}  // namespace skinsim::driver
