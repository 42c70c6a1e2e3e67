// `skinsim truth`, part 2: renders a scene written by write_truth_scene (truth_scene.h) with
// Blender Cycles, headless (`blender -b --factory-startup -P scripts/truth/cycles_render.py`),
// to a linear OpenEXR; and the metrics of skinsim's images against such a truth.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "image/image.h"

namespace skinsim::driver {

// $SKINSIM_BLENDER, else "blender" from PATH.
std::string blender_program();

// Throws UserError when `blender` cannot be run (not installed), saying how to get it.
void require_blender(const std::string& blender);

// The first line of `blender --version` (e.g. "Blender 3.4.1"): which Blender renders a
// truth, for its key (truth_store.h). Asked once per process and program. Throws UserError
// when Blender is missing, fails or prints nothing.
std::string blender_version(const std::string& blender);

// scripts/truth/cycles_render.py of the source tree skinsim was built from.
std::filesystem::path truth_script();

struct TruthRender {
  std::string blender;           // the program
  std::filesystem::path script;  // cycles_render.py
  int threads = 0;               // 0: Blender's own choice (every core)
};

// Renders scene_dir/scene.json to `exr` with the Monte Carlo `seed`; Blender's output is
// appended to `log`. Returns the wall-clock seconds. Throws UserError when Blender is missing
// or fails (naming the log).
double render_truth(const TruthRender& render, const std::filesystem::path& scene_dir, int seed,
                    const std::filesystem::path& exr, const std::filesystem::path& log);

// PSNR, SSIM and FLIP of `test` against `truth` over every pixel and, with `skin`, over the
// skin pixels when it has any: {"all": {...}, "skin": {...}} (values as
// quality/json_value.h writes them).
nlohmann::json truth_metrics(const image::Image& test, const image::Image& truth,
                             const image::Mask* skin);

}  // namespace skinsim::driver
