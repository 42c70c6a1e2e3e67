#include "gpu_model/device_profile.h"

namespace skinsim::gpu_model {

const char* confidence_name(Confidence c) {
  switch (c) {
    case Confidence::kLow:
      return "low";
    case Confidence::kMedium:
      return "medium";
    case Confidence::kHigh:
      return "high";
    case Confidence::kCertain:
      return "certain";
  }
  return "low";
}

const char* gpu_class_name(GpuClass c) {
  switch (c) {
    case GpuClass::kTbdr:
      return "tbdr";
    case GpuClass::kTilerEarlyZ:
      return "tiler-early-z";
    case GpuClass::kBinning:
      return "binning";
  }
  return "tbdr";
}

const std::vector<FigureSpec>& figure_specs() {
  using P = DeviceProfile;
  // Integer figures the emulator takes as int stay far below 2^31.
  const auto integer = [](double min, double max) { return FigureBounds{min, max, true, false}; };
  const auto power_of_two = [](double min, double max) {
    return FigureBounds{min, max, true, true};
  };
  const auto real = [](double min, double max) { return FigureBounds{min, max, false, false}; };
  // Issue cycles of one instruction: from 64 co-issued per clock to a 1000-cycle microcoded op.
  const FigureBounds op_cycles = real(1.0 / 64, 1000.0);
  // Per-clock throughputs of one unit: from one item per 1000 clocks to 1024 per clock.
  const FigureBounds per_clock = real(1e-3, 1024.0);
  // Exposed stall or fixed cycles: zero up to a millisecond at the fastest allowed clock.
  const FigureBounds stall_cycles = real(0.0, 1e7);
  // Parameter-buffer bytes per item: packed to an eighth of a byte up to 1 KiB.
  const FigureBounds pb_bytes = real(0.125, 1024.0);
  static const std::vector<FigureSpec> specs = {
      // The pipeline renders 16..8192 pixels per axis (pipeline::PipelineConfig).
      {"display.width", &P::display_width, integer(16, 8192), "px", true},
      {"display.height", &P::display_height, integer(16, 8192), "px", true},
      // 1 MHz .. 10 GHz: below, a frame takes minutes; above, no GPU clocks.
      {"gpu.clock_mhz", &P::clock_mhz, real(1.0, 1e4), "MHz", false},
      // sim::Gpu runs 1..64 cores.
      {"gpu.cores", &P::cores, integer(1, 64), "cores", true},
      // Up to 1024 vec4 pipes: a binning GPU is modelled as one core holding all its lanes
      // (Adreno 740: 1536 lanes = 384 pipes).
      {"gpu.pipes_per_core", &P::pipes_per_core, integer(1, 1024), "pipes", false},
      {"alu.vector_op_cycles", &P::vector_op_cycles, op_cycles, "cycles", false},
      {"alu.scalar_op_cycles", &P::scalar_op_cycles, op_cycles, "cycles", false},
      {"alu.transcendental_op_cycles", &P::transcendental_op_cycles, op_cycles, "cycles", false},
      // From a 16-wide FP16 path to mediump costing more than highp (conversions).
      {"alu.mediump_op_cost", &P::mediump_op_cost, real(1.0 / 16, 4.0), "x", false},
      // Zero when texture instructions co-issue for free.
      {"alu.texture_issue_cycles", &P::texture_issue_cycles, real(0.0, 1000.0), "cycles", false},
      {"alu.blend_cycles", &P::blend_cycles, real(0.0, 1000.0), "cycles", false},
      {"texture.units_per_core", &P::tmus_per_core, integer(1, 64), "TMUs", false},
      {"texture.bilinear_per_unit_per_clock", &P::bilinear_per_tmu_clock, per_clock, "quads/clk",
       false},
      // A trilinear or wide-format sample costs from a fraction of a bilinear one (dedicated
      // hardware) up to 16 of them.
      {"texture.trilinear_bilinear_ops", &P::trilinear_bilinear_ops, real(0.125, 16.0), "ops",
       false},
      {"texture.wide_format_bilinear_ops", &P::wide_format_bilinear_ops, real(0.125, 16.0), "ops",
       false},
      {"texture.dependent_read_stall_cycles", &P::dependent_read_stall_cycles, real(0.0, 1e4),
       "cycles", false},
      // sim::TextureCache needs a power-of-two line and a size that is a multiple of line x
      // ways (checked by the loader across figures). Its tag store is allocated up front for
      // every core, so the size stays at plausible per-core caches (up to 1 MiB) and lines
      // at 16 B..1 KiB.
      {"texture.cache_bytes", &P::texture_cache_bytes, integer(64, 1 << 20), "B", true},
      {"texture.cache_line_bytes", &P::texture_cache_line_bytes, power_of_two(16, 1024), "B", true},
      {"texture.cache_ways", &P::texture_cache_ways, integer(1, 64), "ways", true},
      {"texture.cache_set_hash", &P::texture_cache_set_hash, integer(0, 1), "", true},
      // sim::Gpu renders square tiles of 4..256 pixels (the loader checks width == height).
      {"tile.width", &P::tile_width, integer(4, 256), "px", true},
      {"tile.height", &P::tile_height, integer(4, 256), "px", true},
      // Up to RGBA32F (16 B) per pixel.
      {"tile.depth_stencil_bytes_per_pixel", &P::tile_depth_stencil_bytes_per_pixel, integer(1, 16),
       "B", false},
      // From a 4x4 tile of 1 B pixels up to 64 MiB (binning GPUs' GMEM is a few MiB).
      {"tile.memory_bytes", &P::tile_memory_bytes, integer(16, 1 << 26), "B", false, false},
      // 10 MB/s .. 10 TB/s.
      {"memory.peak_gb_per_s", &P::dram_peak_gb_per_s, real(0.01, 1e4), "GB/s", false},
      // A share of the peak; below 1 % the bus would be idle, not busy.
      {"memory.achievable_fraction", &P::dram_achievable_fraction, real(0.01, 1.0), "", false},
      // Compressed / uncompressed render-target bytes: lossless schemes fall back to raw
      // blocks plus a header, so from a solid-colour 1/64 up to slightly above 1.
      {"memory.framebuffer_compression", &P::framebuffer_compression, real(1.0 / 64, 1.25), "x",
       false},
      {"tiler.triangles_per_clock_per_core", &P::tiler_triangles_per_clock_per_core, per_clock,
       "tri/clk", false},
      {"tiler.tile_refs_per_clock_per_core", &P::tiler_tile_refs_per_clock_per_core, per_clock,
       "refs/clk", false},
      {"parameter_buffer.vertex_position_bytes", &P::pb_vertex_position_bytes, integer(1, 64), "B",
       false},
      {"parameter_buffer.bytes_per_varying_float", &P::pb_bytes_per_varying_float, real(0.125, 8.0),
       "B", false},
      {"parameter_buffer.bytes_per_triangle", &P::pb_bytes_per_triangle, pb_bytes, "B", false},
      {"parameter_buffer.bytes_per_tile_ref", &P::pb_bytes_per_tile_ref, pb_bytes, "B", false},
      // A tile reference re-reads from a small fraction of a vertex (shared) up to all three
      // and more.
      {"parameter_buffer.vertices_read_per_tile_ref", &P::pb_vertices_read_per_tile_ref,
       real(0.01, 16.0), "vertices", false},
      {"isp.fragments_per_clock_per_core", &P::isp_fragments_per_clock_per_core, per_clock,
       "frag/clk", false},
      {"isp.hsr_flush_cycles", &P::isp_hsr_flush_cycles, stall_cycles, "cycles", false},
      {"overhead.render_cycles", &P::render_overhead_cycles, stall_cycles, "cycles", false},
      {"overhead.tile_cycles", &P::tile_overhead_cycles, stall_cycles, "cycles", false},
      {"hsr.overdraw_removed", &P::hsr_overdraw_removed, real(0.0, 1.0), "", false},
      // Energies: from 0.01 pJ (below any switched gate) to 10 nJ per event.
      {"energy.dram_pj_per_byte", &P::dram_pj_per_byte, real(0.01, 1e4), "pJ/B", false, false},
      {"energy.fp32_lane_op_pj", &P::fp32_lane_op_pj, real(0.01, 1e4), "pJ", false, false},
      {"energy.fp16_lane_op_pj", &P::fp16_lane_op_pj, real(0.01, 1e4), "pJ", false, false},
      {"energy.texture_sample_pj", &P::texture_sample_pj, real(0.01, 1e4), "pJ", false, false},
      {"energy.depth_test_pj", &P::depth_test_pj, real(0.01, 1e4), "pJ", false, false},
  };
  return specs;
}

SimParameters sim_parameters(const DeviceProfile& profile) {
  SimParameters s;
  s.tile_width = static_cast<int>(profile.tile_width.value);
  s.tile_height = static_cast<int>(profile.tile_height.value);
  s.cores = static_cast<int>(profile.cores.value);
  s.texture_cache_bytes = static_cast<int>(profile.texture_cache_bytes.value);
  s.texture_cache_line_bytes = static_cast<int>(profile.texture_cache_line_bytes.value);
  s.texture_cache_ways = static_cast<int>(profile.texture_cache_ways.value);
  s.texture_cache_set_hash = profile.texture_cache_set_hash.value != 0.0;
  s.tile_depth_stencil_bytes_per_pixel =
      static_cast<int>(profile.tile_depth_stencil_bytes_per_pixel.value);
  return s;
}

}  // namespace skinsim::gpu_model
