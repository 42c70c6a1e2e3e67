// A device profile: every hardware figure the cost model and the emulator use, each with
// where it comes from, how sure it is, and (for uncertain figures) a plausible range that
// sensitivity analysis sweeps. Profiles are data files: data/devices/<name>.toml.
#pragma once

#include <string>
#include <vector>

namespace skinsim::gpu_model {

enum class Confidence { kLow, kMedium, kHigh, kCertain };

const char* confidence_name(Confidence c);

// How a GPU class removes hidden surfaces and what its tile memory holds (docs/hardware.md).
enum class GpuClass {
  kTbdr,         // PowerVR, Apple: deferred HSR, overdraw removed whatever the draw order
  kTilerEarlyZ,  // Arm Mali: early ZS in submission order, Forward Pixel Kill removes part
  kBinning,      // Qualcomm Adreno: GMEM bins, low-resolution Z from the binning pass
};

const char* gpu_class_name(GpuClass c);

struct Figure {
  double value = 0.0;
  // Plausible range; min == max == value when the profile gives none.
  double min = 0.0;
  double max = 0.0;
  bool has_range = false;
  Confidence confidence = Confidence::kLow;
  std::string source;
};

struct DeviceProfile {
  std::string name;         // file stem, e.g. "ipad4"
  std::string source_path;  // file it was loaded from
  std::string device;       // e.g. "iPad (4th generation)"
  std::string soc;          // e.g. "Apple A6X"
  std::string gpu;          // e.g. "PowerVR SGX554MP4"
  GpuClass gpu_class = GpuClass::kTbdr;

  // [display]
  Figure display_width;  // pixels
  Figure display_height;

  // [gpu]
  Figure clock_mhz;
  Figure cores;
  Figure pipes_per_core;  // USSE pipes per core

  // [alu]: cycles per instruction per pipe.
  Figure vector_op_cycles;
  Figure scalar_op_cycles;
  Figure transcendental_op_cycles;
  // Issue cost of a mediump (FP16) vector or scalar op as a multiple of the highp one.
  Figure mediump_op_cost;
  Figure texture_issue_cycles;  // issue slot of a texture instruction in the program
  Figure blend_cycles;          // per blended fragment (SGX blends in the USSE)

  // [texture]
  Figure tmus_per_core;
  Figure bilinear_per_tmu_clock;       // bilinear texel-quads per TMU per clock
  Figure trilinear_bilinear_ops;       // bilinear operations per trilinear sample
  Figure wide_format_bilinear_ops;     // cost multiplier of an FP16/FP32 sample
  Figure dependent_read_stall_cycles;  // exposed TMU cycles per dependent read
  Figure texture_cache_bytes;          // per core
  Figure texture_cache_line_bytes;
  Figure texture_cache_ways;
  Figure texture_cache_set_hash;  // 0: line % sets, 1: XOR-folded index (sim::SetIndex)

  // [tile]
  Figure tile_width;
  Figure tile_height;
  Figure tile_depth_stencil_bytes_per_pixel;
  // On-chip bytes a tile's colour (and, on binning GPUs, depth) may occupy; larger pixels
  // shrink the tile (fitted_tile, tile_memory.h).
  Figure tile_memory_bytes;

  // [hsr]: share of the order-dependent overdraw (fragments that pass an early depth test in
  // submission order but end up hidden) that the GPU does not shade. 1 on a TBDR.
  Figure hsr_overdraw_removed;

  // [memory]
  Figure dram_peak_gb_per_s;  // 1 GB = 1e9 bytes
  Figure dram_achievable_fraction;
  // Render-target DRAM bytes after framebuffer compression (AFBC, UBWC, Apple lossless) as a
  // share of the uncompressed bytes; 1 without compression.
  Figure framebuffer_compression;

  // [tiler]
  Figure tiler_triangles_per_clock_per_core;  // setup + cull
  Figure tiler_tile_refs_per_clock_per_core;  // binning

  // [parameter_buffer]
  Figure pb_vertex_position_bytes;
  Figure pb_bytes_per_varying_float;
  Figure pb_bytes_per_triangle;
  Figure pb_bytes_per_tile_ref;
  Figure pb_vertices_read_per_tile_ref;

  // [isp]
  Figure isp_fragments_per_clock_per_core;
  Figure isp_hsr_flush_cycles;

  // [overhead]
  Figure render_overhead_cycles;
  Figure tile_overhead_cycles;

  // [energy]: dynamic energy per counted event (gpu_model/energy.h).
  Figure dram_pj_per_byte;
  Figure fp32_lane_op_pj;  // one FP32 lane operation, operand delivery included
  Figure fp16_lane_op_pj;
  Figure texture_sample_pj;  // one bilinear texture operation
  Figure depth_test_pj;      // one fragment's depth/stencil test in tile memory
};

// What values a figure accepts: what the emulator (sim::GpuConfig, sim::TextureCache) and the
// pipeline can run, and otherwise physically plausible bounds that keep every modelled time
// finite. Inclusive; the value and both range endpoints must satisfy them.
struct FigureBounds {
  double min = 0.0;
  double max = 0.0;
  bool integer = false;
  bool power_of_two = false;  // implies integer
};

struct FigureSpec {
  const char* path;  // dotted TOML path, e.g. "gpu.clock_mhz"
  Figure DeviceProfile::*member;
  FigureBounds bounds;
  const char* unit;
  // True when the emulator's counters depend on the figure, so varying it needs a re-run.
  bool affects_counters;
  // False for figures the frame time does not use (energy, tile memory): the time's
  // sensitivity and range leave them out.
  bool timed = true;
};

// Every figure of a profile, in file order.
const std::vector<FigureSpec>& figure_specs();

// What the emulator needs from a profile.
struct SimParameters {
  int tile_width = 0;
  int tile_height = 0;
  int cores = 0;
  int texture_cache_bytes = 0;  // per core
  int texture_cache_line_bytes = 0;
  int texture_cache_ways = 0;
  bool texture_cache_set_hash = false;  // XOR-fold the set index
  int tile_depth_stencil_bytes_per_pixel = 0;
};

SimParameters sim_parameters(const DeviceProfile& profile);

}  // namespace skinsim::gpu_model
