// Micro-benchmarks of the emulated GPU in the style of the low-level tests hardware reviewers
// run (GLBenchmark / GFXBench fill, triangle, bandwidth and ALU tests). Each benchmark is a
// real render pass on the emulator, timed by the cost model with a device profile, and
// reports the simulated throughput beside the device's spec peak. They check the emulator
// and the model together: no simulated rate may exceed what the hardware figures allow,
// and each pass must be limited by the unit it was built to stress.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/timing.h"
#include "sim/counters.h"

namespace skinsim::microbench {

struct MicrobenchOptions {
  int width = 1024;  // render-target size of every benchmark pass
  int height = 768;
  int fill_layers = 4;            // full-screen layers of the fill-rate passes
  int alu_vector_ops = 64;        // vec4 multiply-adds per fragment of the ALU-bound shader
  int triangle_cell_pixels = 2;   // grid cell of the triangle passes (2 triangles per cell)
  int threads = 0;                // host worker threads; 0 = all, 1 = synchronous
  std::vector<std::string> only;  // benchmark names to run (microbenchmark_names()); empty = all
};

struct MicrobenchResult {
  std::string name;        // e.g. "fill_blended"
  std::string unit;        // of value and peak, e.g. "Mtexel/s"
  double value = 0.0;      // simulated throughput: work in the pass / modelled pass time
  double peak = 0.0;       // the device's spec peak for that work
  std::string peak_basis;  // how the peak follows from the profile
  double ratio = 0.0;      // value / peak
  gpu_model::Unit bottleneck = gpu_model::Unit::kOverhead;  // unit the model named
  double pass_ms = 0.0;  // the test pass alone, its stages in steady state (standalone_ms)
  std::string shows;     // what the result shows, with the pass's own numbers
  sim::PassCounters counters;
  gpu_model::PassTiming timing;
};

// Names of all benchmarks, in run order.
const std::vector<std::string>& microbenchmark_names();

// Runs the benchmarks on the emulated GPU configured from `profile` and times each pass
// with the cost model. Deterministic for any thread count. Throws MicrobenchError naming the
// option at fault (non-positive sizes, unknown benchmark name, ...), and gpu_model errors if
// the profile cannot drive the emulator.
std::vector<MicrobenchResult> run_microbenchmarks(const gpu_model::DeviceProfile& profile,
                                                  const MicrobenchOptions& options);

// Fixed-width table: benchmark, value, unit, peak, % of peak, bottleneck, pass ms; then the
// "what it shows" lines.
std::string format_microbench_table(const std::vector<MicrobenchResult>& results);

// Array of {name, value, unit, peak, peak_basis, ratio, bottleneck, pass_ms, shows, counters:
// {...key counters...}, dram_bytes}.
nlohmann::json to_json(const std::vector<MicrobenchResult>& results);

}  // namespace skinsim::microbench
