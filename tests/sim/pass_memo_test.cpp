// The render-pass memo: a replayed pass leaves exactly what rendering it leaves (targets and
// counters), any changed input is a miss, and only passes that a later pass samples are
// kept across frames.
#include "sim/pass_memo.h"

#include <gtest/gtest.h>

#include "sim/gpu.h"
#include "sim/mesh.h"
#include "tests/sim/counter_diff.h"
#include "tests/sim/test_shaders.h"

namespace skinsim::sim {
namespace {

// A full-target quad in clip space with uvs over [0, 1]^2.
Mesh full_quad() {
  return {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
          {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
          {0, 1, 2, 0, 2, 3}};
}

// A mipmapped 32x32 texture of smooth, non-repeating values.
Texture2D gradient_texture(float shift) {
  std::vector<glm::vec4> texels;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      texels.emplace_back(x / 31.0f, y / 31.0f, std::fmod(shift + 0.37f * (x ^ y), 1.0f), 1.0f);
    }
  }
  return Texture2D("gradient", 32, 32, texels, TexelFormat::kRGBA8, {}, true);
}

// Draws `texture` minified onto a 20x12 target, or a flat colour without one.
RenderPassDesc textured_pass(RenderTarget& target, const Mesh& quad, const Texture2D* texture,
                             glm::vec4 color = glm::vec4(1.0f)) {
  RenderPassDesc pass;
  pass.name = "textured";
  pass.color = &target;
  DrawCall d;
  d.geometry = quad.geometry();
  d.vertex_program = make_vertex_program<testing::PassThroughVS>({});
  if (texture) {
    d.fragment_program = make_fragment_program<testing::TexturedFS>({});
    d.textures.textures[0] = texture;
  } else {
    d.fragment_program = make_fragment_program<testing::FlatColorFS>({color});
  }
  pass.draws.push_back(d);
  return pass;
}

GpuConfig test_config() {
  GpuConfig config;
  config.cores = 2;
  config.tile_size = 8;
  return config;
}

// A frame of two passes, the second sampling the first's target, as the mobile pipeline's
// irradiance and blur; returns the second's counters.
struct TwoPassFrame {
  RenderTarget first{"first", 20, 12, TexelFormat::kRGBA8};
  RenderTarget second{"second", 20, 12, TexelFormat::kRGBA8};
  PassCounters first_counters, second_counters;
  void render(Gpu& gpu, const Mesh& quad, const Texture2D& source, PassMemo* memo) {
    first_counters = gpu.execute(textured_pass(first, quad, &source));
    const Texture2D view = texture_view(first, {Filter::kBilinear, Wrap::kClamp});
    second_counters = gpu.execute(textured_pass(second, quad, &view));
    if (memo) memo->end_frame();
  }
};

TEST(PassMemo, AReplayedPassLeavesWhatRenderingItLeaves) {
  const Mesh quad = full_quad();
  const Texture2D source = gradient_texture(0.0f);
  TwoPassFrame rendered;
  {
    Gpu gpu(test_config());
    rendered.render(gpu, quad, source, nullptr);
  }

  PassMemo memo(1 << 20);
  Gpu gpu(test_config());
  gpu.set_pass_memo(&memo);
  TwoPassFrame first_frame, second_frame;
  first_frame.render(gpu, quad, source, &memo);
  EXPECT_EQ(memo.stats().replayed, 0);
  second_frame.render(gpu, quad, source, &memo);
  // The first pass is replayed; the second, which nothing sampled, was not kept, so it is
  // rendered again, sampling the replayed target.
  EXPECT_EQ(memo.stats().replayed, 1);
  EXPECT_EQ(memo.stats().rendered, 3);

  EXPECT_GT(rendered.first_counters.texture.cache_misses, 0u);
  for (const TwoPassFrame* f : {&first_frame, &second_frame}) {
    EXPECT_EQ(f->first.pixels, rendered.first.pixels);
    EXPECT_EQ(f->second.pixels, rendered.second.pixels);
    EXPECT_TRUE(f->first_counters == rendered.first_counters)
        << testing::first_counter_difference(f->first_counters, rendered.first_counters);
    EXPECT_TRUE(f->second_counters == rendered.second_counters)
        << testing::first_counter_difference(f->second_counters, rendered.second_counters);
  }
}

TEST(PassMemo, AnyChangedInputIsRenderedAgain) {
  const Mesh quad = full_quad();
  const Texture2D source = gradient_texture(0.0f);
  PassMemo memo(1 << 20);
  RenderTarget target("t", 20, 12, TexelFormat::kRGBA8);
  // Runs `pass` into `target` and a pass sampling it (so that it is kept); whether `pass`
  // was replayed.
  const auto replayed = [&](const RenderPassDesc& pass, GpuConfig config = test_config()) {
    Gpu gpu(config);
    gpu.set_pass_memo(&memo);
    const int before = memo.stats().replayed;
    gpu.execute(pass);
    const bool was_replayed = memo.stats().replayed > before;
    RenderTarget sampler_of_it("s", 20, 12, TexelFormat::kRGBA8);
    const Texture2D view = texture_view(target, {});
    gpu.execute(textured_pass(sampler_of_it, quad, &view));
    memo.end_frame();
    return was_replayed;
  };
  EXPECT_FALSE(replayed(textured_pass(target, quad, &source)));
  EXPECT_TRUE(replayed(textured_pass(target, quad, &source))) << "the same pass again";

  const Texture2D other_texels = gradient_texture(0.25f);
  EXPECT_FALSE(replayed(textured_pass(target, quad, &other_texels))) << "a texel changed";

  EXPECT_FALSE(replayed(textured_pass(target, quad, nullptr, glm::vec4(0.5f))));
  EXPECT_TRUE(replayed(textured_pass(target, quad, nullptr, glm::vec4(0.5f))));
  EXPECT_FALSE(replayed(textured_pass(target, quad, nullptr, glm::vec4(0.5f, 0.5f, 0.5f, 0.25f))))
      << "a uniform changed";

  Mesh moved = full_quad();
  moved.positions[2].x = 0.5f;
  EXPECT_FALSE(replayed(textured_pass(target, moved, &source))) << "a vertex moved";

  GpuConfig smaller_cache = test_config();
  smaller_cache.texture_cache.size_bytes = 2048;
  EXPECT_FALSE(replayed(textured_pass(target, quad, &source), smaller_cache))
      << "the texture cache changed";

  // What a render area leaves untouched is an input: the same area over the same target
  // replays, over a changed one it renders.
  RenderPassDesc partial = textured_pass(target, quad, &source);
  partial.render_area = PixelRect{0, 0, 8, 8};
  replayed(partial);
  replayed(partial);  // the target now holds what the area leaves: a fixed point
  EXPECT_TRUE(replayed(partial));
  target.at(15, 10) = glm::vec4(1.0f);
  EXPECT_FALSE(replayed(partial)) << "the target outside the render area changed";
}

TEST(PassMemo, KeepsOnlyPassesALaterPassSamples) {
  const Mesh quad = full_quad();
  const Texture2D source = gradient_texture(0.0f);
  PassMemo memo(1 << 20);
  Gpu gpu(test_config());
  gpu.set_pass_memo(&memo);
  TwoPassFrame frame;
  frame.render(gpu, quad, source, &memo);
  // The first target is kept as bytes (RGBA8); the second, sampled by nothing, is not kept.
  EXPECT_EQ(memo.stats().bytes, 20u * 12u * 4u);

  PassMemo small(100);  // holds nothing
  Gpu gpu_small(test_config());
  gpu_small.set_pass_memo(&small);
  TwoPassFrame a, b;
  a.render(gpu_small, quad, source, &small);
  b.render(gpu_small, quad, source, &small);
  EXPECT_EQ(small.stats().replayed, 0);
  EXPECT_EQ(b.second.pixels, frame.second.pixels);
}

TEST(PassMemo, ReplaysADepthTargetAndAFloatTarget) {
  const Mesh quad = full_quad();
  RenderTarget depth("depth", 16, 16, TexelFormat::kDepth24);
  RenderPassDesc pass;
  pass.name = "shadow";
  pass.depth = &depth;
  pass.store_depth = true;
  DrawCall d;
  d.geometry = quad.geometry();
  d.vertex_program = make_vertex_program<testing::PassThroughVS>({});
  pass.draws.push_back(d);

  PassMemo memo(1 << 20);
  Gpu gpu(test_config());
  gpu.set_pass_memo(&memo);
  RenderTarget hdr("hdr", 16, 16, TexelFormat::kRGBA16F);
  const auto frame = [&] {
    gpu.execute(pass);
    const Texture2D view = texture_view(depth, {Filter::kNearest, Wrap::kClamp});
    gpu.execute(textured_pass(hdr, quad, &view));
    memo.end_frame();
  };
  frame();
  const std::vector<glm::vec4> rendered = depth.pixels;
  std::fill(depth.pixels.begin(), depth.pixels.end(), glm::vec4(0.0f));
  EXPECT_EQ(memo.stats().bytes, 16u * 16u * 4u);  // the depth's red channel only
  frame();
  EXPECT_EQ(memo.stats().replayed, 1);
  EXPECT_EQ(depth.pixels, rendered);
}

}  // namespace
}  // namespace skinsim::sim
