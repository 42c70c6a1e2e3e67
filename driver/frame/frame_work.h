// The work a frame asks for, estimated from its scene and knobs before anything renders. A
// small input can ask for unbounded work: a 240 KB glTF of 20,000 screen-covering triangles
// is 983 million depth tests at 256x192, and `--texture-space-size 4096` renders 16.8
// million texels per texture-space pass whatever the frame's size. Such a frame is refused
// (far beyond any skin scene) or announced before it starts, never run for minutes silently.
#pragma once

#include <string>
#include <vector>

#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"

namespace skinsim::driver {

struct FrameWork {
  // Fragments the camera's view depth-tests: the screen area of every front-facing triangle
  // within the frame (a triangle crossing the camera's plane counts as the whole frame).
  double view_fragments = 0.0;
  double depth_complexity = 0.0;  // view_fragments per pixel of the frame
  // Texels of each texture-space pass; 0 when the technique renders none.
  double texture_space_texels = 0.0;
};

// Real heads have a depth complexity of 1-3 (a scan with its eyes and backdrop under 2).
// Above kNotedDepthComplexity a run says what it is about to do; above kMaxDepthComplexity
// (the whole frame covered 1,024 times over) it is refused: at 2048x1536 that is over three
// billion depth tests, minutes of emulation, for a scene no skin technique is about.
inline constexpr double kNotedDepthComplexity = 16.0;
inline constexpr double kMaxDepthComplexity = 1024.0;
// Texture-space passes above 2048x2048 texels (the knob goes to 4096) are announced.
inline constexpr double kNotedTextureSpaceTexels = 2048.0 * 2048.0;

// The config must be resolved (driver::resolve_config).
FrameWork estimate_frame_work(const pipeline::GpuScene& scene,
                              const pipeline::PipelineConfig& config);

// Throws UserError naming the scene when `work` is beyond the limits above.
void require_bounded_work(const FrameWork& work, const pipeline::PipelineConfig& config,
                          const std::string& scene_label);

// What a run prints before it starts when `work` is large but allowed.
std::vector<std::string> frame_work_notes(const FrameWork& work,
                                          const pipeline::PipelineConfig& config);

}  // namespace skinsim::driver
