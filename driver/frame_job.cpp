#include "driver/frame_job.h"

#include "gpu_model/frame_cost.h"

namespace skinsim::driver {

sim::GpuConfig gpu_config(const gpu_model::DeviceProfile& device, int threads) {
  const gpu_model::SimParameters p = gpu_model::sim_parameters(device);
  sim::GpuConfig c;
  c.tile_size = p.tile_width;
  c.cores = p.cores;
  c.texture_cache.size_bytes = static_cast<std::uint32_t>(p.texture_cache_bytes);
  c.texture_cache.line_bytes = static_cast<std::uint32_t>(p.texture_cache_line_bytes);
  c.texture_cache.associativity = static_cast<std::uint32_t>(p.texture_cache_ways);
  c.depth_stencil_bytes_per_pixel = p.tile_depth_stencil_bytes_per_pixel;
  c.threads = threads;
  return c;
}

FrameResult run_frame(const pipeline::GpuScene& scene, pipeline::PipelineConfig config,
                      const gpu_model::DeviceProfile& device, int threads) {
  std::tie(config.width, config.height) =
      pipeline::render_size(config, static_cast<int>(device.display_width.value),
                            static_cast<int>(device.display_height.value));
  config.validate();
  sim::Gpu gpu(gpu_config(device, threads));
  FrameResult r;
  r.config = config;
  r.output = pipeline::render_frame(scene, config, gpu);
  r.timing = gpu_model::estimate_frame(r.output.passes, device);
  return r;
}

}  // namespace skinsim::driver
