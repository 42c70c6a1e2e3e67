// Render targets as images a user can open.
#pragma once

#include <filesystem>

#include "image/image.h"
#include "sim/render_target.h"

namespace skinsim::driver {

// RGB of a render target as stored (display-encoded for the frame), clamped to [0,1].
image::Image to_image(const sim::RenderTarget& target, float scale = 1.0f);
// Writes the target's RGB x scale as an 8-bit PNG, atomically.
void write_png(const sim::RenderTarget& target, const std::filesystem::path& path,
               float scale = 1.0f);

}  // namespace skinsim::driver
