// Depth-only passes and shadow-map comparison on the emulated GPU: the stored depth is the
// ISP's, quantised to the depth format; nothing is shaded; a shadow sampler compares one
// texel (nearest) or filters the 2x2 comparisons (hardware PCF), counted as one sample.
#include <gtest/gtest.h>

#include "sim/gpu.h"
#include "sim/mesh.h"
#include "tests/sim/test_shaders.h"

namespace skinsim::sim {
namespace {

// Two clip-space triangles covering [x0, x1] x [-1, 1] at NDC depth z.
Mesh quad(float x0, float x1, float z) {
  return {{{x0, -1.0f, z}, {x1, -1.0f, z}, {x1, 1.0f, z}, {x0, 1.0f, z}}, {}, {0, 1, 2, 0, 2, 3}};
}

PassCounters depth_only(RenderTarget& depth, const std::vector<const Mesh*>& quads) {
  RenderPassDesc pass;
  pass.name = "shadow";
  pass.depth = &depth;
  pass.store_depth = true;
  for (const Mesh* q : quads) {
    DrawCall d;
    d.geometry = q->geometry();
    d.vertex_program = make_vertex_program<testing::PassThroughVS>({});
    pass.draws.push_back(d);
  }
  GpuConfig config;
  config.threads = 1;
  Gpu gpu(config);
  return gpu.execute(pass);
}

TEST(DepthOnlyPass, StoresTheNearestDepthAndShadesNothing) {
  RenderTarget depth("shadow_map", 64, 32, TexelFormat::kDepth16);
  const Mesh far = quad(-1.0f, 1.0f, 0.5f),
             near = quad(-1.0f, 0.0f, -0.5f);  // near covers the left half
  const PassCounters c = depth_only(depth, {&far, &near});
  EXPECT_EQ(c.fragments_shaded, 0u);
  EXPECT_EQ(c.fragments_depth_tested, 64u * 32u + 32u * 32u);
  EXPECT_EQ(c.depth_store_bytes, 64u * 32u * 2u);  // 16 bits per texel
  EXPECT_EQ(c.color_store_bytes, 0u);
  // NDC z -> window depth z * 0.5 + 0.5, then 16-bit UNORM.
  EXPECT_FLOAT_EQ(depth.at(10, 5).x, std::round(0.25f * 65535.0f) / 65535.0f);
  EXPECT_FLOAT_EQ(depth.at(50, 5).x, std::round(0.75f * 65535.0f) / 65535.0f);
}

TEST(DepthOnlyPass, RejectsAColourFormatDepthTarget) {
  RenderTarget depth("not_depth", 8, 8, TexelFormat::kRGBA8);
  const Mesh q = quad(-1.0f, 1.0f, 0.0f);
  EXPECT_THROW(depth_only(depth, {&q}), std::invalid_argument);
}

// A 4x1 depth texture: texels 0-1 at depth 0.25 (an occluder), 2-3 at 1 (empty).
Texture2D step_map(const RenderTarget& depth, Filter filter) {
  return texture_view(depth, {filter, Wrap::kClamp});
}

TEST(ShadowSampler, NearestComparesOneTexelAndPcfFiltersFour) {
  RenderTarget depth("shadow_map", 4, 1, TexelFormat::kDepth24);
  for (int x = 0; x < 4; ++x)
    depth.at(x, 0) = quantize(glm::vec4(x < 2 ? 0.25f : 1.0f), depth.format);
  TextureLineLog lines;
  TextureCounters counters;
  ExecTexUnit tex(&lines, &counters);
  const Texture2D nearest = step_map(depth, Filter::kNearest);
  const Texture2D linear = step_map(depth, Filter::kBilinear);
  TextureBindings bindings;
  bindings.textures[0] = &nearest;
  bindings.textures[1] = &linear;
  tex.bind(&bindings);
  // A receiver at depth 0.5: behind the occluder (texels 0, 1), in front of the rest.
  EXPECT_EQ(tex.sample_shadow(0, glm::vec3(0.125f, 0.5f, 0.5f)), 0.0f);
  EXPECT_EQ(tex.sample_shadow(0, glm::vec3(0.875f, 0.5f, 0.5f)), 1.0f);
  // Half-way between texel centres 1 (shadowed) and 2 (lit): half lit.
  EXPECT_FLOAT_EQ(tex.sample_shadow(1, glm::vec3(0.5f, 0.5f, 0.5f)), 0.5f);
  EXPECT_FLOAT_EQ(tex.sample_shadow(1, glm::vec3(0.5625f, 0.5f, 0.5f)), 0.75f);
  // A receiver in front of everything is lit.
  EXPECT_EQ(tex.sample_shadow(1, glm::vec3(0.25f, 0.5f, 0.1f)), 1.0f);
  EXPECT_EQ(counters.samples(), 5u);
  EXPECT_EQ(counters.samples_by_filter[static_cast<int>(Filter::kBilinear)], 3u);
  EXPECT_EQ(counters.samples_dependent, 5u);
  EXPECT_EQ(counters.texels_touched, 2u * 1u + 3u * 4u);
}

}  // namespace
}  // namespace skinsim::sim
