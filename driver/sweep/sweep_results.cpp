#include "driver/sweep/sweep_results.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <optional>
#include <set>

#include "driver/sweep/sweep_comparisons.h"
#include "driver/sweep/sweep_config_result.h"
#include "driver/sweep/sweep_crops.h"
#include "driver/sweep/sweep_run.h"
#include "reports/csv_writer.h"
#include "reports/recommendation.h"
#include "reports/sweep_json.h"

namespace skinsim::driver {

namespace {

// A stored result belongs to this sweep only when its whole fingerprint matches: every knob
// (the --set ones too), the device and the scene. Comparing the swept knobs alone would
// show another sweep's rows (one that differed only in a --set knob) as this one's.
bool belongs_to(const StoredConfig& stored, const SweepConfig& config,
                const std::map<std::string, nlohmann::json>& fingerprints) {
  const auto it = fingerprints.find(config.id);
  return it != fingerprints.end() && stored.fingerprint == it->second;
}

std::string joined(const std::set<std::string>& values) {
  return fmt::format("{}", fmt::join(values, ", "));
}

}  // namespace

results::SweepTable assemble_sweep_table(const SweepSpec& spec,
                                         const std::vector<SweepConfig>& configs,
                                         const std::map<std::string, nlohmann::json>& fingerprints,
                                         const std::string& out_dir) {
  results::SweepTable table;
  table.scene = spec.scene.label();
  table.budget_ms = spec.budget_ms;
  std::vector<StoredConfig> stored;
  std::set<std::string> devices, resolutions;
  for (const SweepConfig& c : configs) {
    std::optional<StoredConfig> s =
        read_stored_config(std::filesystem::path(out_dir) / config_json_path(c.id));
    if (!s || !belongs_to(*s, c, fingerprints)) continue;
    // configs/<id>.json keeps every knob (the fingerprint); the table shows the knobs the
    // frame depends on, so a knob the technique ignores has no misleading value.
    keep_used_knobs(c, s->row.knobs);
    devices.insert(results::knob_value(s->row, "device"));
    resolutions.insert(results::knob_value(s->row, "resolution"));
    table.rows.push_back(s->row);
    stored.push_back(std::move(*s));
  }
  table.device = joined(devices);
  table.resolution = joined(resolutions);
  if (stored.empty()) return table;

  const std::string metric = reports::recommend_metric(table.rows);
  add_comparisons(spec, table, out_dir, metric);
  const std::vector<reports::Recommendation> recommendations = reports::recommend(table, metric);
  const std::optional<std::size_t> first = recommendations.front().chosen;
  const StoredConfig& chosen = stored[first.value_or(0)];
  table.heatmap = chosen.heatmap;
  table.sensitivity = chosen.sensitivity;
  table.assumptions.push_back(
      fmt::format("Device figures, heat map and sensitivity are those of configuration '{}' ({}).",
                  chosen.row.id,
                  first ? fmt::format("the recommended one for {}", recommendations.front().group)
                        : "none fits the budget; the first one"));
  table.assumptions.insert(table.assumptions.end(), chosen.assumptions.begin(),
                           chosen.assumptions.end());
  return table;
}

void finish_sweep_data(results::SweepTable& table, const std::string& out_dir,
                       const std::map<std::string, std::string>& truth_images) {
  if (!table.rows.empty()) {
    const std::string metric = reports::recommend_metric(table.rows);
    table.panels = write_comparison_panels(table, reports::recommend(table, metric), out_dir,
                                           metric == "flip_skin", truth_images);
  }
  write_sweep_data(table, out_dir);
}

void remove_stale_report(const std::string& out_dir) {
  std::error_code ignored;  // none there: nothing stale
  std::filesystem::remove(std::filesystem::path(out_dir) / "report.html", ignored);
}

void write_sweep_data(const results::SweepTable& table, const std::string& out_dir) {
  const std::filesystem::path dir(out_dir);
  reports::write_sweep_json(table, (dir / "results.json").string());
  reports::write_sweep_csv(table, (dir / "results.csv").string());
}

}  // namespace skinsim::driver
