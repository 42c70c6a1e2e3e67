// MSAA on the tile: per-sample coverage and depth at the standard positions, one shade per
// pixel per primitive, the box resolve at the tile store, and what it counts.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <set>

#include "sim/gpu.h"
#include "sim/mesh.h"
#include "tests/sim/counter_diff.h"
#include "tests/sim/test_shaders.h"

namespace skinsim::sim {
namespace {

using testing::first_counter_difference;
using testing::FlatColorFS;
using testing::PassThroughVS;

constexpr int kSize = 64;

// A triangle given in pixel coordinates of a kSize x kSize target, at depth z.
Mesh pixel_triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, float z = 0.5f) {
  Mesh m;
  for (const glm::vec2 p : {a, b, c}) {
    m.positions.emplace_back(p.x / (kSize / 2.0f) - 1.0f, 1.0f - p.y / (kSize / 2.0f), z);
  }
  m.indices = {0, 1, 2};
  return m;
}

DrawCall white_draw(const Mesh& m, glm::vec4 color = glm::vec4(1.0f)) {
  DrawCall d;
  d.geometry = m.geometry();
  d.vertex_program = make_vertex_program<PassThroughVS>({});
  d.fragment_program = make_fragment_program<FlatColorFS>({color});
  d.cull = CullMode::kNone;
  return d;
}

struct Rendered {
  PassCounters counters;
  std::vector<glm::vec4> pixels;
};

Rendered render(const std::vector<const Mesh*>& meshes, int samples, int threads = 1) {
  RenderTarget rt("rt", kSize, kSize, TexelFormat::kRGBA8);
  RenderPassDesc pass;
  pass.name = "msaa";
  pass.color = &rt;
  pass.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  pass.samples = samples;
  for (const Mesh* m : meshes) pass.draws.push_back(white_draw(*m));
  GpuConfig config;
  config.threads = threads;
  Rendered r{Gpu(config).execute(pass), {}};
  r.pixels = rt.pixels;
  return r;
}

// The right triangle (8, 8), (40, 8), (8, 40): legs of 32 pixels, no sample of the 1x, 2x or
// 4x pattern on its legs, and only the 1x pixel centres on its hypotenuse x + y = 48.
const Mesh& right_triangle() {
  static const Mesh m = pixel_triangle({8, 8}, {40, 8}, {8, 40});
  return m;
}

// Red values strictly between the clear (0) and the triangle (1).
std::set<float> partial_values(const std::vector<glm::vec4>& pixels) {
  std::set<float> values;
  for (const glm::vec4& p : pixels) {
    if (p.r > 0.0f && p.r < 1.0f) values.insert(p.r);
  }
  return values;
}

TEST(Msaa, SilhouetteEdgeGetsIntermediateCoverageOnlyWhenMultisampled) {
  // Edges at slopes that cross the pixel grid at every phase.
  const Mesh slanted = pixel_triangle({8.3f, 6.1f}, {57.7f, 21.4f}, {11.2f, 52.9f});
  const std::set<float> one = partial_values(render({&slanted}, 1).pixels);
  const std::set<float> four = partial_values(render({&slanted}, 4).pixels);
  EXPECT_TRUE(one.empty()) << one.size() << " grey levels at 1x";
  // Along the edges a pixel has 1, 2 or 3 of its 4 samples inside: 1/4, 1/2 or 3/4 of
  // white, as RGBA8 stores them.
  std::set<float> quarters;
  for (const float f : {0.25f, 0.5f, 0.75f}) {
    quarters.insert(quantize(glm::vec4(f), TexelFormat::kRGBA8).r);
  }
  EXPECT_EQ(four, quarters);
}

// Samples of pixel lattice points strictly inside the triangle, for a sample at offset
// (fx, fy) in [0, 1) from the pixel's corner: lattice points (k + fx, m + fy) from the
// corner (8, 8) with k, m >= 0 and k + m + fx + fy < 32, i.e. k + m <= 31 when fx + fy < 1
// and k + m <= 30 when 1 < fx + fy < 2: 32 * 33 / 2 = 528 or 31 * 32 / 2 = 496.
TEST(Msaa, SamplesCoveredEqualTheAnalyticCount) {
  // 4x: fx + fy = 0.5, 1.25, 0.75, 1.5 for the four standard positions.
  const PassCounters four = render({&right_triangle()}, 4).counters;
  EXPECT_EQ(four.samples, 4);
  EXPECT_EQ(four.samples_covered, 528u + 496u + 528u + 496u);
  // 2x: fx + fy = 1.5 and 0.5.
  EXPECT_EQ(render({&right_triangle()}, 2).counters.samples_covered, 496u + 528u);
  // 1x: the centre's fx + fy = 1 puts k + m = 31 on the hypotenuse, a bottom-right edge
  // the fill rule leaves out.
  const PassCounters one = render({&right_triangle()}, 1).counters;
  EXPECT_EQ(one.samples_covered, 496u);
  EXPECT_EQ(one.fragments_depth_tested, 496u);
  EXPECT_EQ(one.resolves, 0u);
  // Every pixel's samples are in tile memory, and every pixel is resolved once.
  EXPECT_EQ(four.samples_in_tile, 4u * kSize * kSize);
  EXPECT_EQ(four.resolves, static_cast<std::uint64_t>(kSize) * kSize);
  // One fragment per pixel with any sample covered, shaded once.
  EXPECT_EQ(four.fragments_shaded, four.fragments_depth_tested);
  EXPECT_GT(four.fragments_depth_tested, one.fragments_depth_tested);
}

// Two triangles sharing an edge: the pixels along it hold samples of both, so each is
// shaded twice (once per primitive), and no sample is covered twice or left out.
TEST(Msaa, EdgePixelsAreShadedOncePerPrimitive) {
  const Mesh a = pixel_triangle({8, 8}, {40, 8}, {8, 40});
  const Mesh b = pixel_triangle({40, 8}, {40, 40}, {8, 40});
  const Rendered r = render({&a, &b}, 4);
  EXPECT_EQ(r.counters.samples_covered, 4u * 32 * 32);  // the square, each sample once
  EXPECT_GT(r.counters.fragments_shaded, 32u * 32);
  EXPECT_EQ(r.counters.fragments_shaded, r.counters.fragments_depth_tested);
  EXPECT_TRUE(partial_values(r.pixels).empty());  // both white: the seam does not show
}

TEST(Msaa, RenderTargetBytesDoNotGrowWithSamples) {
  const PassCounters one = render({&right_triangle()}, 1).counters;
  const PassCounters four = render({&right_triangle()}, 4).counters;
  EXPECT_EQ(four.color_store_bytes, one.color_store_bytes);
  EXPECT_EQ(four.color_store_bytes, 4u * kSize * kSize);  // RGBA8: the resolved pixels only
  EXPECT_EQ(four.color_load_bytes, one.color_load_bytes);
  EXPECT_EQ(four.depth_store_bytes, one.depth_store_bytes);
  EXPECT_EQ(four.texture.dram_bytes, one.texture.dram_bytes);
}

TEST(Msaa, ImagesAndCountersIdenticalForAnyThreadCountAt4x) {
  // Overlapping triangles at different depths, over many tiles.
  const Mesh back = pixel_triangle({-5, 3}, {70, 10}, {20, 66}, 0.7f);
  const Mesh front = pixel_triangle({60, -4}, {50, 61}, {3, 30}, 0.3f);
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 8);
  const Rendered r1 = render({&back, &front}, 4, 1);
  for (int threads : {2, 8}) {
    const Rendered r = render({&back, &front}, 4, threads);
    EXPECT_EQ(r.pixels, r1.pixels) << threads << " threads";
    EXPECT_TRUE(r.counters == r1.counters) << first_counter_difference(r.counters, r1.counters);
  }
  EXPECT_FALSE(partial_values(r1.pixels).empty());
}

TEST(Msaa, RejectsASampleCountOtherThanOneTwoOrFour) {
  RenderTarget rt("rt", kSize, kSize, TexelFormat::kRGBA8);
  RenderPassDesc pass;
  pass.name = "msaa";
  pass.color = &rt;
  pass.samples = 3;
  pass.draws.push_back(white_draw(right_triangle()));
  try {
    Gpu(GpuConfig{}).execute(pass);
    FAIL() << "3 samples accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("must be 1, 2 or 4, got 3"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace skinsim::sim
