#include "driver/sequence/sequence_animation.h"

#include <algorithm>
#include <cmath>

#include "util/check.h"

namespace skinsim::driver {

void attach_animation(Sequence& sequence, const SceneSource& source) {
  if (!sequence.animated) return;
  if (source.builtin()) {
    throw SequenceError(
        "--sequence " + std::string(sequence.animation.empty() ? "animation" : "animation:") +
        sequence.animation +
        ": the built-in head has no animation; give an animated glTF with --scene (or use the "
        "presets push-in, head-turn, light-orbit)");
  }
  sequence.animation_clip = std::make_shared<const scene::NodeAnimation>(
      scene::load_animation(source.path, sequence.animation));
  if (sequence.frames > 0) return;
  // The small tolerance keeps a keyframe that falls on a frame (2 s at 30 fps) from being
  // lost to rounding.
  const double steps = std::floor(sequence.animation_clip->duration_s * sequence.fps + 1e-9);
  sequence.frames = static_cast<int>(std::min<double>(steps, kMaxSequenceFrames - 1)) + 1;
}

AnimatedScene::AnimatedScene(const SceneSource& source, float aspect, const Sequence& sequence)
    : animation_(sequence.animation_clip), file_(source.path, gltf_load_options(source, aspect)) {
  SKINSIM_CHECK(animation_);
}

const pipeline::GpuScene& AnimatedScene::at(double time_s) {
  if (!gpu_ || time_s != time_s_) {
    gpu_.reset();
    scene_ = std::make_unique<scene::Scene>(pose(time_s));
    gpu_ = std::make_unique<pipeline::GpuScene>(*scene_);
    time_s_ = time_s;
  }
  return *gpu_;
}

nlohmann::json posed_scene_fingerprint(const nlohmann::json& scene, const Sequence& sequence,
                                       double time_s) {
  if (!sequence.animated) return scene;
  nlohmann::json posed = scene;
  posed["animation"] = {{"name", sequence.animation_clip->name}, {"time_s", time_s}};
  return posed;
}

}  // namespace skinsim::driver
