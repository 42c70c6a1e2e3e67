#include "driver/sweep_comparisons.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>

#include <map>
#include <optional>

#include "driver/frame_comparison.h"
#include "driver/sweep_reference.h"
#include "io/atomic_file.h"
#include "io/read_file.h"
#include "pipeline/knob.h"
#include "quality/image.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

namespace fs = std::filesystem;
using reports::ConfigResult;
using reports::FrameComparison;

namespace {

// Device and resolution, then every swept knob the reference depends on (light, framing).
std::string group_label(const SweepSpec& spec, const ConfigResult& row) {
  std::vector<std::string> parts = {reports::knob_value(row, "device"),
                                    reports::knob_value(row, "resolution")};
  for (const SweepAxis& axis : spec.axes) {
    if (axis.knob == "device" || axis.knob == "resolution") continue;
    if (!pipeline::find_knob(axis.knob).reference) continue;
    const std::string value = reports::knob_value(row, axis.knob);
    if (!value.empty()) parts.push_back(axis.knob + " " + value);
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

// What the cached comparison of two frames depends on: both frames' and the mask's bytes.
std::string comparison_key(const fs::path& dir, const ConfigResult& row, const ConfigResult& other,
                           const std::string& mask) {
  std::string key = content_fingerprint(io::read_regular_file(dir / row.frame_image, "frame"));
  key += content_fingerprint(io::read_regular_file(dir / other.frame_image, "frame"));
  if (!mask.empty()) key += content_fingerprint(io::read_regular_file(dir / mask, "skin mask"));
  return key;
}

std::optional<FrameComparison> cached(const fs::path& path, const std::string& key) {
  if (!fs::exists(path)) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(io::read_regular_file(path, "comparison"), nullptr,
                                                 /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object() || j.value("key", "") != key) return std::nullopt;
  try {
    return j.at("comparison").get<FrameComparison>();
  } catch (const std::exception&) {
    return std::nullopt;  // damaged: compare again
  }
}

// `row`'s frame against `other`'s, as FLIP over the reference's skin (or the whole frame).
FrameComparison compare(const fs::path& dir, const ConfigResult& row, const ConfigResult& other,
                        bool over_skin) {
  FrameComparison c;
  c.against = other.id;
  if (row.id == other.id) return c;
  const std::string mask = over_skin ? reference_mask_path(row.reference_image) : "";
  const fs::path cache = dir / comparison_cache_path(row.id, other.id);
  const std::string key = comparison_key(dir, row, other, mask);
  if (std::optional<FrameComparison> hit = cached(cache, key)) return *hit;

  const quality::Image test = quality::load_png(dir / row.frame_image);
  const quality::Image against = quality::load_png(dir / other.frame_image);
  std::optional<quality::Mask> skin;
  if (over_skin) skin = quality::load_mask_png(dir / mask);
  c = compare_frames(test, against, skin ? &*skin : nullptr);
  c.against = other.id;
  fs::create_directories(cache.parent_path());
  io::write_file_atomically(cache, nlohmann::json{{"key", key}, {"comparison", c}}.dump(1) + "\n");
  return c;
}

// The best row of `members` (indices into rows) by `metric`, lower first; ties: the cheaper,
// then the earlier.
std::optional<std::size_t> best_of(const std::vector<ConfigResult>& rows,
                                   const std::vector<std::size_t>& members,
                                   const std::string& metric) {
  std::optional<std::size_t> best;
  for (const std::size_t i : members) {
    const auto it = rows[i].quality.find(metric);
    if (it == rows[i].quality.end()) continue;
    if (!best) {
      best = i;
      continue;
    }
    const double b = rows[*best].quality.at(metric);
    if (it->second < b || (it->second == b && rows[i].frame_ms < rows[*best].frame_ms)) best = i;
  }
  return best;
}

}  // namespace

std::string comparison_cache_path(const std::string& id, const std::string& other) {
  return "configs/compare/" + id + "_vs_" + other + ".json";
}

void add_comparisons(const SweepSpec& spec, reports::SweepTable& table, const fs::path& sweep_dir,
                     const std::string& metric) {
  std::vector<ConfigResult>& rows = table.rows;
  std::map<std::string, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].group = group_label(spec, rows[i]);
    groups[rows[i].group].push_back(i);
  }
  // (row, finest, best) for every row with images and a best to compare with.
  struct Task {
    std::size_t row, finest, best;
  };
  std::vector<Task> tasks;
  for (const auto& [group, members] : groups) {
    const std::optional<std::size_t> best = best_of(rows, members, metric);
    if (!best) continue;
    std::map<std::string, std::vector<std::size_t>> by_technique;
    for (const std::size_t i : members) {
      by_technique[reports::knob_value(rows[i], "technique")].push_back(i);
    }
    for (const auto& [technique, own] : by_technique) {
      const std::optional<std::size_t> finest = best_of(rows, own, metric);
      if (!finest) continue;
      for (const std::size_t i : own) {
        if (rows[i].frame_image.empty() || rows[i].reference_image.empty()) continue;
        tasks.push_back({i, *finest, *best});
      }
    }
  }
  const bool over_skin = metric == "flip_skin";
  tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t t) {
    const Task& task = tasks[t];
    ConfigResult& row = rows[task.row];
    row.vs_finest = compare(sweep_dir, row, rows[task.finest], over_skin);
    row.vs_best = task.best == task.finest ? *row.vs_finest
                                           : compare(sweep_dir, row, rows[task.best], over_skin);
  });
}

}  // namespace skinsim::driver
