#include "driver/sweep/image_diff.h"

#include <fmt/format.h>

#include <algorithm>
#include <glm/common.hpp>

#include "driver/sweep/crop_windows.h"
#include "driver/sweep/frame_comparison.h"
#include "quality/metrics.h"

namespace skinsim::driver {

reports::ImageDiff diff_frames(const std::filesystem::path& a, const std::filesystem::path& b,
                               const image::Mask* mask, const std::string& over,
                               const std::filesystem::path& out_dir, const std::string& stem) {
  const image::Image frame_a = image::load_png(a);
  const image::Image frame_b = image::load_png(b);
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

  const image::Image difference = amplified_difference(frame_b, frame_a);
  diff.difference_image = stem + "_difference.png";
  image::save_png(difference, out_dir / diff.difference_image);
  const image::ScalarMap error = flip_error_map(frame_b, frame_a, mask);
  // The fixed places (an eye, the lips, ...) need the skin: a sweep's reference mask.
  std::vector<std::string> not_found;
  const std::vector<Landmark> landmarks =
      mask ? find_landmarks(frame_a, *mask, &not_found) : std::vector<Landmark>{};
  diff.windows = write_crop_windows(
      landmarks,
      {{"largest difference between A and B", error}, {"next-largest difference", error}},
      {{"A", &frame_a},
       {"B", &frame_b},
       {fmt::format("|B - A| x {:g}", kDifferenceGain), &difference}},
      out_dir, stem, not_found);
  return diff;
}

reports::ImageChange diff_pixels(const std::filesystem::path& a, const std::filesystem::path& b) {
  const image::Image image_a = image::load_png(a);
  const image::Image image_b = image::load_png(b);
  reports::ImageChange change;
  if (image_a.width != image_b.width || image_a.height != image_b.height) {
    change.size_mismatch =
        fmt::format("{}x{} vs {}x{}", image_a.width, image_a.height, image_b.width, image_b.height);
    return change;
  }
  for (std::size_t i = 0; i < image_a.rgb.size(); ++i) {
    const glm::vec3 d = glm::abs(image_b.rgb[i] - image_a.rgb[i]);
    const double largest = std::max({d.r, d.g, d.b});
    change.differing_px += largest > 0.0;
    change.max_difference = std::max(change.max_difference, largest);
  }
  return change;
}

}  // namespace skinsim::driver
