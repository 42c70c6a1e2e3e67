// Wall time of emulating one frame of the default scene through the full skin pipeline on
// the iPad 4 profile at its display resolution, per host thread count. Run:
//   build/bench/bench_frame --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include "driver/frame_job.h"
#include "driver/host_memory.h"
#include "driver/scene_source.h"
#include "gpu_model/profile_loader.h"
#include "pipeline/bake/brdf_lut.h"

namespace {

using namespace skinsim;

struct Fixture {
  gpu_model::DeviceProfile device = gpu_model::load_device_profile("ipad4", SKINSIM_BENCH_DATA_DIR);
  scene::Scene scene = driver::load_scene(driver::SceneSource{}, 4.0f / 3.0f);
  pipeline::GpuScene gpu_scene{scene};
  pipeline::PipelineConfig config = driver::resolve_config({}, device);  // the display size
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void BM_SkinFrame(benchmark::State& state) {
  Fixture& f = fixture();
  const int threads = static_cast<int>(state.range(0));
  std::uint64_t fragments = 0;
  for (auto _ : state) {
    const driver::FrameResult r = driver::run_frame(f.gpu_scene, f.config, f.device, threads);
    fragments = 0;
    for (const auto& p : r.output.passes) fragments += p.fragments_shaded;
    benchmark::DoNotOptimize(r.timing.frame_ms);
  }
  state.counters["fragments"] = static_cast<double>(fragments);
  state.counters["fragments/s"] = benchmark::Counter(
      static_cast<double>(fragments) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SkinFrame)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

void BM_DefaultSceneBuild(benchmark::State& state) {
  for (auto _ : state) {
    const scene::Scene s = driver::load_scene(driver::SceneSource{}, 4.0f / 3.0f);
    benchmark::DoNotOptimize(s.meshes.size());
  }
}
BENCHMARK(BM_DefaultSceneBuild)->Unit(benchmark::kMillisecond);

// The BRDF LUT baker at 8x32 ... 128x512 (width = 8 x arg, height = 32 x arg).
void BM_BrdfLutBake(benchmark::State& state) {
  bake::BrdfLutParams p;
  p.width = 8 * static_cast<int>(state.range(0));
  p.height = 32 * static_cast<int>(state.range(0));
  for (auto _ : state) {
    const bake::BrdfLut lut = bake::bake_brdf_lut(p);
    benchmark::DoNotOptimize(lut.levels.size());
  }
}
BENCHMARK(BM_BrdfLutBake)->Arg(1)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);

}  // namespace

// As in the skinsim CLI: frames reuse freed memory instead of faulting it in again.
int main(int argc, char** argv) {
  skinsim::driver::retain_freed_memory();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
