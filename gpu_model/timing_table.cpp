#include "gpu_model/timing_table.h"

#include <fmt/format.h>

#include "gpu_model/profile_loader.h"

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
      "{:<24} {:>8} {:>10} {:>8} {:>8} {:>8} {:>5} {:>5} {:>5} {:>5} {:>5} {:>9}\n", "pass", "ms",
      "bottleneck", "TA ms", "3D ms", "alone ms", "ALU%", "TEX%", "ISP%", "BW%", "bal%", "DRAM MB");
  for (std::size_t i = 0; i < frame.passes.size(); ++i) {
    const PassTiming& p = frame.passes[i];
    out += fmt::format(
        "{:<24} {:>8.3f} {:>10} {:>8.3f} {:>8.3f} {:>8.3f} {:>5.0f} {:>5.0f} {:>5.0f} {:>5.0f} "
        "{:>5.0f} {:>9.2f}\n",
        p.name, frame.schedule[i].exposed_ms, unit_name(p.bottleneck), p.ta_ms, p.render_ms,
        p.standalone_ms, util(p, Unit::kAlu), util(p, Unit::kTexture), util(p, Unit::kIsp),
        util(p, Unit::kBandwidth), 100.0 * p.balance, p.dram.total() / kMegabyte);
  }
  if (frame.dram_wait_ms > 0.0) {
    out += fmt::format("{:<24} {:>8.3f} {:>10}\n", kDramWaitRow, frame.dram_wait_ms, "bandwidth");
  }
  out += fmt::format("{:<24} {:>8.3f} {:>10} {:>66.2f}\n", "frame", frame.frame_ms,
                     frame.dram_wait_ms > 0.0 ? "bandwidth" : "pipeline",
                     frame.dram_bytes / kMegabyte);
  out += fmt::format("{} at {:.1f} fps on {}\n", fmt::format("{:.3f} ms", frame.frame_ms),
                     frame.fps, frame.device);
  return out;
}

std::string frame_table_legend() {
  return std::string(
             "columns: ms = the pass's share of the frame (render end - previous render end); "
             "the rows add up to the frame\n"
             "  TA ms, 3D ms = tiler and renderer stage times; alone ms = the pass with nothing "
             "overlapping it\n"
             "  ALU% TEX% ISP% BW% = unit busy time / alone ms; bottleneck = the busiest unit; "
             "bal% = mean / busiest 3D core\n  ") +
         kDramWaitRow +
         " (when > 0) = the frame's DRAM traffic outlasting the pipeline; docs/cost-model.md\n";
}

std::string format_sensitivity_table(const std::vector<SensitivityRow>& rows) {
  std::string out = fmt::format("{:<58} {:>8} {:>22} {:>9} {:>9} {:>9}\n", "figure", "conf.",
                                "min / base / max", "ms @min", "ms @base", "ms @max");
  for (const SensitivityRow& r : rows) {
    out += fmt::format("{:<58} {:>8} {:>22} {:>9} {:>9.3f} {:>9}\n",
                       r.unit.empty() ? r.figure : fmt::format("{} ({})", r.figure, r.unit),
                       confidence_name(r.confidence),
                       fmt::format("{:g} / {:g} / {:g}", r.value_min, r.value_base, r.value_max),
                       ms_or_dash(r.frame_ms_min), r.frame_ms_base, ms_or_dash(r.frame_ms_max));
  }
  return out;
}

std::string format_device_table(const std::vector<DeviceProfile>& profiles) {
  std::string out = fmt::format(
      "{:<9} {:<22} {:<18} {:>10} {:>7} {:>6} {:>7} {:>4} {:>12} {:>6} {:>9}\n", "name", "device",
      "GPU", "display", "cores", "MHz", "GFLOPS", "TMUs", "DRAM GB/s", "tile", "tex$ KiB");
  for (const DeviceProfile& p : profiles) {
    // Peak FP32: cores x pipes x 8 FLOP (vec4 multiply-add) per clock (hardware.md).
    const double gflops = p.cores.value * p.pipes_per_core.value * 8.0 * p.clock_mhz.value / 1e3;
    out += fmt::format(
        "{:<9} {:<22} {:<18} {:>10} {:>7} {:>6g} {:>7.1f} {:>4g} {:>12} {:>6} {:>9g}\n", p.name,
        p.device, p.gpu, fmt::format("{:g}x{:g}", p.display_width.value, p.display_height.value),
        fmt::format("{:g}x{:g}", p.cores.value, p.pipes_per_core.value), p.clock_mhz.value, gflops,
        p.cores.value * p.tmus_per_core.value,
        fmt::format("{:.1f} ({:.1f})", p.dram_peak_gb_per_s.value,
                    p.dram_peak_gb_per_s.value * p.dram_achievable_fraction.value),
        fmt::format("{:g}x{:g}", p.tile_width.value, p.tile_height.value),
        p.texture_cache_bytes.value / 1024.0);
  }
  return out;
}

}  // namespace skinsim::gpu_model
