#include "microbench/bench_context.h"

#include "gpu_model/gpu_config.h"
#include "gpu_model/pass_cost.h"

namespace skinsim::microbench {

BenchContext::BenchContext(const gpu_model::DeviceProfile& profile,
                           const MicrobenchOptions& options)
    : profile_(profile), options_(options), gpu_(gpu_model::gpu_config(profile, options.threads)) {}

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
  r.pass_ms = measured.timing.standalone_ms;
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
