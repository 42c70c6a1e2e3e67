#include "driver/sweep/sweep_comparisons.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/collaborative_call_once.h>
#include <tbb/parallel_for.h>

#include <functional>
#include <map>
#include <mutex>
#include <optional>

#include "driver/sweep/frame_comparison.h"
#include "driver/sweep/sweep_reference.h"
#include "image/image.h"
#include "io/atomic_file.h"
#include "io/json_input.h"
#include "pipeline/knob.h"
#include "util/build_identity.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

namespace fs = std::filesystem;
using results::ConfigResult;
using results::FrameComparison;

namespace {

// Device and resolution, then every swept knob the reference depends on (light, framing).
std::string group_label(const SweepSpec& spec, const ConfigResult& row) {
  std::vector<std::string> parts = {results::knob_value(row, "device"),
                                    results::knob_value(row, "resolution")};
  for (const SweepAxis& axis : spec.axes) {
    if (axis.knob == "device" || axis.knob == "resolution") continue;
    if (!pipeline::find_knob(axis.knob).reference) continue;
    const std::string value = results::knob_value(row, axis.knob);
    if (!value.empty()) parts.push_back(axis.knob + " " + value);
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

// What the cached comparison of two frames depends on: both frames' and the mask's bytes, and
// the build that measures them.
std::string comparison_key(const fs::path& dir, const ConfigResult& row, const ConfigResult& other,
                           const std::string& mask) {
  std::string key(build_identity());
  key += content_fingerprint(io::read_regular_file(dir / row.frame_image, "frame"));
  key += content_fingerprint(io::read_regular_file(dir / other.frame_image, "frame"));
  if (!mask.empty()) key += content_fingerprint(io::read_regular_file(dir / mask, "skin mask"));
  return key;
}

std::optional<FrameComparison> cached(const fs::path& path, const std::string& key) {
  if (!fs::exists(path)) return std::nullopt;
  const nlohmann::json j = io::parse_json_or_discarded(io::read_regular_file(path, "comparison"));
  if (j.is_discarded() || !j.is_object() || j.value("key", "") != key) return std::nullopt;
  try {
    return j.at("comparison").get<FrameComparison>();
  } catch (const std::exception&) {
    return std::nullopt;  // damaged: compare again
  }
}

// The images the comparisons read, each prepared once: a group's best and finest frames are
// compared with every member, and a reference's skin mask serves its whole group.
class ComparisonImages {
 public:
  explicit ComparisonImages(fs::path dir) : dir_(std::move(dir)) {}

  // A frame's FLIP features: what every comparison against it needs.
  const quality::FlipFeatures& frame(const std::string& relative) {
    return get(frames_, relative,
               [](const fs::path& p) { return quality::FlipFeatures(image::load_png(p)); });
  }
  const image::Mask& mask(const std::string& relative) {
    return get(masks_, relative, [](const fs::path& p) { return image::load_mask_png(p); });
  }

 private:
  template <class T>
  struct Entry {
    tbb::collaborative_once_flag once;
    std::optional<T> value;
  };

  // The first comparison to ask for an image prepares it; the others that ask meanwhile help
  // with its parallel work instead of preparing it again. The first tasks all ask at once, and
  // the best frame's features (100 MB) were made twice: a resumed sweep's comparisons and
  // report peaked at 652 MB, now 584-590 MB.
  template <class T, class Load>
  const T& get(std::map<std::string, Entry<T>>& cache, const std::string& relative, Load load) {
    Entry<T>* entry = nullptr;
    {
      const std::lock_guard lock(mutex_);
      entry = &cache[relative];  // std::map: stays put
    }
    tbb::collaborative_call_once(entry->once, [&] { entry->value.emplace(load(dir_ / relative)); });
    return *entry->value;
  }

  const fs::path dir_;
  std::mutex mutex_;
  std::map<std::string, Entry<quality::FlipFeatures>> frames_;
  std::map<std::string, Entry<image::Mask>> masks_;
};

// `row`'s frame (decoded by `test` when not cached) against `other`'s, as FLIP over the
// reference's skin (or the whole frame).
FrameComparison compare(const fs::path& dir, const ConfigResult& row,
                        const std::function<const image::Image&()>& test, const ConfigResult& other,
                        bool over_skin, ComparisonImages& images) {
  FrameComparison c;
  c.against = other.id;
  if (row.id == other.id) return c;
  const std::string mask = over_skin ? reference_mask_path(row.reference_image) : "";
  const fs::path cache = dir / comparison_cache_path(row.id, other.id);
  const std::string key = comparison_key(dir, row, other, mask);
  if (std::optional<FrameComparison> hit = cached(cache, key)) return *hit;

  c = compare_frames(test(), images.frame(other.frame_image),
                     over_skin ? &images.mask(mask) : nullptr);
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

void add_comparisons(const SweepSpec& spec, results::SweepTable& table, const fs::path& sweep_dir,
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
      by_technique[results::knob_value(rows[i], "technique")].push_back(i);
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
  ComparisonImages images(sweep_dir);
  tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t t) {
    const Task& task = tasks[t];
    ConfigResult& row = rows[task.row];
    std::optional<image::Image> own;  // decoded once, and only if a comparison is not cached
    const std::function<const image::Image&()> own_frame = [&]() -> const image::Image& {
      if (!own) own = image::load_png(sweep_dir / row.frame_image);
      return *own;
    };
    const auto compare_with = [&](std::size_t other) {
      return compare(sweep_dir, row, own_frame, rows[other], over_skin, images);
    };
    row.vs_finest = compare_with(task.finest);
    row.vs_best = task.best == task.finest ? *row.vs_finest : compare_with(task.best);
  });
}

}  // namespace skinsim::driver
