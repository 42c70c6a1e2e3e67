// A render target in (emulated) DRAM: what tiles load from and resolve to.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "sim/texture.h"

namespace skinsim::sim {

struct RenderTarget {
  std::string name;
  int width = 0;
  int height = 0;
  TexelFormat format = TexelFormat::kRGBA8;
  std::vector<glm::vec4> pixels;  // row-major, values as stored (quantised to format)

  RenderTarget() = default;
  RenderTarget(std::string n, int w, int h, TexelFormat f)
      : name(std::move(n)), width(w), height(h), format(f),
        pixels(static_cast<size_t>(w) * h, glm::vec4(0.0f)) {}
  glm::vec4& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const glm::vec4& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// A texture view of a finished render target (the next pass samples it). Single level.
Texture2D as_texture(const RenderTarget& target, SamplerState sampler);

}  // namespace skinsim::sim
