#include "gpu_model/timing_table.h"

#include <fmt/format.h>

#include <algorithm>

#include "gpu_model/energy.h"
#include "gpu_model/profile_loader.h"
#include "results/pass_rows.h"

namespace skinsim::gpu_model {
namespace {

constexpr double kMegabyte = 1e6;

double util(const PassTiming& p, Unit u) {
  return 100.0 * p.utilisation[static_cast<int>(u)];
}

std::string ms_or_dash(const std::optional<double>& ms) {
  return ms ? fmt::format("{:.3f}", *ms) : std::string("re-run");
}

}  // namespace

std::string format_frame_table(const FrameTiming& frame) {
  std::string out = fmt::format(
      "{:<24} {:>8} {:>10} {:>8} {:>8} {:>8} {:>5} {:>5} {:>5} {:>5} {:>5} {:>9} {:>8}\n", "pass",
      "ms", "bottleneck", "TA ms", "3D ms", "alone ms", "ALU%", "TEX%", "ISP%", "BW%", "bal%",
      "DRAM MB", "mJ");
  for (std::size_t i = 0; i < frame.passes.size(); ++i) {
    const PassTiming& p = frame.passes[i];
    out += fmt::format(
        "{:<24} {:>8.3f} {:>10} {:>8.3f} {:>8.3f} {:>8.3f} {:>5.0f} {:>5.0f} {:>5.0f} {:>5.0f} "
        "{:>5.0f} {:>9.2f} {:>8.3f}\n",
        p.name, frame.schedule[i].exposed_ms, unit_name(p.bottleneck), p.ta_ms, p.render_ms,
        p.standalone_ms, util(p, Unit::kAlu), util(p, Unit::kTexture), util(p, Unit::kIsp),
        util(p, Unit::kBandwidth), 100.0 * p.balance, p.dram.total() / kMegabyte,
        frame.energy.passes[i].mj.total());
  }
  if (frame.dram_wait_ms > 0.0) {
    out += fmt::format("{:<24} {:>8.3f} {:>10}\n", results::kDramWaitRow, frame.dram_wait_ms,
                       "bandwidth");
  }
  const FrameEnergy& e = frame.energy;
  out += fmt::format("{:<24} {:>8.3f} {:>10} {:>66.2f} {:>8.3f}\n", "frame", frame.frame_ms,
                     frame.dram_wait_ms > 0.0 ? "bandwidth" : "pipeline",
                     frame.dram_bytes / kMegabyte, e.mj.total());
  out += fmt::format("{} at {:.1f} fps on {}\n", fmt::format("{:.3f} ms", frame.frame_ms),
                     frame.fps, frame.device);
  out += fmt::format(
      "{:.3f} mJ per frame (range {:.3f}-{:.3f}; DRAM {:.3f}, ALU {:.3f}, texture {:.3f}, "
      "depth {:.3f}), {:.0f} mW at one frame per {:.1f} ms\n",
      e.mj.total(), e.low_mj, e.high_mj, e.mj.dram, e.mj.alu, e.mj.texture, e.mj.depth,
      average_power_mw(e.mj.total(), frame.frame_ms, kPowerBudgetMs),
      std::max(frame.frame_ms, kPowerBudgetMs));
  return out;
}

std::string frame_table_legend() {
  return std::string(
             "columns: ms = the pass's share of the frame (render end - previous render end); "
             "the rows add up to the frame\n"
             "  TA ms, 3D ms = tiler and renderer stage times; alone ms = the pass with nothing "
             "overlapping it\n"
             "  ALU% TEX% ISP% BW% = unit busy time / alone ms; bottleneck = the busiest unit; "
             "bal% = mean / busiest 3D core; mJ = dynamic energy (docs/cost-model.md)\n  ") +
         results::kDramWaitRow +
         " (when > 0) = the frame's DRAM traffic outlasting the pipeline; docs/cost-model.md\n";
}

std::string format_sensitivity_table(const std::vector<SensitivityRow>& rows) {
  // The figures that move the frame most first; ties (and rows without both ends) keep the
  // profile's order.
  std::vector<const SensitivityRow*> sorted;
  for (const SensitivityRow& r : rows) sorted.push_back(&r);
  std::stable_sort(sorted.begin(), sorted.end(), [](const auto* a, const auto* b) {
    return a->swing_ms().value_or(-1.0) > b->swing_ms().value_or(-1.0);
  });
  std::string out = fmt::format("{:<58} {:>8} {:>22} {:>9} {:>9} {:>9} {:>9}\n", "figure", "conf.",
                                "min / base / max", "ms @min", "ms @base", "ms @max", "swing ms");
  for (const SensitivityRow* r : sorted) {
    out += fmt::format("{:<58} {:>8} {:>22} {:>9} {:>9.3f} {:>9} {:>9}\n",
                       r->unit.empty() ? r->figure : fmt::format("{} ({})", r->figure, r->unit),
                       confidence_name(r->confidence),
                       fmt::format("{:g} / {:g} / {:g}", r->value_min, r->value_base, r->value_max),
                       ms_or_dash(r->frame_ms_min), r->frame_ms_base, ms_or_dash(r->frame_ms_max),
                       ms_or_dash(r->swing_ms()));
  }
  return out +
         "swing ms = |ms @max - ms @min|: how far the figure's range alone moves the frame; "
         "largest first\n";
}

DeviceKeyFigures key_figures(const DeviceProfile& p) {
  DeviceKeyFigures k;
  k.display_width = p.display_width.value;
  k.display_height = p.display_height.value;
  k.cores = p.cores.value;
  k.pipes_per_core = p.pipes_per_core.value;
  k.clock_mhz = p.clock_mhz.value;
  // Peak FP32: cores x pipes x 8 FLOP (vec4 multiply-add) per clock (hardware.md).
  k.peak_gflops = k.cores * k.pipes_per_core * 8.0 * k.clock_mhz / 1e3;
  k.tmus = k.cores * p.tmus_per_core.value;
  k.dram_peak_gb_per_s = p.dram_peak_gb_per_s.value;
  k.dram_achievable_gb_per_s = p.dram_peak_gb_per_s.value * p.dram_achievable_fraction.value;
  k.tile_width = p.tile_width.value;
  k.tile_height = p.tile_height.value;
  k.texture_cache_kib = p.texture_cache_bytes.value / 1024.0;
  k.fp16_rate = 1.0 / p.mediump_op_cost.value;
  k.tile_at_32_bpp = fitted_tile(p, 32.0);
  return k;
}

std::string format_device_table(const std::vector<DeviceProfile>& profiles) {
  std::string out = fmt::format(
      "{:<10} {:<22} {:<20} {:<13} {:>10} {:>7} {:>6} {:>7} {:>5} {:>4} {:>12} {:>7} {:>9} "
      "{:>9} {:>4} {:>4}\n",
      "name", "device", "GPU", "class", "display", "cores", "MHz", "GFLOPS", "FP16x", "TMUs",
      "DRAM GB/s", "tile", "tile@32B", "tex$ KiB", "FBC", "HSR");
  for (const DeviceProfile& p : profiles) {
    const DeviceKeyFigures k = key_figures(p);
    out += fmt::format(
        "{:<10} {:<22} {:<20} {:<13} {:>10} {:>7} {:>6g} {:>7.1f} {:>5g} {:>4g} {:>12} {:>7} "
        "{:>9} {:>9g} {:>4g} {:>4g}\n",
        p.name, p.device, p.gpu, gpu_class_name(p.gpu_class),
        fmt::format("{:g}x{:g}", k.display_width, k.display_height),
        fmt::format("{:g}x{:g}", k.cores, k.pipes_per_core), k.clock_mhz, k.peak_gflops,
        k.fp16_rate, k.tmus,
        fmt::format("{:.1f} ({:.1f})", k.dram_peak_gb_per_s, k.dram_achievable_gb_per_s),
        fmt::format("{:g}x{:g}", k.tile_width, k.tile_height),
        fmt::format("{}x{}", k.tile_at_32_bpp.width, k.tile_at_32_bpp.height), k.texture_cache_kib,
        p.framebuffer_compression.value, p.hsr_overdraw_removed.value);
  }
  return out;
}

std::string device_table_legend() {
  return "name = the profile (--device NAME; data/devices/NAME.toml); display = pixels;\n"
         "cores = GPU cores x shader pipes per core; MHz = GPU clock; GFLOPS = peak FP32,\n"
         "cores x pipes x 8 FLOP (vec4 multiply-add) x clock; TMUs = texture units, all cores;\n"
         "DRAM GB/s = peak (achievable: peak x the profile's achievable fraction); tile = tile\n"
         "size in pixels; tile@32B = the tile when a pixel needs 32 B of colour (tile memory);\n"
         "tex$ KiB = texture cache per core; "
         "class = tbdr | tiler-early-z | binning;\nFP16x = mediump ops per highp op time;\n"
         "FBC = render-target DRAM bytes kept by framebuffer compression; HSR = share of\n"
         "order-dependent overdraw not shaded. Sources and ranges: the .toml files\n";
}

}  // namespace skinsim::gpu_model
