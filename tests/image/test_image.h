// Deterministic synthetic test images for the image, metric and driver tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "image/image.h"

namespace skinsim::image::testing {

// Smooth gradients plus a sinusoidal pattern: structure for SSIM and FLIP to see.
inline Image pattern_image(int width, int height) {
  Image image = Image::filled(width, height, glm::vec3(0.0f));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float u = static_cast<float>(x) / width;
      const float v = static_cast<float>(y) / height;
      const float wave = 0.5f + 0.25f * std::sin(0.35f * x) * std::cos(0.21f * y);
      image.at(x, y) = glm::vec3(0.2f + 0.6f * u, wave, 0.3f + 0.4f * v);
    }
  }
  return image;
}

// Adds zero-mean uniform noise of the given amplitude, clamped to [0,1]; fixed seed.
inline Image add_noise(const Image& image, float amplitude, std::uint32_t seed = 7) {
  std::mt19937 random(seed);
  Image out = image;
  for (glm::vec3& p : out.rgb) {
    for (int c = 0; c < 3; ++c) {
      const float unit = static_cast<float>(random()) / 4294967296.0f;  // [0,1)
      p[c] = std::clamp(p[c] + amplitude * (2.0f * unit - 1.0f), 0.0f, 1.0f);
    }
  }
  return out;
}

// 3x3 box blur with clamped borders.
inline Image box_blur(const Image& image) {
  Image out = image;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      glm::vec3 sum(0.0f);
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          sum += image.at(std::clamp(x + dx, 0, image.width - 1),
                          std::clamp(y + dy, 0, image.height - 1));
        }
      }
      out.at(x, y) = sum / 9.0f;
    }
  }
  return out;
}

}  // namespace skinsim::image::testing
