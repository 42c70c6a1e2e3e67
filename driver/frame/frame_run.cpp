// resolve_config and run_frame (frame_job.h): the emulated frame and its modelled timing,
// apart from the reference and the image quality, so a program that only emulates frames
// (bench/thread_scaling) links no image library.
#include "driver/frame/frame_job.h"
#include "driver/frame/frame_work.h"
#include "gpu_model/frame_cost.h"
#include "gpu_model/gpu_config.h"
#include "sim/pass_memo.h"
#include "util/check.h"

namespace skinsim::driver {

pipeline::PipelineConfig resolve_config(pipeline::PipelineConfig config,
                                        const gpu_model::DeviceProfile& device) {
  std::tie(config.width, config.height) =
      pipeline::render_size(config, static_cast<int>(device.display_width.value),
                            static_cast<int>(device.display_height.value));
  config.validate();
  return config;
}

FrameResult run_frame(const pipeline::GpuScene& scene, const pipeline::PipelineConfig& config,
                      const gpu_model::DeviceProfile& device, int threads,
                      const PassCapture& capture, sim::PassMemo* memo) {
  SKINSIM_CHECK(config.width > 0 && config.height > 0);  // resolve_config first
  require_bounded_work(estimate_frame_work(scene, config), config, scene.scene().source);
  sim::Gpu gpu(gpu_model::gpu_config(device, threads));
  if (capture) gpu.set_pass_capture(capture);
  gpu.set_pass_memo(memo);
  FrameResult r;
  r.config = config;
  r.output = pipeline::render_frame(scene, config, gpu);
  if (memo) memo->end_frame();
  r.timing = gpu_model::estimate_frame(r.output.passes, device);
  r.range = gpu_model::frame_ms_range(r.output.passes, device);
  return r;
}

}  // namespace skinsim::driver
