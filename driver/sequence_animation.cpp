#include "driver/sequence_animation.h"

#include <algorithm>
#include <cmath>

namespace skinsim::driver {

AnimatedScene::AnimatedScene(const SceneSource& source, float aspect, const Sequence& sequence)
    : source_(source), aspect_(aspect) {
  if (source.builtin()) {
    throw SequenceError(
        "--sequence " + std::string(sequence.animation.empty() ? "animation" : "animation:") +
        sequence.animation +
        ": the built-in head has no animation; give an animated glTF with --scene (or use the "
        "presets push-in, head-turn, light-orbit)");
  }
  animation_ = scene::load_animation(source.path, sequence.animation);
  source_.animation = &animation_;
}

const pipeline::GpuScene& AnimatedScene::at(double time_s) {
  if (!gpu_ || time_s != time_s_) {
    source_.animation_time_s = time_s;
    gpu_.reset();
    scene_ = std::make_unique<scene::Scene>(load_scene(source_, aspect_));
    gpu_ = std::make_unique<pipeline::GpuScene>(*scene_);
    time_s_ = time_s;
  }
  return *gpu_;
}

void fit_to_animation(Sequence& sequence, const scene::NodeAnimation& animation) {
  if (sequence.frames > 0) return;
  // The small tolerance keeps a keyframe that falls on a frame (2 s at 30 fps) from being
  // lost to rounding.
  const double steps = std::floor(animation.duration_s * sequence.fps + 1e-9);
  sequence.frames = static_cast<int>(std::min<double>(steps, kMaxSequenceFrames - 1)) + 1;
}

}  // namespace skinsim::driver
