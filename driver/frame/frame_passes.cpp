#include "driver/frame/frame_passes.h"

#include "results/pass_rows.h"

namespace skinsim::driver {

namespace {

std::map<std::string, double> dram_by_cause(const gpu_model::DramBytes& d) {
  return {{"parameter_write", d.parameter_write},
          {"parameter_read", d.parameter_read},
          {"texture", d.texture},
          {"color_load", d.color_load},
          {"color_store", d.color_store},
          {"depth_load", d.depth_load},
          {"depth_store", d.depth_store}};
}

}  // namespace

std::vector<results::PassCost> pass_costs(const gpu_model::FrameTiming& timing) {
  std::vector<results::PassCost> passes;
  for (std::size_t i = 0; i < timing.passes.size(); ++i) {
    const gpu_model::PassTiming& p = timing.passes[i];
    const gpu_model::PassSlot& s = timing.schedule[i];
    passes.push_back({p.name, s.exposed_ms, gpu_model::unit_name(p.bottleneck),
                      dram_by_cause(p.dram), s.ta_start_ms, s.ta_end_ms, s.render_start_ms,
                      s.render_end_ms});
  }
  if (timing.dram_wait_ms > 0.0) {
    // On the 3D lane after the last render: the frame ends when its last byte has moved.
    passes.push_back({results::kDramWaitRow,
                      timing.dram_wait_ms,
                      gpu_model::unit_name(gpu_model::Unit::kBandwidth),
                      {},
                      timing.pipeline_ms,
                      timing.pipeline_ms,
                      timing.pipeline_ms,
                      timing.frame_ms});
  }
  return passes;
}

}  // namespace skinsim::driver
