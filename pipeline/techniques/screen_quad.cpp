#include "pipeline/techniques/screen_quad.h"

namespace skinsim::pipeline {

ScreenQuad::ScreenQuad(const sim::PixelRect& r, int w, int h) {
  const float u0 = static_cast<float>(r.x0) / w, u1 = static_cast<float>(r.x1) / w;
  const float v0 = static_cast<float>(r.y0) / h, v1 = static_cast<float>(r.y1) / h;
  // Texture v grows downwards (row 0 at the top), clip y upwards.
  for (const glm::vec2 uv :
       {glm::vec2(u0, v1), glm::vec2(u1, v1), glm::vec2(u1, v0), glm::vec2(u0, v0)}) {
    mesh_.positions.emplace_back(uv.x * 2.0f - 1.0f, 1.0f - uv.y * 2.0f, 0.0f);
    mesh_.uvs.push_back(uv);
  }
}

sim::PassCounters quad_pass(const std::string& name, sim::DrawCall draw, sim::RenderTarget& target,
                            const sim::PixelRect& rect, sim::Gpu& gpu) {
  const ScreenQuad quad(rect, target.width, target.height);
  draw.geometry = quad.geometry();
  draw.cull = sim::CullMode::kNone;
  draw.depth_test = false;
  draw.depth_write = false;
  sim::RenderPassDesc pass;
  pass.name = name;
  pass.color = &target;
  pass.render_area = rect;
  pass.draws.push_back(std::move(draw));
  return gpu.execute(pass);
}

}  // namespace skinsim::pipeline
