#include "pipeline/blur_pass.h"

#include <cmath>

#include "pipeline/shaders/blur.h"
#include "sim/program.h"

namespace skinsim::pipeline {

namespace {

// Clip-space quad over a pixel rectangle of a w x h target, with matching texture coords.
struct ScreenQuad {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
  ScreenQuad(const sim::PixelRect& r, int w, int h) {
    const float u0 = static_cast<float>(r.x0) / w, u1 = static_cast<float>(r.x1) / w;
    const float v0 = static_cast<float>(r.y0) / h, v1 = static_cast<float>(r.y1) / h;
    // Texture v grows downwards (row 0 at the top), clip y upwards.
    for (const glm::vec2 uv : {glm::vec2(u0, v1), glm::vec2(u1, v1), glm::vec2(u1, v0),
                               glm::vec2(u0, v0)}) {
      positions.emplace_back(uv.x * 2.0f - 1.0f, 1.0f - uv.y * 2.0f, 0.0f);
      uvs.push_back(uv);
    }
  }
  sim::Geometry geometry() const {
    sim::Geometry g;
    g.attributes.positions = positions.data();
    g.attributes.uvs = uvs.data();
    g.vertex_count = positions.size();
    g.indices = indices.data();
    g.index_count = indices.size();
    return g;
  }
};

}  // namespace

// One separable blur axis over the skin's bounding rectangle of the buffer.
sim::PassCounters blur_pass(const std::string& name, const sim::RenderTarget& source,
                            sim::RenderTarget& target, const sim::PixelRect& rect,
                            glm::vec2 axis, float sigma_texels, sim::Gpu& gpu) {
  const sim::Texture2D src =
      sim::as_texture(source, {sim::Filter::kBilinear, sim::Wrap::kClamp});
  shaders::BlurVS::Uniforms vu;
  shaders::BlurFS::Uniforms fu;
  // Taps span +-2.5 sigma; spacing grows with sigma, so wide kernels are sampled sparsely
  // (the quality cost of a small tap count that the sweep measures).
  const int half = shaders::kBlurTaps / 2;
  const float spacing = sigma_texels * 2.5f / static_cast<float>(half);
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
  d.fragment_program = sim::make_fragment_program<shaders::BlurFS>(fu);
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
