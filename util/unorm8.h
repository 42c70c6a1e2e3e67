// 8-bit unsigned normalised channels as skinsim holds them: byte k is the float k / 255, and a
// float is stored as its nearest byte. The emulator's quantize stores RGBA8 targets and
// textures as these values, the pass memo keeps such targets as their bytes, PNGs are written
// with the nearest bytes, and quality::load_png decodes 8-bit images to these values, so a
// frame read back from its PNG is the very frame that was written.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
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
