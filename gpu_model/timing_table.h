// Human-readable tables (fixed-width text) of cost-model results and device profiles.
#pragma once

#include <string>
#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/sensitivity.h"
#include "gpu_model/tile_memory.h"
#include "gpu_model/timing.h"

namespace skinsim::gpu_model {

// One row per pass (its ms = share of the frame, bottleneck, TA, 3D and standalone ms,
// utilisation, core balance, DRAM MB), a dram_wait row when the frame is bandwidth-bound, and
// the frame; the rows' ms add up to the frame's.
std::string format_frame_table(const FrameTiming& frame);
// What each column of format_frame_table means, a few lines to print under it.
std::string frame_table_legend();

std::string format_sensitivity_table(const std::vector<SensitivityRow>& rows);

// The key figures of a profile that `skinsim devices` shows (its table and --json).
struct DeviceKeyFigures {
  double display_width = 0.0, display_height = 0.0;
  double cores = 0.0, pipes_per_core = 0.0, clock_mhz = 0.0;
  double peak_gflops = 0.0;  // FP32: cores x pipes x 8 FLOP (vec4 multiply-add) x clock
  double tmus = 0.0;         // texture units, all cores
  double dram_peak_gb_per_s = 0.0, dram_achievable_gb_per_s = 0.0;
  double tile_width = 0.0, tile_height = 0.0;
  double texture_cache_kib = 0.0;  // per core
  double fp16_rate = 0.0;          // mediump ops per highp op issued: 1 / alu.mediump_op_cost
  TileShape tile_at_32_bpp;        // fitted_tile at 32 bytes of colour per pixel
};
DeviceKeyFigures key_figures(const DeviceProfile& p);

// Key figures of the given profiles, one row each, and what each column means.
std::string format_device_table(const std::vector<DeviceProfile>& profiles);
std::string device_table_legend();

}  // namespace skinsim::gpu_model
