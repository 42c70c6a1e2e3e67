// TEST DATA ONLY: a made-up sweep (4 integration-buffer scales x 4 LUT sizes) with plausible
// but invented numbers, for exercising the reports module without running the simulator.
// Nothing here is a modelled or measured result.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "results/sweep_table.h"

namespace skinsim::reports::testing {

inline results::ConfigResult synthetic_config(double scale, int lut_w, int lut_h) {
  results::ConfigResult c;
  c.id = fmt::format("s{}_lut{}x{}", scale, lut_w, lut_h);
  c.label = fmt::format("scale {}, LUT {}x{}", scale, lut_w, lut_h);
  c.knobs = {{"technique", "mobile_ssss"},
             {"scale", fmt::format("{}", scale)},
             {"lut", fmt::format("{}x{}", lut_w, lut_h)},
             {"lut_format", "rgba8"},
             {"blur_iterations", "1"},
             {"device", "sgx554mp4"},
             {"resolution", "2048x1536"}};
  const double area = scale * scale;
  const double lut_steps = std::log2(lut_w * lut_h / 1024.0);  // 0 for 16x64 ... 6 for 128x512
  const double irradiance = 1.0 + 9.0 * area;
  const double blur = 0.6 + 4.5 * area;
  const double shade = 13.0 + 0.9 * lut_steps;
  c.passes = {
      {"irradiance",
       irradiance,
       area > 0.3 ? "alu" : "vertex",
       {{"color_store", 12.6e6 * area}, {"parameter_buffer", 3.1e6}}},
      {"blur_h", blur, "texture", {{"color_store", 12.6e6 * area}, {"texture_miss", 9e6 * area}}},
      {"blur_v", blur, "texture", {{"color_store", 12.6e6 * area}, {"texture_miss", 9e6 * area}}},
      {"skin_shade",
       shade,
       lut_steps > 3 ? "texture" : "alu",
       {{"color_store", 12.6e6}, {"texture_miss", 4e6 + 1.5e6 * lut_steps}}},
      {"eyes_background", 2.0, "dram", {{"color_store", 2e6}, {"color_load", 12.6e6}}}};
  c.frame_ms = 0.0;
  c.dram_bytes = 0.0;
  for (results::PassCost& p : c.passes) {  // renders back to back, no TA work
    p.render_start_ms = p.ta_start_ms = p.ta_end_ms = c.frame_ms;
    p.render_end_ms = c.frame_ms + p.ms;
    c.frame_ms += p.ms;
    for (const auto& [cause, bytes] : p.dram_bytes_by_cause) c.dram_bytes += bytes;
  }
  c.fps = 1000.0 / c.frame_ms;
  c.frame_ms_low = 0.9 * c.frame_ms;  // a profile's uncertain figures: -10% / +40%
  c.frame_ms_high = 1.4 * c.frame_ms;
  c.energy_mj = 0.1e-6 * c.dram_bytes + 0.05 * c.frame_ms;  // 100 pJ/B plus the work
  c.energy_mj_low = 0.6 * c.energy_mj;
  c.energy_mj_high = 1.7 * c.energy_mj;
  const double flip = 0.03 + 0.09 * std::pow(1.0 - scale, 1.5) + 0.04 / (1.0 + lut_steps);
  c.quality = {{"flip_skin", flip},
               {"ssim_skin", 1.0 - 1.6 * flip},
               {"psnr_skin", 44.0 - 80.0 * flip},
               {"psnr_frame", 47.0 - 60.0 * flip}};
  c.frame_image = "frames/" + c.id + ".png";
  c.error_image = "errors/" + c.id + ".png";
  return c;
}

inline results::TileHeatmap synthetic_heatmap() {
  results::TileHeatmap h;
  h.tiles_x = 64;
  h.tiles_y = 48;
  h.tile_size = 32;
  h.pass_name = "skin_shade";
  h.config_id = "s0.5_lut32x128";
  for (int ty = 0; ty < h.tiles_y; ++ty) {
    for (int tx = 0; tx < h.tiles_x; ++tx) {
      // An upright head-shaped ellipse in the middle of the frame; cost grows toward its centre.
      const double dx = (tx - 31.5) / 16.0, dy = (ty - 22.0) / 20.0;
      const double r2 = dx * dx + dy * dy;
      const double ms = r2 < 1.0 ? 0.004 + 0.012 * (1.0 - r2) : 0.0005;
      h.ms.push_back(ms);
      h.bottleneck.push_back(r2 >= 1.0 ? "dram" : (r2 < 0.4 ? "texture" : "alu"));
    }
  }
  return h;
}

inline results::SweepTable synthetic_sweep() {
  results::SweepTable t;
  t.device = "PowerVR SGX554MP4 (iPad 4) [synthetic test data]";
  t.scene = "LeePerrySmith head [synthetic test data]";
  t.resolution = "2048x1536";
  t.budget_ms = 33.3;
  for (double scale : {0.25, 0.5, 0.75, 1.0}) {
    for (int lut : {1, 2, 4, 8}) t.rows.push_back(synthetic_config(scale, 16 * lut, 64 * lut));
  }
  t.heatmap = synthetic_heatmap();
  t.assumptions = {"GPU clock 300 MHz (not published; 280 MHz also quoted)",
                   "Texture cache 8 KB per core, 64-byte lines (not published)"};
  t.sensitivity = {{"gpu_clock_mhz", "MHz", 280, 300, 320, 31.9, 30.1, 28.5},
                   {"texture_cache_kb", "KB", 4, 8, 16, 32.4, 30.1, 29.3}};
  return t;
}

}  // namespace skinsim::reports::testing
