#include "driver/truth/truth_render.h"

#include <fmt/format.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>

#include "driver/frame/truth_process.h"
#include "quality/json_value.h"
#include "quality/metrics.h"
#include "util/text.h"
#include "util/user_error.h"

namespace skinsim::driver {

std::string blender_program() {
  const char* set = std::getenv("SKINSIM_BLENDER");
  return set && *set ? set : "blender";
}

void require_blender(const std::string& blender) {
  if (!program_exists(blender)) {
    throw UserError("Blender (" + blender +
                    ") is not installed: scripts/install-deps.sh installs it, or set "
                    "SKINSIM_BLENDER to its path");
  }
}

std::string blender_version(const std::string& blender) {
  static std::mutex mutex;
  static std::map<std::string, std::string> known;  // program -> its version
  const std::lock_guard lock(mutex);
  if (const auto it = known.find(blender); it != known.end()) return it->second;
  require_blender(blender);
  std::string log = (std::filesystem::temp_directory_path() / "skinsim-blender-XXXXXX").string();
  const int fd = mkstemp(log.data());
  if (fd < 0) {
    throw UserError(fmt::format("cannot make a scratch file in {}: {}",
                                std::filesystem::temp_directory_path().string(),
                                std::strerror(errno)));
  }
  ::close(fd);
  const int rc = run_program({blender, "--version"}, log);
  std::string line;
  std::getline(std::ifstream(log), line);
  std::filesystem::remove(log);
  // Only the version goes into the key: never more than a line, and no control characters.
  line = sanitized(line.substr(0, line.find_last_not_of(" \t\r") + 1), 200);
  if (rc != 0 || line.empty()) {
    throw UserError(fmt::format(
        "Blender ({}) --version {}: the truth store's key names the Blender that renders a "
        "truth",
        blender, rc != 0 ? fmt::format("failed (exit {})", rc) : std::string("printed nothing")));
  }
  return known[blender] = line;
}

std::filesystem::path truth_script() {
  return SKINSIM_TRUTH_SCRIPT;
}

double render_truth(const TruthRender& render, const std::filesystem::path& scene_dir, int seed,
                    const std::filesystem::path& exr, const std::filesystem::path& log) {
  require_blender(render.blender);
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

nlohmann::json truth_metrics(const image::Image& test, const image::Image& truth,
                             const image::Mask* skin) {
  const auto measure = [&](const image::Mask* mask) {
    return nlohmann::json{{"psnr_db", quality::metric_to_json(quality::psnr(test, truth, mask))},
                          {"ssim", quality::metric_to_json(quality::ssim(test, truth, mask))},
                          {"flip", quality::metric_to_json(quality::flip(test, truth, mask).mean)}};
  };
  nlohmann::json out{{"all", measure(nullptr)}};
  if (skin && skin->count() > 0) out["skin"] = measure(skin);  // a scan may show no skin
  return out;
}

}  // namespace skinsim::driver
