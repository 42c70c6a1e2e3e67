// FLIP LDR, following Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom and Fairchild,
// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020, with the constants of the
// paper and its reference implementation (github.com/NVlabs/flip). Convolutions clamp at the
// image border (the reference's C++ code does the same). Like that code, FLIP here computes in
// single precision; the per-pixel colour and error work runs on four pixels at once, or eight
// where the processor has AVX2 (util/float_lanes.h), with the same bits either way.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "quality/error.h"
#include "quality/flip_color.h"
#include "quality/metric_inputs.h"
#include "quality/metrics.h"
#include "quality/separable_stream.h"
#include "util/float_lanes.h"
#include "util/simd_dispatch.h"
#include "util/unorm8.h"

// Eight-lane vectors pass only between always-inlined functions inside target("avx2") code
// (util/float_lanes.h), never across a call.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace skinsim::quality {
namespace {

using flip_color::Colour;
constexpr double kPi = std::numbers::pi;

// Colour pipeline exponent and error redistribution (section 4.3): qc, pc, pt.
constexpr float kQc = 0.7f;
constexpr float kPc = 0.4f;
constexpr float kPt = 0.95f;
// Feature pipeline exponent (section 4.4) and the width of a digit, 0.082 degrees, which sets
// the feature filters' standard deviation 0.5 * w * ppd.
constexpr double kQf = 0.5;
static_assert(kQf == 0.5, "the feature error below uses sqrt for the power qf");
constexpr double kDigitWidthDegrees = 0.082;

// Contrast sensitivity functions as sums of Gaussians a * sqrt(pi / b) * exp(-pi^2 x^2 / b)
// (x in degrees), one set per opponent channel (section 4.1; constants from the paper's code).
struct CsfTerm {
  double a;
  double b;
};
constexpr std::array<CsfTerm, 2> kCsfAchromatic{{{1.0, 0.0047}, {0.0, 1e-5}}};
constexpr std::array<CsfTerm, 2> kCsfRedGreen{{{1.0, 0.0053}, {0.0, 1e-5}}};
constexpr std::array<CsfTerm, 2> kCsfBlueYellow{{{34.1, 0.04}, {13.5, 0.025}}};
constexpr double kCsfLargestB = 0.04;

// The 1D factor of one CSF term, normalised to sum 1, and the term's share of the 2D kernel's
// sum: the 2D kernel sum_t a_t sqrt(pi/b_t) G_t(x) G_t(y), normalised to sum 1 over its
// (2r+1)^2 taps as in the paper's code, equals sum_t share_t * (g_t(x) g_t(y)).
struct CsfFactor {
  std::vector<float> kernel;
  double share;
};

std::vector<CsfFactor> csf_factors(const std::array<CsfTerm, 2>& terms, double ppd) {
  const int radius =
      static_cast<int>(std::ceil(3.0 * std::sqrt(kCsfLargestB / (2.0 * kPi * kPi)) * ppd));
  std::vector<CsfFactor> factors;
  double total = 0.0;
  for (const CsfTerm& term : terms) {
    if (term.a == 0.0) continue;
    std::vector<double> taps(2 * radius + 1);
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
      const double x_degrees = i / ppd;
      taps[i + radius] = std::exp(-kPi * kPi * x_degrees * x_degrees / term.b);
      sum += taps[i + radius];
    }
    CsfFactor factor{std::vector<float>(taps.size()), term.a * std::sqrt(kPi / term.b) * sum * sum};
    for (std::size_t i = 0; i < taps.size(); ++i)
      factor.kernel[i] = static_cast<float>(taps[i] / sum);
    total += factor.share;
    factors.push_back(std::move(factor));
  }
  for (CsfFactor& factor : factors) factor.share /= total;
  return factors;
}

// Scales the positive taps to sum 1 and the negative taps to sum -1 (as FLIP's code).
std::vector<float> normalise_signed(const std::vector<double>& taps) {
  double positive = 0.0;
  double negative = 0.0;
  for (double t : taps) (t > 0.0 ? positive : negative) += t;
  std::vector<float> kernel(taps.size());
  for (std::size_t i = 0; i < taps.size(); ++i) {
    kernel[i] = static_cast<float>(taps[i] > 0.0 ? taps[i] / positive : taps[i] / -negative);
  }
  return kernel;
}

struct FeatureKernels {
  std::vector<float> smooth;  // Gaussian, sum 1
  std::vector<float> edge;    // first derivative of the Gaussian, -x g(x)
  std::vector<float> point;   // second derivative, (x^2 / sd^2 - 1) g(x)
};

// The 2D edge and point filters of section 4.4 are separable: (derivative along x) times
// (Gaussian along y). Normalising the 1D derivative's positive/negative taps and the 1D
// Gaussian to sum 1 gives exactly the 2D filter normalised as in the paper's code.
FeatureKernels feature_kernels(double ppd) {
  const double sd = 0.5 * kDigitWidthDegrees * ppd;
  const int radius = static_cast<int>(std::ceil(3.0 * sd));
  std::vector<double> edge(2 * radius + 1);
  std::vector<double> point(2 * radius + 1);
  for (int i = -radius; i <= radius; ++i) {
    const double g = std::exp(-(i * i) / (2.0 * sd * sd));
    edge[i + radius] = -i * g;
    point[i + radius] = (i * i / (sd * sd) - 1.0) * g;
  }
  return {gaussian_kernel(sd, radius), normalise_signed(edge), normalise_signed(point)};
}

// Source channels per image: Y, Cx, Cz of YCxCz, and the luminance Y / Y_white in [0,1].
constexpr int kSourcesPerImage = 4;
constexpr int kLuminance = 3;

// Which filtered outputs (column filter indices) make up one image's FLIP inputs.
struct ImageOutputs {
  std::array<std::vector<std::pair<int, double>>, 3> opponent;  // (filter, share) per channel
  int edge_x, edge_y, point_x, point_y;
};

// Adds one image's filters to the stream; `image` selects its block of source channels.
ImageOutputs add_image_filters(SeparableStream& stream, int image, double ppd,
                               const FeatureKernels& features) {
  const auto add_row = [&](int source, const std::vector<float>& along_x) {
    stream.row_filters.push_back({image * kSourcesPerImage + source, along_x});
    return static_cast<int>(stream.row_filters.size()) - 1;
  };
  const auto add_column = [&](int row_filter, const std::vector<float>& along_y) {
    stream.column_filters.push_back({row_filter, along_y});
    return static_cast<int>(stream.column_filters.size()) - 1;
  };
  ImageOutputs out{};
  const std::array<const std::array<CsfTerm, 2>*, 3> csf{&kCsfAchromatic, &kCsfRedGreen,
                                                         &kCsfBlueYellow};
  for (int c = 0; c < 3; ++c) {
    for (const CsfFactor& f : csf_factors(*csf[c], ppd)) {
      out.opponent[c].emplace_back(add_column(add_row(c, f.kernel), f.kernel), f.share);
    }
  }
  const int smooth_rows = add_row(kLuminance, features.smooth);
  out.edge_x = add_column(add_row(kLuminance, features.edge), features.smooth);
  out.edge_y = add_column(smooth_rows, features.edge);
  out.point_x = add_column(add_row(kLuminance, features.point), features.smooth);
  out.point_y = add_column(smooth_rows, features.point);
  return out;
}

// sRGB decoding of the 256 values an 8-bit image holds (util/unorm8.h), which is what
// rendered frames and their PNGs are; other values take the pow() path. Both give identical
// results.
class SrgbDecoder {
 public:
  SrgbDecoder() {
    for (int i = 0; i < 256; ++i) table_[i] = decode(kUnorm8Value[i]);
  }
  float operator()(float encoded) const {
    const std::optional<std::uint8_t> code = unorm8_code(encoded);
    return code ? table_[*code] : decode(encoded);
  }

 private:
  // The exact value rounded to float once.
  static float decode(float encoded) {
    return static_cast<float>(
        flip_color::srgb_to_linear(std::clamp(static_cast<double>(encoded), 0.0, 1.0)));
  }
  std::array<float, 256> table_;
};

// Source columns of row y: YCxCz and luminance, a vector of pixels at a time.
template <class V>
[[gnu::always_inline]] inline void write_source_row(const image::Image& image, int y,
                                                    Columns columns, const SrgbDecoder& decode,
                                                    float* const* rows) {
  const std::size_t begin = static_cast<std::size_t>(y) * image.width;
  for (int x = columns.begin; x < columns.end; x += kLanes<V>) {
    const int n = std::min(kLanes<V>, columns.end - x);
    Colour<V> linear{};
    for (int lane = 0; lane < n; ++lane) {
      const glm::vec3& p = image.rgb[begin + x + lane];
      linear.x[lane] = decode(p.r);
      linear.y[lane] = decode(p.g);
      linear.z[lane] = decode(p.b);
    }
    const Colour<V> opponent = flip_color::xyz_to_ycxcz(flip_color::linear_rgb_to_xyz(linear));
    store_lanes(rows[0] + x, opponent.x, n);
    store_lanes(rows[1] + x, opponent.y, n);
    store_lanes(rows[2] + x, opponent.z, n);
    store_lanes(rows[kLuminance] + x, (opponent.x + 16.0f) / 116.0f, n);
  }
}

[[gnu::target("avx2")]] void write_source_row_avx2(const image::Image& image, int y,
                                                   Columns columns, const SrgbDecoder& decode,
                                                   float* const* rows) {
  write_source_row<Float8>(image, y, columns, decode, rows);
}

// A vector of pixels' FLIP features: Hunt-adjusted L*a*b*, edge and point strengths.
template <class V>
struct FlipLanes {
  Colour<V> hunt_lab;
  V edge, point;
};

// The features of pixels [x, x + n) from the filtered rows.
template <class V>
[[gnu::always_inline]] inline FlipLanes<V> pixel_features(const ImageOutputs& o,
                                                          std::span<const float* const> f, int x,
                                                          int n) {
  Colour<V> opponent{};
  const std::array<V*, 3> channel{&opponent.x, &opponent.y, &opponent.z};
  for (int c = 0; c < 3; ++c) {
    for (const auto& [filter, share] : o.opponent[c]) {
      *channel[c] += static_cast<float>(share) * load_lanes<V>(f[filter] + x, n);
    }
  }
  const auto length = [&](int a, int b) __attribute__((always_inline)) {
    const V u = load_lanes<V>(f[a] + x, n), v = load_lanes<V>(f[b] + x, n);
    return sqrt_lanes(u * u + v * v);
  };
  return {flip_color::ycxcz_to_hunt_lab(opponent), length(o.edge_x, o.edge_y),
          length(o.point_x, o.point_y)};
}

// Largest colour difference FLIP expects: HyAB between Hunt-adjusted green and blue, to qc.
float max_colour_difference() {
  const auto hunt_lab = [](float r, float g, float b) {
    return flip_color::hunt_adjust(flip_color::xyz_to_lab(
        flip_color::linear_rgb_to_xyz(Colour<Float4>{splat(r), splat(g), splat(b)})));
  };
  return pow_lanes(flip_color::hyab(hunt_lab(0, 1, 0), hunt_lab(0, 0, 1)), splat(kQc))[0];
}

// Section 4.3's colour error of a colour difference `hyab` > 0 (HyAB in Hunt-adjusted
// L*a*b*) where there are no edges or points: small differences compressed into [0, pt), large
// ones into [pt, 1].
template <class V>
[[gnu::always_inline]] inline V colour_error(V hyab, float cmax) {
  const V colour = pow_lanes(hyab, splat<V>(kQc));
  const float pccmax = kPc * cmax;
  return colour < pccmax ? kPt / pccmax * colour
                         : kPt + (colour - pccmax) / (cmax - pccmax) * (1.0f - kPt);
}

}  // namespace

double flip_visibility_threshold() {
  // One just-noticeable difference of lightness, Delta E*ab = 2.3 (Mahy, Van Eycken and
  // Oosterlinck 1994, as Sharma 2003 quotes it); a pure lightness step has HyAB = |Delta L*|.
  constexpr float kJndDeltaE = 2.3f;
  return colour_error(splat(kJndDeltaE), max_colour_difference())[0];
}

double flip_visible_area_pixels(const FlipParams& params) {
  const double digit = kDigitWidthDegrees * params.pixels_per_degree;
  return digit * digit;
}

double pixels_per_degree(double distance_m, double monitor_width_m, int monitor_width_px) {
  return distance_m * (monitor_width_px / monitor_width_m) * (kPi / 180.0);
}

namespace {

double checked_pixels_per_degree(const FlipParams& params) {
  if (!(params.pixels_per_degree > 0.0) || !std::isfinite(params.pixels_per_degree)) {
    throw QualityError("FLIP: pixels_per_degree must be a positive number, got " +
                       std::to_string(params.pixels_per_degree));
  }
  return params.pixels_per_degree;
}

// Section 4.5: the colour error of two pixels, amplified by their feature difference; a
// vector of pairs at once.
template <class V>
[[gnu::always_inline]] inline V pixel_error(const FlipLanes<V>& t, const FlipLanes<V>& r,
                                            float cmax) {
  const V distance = flip_color::hyab(t.hunt_lab, r.hunt_lab);
  const V feature_difference = max_lanes(abs_lanes(t.edge - r.edge), abs_lanes(t.point - r.point));
  const V feature_error = sqrt_lanes(feature_difference / std::numbers::sqrt2_v<float>);  // ^qf
  const V error = pow_lanes(colour_error(distance, cmax), 1.0f - feature_error);
  // No colour difference: the error is 0 whatever the features.
  return distance == 0.0f ? splat<V>(0.0f) : error;
}

// Which pixels of `a` may differ from `b` after filters `radius` wide: those with a pixel
// where the images differ within `radius` along x and along y. Elsewhere every filter reads
// the same values in the same order, so both images' FLIP pixels are equal bit for bit and
// the error is exactly 0 (the images' borders clamp to pixels inside the same window).
// Returns the mask and, per row, the columns from its first such pixel to its last.
struct NearDifferences {
  std::vector<std::uint8_t> mask;
  std::vector<Columns> rows;
};
NearDifferences near_differences(const image::Image& a, const image::Image& b, int radius) {
  const int w = a.width, h = a.height;
  std::vector<std::uint8_t> across(a.pixel_count(), 0);  // a difference within radius along x
  tbb::parallel_for(0, h, [&](int y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    int last = -radius - 1;  // the last differing x at or before the window's right end
    for (int x = 0; x < w + radius; ++x) {
      if (x < w && a.rgb[row + x] != b.rgb[row + x]) last = x;
      if (x - radius >= 0 && last >= x - 2 * radius) across[row + x - radius] = 1;
    }
  });
  NearDifferences near{std::vector<std::uint8_t>(a.pixel_count(), 0),
                       std::vector<Columns>(static_cast<std::size_t>(h))};
  // Down the rows in strips of columns, so that each step reads and writes a row's run of
  // bytes rather than one byte a row apart.
  constexpr int kStrip = 256;
  tbb::parallel_for(0, (w + kStrip - 1) / kStrip, [&](int strip) {
    const int x0 = strip * kStrip, x1 = std::min(w, x0 + kStrip);
    std::vector<int> last(static_cast<std::size_t>(x1 - x0), -radius - 1);
    for (int y = 0; y < h + radius; ++y) {
      if (y < h) {
        const std::uint8_t* row = &across[static_cast<std::size_t>(y) * w];
        for (int x = x0; x < x1; ++x) last[x - x0] = row[x] ? y : last[x - x0];
      }
      if (y - radius < 0) continue;
      std::uint8_t* out = &near.mask[static_cast<std::size_t>(y - radius) * w];
      for (int x = x0; x < x1; ++x) out[x] = last[x - x0] >= y - 2 * radius ? 1 : 0;
    }
  });
  tbb::parallel_for(0, h, [&](int y) {
    const std::uint8_t* row = &near.mask[static_cast<std::size_t>(y) * w];
    int begin = 0, end = w;
    while (begin < end && !row[begin]) ++begin;
    while (end > begin && !row[end - 1]) --end;
    near.rows[y] = {begin, end};
  });
  return near;
}

// One filtered row's FLIP pixels, kLanes<V> at a time, to `sink` (stream_flip_pixels).
template <class V, class Sink>
[[gnu::always_inline]] inline void sink_row(std::span<const ImageOutputs> outputs,
                                            std::span<const float* const> filtered,
                                            const std::uint8_t* near, std::size_t row,
                                            Columns columns, const Sink& sink) {
  for (int x = columns.begin; x < columns.end; x += kLanes<V>) {
    const int n = std::min(kLanes<V>, columns.end - x);
    IntLanes<V> keep = ~IntLanes<V>{};
    if (near != nullptr) {
      bool any = false;
      for (int lane = 0; lane < kLanes<V>; ++lane) {
        const bool wanted = lane < n && near[row + x + lane];
        keep[lane] = wanted ? -1 : 0;
        any = any || wanted;
      }
      if (!any) continue;
    }
    const FlipLanes<V> first = pixel_features<V>(outputs[0], filtered, x, n);
    if (outputs.size() == 1) {
      sink(row + x, n, keep, first, static_cast<const FlipLanes<V>*>(nullptr));
    } else {
      const FlipLanes<V> second = pixel_features<V>(outputs[1], filtered, x, n);
      sink(row + x, n, keep, first, &second);
    }
  }
}

template <class Sink>
[[gnu::target("avx2")]] void sink_row_avx2(std::span<const ImageOutputs> outputs,
                                           std::span<const float* const> filtered,
                                           const std::uint8_t* near, std::size_t row,
                                           Columns columns, const Sink& sink) {
  sink_row<Float8>(outputs, filtered, near, row, columns, sink);
}

// Streams `images` (one or two) through their filters and hands `sink` the FLIP pixels a
// vector at a time: sink(i, n, keep, lanes of images[0], lanes of images[1] or nullptr) for
// pixels [i, i + n) (row-major indices, n <= the lanes, in one row). With `unchanged_from`,
// `keep` is -1 in the lanes of pixels near a difference between images[0] and it
// (near_differences), 0 elsewhere, and groups without such a pixel are skipped; without, every
// lane is -1. `sink` is a generic lambda marked always_inline: it is called with four lanes
// (SSE2) or eight (AVX2, where use_avx2()), and must be compiled into each width's loop.
template <class Sink>
void stream_flip_pixels(std::span<const image::Image* const> images, double ppd,
                        const image::Image* unchanged_from, const Sink& sink) {
  const FeatureKernels features = feature_kernels(ppd);
  const int count = static_cast<int>(images.size());
  SeparableStream stream{images[0]->width, images[0]->height, count * kSourcesPerImage, {}, {}, {}};
  std::vector<ImageOutputs> outputs;
  for (int i = 0; i < count; ++i) outputs.push_back(add_image_filters(stream, i, ppd, features));
  std::vector<std::uint8_t> near;
  if (unchanged_from != nullptr) {
    int radius = 0;
    for (const RowFilter& f : stream.row_filters) {
      radius = std::max(radius, static_cast<int>(f.kernel.size() / 2));
    }
    for (const ColumnFilter& f : stream.column_filters) {
      radius = std::max(radius, static_cast<int>(f.kernel.size() / 2));
    }
    NearDifferences differences = near_differences(*images[0], *unchanged_from, radius);
    near = std::move(differences.mask);
    stream.wanted = std::move(differences.rows);  // only there can the error be other than 0
  }
  const bool avx2 = use_avx2();
  const SrgbDecoder decode;
  const auto source = [&](int y, Columns columns, std::span<float* const> rows) {
    for (int i = 0; i < count; ++i) {
      float* const* image_rows = rows.data() + i * kSourcesPerImage;
      if (avx2) {
        write_source_row_avx2(*images[i], y, columns, decode, image_rows);
      } else {
        write_source_row<Float4>(*images[i], y, columns, decode, image_rows);
      }
    }
  };
  const auto row_sink = [&](int y, Columns columns, std::span<const float* const> filtered) {
    const std::size_t row = static_cast<std::size_t>(y) * stream.width;
    const std::uint8_t* near_mask = near.empty() ? nullptr : near.data();
    if (avx2) {
      sink_row_avx2(outputs, filtered, near_mask, row, columns, sink);
    } else {
      sink_row<Float4>(outputs, filtered, near_mask, row, columns, sink);
    }
  };
  run_separable_stream(stream, source, row_sink);
}

}  // namespace

FlipResult flip(const image::Image& test, const image::Image& reference, const image::Mask* mask,
                const FlipParams& params) {
  check_metric_inputs("FLIP", test, reference, mask);
  const float cmax = max_colour_difference();
  FlipResult result;
  result.map = image::ScalarMap{test.width, test.height, std::vector<float>(test.pixel_count())};
  const std::array<const image::Image*, 2> images{&test, &reference};
  // The map starts at 0, the error wherever the images do not differ nearby.
  stream_flip_pixels(
      images, checked_pixels_per_degree(params), &reference,
      [&](std::size_t i, int n, auto keep, const auto& t, const auto* r)
          __attribute__((always_inline)) {
            store_lanes(&result.map.values[i], keep ? pixel_error(t, *r, cmax) : 0.0f, n);
          });
  result.mean = masked_mean(result.map.values, test.width, test.height, mask);
  return result;
}

FlipFeatures::FlipFeatures(const image::Image& image, const FlipParams& params)
    : image_(image), params_(params) {
  check_metric_inputs("FLIP", image, image, nullptr);
  for (std::vector<float>& plane : planes_) plane.resize(image.pixel_count());
  const std::array<const image::Image*, 1> images{&image};
  stream_flip_pixels(
      images, checked_pixels_per_degree(params), nullptr,
      [&](std::size_t i, int n, auto, const auto& p, const auto*) __attribute__((always_inline)) {
        store_lanes(&planes_[kLightness][i], p.hunt_lab.x, n);
        store_lanes(&planes_[kA][i], p.hunt_lab.y, n);
        store_lanes(&planes_[kB][i], p.hunt_lab.z, n);
        store_lanes(&planes_[kEdge][i], p.edge, n);
        store_lanes(&planes_[kPoint][i], p.point, n);
      });
}

FlipResult flip(const image::Image& test, const FlipFeatures& reference, const image::Mask* mask) {
  check_metric_inputs("FLIP", test, test, mask);
  if (test.width != reference.width() || test.height != reference.height()) {
    throw QualityError("FLIP: test image is " + std::to_string(test.width) + "x" +
                       std::to_string(test.height) + " but reference is " +
                       std::to_string(reference.width()) + "x" +
                       std::to_string(reference.height()));
  }
  const float cmax = max_colour_difference();
  FlipResult result;
  result.map = image::ScalarMap{test.width, test.height, std::vector<float>(test.pixel_count())};
  const std::array<const image::Image*, 1> images{&test};
  stream_flip_pixels(
      images, checked_pixels_per_degree(reference.params()), &reference.image(),
      [&](std::size_t i, int n, auto keep, const auto& t, const auto*)
          __attribute__((always_inline)) {
            using V = decltype(t.edge);
            const auto lanes = [&](FlipFeatures::Plane p) __attribute__((always_inline)) {
              return load_lanes<V>(reference.plane(p) + i, n);
            };
            const FlipLanes<V> r{
                {lanes(FlipFeatures::kLightness), lanes(FlipFeatures::kA), lanes(FlipFeatures::kB)},
                lanes(FlipFeatures::kEdge),
                lanes(FlipFeatures::kPoint)};
            store_lanes(&result.map.values[i], keep ? pixel_error(t, r, cmax) : 0.0f, n);
          });
  result.mean = masked_mean(result.map.values, test.width, test.height, mask);
  return result;
}

}  // namespace skinsim::quality
