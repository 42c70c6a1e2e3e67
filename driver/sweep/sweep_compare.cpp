// `skinsim compare` of two sweep directories: configurations matched by id (ids are made from
// the knob values, so the same id is the same configuration), each one's modelled times and
// quality compared, and its frames where both sweeps kept them.
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "driver/sweep/image_diff.h"
#include "driver/sweep/result_values.h"
#include "driver/sweep/run_compare.h"
#include "driver/sweep/sweep_reference.h"

namespace skinsim::driver {

namespace fs = std::filesystem;
using results::ConfigResult;

namespace {

// A row's results under the names a run's result.json gives them.
NamedValues row_values(const ConfigResult& row) {
  NamedValues v = {{"timing.frame_ms", row.frame_ms},
                   {"timing.frame_ms_range.low", row.frame_ms_low},
                   {"timing.frame_ms_range.high", row.frame_ms_high},
                   {"timing.fps", row.fps},
                   {"timing.dram_bytes.total", row.dram_bytes},
                   {"energy.frame_mj", row.energy_mj},
                   {"energy.low_mj", row.energy_mj_low},
                   {"energy.high_mj", row.energy_mj_high}};
  for (const results::PassCost& p : results::merged_passes(row)) {
    v["timing.passes." + p.name + ".ms"] = p.ms;
  }
  for (const auto& [metric, value] : row.quality) v["quality." + metric] = value;
  return v;
}

// The sweep-wide settings, then every knob whose value differs between matched
// configurations (a knob both sweeps held fixed, at different values), once each.
std::vector<reports::SettingChange> setting_changes(
    const results::SweepTable& a, const results::SweepTable& b,
    const std::vector<std::pair<const ConfigResult*, const ConfigResult*>>& common) {
  std::vector<reports::SettingChange> changes;
  std::set<std::tuple<std::string, std::string, std::string>> seen;
  const auto add = [&](const std::string& name, const std::string& va, const std::string& vb) {
    if (va != vb && seen.emplace(name, va, vb).second) changes.push_back({name, va, vb});
  };
  add("device", a.device, b.device);
  add("scene", a.scene, b.scene);
  add("resolution", a.resolution, b.resolution);
  add("budget_ms", fmt::format("{:g}", a.budget_ms), fmt::format("{:g}", b.budget_ms));
  for (const auto& [ra, rb] : common) {
    std::set<std::string> knobs;
    for (const auto& [k, v] : ra->knobs) knobs.insert(k);
    for (const auto& [k, v] : rb->knobs) knobs.insert(k);
    for (const std::string& k : knobs)
      add(k, results::knob_value(*ra, k), results::knob_value(*rb, k));
  }
  return changes;
}

// A's frame against B's, FLIP over A's reference skin mask where the sweep kept one.
reports::ImageDiff diff_row_frames(const fs::path& a, const ConfigResult& ra, const fs::path& b,
                                   const ConfigResult& rb, const fs::path& out_dir) {
  std::optional<image::Mask> skin;
  if (!ra.reference_image.empty()) {
    const fs::path mask = a / reference_mask_path(ra.reference_image);
    if (fs::exists(mask)) skin = image::load_mask_png(mask);
  }
  reports::ImageDiff diff = diff_frames(
      a / ra.frame_image, b / rb.frame_image, skin ? &*skin : nullptr,
      skin ? "the skin (A's reference mask)" : "the whole frame", out_dir, "crops/" + ra.id);
  diff.a_image = link_from(out_dir, a / ra.frame_image);
  diff.b_image = link_from(out_dir, b / rb.frame_image);
  return diff;
}

}  // namespace

reports::Comparison compare_sweeps(const fs::path& a, const fs::path& b,
                                   const reports::Tolerances& tolerances, const fs::path& out_dir) {
  const results::SweepTable ta = results::read_sweep_json((a / "results.json").string());
  const results::SweepTable tb = results::read_sweep_json((b / "results.json").string());
  reports::Comparison c;
  c.kind = "sweep";
  std::map<std::string, const ConfigResult*> in_b;
  for (const ConfigResult& r : tb.rows) in_b[r.id] = &r;
  std::vector<std::pair<const ConfigResult*, const ConfigResult*>> common;
  for (const ConfigResult& r : ta.rows) {
    const auto it = in_b.find(r.id);
    if (it == in_b.end()) {
      c.removed.push_back(r.id);
      continue;
    }
    common.emplace_back(&r, it->second);
    in_b.erase(it);
  }
  for (const ConfigResult& r : tb.rows) {
    if (in_b.count(r.id)) c.added.push_back(r.id);
  }
  c.changes = setting_changes(ta, tb, common);
  if (!out_dir.empty()) fs::create_directories(out_dir / "crops");
  c.configs.resize(common.size());
  tbb::parallel_for(std::size_t{0}, common.size(), [&](std::size_t i) {
    const auto [ra, rb] = common[i];
    reports::ConfigDiff& d = c.configs[i];
    d.id = ra->id;
    compare_values(row_values(*ra), row_values(*rb), tolerances, d);
    if (!ra->frame_image.empty() && !rb->frame_image.empty()) {
      d.image = diff_row_frames(a, *ra, b, *rb, out_dir);
    }
  });
  return c;
}

}  // namespace skinsim::driver
