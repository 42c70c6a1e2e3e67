// The static cost of one shader invocation, derived by running the shader's own code with
// counting types (shader_lang.h), the way an offline shader compiler reports instruction
// counts (PVRShaderEditor, Mali Offline Compiler).
#pragma once

#include <cstdint>
#include <string>

namespace skinsim::sim {

// The default float precision a program runs at, as a GLSL ES fragment shader states it
// (`precision mediump float;`): highp is FP32, mediump FP16 (shading/fp16.h).
enum class Precision : std::uint8_t { kHighp, kMediump };

struct OpProfile {
  // ALU instructions by class. A vector op works on 2-4 lanes in one instruction; a fused
  // multiply-add counts once (see shader_lang.h for the fusion rule).
  std::uint32_t vector_ops = 0;
  std::uint32_t scalar_ops = 0;
  // Special-function ops: exp2, log2, rsqrt, sqrt, reciprocal, sin, cos.
  std::uint32_t transcendental_ops = 0;
  // Of the ALU ops above, those at mediump (a program's default precision applies to all
  // its ops), which a device may issue at another rate (gpu_model: alu.mediump_op_cost).
  std::uint32_t vector_ops_mediump = 0;
  std::uint32_t scalar_ops_mediump = 0;
  std::uint32_t transcendental_ops_mediump = 0;
  // Texture reads. Independent: coordinates are a varying used unmodified, so the fetch can
  // be issued before the program runs. Dependent: coordinates computed in the shader.
  std::uint32_t texture_reads_independent = 0;
  std::uint32_t texture_reads_dependent = 0;
  // Interpolated inputs (floats) the program reads; vertex programs: attribute floats read.
  std::uint32_t input_floats = 0;
  // Output floats written (vertex programs: position + varyings).
  std::uint32_t output_floats = 0;

  std::uint32_t alu_ops() const { return vector_ops + scalar_ops + transcendental_ops; }
  std::uint32_t texture_reads() const {
    return texture_reads_independent + texture_reads_dependent;
  }
  bool operator==(const OpProfile&) const = default;
};

struct NamedProfile {
  std::string name;
  OpProfile profile;
};

}  // namespace skinsim::sim
