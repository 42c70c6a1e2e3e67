#include "microbench/bench_context.h"

#include <fmt/format.h>

#include "gpu_model/pass_cost.h"
#include "microbench/microbench_error.h"

namespace skinsim::microbench {

sim::GpuConfig gpu_config(const gpu_model::DeviceProfile& profile, int threads) {
  const gpu_model::SimParameters s = gpu_model::sim_parameters(profile);
  if (s.tile_width != s.tile_height) {
    throw MicrobenchError(fmt::format(
        "{}: fields 'tile.width' ({}) and 'tile.height' ({}) differ; the emulator renders "
        "square tiles",
        profile.source_path, s.tile_width, s.tile_height));
  }
  sim::GpuConfig c;
  c.tile_size = s.tile_width;
  c.cores = s.cores;
  c.texture_cache.size_bytes = static_cast<std::uint32_t>(s.texture_cache_bytes);
  c.texture_cache.line_bytes = static_cast<std::uint32_t>(s.texture_cache_line_bytes);
  c.texture_cache.associativity = static_cast<std::uint32_t>(s.texture_cache_ways);
  c.depth_stencil_bytes_per_pixel = s.tile_depth_stencil_bytes_per_pixel;
  c.threads = threads;
  return c;
}

BenchContext::BenchContext(const gpu_model::DeviceProfile& profile,
                           const MicrobenchOptions& options)
    : profile_(profile), options_(options), gpu_(gpu_config(profile, options.threads)) {}

MeasuredPass BenchContext::run(const sim::RenderPassDesc& pass) {
  MeasuredPass m;
  m.counters = gpu_.execute(pass);
  m.timing = gpu_model::estimate_pass(m.counters, profile_);
  return m;
}

MicrobenchResult make_result(std::string name, std::string unit, double work, const SpecPeak& peak,
                             MeasuredPass measured, std::string shows) {
  MicrobenchResult r;
  r.name = std::move(name);
  r.unit = std::move(unit);
  r.pass_ms = measured.timing.ms;
  r.value = work / (r.pass_ms * 1e-3);
  r.peak = peak.value;
  r.peak_basis = peak.basis;
  r.ratio = r.value / r.peak;
  r.bottleneck = measured.timing.bottleneck;
  r.shows = std::move(shows);
  r.counters = std::move(measured.counters);
  r.timing = std::move(measured.timing);
  return r;
}

}  // namespace skinsim::microbench
