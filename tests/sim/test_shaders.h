// Minimal shaders for the emulator's own tests.
#pragma once

#include "microbench/shaders.h"
#include "sim/program.h"

namespace skinsim::sim::testing {

// Positions are already in clip space (z, w from the attribute; w = 1).
struct PassThroughVS {
  static constexpr const char* kName = "test_passthrough_vs";
  struct Uniforms {};
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out, const Uniforms&) {
    using vec4 = typename L::vec4;
    const auto p = in.position();
    out.position = vec4(sl::x(p), sl::y(p), sl::z(p), 1.0f);
    out.set(0, in.uv());
  }
};

// A constant colour, and one texture read returned as is: the micro-benchmarks' shaders.
using FlatColorFS = microbench::shaders::FlatColorFS;
using TexturedFS = microbench::shaders::TextureReadFS;

// One independent read, one dependent read, and some arithmetic with known op counts.
struct ProfileProbeFS {
  static constexpr const char* kName = "test_probe_fs";
  struct Uniforms {
    glm::vec3 light{0.0f, 0.0f, 1.0f};
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms& u) {
    using vec3 = typename L::vec3;
    const auto base = tex.sample(0, in.texcoord(0));              // independent
    const vec3 n = sl::normalize(in.v3(2));                       // dot + rsqrt + mul
    const auto ndotl = sl::saturate(sl::dot(n, vec3(u.light)));   // dot + sat
    const auto lut = tex.sample(1, sl::xy(base) * 0.5f + 0.25f);  // mad (fused), dependent
    return base * ndotl + lut;                                    // mad (fused)
  }
};

}  // namespace skinsim::sim::testing
