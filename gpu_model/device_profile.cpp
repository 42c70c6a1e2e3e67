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

const std::vector<FigureSpec>& figure_specs() {
  using P = DeviceProfile;
  using K = FigureKind;
  static const std::vector<FigureSpec> specs = {
      {"display.width", &P::display_width, K::kCount, "px", true},
      {"display.height", &P::display_height, K::kCount, "px", true},
      {"gpu.clock_mhz", &P::clock_mhz, K::kRate, "MHz", false},
      {"gpu.cores", &P::cores, K::kCount, "cores", true},
      {"gpu.pipes_per_core", &P::pipes_per_core, K::kCount, "pipes", false},
      {"alu.vector_op_cycles", &P::vector_op_cycles, K::kRate, "cycles", false},
      {"alu.scalar_op_cycles", &P::scalar_op_cycles, K::kRate, "cycles", false},
      {"alu.transcendental_op_cycles", &P::transcendental_op_cycles, K::kRate, "cycles", false},
      {"alu.texture_issue_cycles", &P::texture_issue_cycles, K::kCycles, "cycles", false},
      {"alu.blend_cycles", &P::blend_cycles, K::kCycles, "cycles", false},
      {"texture.units_per_core", &P::tmus_per_core, K::kCount, "TMUs", false},
      {"texture.bilinear_per_unit_per_clock", &P::bilinear_per_tmu_clock, K::kRate, "quads/clk",
       false},
      {"texture.trilinear_bilinear_ops", &P::trilinear_bilinear_ops, K::kRate, "ops", false},
      {"texture.wide_format_bilinear_ops", &P::wide_format_bilinear_ops, K::kRate, "ops", false},
      {"texture.dependent_read_stall_cycles", &P::dependent_read_stall_cycles, K::kCycles, "cycles",
       false},
      {"texture.cache_bytes", &P::texture_cache_bytes, K::kBytes, "B", true},
      {"texture.cache_line_bytes", &P::texture_cache_line_bytes, K::kBytes, "B", true},
      {"texture.cache_ways", &P::texture_cache_ways, K::kCount, "ways", true},
      {"texture.cache_set_hash", &P::texture_cache_set_hash, K::kSwitch, "", true},
      {"tile.width", &P::tile_width, K::kCount, "px", true},
      {"tile.height", &P::tile_height, K::kCount, "px", true},
      {"tile.color_bytes_per_pixel", &P::tile_color_bytes_per_pixel, K::kBytes, "B", false},
      {"tile.depth_stencil_bytes_per_pixel", &P::tile_depth_stencil_bytes_per_pixel, K::kBytes, "B",
       false},
      {"memory.peak_gb_per_s", &P::dram_peak_gb_per_s, K::kRate, "GB/s", false},
      {"memory.achievable_fraction", &P::dram_achievable_fraction, K::kFraction, "", false},
      {"tiler.triangles_per_clock_per_core", &P::tiler_triangles_per_clock_per_core, K::kRate,
       "tri/clk", false},
      {"tiler.tile_refs_per_clock_per_core", &P::tiler_tile_refs_per_clock_per_core, K::kRate,
       "refs/clk", false},
      {"parameter_buffer.vertex_position_bytes", &P::pb_vertex_position_bytes, K::kBytes, "B",
       false},
      {"parameter_buffer.bytes_per_varying_float", &P::pb_bytes_per_varying_float, K::kRate, "B",
       false},
      {"parameter_buffer.bytes_per_triangle", &P::pb_bytes_per_triangle, K::kRate, "B", false},
      {"parameter_buffer.bytes_per_tile_ref", &P::pb_bytes_per_tile_ref, K::kRate, "B", false},
      {"parameter_buffer.vertices_read_per_tile_ref", &P::pb_vertices_read_per_tile_ref, K::kRate,
       "vertices", false},
      {"isp.fragments_per_clock_per_core", &P::isp_fragments_per_clock_per_core, K::kRate,
       "frag/clk", false},
      {"isp.hsr_flush_cycles", &P::isp_hsr_flush_cycles, K::kCycles, "cycles", false},
      {"overhead.render_cycles", &P::render_overhead_cycles, K::kCycles, "cycles", false},
      {"overhead.tile_cycles", &P::tile_overhead_cycles, K::kCycles, "cycles", false},
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
  s.tile_color_bytes_per_pixel = static_cast<int>(profile.tile_color_bytes_per_pixel.value);
  s.tile_depth_stencil_bytes_per_pixel =
      static_cast<int>(profile.tile_depth_stencil_bytes_per_pixel.value);
  return s;
}

}  // namespace skinsim::gpu_model
