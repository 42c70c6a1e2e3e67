// One knob of a frame as a row of a table: every interface reads the rows (the `run` options,
// sweep axes and their options, configuration ids, --set, budget files, validation messages,
// whether a knob applies to a technique, `skinsim knobs` and docs/knobs.md), so a knob is added in
// one place. The way pbrt-v4 builds objects from a parameter set, with the parameters described
// once.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace skinsim::pipeline {

struct PipelineConfig;

struct KnobSpec {
  std::string name;    // the key: --set NAME=VALUE, sweep axes, budget [pipeline], result.json
  std::string flag;    // the `run` / `sweep` option, e.g. "--lod-distance"
  std::string values;  // what it accepts, e.g. "number in (0, 1]"
  std::string help;    // one sentence
  // Parses text into the config; throws ConfigError naming the knob on a syntax error.
  std::function<void(PipelineConfig&, const std::string&)> set;
  std::function<std::string(const PipelineConfig&)> get;
  // Why the config's value is out of range ("" when it is in range): validate() throws it.
  std::function<std::string(const PipelineConfig&)> invalid;
  // Whether the frame depends on the knob given the rest of the config, for a technique that
  // uses it (the BRDF LUT knobs only with the ks_lut specular model); empty: always.
  std::function<bool(const PipelineConfig&)> applies;
  // Whether this knob's value decides whether others apply (technique, specular, shadows):
  // sweeps enumerate such axes before folding the others.
  bool decides = false;
  // Whether the reference frame depends on it (the scene's framing and light, the BRDF
  // parameters): sweeps render one reference per combination of these.
  bool reference = false;
  // The sweep's own option for the knob as an axis, and its help ("--scales", "Integration-
  // buffer scales, e.g. 1,0.5,0.25,0.125"); empty: swept from sweep files only.
  std::string sweep_flag;
  std::string sweep_help;
  // What a configuration's id puts before the knob's value: numbers need a name to be
  // readable ("scale0.5"), words do not ("mobile"). Unset: the knob's name.
  std::optional<std::string> id_prefix;
};

// Every knob: the ones all techniques use, then each technique's own (technique.h), in
// registry order.
const std::vector<KnobSpec>& all_knobs();
// The knob called `name`; throws ConfigError listing the known names.
const KnobSpec& find_knob(const std::string& name);
// The knobs every technique uses (technique, resolution, gamma, the specular knobs).
const std::vector<KnobSpec>& common_knobs();

}  // namespace skinsim::pipeline
