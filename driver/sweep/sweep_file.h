// Sweep files (TOML): the axes, fixed knobs, scene and budget of a sweep, e.g.
//
//   [axes]
//   scale = [1, 0.5, 0.25]
//   lut = ["8x32", "32x128"]
//   device = ["ipad4", "iphone5"]
//   [fixed]
//   blur_iterations = 2
//   [scene]
//   path = "head.glb"          # relative to the sweep file; "builtin" (default)
//   skin_materials = ["all"]
//   units_per_mm = 0.0196      # optional: else metres if plausible, else from the head
//   skin_albedo = "194,150,130"  # or an image, relative to the sweep file
//   [report]
//   budget_ms = 33.3
//
// See docs/sweeps.md for every key.
#pragma once

#include <string>

#include "driver/sweep/sweep_spec.h"

namespace skinsim::driver {

// Parses a sweep file; throws SweepError naming the file, line and key at fault (also for TOML
// syntax errors and unknown tables or keys).
SweepSpec parse_sweep_file(const std::string& path);

// The same from text; `name` stands for the file in messages and relative scene paths are
// resolved against `base_dir`.
SweepSpec parse_sweep_text(const std::string& text, const std::string& name,
                           const std::string& base_dir);

}  // namespace skinsim::driver
