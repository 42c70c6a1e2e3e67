#include "gpu_model/sensitivity.h"

#include <algorithm>

#include "gpu_model/frame_cost.h"

namespace skinsim::gpu_model {
namespace {

// An endpoint equal to the figure's own value is the base frame: no estimate, and above
// all no emulator re-run (e.g. the clock's range ends at its value).
std::optional<double> frame_ms_with(const std::vector<sim::PassCounters>& passes,
                                    const DeviceProfile& base, double base_ms,
                                    const FigureSpec& spec, double value, const Recount& recount) {
  if (value == (base.*spec.member).value) return base_ms;
  DeviceProfile varied = base;
  (varied.*spec.member).value = value;
  if (!spec.affects_counters) return estimate_frame(passes, varied).frame_ms;
  if (!recount) return std::nullopt;
  return estimate_frame(recount(varied), varied).frame_ms;
}

}  // namespace

std::vector<SensitivityRow> sensitivity(const std::vector<sim::PassCounters>& passes,
                                        const DeviceProfile& profile, const Recount& recount) {
  const double base_ms = estimate_frame(passes, profile).frame_ms;
  std::vector<SensitivityRow> rows;
  for (const FigureSpec& spec : figure_specs()) {
    const Figure& f = profile.*spec.member;
    if (!f.has_range || !spec.timed) continue;
    SensitivityRow row;
    row.figure = spec.path;
    row.unit = spec.unit;
    row.confidence = f.confidence;
    row.value_min = f.min;
    row.value_base = f.value;
    row.value_max = f.max;
    row.needs_recount = spec.affects_counters;
    row.frame_ms_base = base_ms;
    row.frame_ms_min = frame_ms_with(passes, profile, base_ms, spec, f.min, recount);
    row.frame_ms_max = frame_ms_with(passes, profile, base_ms, spec, f.max, recount);
    rows.push_back(std::move(row));
  }
  return rows;
}

FrameMsRange frame_ms_range(const std::vector<sim::PassCounters>& passes,
                            const DeviceProfile& profile) {
  FrameMsRange range;
  range.base = estimate_frame(passes, profile).frame_ms;
  DeviceProfile fastest = profile;
  DeviceProfile slowest = profile;
  for (const FigureSpec& spec : figure_specs()) {
    const Figure& f = profile.*spec.member;
    if (!f.has_range || !spec.timed) continue;
    if (spec.affects_counters) {
      ++range.left_out;
      continue;
    }
    ++range.figures;
    const double at_min = *frame_ms_with(passes, profile, range.base, spec, f.min, {});
    const double at_max = *frame_ms_with(passes, profile, range.base, spec, f.max, {});
    (fastest.*spec.member).value = at_min <= at_max ? f.min : f.max;
    (slowest.*spec.member).value = at_min <= at_max ? f.max : f.min;
  }
  // The corners bound the base in practice; min/max keep the stated order if a figure's
  // effect reverses when others move.
  range.low = std::min(range.base, estimate_frame(passes, fastest).frame_ms);
  range.high = std::max(range.base, estimate_frame(passes, slowest).frame_ms);
  return range;
}

}  // namespace skinsim::gpu_model
