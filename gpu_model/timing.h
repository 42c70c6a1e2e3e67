// Results of the cost model: per tile, per pass, per frame.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace skinsim::gpu_model {

// Units a pass can be bound by.
enum class Unit { kAlu = 0, kTexture, kIsp, kBandwidth, kTiler, kOverhead };
constexpr int kUnitCount = 6;
const char* unit_name(Unit u);

// DRAM traffic of a pass by cause. parameter_write is the tiler's; the rest the renderer's.
struct DramBytes {
  double parameter_write = 0.0;
  double parameter_read = 0.0;
  double texture = 0.0;
  double color_load = 0.0;
  double color_store = 0.0;
  double depth_load = 0.0;
  double depth_store = 0.0;

  double total() const {
    return parameter_write + parameter_read + texture + color_load + color_store + depth_load +
           depth_store;
  }
  double renderer() const { return total() - parameter_write; }
  void add(const DramBytes& o);
};

// One tile on the 3D core, for heat maps.
struct TileTiming {
  int tile_x = 0;
  int tile_y = 0;
  int core = 0;           // core the list schedule gave it
  double start_ms = 0.0;  // from the start of the pass's render
  double ms = 0.0;
  Unit bottleneck = Unit::kOverhead;  // kIsp, kAlu, kTexture or kOverhead
  double isp_cycles = 0.0;
  double alu_cycles = 0.0;
  double texture_cycles = 0.0;
  double overhead_cycles = 0.0;
};

// The tiler (TA) stage of a pass.
struct TilerTiming {
  double vertex_cycles = 0.0;   // vertex shading on all USSE pipes, wall cycles
  double setup_cycles = 0.0;    // triangle setup and culling, wall cycles
  double binning_cycles = 0.0;  // tile-list writes, wall cycles
  double bandwidth_ms = 0.0;    // parameter-buffer write at achievable bandwidth
  double ms = 0.0;              // stage time
};

struct PassTiming {
  std::string name;
  TilerTiming ta;
  double ta_ms = 0.0;                // tiler stage
  double makespan_ms = 0.0;          // tiles over cores, list schedule
  double render_bandwidth_ms = 0.0;  // renderer DRAM bytes at achievable bandwidth
  double render_ms = 0.0;            // 3D stage: max(makespan, bandwidth) + per-render overhead
  // The pass alone, nothing overlapping it: max(ta, render, all bytes / bandwidth). Not the
  // pass's share of a frame (PassSlot::exposed_ms); the denominator of `utilisation`.
  double standalone_ms = 0.0;
  // Mean-to-max core balance: mean core busy time / makespan (1 = perfectly balanced).
  double balance = 1.0;
  Unit bottleneck = Unit::kOverhead;
  std::array<double, kUnitCount> busy_ms{};      // per unit; per-core units averaged over cores
  std::array<double, kUnitCount> utilisation{};  // busy_ms / standalone_ms
  DramBytes dram;
  std::vector<double> core_busy_ms;
  std::vector<TileTiming> tiles;  // row-major, as in the counters
};

// Where a pass sits in the frame's two-stage (TA, 3D) pipeline.
struct PassSlot {
  double ta_start_ms = 0.0;
  double ta_end_ms = 0.0;
  double render_start_ms = 0.0;
  double render_end_ms = 0.0;
  // render_end - previous render_end: the pass's share of the frame, what every output calls
  // the pass's "ms". The passes' exposed_ms plus FrameTiming::dram_wait_ms (listed as
  // results::kDramWaitRow) add up to frame_ms.
  double exposed_ms = 0.0;
};

// Dynamic energy (energy.h), millijoules by cause.
struct EnergyParts {
  double dram = 0.0;
  double alu = 0.0;
  double texture = 0.0;
  double depth = 0.0;

  double total() const { return dram + alu + texture + depth; }
  void add(const EnergyParts& o);
};

struct PassEnergy {
  std::string name;
  EnergyParts mj;       // at the figures' values
  double low_mj = 0.0;  // at every energy figure's range minimum
  double high_mj = 0.0;
};

struct FrameEnergy {
  std::vector<PassEnergy> passes;
  EnergyParts mj;  // sum over passes
  double low_mj = 0.0;
  double high_mj = 0.0;
};

struct FrameTiming {
  std::string device;
  std::vector<PassTiming> passes;
  std::vector<PassSlot> schedule;  // one per pass
  double pipeline_ms = 0.0;        // end of the last render
  double bandwidth_ms = 0.0;       // all frame bytes at achievable bandwidth
  double frame_ms = 0.0;           // max(pipeline_ms, bandwidth_ms)
  // frame_ms - pipeline_ms: the time the frame's DRAM traffic outlasts the pipeline (0 unless
  // the frame is bandwidth-bound). Reported beside the passes so that they add up to frame_ms.
  double dram_wait_ms = 0.0;
  double fps = 0.0;
  DramBytes dram;
  double dram_bytes = 0.0;
  FrameEnergy energy;
};

}  // namespace skinsim::gpu_model
