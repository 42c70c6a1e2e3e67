#include "driver/sweep_crops.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "driver/crop_landmarks.h"
#include "driver/sweep_reference.h"
#include "quality/error_map.h"
#include "quality/image.h"
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
std::optional<Window> worst_window(const quality::ScalarMap& error, int size,
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
Window zoom_window(const quality::ScalarMap& error, const Window& window) {
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

quality::Image crop(const quality::Image& image, const Window& w, int magnify) {
  quality::Image out;
  out.width = out.height = w.size * magnify;
  out.rgb.resize(out.pixel_count());
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x)
      out.at(x, y) = image.at(w.x + x / magnify, w.y + y / magnify);
  }
  return out;
}

quality::Image amplified_difference(const quality::Image& a, const quality::Image& b) {
  quality::ScalarMap d{a.width, a.height, std::vector<float>(a.pixel_count())};
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    const glm::vec3 diff = glm::abs(a.rgb[i] - b.rgb[i]);
    d.values[i] = static_cast<float>((diff.r + diff.g + diff.b) / 3.0 * kDifferenceGain);
  }
  return quality::false_colour(d);
}

quality::Image colour_bar() {
  quality::Image bar = quality::Image::filled(256, 16, glm::vec3(0.0f));
  for (int y = 0; y < bar.height; ++y) {
    for (int x = 0; x < bar.width; ++x) {
      bar.at(x, y) = quality::color_map(quality::ColorMap::kMagma, x / 255.0f);
    }
  }
  return bar;
}

quality::ScalarMap flip_map(const quality::Image& test, const quality::Image& against,
                            const quality::Mask* mask) {
  quality::ScalarMap map = quality::flip(test, against).map;
  if (mask) {  // windows are looked for where the metric looks: on skin
    for (std::size_t i = 0; i < map.values.size(); ++i) {
      if (mask->values[i] == 0) map.values[i] = 0.0f;
    }
  }
  return map;
}

}  // namespace

std::vector<reports::ComparisonPanel> write_comparison_panels(
    const reports::SweepTable& table, const std::vector<reports::Recommendation>& recommendations,
    const fs::path& sweep_dir, bool over_skin) {
  std::vector<reports::ComparisonPanel> panels;
  const std::string bar_path = "compare/colour_bar.png";
  fs::create_directories(sweep_dir / "compare");
  for (std::size_t g = 0; g < recommendations.size(); ++g) {
    const reports::Recommendation& rec = recommendations[g];
    if (!rec.chosen || !rec.best) continue;
    const reports::ConfigResult& chosen = table.rows[*rec.chosen];
    const reports::ConfigResult& best = table.rows[*rec.best];
    if (chosen.frame_image.empty() || chosen.reference_image.empty()) continue;
    const quality::Image reference = quality::load_png(sweep_dir / chosen.reference_image);
    const quality::Image chosen_frame = quality::load_png(sweep_dir / chosen.frame_image);
    const quality::Image best_frame = quality::load_png(sweep_dir / best.frame_image);
    std::optional<quality::Mask> skin;
    if (over_skin)
      skin = quality::load_mask_png(sweep_dir / reference_mask_path(chosen.reference_image));
    const quality::Mask* mask = skin ? &*skin : nullptr;

    reports::ComparisonPanel panel;
    panel.group = rec.group;
    panel.chosen = chosen.id;
    panel.best = best.id;
    panel.reference_image = chosen.reference_image;
    panel.chosen_image = chosen.frame_image;
    panel.best_image = best.frame_image;
    panel.difference_gain = kDifferenceGain;
    panel.colour_bar = bar_path;

    const int size =
        std::min(kWindow, std::min(reference.width, reference.height) / 2) / kZoom * kZoom;
    std::vector<std::pair<std::string, quality::ScalarMap>> searches;
    searches.emplace_back("largest error against the reference",
                          flip_map(chosen_frame, reference, mask));
    if (*rec.chosen != *rec.best) {
      searches.emplace_back("largest difference from the best configuration",
                            flip_map(chosen_frame, best_frame, mask));
    }
    const quality::Image difference = amplified_difference(chosen_frame, reference);
    std::vector<std::pair<std::string, const quality::Image*>> sources = {
        {"reference", &reference},
        {"best: " + best.id, &best_frame},
        {"recommended: " + chosen.id, &chosen_frame},
        {fmt::format("|recommended - reference| x {:g}", kDifferenceGain), &difference}};
    if (*rec.chosen == *rec.best) sources.erase(sources.begin() + 1);  // best == recommended
    const auto add_window = [&](const std::string& why, const Window& window, const Window& zoom) {
      const std::size_t w = panel.windows.size();
      reports::CropWindow crop_window{why,    window.x,  window.y, window.size, zoom.x,
                                      zoom.y, zoom.size, kZoom,    {},          {}};
      for (std::size_t k = 0; k < sources.size(); ++k) {
        const std::string stem = fmt::format("compare/g{}_w{}_{}", g, w, k);
        quality::save_png(crop(*sources[k].second, window, 1), sweep_dir / (stem + ".png"));
        quality::save_png(crop(*sources[k].second, zoom, kZoom), sweep_dir / (stem + "_x4.png"));
        crop_window.images.emplace_back(sources[k].first, stem + ".png");
        crop_window.zoomed.emplace_back(sources[k].first, stem + "_x4.png");
      }
      panel.windows.push_back(std::move(crop_window));
    };
    if (size < kZoom) {
      panels.push_back(std::move(panel));
      continue;
    }
    // The fixed places first (an eye, the lips, a shadow edge, the silhouette), then where the
    // error is worst.
    if (mask) {
      for (const Landmark& l : find_landmarks(reference, *mask)) {
        const Window window = centred(l.x, l.y, size, 0, 0, reference.width, reference.height);
        add_window(
            l.why, window,
            centred(l.x, l.y, size / kZoom, window.x, window.y, window.x + size, window.y + size));
      }
    }
    std::optional<Window> previous;
    for (const auto& [why, error] : searches) {
      const std::optional<Window> window = worst_window(error, size, previous);
      if (!window) continue;
      previous = window;
      add_window(why, *window, zoom_window(error, *window));
    }
    panels.push_back(std::move(panel));
  }
  if (!panels.empty()) quality::save_png(colour_bar(), sweep_dir / bar_path);
  return panels;
}

}  // namespace skinsim::driver
