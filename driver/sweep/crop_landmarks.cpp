#include "driver/sweep/crop_landmarks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

namespace skinsim::driver {

namespace {

struct Box {
  int x0, y0, x1, y1;  // inclusive
};

std::optional<Box> skin_box(const image::Mask& skin) {
  std::optional<Box> box;
  for (int y = 0; y < skin.height; ++y) {
    for (int x = 0; x < skin.width; ++x) {
      if (!skin.values[static_cast<std::size_t>(y) * skin.width + x]) continue;
      if (!box) box = Box{x, y, x, y};
      box->x0 = std::min(box->x0, x);
      box->x1 = std::max(box->x1, x);
      box->y1 = std::max(box->y1, y);
    }
  }
  return box;
}

// Labels 4-connected regions of non-skin pixels; returns the centroid of the largest one that
// does not touch the frame border (a hole in the skin: an eye, or an open mouth), if it covers
// at least 1/2000 of the skin's box.
std::optional<Landmark> eye(const image::Mask& skin, const Box& box) {
  const int w = skin.width, h = skin.height;
  std::vector<std::int32_t> label(static_cast<std::size_t>(w) * h, -1);
  std::vector<int> stack;
  std::optional<Landmark> best;
  long long best_area =
      (static_cast<long long>(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1)) / 2000;
  int next = 0;
  for (int start = 0; start < w * h; ++start) {
    if (skin.values[start] || label[start] >= 0) continue;
    long long area = 0, sx = 0, sy = 0;
    bool border = false;
    stack.assign(1, start);
    label[start] = next;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      const int x = p % w, y = p / w;
      ++area;
      sx += x;
      sy += y;
      border = border || x == 0 || y == 0 || x == w - 1 || y == h - 1;
      for (const int q : {x > 0 ? p - 1 : -1, x < w - 1 ? p + 1 : -1, y > 0 ? p - w : -1,
                          y < h - 1 ? p + w : -1}) {
        if (q >= 0 && !skin.values[q] && label[q] < 0) {
          label[q] = next;
          stack.push_back(q);
        }
      }
    }
    ++next;
    if (!border && area > best_area) {
      best_area = area;
      best = Landmark{"an eye (the largest hole in the skin mask)", static_cast<int>(sx / area),
                      static_cast<int>(sy / area)};
    }
  }
  return best;
}

// Skin pixels whose (2r+1)^2 neighbourhood is all skin, from a summed-area table of the mask.
class InteriorTest {
 public:
  InteriorTest(const image::Mask& skin, int r) : w_(skin.width), h_(skin.height), r_(r) {
    sat_.assign(static_cast<std::size_t>(w_ + 1) * (h_ + 1), 0);
    for (int y = 0; y < h_; ++y) {
      for (int x = 0; x < w_; ++x) {
        at(x + 1, y + 1) = (skin.values[static_cast<std::size_t>(y) * w_ + x] ? 1 : 0) +
                           at(x, y + 1) + at(x + 1, y) - at(x, y);
      }
    }
  }
  bool operator()(int x, int y) const {
    if (x - r_ < 0 || y - r_ < 0 || x + r_ >= w_ || y + r_ >= h_) return false;
    const int x0 = x - r_, y0 = y - r_, x1 = x + r_ + 1, y1 = y + r_ + 1;
    const long long n = at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
    return n == static_cast<long long>(2 * r_ + 1) * (2 * r_ + 1);
  }

 private:
  long long& at(int x, int y) { return sat_[static_cast<std::size_t>(y) * (w_ + 1) + x]; }
  long long at(int x, int y) const { return sat_[static_cast<std::size_t>(y) * (w_ + 1) + x]; }
  int w_, h_, r_;
  std::vector<long long> sat_;
};

float luminance(const glm::vec3& c) {
  return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;  // ITU-R BT.709 weights
}

// Redness independent of how brightly the skin is lit: (red - green) / (red + green + blue).
float redness(const glm::vec3& c) {
  const float sum = c.r + c.g + c.b;
  return sum > 0.0f ? (c.r - c.g) / sum : 0.0f;
}

// The reddest interior skin in the lower half of the skin's box, within its middle third
// across: lips are the most saturated red on a face; on skin of one colour, the mouth's crease
// reddened by diffusion. Only when it is redder than the region's median skin by kLipRedness:
// a face lit without any red shows none.
std::optional<Landmark> lips(const image::Image& ref, const Box& box, const InteriorTest& in,
                             std::vector<std::string>& not_found) {
  std::optional<Landmark> best;
  float best_red = 0.0f;
  std::vector<float> reds;
  const int third = (box.x1 - box.x0) / 3;
  for (int y = (box.y0 + box.y1) / 2; y <= box.y1; ++y) {
    for (int x = box.x0 + third; x <= box.x1 - third; ++x) {
      if (!in(x, y)) continue;
      const float red = redness(ref.at(x, y));
      reds.push_back(red);
      if (!best || red > best_red) {
        best_red = red;
        best = Landmark{"the lips (the reddest skin in the lower middle of the face)", x, y};
      }
    }
  }
  if (!best) {
    not_found.push_back("the lips: not found (no skin in the lower middle of the frame)");
    return best;
  }
  const auto mid = reds.begin() + static_cast<std::ptrdiff_t>(reds.size() / 2);
  std::nth_element(reds.begin(), mid, reds.end());
  if (best_red - *mid < kLipRedness) {
    not_found.push_back(fmt::format(
        "the lips: not found (the reddest skin in the lower middle of the frame is only {:.3f} "
        "redder than its median, under the {} lips show)",
        best_red - *mid, kLipRedness));
    return std::nullopt;
  }
  return best;
}

// The largest luminance step across interior skin, measured between pixels `step` apart in x
// and in y: the key light's terminator or a cast shadow's edge.
std::optional<Landmark> shadow_edge(const image::Image& ref, const Box& box, const InteriorTest& in,
                                    int step) {
  std::optional<Landmark> best;
  float best_step = 0.0f;
  for (int y = box.y0 + step; y <= box.y1 - step; ++y) {
    for (int x = box.x0 + step; x <= box.x1 - step; ++x) {
      if (!in(x, y)) continue;
      const float gx = luminance(ref.at(x + step, y)) - luminance(ref.at(x - step, y));
      const float gy = luminance(ref.at(x, y + step)) - luminance(ref.at(x, y - step));
      const float g = std::hypot(gx, gy);
      if (g > best_step) {
        best_step = g;
        best = Landmark{"the strongest shadow edge on the skin (largest luminance step)", x, y};
      }
    }
  }
  return best;
}

// The skin's left edge at the height of the box's middle: where the rim light and the
// silhouette's aliasing show.
std::optional<Landmark> silhouette(const image::Mask& skin, const Box& box) {
  const int y = (box.y0 + box.y1) / 2;
  for (int x = 0; x < skin.width; ++x) {
    if (skin.values[static_cast<std::size_t>(y) * skin.width + x]) {
      return Landmark{"the silhouette (the skin's left edge at mid-height)", x, y};
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<Landmark> find_landmarks(const image::Image& reference, const image::Mask& skin,
                                     std::vector<std::string>* not_found) {
  std::vector<Landmark> out;
  std::vector<std::string> missing;
  const std::optional<Box> box = skin_box(skin);
  if (!box) return out;
  // Interior: 1% of the box's height from any non-skin pixel, so edges of the mask (eyelids,
  // silhouette) are not taken for lips or shadows.
  const int margin = std::max(2, (box->y1 - box->y0) / 100);
  const InteriorTest interior(skin, margin);
  for (const std::optional<Landmark>& found :
       {eye(skin, *box), lips(reference, *box, interior, missing),
        shadow_edge(reference, *box, interior, margin), silhouette(skin, *box)}) {
    if (found) out.push_back(*found);
  }
  if (not_found) *not_found = std::move(missing);
  return out;
}

}  // namespace skinsim::driver
