// 8-bit unsigned normalised channels as skinsim holds them: byte k is the float k / 255, and a
// float is stored as its nearest byte. The emulator's quantize stores RGBA8 targets and
// textures as these values, the pass memo keeps such targets as their bytes, PNGs are written
// with the nearest bytes, and image::load_png decodes 8-bit images to these values, so a
// frame read back from its PNG is the very frame that was written.
#pragma once

#include <emmintrin.h>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>

namespace skinsim {

inline constexpr std::array<float, 256> kUnorm8Value = [] {
  std::array<float, 256> v{};
  for (int k = 0; k < 256; ++k) v[k] = static_cast<float>(k) / 255.0f;
  return v;
}();

// The byte nearest `v`: clamped to [0,1], halves rounded away from zero (as glm::round and
// lround), NaN to 0 (the D3D10+/Vulkan float-to-UNORM rule; GLES leaves it open). No libm
// call: the scaled value is below 255, where adding 0.5 in double is exact, so truncating it
// rounds as lround does (the same byte for every float, checked exhaustively; in float,
// 0.49999997f + 0.5f would round up to 1).
inline std::uint8_t unorm8_nearest(float v) {
  if (!(v > 0.0f)) return 0;  // NaN, -0 and below
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(static_cast<double>(v * 255.0f) + 0.5);
}

// unorm8_nearest of values[0, count) into bytes[0, count), sixteen at a time: the same byte
// for every float (tests/quality/unorm8_test.cpp checks all 2^32). A frame's PNG is 9.4
// million of these, which one by one took a fifth of writing it (BM_FramePngAndThumbnail).
// Below 255, x - trunc(x) is exact, so trunc(x) + (x - trunc(x) >= 0.5) is trunc(x + 0.5)
// taken exactly, as the one-by-one double addition takes it. With `rounded`, also each byte's
// value (kUnorm8Value: k / 255 correctly rounded, as the division here is).
inline void unorm8_nearest(const float* values, std::size_t count, std::uint8_t* bytes,
                           float* rounded = nullptr) {
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), half = _mm_set1_ps(0.5f);
  const __m128 scale = _mm_set1_ps(255.0f);
  const __m128i top = _mm_set1_epi32(255);
  const auto nearest4 = [&](const float* p) {
    const __m128 v = _mm_loadu_ps(p);
    const __m128 positive = _mm_cmpgt_ps(v, zero);  // false for NaN
    const __m128 saturated = _mm_cmpge_ps(v, one);
    // Lanes out of (0, 1) convert 0 here: their result is chosen below.
    const __m128 x = _mm_and_ps(_mm_mul_ps(v, scale), _mm_andnot_ps(saturated, positive));
    const __m128i whole = _mm_cvttps_epi32(x);
    const __m128 fraction = _mm_sub_ps(x, _mm_cvtepi32_ps(whole));
    const __m128i up = _mm_castps_si128(_mm_cmpge_ps(fraction, half));  // -1 where true
    const __m128i sat = _mm_castps_si128(saturated);
    return _mm_or_si128(_mm_and_si128(sat, top), _mm_sub_epi32(whole, up));
  };
  std::size_t i = 0;
  for (; i + 16 <= count; i += 16) {
    const __m128i k[4] = {nearest4(values + i), nearest4(values + i + 4), nearest4(values + i + 8),
                          nearest4(values + i + 12)};
    const __m128i sixteen =
        _mm_packus_epi16(_mm_packs_epi32(k[0], k[1]), _mm_packs_epi32(k[2], k[3]));  // 0..255
    _mm_storeu_si128(reinterpret_cast<__m128i*>(bytes + i), sixteen);
    if (rounded) {
      for (int q = 0; q < 4; ++q) {
        _mm_storeu_ps(rounded + i + 4 * q, _mm_div_ps(_mm_cvtepi32_ps(k[q]), scale));
      }
    }
  }
  for (; i < count; ++i) {
    bytes[i] = unorm8_nearest(values[i]);
    if (rounded) rounded[i] = kUnorm8Value[bytes[i]];
  }
}

// The byte whose value is `v` bit for bit, or nullopt when `v` is no RGBA8 value (one the
// host wrote, say; -0 included).
inline std::optional<std::uint8_t> unorm8_code(float v) {
  if (!(v >= 0.0f && v <= 1.0f)) return std::nullopt;
  const int k = static_cast<int>(v * 255.0f + 0.5f);
  if (std::bit_cast<std::uint32_t>(kUnorm8Value[k]) != std::bit_cast<std::uint32_t>(v)) {
    return std::nullopt;
  }
  return static_cast<std::uint8_t>(k);
}

}  // namespace skinsim
