// The elementary functions on float lanes FLIP computes with (util/float_lanes.h), against libm
// in double over the ranges FLIP uses them on.
#include "util/float_lanes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

namespace skinsim::quality {
namespace {

// |got - exact| in units of the last place of the float nearest `exact`.
double ulps(float got, double exact) {
  const float nearest = std::abs(static_cast<float>(exact));
  return std::abs(static_cast<double>(got) - exact) / (std::nextafter(nearest, INFINITY) - nearest);
}

TEST(FloatLanes, Log2IsWithinTwoUlpOverEveryNormalFloat) {
  for (std::uint32_t bits = 0x00800000u; bits < 0x7f800000u; bits += 997) {
    const float x = std::bit_cast<float>(bits);
    ASSERT_LE(ulps(log2_lanes(splat(x))[0], std::log2(static_cast<double>(x))), 2.0) << x;
  }
}

TEST(FloatLanes, Exp2IsWithinTwoUlpOverTheNormalRange) {
  for (double y = -126.0; y <= 127.0; y += 1e-4) {
    const float f = static_cast<float>(y);
    ASSERT_LE(ulps(exp2_lanes(splat(f))[0], std::exp2(static_cast<double>(f))), 2.0) << f;
  }
  // Beyond the normal range, clamped rather than infinite or subnormal.
  EXPECT_EQ(exp2_lanes(splat(200.0f))[0], std::exp2(127.0f));
  EXPECT_EQ(exp2_lanes(splat(-200.0f))[0], std::exp2(-126.0f));
}

// CIELAB's f(t) above its linear toe: t in (0.008856, 1].
TEST(FloatLanes, CubeRootIsWithinFourUlpWhereCielabTakesIt) {
  for (double t = 0.008856; t <= 1.0; t += 1e-6) {
    const float f = static_cast<float>(t);
    ASSERT_LE(ulps(cbrt_lanes(splat(f))[0], std::cbrt(static_cast<double>(f))), 4.0) << f;
  }
}

// pow's rounding error grows with |y log2 x|; over FLIP's ranges (HyAB distances to 0.7, and
// colour errors in (0, 1] to powers in [0, 1]) it stays within 1e-6 of the exact value.
TEST(FloatLanes, PowIsWithinOneMillionthOverFlipsRanges) {
  const auto relative = [](float x, float y) {
    const double exact = std::pow(static_cast<double>(x), static_cast<double>(y));
    return std::abs(pow_lanes(splat(x), splat(y))[0] - exact) / exact;
  };
  for (double x = 1e-6; x <= 300.0; x *= 1.00001) {
    ASSERT_LE(relative(static_cast<float>(x), 0.7f), 1e-6) << x;
  }
  for (double x = 1e-4; x <= 1.0; x *= 1.0001) {
    for (int k = 0; k <= 20; ++k) {
      ASSERT_LE(relative(static_cast<float>(x), k / 20.0f), 1e-6) << x << " ^ " << k / 20.0f;
    }
  }
}

TEST(FloatLanes, LanesAreIndependent) {
  const Float4 x = {0.25f, 3.0f, 1e-3f, 77.0f};
  const Float4 together = pow_lanes(x, splat(0.7f));
  for (int lane = 0; lane < 4; ++lane) {
    EXPECT_EQ(together[lane], pow_lanes(splat(x[lane]), splat(0.7f))[0]) << lane;
  }
}

TEST(FloatLanes, PartialLoadsAndStoresTouchOnlyTheirLanes) {
  const float source[3] = {1.0f, 2.0f, 3.0f};
  const Float4 v = load_lanes(source, 3);
  EXPECT_EQ(v[2], 3.0f);
  EXPECT_EQ(v[3], 0.0f);
  float target[4] = {9.0f, 9.0f, 9.0f, 9.0f};
  store_lanes(target, splat(5.0f), 2);
  EXPECT_EQ(target[1], 5.0f);
  EXPECT_EQ(target[2], 9.0f);
}

}  // namespace
}  // namespace skinsim::quality
