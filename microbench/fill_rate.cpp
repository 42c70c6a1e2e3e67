// Texel fill rate: several full-screen layers, one bilinear read each (GLBenchmark-style
// fill test). Blended layers must all be shaded; opaque ones show deferred hidden-surface
// removal shading only the front layer (hardware.md, "hidden surface removal").
#include <fmt/format.h>

#include "microbench/benchmarks.h"
#include "microbench/meshes.h"
#include "microbench/shaders.h"

namespace skinsim::microbench {
namespace {

constexpr int kTextureSize = 256;

// A 256x256 RGBA8 pattern (alpha 0.5 for blending), magnified over the target: each core's
// texture cache holds the footprint, so the pass measures the texture units, not DRAM.
sim::Texture2D fill_texture() {
  std::vector<glm::vec4> texels;
  texels.reserve(kTextureSize * kTextureSize);
  for (int y = 0; y < kTextureSize; ++y) {
    for (int x = 0; x < kTextureSize; ++x) {
      texels.emplace_back(static_cast<float>(x) / (kTextureSize - 1),
                          static_cast<float>(y) / (kTextureSize - 1),
                          static_cast<float>((x ^ y) & 255) / 255.0f, 0.5f);
    }
  }
  return sim::Texture2D("fill_pattern", kTextureSize, kTextureSize, texels,
                        sim::TexelFormat::kRGBA8, {sim::Filter::kBilinear, sim::Wrap::kRepeat},
                        false);
}

enum class Layering { kBlended, kOpaque };

MeasuredPass fill_pass(BenchContext& ctx, Layering layering) {
  const MicrobenchOptions& o = ctx.options();
  const sim::Texture2D texture = fill_texture();
  const Mesh quad = grid_mesh(1, 1, 0.0f);
  const auto fragment = sim::make_fragment_program<shaders::TextureReadFS>({});
  sim::RenderTarget target("fill", o.width, o.height, sim::TexelFormat::kRGBA8);
  sim::RenderPassDesc pass;
  pass.name = layering == Layering::kBlended ? "fill_blended" : "fill_opaque";
  pass.color = &target;
  for (int i = 0; i < o.fill_layers; ++i) {
    // Back to front (the worst order for an immediate-mode GPU): depth in (-1, 1), falling.
    shaders::TransformUvVS::Uniforms u;
    u.transform[3][2] = 1.0f - 2.0f * static_cast<float>(i + 1) / (o.fill_layers + 1);
    sim::DrawCall d;
    d.geometry = quad.geometry();
    d.vertex_program = sim::make_vertex_program<shaders::TransformUvVS>(u);
    d.fragment_program = fragment;
    d.textures.textures[0] = &texture;
    if (layering == Layering::kBlended) {
      d.blend = sim::BlendMode::kAlpha;
      d.depth_test = false;
      d.depth_write = false;
    }
    pass.draws.push_back(d);
  }
  return ctx.run(pass);
}

double texel_mega(const MeasuredPass& m) {
  return static_cast<double>(m.counters.texture.samples()) * 1e-6;
}

}  // namespace

MicrobenchResult run_fill_blended(BenchContext& ctx) {
  MeasuredPass m = fill_pass(ctx, Layering::kBlended);
  const double work = texel_mega(m);
  std::string shows = fmt::format(
      "{} alpha-blended full-screen layers, 1 bilinear read each: {:.2f} layers shaded per "
      "pixel (blending defeats HSR); SGX blends in the USSE, {:g} cycles per fragment",
      ctx.options().fill_layers, static_cast<double>(m.counters.fragments_shaded) / ctx.pixels(),
      ctx.profile().blend_cycles.value);
  return make_result("fill_blended", "Mtexel/s", work, texel_fill_peak(ctx.profile()), std::move(m),
                     std::move(shows));
}

MicrobenchResult run_fill_opaque(BenchContext& ctx) {
  MeasuredPass m = fill_pass(ctx, Layering::kOpaque);
  const double work = texel_mega(m);
  std::string shows = fmt::format(
      "{} opaque full-screen layers drawn back to front: {:.2f} depth tests but {:.2f} "
      "shaded fragments per pixel (deferred HSR removes the overdraw)",
      ctx.options().fill_layers,
      static_cast<double>(m.counters.fragments_depth_tested) / ctx.pixels(),
      static_cast<double>(m.counters.fragments_shaded) / ctx.pixels());
  return make_result("fill_opaque", "Mtexel/s", work, texel_fill_peak(ctx.profile()), std::move(m),
                     std::move(shows));
}

}  // namespace skinsim::microbench
