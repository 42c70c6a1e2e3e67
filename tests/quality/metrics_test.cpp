#include "quality/metrics.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <limits>
#include <span>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "quality/error.h"
#include "quality/separable_stream.h"
#include "tests/image/test_image.h"
#include "util/simd_dispatch.h"

namespace skinsim::quality {
namespace {

using image::Image;
using image::Mask;
using image::ScalarMap;
using image::testing::add_noise;
using image::testing::box_blur;
using image::testing::pattern_image;

// A reference/test pair with noise and a red square, stored as 8-bit values (as the PNGs the
// external cross-checks below read).
std::pair<Image, Image> cross_check_pair() {
  const Image reference = pattern_image(80, 60);
  Image test = add_noise(reference, 0.1f);
  for (int y = 20; y < 40; ++y) {
    for (int x = 30; x < 50; ++x) test.at(x, y) = glm::vec3(0.9f, 0.2f, 0.1f);
  }
  const auto eight_bit = [](Image image) {
    for (glm::vec3& p : image.rgb) p = glm::round(glm::clamp(p, 0.0f, 1.0f) * 255.0f) / 255.0f;
    return image;
  };
  return {eight_bit(test), eight_bit(reference)};
}

TEST(Psnr, IdenticalImagesGiveInfinity) {
  const Image image = pattern_image(64, 48);
  EXPECT_EQ(psnr(image, image), std::numeric_limits<double>::infinity());
}

TEST(Psnr, UniformOffsetGivesMinus20Log10) {
  const Image reference = Image::filled(40, 30, glm::vec3(0.25f, 0.5f, 0.625f));
  for (float d : {0.5f, 0.125f, 0.0078125f}) {
    Image test = reference;
    for (glm::vec3& p : test.rgb) p += glm::vec3(d);
    EXPECT_NEAR(psnr(test, reference), -20.0 * std::log10(static_cast<double>(d)), 1e-9)
        << "offset " << d;
  }
}

TEST(Psnr, MaskRestrictsTheStatistic) {
  const Image reference = pattern_image(64, 48);
  Image test = reference;
  Mask mask = Mask::filled(64, 48, 0);
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (x < 32)
        test.at(x, y) += glm::vec3(0.1f);  // changed, but masked out
      else
        mask.values[y * 64 + x] = 1;
    }
  }
  EXPECT_EQ(psnr(test, reference, &mask), std::numeric_limits<double>::infinity());
  EXPECT_LT(psnr(test, reference), 30.0);
}

TEST(Ssim, IdenticalImagesGiveOne) {
  const Image image = pattern_image(64, 48);
  ScalarMap map;
  EXPECT_EQ(ssim(image, image, nullptr, &map), 1.0);
  ASSERT_EQ(map.values.size(), 64u * 48u);
  for (float v : map.values) ASSERT_EQ(v, 1.0f);
}

TEST(Ssim, MoreNoiseLowersSsim) {
  const Image reference = pattern_image(96, 64);
  const double low = ssim(add_noise(reference, 0.02f), reference);
  const double mid = ssim(add_noise(reference, 0.08f), reference);
  const double high = ssim(add_noise(reference, 0.25f), reference);
  EXPECT_LT(low, 1.0);
  EXPECT_GT(low, mid);
  EXPECT_GT(mid, high);
}

TEST(Ssim, MatchesADoublePrecisionTranscription) {
  // Expected values from numpy: Wang et al.'s SSIM with a full 11x11 window, edge padding and
  // double precision. Float window sums differ by a few 1e-5.
  const auto [test, reference] = cross_check_pair();
  ScalarMap map;
  EXPECT_NEAR(ssim(test, reference, nullptr, &map), 0.69295365, 1e-5);
  EXPECT_NEAR(map.values[30 * 80 + 40], 0.48870886, 1e-4);
  EXPECT_NEAR(map.values[10 * 80 + 10], 0.82046652, 1e-4);
  EXPECT_NEAR(map.values[0], 0.84965609, 1e-4);
}

TEST(Ssim, BlurLowersSsim) {
  const Image reference = pattern_image(96, 64);
  const double blurred = ssim(box_blur(reference), reference);
  EXPECT_LT(blurred, 0.999);
  EXPECT_GT(blurred, 0.0);
}

TEST(Ssim, MaskRestrictsTheStatistic) {
  const Image reference = pattern_image(96, 64);
  Image test = reference;
  const Image noisy = add_noise(reference, 0.2f);
  Mask mask = Mask::filled(96, 64, 0);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 96; ++x) {
      if (x < 40) test.at(x, y) = noisy.at(x, y);
      if (x >= 46) mask.values[y * 96 + x] = 1;  // beyond the 5-pixel window radius
    }
  }
  EXPECT_EQ(ssim(test, reference, &mask), 1.0);
  EXPECT_LT(ssim(test, reference), 0.9);
  // The mask changes only the mean: one map gives both means, to the last bit.
  ScalarMap map;
  const double whole = ssim(test, reference, nullptr, &map);
  EXPECT_EQ(whole, map_mean(map));
  Mask half = Mask::filled(96, 64, 0);
  for (int y = 0; y < 64; ++y) {
    for (int x = 20; x < 70; ++x) half.values[y * 96 + x] = 1;
  }
  EXPECT_EQ(ssim(test, reference, &half), map_mean(map, &half));
  EXPECT_LT(map_mean(map, &half), 0.95);
}

// A stream restricted to wanted columns computes those values exactly as the whole-image
// stream does (FLIP restricts itself to the pixels near a difference), asks its source only
// for what they read, and skips chunks of rows that want nothing.
TEST(SeparableStream, WantedColumnsGiveTheWholeImagesValuesToTheLastBit) {
  const int w = 300, h = 400;
  SeparableStream stream{w, h, 2, {}, {}, {}};
  stream.row_filters = {{0, gaussian_kernel(2.0, 6)}, {1, {0.25f, -1.0f, 0.5f}}};
  stream.column_filters = {{0, gaussian_kernel(1.5, 4)}, {1, {0.5f, 0.25f, 0.125f, 1.0f, 3.0f}}};
  const auto value = [](int c, int x, int y) {
    return std::sin(0.37f * static_cast<float>(x * (c + 1)) + 0.11f * static_cast<float>(y)) +
           0.001f * static_cast<float>((x * 7919 + y * 104729 + c) % 1000);
  };
  std::vector<Columns> asked(h);  // the source columns asked for, per row
  const auto source = [&](int y, Columns columns, std::span<float* const> rows) {
    asked[y] = columns;
    for (int c = 0; c < 2; ++c) {
      for (int x = 0; x < w; ++x) rows[c][x] = std::nanf("");  // unasked columns are garbage
      for (int x = columns.begin; x < columns.end; ++x) rows[c][x] = value(c, x, y);
    }
  };
  const auto run = [&](std::vector<std::vector<float>>& out) {
    out.assign(2, std::vector<float>(static_cast<std::size_t>(w) * h, -1.0f));
    run_separable_stream(stream, source,
                         [&](int y, Columns columns, std::span<const float* const> filtered) {
                           for (int f = 0; f < 2; ++f) {
                             for (int x = columns.begin; x < columns.end; ++x) {
                               out[f][static_cast<std::size_t>(y) * w + x] = filtered[f][x];
                             }
                           }
                         });
  };
  std::vector<std::vector<float>> whole, restricted;
  run(whole);
  // Rows 0-127 (the first chunk) want nothing; below, columns that wander within a chunk: in
  // the middle, at the right edge, at the left edge.
  stream.wanted.assign(h, Columns{});
  for (int y = 128; y < 256; ++y) stream.wanted[y] = {100 + y % 20, 140 + y % 20};
  for (int y = 256; y < 384; ++y) stream.wanted[y] = {w - 40 + y % 10, w};
  for (int y = 384; y < h; ++y) stream.wanted[y] = {0, 10 + y % 5};
  std::fill(asked.begin(), asked.end(), Columns{-1, -1});
  run(restricted);
  for (int y = 0; y < h; ++y) {
    for (int x = stream.wanted[y].begin; x < stream.wanted[y].end; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      for (int f = 0; f < 2; ++f) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(restricted[f][i]),
                  std::bit_cast<std::uint32_t>(whole[f][i]))
            << "filter " << f << " at (" << x << ", " << y << ")";
      }
    }
  }
  // The first chunk (rows 0-127, and the source rows only its own filters read) was skipped.
  for (int y = 0; y < 100; ++y) EXPECT_EQ(asked[y].begin, -1) << "row " << y;
  EXPECT_EQ(restricted[0][0], -1.0f);
  EXPECT_THROW(
      {
        stream.wanted.resize(h - 1);
        run(restricted);
      },
      std::invalid_argument);
}

TEST(Flip, IdenticalImagesGiveZero) {
  const Image image = pattern_image(64, 48);
  const FlipResult result = flip(image, image);
  EXPECT_EQ(result.mean, 0.0);
  for (float v : result.map.values) ASSERT_EQ(v, 0.0f);
}

TEST(Flip, PreparedFeaturesGiveTheSameMapToTheLastBit) {
  const Image reference = pattern_image(96, 64);
  const Image test = add_noise(reference, 0.1f);
  Mask mask = Mask::filled(96, 64, 0);
  for (int y = 10; y < 50; ++y) {
    for (int x = 5; x < 80; ++x) mask.values[y * 96 + x] = 1;
  }
  const FlipParams params{30.0};
  const FlipResult direct = flip(test, reference, &mask, params);
  const FlipResult prepared = flip(test, FlipFeatures(reference, params), &mask);
  EXPECT_GT(direct.mean, 0.01);
  EXPECT_EQ(prepared.mean, direct.mean);
  EXPECT_EQ(prepared.map.values, direct.map.values);
  EXPECT_THROW(flip(pattern_image(64, 64), FlipFeatures(reference)), QualityError);
}

TEST(Flip, OneChangedPixelReachesExactlyTheFiltersRadius) {
  // At the default 67 pixels per degree the widest filters (the CSFs) reach 10 pixels: the
  // error is above 0 out to 10 pixels from a changed pixel, along each axis and at the
  // corner, and exactly 0 beyond (where FLIP skips the pixels whose windows are identical).
  const Image reference = Image::filled(64, 64, glm::vec3(0.5f));
  Image test = reference;
  test.at(32, 32) = glm::vec3(0.9f, 0.2f, 0.4f);
  for (const FlipResult& r : {flip(test, reference), flip(test, FlipFeatures(reference))}) {
    const auto at = [&](int x, int y) { return r.map.values[y * 64 + x]; };
    EXPECT_GT(at(32, 32), 0.1f);
    EXPECT_GT(at(42, 32), 0.0f);
    EXPECT_GT(at(32, 22), 0.0f);
    EXPECT_GT(at(42, 42), 0.0f);
    EXPECT_EQ(at(43, 32), 0.0f);
    EXPECT_EQ(at(32, 21), 0.0f);
    EXPECT_EQ(at(43, 43), 0.0f);
  }
}

TEST(Flip, DefaultPixelsPerDegreeIsThePapers) {
  EXPECT_NEAR(FlipParams{}.pixels_per_degree, 67.0206, 1e-3);
}

TEST(Flip, MatchesTheReferenceImplementation) {
  // Expected values from a direct numpy transcription of NVIDIA's reference flip.py (HPG 2020
  // release: full 2D kernels, edge padding, double precision) run on this pair.
  const auto [test, reference] = cross_check_pair();
  const FlipResult result = flip(test, reference);
  EXPECT_NEAR(result.mean, 0.1896695005, 1e-5);
  const auto at = [&](int x, int y) { return result.map.values[y * 80 + x]; };
  EXPECT_NEAR(at(40, 30), 0.9745243265, 1e-5);  // inside the red square
  EXPECT_NEAR(at(10, 10), 0.1934600509, 1e-5);  // noise only
  EXPECT_NEAR(at(29, 20), 0.4381095097, 1e-5);  // at the square's corner
  EXPECT_NEAR(at(79, 59), 0.2234533640, 1e-5);  // image corner (edge padding)
}

// The sRGB-encoded grey of CIE lightness L* (D65 white, Y = ((L* + 16) / 116)^3 above the
// linear toe).
float srgb_grey_of_lightness(double l_star) {
  const double y = std::pow((l_star + 16.0) / 116.0, 3.0);
  return static_cast<float>(y <= 0.0031308 ? 12.92 * y : 1.055 * std::pow(y, 1.0 / 2.4) - 0.055);
}

TEST(FlipVisibility, ThresholdIsWhatAOneJndLightnessStepGivesInAUniformRegion) {
  // Two flat greys 2.3 L* apart (Mahy et al.'s JND), as 16-bit-exact floats: FLIP's map in
  // the middle, far from the border, is the threshold.
  const Image darker = Image::filled(64, 64, glm::vec3(srgb_grey_of_lightness(60.0)));
  const Image lighter = Image::filled(64, 64, glm::vec3(srgb_grey_of_lightness(62.3)));
  const FlipResult result = flip(darker, lighter);
  EXPECT_NEAR(result.map.values[32 * 64 + 32], flip_visibility_threshold(), 2e-3);
  EXPECT_NEAR(flip_visibility_threshold(), 0.103, 0.002);
  // A step of half a JND is below it, two JNDs above.
  const Image half = Image::filled(64, 64, glm::vec3(srgb_grey_of_lightness(61.15)));
  const Image twice = Image::filled(64, 64, glm::vec3(srgb_grey_of_lightness(64.6)));
  EXPECT_LT(flip(darker, half).map.values[32 * 64 + 32], flip_visibility_threshold());
  EXPECT_GT(flip(darker, twice).map.values[32 * 64 + 32], flip_visibility_threshold());
}

TEST(FlipVisibility, AreaIsOneDigitSquaredAtTheObserversResolution) {
  EXPECT_NEAR(flip_visible_area_pixels(), std::pow(0.082 * FlipParams{}.pixels_per_degree, 2.0),
              1e-9);
  FlipParams closer;
  closer.pixels_per_degree = 30.0;
  EXPECT_NEAR(flip_visible_area_pixels(closer), 0.082 * 0.082 * 900.0, 1e-9);
}

TEST(FlipVisibility, StatisticsCountPercentilesAndVisiblePixelsUnderTheMask) {
  ScalarMap map{10, 10, std::vector<float>(100, 0.05f)};
  for (int i = 0; i < 40; ++i) map.values[i] = 0.5f;  // the top four rows clearly visible
  Mask mask = Mask::filled(10, 10, 1);
  for (int i = 0; i < 20; ++i) mask.values[i] = 0;  // two of those rows are not skin
  const FlipStatistics s = flip_statistics(map, &mask);
  EXPECT_EQ(s.pixels, 80u);
  EXPECT_EQ(s.visible_pixels, 20u);
  EXPECT_DOUBLE_EQ(s.visible_percent(), 25.0);
  EXPECT_NEAR(s.mean, (20 * 0.5 + 60 * 0.05) / 80.0, 1e-6);
  EXPECT_FLOAT_EQ(static_cast<float>(s.p95), 0.5f);
  EXPECT_FALSE(s.visible());  // 20 pixels: less than one digit's area (~30)
  const FlipStatistics all = flip_statistics(map);
  EXPECT_EQ(all.visible_pixels, 40u);
  EXPECT_TRUE(all.visible());
  EXPECT_FLOAT_EQ(static_cast<float>(all.p95), 0.5f);
  EXPECT_FLOAT_EQ(
      static_cast<float>(flip_statistics(ScalarMap{10, 10, std::vector<float>(100, 0.05f)}).p99),
      0.05f);
  EXPECT_THROW(flip_statistics(map, &(mask = Mask::filled(5, 5, 1))), QualityError);
}

TEST(Flip, BlackVersusWhiteIsNearOne) {
  const Image black = Image::filled(48, 48, glm::vec3(0.0f));
  const Image white = Image::filled(48, 48, glm::vec3(1.0f));
  const FlipResult result = flip(black, white);
  EXPECT_GT(result.mean, 0.9);
  EXPECT_LE(result.mean, 1.0);
}

TEST(Flip, MoreNoiseRaisesError) {
  const Image reference = pattern_image(96, 64);
  const double low = flip(add_noise(reference, 0.02f), reference).mean;
  const double mid = flip(add_noise(reference, 0.08f), reference).mean;
  const double high = flip(add_noise(reference, 0.25f), reference).mean;
  EXPECT_GT(low, 0.0);
  EXPECT_LT(low, mid);
  EXPECT_LT(mid, high);
}

TEST(Flip, BiggerColourShiftBiggerError) {
  const Image reference = pattern_image(64, 48);
  double previous = 0.0;
  for (float shift : {0.02f, 0.06f, 0.15f, 0.3f}) {
    Image test = reference;
    for (glm::vec3& p : test.rgb) p.r = std::min(1.0f, p.r + shift);
    const double error = flip(test, reference).mean;
    EXPECT_GT(error, previous) << "red shift " << shift;
    // The magnitude does not depend much on which image is the reference.
    EXPECT_NEAR(flip(reference, test).mean, error, 0.25 * error) << "red shift " << shift;
    previous = error;
  }
}

TEST(Flip, MaskRestrictsTheStatistic) {
  const Image reference = pattern_image(128, 48);
  Image test = reference;
  Mask mask = Mask::filled(128, 48, 0);
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 128; ++x) {
      if (x < 40) test.at(x, y) = glm::vec3(1.0f) - reference.at(x, y);
      if (x >= 80) mask.values[y * 128 + x] = 1;  // beyond the filters' reach (about 10 px)
    }
  }
  EXPECT_EQ(flip(test, reference, &mask).mean, 0.0);
  EXPECT_GT(flip(test, reference).mean, 0.1);
}

TEST(Metrics, ResultsDoNotDependOnThreadCount) {
  const Image reference = pattern_image(200, 150);
  const Image test = add_noise(reference, 0.1f);
  FlipResult one_thread;
  ScalarMap ssim_one;
  double ssim_mean_one = 0.0;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one_thread = flip(test, reference);
    ssim_mean_one = ssim(test, reference, nullptr, &ssim_one);
  }
  const FlipResult many = flip(test, reference);
  ScalarMap ssim_many;
  const double ssim_mean_many = ssim(test, reference, nullptr, &ssim_many);
  EXPECT_EQ(one_thread.mean, many.mean);
  EXPECT_EQ(one_thread.map.values, many.map.values);
  EXPECT_EQ(ssim_mean_one, ssim_mean_many);
  EXPECT_EQ(ssim_one.values, ssim_many.values);
}

TEST(Metrics, ImagesSmallerThanTheFiltersWork) {
  for (auto [w, h] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{2, 17}}) {
    const Image reference = pattern_image(w, h);
    const Image test = add_noise(reference, 0.3f);
    EXPECT_TRUE(std::isfinite(psnr(test, reference)));
    const double s = ssim(test, reference);
    EXPECT_GT(s, -1.0);
    EXPECT_LT(s, 1.0);
    const double f = flip(test, reference).mean;
    EXPECT_GT(f, 0.0);
    EXPECT_LE(f, 1.0);
  }
}

TEST(Metrics, BadInputNamesTheProblem) {
  const Image a = pattern_image(32, 32);
  const Image b = pattern_image(32, 16);
  try {
    psnr(a, b);
    FAIL() << "size mismatch accepted";
  } catch (const QualityError& e) {
    EXPECT_NE(std::string(e.what()).find("32x16"), std::string::npos) << e.what();
  }
  const Mask empty = Mask::filled(32, 32, 0);
  EXPECT_THROW(ssim(a, a, &empty), QualityError);
  const Mask wrong_size = Mask::filled(8, 8, 1);
  EXPECT_THROW(flip(a, a, &wrong_size), QualityError);
  Image nan_image = a;
  nan_image.at(3, 4).g = std::nanf("");
  try {
    flip(nan_image, a);
    FAIL() << "NaN accepted";
  } catch (const QualityError& e) {
    EXPECT_NE(std::string(e.what()).find("(3, 4)"), std::string::npos) << e.what();
  }
  // Over several blocks of pixels checked in parallel, the first bad pixel is named.
  Image large = Image::filled(300, 300, glm::vec3(0.5f));
  large.at(10, 250).b = std::numeric_limits<float>::infinity();
  large.at(200, 5).r = -std::numeric_limits<float>::infinity();
  try {
    psnr(large, Image::filled(300, 300, glm::vec3(0.5f)));
    FAIL() << "infinity accepted";
  } catch (const QualityError& e) {
    EXPECT_NE(std::string(e.what()).find("(200, 5)"), std::string::npos) << e.what();
  }
  Image truncated = a;
  truncated.rgb.pop_back();
  EXPECT_THROW(psnr(truncated, a), QualityError);
  EXPECT_THROW(flip(a, a, nullptr, FlipParams{0.0}), QualityError);
}

// The separable filters (FLIP's and SSIM's) have an AVX path beside the SSE2 baseline, and
// FLIP's per-pixel colour and error work an AVX2 one (util/simd_dispatch.h): every path must
// give the same bits. 301 columns: 64-wide AVX filter blocks, then a 32-wide block and a
// partial group of four in the tail; 37 groups of eight pixels and a partial one of five. The
// left 100 columns of the test equal the reference, so FLIP skips groups there and keeps some
// lanes of the groups near them (the prepared path's near-difference mask).
TEST(SimdPaths, WideAndBaselineGiveTheSameBits) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this processor has no AVX2";
  const Image reference = pattern_image(301, 97);
  Image test = box_blur(add_noise(reference, 0.2f));
  for (int y = 0; y < test.height; ++y) {
    for (int x = 0; x < 100; ++x) test.at(x, y) = reference.at(x, y);
  }
  const auto bits = [](const std::vector<float>& v) {
    std::vector<std::uint32_t> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(),
                   [](float f) { return std::bit_cast<std::uint32_t>(f); });
    return out;
  };
  const auto measure = [&] {
    ScalarMap ssim_map;
    const double ssim_mean = ssim(test, reference, nullptr, &ssim_map);
    const FlipFeatures prepared(reference);
    std::vector<std::uint32_t> planes;
    for (int p = 0; p < FlipFeatures::kPlanes; ++p) {
      const float* plane = prepared.plane(static_cast<FlipFeatures::Plane>(p));
      const std::vector<std::uint32_t> b =
          bits(std::vector<float>(plane, plane + reference.pixel_count()));
      planes.insert(planes.end(), b.begin(), b.end());
    }
    return std::tuple{bits(flip(test, reference).map.values), bits(ssim_map.values),
                      std::bit_cast<std::uint64_t>(ssim_mean), planes,
                      bits(flip(test, prepared).map.values)};
  };
  ASSERT_TRUE(use_avx());
  ASSERT_TRUE(use_avx2());
  const auto wide = measure();
  const auto baseline = [&] {
    const BaselineSimdScope scope;
    EXPECT_FALSE(use_avx());
    EXPECT_FALSE(use_avx2());
    return measure();
  }();
  EXPECT_TRUE(use_avx2());
  EXPECT_EQ(std::get<0>(wide), std::get<0>(baseline)) << "FLIP of two images";
  EXPECT_EQ(std::get<1>(wide), std::get<1>(baseline)) << "SSIM map";
  EXPECT_EQ(std::get<2>(wide), std::get<2>(baseline)) << "SSIM mean";
  EXPECT_EQ(std::get<3>(wide), std::get<3>(baseline)) << "a prepared image's FLIP planes";
  EXPECT_EQ(std::get<4>(wide), std::get<4>(baseline)) << "FLIP against a prepared image";
  // The map is not all zeros, nor all errors: the kept and skipped lanes both occur.
  const std::vector<float> map = flip(test, FlipFeatures(reference)).map.values;
  EXPECT_EQ(map[50], 0.0f);
  EXPECT_GT(map[200], 0.0f);
}

}  // namespace
}  // namespace skinsim::quality
