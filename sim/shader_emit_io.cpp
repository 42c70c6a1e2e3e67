#include "sim/shader_emit_io.h"

#include <stdexcept>

namespace skinsim::sim {

namespace {

using sl::GlslDialect;
using sl::GlslEmitter;

constexpr const char* kLaneLetters = "xyzw";
constexpr const char* kTextureLod = "GL_EXT_shader_texture_lod";

std::string group_name(int group) {
  return "v_slot" + std::to_string(group);
}

// `slot`'s lanes in its group, e.g. ".zw" for slots 2-3; none for a whole vec4.
std::string group_lanes(int first_lane, int n) {
  std::string s;
  if (n < 4) s.append(".").append(kLaneLetters + first_lane, static_cast<size_t>(n));
  return s;
}

bool es3(GlslDialect d) {
  return d == GlslDialect::kEs300;
}

const char* sampler_type(SamplerKind kind) {
  switch (kind) {
    case SamplerKind::k2D:
      return "sampler2D";
    case SamplerKind::kCube:
      return "samplerCube";
    case SamplerKind::kShadow:
      return "sampler2DShadow";
    case SamplerKind::kUnused:
      break;
  }
  return "";
}

std::string header(GlslDialect d, const std::set<std::string>& extensions, Precision precision) {
  std::string s = es3(d) ? "#version 300 es\n" : "#version 100\n";
  for (const std::string& e : extensions) s += "#extension " + e + " : require\n";
  return s + (precision == Precision::kMediump ? "precision mediump float;\n"
                                               : "precision highp float;\n");
}

// Declarations of the packed varyings any of whose slots `used` holds.
std::string varying_declarations(const std::bitset<kMaxVaryings>& used, const char* qualifier) {
  std::string s;
  for (int group = 0; group * 4 < kMaxVaryings; ++group) {
    bool any = false;
    for (int lane = 0; lane < 4 && group * 4 + lane < kMaxVaryings; ++lane) {
      any = any || used.test(static_cast<size_t>(group * 4 + lane));
    }
    if (any) s += std::string(qualifier) + " vec4 " + group_name(group) + ";\n";
  }
  return s;
}

std::string sampler_declarations(const GlslInterface& io) {
  std::string s;
  for (int b = 0; b < kMaxTextureBindings; ++b) {
    const SamplerKind kind = io.samplers[static_cast<size_t>(b)];
    if (kind == SamplerKind::kUnused) continue;
    // Shadow samplers have no default precision (EXT_shadow_samplers; GLSL ES 3.00 4.5.4).
    const char* precision = kind == SamplerKind::kShadow ? "lowp " : "";
    s +=
        std::string("uniform ") + precision + sampler_type(kind) + " s" + std::to_string(b) + ";\n";
  }
  return s;
}

}  // namespace

const char* attribute_name(VertexAttribute a) {
  switch (a) {
    case VertexAttribute::kPosition:
      return "a_position";
    case VertexAttribute::kNormal:
      return "a_normal";
    case VertexAttribute::kUv:
      return "a_uv";
    case VertexAttribute::kTangent:
      return "a_tangent";
    case VertexAttribute::kThickness:
      return "a_thickness";
    case VertexAttribute::kCount:
      break;
  }
  return "";
}

std::string varying_component(int slot) {
  return group_name(slot / 4) + "." + kLaneLetters[slot % 4];
}

std::string varying_lanes(int slot, int n) {
  if (n == 1) return varying_component(slot);
  const int first_group = slot / 4, last_group = (slot + n - 1) / 4;
  if (first_group == last_group) return group_name(first_group) + group_lanes(slot % 4, n);
  // Straddles two vec4s: a constructor of both parts.
  const int first_n = 4 - slot % 4;
  return "vec" + std::to_string(n) + "(" + group_name(first_group) +
         group_lanes(slot % 4, first_n) + ", " + group_name(last_group) +
         group_lanes(0, n - first_n) + ")";
}

void EmitVertexOut::write_lanes(int slot, int n, const std::string& expr) {
  for (int lane = 0; lane < n;) {
    const int s = slot + lane;
    const int run = std::min(n - lane, 4 - s % 4);  // lanes landing in s's vec4
    std::string value = expr;
    if (run < n) value += group_lanes(lane, run);
    GlslEmitter::statement(group_name(s / 4) + group_lanes(s % 4, run) + " = " + value + ";");
    lane += run;
  }
}

// Records `binding`'s sampler type and spells the read: `es100` and `es300` name the
// function in each dialect; `extension` is what ES 1.00 needs for it, if anything.
std::string EmitTexUnit::read(int binding, SamplerKind kind, const char* es100, const char* es300,
                              const char* extension, const std::string& arguments) const {
  if (binding < 0 || binding >= kMaxTextureBindings) {
    throw std::logic_error("texture binding " + std::to_string(binding) + " out of range");
  }
  SamplerKind& slot = io_->samplers[static_cast<size_t>(binding)];
  if (slot != SamplerKind::kUnused && slot != kind) {
    throw std::logic_error("texture binding " + std::to_string(binding) +
                           " is read as two sampler types");
  }
  slot = kind;
  if (extension) GlslEmitter::require_extension(extension);
  return std::string(es3(GlslEmitter::dialect()) ? es300 : es100) + "(s" + std::to_string(binding) +
         ", " + arguments + ")";
}

sl::EVec<4> EmitTexUnit::sample(int binding, const EmitVarying<2>& uv) const {
  return sl::EVec<4>::computed(
      read(binding, SamplerKind::k2D, "texture2D", "texture", nullptr, uv.value.expr));
}

sl::EVec<4> EmitTexUnit::sample_lod(int binding, const sl::EVec<2>& uv,
                                    const sl::EFloat& lod) const {
  return sl::EVec<4>::computed(read(binding, SamplerKind::k2D, "texture2DLodEXT", "textureLod",
                                    kTextureLod, uv.expr + ", " + lod.expr));
}

sl::EVec<4> EmitTexUnit::sample_cube(int binding, const EmitVarying<3>& direction) const {
  return sl::EVec<4>::computed(
      read(binding, SamplerKind::kCube, "textureCube", "texture", nullptr, direction.value.expr));
}

sl::EVec<4> EmitTexUnit::sample_cube_lod(int binding, const sl::EVec<3>& direction,
                                         const sl::EFloat& lod) const {
  return sl::EVec<4>::computed(read(binding, SamplerKind::kCube, "textureCubeLodEXT", "textureLod",
                                    kTextureLod, direction.expr + ", " + lod.expr));
}

sl::EFloat EmitTexUnit::sample_shadow(int binding, const sl::EVec<3>& coord) const {
  return sl::EFloat::computed(read(binding, SamplerKind::kShadow, "shadow2DEXT", "texture",
                                   "GL_EXT_shadow_samplers", coord.expr));
}

std::string glsl_vertex_shader(const GlslInterface& io, const sl::GlslEmitter& body,
                               const std::string& position, GlslDialect dialect) {
  std::string s = header(dialect, body.extensions(), Precision::kHighp);
  for (int a = 0; a < static_cast<int>(VertexAttribute::kCount); ++a) {
    if (!io.attributes.test(static_cast<size_t>(a))) continue;
    static constexpr const char* kTypes[] = {"vec3", "vec3", "vec2", "vec4", "float"};
    s += std::string(es3(dialect) ? "in " : "attribute ") + kTypes[a] + " " +
         attribute_name(static_cast<VertexAttribute>(a)) + ";\n";
  }
  s += varying_declarations(io.varyings, es3(dialect) ? "out" : "varying");
  s += sampler_declarations(io);
  return s + "void main() {\n" + body.body() + "  gl_Position = " + position + ";\n}\n";
}

std::string glsl_fragment_shader(const GlslInterface& io, const sl::GlslEmitter& body,
                                 const std::string& colour, GlslDialect dialect,
                                 Precision precision) {
  std::string s = header(dialect, body.extensions(), precision);
  s += varying_declarations(io.varyings, es3(dialect) ? "in" : "varying");
  if (io.inverse_target_size) s += "uniform vec2 u_inv_target_size;\n";
  s += sampler_declarations(io);
  if (es3(dialect)) s += "out vec4 frag_colour;\n";
  return s + "void main() {\n" + body.body() + "  " +
         (es3(dialect) ? "frag_colour" : "gl_FragColor") + " = " + colour + ";\n}\n";
}

}  // namespace skinsim::sim
