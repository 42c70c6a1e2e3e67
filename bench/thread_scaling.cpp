// Host-thread scaling of one emulated frame, and its determinism: renders the default scene's
// skin frame at the device's display resolution (2048x1536 on ipad4) with 1, 2, 4, ... host
// threads up to the machine's, prints the best and median wall time of each count beside
// its speed-up over 1 thread, and exits 1 unless every count gives the 1-thread frame's
// image and counters bit for bit. It prints their digest too: two machines that print the
// same one rendered and counted the same frame. It reads no images and draws no charts, so it runs
// on a bare many-core machine with only the data directory beside it:
//   build/bench/thread_scaling [--frames N] [--max-threads T] [--data DIR]
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "driver/frame_job.h"
#include "driver/host_memory.h"
#include "driver/scene_source.h"
#include "gpu_model/profile_loader.h"

namespace {

using namespace skinsim;

// FNV-1a over the frame's pixels and every pass's counters, tile by tile: equal digests mean
// the same image and the same counted work.
class Digest {
 public:
  template <typename T>
  void add(const T& value) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    for (std::size_t i = 0; i < sizeof(T); ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

void add_texture(Digest& d, const sim::TextureCounters& t) {
  for (const std::uint64_t n : t.samples_by_filter) d.add(n);
  for (const std::uint64_t n : {t.samples_dependent, t.samples_wide_format, t.texels_touched,
                                t.cache_line_accesses, t.cache_misses, t.dram_bytes}) {
    d.add(n);
  }
}

std::uint64_t frame_digest(const driver::FrameResult& r) {
  Digest d;
  for (const glm::vec4& p : r.output.frame.pixels) d.add(p);
  for (const sim::PassCounters& pass : r.output.passes) {
    for (const sim::TileCounters& t : pass.tiles) {
      for (const std::uint64_t n :
           {t.fragments_depth_tested, t.fragments_shaded, t.fragments_blended, t.color_load_bytes,
            t.color_store_bytes, t.depth_store_bytes}) {
        d.add(n);
      }
      add_texture(d, t.texture);
    }
  }
  d.add(r.timing.frame_ms);
  return d.value();
}

int int_option(int argc, char** argv, const char* name, int fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) {
      char* end = nullptr;
      const long v = std::strtol(argv[i + 1], &end, 10);
      if (*end != '\0' || v < 1 || v > 1024) {
        std::fprintf(stderr, "thread_scaling: %s wants a whole number in [1, 1024], got '%s'\n",
                     name, argv[i + 1]);
        std::exit(2);
      }
      return static_cast<int>(v);
    }
  }
  return fallback;
}

std::string string_option(int argc, char** argv, const char* name, const char* fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return argv[i + 1];
  }
  return fallback;
}

}  // namespace

int main(int argc, char** argv) try {
  driver::retain_freed_memory();
  const int frames = int_option(argc, argv, "--frames", 3);
  const int max_threads =
      int_option(argc, argv, "--max-threads",
                 static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  const gpu_model::DeviceProfile device = gpu_model::load_device_profile(
      "ipad4", string_option(argc, argv, "--data", SKINSIM_BENCH_DATA_DIR));
  const pipeline::PipelineConfig config = driver::resolve_config({}, device);  // the display's size
  const scene::Scene scene = driver::load_scene(
      driver::SceneSource{}, static_cast<float>(config.width) / static_cast<float>(config.height));
  const pipeline::GpuScene gpu_scene(scene);

  std::vector<int> counts;
  for (int t = 1; t < max_threads; t *= 2) counts.push_back(t);
  counts.push_back(max_threads);

  std::printf("%dx%d frame on %s (%d emulated cores), %d frames per thread count\n", config.width,
              config.height, device.name.c_str(), gpu_model::sim_parameters(device).cores, frames);
  std::printf("%8s %10s %10s %9s  %s\n", "threads", "best ms", "median ms", "speed-up",
              "image and counters");
  std::uint64_t expected = 0;
  double one_thread_ms = 0.0;
  bool identical = true;
  for (const int threads : counts) {
    std::vector<double> ms;
    std::uint64_t digest = 0;
    for (int f = 0; f < frames; ++f) {
      const auto t0 = std::chrono::steady_clock::now();
      const driver::FrameResult r = driver::run_frame(gpu_scene, config, device, threads);
      ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      digest = frame_digest(r);
      if (threads == 1 && f == 0) expected = digest;
      identical = identical && digest == expected;
    }
    std::sort(ms.begin(), ms.end());
    if (threads == 1) one_thread_ms = ms.front();
    std::printf("%8d %10.1f %10.1f %8.2fx  %s\n", threads, ms.front(), ms[ms.size() / 2],
                one_thread_ms / ms.front(),
                digest == expected ? "identical to 1 thread" : "DIFFERENT from 1 thread");
  }
  std::printf("frame digest (image, every tile's counters, modelled ms): %016llx\n",
              static_cast<unsigned long long>(expected));
  return identical ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "thread_scaling: %s\n", e.what());
  return 2;
}
