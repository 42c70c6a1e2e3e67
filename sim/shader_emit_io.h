// The Emit language's inputs, outputs and texture unit (beside Exec's and Count's in
// shader_io.h): what a shader reads and writes is spelled as GLSL ES and recorded in a
// GlslInterface, from which glsl_shader.cpp declares the attributes, varyings, samplers and
// uniforms around the body.
//
// Varyings are the emulator's float slots packed four to a vec4, `v_slot0` holding slots
// 0-3: the vertex shader writes the slots it sets and the fragment shader reads the ones it
// uses, so the two always agree on the layout (and 20 slots fit GLES2's 8 varying vectors).
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <string>

#include "shading/shader_lang.h"
#include "sim/shader_io.h"
#include "sim/texture_unit.h"

namespace skinsim::sim {

enum class SamplerKind : std::uint8_t { kUnused, k2D, kCube, kShadow };
enum class VertexAttribute : std::uint8_t { kPosition, kNormal, kUv, kTangent, kThickness, kCount };

const char* attribute_name(VertexAttribute a);  // a_position, ...

// What one emitted shader body used.
struct GlslInterface {
  std::array<SamplerKind, kMaxTextureBindings> samplers{};  // by binding, named s0..s7
  std::bitset<static_cast<int>(VertexAttribute::kCount)> attributes;
  std::bitset<kMaxVaryings> varyings;  // slots written (vertex) or read (fragment)
  bool inverse_target_size = false;    // the uniform u_inv_target_size (screen_texcoord)
};

// Name of the vec4 varying holding `slot`, and the slot's component.
std::string varying_component(int slot);
// Lanes [slot, slot + n) of the packed varyings as one GLSL expression.
std::string varying_lanes(int slot, int n);

template <int N>
struct EmitVarying {
  sl::EVec<N> value;
};

class EmitFragIn {
 public:
  explicit EmitFragIn(GlslInterface* io) : io_(io) {}
  sl::EFloat f(int slot) const { return read<1>(slot); }
  sl::EVec<2> v2(int slot) const { return read<2>(slot); }
  sl::EVec<3> v3(int slot) const { return read<3>(slot); }
  sl::EVec<4> v4(int slot) const { return read<4>(slot); }
  EmitVarying<2> texcoord(int slot) const { return {read<2>(slot)}; }
  EmitVarying<3> direction(int slot) const { return {read<3>(slot)}; }
  sl::EVec<2> frag_coord() const { return sl::EVec<2>::named("gl_FragCoord.xy"); }
  // The screen-linear iterator of ExecFragIn::screen_texcoord, as GLSL computes it.
  EmitVarying<2> screen_texcoord() const {
    io_->inverse_target_size = true;
    return {sl::EVec<2>::computed("gl_FragCoord.xy * u_inv_target_size")};
  }

 private:
  template <int N>
  sl::EVec<N> read(int slot) const {
    for (int i = 0; i < N; ++i) io_->varyings.set(static_cast<size_t>(slot + i));
    return sl::EVec<N>::named(varying_lanes(slot, N));
  }
  GlslInterface* io_;
};

// Texture reads as GLSL ES spells them, matching ExecTexUnit's choices: a varying read
// takes its LOD from derivatives (texture2D); a computed coordinate reads LOD 0 unless
// given one (texture2DLodEXT, as ExecTexUnit::sample(int, vec2) does).
class EmitTexUnit {
 public:
  explicit EmitTexUnit(GlslInterface* io) : io_(io) {}
  sl::EVec<4> sample(int binding, const EmitVarying<2>& uv) const;
  sl::EVec<4> sample(int binding, const sl::EVec<2>& uv) const {
    return sample_lod(binding, uv, sl::EFloat(0.0f));
  }
  sl::EVec<4> sample_lod(int binding, const sl::EVec<2>& uv, const sl::EFloat& lod) const;
  sl::EVec<4> sample_cube(int binding, const EmitVarying<3>& direction) const;
  sl::EVec<4> sample_cube_lod(int binding, const sl::EVec<3>& direction,
                              const sl::EFloat& lod) const;
  sl::EFloat sample_shadow(int binding, const EmitVarying<3>& coord) const {
    return sample_shadow(binding, coord.value);
  }
  sl::EFloat sample_shadow(int binding, const sl::EVec<3>& coord) const;

 private:
  std::string read(int binding, SamplerKind kind, const char* es100, const char* es300,
                   const char* extension, const std::string& arguments) const;
  GlslInterface* io_;
};

class EmitVertexIn {
 public:
  explicit EmitVertexIn(GlslInterface* io) : io_(io) {}
  sl::EVec<3> position() const { return read<3>(VertexAttribute::kPosition); }
  sl::EVec<3> normal() const { return read<3>(VertexAttribute::kNormal); }
  sl::EVec<2> uv() const { return read<2>(VertexAttribute::kUv); }
  sl::EVec<4> tangent() const { return read<4>(VertexAttribute::kTangent); }
  sl::EFloat thickness() const { return read<1>(VertexAttribute::kThickness); }

 private:
  template <int N>
  sl::EVec<N> read(VertexAttribute a) const {
    io_->attributes.set(static_cast<size_t>(a));
    return sl::EVec<N>::named(attribute_name(a));
  }
  GlslInterface* io_;
};

struct EmitVertexOut {
  explicit EmitVertexOut(GlslInterface* io) : io_(io) {}
  sl::EVec<4> position;  // gl_Position, written once the body ends
  template <int N>
  void set(int slot, const sl::EVec<N>& v) {
    for (int i = 0; i < N; ++i) io_->varyings.set(static_cast<size_t>(slot + i));
    write_lanes(slot, N, v.expr);
  }

 private:
  void write_lanes(int slot, int n, const std::string& expr);
  GlslInterface* io_;
};

struct Emit {
  static constexpr bool kExecutes = false;
  using f32 = sl::EFloat;
  using vec2 = sl::EVec<2>;
  using vec3 = sl::EVec<3>;
  using vec4 = sl::EVec<4>;
  using FragIn = EmitFragIn;
  using TexUnit = EmitTexUnit;
  using VertexIn = EmitVertexIn;
  using VertexOut = EmitVertexOut;
};

// Whole shaders around an emitted body: version, extensions, precision, declarations of
// what `io` records, and main() ending with the body's result (gl_Position, the colour).
// Vertex shaders are highp (the GLSL ES vertex default); a fragment shader states its
// program's default precision.
std::string glsl_vertex_shader(const GlslInterface& io, const sl::GlslEmitter& body,
                               const std::string& position, sl::GlslDialect dialect);
std::string glsl_fragment_shader(const GlslInterface& io, const sl::GlslEmitter& body,
                                 const std::string& colour, sl::GlslDialect dialect,
                                 Precision precision);

}  // namespace skinsim::sim
