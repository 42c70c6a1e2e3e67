// `skinsim export`: one frame of a technique as a GPU capture would describe it, for running
// the pipeline elsewhere (a device, Mesa llvmpipe) or feeding its shaders to a vendor's
// offline compiler. Every pass's programs as GLSL ES, emitted from the same C++ shader code
// the emulator runs and counts (sim/shader_emit_io.h), and frame.json: the passes in draw
// order with their targets and sizes, load/clear/store actions, draws, texture bindings and
// samplers, fixed-function state and the uniforms left in the shaders.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "driver/frame/frame_job.h"
#include "shading/shader_lang.h"

namespace skinsim::driver {

struct ExportedFrame {
  nlohmann::json description;                // frame.json
  std::map<std::string, std::string> files;  // path relative to the export → contents
};

// Runs the frame job (without its reference) and records every pass the emulated GPU
// executes; `with_data` adds the binary payloads (frame_export_data.h).
ExportedFrame export_frame(FrameJob job, sim::sl::GlslDialect dialect, bool with_data);

// "es100" or "es300"; throws UserError naming the option otherwise.
sim::sl::GlslDialect parse_glsl_dialect(const std::string& name);
const char* glsl_dialect_name(sim::sl::GlslDialect dialect);

}  // namespace skinsim::driver
