// 8-bit channel conversions (util/unorm8.h): the four-at-a-time path gives every float the byte
// the one-by-one function gives it.
#include "util/unorm8.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <bit>
#include <cstdint>
#include <vector>

namespace skinsim {
namespace {

// All 2^32 bit patterns: NaNs, infinities, denormals, -0 and every value near a rounding
// boundary included. Blocks start at offsets 0, 1 or 2, so the one-by-one tail runs too, and
// every other block also takes the bytes' values.
TEST(Unorm8, EveryFloatGetsTheOneByOneByte) {
  constexpr std::uint64_t kBlock = std::uint64_t{1} << 20;
  std::atomic<std::uint64_t> mismatches{0};
  std::atomic<std::uint32_t> first_mismatch{0};
  tbb::parallel_for(std::uint64_t{0}, (std::uint64_t{1} << 32) / kBlock, [&](std::uint64_t b) {
    std::vector<float> values(kBlock);
    for (std::uint64_t i = 0; i < kBlock; ++i) {
      values[i] = std::bit_cast<float>(static_cast<std::uint32_t>(b * kBlock + i));
    }
    std::vector<std::uint8_t> bytes(kBlock);
    std::vector<float> rounded(kBlock);
    const std::size_t skew = b % 3;  // 0, 1 or 2 values converted one by one first
    for (std::size_t i = 0; i < skew; ++i) bytes[i] = unorm8_nearest(values[i]);
    for (std::size_t i = 0; i < skew; ++i) rounded[i] = kUnorm8Value[bytes[i]];
    unorm8_nearest(values.data() + skew, kBlock - skew, bytes.data() + skew,
                   b % 2 ? rounded.data() + skew : nullptr);
    for (std::uint64_t i = 0; i < kBlock; ++i) {
      const std::uint8_t byte = unorm8_nearest(values[i]);
      if (bytes[i] != byte || (b % 2 && std::bit_cast<std::uint32_t>(rounded[i]) !=
                                            std::bit_cast<std::uint32_t>(kUnorm8Value[byte]))) {
        if (mismatches.fetch_add(1) == 0) first_mismatch = std::bit_cast<std::uint32_t>(values[i]);
      }
    }
  });
  EXPECT_EQ(mismatches.load(), 0u) << "first at bit pattern " << std::hex << first_mismatch.load();
}

TEST(Unorm8, BoundariesAndSpecialValues) {
  const std::vector<float> values = {-1.0f,
                                     -0.0f,
                                     0.0f,
                                     0.49999997f / 255.0f,
                                     0.5f / 255.0f,
                                     127.5f / 255.0f,
                                     254.5f / 255.0f,
                                     0.99999994f,
                                     1.0f,
                                     2.0f,
                                     std::bit_cast<float>(0x7fc00000u)};
  const std::vector<std::uint8_t> expected = {0, 0, 0, 0, 1, 128, 255, 255, 255, 255, 0};
  for (const std::size_t copies : {std::size_t{1}, std::size_t{2}}) {  // the tail, then 16 at once
    std::vector<float> many;
    std::vector<std::uint8_t> want;
    for (std::size_t c = 0; c < copies; ++c) {
      many.insert(many.end(), values.begin(), values.end());
      want.insert(want.end(), expected.begin(), expected.end());
    }
    std::vector<std::uint8_t> bytes(many.size());
    unorm8_nearest(many.data(), many.size(), bytes.data());
    EXPECT_EQ(bytes, want);
  }
}

}  // namespace
}  // namespace skinsim
