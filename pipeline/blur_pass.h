// Pass 2 of the GPU Pro 5 pipeline: one axis of the alpha-masked separable Gaussian over a
// rectangle of the integration buffer (shaders/blur.h), as one render pass.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "sim/counters.h"
#include "sim/gpu.h"
#include "sim/render_target.h"

namespace skinsim::pipeline {

// The depth-aware blur's settings (shaders/blur.h, DepthAwareBlurFS).
struct BlurFollow {
  float codes_per_tolerance = 1.0f;
  bool last_axis = false;  // write premultiplied light and coverage for the skin pass
};

// Blurs `source` along `axis` ((1,0) or (0,1)) with standard deviation `sigma_texels` into
// `target`, rendering only the tiles of `rect` (the skin's bounding rectangle); depth-aware
// when `follow` is given (nearest taps at whole texels).
sim::PassCounters blur_pass(const std::string& name, const sim::RenderTarget& source,
                            sim::RenderTarget& target, const sim::PixelRect& rect, glm::vec2 axis,
                            float sigma_texels, sim::Gpu& gpu,
                            const std::optional<BlurFollow>& follow = std::nullopt);

}  // namespace skinsim::pipeline
