// Wall time of the host's hot paths on the default scene at the iPad 4's display resolution,
// per host thread count: emulating one frame through the full skin pipeline, and what a
// sweep adds to each frame (the reference render, FLIP against a prepared frame). Run:
//   build/bench/bench_frame --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <filesystem>
#include <memory>

#include "driver/frame/frame_job.h"
#include "driver/frame/frame_quality.h"
#include "driver/frame/host_memory.h"
#include "driver/frame/images.h"
#include "driver/frame/scene_source.h"
#include "driver/sweep/sweep_thumbnails.h"
#include "gpu_model/profile_loader.h"
#include "image/image.h"
#include "pipeline/bake/brdf_lut.h"
#include "pipeline/reference/reference.h"
#include "quality/metrics.h"

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

// The default frame with `msaa` samples per pixel on the framebuffer render.
void skin_frame(benchmark::State& state, int msaa) {
  Fixture& f = fixture();
  const int threads = static_cast<int>(state.range(0));
  pipeline::PipelineConfig config = f.config;
  config.msaa = msaa;
  std::uint64_t fragments = 0;
  for (auto _ : state) {
    const driver::FrameResult r = driver::run_frame(f.gpu_scene, config, f.device, threads);
    fragments = 0;
    for (const auto& p : r.output.passes) fragments += p.fragments_shaded;
    benchmark::DoNotOptimize(r.timing.frame_ms);
  }
  state.counters["fragments"] = static_cast<double>(fragments);
  state.counters["fragments/s"] = benchmark::Counter(
      static_cast<double>(fragments) * state.iterations(), benchmark::Counter::kIsRate);
}
void BM_SkinFrame(benchmark::State& state) {
  skin_frame(state, 1);
}
BENCHMARK(BM_SkinFrame)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

void BM_SkinFrameMsaa4(benchmark::State& state) {
  skin_frame(state, 4);
}
BENCHMARK(BM_SkinFrameMsaa4)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

// The ground-truth reference a sweep renders once per scene and resolution (ray-cast shadows,
// diffusion over the skin's 3D positions).
void BM_ReferenceFrame(benchmark::State& state) {
  Fixture& f = fixture();
  for (auto _ : state) {
    const pipeline::ReferenceFrame r =
        pipeline::render_reference(f.gpu_scene, f.config, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(r.frame.pixels.data());
  }
}
BENCHMARK(BM_ReferenceFrame)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// FLIP of one configuration's frame against another's, prepared once (quality::FlipFeatures),
// as a sweep compares each configuration with its group's best: the default sweep's buffer
// scales 0.125 and 0.25, which differ in about 11% of the pixels.
void BM_FlipAgainstPrepared(benchmark::State& state) {
  Fixture& f = fixture();
  static const auto frames = [&f] {
    const auto frame_at = [&f](float scale) {
      pipeline::PipelineConfig config = f.config;
      config.mobile.scale = scale;
      config.lut_width = 64;
      config.lut_height = 256;
      return driver::to_image(driver::run_frame(f.gpu_scene, config, f.device, 0).output.frame);
    };
    return std::pair{frame_at(0.125f), quality::FlipFeatures(frame_at(0.25f))};
  }();
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    arena.execute(
        [&] { benchmark::DoNotOptimize(quality::flip(frames.first, frames.second).mean); });
  }
}
BENCHMARK(BM_FlipAgainstPrepared)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// What a sweep does with each configuration's frame beside the next frame
// (driver/sweep/sweep_run.cpp, finish): PSNR, SSIM and FLIP against the reference, prepared once;
// the frame's and its FLIP map's PNGs with their thumbnails; and, after the sweep, each frame
// decoded again for its comparison with its group's best.
const image::Image& scale_eighth_frame() {
  static const image::Image frame = [] {
    Fixture& f = fixture();
    pipeline::PipelineConfig config = f.config;
    config.mobile.scale = 0.125f;
    return driver::to_image(driver::run_frame(f.gpu_scene, config, f.device, 0).output.frame);
  }();
  return frame;
}

const driver::ReferenceImages& prepared_reference() {
  static const driver::ReferenceImages reference = [] {
    Fixture& f = fixture();
    driver::ReferenceImages r =
        driver::reference_images(pipeline::render_reference(f.gpu_scene, f.config, 0));
    r.flip_features = std::make_shared<const quality::FlipFeatures>(r.image);
    return r;
  }();
  return reference;
}

void BM_FrameQuality(benchmark::State& state) {
  const image::Image& frame = scale_eighth_frame();
  const driver::ReferenceImages& reference = prepared_reference();
  tbb::task_arena arena(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    arena.execute([&] { benchmark::DoNotOptimize(driver::evaluate_quality(frame, reference)); });
  }
}
BENCHMARK(BM_FrameQuality)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

std::filesystem::path bench_directory() {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() / "skinsim_bench_images";
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

void BM_FramePngAndThumbnail(benchmark::State& state) {
  const image::Image& frame = scale_eighth_frame();
  tbb::task_arena arena(1);
  for (auto _ : state) {
    arena.execute(
        [&] { driver::write_image_and_thumbnail(frame, bench_directory(), "frame.png"); });
  }
}
BENCHMARK(BM_FramePngAndThumbnail)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FramePngDecode(benchmark::State& state) {
  const std::filesystem::path png = bench_directory() / "decoded.png";
  image::save_png(scale_eighth_frame(), png);
  tbb::task_arena arena(1);
  for (auto _ : state) {
    arena.execute([&] { benchmark::DoNotOptimize(image::load_png(png).rgb.data()); });
  }
}
BENCHMARK(BM_FramePngDecode)->Unit(benchmark::kMillisecond)->UseRealTime();

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
