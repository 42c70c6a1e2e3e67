#include "driver/truth_render.h"

#include <chrono>
#include <cstdlib>

#include "driver/truth_process.h"
#include "quality/json_value.h"
#include "quality/metrics.h"
#include "util/user_error.h"

namespace skinsim::driver {

std::string blender_program() {
  const char* set = std::getenv("SKINSIM_BLENDER");
  return set && *set ? set : "blender";
}

std::filesystem::path truth_script() {
  return SKINSIM_TRUTH_SCRIPT;
}

double render_truth(const TruthRender& render, const std::filesystem::path& scene_dir, int seed,
                    const std::filesystem::path& exr, const std::filesystem::path& log) {
  if (!program_exists(render.blender)) {
    throw UserError("Blender (" + render.blender +
                    ") is not installed: scripts/install-deps.sh installs it, or set "
                    "SKINSIM_BLENDER to its path");
  }
  if (!std::filesystem::is_regular_file(render.script)) {
    throw UserError("the Cycles script " + render.script.string() + " is missing");
  }
  const auto start = std::chrono::steady_clock::now();
  const int rc =
      run_program({render.blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code", "2",
                   "-P", render.script.string(), "--", (scene_dir / "scene.json").string(),
                   exr.string(), std::to_string(seed), std::to_string(render.threads)},
                  log);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The image is the test of success too: a script that ends early need not raise.
  if (rc != 0 || !std::filesystem::is_regular_file(exr)) {
    throw UserError("Blender failed to render the truth (exit " + std::to_string(rc) + "; see " +
                    log.string() + ")");
  }
  return seconds;
}

nlohmann::json truth_metrics(const quality::Image& test, const quality::Image& truth,
                             const quality::Mask* skin) {
  const auto measure = [&](const quality::Mask* mask) {
    return nlohmann::json{{"psnr_db", quality::metric_to_json(quality::psnr(test, truth, mask))},
                          {"ssim", quality::metric_to_json(quality::ssim(test, truth, mask))},
                          {"flip", quality::metric_to_json(quality::flip(test, truth, mask).mean)}};
  };
  nlohmann::json out{{"all", measure(nullptr)}};
  if (skin && skin->count() > 0) out["skin"] = measure(skin);  // a scan may show no skin
  return out;
}

}  // namespace skinsim::driver
