// Images of `skinsim compare`: two frames, identical pixels or FLIP of B against A with the
// sweep's visibility verdict and crops of the windows where they differ most; any other two
// images, which pixels differ.
#pragma once

#include <filesystem>
#include <string>

#include "image/image.h"
#include "reports/comparison.h"

namespace skinsim::driver {

// A's and B's frame files; FLIP counts the pixels of `mask` (every pixel if null), which
// `over` names ("the skin", "the whole frame"). When they differ and `out_dir` is not empty,
// writes the amplified difference (<stem>_difference.png) and the crops (<stem>_w*.png) there;
// the diff's paths are relative to `out_dir`, except a_image/b_image, which are left for the
// caller to link.
reports::ImageDiff diff_frames(const std::filesystem::path& a, const std::filesystem::path& b,
                               const image::Mask* mask, const std::string& over,
                               const std::filesystem::path& out_dir, const std::string& stem);

// Which pixels of two images differ, and by how much at most (no verdict); names and links are
// left for the caller.
reports::ImageChange diff_pixels(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace skinsim::driver
