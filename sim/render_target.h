// A render target in (emulated) DRAM: what tiles load from and resolve to.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "sim/texture.h"
#include "util/check.h"

namespace skinsim::sim {

struct RenderTarget {
  std::string name;
  int width = 0;
  int height = 0;
  TexelFormat format = TexelFormat::kRGBA8;
  std::vector<glm::vec4> pixels;  // row-major, values as stored (quantised to format)

  RenderTarget() = default;
  RenderTarget(std::string n, int w, int h, TexelFormat f)
      : name(std::move(n)),
        width(w),
        height(h),
        format(f),
        pixels(static_cast<size_t>(w) * h, glm::vec4(0.0f)) {}
  glm::vec4& at(int x, int y) { return pixels[index(x, y)]; }
  const glm::vec4& at(int x, int y) const { return pixels[index(x, y)]; }

 private:
  size_t index(int x, int y) const {
    SKINSIM_DCHECK_INDEX(x, width);
    SKINSIM_DCHECK_INDEX(y, height);
    return static_cast<size_t>(y) * width + x;
  }
};

// A single-level texture over a finished render target's pixels, for a later pass to sample
// in place (no copy, as on the GPU). The target must outlive the view and keep its size;
// a pass may not render to a target it samples (Gpu::execute rejects that).
Texture2D texture_view(const RenderTarget& target, SamplerState sampler);

}  // namespace skinsim::sim
