// One frame, end to end: the pipeline on the emulated GPU configured from a device
// profile, then the cost model's timing of its passes.
#pragma once

#include "gpu_model/device_profile.h"
#include "gpu_model/timing.h"
#include "pipeline/config.h"
#include "pipeline/frame.h"
#include "pipeline/gpu_scene.h"

namespace skinsim::driver {

struct FrameResult {
  pipeline::PipelineConfig config;  // with the resolution resolved
  pipeline::FrameOutput output;
  gpu_model::FrameTiming timing;
};

// Resolves the config's resolution (default: the device display), renders and times the
// frame.
FrameResult run_frame(const pipeline::GpuScene& scene, pipeline::PipelineConfig config,
                      const gpu_model::DeviceProfile& device, int threads);

}  // namespace skinsim::driver
