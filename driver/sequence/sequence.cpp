#include "driver/sequence/sequence.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "io/read_file.h"
#include "pipeline/lighting.h"

namespace skinsim::driver {

namespace {

// Angles about the up axis: a path may go past +-180 degrees (an orbit), the knobs may not.
bool is_turn_angle(const std::string& knob) {
  return knob == "camera_yaw_deg" || knob == "light_azimuth_deg";
}

double wrap_degrees(double deg) {
  const double wrapped = std::remainder(deg, 360.0);  // in [-180, 180]
  return wrapped == -180.0 ? 180.0 : wrapped;
}

// The knob's value as the run set it, or nullopt when it is "auto".
std::optional<double> knob_number(const pipeline::PipelineConfig& config, const std::string& knob) {
  const std::string text = pipeline::get_config_field(config, knob);
  if (text == "auto") return std::nullopt;
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {  // not a number: reported below
  }
  throw SequenceError(
      fmt::format("sequence track '{}': the knob is not numeric (its value is '{}')", knob, text));
}

Sequence preset(const std::string& name) {
  Sequence s;
  s.name = name;
  s.fps = 30.0;
  if (name == "push-in") {
    s.frames = 60;
    s.tracks = {{.knob = "camera_distance_m", .from = 2.8, .to = 0.35}};
  } else if (name == "head-turn") {
    s.frames = 60;
    s.tracks = {{.knob = "camera_yaw_deg", .relative = true, .by = 90.0},
                {.knob = "light_azimuth_deg", .relative = true, .by = 90.0}};
  } else if (name == "light-orbit") {
    s.frames = 120;
    s.loops = true;
    s.tracks = {{.knob = "light_azimuth_deg", .relative = true, .by = 360.0}};
  } else if (name == "animation" || name.starts_with("animation:")) {
    s.animated = true;
    s.animation = name.substr(std::min(name.size(), std::string("animation:").size()));
  } else {
    throw SequenceError(
        fmt::format("--sequence: unknown sequence '{}': expected one of {}, animation[:NAME] or a "
                    "sequence file (.toml)",
                    name, fmt::join(sequence_preset_names(), ", ")));
  }
  return s;
}

}  // namespace

double Sequence::progress(int frame) const {
  if (loops) return static_cast<double>(frame) / frames;
  return frames > 1 ? static_cast<double>(frame) / (frames - 1) : 0.0;
}

const std::vector<std::string>& sequence_preset_names() {
  static const std::vector<std::string> names = {"push-in", "head-turn", "light-orbit"};
  return names;
}

Sequence load_sequence(const std::string& name_or_file, int frames, double fps) {
  Sequence s =
      name_or_file.ends_with(".toml")
          ? parse_sequence_file(io::read_regular_file(name_or_file, "sequence file"), name_or_file)
          : preset(name_or_file);
  if (frames < 0 || frames > kMaxSequenceFrames) {
    throw SequenceError(fmt::format("--frames: {} is out of range: must be in [1, {}]", frames,
                                    kMaxSequenceFrames));
  }
  if (frames > 0) s.frames = frames;
  if (!(fps >= 0.0) || fps > 1000.0) {
    throw SequenceError(fmt::format("--fps: {} is out of range: must be in (0, 1000]", fps));
  }
  if (fps > 0.0) s.fps = fps;
  return s;
}

void check_sequence(const Sequence& sequence, const pipeline::PipelineConfig& config) {
  const std::vector<std::string>& names = pipeline::config_field_names();
  const pipeline::PipelineConfig defaults;
  for (const SequenceTrack& t : sequence.tracks) {
    if (std::find(names.begin(), names.end(), t.knob) == names.end()) {
      throw SequenceError(fmt::format("sequence '{}': unknown knob '{}'", sequence.name, t.knob));
    }
    knob_number(config, t.knob);  // throws for a knob that is not a number
    if (!t.relative && pipeline::get_config_field(config, t.knob) !=
                           pipeline::get_config_field(defaults, t.knob)) {
      throw SequenceError(fmt::format(
          "sequence '{}' moves {} from {} to {}; the run's own value ({}) would be overwritten: "
          "leave that knob out",
          sequence.name, t.knob, t.from, t.to, pipeline::get_config_field(config, t.knob)));
    }
  }
}

pipeline::PipelineConfig sequence_frame_config(const Sequence& sequence, int frame,
                                               const pipeline::PipelineConfig& config,
                                               const pipeline::GpuScene& scene) {
  pipeline::PipelineConfig c = config;
  const double at = sequence.progress(frame);
  for (const SequenceTrack& t : sequence.tracks) {
    double value = 0.0;
    if (t.relative) {
      std::optional<double> start = knob_number(config, t.knob);
      if (!start && t.knob == "light_azimuth_deg") start = pipeline::key_light_azimuth_deg(scene);
      if (!start) {
        throw SequenceError(fmt::format(
            "sequence '{}': track '{}' moves the run's value, and the run has none: set it",
            sequence.name, t.knob));
      }
      value = *start + at * t.by;
    } else {
      value = t.from + at * (t.to - t.from);
    }
    if (is_turn_angle(t.knob)) value = wrap_degrees(value);
    try {
      pipeline::set_config_field(c, t.knob, fmt::format("{}", value));
    } catch (const pipeline::ConfigError& e) {
      throw SequenceError(
          fmt::format("sequence '{}', frame {}: {}", sequence.name, frame, e.what()));
    }
  }
  c.validate();
  return c;
}

}  // namespace skinsim::driver
