#include "pipeline/blur_pass.h"

#include <algorithm>
#include <cmath>

#include "pipeline/shaders/blur.h"
#include "pipeline/techniques/screen_quad.h"
#include "sim/program.h"

namespace skinsim::pipeline {

// One separable blur axis over the skin's bounding rectangle of the buffer.
sim::PassCounters blur_pass(const std::string& name, const sim::RenderTarget& source,
                            sim::RenderTarget& target, const sim::PixelRect& rect, glm::vec2 axis,
                            float sigma_texels, sim::Gpu& gpu,
                            const std::optional<BlurFollow>& follow) {
  const sim::Filter filter = follow ? sim::Filter::kNearest : sim::Filter::kBilinear;
  const sim::Texture2D src = sim::texture_view(source, {filter, sim::Wrap::kClamp});
  shaders::BlurVS::Uniforms vu;
  shaders::BlurFS::Uniforms fu;
  // Taps span +-2.5 sigma; spacing grows with sigma, so wide kernels are sampled sparsely
  // (the quality cost of a small tap count that the sweep measures). Depth-aware taps read
  // whole texels (nearest), so their spacing is rounded to whole texels.
  const int half = shaders::kBlurTaps / 2;
  float spacing = sigma_texels * 2.5f / static_cast<float>(half);
  if (follow) spacing = std::max(1.0f, std::round(spacing));
  float total = 0.0f;
  for (int i = 0; i < shaders::kBlurTaps; ++i) {
    const float x = static_cast<float>(i - half) * spacing;
    fu.weights[i] = sigma_texels > 0.0f ? std::exp(-x * x / (2.0f * sigma_texels * sigma_texels))
                                        : (i == half ? 1.0f : 0.0f);
    total += fu.weights[i];
    vu.offsets[i] = axis * x / glm::vec2(source.width, source.height);
  }
  for (float& w : fu.weights) w /= total;
  const ScreenQuad quad(rect, target.width, target.height);
  sim::DrawCall d;
  d.geometry = quad.geometry();
  d.vertex_program = sim::make_vertex_program<shaders::BlurVS>(vu);
  if (follow) {
    d.fragment_program = sim::make_fragment_program<shaders::DepthAwareBlurFS>(
        {fu.weights, follow->codes_per_tolerance, follow->last_axis});
  } else {
    d.fragment_program = sim::make_fragment_program<shaders::BlurFS>(fu);
  }
  d.textures.textures[0] = &src;
  d.cull = sim::CullMode::kNone;
  d.depth_test = false;
  d.depth_write = false;
  sim::RenderPassDesc pass;
  pass.name = name;
  pass.color = &target;
  pass.render_area = rect;
  pass.draws.push_back(d);
  return gpu.execute(pass);
}

}  // namespace skinsim::pipeline
