// Host-thread scaling of one emulated frame, and its determinism: renders the default scene's
// skin frame at the device's display resolution (2048x1536 on ipad4) with 1, 2, 4, ... host
// threads up to the machine's, prints the best and median wall time of each count beside
// its speed-up over 1 thread, and exits 1 unless every count gives the 1-thread frame's
// image and counters bit for bit. It prints their digest too: two machines that print the
// same one rendered and counted the same frame. Where the machine has at least twice the
// device's cores, it then renders 2, 4, ... frames at once with the threads shared among them
// (what a sweep could do instead of one frame with every thread) and prints the frames per
// second and the process's peak memory of each, and then the default sweep's 16 frames in 1,
// 2, 4, ... lanes, each lane taking the next configuration and replaying passes from its own
// memo (run_sweep renders one lane with every thread, the first row; it ran several on such a
// machine before 2026-11-26, docs/performance.md). It reads no images and draws no charts, so
// it runs on a bare many-core machine with only the data directory beside it:
//   build/bench/thread_scaling [--frames N] [--max-threads T] [--data DIR]
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "driver/frame/frame_job.h"
#include "driver/frame/host_memory.h"
#include "driver/frame/scene_source.h"
#include "driver/sweep/sweep_run.h"
#include "driver/sweep/sweep_spec.h"
#include "gpu_model/profile_loader.h"
#include "sim/pass_memo.h"

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

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// Runs lane(0) .. lane(lanes - 1) at once, one std::thread each, and waits for them.
template <typename Lane>
void run_lanes(int lanes, const Lane& lane) {
  std::vector<std::thread> threads;
  for (int i = 0; i < lanes; ++i) threads.emplace_back([&lane, i] { lane(i); });
  for (std::thread& t : threads) t.join();
}

// `rounds` rounds of `in_flight` frames at once, each frame on threads / in_flight host
// threads; returns frames per second, and clears `identical` if any frame differs from
// `expected`. Rows run with the frames in flight ascending, so a row's peak memory is its
// own (peak memory only grows).
double frames_per_second(const pipeline::GpuScene& scene, const pipeline::PipelineConfig& config,
                         const gpu_model::DeviceProfile& device, int threads, int in_flight,
                         int rounds, std::uint64_t expected, bool& identical) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int round = 0; round < rounds; ++round) {
    std::vector<std::uint64_t> digests(in_flight);
    run_lanes(in_flight, [&](int lane) {
      digests[lane] = frame_digest(driver::run_frame(scene, config, device, threads / in_flight));
    });
    for (const std::uint64_t d : digests) identical = identical && d == expected;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return static_cast<double>(rounds * in_flight) / seconds;
}

// The default sweep's frames (no quality metrics, no files), `lanes` at a time: each lane
// takes the next configuration and replays passes from a memo of its own, as large as
// run_sweep's. Returns the seconds taken and the passes replayed and rendered.
struct SweepFrames {
  double seconds;
  std::uint64_t replayed, rendered;
};
SweepFrames sweep_frames(const pipeline::GpuScene& scene, const gpu_model::DeviceProfile& device,
                         int threads, int lanes) {
  const std::vector<driver::SweepConfig> configs =
      driver::expand_sweep(driver::default_sweep_spec());
  std::atomic<std::size_t> next{0};
  std::atomic<std::uint64_t> replayed{0}, rendered{0};
  const auto t0 = std::chrono::steady_clock::now();
  run_lanes(lanes, [&](int) {
    sim::PassMemo memo(driver::kPassMemoBytes);
    for (std::size_t i = next++; i < configs.size(); i = next++) {
      driver::run_frame(scene, driver::resolve_config(configs[i].config, device), device,
                        threads / lanes, {}, &memo);
    }
    replayed += memo.stats().replayed;
    rendered += memo.stats().rendered;
  });
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          replayed.load(), rendered.load()};
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

  const int cores = gpu_model::sim_parameters(device).cores;
  if (max_threads >= 2 * cores) {
    std::printf("\n%d host threads shared by frames in flight, %d rounds each\n", max_threads,
                frames);
    std::printf("%9s %16s %13s %13s  %s\n", "in flight", "threads a frame", "frames / s",
                "peak RSS MB", "image and counters");
    for (int in_flight = 1; max_threads / in_flight >= cores; in_flight *= 2) {
      bool same = true;
      const double rate = frames_per_second(gpu_scene, config, device, max_threads, in_flight,
                                            frames, expected, same);
      identical = identical && same;
      std::printf("%9d %16d %13.2f %13.0f  %s\n", in_flight, max_threads / in_flight, rate,
                  peak_rss_mb(), same ? "identical to 1 thread" : "DIFFERENT from 1 thread");
    }
  }
  if (max_threads >= 2 * cores) {
    std::printf("\nthe default sweep's frames, %d host threads shared by lanes\n", max_threads);
    std::printf("%6s %16s %10s %16s %13s\n", "lanes", "threads a frame", "seconds",
                "passes replayed", "peak RSS MB");
    for (int lanes = 1; max_threads / lanes >= cores; lanes *= 2) {
      const SweepFrames f = sweep_frames(gpu_scene, device, max_threads, lanes);
      std::printf("%6d %16d %10.2f %9llu of %3llu %13.0f\n", lanes, max_threads / lanes, f.seconds,
                  static_cast<unsigned long long>(f.replayed),
                  static_cast<unsigned long long>(f.replayed + f.rendered), peak_rss_mb());
    }
  }
  std::printf("frame digest (image, every tile's counters, modelled ms): %016llx\n",
              static_cast<unsigned long long>(expected));
  return identical ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "thread_scaling: %s\n", e.what());
  return 2;
}
