#include "driver/sweep/crop_windows.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "quality/error_map.h"
#include "quality/metrics.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

constexpr int kWindow = 128;  // 1:1 crop edge in pixels (smaller frames: half their height)
constexpr int kZoom = 4;

struct Window {
  int x = 0, y = 0, size = 0;
};

bool overlaps(const Window& a, const Window& b) {
  return a.x < b.x + b.size && b.x < a.x + a.size && a.y < b.y + b.size && b.y < a.y + a.size;
}

// The size x size window with the largest error sum (a summed-area table), not overlapping
// `avoid`; ties go to the first in row order, so the choice is deterministic.
std::optional<Window> worst_window(const image::ScalarMap& error, int size,
                                   const std::optional<Window>& avoid) {
  const int w = error.width, h = error.height;
  std::vector<double> sat(static_cast<std::size_t>(w + 1) * (h + 1), 0.0);
  const auto at = [&](int x, int y) -> double& {
    return sat[static_cast<std::size_t>(y) * (w + 1) + x];
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      at(x + 1, y + 1) = error.values[static_cast<std::size_t>(y) * w + x] + at(x, y + 1) +
                         at(x + 1, y) - at(x, y);
    }
  }
  std::optional<Window> best;
  double best_sum = 0.0;
  for (int y = 0; y + size <= h; y += size / 8) {
    for (int x = 0; x + size <= w; x += size / 8) {
      const Window candidate{x, y, size};
      if (avoid && overlaps(candidate, *avoid)) continue;
      const double sum = at(x + size, y + size) - at(x, y + size) - at(x + size, y) + at(x, y);
      if (sum > best_sum) {
        best_sum = sum;
        best = candidate;
      }
    }
  }
  return best;  // none when the error is zero everywhere outside `avoid`
}

// The magnified window: size/zoom around the window's largest error, inside the window.
Window zoom_window(const image::ScalarMap& error, const Window& window) {
  int px = window.x, py = window.y;
  float largest = -1.0f;
  for (int y = window.y; y < window.y + window.size; ++y) {
    for (int x = window.x; x < window.x + window.size; ++x) {
      const float v = error.values[static_cast<std::size_t>(y) * error.width + x];
      if (v > largest) {
        largest = v;
        px = x;
        py = y;
      }
    }
  }
  const int size = window.size / kZoom;
  return {std::clamp(px - size / 2, window.x, window.x + window.size - size),
          std::clamp(py - size / 2, window.y, window.y + window.size - size), size};
}

// The size x size window centred on (x, y) as far as the area [x0, x1) x [y0, y1) allows.
Window centred(int x, int y, int size, int x0, int y0, int x1, int y1) {
  return {std::clamp(x - size / 2, x0, x1 - size), std::clamp(y - size / 2, y0, y1 - size), size};
}

image::Image crop(const image::Image& image, const Window& w, int magnify) {
  image::Image out;
  out.width = out.height = w.size * magnify;
  out.rgb.resize(out.pixel_count());
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x)
      out.at(x, y) = image.at(w.x + x / magnify, w.y + y / magnify);
  }
  return out;
}

}  // namespace

void write_colour_bar(const fs::path& path) {
  image::Image bar = image::Image::filled(256, 16, glm::vec3(0.0f));
  for (int y = 0; y < bar.height; ++y) {
    for (int x = 0; x < bar.width; ++x) {
      bar.at(x, y) = quality::color_map(quality::ColorMap::kMagma, x / 255.0f);
    }
  }
  image::save_png(bar, path);
}

image::ScalarMap flip_error_map(const image::Image& test, const image::Image& against,
                                const image::Mask* mask) {
  image::ScalarMap map = quality::flip(test, against).map;
  if (mask) {  // windows are looked for where the metric looks: on skin
    for (std::size_t i = 0; i < map.values.size(); ++i) {
      if (mask->values[i] == 0) map.values[i] = 0.0f;
    }
  }
  return map;
}

image::Image amplified_difference(const image::Image& a, const image::Image& b) {
  image::ScalarMap d{a.width, a.height, std::vector<float>(a.pixel_count())};
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    const glm::vec3 diff = glm::abs(a.rgb[i] - b.rgb[i]);
    d.values[i] = static_cast<float>((diff.r + diff.g + diff.b) / 3.0 * kDifferenceGain);
  }
  return quality::false_colour(d);
}

std::vector<results::CropWindow> write_crop_windows(const std::vector<Landmark>& landmarks,
                                                    const std::vector<NamedMap>& searches,
                                                    const std::vector<NamedImage>& images,
                                                    const fs::path& dir, const std::string& stem,
                                                    const std::vector<std::string>& not_found) {
  std::vector<results::CropWindow> windows;
  if (images.empty()) return windows;
  const image::Image& first = *images.front().second;
  const int size = std::min(kWindow, std::min(first.width, first.height) / 2) / kZoom * kZoom;
  if (size < kZoom) return windows;
  const auto add = [&](const std::string& why, const Window& window, const Window& zoom) {
    results::CropWindow crop_window{why,    window.x,  window.y, window.size, zoom.x,
                                    zoom.y, zoom.size, kZoom,    {},          {}};
    for (std::size_t k = 0; k < images.size(); ++k) {
      const std::string name = fmt::format("{}_w{}_{}", stem, windows.size(), k);
      image::save_png(crop(*images[k].second, window, 1), dir / (name + ".png"));
      image::save_png(crop(*images[k].second, zoom, kZoom), dir / (name + "_x4.png"));
      crop_window.images.emplace_back(images[k].first, name + ".png");
      crop_window.zoomed.emplace_back(images[k].first, name + "_x4.png");
    }
    windows.push_back(std::move(crop_window));
  };
  for (const Landmark& l : landmarks) {  // centred on it, magnified around it
    const Window window = centred(l.x, l.y, size, 0, 0, first.width, first.height);
    add(l.why, window,
        centred(l.x, l.y, size / kZoom, window.x, window.y, window.x + size, window.y + size));
  }
  for (const std::string& why : not_found) {
    results::CropWindow sentence;
    sentence.why = why;
    windows.push_back(std::move(sentence));
  }
  std::optional<Window> previous;
  for (const auto& [why, error] : searches) {
    const std::optional<Window> window = worst_window(error, size, previous);
    if (!window) continue;
    previous = window;
    add(why, *window, zoom_window(error, *window));
  }
  return windows;
}

}  // namespace skinsim::driver
