// Shader programs as the GPU runs them. A shader is a struct with a name, a Uniforms type
// and templated `vertex`/`fragment` functions (see pipeline/shaders/); the wrappers here
// instantiate it for execution, record its op profile once and emit it as GLSL ES on
// request, all from the same code.
#pragma once

#include <algorithm>
#include <memory>
#include <string>

#include "shading/op_profile.h"
#include "sim/shader_io.h"

namespace skinsim::sim {

// A program as GLSL ES source, with what it declares (attributes, samplers, uniforms).
struct GlslShader {
  std::string source;
  GlslInterface interface;
};

class VertexProgram {
 public:
  virtual ~VertexProgram() = default;
  const std::string& name() const { return name_; }
  const OpProfile& profile() const { return profile_; }
  // Varying floats this program writes per vertex (the parameter-buffer payload).
  int varying_floats() const { return varying_floats_; }
  virtual void run(const ExecVertexIn& in, ExecVertexOut& out) const = 0;
  // The same program as GLSL ES source, uniforms inlined as constants (docs/shaders.md).
  virtual GlslShader glsl(sl::GlslDialect dialect) const = 0;

 protected:
  std::string name_;
  OpProfile profile_;
  int varying_floats_ = 0;
};

class FragmentProgram {
 public:
  virtual ~FragmentProgram() = default;
  const std::string& name() const { return name_; }
  const OpProfile& profile() const { return profile_; }
  virtual glm::vec4 shade(const ExecFragIn& in, ExecTexUnit& tex) const = 0;
  // Four fragments of one draw at once (the lanes of `in`; those past tex.fragments() are
  // padding): per lane exactly what shade() gives.
  virtual sl::Lanes<4> shade4(const Exec4FragIn& in, Exec4TexUnit& tex) const = 0;
  virtual GlslShader glsl(sl::GlslDialect dialect) const = 0;

 protected:
  std::string name_;
  OpProfile profile_;
};

// Shader requirements: `static constexpr const char* kName`, `struct Uniforms`, and
//   template <class L> static void vertex(const typename L::VertexIn&,
//                                         typename L::VertexOut&, const Uniforms&);
template <class Shader>
class VertexProgramOf final : public VertexProgram {
 public:
  explicit VertexProgramOf(typename Shader::Uniforms uniforms) : uniforms_(std::move(uniforms)) {
    name_ = Shader::kName;
    CountVertexIn in;
    CountVertexOut out;
    {
      sl::OpRecorder recorder(&profile_);
      Shader::template vertex<Count>(in, out, uniforms_);
    }
    varying_floats_ = out.highest_slot;
    profile_.output_floats = 4 + static_cast<std::uint32_t>(varying_floats_);
  }
  void run(const ExecVertexIn& in, ExecVertexOut& out) const override {
    Shader::template vertex<Exec>(in, out, uniforms_);
  }
  GlslShader glsl(sl::GlslDialect dialect) const override {
    sl::GlslEmitter body(dialect);
    GlslInterface io;
    EmitVertexIn in(&io);
    EmitVertexOut out(&io);
    Shader::template vertex<Emit>(in, out, uniforms_);
    return {glsl_vertex_shader(io, body, out.position.expr, dialect), io};
  }

 private:
  typename Shader::Uniforms uniforms_;
};

//   template <class L> static typename L::vec4 fragment(const typename L::FragIn&,
//                                                       typename L::TexUnit&, const Uniforms&);
// kPrecision is the program's default precision (`precision mediump float;`): a mediump
// program runs in the ExecMediump language, its ops are counted as mediump, its source says
// so, and its name ends in "_mediump".
template <class Shader, Precision kPrecision = Precision::kHighp>
class FragmentProgramOf final : public FragmentProgram {
 public:
  explicit FragmentProgramOf(typename Shader::Uniforms uniforms) : uniforms_(std::move(uniforms)) {
    name_ = std::string(Shader::kName) + (kPrecision == Precision::kMediump ? "_mediump" : "");
    CountFragIn in;
    CountTexUnit tex;
    {
      sl::PrecisionScope precision(kPrecision);
      sl::OpRecorder recorder(&profile_);
      Shader::template fragment<Count>(in, tex, uniforms_);
    }
    profile_.output_floats = 4;
  }
  glm::vec4 shade(const ExecFragIn& in, ExecTexUnit& tex) const override {
    if constexpr (kPrecision == Precision::kHighp) {
      return Shader::template fragment<Exec>(in, tex, uniforms_);
    } else {
      sl::PrecisionScope precision(kPrecision);
      MediumpFragIn mediump_in(in);
      MediumpTexUnit mediump_tex(tex);
      return Shader::template fragment<ExecMediump>(mediump_in, mediump_tex, uniforms_).v;
    }
  }
  sl::Lanes<4> shade4(const Exec4FragIn& in, Exec4TexUnit& tex) const override {
    if constexpr (kPrecision == Precision::kHighp) {
      return Shader::template fragment<Exec4>(in, tex, uniforms_);
    } else {
      sl::Lanes<4> r;
      for (int l = 0; l < tex.fragments(); ++l) r.set_lane(l, shade(in.lane(l), tex.lane(l)));
      return r;
    }
  }
  GlslShader glsl(sl::GlslDialect dialect) const override {
    sl::GlslEmitter body(dialect);
    GlslInterface io;
    EmitFragIn in(&io);
    EmitTexUnit tex(&io);
    const sl::EVec<4> colour = Shader::template fragment<Emit>(in, tex, uniforms_);
    return {glsl_fragment_shader(io, body, colour.expr, dialect, kPrecision), io};
  }

 private:
  typename Shader::Uniforms uniforms_;
};

template <class Shader>
std::shared_ptr<const VertexProgram> make_vertex_program(typename Shader::Uniforms u) {
  return std::make_shared<VertexProgramOf<Shader>>(std::move(u));
}
template <class Shader>
std::shared_ptr<const FragmentProgram> make_fragment_program(typename Shader::Uniforms u) {
  return std::make_shared<FragmentProgramOf<Shader>>(std::move(u));
}
// The program at a precision chosen at run time (a knob); instantiates both.
template <class Shader>
std::shared_ptr<const FragmentProgram> make_fragment_program(typename Shader::Uniforms u,
                                                             Precision precision) {
  if (precision == Precision::kMediump) {
    return std::make_shared<FragmentProgramOf<Shader, Precision::kMediump>>(std::move(u));
  }
  return make_fragment_program<Shader>(std::move(u));
}

}  // namespace skinsim::sim
