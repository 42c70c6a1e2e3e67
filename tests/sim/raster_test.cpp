// Exact counter checks of the emulated GPU on hand-checkable scenes.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>

#include "sim/gpu.h"
#include "sim/mesh.h"
#include "tests/sim/counter_diff.h"
#include "tests/sim/test_shaders.h"

namespace skinsim::sim {
namespace {

using testing::first_counter_difference;
using testing::FlatColorFS;
using testing::PassThroughVS;
using testing::TexturedFS;

// An n x n grid over clip-space [x0,x1]x[y0,y1] at depth z, counter-clockwise triangles;
// interior vertices jittered (shared edges at arbitrary sub-pixel positions).
Mesh grid_mesh(int n, float z, float jitter, unsigned seed, float x0 = -1, float y0 = -1,
               float x1 = 1, float y1 = 1) {
  Mesh m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> d(-jitter, jitter);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      float x = x0 + (x1 - x0) * i / n, y = y0 + (y1 - y0) * j / n;
      if (i > 0 && i < n && j > 0 && j < n) {
        x += d(rng) * (x1 - x0) / n;
        y += d(rng) * (y1 - y0) / n;
      }
      m.positions.emplace_back(x, y, z);
      m.uvs.emplace_back(static_cast<float>(i) / n, static_cast<float>(j) / n);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, e = c + 1;
      m.indices.insert(m.indices.end(), {a, b, e, a, e, c});
    }
  }
  return m;
}

DrawCall flat_draw(const Mesh& m, glm::vec4 color, BlendMode blend = BlendMode::kOpaque) {
  DrawCall d;
  d.geometry = m.geometry();
  d.vertex_program = make_vertex_program<PassThroughVS>({});
  d.fragment_program = make_fragment_program<FlatColorFS>({color});
  d.blend = blend;
  return d;
}

// A pass with one opaque draw of `m` sampling `tex` at the mesh's UVs.
RenderPassDesc textured_pass(const char* name, RenderTarget& rt, const Mesh& m,
                             const Texture2D& tex) {
  RenderPassDesc pass;
  pass.name = name;
  pass.color = &rt;
  DrawCall d = flat_draw(m, glm::vec4(1.0f));
  d.fragment_program = make_fragment_program<TexturedFS>({});
  d.textures.textures[0] = &tex;
  pass.draws.push_back(d);
  return pass;
}

GpuConfig config(int threads) {
  GpuConfig c;
  c.threads = threads;
  return c;
}

TEST(Raster, FullScreenQuadShadesEveryPixelOnce) {
  RenderTarget rt("rt", 100, 70, TexelFormat::kRGBA8);
  const Mesh quad = grid_mesh(1, 0.5f, 0.0f, 1);
  RenderPassDesc pass;
  pass.name = "quad";
  pass.color = &rt;
  pass.draws.push_back(flat_draw(quad, glm::vec4(1.0f)));
  const PassCounters c = Gpu(config(1)).execute(pass);
  EXPECT_EQ(c.fragments_shaded, 100u * 70u);
  EXPECT_EQ(c.fragments_depth_tested, 100u * 70u);
  EXPECT_EQ(c.triangles_in, 2u);
  EXPECT_EQ(c.triangles_binned, 2u);
  EXPECT_EQ(c.tiles_rendered, 4u * 3u);
  EXPECT_EQ(c.color_store_bytes, 100u * 70u * 4u);
  EXPECT_EQ(c.draws[0].fragments_shaded, 100u * 70u);
  for (const glm::vec4& p : rt.pixels) ASSERT_EQ(p, glm::vec4(1.0f));
}

// Two full-target layers, red then `second_color` (blended by `blend`), in that order.
PassCounters two_layers(RenderTarget& rt, const Mesh& first, const Mesh& second,
                        glm::vec4 second_color, BlendMode blend = BlendMode::kOpaque) {
  RenderPassDesc pass;
  pass.name = "layers";
  pass.color = &rt;
  pass.draws.push_back(flat_draw(first, glm::vec4(1, 0, 0, 1)));
  pass.draws.push_back(flat_draw(second, second_color, blend));
  return Gpu(config(1)).execute(pass);
}

TEST(Raster, HiddenSurfaceRemovalShadesOnlyVisibleFragments) {
  RenderTarget rt("rt", 96, 64, TexelFormat::kRGBA8);
  const Mesh back = grid_mesh(1, 0.8f, 0.0f, 1), front = grid_mesh(1, 0.2f, 0.0f, 1);
  // Back to front: the worst case for an immediate-mode GPU, free for deferred HSR.
  const PassCounters c = two_layers(rt, back, front, glm::vec4(0, 1, 0, 1));
  EXPECT_EQ(c.fragments_depth_tested, 2u * 96u * 64u);
  EXPECT_EQ(c.fragments_shaded, 96u * 64u);
  EXPECT_EQ(c.draws[0].fragments_shaded, 0u);
  EXPECT_EQ(c.draws[1].fragments_shaded, 96u * 64u);
  EXPECT_EQ(c.hsr_flushes, 0u);
  EXPECT_EQ(rt.at(50, 30), glm::vec4(0, 1, 0, 1));
}

// What an early-Z GPU without deferred HSR would shade (DrawFragments::fragments_early_z):
// back to front both layers pass the depth test as they arrive, front to back only the front.
TEST(Raster, EarlyZCountFollowsSubmissionOrder) {
  const Mesh back = grid_mesh(1, 0.8f, 0.0f, 1), front = grid_mesh(1, 0.2f, 0.0f, 1);
  const auto early_z = [&](const Mesh& first, const Mesh& second) {
    RenderTarget rt("rt", 96, 64, TexelFormat::kRGBA8);
    const PassCounters c = two_layers(rt, first, second, glm::vec4(0, 1, 0, 1));
    std::uint64_t passed = 0, shaded = 0;
    for (const TileCounters& t : c.tiles) {
      for (const DrawFragments& df : t.shaded_by_draw) {
        passed += df.fragments_early_z;
        shaded += df.fragments_shaded;
      }
    }
    EXPECT_EQ(shaded, 96u * 64u);  // deferred HSR: the front layer either way
    return passed;
  };
  EXPECT_EQ(early_z(back, front), 2u * 96u * 64u);
  EXPECT_EQ(early_z(front, back), 96u * 64u);
}

TEST(Raster, BlendingDefeatsHiddenSurfaceRemoval) {
  RenderTarget rt("rt", 64, 64, TexelFormat::kRGBA8);
  const Mesh back = grid_mesh(1, 0.8f, 0.0f, 1), front = grid_mesh(1, 0.2f, 0.0f, 1);
  const PassCounters c = two_layers(rt, back, front, glm::vec4(0, 0, 1, 0.5f), BlendMode::kAlpha);
  EXPECT_EQ(c.fragments_shaded, 2u * 64u * 64u);
  EXPECT_EQ(c.fragments_blended, 64u * 64u);
  EXPECT_EQ(c.hsr_flushes, 4u);  // one per tile, before its first blended triangle
  const glm::vec4 p = rt.at(10, 10);
  EXPECT_NEAR(p.r, 0.5f, 1.0f / 255);
  EXPECT_NEAR(p.b, 0.5f, 1.0f / 255);
}

TEST(Raster, SharedEdgesTouchEveryPixelExactlyOnce) {
  RenderTarget rt("rt", 157, 93, TexelFormat::kRGBA32F);
  const Mesh mesh = grid_mesh(17, 0.5f, 0.2f, 7);  // jitter small enough not to fold
  RenderPassDesc pass;
  pass.name = "edges";
  pass.color = &rt;
  DrawCall d = flat_draw(mesh, glm::vec4(1.0f), BlendMode::kAdditive);
  d.depth_test = false;
  d.depth_write = false;
  pass.draws.push_back(d);
  const PassCounters c = Gpu(config(1)).execute(pass);
  EXPECT_EQ(c.fragments_shaded, 157u * 93u);
  for (int y = 0; y < rt.height; ++y) {
    for (int x = 0; x < rt.width; ++x) ASSERT_EQ(rt.at(x, y).r, 1.0f) << x << "," << y;
  }
}

TEST(Raster, BackFacesAreCulledAndCounted) {
  RenderTarget rt("rt", 32, 32, TexelFormat::kRGBA8);
  Mesh quad = grid_mesh(1, 0.5f, 0.0f, 1);
  std::swap(quad.indices[1], quad.indices[2]);  // first triangle now clockwise
  RenderPassDesc pass;
  pass.name = "cull";
  pass.color = &rt;
  pass.draws.push_back(flat_draw(quad, glm::vec4(1.0f)));
  const PassCounters culled = Gpu(config(1)).execute(pass);
  EXPECT_EQ(culled.triangles_culled_backface, 1u);
  EXPECT_EQ(culled.triangles_binned, 1u);
  EXPECT_LT(culled.fragments_shaded, 32u * 32u);
  pass.draws[0].cull = CullMode::kNone;  // both windings drawn: the fill rule still holds
  const PassCounters both = Gpu(config(1)).execute(pass);
  EXPECT_EQ(both.triangles_culled_backface, 0u);
  EXPECT_EQ(both.fragments_shaded, 32u * 32u);
}

TEST(Raster, NearPlaneCrossingTriangleIsClipped) {
  RenderTarget rt("rt", 64, 64, TexelFormat::kRGBA8);
  Mesh tri;
  // PassThroughVS sets w = 1, so z < -1 is in front of the near plane.
  tri.positions = {{-0.5f, -0.5f, -3.0f}, {0.5f, -0.5f, 0.0f}, {0.0f, 0.5f, 0.0f}};
  tri.uvs.assign(3, glm::vec2(0.0f));
  tri.indices = {0, 1, 2};
  RenderPassDesc pass;
  pass.name = "clip";
  pass.color = &rt;
  pass.draws.push_back(flat_draw(tri, glm::vec4(1.0f)));
  const PassCounters c = Gpu(config(1)).execute(pass);
  EXPECT_EQ(c.triangles_clipped, 1u);
  EXPECT_EQ(c.triangles_binned, 2u);  // the clipped quad becomes two triangles
  EXPECT_GT(c.fragments_shaded, 0u);
}

TEST(Raster, LoadKeepsTheTargetWhereNothingIsDrawn) {
  RenderTarget rt("rt", 70, 40, TexelFormat::kRGBA8);
  for (int y = 0; y < rt.height; ++y) {
    for (int x = 0; x < rt.width; ++x) rt.at(x, y) = glm::vec4(x / 255.0f, y / 255.0f, 0, 1);
  }
  const RenderTarget before = rt;
  const Mesh left_half = grid_mesh(1, 0.5f, 0.0f, 1, -1, -1, 0, 1);  // pixels x < 35
  RenderPassDesc pass;
  pass.name = "load";
  pass.color = &rt;
  pass.color_load = LoadOp::kLoad;
  pass.draws.push_back(flat_draw(left_half, glm::vec4(1.0f)));
  const PassCounters c = Gpu(config(2)).execute(pass);
  EXPECT_EQ(c.color_load_bytes, 70u * 40u * 4u);
  for (int y = 0; y < rt.height; ++y) {
    for (int x = 0; x < rt.width; ++x) {
      ASSERT_EQ(rt.at(x, y), x < 35 ? glm::vec4(1.0f) : before.at(x, y)) << x << "," << y;
    }
  }
}

TEST(Raster, RenderAreaLimitsTilesAndResolves) {
  RenderTarget rt("rt", 128, 128, TexelFormat::kRGBA8);
  const Mesh quad = grid_mesh(1, 0.5f, 0.0f, 1);
  RenderPassDesc pass;
  pass.name = "area";
  pass.color = &rt;
  pass.render_area = PixelRect{40, 40, 70, 60};  // snaps to tiles [32,96) x [32,64)
  pass.draws.push_back(flat_draw(quad, glm::vec4(1.0f)));
  const PassCounters c = Gpu(config(1)).execute(pass);
  EXPECT_EQ(c.tiles_rendered, 2u);
  EXPECT_EQ(c.fragments_shaded, 2u * 32u * 32u);
  EXPECT_EQ(c.color_store_bytes, 2u * 32u * 32u * 4u);
  EXPECT_EQ(rt.at(0, 0), glm::vec4(0.0f));
  EXPECT_EQ(rt.at(33, 33), glm::vec4(1.0f));
}

// 4608 triangles: more than one set-up chunk, so varying offsets are rebased when the chunks
// are joined. Texture coordinates map pixel centres to texel centres, so with nearest
// filtering the image is the texture, flipped (v grows up the screen).
TEST(Raster, LargeMeshKeepsEachTrianglesVaryings) {
  constexpr int kTexels = 64;
  std::vector<glm::vec4> texels(kTexels * kTexels);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  for (glm::vec4& t : texels) t = glm::vec4(byte(rng), byte(rng), byte(rng), 255) / 255.0f;
  const Texture2D tex("noise", kTexels, kTexels, texels, TexelFormat::kRGBA8,
                      {Filter::kNearest, Wrap::kClamp}, false);
  const Mesh grid = grid_mesh(48, 0.5f, 0.0f, 1);
  for (int threads : {1, 2}) {
    RenderTarget rt("rt", kTexels, kTexels, TexelFormat::kRGBA8);
    const PassCounters c = Gpu(config(threads)).execute(textured_pass("many", rt, grid, tex));
    EXPECT_EQ(c.triangles_binned, 48u * 48u * 2u);
    EXPECT_EQ(c.fragments_shaded, static_cast<std::uint64_t>(kTexels * kTexels));
    for (int y = 0; y < kTexels; ++y) {
      for (int x = 0; x < kTexels; ++x) {
        ASSERT_EQ(rt.at(x, y), tex.level(0).at(x, kTexels - 1 - y)) << x << "," << y;
      }
    }
  }
}

TEST(Raster, PassSamplingItsOwnTargetIsRejected) {
  RenderTarget rt("feedback", 64, 64, TexelFormat::kRGBA8);
  const Texture2D view = texture_view(rt, {Filter::kBilinear, Wrap::kClamp});
  const Mesh quad = grid_mesh(1, 0.5f, 0.0f, 1);
  try {
    Gpu(config(1)).execute(textured_pass("loop", rt, quad, view));
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("samples its own target 'feedback'"), std::string::npos)
        << e.what();
  }
}

TEST(Raster, ImagesAndCountersIdenticalForAnyThreadCount) {
  std::vector<glm::vec4> texels(64 * 64);
  for (int i = 0; i < 64 * 64; ++i) {
    texels[i] = glm::vec4((i % 64) / 63.0f, (i / 64) / 63.0f, ((i * 37) % 17) / 16.0f, 1.0f);
  }
  const Texture2D tex("checker", 64, 64, texels, TexelFormat::kRGBA8, {}, true);
  const Mesh back = grid_mesh(9, 0.7f, 0.4f, 3);
  const Mesh front = grid_mesh(13, 0.3f, 0.4f, 5, -0.6f, -0.5f, 0.7f, 0.8f);

  auto render = [&](int threads, std::vector<glm::vec4>& pixels) {
    RenderTarget rt("rt", 301, 187, TexelFormat::kRGBA8);
    RenderPassDesc pass;
    pass.name = "determinism";
    pass.color = &rt;
    for (const Mesh* m : {&back, &front}) {
      DrawCall d;
      d.geometry = m->geometry();
      d.vertex_program = make_vertex_program<PassThroughVS>({});
      d.fragment_program = make_fragment_program<TexturedFS>({});
      d.textures.textures[0] = &tex;
      pass.draws.push_back(d);
    }
    const PassCounters c = Gpu(config(threads)).execute(pass);
    pixels = rt.pixels;
    return c;
  };
  // 8 host threads: more than the 4 emulated cores, so tiles of one core shade at once. TBB
  // caps a process at the machine's hardware threads unless told otherwise, and would run
  // "8" as 2 on a 2-core machine.
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 8);
  std::vector<glm::vec4> p1, p2, p4, p8;
  const PassCounters c1 = render(1, p1), c2 = render(2, p2), c4 = render(4, p4), c8 = render(8, p8);
  EXPECT_EQ(p1, p2);
  EXPECT_EQ(p1, p4);
  EXPECT_EQ(p1, p8);
  for (const PassCounters* c : {&c2, &c4, &c8}) {
    EXPECT_TRUE(*c == c1) << first_counter_difference(*c, c1);
  }
  EXPECT_GT(c1.texture.cache_misses, 0u);
  EXPECT_EQ(c1.texture.samples(), c1.fragments_shaded);
}

// Each core's cache is warm from one of its tiles to the next, whichever host threads shaded
// them and replayed their logs: a texture of 4 cache lines, all of which each core's tiles
// sample, misses 4 times per core over 48 tiles (the compulsory misses).
TEST(Raster, EachCoresCacheStaysWarmFromTileToTileOnAnyThreadCount) {
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 8);
  std::vector<glm::vec4> texels(8 * 8, glm::vec4(0.5f));  // RGBA8, twiddled: 256 B, 4 lines
  const Texture2D tex("small", 8, 8, texels, TexelFormat::kRGBA8, {Filter::kNearest, Wrap::kRepeat},
                      false);
  const Mesh quad = grid_mesh(1, 0.5f, 0.0f, 1);
  for (int cores : {1, 2}) {
    for (int threads : {1, 8}) {
      GpuConfig c = config(threads);
      c.cores = cores;
      c.tile_size = 8;
      RenderTarget rt("rt", 64, 48, TexelFormat::kRGBA8);  // 8x6 tiles of 8x8 pixels
      const PassCounters counted = Gpu(c).execute(textured_pass("warm", rt, quad, tex));
      std::vector<std::uint64_t> misses(cores, 0);
      for (const TileCounters& t : counted.tiles) misses[t.core] += t.texture.cache_misses;
      EXPECT_EQ(misses, std::vector<std::uint64_t>(cores, 4u)) << cores << " cores, " << threads;
      EXPECT_EQ(counted.texture.cache_line_accesses, 64u * 48u);
    }
  }
}

}  // namespace
}  // namespace skinsim::sim
