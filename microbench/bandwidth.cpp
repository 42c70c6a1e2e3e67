// DRAM bandwidth: passes whose bytes far outweigh their work. A 1:1 nearest-filtered copy
// of an RGBA32F texture much larger than the texture cache (every texel line misses once),
// and a load + resolve of an RGBA16F target with its depth/stencil stored (tile loads and
// stores, hardware.md "Every render-target switch ends a render").
#include <fmt/format.h>

#include "microbench/benchmarks.h"
#include "microbench/meshes.h"
#include "microbench/shaders.h"

namespace skinsim::microbench {
namespace {

sim::Texture2D copy_source(int width, int height) {
  std::vector<glm::vec4> texels;
  texels.reserve(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      texels.emplace_back(static_cast<float>(x) / width, static_cast<float>(y) / height,
                          static_cast<float>((x * 7 + y * 13) % 101) / 100.0f, 1.0f);
    }
  }
  return sim::Texture2D("copy_source", width, height, texels, sim::TexelFormat::kRGBA32F,
                        {sim::Filter::kNearest, sim::Wrap::kClamp}, false);
}

double giga_bytes(const MeasuredPass& m) {
  return m.timing.dram.total() * 1e-9;
}

}  // namespace

MicrobenchResult run_bandwidth_copy(BenchContext& ctx) {
  const MicrobenchOptions& o = ctx.options();
  const sim::Texture2D source = copy_source(o.width, o.height);
  const Mesh quad = grid_mesh(1, 1, 0.0f);
  sim::RenderTarget target("copy", o.width, o.height, sim::TexelFormat::kRGBA32F);
  sim::RenderPassDesc pass;
  pass.name = "bandwidth_copy";
  pass.color = &target;
  sim::DrawCall d;
  d.geometry = quad.geometry();
  d.vertex_program = sim::make_vertex_program<shaders::TransformUvVS>({});
  d.fragment_program = sim::make_fragment_program<shaders::TextureReadFS>({});
  d.textures.textures[0] = &source;
  pass.draws.push_back(d);
  MeasuredPass m = ctx.run(pass);

  std::string shows = fmt::format(
      "1:1 nearest copy of a {}x{} RGBA32F texture ({:.1f} MB, {:g} KiB cache per core): "
      "{:.1f} B/px texture reads + {:.1f} B/px resolve",
      o.width, o.height, static_cast<double>(source.size_bytes()) * 1e-6,
      ctx.profile().texture_cache_bytes.value / 1024.0, m.timing.dram.texture / ctx.pixels(),
      m.timing.dram.color_store / ctx.pixels());
  const double work = giga_bytes(m);
  return make_result("bandwidth_copy", "GB/s", work, achievable_bandwidth(ctx.profile()),
                     std::move(m), std::move(shows));
}

MicrobenchResult run_bandwidth_resolve(BenchContext& ctx) {
  const MicrobenchOptions& o = ctx.options();
  const Mesh quad = grid_mesh(1, 1, 0.0f);
  sim::RenderTarget target("resolve", o.width, o.height, sim::TexelFormat::kRGBA16F);
  sim::RenderPassDesc pass;
  pass.name = "bandwidth_resolve";
  pass.color = &target;
  pass.color_load = sim::LoadOp::kLoad;  // keep the previous contents: tiles load them
  pass.store_depth = true;
  sim::DrawCall d;
  d.geometry = quad.geometry();
  d.vertex_program = sim::make_vertex_program<shaders::TransformVS>({});
  d.fragment_program = sim::make_fragment_program<shaders::FlatColorFS>({glm::vec4(0.125f)});
  d.blend = sim::BlendMode::kAdditive;
  d.depth_test = false;
  pass.draws.push_back(d);
  MeasuredPass m = ctx.run(pass);

  const auto& dram = m.timing.dram;
  std::string shows = fmt::format(
      "{}x{} RGBA16F target loaded, blended once and resolved, depth/stencil stored: "
      "{:.1f} + {:.1f} + {:.1f} B/px of tile loads and stores",
      o.width, o.height, dram.color_load / ctx.pixels(), dram.color_store / ctx.pixels(),
      dram.depth_store / ctx.pixels());
  const double work = giga_bytes(m);
  return make_result("bandwidth_resolve", "GB/s", work, achievable_bandwidth(ctx.profile()),
                     std::move(m), std::move(shows));
}

}  // namespace skinsim::microbench
