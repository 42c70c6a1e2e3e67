#include "tests/pipeline/small_frames.h"

#include <stdexcept>

#include "scene/procedural_head.h"
#include "sim/gpu.h"

namespace skinsim::pipeline::testing {

const GpuScene& small_scene() {
  static const scene::Scene s = [] {
    scene::DefaultSceneOptions o;
    o.head_triangles = 4000;
    o.texture_size = 256;
    o.eye_texture_size = 64;
    o.environment_size = 16;
    return scene::make_default_scene(o);
  }();
  static const GpuScene gs(s);
  return gs;
}

PipelineConfig small_config(const std::string& technique) {
  PipelineConfig c;
  set_config_field(c, "technique", technique);
  set_config_field(c, "resolution", "256x192");
  set_config_field(c, "texture_space_size", "128");
  set_config_field(c, "burley_samples", "8");
  return c;
}

FrameOutput render(const PipelineConfig& c) {
  sim::GpuConfig g;
  g.threads = 2;
  sim::Gpu gpu(g);
  return render_frame(small_scene(), c, gpu);
}

const sim::DrawCounters& skin_draw(const FrameOutput& out) {
  const sim::PassCounters& skin = out.passes.back();
  for (const sim::DrawCounters& d : skin.draws) {
    if (d.fragment_program != "background_fs" && d.fragment_program != "eye_fs") return d;
  }
  throw std::runtime_error("no skin draw");
}

glm::vec3 centre_mean(const sim::RenderTarget& frame) {
  glm::vec3 sum(0.0f);
  int n = 0;
  for (int y = frame.height * 3 / 8; y < frame.height * 5 / 8; ++y) {
    for (int x = frame.width * 3 / 8; x < frame.width * 5 / 8; ++x) {
      sum += glm::vec3(frame.at(x, y));
      ++n;
    }
  }
  return sum / static_cast<float>(n);
}

}  // namespace skinsim::pipeline::testing
