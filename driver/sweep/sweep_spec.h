// What a sweep runs: axes of knob values (any pipeline knob by name, plus `device`), knobs held
// fixed, and the scene; expanded into configurations with short, stable, readable ids.
#pragma once

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "driver/frame/scene_source.h"
#include "pipeline/config.h"
#include "pipeline/technique.h"
#include "util/user_error.h"

namespace skinsim::driver {

// Bad sweep input (an unknown knob, a bad value, a broken sweep file); the message names the
// option or file, line and key at fault.
class SweepError : public UserError {
 public:
  using UserError::UserError;
};

// One swept knob: every value is tried with every value of the other axes, for each
// configuration whose technique uses the knob (pipeline::knob_applies).
struct SweepAxis {
  std::string knob;                 // a key of pipeline::config_field_names(), or "device"
  std::vector<std::string> values;  // as given; canonicalised by expand_sweep
  std::string origin;               // where it came from, for errors: "--scales", "s.toml:4"
};

// A knob every configuration shares (e.g. blur_iterations = 2).
struct FixedKnob {
  std::string knob;
  std::string value;
  std::string origin;
};

struct SweepSpec {
  std::vector<SweepAxis> axes;  // the first axis varies slowest
  std::vector<FixedKnob> fixed;
  SceneSource scene;
  double budget_ms = 1000.0 / 30.0;  // frame budget the report recommends within
};

// The default sweep: integration-buffer scales 1, 0.5, 0.25, 0.125 x BRDF LUT sizes 8x32,
// 16x64, 32x128, 64x256, on ipad4 at its display resolution, built-in scene.
SweepSpec default_sweep_spec();

// Adds an axis, replacing an existing axis of the same knob (the command line overrides a
// sweep file this way). Throws SweepError naming `origin` for an unknown knob or no values.
void set_axis(SweepSpec& spec, const std::string& knob, const std::vector<std::string>& values,
              const std::string& origin);

// Throws SweepError naming `fixed.origin` when its knob is also an axis of `spec`: the axis
// would set it in every configuration, so the fixed value would be silently ignored.
void require_not_swept(const SweepSpec& spec, const FixedKnob& fixed);

// The knob names an axis or a fixed knob may use: config_field_names() and "device".
std::vector<std::string> sweep_knob_names();

struct SweepConfig {
  std::string id;      // unique in the sweep, file-name safe, e.g. "scale0.5_lut32x128"
  std::string label;   // the swept knobs it uses, e.g. "scale 0.5, lut 32x128"
  std::string device;  // profile name or .toml path
  pipeline::PipelineConfig config;  // fixed and swept knobs applied, validated (resolution
                                    // 0x0 = the device's display, resolved at run time)
  // (knob, canonical value) of the axes it uses, in axis order.
  std::vector<std::pair<std::string, std::string>> swept;
};

// Sweeps larger than this are refused unless the user raises the limit (`--max-configs`):
// each configuration renders frames and writes megabytes, so 1.6 million would run for hours.
inline constexpr std::size_t kDefaultMaxConfigs = 10000;

// Every combination of the axes' values, in axis order (last axis fastest), except that an
// axis a combination's technique does not use (pipeline::knob_applies: scale for wrap, lut
// with an analytic specular model) is not expanded for it: it keeps its base value (fixed,
// else the default), and the combinations that then repeat one run only once. Only the
// technique and specular axes are enumerated to find out which axes apply, so the count is
// known before anything is built. The id still names every axis's value, the label only those
// used. Values are validated and canonicalised through pipeline::set_config_field/
// get_config_field ("1.0" -> "1"), and every configuration through PipelineConfig::validate().
// Throws SweepError naming the axis origin and value, a duplicate value on one axis, or more
// than `max_configs` configurations (naming the count, the limit and --max-configs).
std::vector<SweepConfig> expand_sweep(const SweepSpec& spec,
                                      std::size_t max_configs = kDefaultMaxConfigs);

// How many configurations expand_sweep would make (saturating at SIZE_MAX), without making
// them: milliseconds even for a product of billions. Validates every value as expand_sweep.
std::size_t count_sweep_configs(const SweepSpec& spec);

// Everything a finished configuration's results depend on that the sweep controls: every
// pipeline knob (resolution resolved to `width`x`height`), the device and the scene
// (`scene`: scene_fingerprint, computed once for all configurations). A stored result is
// reused only when its fingerprint equals this one.
nlohmann::json config_fingerprint(const SweepConfig& config, const nlohmann::json& scene, int width,
                                  int height);

// Every pipeline knob plus device, with the resolution resolved (the fingerprint's knobs;
// a results row keeps those the configuration uses, see keep_used_knobs).
std::vector<std::pair<std::string, std::string>> all_knobs(const SweepConfig& config, int width,
                                                           int height);

// Removes from `knobs` (as all_knobs gives them) the pipeline knobs this configuration's
// frame does not depend on (pipeline::knob_applies): what a results row shows.
void keep_used_knobs(const SweepConfig& config, std::map<std::string, std::string>& knobs);

}  // namespace skinsim::driver
