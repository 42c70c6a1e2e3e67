#include "driver/sweep/sweep_crops.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "driver/sweep/crop_windows.h"
#include "driver/sweep/sweep_reference.h"
#include "image/image.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

std::vector<results::ComparisonPanel> write_comparison_panels(
    const results::SweepTable& table, const std::vector<reports::Recommendation>& recommendations,
    const fs::path& sweep_dir, bool over_skin,
    const std::map<std::string, std::string>& truth_images) {
  std::vector<results::ComparisonPanel> panels;
  const std::string bar_path = "compare/colour_bar.png";
  fs::create_directories(sweep_dir / "compare");
  for (std::size_t g = 0; g < recommendations.size(); ++g) {
    const reports::Recommendation& rec = recommendations[g];
    if (!rec.chosen || !rec.best) continue;
    const results::ConfigResult& chosen = table.rows[*rec.chosen];
    const results::ConfigResult& best = table.rows[*rec.best];
    if (chosen.frame_image.empty() || chosen.reference_image.empty()) continue;
    const image::Image reference = image::load_png(sweep_dir / chosen.reference_image);
    const image::Image chosen_frame = image::load_png(sweep_dir / chosen.frame_image);
    const image::Image best_frame = image::load_png(sweep_dir / best.frame_image);
    std::optional<image::Mask> skin;
    if (over_skin)
      skin = image::load_mask_png(sweep_dir / reference_mask_path(chosen.reference_image));
    const image::Mask* mask = skin ? &*skin : nullptr;

    results::ComparisonPanel panel;
    panel.group = rec.group;
    panel.chosen = chosen.id;
    panel.best = best.id;
    panel.reference_image = chosen.reference_image;
    panel.chosen_image = chosen.frame_image;
    panel.best_image = best.frame_image;
    panel.difference_gain = kDifferenceGain;
    panel.colour_bar = bar_path;
    std::optional<image::Image> truth;
    if (const auto t = truth_images.find(rec.group); t != truth_images.end()) {
      truth = image::load_png(sweep_dir / t->second);
    }

    std::vector<NamedMap> searches;
    searches.emplace_back("largest error against the reference",
                          flip_error_map(chosen_frame, reference, mask));
    if (*rec.chosen != *rec.best) {
      searches.emplace_back("largest difference from the best configuration",
                            flip_error_map(chosen_frame, best_frame, mask));
    }
    // Each window shows both differences, so a window found against the best shows the
    // difference it was found in, not only the one against the reference.
    const image::Image difference = amplified_difference(chosen_frame, reference);
    const image::Image from_best = amplified_difference(chosen_frame, best_frame);
    std::vector<NamedImage> images = {
        {"reference", &reference},
        {"best: " + best.id, &best_frame},
        {"recommended: " + chosen.id, &chosen_frame},
        {fmt::format("|recommended - reference| x {:g}", kDifferenceGain), &difference},
        {fmt::format("|recommended - best| x {:g}", kDifferenceGain), &from_best}};
    if (*rec.chosen == *rec.best) {  // best == recommended
      images.pop_back();
      images.erase(images.begin() + 1);
    }
    // The truth beside the reference, and the recommended frame's difference from it beside
    // the one from the reference.
    std::optional<image::Image> from_truth;
    if (truth) {
      from_truth = amplified_difference(chosen_frame, *truth);
      images.insert(images.begin() + 1, {"truth (path-traced)", &*truth});
      const auto after = std::find_if(images.begin(), images.end(), [](const NamedImage& i) {
        return i.first.rfind("|recommended - reference|", 0) == 0;
      });
      images.insert(after + 1,
                    {fmt::format("|recommended - truth| x {:g}", kDifferenceGain), &*from_truth});
    }
    // The fixed places first (an eye, the lips, a shadow edge, the silhouette), then where the
    // error is worst.
    std::vector<std::string> not_found;
    const std::vector<Landmark> landmarks =
        mask ? find_landmarks(reference, *mask, &not_found) : std::vector<Landmark>{};
    panel.windows = write_crop_windows(landmarks, searches, images, sweep_dir,
                                       fmt::format("compare/g{}", g), not_found);
    panels.push_back(std::move(panel));
  }
  if (!panels.empty()) write_colour_bar(sweep_dir / bar_path);
  return panels;
}

}  // namespace skinsim::driver
