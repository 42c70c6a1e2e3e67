#include "driver/truth/truth_sweep.h"

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <optional>

#include "driver/frame/reference_cache.h"
#include "driver/sweep/frame_comparison.h"
#include "driver/sweep/sweep_results.h"
#include "reports/recommendation.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

struct RowImages {
  image::Image frame;
  std::optional<image::Mask> skin;  // the reference's, when it was rendered
  const image::Mask* mask() const { return skin && skin->count() > 0 ? &*skin : nullptr; }
};

RowImages load_row(const results::ConfigResult& row, const std::string& out_dir) {
  RowImages r;
  r.frame = image::load_png(fs::path(out_dir) / row.frame_image);
  if (!row.reference_image.empty()) {
    r.skin = image::load_mask_png(fs::path(out_dir) / reference_mask_path(row.reference_image));
  }
  return r;
}

// The figures of one region ("skin" -> "_skin", "all" -> "_frame") into the row's quality.
void add_figures(results::ConfigResult& row, const nlohmann::json& judged,
                 const nlohmann::json& floor) {
  for (const auto& [region, suffix] : {std::pair{"skin", "_skin"}, std::pair{"all", "_frame"}}) {
    if (!judged.contains(region)) continue;
    const nlohmann::json& m = judged[region];
    // Named as the reference's columns are (psnr_skin, visible_skin_pct), "truth_" first.
    for (const auto& [column, field] :
         {std::pair{"psnr{}", "psnr_db"}, std::pair{"ssim{}", "ssim"}, std::pair{"flip{}", "flip"},
          std::pair{"visible{}_pct", "visible_pct"}, std::pair{"visible{}_px", "visible_px"}}) {
      const nlohmann::json& v = m[field];
      if (v.is_number()) {
        row.quality["truth_" + fmt::format(fmt::runtime(column), suffix)] = v.get<double>();
      }
    }
    row.quality[fmt::format("truth_visible{}", suffix)] = m["visible"].get<bool>() ? 1.0 : 0.0;
    if (floor.value("measured", false) && floor.contains(region)) {
      row.quality[fmt::format("truth_floor_flip{}", suffix)] = floor[region]["flip"].get<double>();
    }
  }
}

std::optional<std::string> chosen_id(const reports::Recommendation& r,
                                     const results::SweepTable& table) {
  if (!r.chosen) return std::nullopt;
  return table.rows[*r.chosen].id;
}

}  // namespace

nlohmann::json judge_sweep_with_truth(results::SweepTable& table, const std::string& out_dir,
                                      const GroupTruth& truth_of) {
  const std::string metric = reports::recommend_metric(table.rows);
  const char* region = metric == "flip_skin" ? "skin" : "all";
  results::SweepTable judged = table;  // the verdicts the truth gives
  std::map<std::string, Truth> truths;
  std::map<std::string, nlohmann::json> groups;
  std::map<std::string, std::size_t> best;  // per group, the row closest to the truth
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    results::ConfigResult& row = table.rows[i];
    if (row.frame_image.empty()) continue;
    const RowImages images = load_row(row, out_dir);
    auto it = truths.find(row.group);
    if (it == truths.end()) {
      it = truths.emplace(row.group, truth_of(row, images.frame.width, images.frame.height)).first;
      // The report shows it beside the frames (sweep_report_truth.h), as they are seen.
      const std::string image = fmt::format("{}/g{}.png", kTruthImageDir, groups.size());
      fs::create_directories(fs::path(out_dir) / kTruthImageDir);
      image::save_png(it->second.images.image, fs::path(out_dir) / image);
      groups[row.group] = {{"group", row.group},
                           {"truth", it->second.about},
                           {"image", image},
                           {"noise_floor", truth_noise_floor(it->second, images.mask())}};
    }
    const nlohmann::json j = judge_against_truth(images.frame, it->second, images.mask());
    add_figures(row, j, groups[row.group]["noise_floor"]);
    const nlohmann::json& m = j.contains(region) ? j[region] : j["all"];
    judged.rows[i].quality[metric] = m["flip"].get<double>();
    judged.rows[i].visible_vs_reference = m["visible"].get<bool>();
    const auto b = best.find(row.group);
    if (b == best.end() || judged.rows[b->second].quality[metric] > m["flip"].get<double>()) {
      best[row.group] = i;
    }
  }
  // The recommendation's tie rule compares each frame with the best one: under the truth, the
  // best is the one closest to the truth.
  for (auto& [group, b] : best) {
    const RowImages best_images = load_row(table.rows[b], out_dir);
    for (results::ConfigResult& row : judged.rows) {
      if (row.group != group || row.frame_image.empty()) continue;
      const RowImages images = load_row(row, out_dir);
      row.vs_best = compare_frames(images.frame, best_images.frame, best_images.mask());
      row.vs_best->against = table.rows[b].id;
    }
  }
  const std::vector<reports::Recommendation> by_reference = reports::recommend(table, metric);
  const std::vector<reports::Recommendation> by_truth = reports::recommend(judged, metric);
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t g = 0; g < by_reference.size() && g < by_truth.size(); ++g) {
    nlohmann::json entry = groups[by_reference[g].group];
    const auto a = chosen_id(by_reference[g], table), b = chosen_id(by_truth[g], judged);
    entry["recommended_by_reference"] = a ? nlohmann::json(*a) : nlohmann::json();
    entry["recommended_by_truth"] = b ? nlohmann::json(*b) : nlohmann::json();
    entry["recommendation_same"] = a == b;
    entry["verdict_by_truth"] = by_truth[g].verdict;
    nlohmann::json changed = nlohmann::json::array();
    int verdicts = 0;
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      if (table.rows[i].group != by_reference[g].group || table.rows[i].frame_image.empty()) {
        continue;
      }
      ++verdicts;
      if (table.rows[i].visible_vs_reference != judged.rows[i].visible_vs_reference) {
        changed.push_back({{"id", table.rows[i].id},
                           {"visible_by_reference", table.rows[i].visible_vs_reference},
                           {"visible_by_truth", judged.rows[i].visible_vs_reference}});
      }
    }
    entry["visibility_verdicts"] = verdicts;
    entry["visibility_verdicts_changed"] = changed;
    out.push_back(entry);
  }
  return out;
}

std::vector<std::string> truth_sweep_lines(const nlohmann::json& judged) {
  std::vector<std::string> lines;
  const auto id = [](const nlohmann::json& v) {
    return v.is_null() ? std::string("none (nothing within the budget)") : v.get<std::string>();
  };
  for (const nlohmann::json& g : judged) {
    const std::string recommendation =
        g["recommendation_same"].get<bool>()
            ? "the recommendation stays " + id(g["recommended_by_reference"])
            : fmt::format("the recommendation changes from {} to {}",
                          id(g["recommended_by_reference"]), id(g["recommended_by_truth"]));
    const int verdicts = g["visibility_verdicts"].get<int>();
    const auto changed = g["visibility_verdicts_changed"].size();
    lines.push_back(fmt::format(
        "judged by the truth, {}: {}; {} of {} \"visibly different\" verdicts stay{} (the "
        "truth's noise floor: {})",
        g["group"].get<std::string>(), recommendation, verdicts - static_cast<int>(changed),
        verdicts, changed ? fmt::format(", {} change", changed) : "",
        truth_figures(g["noise_floor"])));
  }
  return lines;
}

}  // namespace skinsim::driver
