// The skin-rendering techniques skinsim compares, as a registry. Each technique is one folder,
// pipeline/techniques/<name>/: its passes, the shader programs it instantiates, its own knobs
// and a TechniqueSpec, listed once in pipeline/techniques/registry.cpp. The CLI, sweeps, the
// shader report, result.json and the report read the registry; docs/techniques.md describes
// each one.
#pragma once

#include <string>
#include <vector>

#include "pipeline/knob.h"
#include "shading/op_profile.h"

namespace skinsim::sim {
class Gpu;
}

namespace skinsim::pipeline {

class GpuScene;
class FrameLights;
struct FrameOutput;

struct TechniqueSpec {
  std::string name;     // --technique, sweep axes, result.json, golden data folder
  std::string passes;   // its render passes in order, e.g. "irradiance, blur_h, blur_v, skin"
  std::string summary;  // what it is, one line
  // Knobs only this technique uses (rows of the knob table); every technique also uses
  // common_knobs().
  std::vector<KnobSpec> knobs;
  // Renders one frame (config validated, resolution resolved) after the frame's shadow pass:
  // every lit pass binds and sets `lights`.
  FrameOutput (*render)(const GpuScene& scene, const PipelineConfig& config,
                        const FrameLights& lights, sim::Gpu& gpu);
  // The programs it can run, with default uniforms, for `skinsim shaders`.
  std::vector<sim::NamedProfile> (*shaders)();
  // Host time to emulate one frame per output pixel at default knobs, in nanoseconds: the
  // slope between `skinsim run --threads 1 --no-reference` at 1024x768 and 2048x1536 (AMD
  // EPYC, 2026-11-24). Only sweep shards use it, to balance their expected work
  // (driver/sweep/sweep_shard.h); the cost model never does.
  int host_ns_per_pixel = 0;
  // Whether its shader has a specular model of its own (urp: the article's dual GGX), so that
  // the `specular` knob and the BRDF LUT's knobs do not apply to it.
  bool own_specular = false;
};

// Every technique, in registry order (the first is the default).
const std::vector<const TechniqueSpec*>& all_techniques();
std::vector<std::string> technique_names();
// The technique called `name`; throws ConfigError listing the known ones.
const TechniqueSpec& find_technique(const std::string& name);

// The knob names a technique's frame depends on besides the common ones: its own knobs.
std::vector<std::string> technique_knobs(const std::string& technique);

// Whether a frame rendered with `config` depends on `knob`: a common knob or one of the
// technique's own, and the knob's own condition (KnobSpec::applies) holds.
bool knob_applies(const PipelineConfig& config, const std::string& knob);

// The knobs a one-line summary of a frame names: the technique's own, then the specular model,
// when it reads it the BRDF LUT's, and the skin shader's precision (the common knobs that tell
// techniques' frames apart).
std::vector<std::string> summary_knobs(const PipelineConfig& config);

// Whether the config's technique uses the `specular` knob (all but those with their own model).
bool uses_specular_knob(const PipelineConfig& config);
// Whether the config's specular model reads the BRDF LUT (ks_lut; the others evaluate in ALU).
bool reads_brdf_lut(const PipelineConfig& config);

}  // namespace skinsim::pipeline
