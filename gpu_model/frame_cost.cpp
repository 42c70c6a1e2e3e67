#include "gpu_model/frame_cost.h"

#include <algorithm>
#include <cmath>

#include "gpu_model/energy.h"
#include "gpu_model/finite_timing.h"
#include "gpu_model/model_terms.h"
#include "gpu_model/pass_cost.h"
#include "util/check.h"

namespace skinsim::gpu_model {

std::vector<PassSlot> pipeline_schedule(const std::vector<PassTiming>& passes) {
  // Two-stage flow shop (TA -> 3D) in submission order. The TA of a pass starts when the TA is
  // free and the 3D has started the previous render (the parameter buffer holds one render
  // being drawn and one being binned); its 3D starts when its binning is done and the 3D is
  // free.
  std::vector<PassSlot> slots(passes.size());
  double ta_free = 0.0, render_free = 0.0, previous_render_start = 0.0;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    PassSlot& s = slots[i];
    s.ta_start_ms = std::max(ta_free, previous_render_start);
    s.ta_end_ms = s.ta_start_ms + passes[i].ta_ms;
    s.render_start_ms = std::max(s.ta_end_ms, render_free);
    s.render_end_ms = s.render_start_ms + passes[i].render_ms;
    s.exposed_ms = s.render_end_ms - render_free;
    ta_free = s.ta_end_ms;
    render_free = s.render_end_ms;
    previous_render_start = s.render_start_ms;
  }
  return slots;
}

FrameTiming estimate_frame(const std::vector<sim::PassCounters>& passes,
                           const DeviceProfile& profile) {
  FrameTiming f;
  f.device = profile.name;
  f.passes.reserve(passes.size());
  for (const sim::PassCounters& pass : passes) {
    f.passes.push_back(estimate_pass(pass, profile));
    f.dram.add(f.passes.back().dram);
  }
  f.schedule = pipeline_schedule(f.passes);
  f.pipeline_ms = f.schedule.empty() ? 0.0 : f.schedule.back().render_end_ms;
  f.dram_bytes = f.dram.total();
  // Overlapping stages share one DRAM: the frame is no faster than all its bytes.
  f.bandwidth_ms = f.dram_bytes / dram_bytes_per_ms(profile);
  f.frame_ms = std::max(f.pipeline_ms, f.bandwidth_ms);
  f.dram_wait_ms = f.frame_ms - f.pipeline_ms;
  f.fps = f.frame_ms > 0.0 ? 1000.0 / f.frame_ms : 0.0;
  f.energy = estimate_energy(passes, f.passes, profile);
  check_finite(f);
  double passes_ms = f.dram_wait_ms;
  for (const PassSlot& s : f.schedule) passes_ms += s.exposed_ms;
  SKINSIM_CHECK_LE(std::abs(passes_ms - f.frame_ms), 1e-9 * f.frame_ms);
  return f;
}

}  // namespace skinsim::gpu_model
