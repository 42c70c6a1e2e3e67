#include "driver/image_diff.h"

#include <fmt/format.h>

#include "driver/crop_windows.h"
#include "driver/frame_comparison.h"
#include "quality/metrics.h"

namespace skinsim::driver {

reports::ImageDiff diff_frames(const std::filesystem::path& a, const std::filesystem::path& b,
                               const quality::Mask* mask, const std::string& over,
                               const std::filesystem::path& out_dir, const std::string& stem) {
  const quality::Image frame_a = quality::load_png(a);
  const quality::Image frame_b = quality::load_png(b);
  reports::ImageDiff diff;
  diff.over = over;
  if (frame_a.width != frame_b.width || frame_a.height != frame_b.height) {
    diff.size_mismatch =
        fmt::format("{}x{} vs {}x{}", frame_a.width, frame_a.height, frame_b.width, frame_b.height);
    return diff;
  }
  if (mask && (mask->width != frame_a.width || mask->height != frame_a.height)) {
    mask = nullptr;  // not this frame's mask
    diff.over = "the whole frame";
  }
  diff.identical = frame_a.rgb == frame_b.rgb;
  if (diff.identical) return diff;
  diff.flip = compare_frames(frame_b, frame_a, mask);
  diff.threshold = quality::flip_visibility_threshold();
  diff.visible_area_px = quality::flip_visible_area_pixels();
  // B against A; not `= "A"`, which GCC 12 misreports as -Wrestrict (cmake/warnings.cmake)
  diff.flip.against = std::string(1, 'A');
  if (out_dir.empty()) return diff;

  const quality::Image difference = amplified_difference(frame_b, frame_a);
  diff.difference_image = stem + "_difference.png";
  quality::save_png(difference, out_dir / diff.difference_image);
  const quality::ScalarMap error = flip_error_map(frame_b, frame_a, mask);
  diff.windows = write_crop_windows(
      {{"largest difference between A and B", error}, {"next-largest difference", error}},
      {{"A", &frame_a},
       {"B", &frame_b},
       {fmt::format("|B - A| x {:g}", kDifferenceGain), &difference}},
      out_dir, stem);
  return diff;
}

}  // namespace skinsim::driver
