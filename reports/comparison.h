// What `skinsim compare A B` found between two runs or two sweeps: what changed in the
// configuration, which values moved beyond their tolerance, and whether the frames differ
// visibly (the sweep's FrameComparison rule). The driver fills it; the terminal table,
// compare.json and compare.html are written from it alone.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

// A knob or setting whose value differs between A and B ("" where one side has none).
struct SettingChange {
  std::string name;
  std::string a;
  std::string b;
};

// How close two values must be to count as the same: |b - a| <= tolerance x |a|.
struct Tolerances {
  double counter = 0.0;     // emulator counts: exact by default (the emulator is deterministic)
  double modelled = 0.001;  // modelled times, bytes and rates (timing.*, sensitivity.*)
  double quality = 0.001;   // image-quality metrics against each side's reference (quality.*)
};

// One numeric value of the results, e.g. "timing.frame_ms" or
// "counters.skin_shade.texture.cache_misses"; absent on a side that does not have it.
struct ValueDelta {
  std::string name;
  std::string kind;  // "counter", "modelled" or "quality": picks the tolerance
  std::optional<double> a;
  std::optional<double> b;
  double tolerance = 0.0;

  // (b - a) / |a|: +inf when a is 0 and b is not, or when one side lacks the value.
  double relative_change() const;
  bool moved() const;  // beyond the tolerance, or present on one side only
};

// A's frame against B's: FLIP over `mask_note`'s pixels, the verdict, and crops of the windows
// where they differ most (paths relative to the comparison's output directory).
struct ImageDiff {
  std::string a_image;  // paths as the page links them (relative to the output directory)
  std::string b_image;
  std::string difference_image;   // |B - A| amplified, full size ("" when not written)
  bool identical = false;         // same pixels: no FLIP needed
  std::string size_mismatch;      // e.g. "256x192 vs 320x240": not comparable, so different
  results::FrameComparison flip;  // B's frame against A's
  std::string over;               // what FLIP counted, e.g. "the whole frame"
  double threshold = 0.0;         // the rule: pixels above this FLIP error...
  double visible_area_px = 0.0;   // ...covering at least this many pixels are visible
  std::vector<results::CropWindow> windows;

  bool different() const { return !size_mismatch.empty() || flip.visible; }
};

// Another image of two runs (intermediates, the LUT, the reference, the error map): whether its
// pixels moved. Shown for what it tells (which pass changed), not judged: the frame's verdict
// and the counters decide whether the runs differ.
struct ImageChange {
  std::string name;     // file name, e.g. "irradiance.png"
  std::string a_image;  // links relative to the output directory ("" when only on one side)
  std::string b_image;
  std::string size_mismatch;     // e.g. "32x128 vs 8x32"
  std::size_t differing_px = 0;  // pixels whose stored value differs
  double max_difference = 0.0;   // largest |B - A| of a channel, in display values [0, 1]
};

// One run, or one configuration present in both sweeps.
struct ConfigDiff {
  std::string id;                    // the sweep configuration's id; "run" for two runs
  std::optional<double> frame_ms_a;  // the headline, moved or not
  std::optional<double> frame_ms_b;
  std::size_t values_compared = 0;
  std::vector<ValueDelta> moved;  // sorted by |relative change|, largest first
  std::optional<ImageDiff> image;
  std::vector<ImageChange> other_images;  // runs only

  bool different() const { return !moved.empty() || (image && image->different()); }
};

struct Comparison {
  std::string kind;  // "run" or "sweep"
  std::string a;     // the directories as given
  std::string b;
  Tolerances tolerances;
  std::vector<SettingChange> changes;  // what differs in the configuration, A -> B
  std::vector<std::string> added;      // sweep configurations only in B
  std::vector<std::string> removed;    // sweep configurations only in A
  std::vector<ConfigDiff> configs;
  std::string colour_bar;        // PNG of the difference images' colour scale ("" if none)
  double difference_gain = 1.0;  // difference images show |B - A| x gain

  // Anything added, removed, moved beyond tolerance or visibly different: exit status 1.
  bool different() const;
};

// The rule that makes two frames "visibly different" (FrameComparison::visible), FLIP counted
// over `over` (e.g. "the skin", "the whole frame"): one sentence for reports.
std::string visibility_rule_text(const std::string& over);

void to_json(nlohmann::json& j, const ValueDelta& v);
void to_json(nlohmann::json& j, const ImageDiff& v);
void to_json(nlohmann::json& j, const ImageChange& v);
void to_json(nlohmann::json& j, const ConfigDiff& v);
void to_json(nlohmann::json& j, const Comparison& v);

}  // namespace skinsim::reports
