#include "sim/texture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <random>
#include <utility>

#include "sim/render_target.h"
#include "sim/texture_cache.h"
#include "sim/texture_filtering.h"
#include "sim/texture_unit.h"
#include "util/simd_dispatch.h"

namespace skinsim::sim {
namespace {

TEST(Texture, QuantizesToFormat) {
  EXPECT_EQ(quantize(glm::vec4(0.5f), TexelFormat::kRGBA8), glm::vec4(128.0f / 255.0f));
  EXPECT_EQ(quantize(glm::vec4(2.0f), TexelFormat::kRGBA8), glm::vec4(1.0f));
  EXPECT_EQ(quantize(glm::vec4(std::nanf("")), TexelFormat::kRGBA8), glm::vec4(0.0f));
  EXPECT_EQ(quantize(glm::vec4(-0.3f), TexelFormat::kRGBA8), glm::vec4(0.0f));
  EXPECT_FALSE(std::signbit(quantize(glm::vec4(-0.0f), TexelFormat::kRGBA8).x));
  EXPECT_EQ(quantize(glm::vec4(1.0f / 3.0f), TexelFormat::kRGBA16F).x, 0.333251953125f);
  EXPECT_EQ(quantize(glm::vec4(1e6f), TexelFormat::kRGBA16F).x, 65504.0f);
  EXPECT_EQ(quantize(glm::vec4(0.1f), TexelFormat::kRGBA32F).x, 0.1f);
}

TEST(Texture, Rgba8HoldsEveryByteValueAndRoundsHalvesUp) {
  for (int k = 0; k < 256; ++k) {
    const float byte_value = static_cast<float>(k) / 255.0f;
    ASSERT_EQ(quantize(glm::vec4(byte_value), TexelFormat::kRGBA8), glm::vec4(byte_value)) << k;
    if (k == 255) break;
    const float halfway = (static_cast<float>(k) + 0.5f) / 255.0f;  // rounds half away from 0
    const float next = static_cast<float>(k + 1) / 255.0f;
    const float below = (static_cast<float>(k) + 0.49f) / 255.0f;
    ASSERT_EQ(quantize(glm::vec4(halfway, below, 0.0f, 1.0f), TexelFormat::kRGBA8),
              glm::vec4(next, byte_value, 0.0f, 1.0f))
        << k;
  }
}

TEST(Texture, QuantizesSpansInPlaceLikeSingleValues) {
  std::vector<glm::vec4> values;
  for (int i = 0; i < 600; ++i) values.emplace_back(i / 511.0f - 0.1f, i * 0.37f, -i * 1e-3f, 0.5f);
  for (TexelFormat format : {TexelFormat::kRGBA8, TexelFormat::kRGBA16F, TexelFormat::kRGBA32F}) {
    std::vector<glm::vec4> stored = values;
    quantize_span(stored.data(), stored.data(), stored.size(), format);
    for (size_t i = 0; i < values.size(); ++i) {
      ASSERT_EQ(stored[i], quantize(values[i], format)) << format_name(format) << " value " << i;
    }
  }
}

TEST(Texture, BuildsFullMipChain) {
  const Texture2D t("t", 16, 4, std::vector<glm::vec4>(64, glm::vec4(0.25f)), TexelFormat::kRGBA8,
                    {}, true);
  ASSERT_EQ(t.level_count(), 5);
  EXPECT_EQ(t.level(4).width, 1);
  EXPECT_EQ(t.level(4).height, 1);
  EXPECT_EQ(t.level(2).at(0, 0), quantize(glm::vec4(0.25f), TexelFormat::kRGBA8));
}

TEST(Texture, RenderTargetViewSamplesThePixelsInPlace) {
  RenderTarget rt("rt", 8, 4, TexelFormat::kRGBA16F);
  const Texture2D view = texture_view(rt, {Filter::kTrilinear, Wrap::kClamp});
  EXPECT_EQ(view.level(0).texels, rt.pixels.data());  // no copy
  EXPECT_EQ(view.level_count(), 1);
  EXPECT_EQ(view.sampler().filter, Filter::kBilinear);  // one level: nothing to blend
  EXPECT_EQ(view.format(), TexelFormat::kRGBA16F);
  rt.at(3, 2) = glm::vec4(0.5f);
  EXPECT_EQ(view.level(0).at(3, 2), glm::vec4(0.5f));
}

TEST(Texture, CopiesShareTheirTexels) {
  const Texture2D t("t", 4, 4, std::vector<glm::vec4>(16, glm::vec4(0.25f)), TexelFormat::kRGBA8,
                    {}, true);
  const Texture2D copy = t;
  for (int l = 0; l < t.level_count(); ++l) EXPECT_EQ(copy.level(l).texels, t.level(l).texels);
}

TEST(Texture, RejectsLevelsOfWrongSize) {
  std::vector<MipLevel> levels = {{4, 4, std::vector<glm::vec4>(16)},
                                  {3, 2, std::vector<glm::vec4>(6)}};
  EXPECT_THROW(Texture2D("lut", levels, TexelFormat::kRGBA8, {}), std::invalid_argument);
}

TEST(Texture, CubeCoordinatesFollowOpenGLFaces) {
  EXPECT_EQ(cube_coord({1, 0, 0}).face, 0);
  EXPECT_EQ(cube_coord({-1, 0, 0}).face, 1);
  EXPECT_EQ(cube_coord({0, 1, 0}).face, 2);
  EXPECT_EQ(cube_coord({0, -1, 0}).face, 3);
  EXPECT_EQ(cube_coord({0, 0, 1}).face, 4);
  EXPECT_EQ(cube_coord({0, 0, -1}).face, 5);
  EXPECT_EQ(cube_coord({0, 0, 1}).uv, glm::vec2(0.5f));
}

TEST(TextureFiltering, FloorSplitsBothCoordinates) {
  const auto split = [](float x, float y) { return filtering::floor_split({x, y}); };
  filtering::FloorSplit f = split(2.25f, -0.25f);
  EXPECT_EQ(f.x, 2);
  EXPECT_EQ(f.y, -1);
  EXPECT_EQ(f.fraction_x, 0.25f);
  EXPECT_EQ(f.fraction_y, 0.75f);
  f = split(-3.0f, 0.0f);  // integers split exactly, negative ones too
  EXPECT_EQ(f.x, -3);
  EXPECT_EQ(f.y, 0);
  EXPECT_EQ(f.fraction_x, 0.0f);
  EXPECT_EQ(f.fraction_y, 0.0f);
  f = split(std::nanf(""), 1e20f);  // clamped to +-2^30 texels, NaN to the low end
  EXPECT_EQ(f.x, -(1 << 30));
  EXPECT_EQ(f.y, 1 << 30);
  EXPECT_EQ(f.fraction_x, 0.0f);
  EXPECT_EQ(f.fraction_y, 0.0f);
}

TEST(TextureCache, HitsAfterFillAndEvictsLeastRecentlyUsed) {
  TextureCache cache({256, 64, 2});  // 2 sets x 2 ways
  EXPECT_FALSE(cache.access(0));
  EXPECT_TRUE(cache.access(63));
  EXPECT_FALSE(cache.access(128));  // same set (line 2), second way
  EXPECT_TRUE(cache.access(0));
  EXPECT_FALSE(cache.access(256));  // same set: evicts line 2 (least recent)
  EXPECT_TRUE(cache.access(0));
  EXPECT_FALSE(cache.access(128));
}

// A replayed log gives the hits and misses of accessing its requests live, in order; a
// repeat of the line just requested is not recorded (it is a hit that changes nothing).
TEST(TextureCache, ReplayCountsTheMissesOfAccessingTheLinesInOrder) {
  const std::vector<std::uint64_t> addresses = {0, 63, 128, 0, 256, 300, 0, 128, 128, 256, 0};
  TextureLineLog log(64);
  TextureCache live({256, 64, 2});  // 2 sets x 2 ways
  std::uint64_t live_misses = 0;
  for (const std::uint64_t address : addresses) {
    log.add(log.line_of(address));
    live_misses += !live.access(address);
  }
  EXPECT_EQ(log.lines(), (std::vector<std::uint32_t>{0, 2, 0, 4, 0, 2, 4, 0}));
  TextureCounters counters;
  TextureCache({256, 64, 2}).replay(log, counters);
  EXPECT_EQ(live_misses, 6u);
  EXPECT_EQ(counters.cache_misses, live_misses);
  EXPECT_EQ(counters.dram_bytes, live_misses * 64u);
}

// Least recently used, as the textbook states it: each set a list, most recent first. The
// cache's 4-way sets (a branch-free SIMD update) and its other associativities must agree
// with it on every access of a long random stream that hits and misses in every way.
TEST(TextureCache, EveryAssociativityIsLeastRecentlyUsed) {
  for (const std::uint32_t ways : {1u, 2u, 3u, 4u, 8u}) {
    const std::uint32_t sets = 4;
    TextureCache cache({sets * ways * 64, 64, ways});
    std::vector<std::vector<std::uint32_t>> model(sets);
    std::mt19937 rng(ways);
    std::uniform_int_distribution<std::uint32_t> pick(0, sets * (ways + 2) - 1);
    for (int i = 0; i < 20000; ++i) {
      const std::uint32_t line = pick(rng);
      std::vector<std::uint32_t>& set = model[line % sets];
      const auto found = std::find(set.begin(), set.end(), line);
      const bool hit = found != set.end();
      if (hit) set.erase(found);
      if (set.size() == ways) set.pop_back();
      set.insert(set.begin(), line);
      ASSERT_EQ(cache.access(std::uint64_t{line} * 64), hit) << ways << " ways, access " << i;
    }
  }
}

TEST(TextureCache, RejectsImpossibleGeometry) {
  EXPECT_THROW(TextureCache({1000, 64, 4}), std::invalid_argument);
  EXPECT_THROW(TextureCache({1024, 48, 4}), std::invalid_argument);
}

TEST(TextureCache, ModuloIndexWrapsNonPowerOfTwoSetCount) {
  TextureCache cache({3 * 64, 64, 1, SetIndex::kModulo});  // 3 sets, direct mapped
  EXPECT_FALSE(cache.access(0));
  EXPECT_FALSE(cache.access(64));
  EXPECT_TRUE(cache.access(0));
  EXPECT_FALSE(cache.access(3 * 64));  // line 3 -> set 0: evicts line 0
  EXPECT_FALSE(cache.access(0));
}

TEST(TextureCache, XorFoldNeedsPowerOfTwoSetCount) {
  EXPECT_THROW(TextureCache({3 * 64, 64, 1, SetIndex::kXorFold}), std::invalid_argument);
  EXPECT_NO_THROW(TextureCache({64, 64, 1, SetIndex::kXorFold}));  // one set: nothing to hash
}

// The same offset in two binding regions: one set under modulo, two under XOR folding.
TEST(TextureCache, XorFoldSeparatesSameOffsetInDifferentBindings) {
  const TextureCacheConfig direct{32 * 64, 64, 1};  // 32 sets, direct mapped
  TextureCacheConfig hashed = direct;
  hashed.set_index = SetIndex::kXorFold;
  for (const auto& [config, third_hits] : {std::pair{direct, false}, std::pair{hashed, true}}) {
    TextureCache cache(config);
    EXPECT_FALSE(cache.access(0x40));
    EXPECT_FALSE(cache.access(kBindingAddressStride + 0x40));
    EXPECT_EQ(cache.access(0x40), third_hits);
  }
}

// Within one aligned block of `sets` lines the fold is a permutation: a sequential stream
// still fills every set once, as with modulo.
TEST(TextureCache, XorFoldKeepsSequentialLinesInDistinctSets) {
  TextureCache cache({32 * 64, 64, 1, SetIndex::kXorFold});
  const std::uint64_t base = 5 * kBindingAddressStride;
  for (std::uint64_t line = 0; line < 32; ++line) EXPECT_FALSE(cache.access(base + line * 64));
  for (std::uint64_t line = 0; line < 32; ++line) EXPECT_TRUE(cache.access(base + line * 64));
}

// uv_combine's pattern: six same-size textures read at the same offsets. Their 96 lines
// fit the 128-line cache, but under modulo six lines share each 4-way set and LRU thrashes;
// folding spreads them so the second sweep hits.
TEST(TextureCache, XorFoldRemovesConflictMissesOfSameOffsetStreams) {
  const auto misses = [](SetIndex index) {
    TextureCache cache({8192, 64, 4, index});  // 32 sets x 4 ways, the ipad4 profile
    int n = 0;
    for (int sweep = 0; sweep < 2; ++sweep) {
      for (std::uint64_t line = 0; line < 16; ++line) {
        for (std::uint64_t binding = 0; binding < 6; ++binding) {
          n += !cache.access(binding * kBindingAddressStride + line * 64);
        }
      }
    }
    return n;
  };
  EXPECT_EQ(misses(SetIndex::kModulo), 2 * 96);  // every access misses
  EXPECT_EQ(misses(SetIndex::kXorFold), 96);     // compulsory misses only
}

TEST(TextureUnit, BilinearOfConstantIsConstantAndCountsFootprint) {
  const Texture2D t("t", 8, 8, std::vector<glm::vec4>(64, glm::vec4(0.5f)), TexelFormat::kRGBA8,
                    {Filter::kBilinear, Wrap::kRepeat}, false);
  TextureLineLog lines(64);
  TextureCounters counters;
  ExecTexUnit unit(&lines, &counters);
  TextureBindings b;
  b.textures[0] = &t;
  unit.bind(&b);
  const glm::vec4 v = unit.sample(0, glm::vec2(0.3f, 0.6f));
  TextureCache({8192, 64, 4}).replay(lines, counters);
  EXPECT_EQ(v, quantize(glm::vec4(0.5f), TexelFormat::kRGBA8));
  EXPECT_EQ(counters.samples_by_filter[1], 1u);
  EXPECT_EQ(counters.samples_dependent, 1u);
  EXPECT_EQ(counters.texels_touched, 4u);
  EXPECT_EQ(counters.cache_misses, 1u);  // 8x8 RGBA8 twiddled = 256 B: 2x2 footprint in one line
  EXPECT_EQ(counters.dram_bytes, 64u);
}

TEST(TextureUnit, TrilinearReadsTwoLevels) {
  const Texture2D t("t", 64, 64, std::vector<glm::vec4>(64 * 64, glm::vec4(1.0f)),
                    TexelFormat::kRGBA8, {Filter::kTrilinear, Wrap::kClamp}, true);
  TextureLineLog lines(64);
  TextureCounters counters;
  ExecTexUnit unit(&lines, &counters);
  TextureBindings b;
  b.textures[0] = &t;
  unit.bind(&b);
  Varying<2> uv;
  uv.value = {0.5f, 0.5f};
  uv.ddx = {2.5f / 64, 0};  // ~1.3 levels down
  uv.ddy = {0, 2.5f / 64};
  unit.sample(0, uv);
  EXPECT_EQ(counters.samples_by_filter[2], 1u);
  EXPECT_EQ(counters.samples_dependent, 0u);
  EXPECT_EQ(counters.texels_touched, 8u);
}

// Magnified (lambda <= 0): the blend weight of level 1 is 0. Both levels are still read and
// cached, as on the TMU, and the value is level 0's bilinear one, bit for bit.
TEST(TextureUnit, MagnifiedTrilinearReadsBothLevelsAndReturnsLevelZero) {
  std::vector<glm::vec4> ramp(64 * 64);
  for (int i = 0; i < 64 * 64; ++i)
    ramp[i] = glm::vec4((i % 64) / 63.0f, (i / 64) / 63.0f, 0.25f, 1.0f);
  for (TexelFormat format : {TexelFormat::kRGBA8, TexelFormat::kRGBA16F}) {
    const Texture2D tri("tri", 64, 64, ramp, format, {Filter::kTrilinear, Wrap::kClamp}, true);
    const Texture2D bi("bi", 64, 64, ramp, format, {Filter::kBilinear, Wrap::kClamp}, true);
    TextureLineLog lines(64);
    TextureCounters counters;
    ExecTexUnit unit(&lines, &counters);
    TextureBindings b;
    b.textures[0] = &tri;
    b.textures[1] = &bi;
    unit.bind(&b);
    Varying<2> uv;
    uv.value = {0.30f, 0.393f};  // footprints inside one line at both levels
    uv.ddx = {0.25f / 64, 0};    // 4 pixels per texel
    uv.ddy = {0, 0.25f / 64};
    const glm::vec4 trilinear = unit.sample(0, uv);
    TextureCache({8192, 64, 4}).replay(lines, counters);
    EXPECT_EQ(counters.texels_touched, 8u);
    EXPECT_EQ(lines.lines().size(), 2u);
    EXPECT_EQ(counters.cache_misses, 2u);  // one line in each level
    EXPECT_EQ(trilinear, unit.sample(1, uv));
  }
}

// sample_each gives what as many sample() calls give, bit for bit: values, every counter and
// the cache-line log in order. Over single-level bilinear textures of odd and power-of-two
// sizes, both wraps and both texel sizes, at coordinates inside, across the borders, far
// outside, negative and NaN; in the eight-lane path and the four-lane baseline. A mip-mapped
// texture takes sample() itself.
TEST(TextureUnit, SampleEachIsSampleAfterSample) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> near(-0.3f, 1.3f);
  constexpr int kTaps = 19;  // two full groups of eight and a partial one
  std::vector<std::array<Varying<2>, kTaps>> batches(40);
  for (auto& batch : batches) {
    for (Varying<2>& uv : batch) uv.value = {near(rng), near(rng)};
  }
  batches[0][3].value = {std::nanf(""), 0.5f};
  batches[0][4].value = {-7.25f, 1e9f};
  batches[0][5].value = {0.0f, 1.0f};
  for (const glm::ivec2 size : {glm::ivec2(37, 23), glm::ivec2(64, 32), glm::ivec2(1, 5)}) {
    std::vector<glm::vec4> texels(static_cast<std::size_t>(size.x) * size.y);
    for (glm::vec4& t : texels) t = glm::vec4(near(rng), near(rng), near(rng), near(rng));
    for (const TexelFormat format : {TexelFormat::kRGBA8, TexelFormat::kRGBA16F}) {
      for (const Wrap wrap : {Wrap::kClamp, Wrap::kRepeat}) {
        for (const bool mipmaps : {false, true}) {
          const Texture2D t("t", size.x, size.y, texels, format, {Filter::kBilinear, wrap},
                            mipmaps);
          TextureBindings b;
          b.textures[2] = &t;
          for (const bool baseline : {false, true}) {
            std::optional<BaselineSimdScope> scope;
            if (baseline) scope.emplace();
            TextureLineLog each_lines(64), one_lines(64);
            TextureCounters each_counters, one_counters;
            ExecTexUnit each(&each_lines, &each_counters), one(&one_lines, &one_counters);
            each.bind(&b);
            one.bind(&b);
            const auto expect_bits = [&](const auto& values, int i, const glm::vec4& expected) {
              for (int c = 0; c < 4; ++c) {
                ASSERT_EQ(std::bit_cast<std::uint32_t>(values[i][c]),
                          std::bit_cast<std::uint32_t>(expected[c]))
                    << size.x << "x" << size.y << " tap " << i << " channel " << c;
              }
            };
            for (const auto& batch : batches) {  // independent reads, then dependent ones
              const auto values = each.sample_each<kTaps>(2, [&](int i) { return batch[i]; });
              for (int i = 0; i < kTaps; ++i) expect_bits(values, i, one.sample(2, batch[i]));
              const auto computed =
                  each.sample_each<kTaps>(2, [&](int i) { return batch[i].value; });
              for (int i = 0; i < kTaps; ++i) {
                expect_bits(computed, i, one.sample(2, batch[i].value));
              }
            }
            EXPECT_EQ(each_lines.lines(), one_lines.lines());
            EXPECT_EQ(each_counters.texels_touched, one_counters.texels_touched);
            EXPECT_EQ(each_counters.cache_line_accesses, one_counters.cache_line_accesses);
            for (int f = 0; f < kFilterCount; ++f) {
              EXPECT_EQ(each_counters.samples_by_filter[f], one_counters.samples_by_filter[f]);
            }
            EXPECT_EQ(each_counters.samples_wide_format, one_counters.samples_wide_format);
            EXPECT_EQ(each_counters.samples_dependent, one_counters.samples_dependent);
            EXPECT_EQ(each_counters.samples_dependent, batches.size() * kTaps);
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace skinsim::sim
