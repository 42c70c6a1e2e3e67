// Full-reference image-quality metrics on display-referred sRGB images: PSNR, SSIM and FLIP.
// All take an optional mask (only pixels with mask value != 0 count in the mean) and are
// deterministic: per-pixel values do not depend on the thread count and means are reduced in
// a fixed order. Bad input (size mismatch, empty mask, NaN) throws QualityError.
#pragma once

#include <array>
#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "image/image.h"

namespace skinsim::quality {

// Peak signal-to-noise ratio in dB with peak 1.0 over the R, G and B values of the counted
// pixels: -10 log10(MSE). Identical images give +infinity (see docs/quality-metrics.md for
// how JSON output represents it).
double psnr(const image::Image& test, const image::Image& reference,
            const image::Mask* mask = nullptr);

// Structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004) of the luma
// Y' = 0.299 R' + 0.587 G' + 0.114 B' of the encoded values (as MATLAB's rgb2gray): 11x11
// Gaussian window (sigma 1.5), K1 = 0.01, K2 = 0.03, L = 1, edge-clamped borders. Returns the
// mean of the SSIM map over the mask; writes the full map to `map` if given.
double ssim(const image::Image& test, const image::Image& reference,
            const image::Mask* mask = nullptr, image::ScalarMap* map = nullptr);

// Mean of a per-pixel map over the mask (all pixels without one), as the metrics average
// their maps: ssim(a, b, mask) == map_mean(m, mask) where ssim(a, b, nullptr, &m).
double map_mean(const image::ScalarMap& map, const image::Mask* mask = nullptr);

// Pixels per degree of visual angle for an observer `distance_m` from a monitor
// `monitor_width_m` wide with `monitor_width_px` pixels across (small-angle approximation, as
// FLIP's reference implementation).
double pixels_per_degree(double distance_m, double monitor_width_m, int monitor_width_px);

// FLIP LDR (Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", HPG 2020).
struct FlipParams {
  // The paper's default observer: 0.7 m from a 0.7 m wide 3840-pixel monitor (about 67.0).
  double pixels_per_degree = skinsim::quality::pixels_per_degree(0.7, 0.7, 3840);
};

struct FlipResult {
  double mean = 0.0;     // mean error over the mask, in [0,1]
  image::ScalarMap map;  // per-pixel error in [0,1], every pixel (the mask only affects the mean)
};

FlipResult flip(const image::Image& test, const image::Image& reference,
                const image::Mask* mask = nullptr, const FlipParams& params = {});

// An image's FLIP pixels (what FLIP derives from one of its two images per pixel: the
// filtered colour in Hunt-adjusted L*a*b* and the edge and point strengths), computed once to
// compare many images with it (a sweep's reference, the best frame of a group):
// flip(test, FlipFeatures(reference)) equals flip(test, reference) to the last bit and filters
// only the test image. 32 bytes a pixel: the image and five float planes.
class FlipFeatures {
 public:
  enum Plane { kLightness, kA, kB, kEdge, kPoint, kPlanes };
  explicit FlipFeatures(const image::Image& image, const FlipParams& params = {});
  int width() const { return image_.width; }
  int height() const { return image_.height; }
  const image::Image& image() const { return image_; }  // kept: where a test equals it, error is 0
  const FlipParams& params() const { return params_; }
  const float* plane(Plane p) const { return planes_[p].data(); }

 private:
  image::Image image_;
  FlipParams params_;
  std::array<std::vector<float>, kPlanes> planes_;
};

FlipResult flip(const image::Image& test, const FlipFeatures& reference,
                const image::Mask* mask = nullptr);

// When a FLIP difference is visible. FLIP has no threshold of its own; skinsim calls a pixel
// visibly different when its error exceeds what one just-noticeable lightness step
// (Delta E*ab = 2.3) gives in a uniform region, where FLIP's edge and point terms are zero:
// about 0.10. A frame differs visibly when such pixels cover at least one FLIP "digit"
// (0.082 degrees, the feature scale of the paper's section 4.4) squared: about 30 pixels at
// the default observer's 67 pixels per degree. docs/quality-metrics.md states the rule.
double flip_visibility_threshold();
double flip_visible_area_pixels(const FlipParams& params = {});

// The share of `pixels` that `visible` is, in percent (0 for no pixels).
double visible_percent(std::size_t visible, std::size_t pixels);

// Statistics of a FLIP map over a mask (every pixel if null): the mean, the 95th and 99th
// percentiles (nearest rank), and the pixels above flip_visibility_threshold().
struct FlipStatistics {
  double mean = 0.0;
  double p95 = 0.0;
  double p99 = 0.0;
  std::size_t visible_pixels = 0;
  std::size_t pixels = 0;
  double visible_percent() const;
  bool visible(const FlipParams& params = {}) const;  // visible_pixels >= the area above
};
FlipStatistics flip_statistics(const image::ScalarMap& map, const image::Mask* mask = nullptr);
// flip_statistics(map).visible_pixels alone, without the percentiles' selection.
std::size_t flip_visible_pixels(const image::ScalarMap& map);

}  // namespace skinsim::quality
