#include "quality/error_map.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "image/image.h"
#include "quality/error.h"
#include "quality/json_value.h"

namespace skinsim::quality {
namespace {

TEST(ErrorMap, ColourMapsMatchMatplotlibEndpoints) {
  // matplotlib's _cm_listed tables, first and last entries; the polynomial fits are within
  // 0.02 of them.
  const auto near = [](glm::vec3 a, glm::vec3 b) {
    return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(0.02f)));
  };
  EXPECT_TRUE(near(color_map(ColorMap::kMagma, 0.0f), {0.001462f, 0.000466f, 0.013866f}));
  EXPECT_TRUE(near(color_map(ColorMap::kMagma, 1.0f), {0.987053f, 0.991438f, 0.749504f}));
  EXPECT_TRUE(near(color_map(ColorMap::kViridis, 0.0f), {0.267004f, 0.004874f, 0.329415f}));
  EXPECT_TRUE(near(color_map(ColorMap::kViridis, 1.0f), {0.993248f, 0.906157f, 0.143936f}));
}

TEST(ErrorMap, BrightnessGrowsWithError) {
  for (ColorMap map : {ColorMap::kMagma, ColorMap::kViridis}) {
    float previous = -1.0f;
    for (int i = 0; i <= 20; ++i) {
      const glm::vec3 c = color_map(map, i / 20.0f);
      const float luma = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
      EXPECT_GT(luma, previous) << "t = " << i / 20.0f;
      previous = luma;
    }
  }
}

TEST(ErrorMap, FalseColourKeepsSizeAndClamps) {
  const image::ScalarMap map{3, 1, {-1.0f, 0.5f, 7.0f}};
  const image::Image image = false_colour(map, ColorMap::kViridis);
  ASSERT_EQ(image.width, 3);
  EXPECT_EQ(image.rgb[0], color_map(ColorMap::kViridis, 0.0f));
  EXPECT_EQ(image.rgb[2], color_map(ColorMap::kViridis, 1.0f));
  EXPECT_THROW(false_colour(image::ScalarMap{3, 2, {0.0f}}), QualityError);
}

TEST(ErrorMap, FalseColourIsColorMapBitForBit) {
  // false_colour maps four values at a time, in AVX where the processor has it: every pixel
  // must be the colour color_map gives its value alone in the SSE2 baseline, whatever shares
  // its register, for values across [0,1] at a fine step, the ends, out of range, -0 and NaN,
  // and a last quad cut short (4099 values).
  std::vector<float> values;
  for (int i = 0; i <= 4000; ++i) values.push_back(static_cast<float>(i) / 4000.0f * 1.2f - 0.1f);
  for (const float v :
       {-0.0f, 0.0f, 1.0f, std::nextafter(1.0f, 2.0f), 1e-40f,
        std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity()}) {
    values.push_back(v);
  }
  while (values.size() < 4099) values.push_back(0.3f);
  const image::ScalarMap map{static_cast<int>(values.size()), 1, values};
  for (ColorMap colors : {ColorMap::kMagma, ColorMap::kViridis}) {
    const image::Image image = false_colour(map, colors);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const glm::vec3 expected = color_map(colors, values[i]);
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(image.rgb[i][c]),
                  std::bit_cast<std::uint32_t>(expected[c]))
            << "value " << values[i] << " channel " << c;
      }
    }
  }
}

TEST(JsonValue, InfinityRoundTripsAsString) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(metric_to_json(inf).dump(), "\"inf\"");
  EXPECT_EQ(metric_from_json(metric_to_json(inf)), inf);
  EXPECT_EQ(metric_from_json(metric_to_json(-inf)), -inf);
  EXPECT_TRUE(std::isnan(metric_from_json(metric_to_json(std::nan("")))));
  EXPECT_EQ(metric_from_json(metric_to_json(31.5)), 31.5);
  EXPECT_THROW(metric_from_json(nlohmann::json("big")), nlohmann::json::type_error);
}

}  // namespace
}  // namespace skinsim::quality
