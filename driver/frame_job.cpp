#include "driver/frame_job.h"

#include "gpu_model/frame_cost.h"
#include "gpu_model/gpu_config.h"

namespace skinsim::driver {

FrameResult run_frame(const pipeline::GpuScene& scene, pipeline::PipelineConfig config,
                      const gpu_model::DeviceProfile& device, int threads) {
  std::tie(config.width, config.height) =
      pipeline::render_size(config, static_cast<int>(device.display_width.value),
                            static_cast<int>(device.display_height.value));
  config.validate();
  sim::Gpu gpu(gpu_model::gpu_config(device, threads));
  FrameResult r;
  r.config = config;
  r.output = pipeline::render_frame(scene, config, gpu);
  r.timing = gpu_model::estimate_frame(r.output.passes, device);
  return r;
}

}  // namespace skinsim::driver
