#include "reports/compare_table.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string_view>

namespace skinsim::reports {

namespace {

// Whether a value's name says it counts bytes: "frame.dram_bytes",
// "timing.passes.skin.dram_bytes.texture" (bytes by cause).
bool counts_bytes(const std::string& name) {
  for (std::size_t end = name.find('.'), start = 0;; start = end + 1, end = name.find('.', start)) {
    if (std::string_view(name).substr(start, end - start).ends_with("bytes")) return true;
    if (end == std::string::npos) return false;
  }
}

// A value as the other tables print it: bytes in MB (10^6; six decimals, so a change of one
// byte still shows), the rest as they are.
std::string number(const std::string& name, const std::optional<double>& v) {
  if (!v) return "-";
  if (counts_bytes(name)) return fmt::format("{:.6f} MB", *v / 1e6);
  return fmt::format("{:.6g}", *v);
}

std::string tolerance_text(const char* what, double tolerance) {
  if (tolerance == 0.0) return fmt::format("{} exact", what);
  return fmt::format("{} within {:g}%", what, tolerance * 100.0);
}

std::string changes_text(const Comparison& c) {
  if (c.changes.empty()) return std::string("Changed: ") + kNoChangeText + "\n";
  std::string out = "Changed (A -> B):\n";
  for (const SettingChange& s : c.changes) {
    out += fmt::format("  {}: {} -> {}\n", s.name, s.a.empty() ? "(none)" : s.a,
                       s.b.empty() ? "(none)" : s.b);
  }
  return out;
}

std::string moved_table(const ConfigDiff& d, std::size_t max_values) {
  if (d.moved.empty()) {
    return fmt::format("Moved: none of {} values beyond tolerance\n", d.values_compared);
  }
  std::string out = fmt::format(
      "Moved: {} of {} values beyond tolerance, largest first{}:\n", d.moved.size(),
      d.values_compared,
      d.moved.size() > max_values ? fmt::format(" (the first {}; compare.json has all)", max_values)
                                  : "");
  const std::size_t shown = std::min(max_values, d.moved.size());
  std::size_t width = 5;
  for (std::size_t i = 0; i < shown; ++i) width = std::max(width, d.moved[i].name.size());
  out += fmt::format("  {:<{}}  {:>14}  {:>14}  {:>10}\n", "value", width, "A", "B", "change");
  for (std::size_t i = 0; i < shown; ++i) {
    const ValueDelta& v = d.moved[i];
    out += fmt::format("  {:<{}}  {:>14}  {:>14}  {:>10}\n", v.name, width, number(v.name, v.a),
                       number(v.name, v.b), change_text(v));
  }
  return out;
}

std::string run_text(const Comparison& c, std::size_t max_values) {
  std::string out = changes_text(c) + "Frame time: " + frame_time_text(c.configs.front()) + "\n" +
                    moved_table(c.configs.front(), max_values);
  const std::optional<ImageDiff>& image = c.configs.front().image;
  if (image) out += "Frame: " + image_verdict_text(*image) + "\n";
  if (!c.configs.front().other_images.empty()) {
    out += "Other images (shown, not judged):\n";
    for (const ImageChange& i : c.configs.front().other_images) {
      out += fmt::format("  {}: {}\n", i.name, image_change_text(i));
    }
  }
  return out;
}

std::string sweep_text(const Comparison& c) {
  std::string out = changes_text(c);
  out += fmt::format("Configurations: {} in both, {} only in B, {} only in A\n", c.configs.size(),
                     c.added.size(), c.removed.size());
  if (!c.added.empty()) out += fmt::format("  only in B: {}\n", fmt::join(c.added, ", "));
  if (!c.removed.empty()) out += fmt::format("  only in A: {}\n", fmt::join(c.removed, ", "));
  std::size_t width = 13;
  for (const ConfigDiff& d : c.configs) width = std::max(width, d.id.size());
  out += fmt::format("  {:<{}}  {:<30}  {:>5}  {}\n", "configuration", width, "frame time A -> B",
                     "moved", "frames");
  for (const ConfigDiff& d : c.configs) {
    out += fmt::format("  {:<{}}  {:<30}  {:>5}  {}\n", d.id, width, frame_time_text(d),
                       d.moved.size(), d.image ? image_verdict_short(*d.image) : "no frames kept");
  }
  out += "  (moved: values beyond tolerance; compare.json lists them)\n";
  return out;
}

}  // namespace

std::string change_text(const ValueDelta& d) {
  if (!d.a) return "only in B";
  if (!d.b) return "only in A";
  if (*d.a == 0.0) return "from 0";
  return fmt::format("{:+.1f}%", d.relative_change() * 100.0);
}

std::string frame_time_text(const ConfigDiff& d) {
  if (!d.frame_ms_a || !d.frame_ms_b) return "-";
  if (*d.frame_ms_a == *d.frame_ms_b) return fmt::format("{:.3f} ms, unchanged", *d.frame_ms_a);
  const ValueDelta delta{"timing.frame_ms", "modelled", d.frame_ms_a, d.frame_ms_b, 0.0};
  return fmt::format("{:.3f} ms -> {:.3f} ms ({})", *d.frame_ms_a, *d.frame_ms_b,
                     change_text(delta));
}

std::string image_verdict_text(const ImageDiff& d) {
  if (!d.size_mismatch.empty()) return "different sizes (" + d.size_mismatch + ")";
  if (d.identical) return "identical pixels";
  return fmt::format(
      "{}: FLIP over {} mean {:.4f}, p99 {:.4f}, {:.0f} px above {:.2f} (visible "
      "from {:.0f} px)",
      d.flip.visible ? "visibly different" : "not visibly different", d.over, d.flip.flip_mean,
      d.flip.flip_p99, d.flip.visible_px, d.threshold, d.visible_area_px);
}

std::string image_change_text(const ImageChange& c) {
  if (c.a_image.empty()) return "only in B";
  if (c.b_image.empty()) return "only in A";
  if (!c.size_mismatch.empty()) return "different sizes (" + c.size_mismatch + ")";
  if (c.differing_px == 0) return "identical";
  return fmt::format("{} px differ (largest {:.3f})", c.differing_px, c.max_difference);
}

std::string image_verdict_short(const ImageDiff& d) {
  if (!d.size_mismatch.empty() || d.identical) return image_verdict_text(d);
  return fmt::format("{} ({:.0f} px above {:.2f})",
                     d.flip.visible ? "visibly different" : "not visibly different",
                     d.flip.visible_px, d.threshold);
}

std::string tolerances_text(const Tolerances& t) {
  return fmt::format("{}, {}, {}", tolerance_text("counters", t.counter),
                     tolerance_text("modelled values", t.modelled),
                     tolerance_text("quality metrics", t.quality));
}

std::string format_comparison(const Comparison& c, std::size_t max_values) {
  std::string out = fmt::format("A: {} ({})\nB: {} ({})\nTolerances: {}\n", c.a, c.kind, c.b,
                                c.kind, tolerances_text(c.tolerances));
  out += c.kind == "run" ? run_text(c, max_values) : sweep_text(c);
  out += c.different() ? "Result: different (exit status 1)\n"
                       : "Result: the same within "
                         "tolerances (exit status 0)\n";
  return out;
}

}  // namespace skinsim::reports
