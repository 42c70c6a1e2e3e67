// The Emit language's interface: packed varyings, texture reads by dialect, and whole programs
// emitted through the same wrappers the renderer runs.
#include <gtest/gtest.h>

#include "sim/program.h"

namespace skinsim::sim {
namespace {

using sl::GlslDialect;

TEST(ShaderEmitIo, VaryingSlotsPackFourToAVec4AndStraddleWithAConstructor) {
  EXPECT_EQ(varying_lanes(0, 3), "v_slot0.xyz");
  EXPECT_EQ(varying_lanes(4, 4), "v_slot1");
  EXPECT_EQ(varying_lanes(6, 1), "v_slot1.z");
  EXPECT_EQ(varying_lanes(3, 3), "vec3(v_slot0.w, v_slot1.xy)");
  EXPECT_EQ(varying_lanes(10, 4), "vec4(v_slot2.zw, v_slot3.xy)");
}

TEST(ShaderEmitIo, AVertexOutputStraddlingTwoVec4sIsWrittenInTwoParts) {
  sl::GlslEmitter emitter;
  GlslInterface io;
  EmitVertexOut out(&io);
  out.set(3, sl::EVec<3>::named("t0"));
  EXPECT_EQ(emitter.body(), "  v_slot0.w = t0.x;\n  v_slot1.xy = t0.yz;\n");
  EXPECT_EQ(io.varyings.to_ulong(), 0b111000u);
}

// A shader of each kind of read, as the pipeline's shaders are written.
struct ReadsFS {
  static constexpr const char* kName = "reads_fs";
  struct Uniforms {};
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms&) {
    const auto a = tex.sample(0, in.texcoord(0));          // independent: implicit LOD
    const auto b = tex.sample(1, in.v2(2) * 2.0f);         // dependent: LOD 0, as Exec reads
    const auto c = tex.sample_shadow(2, in.direction(4));  // depth compare
    const auto d = tex.sample(3, in.screen_texcoord());    // a screen-space buffer
    return a + b * c + d;
  }
};

struct PassVS {
  static constexpr const char* kName = "pass_vs";
  struct Uniforms {};
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out, const Uniforms&) {
    using vec4 = typename L::vec4;
    out.position = vec4(in.position(), 1.0f);
    out.set(0, in.uv());
  }
};

TEST(ShaderEmitIo, TextureReadsAreSpelledForEachDialectWithTheExtensionsEs100Needs) {
  const auto fs = make_fragment_program<ReadsFS>({});
  const GlslShader es100 = fs->glsl(GlslDialect::kEs100);
  EXPECT_NE(es100.source.find("#extension GL_EXT_shader_texture_lod : require"), std::string::npos);
  EXPECT_NE(es100.source.find("#extension GL_EXT_shadow_samplers : require"), std::string::npos);
  EXPECT_NE(es100.source.find("texture2D(s0, v_slot0.xy)"), std::string::npos);
  EXPECT_NE(es100.source.find("texture2DLodEXT(s1, "), std::string::npos);
  EXPECT_NE(es100.source.find("shadow2DEXT(s2, v_slot1.xyz)"), std::string::npos);
  EXPECT_NE(es100.source.find("gl_FragColor = "), std::string::npos);
  EXPECT_TRUE(es100.interface.inverse_target_size);
  EXPECT_EQ(es100.interface.samplers[2], SamplerKind::kShadow);

  const GlslShader es300 = fs->glsl(GlslDialect::kEs300);
  EXPECT_EQ(es300.source.find("#extension"), std::string::npos);  // all core in ES 3.0
  EXPECT_NE(es300.source.find("textureLod(s1, "), std::string::npos);
  EXPECT_NE(es300.source.find("out vec4 frag_colour;"), std::string::npos);
}

TEST(ShaderEmitIo, AVertexProgramDeclaresOnlyTheAttributesAndVaryingsItUses) {
  const GlslShader vs = make_vertex_program<PassVS>({})->glsl(GlslDialect::kEs100);
  EXPECT_EQ(vs.source,
            "#version 100\n"
            "precision highp float;\n"
            "attribute vec3 a_position;\n"
            "attribute vec2 a_uv;\n"
            "varying vec4 v_slot0;\n"
            "void main() {\n"
            "  v_slot0.xy = a_uv;\n"
            "  gl_Position = vec4(a_position, 1.0);\n"
            "}\n");
}

}  // namespace
}  // namespace skinsim::sim
