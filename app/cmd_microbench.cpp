// `skinsim microbench`: reviewer-style throughput tests of the emulated GPU on a device.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli_options.h"
#include "app/commands.h"
#include "microbench/microbench.h"

namespace skinsim::app {

namespace {
struct MicrobenchCliOptions {
  DeviceOptions device;
  microbench::MicrobenchOptions bench;
  bool json = false;
};
}  // namespace

Command add_microbench_command(CLI::App& app) {
  auto o = std::make_shared<MicrobenchCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "microbench",
      "Fill-rate, triangle, bandwidth and ALU tests on the emulated GPU, against spec peaks");
  add_device_options(*cmd, o->device);
  cmd->add_option("--width", o->bench.width, "Render-target width")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  cmd->add_option("--height", o->bench.height, "Render-target height")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  cmd->add_option("--only", o->bench.only,
                  "Benchmarks to run: " +
                      fmt::format("{}", fmt::join(microbench::microbenchmark_names(), ", ")))
      ->delimiter(',');
  cmd->add_flag("--json", o->json, "Print JSON instead of a table");
  return [o] {
    const gpu_model::DeviceProfile profile = load_device(o->device);
    microbench::MicrobenchOptions options = o->bench;
    options.threads = o->device.threads;
    const auto results = microbench::run_microbenchmarks(profile, options);
    if (o->json) {
      fmt::print("{}\n", microbench::to_json(results).dump(2));
    } else {
      fmt::print("skinsim microbench on {} ({}), {}x{}\n{}", profile.name, profile.gpu,
                 options.width, options.height, microbench::format_microbench_table(results));
    }
    return 0;
  };
}

}  // namespace skinsim::app
