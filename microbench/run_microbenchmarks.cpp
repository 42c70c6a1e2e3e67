#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "microbench/benchmarks.h"
#include "microbench/error.h"
#include "microbench/microbench.h"

namespace skinsim::microbench {
namespace {

struct Benchmark {
  const char* name;
  MicrobenchResult (*run)(BenchContext&);
};

// Run order: fill, triangles, bandwidth, ALU (the order of a GLBenchmark low-level suite).
const std::vector<Benchmark>& benchmarks() {
  static const std::vector<Benchmark> all = {
      {"fill_blended", run_fill_blended},
      {"fill_opaque", run_fill_opaque},
      {"triangles_visible", run_triangles_visible},
      {"triangles_offscreen", run_triangles_offscreen},
      {"triangles_backface", run_triangles_backface},
      {"bandwidth_copy", run_bandwidth_copy},
      {"bandwidth_resolve", run_bandwidth_resolve},
      {"alu_mad_chain", run_alu_mad_chain},
  };
  return all;
}

void check_range(const char* option, int value, int lo, int hi) {
  if (value < lo || value > hi) {
    throw MicrobenchError(
        fmt::format("microbench option '{}': must be in [{}, {}], got {}", option, lo, hi, value));
  }
}

void validate(const MicrobenchOptions& o) {
  constexpr int kMaxSize = 8192;
  check_range("width", o.width, 1, kMaxSize);
  check_range("height", o.height, 1, kMaxSize);
  check_range("fill_layers", o.fill_layers, 1, 64);
  check_range("alu_vector_ops", o.alu_vector_ops, 1, 4096);
  check_range("triangle_cell_pixels", o.triangle_cell_pixels, 1, std::min(o.width, o.height));
  check_range("threads", o.threads, 0, 1024);
  const std::vector<std::string>& known = microbenchmark_names();
  for (const std::string& name : o.only) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw MicrobenchError(
          fmt::format("microbench option 'only': unknown benchmark '{}' "
                      "(known: {})",
                      name, fmt::join(known, ", ")));
    }
  }
}

bool selected(const MicrobenchOptions& o, const std::string& name) {
  return o.only.empty() || std::find(o.only.begin(), o.only.end(), name) != o.only.end();
}

}  // namespace

const std::vector<std::string>& microbenchmark_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Benchmark& b : benchmarks()) n.emplace_back(b.name);
    return n;
  }();
  return names;
}

std::vector<MicrobenchResult> run_microbenchmarks(const gpu_model::DeviceProfile& profile,
                                                  const MicrobenchOptions& options) {
  validate(options);
  BenchContext ctx(profile, options);
  std::vector<MicrobenchResult> results;
  for (const Benchmark& b : benchmarks()) {
    if (selected(options, b.name)) results.push_back(b.run(ctx));
  }
  return results;
}

}  // namespace skinsim::microbench
