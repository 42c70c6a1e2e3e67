// The micro-benchmark shaders, in the emulator's shading language (shading/shader_lang.h). Each
// is minimal for what its benchmark stresses, so the op profile the emulator records is
// known by inspection (and checked by the tests).
#pragma once

#include <glm/glm.hpp>

#include "sim/program.h"

namespace skinsim::microbench::shaders {

namespace sl = sim::sl;

// Object-space position through a uniform matrix (4 vector MADs), no varyings: the
// parameter buffer holds positions only, as in a triangle-throughput test.
struct TransformVS {
  static constexpr const char* kName = "mb_transform_vs";
  struct Uniforms {
    glm::mat4 transform{1.0f};
  };
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    using vec4 = typename L::vec4;
    const auto p = in.position();
    out.position = u.transform * vec4(sl::x(p), sl::y(p), sl::z(p), 1.0f);
  }
};

// TransformVS plus the texture coordinates as varying 0-1.
struct TransformUvVS {
  static constexpr const char* kName = "mb_transform_uv_vs";
  using Uniforms = TransformVS::Uniforms;
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    TransformVS::vertex<L>(in, out, u);
    out.set(0, in.uv());
  }
};

// One independent texture read, returned as is: one texture issue slot, no ALU op.
struct TextureReadFS {
  static constexpr const char* kName = "mb_texture_read_fs";
  struct Uniforms {};
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms&) {
    return tex.sample(0, in.texcoord(0));
  }
};

// A constant colour: no ALU op, no texture read.
struct FlatColorFS {
  static constexpr const char* kName = "mb_flat_color_fs";
  struct Uniforms {
    glm::vec4 color{1.0f};
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn&, typename L::TexUnit&,
                                   const Uniforms& u) {
    return typename L::vec4(u.color);
  }
};

// A dependent chain of `vector_ops` vec4 multiply-adds on an interpolated input: exactly
// `vector_ops` vector instructions (each multiply fuses into the add that follows it), 8 FLOP
// each. The uniform trip count is unrolled like a compile-time loop bound.
struct MadChainFS {
  static constexpr const char* kName = "mb_mad_chain_fs";
  struct Uniforms {
    int vector_ops = 64;
    glm::vec4 scale{0.999f, 0.998f, 0.997f, 0.996f};  // keeps the chain bounded
    glm::vec4 bias{0.001f, 0.002f, 0.003f, 0.004f};
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit&,
                                   const Uniforms& u) {
    using vec4 = typename L::vec4;
    const auto t = in.v2(0);
    vec4 v(sl::x(t), sl::y(t), sl::x(t), sl::y(t));
    for (int i = 0; i < u.vector_ops; ++i) v = v * u.scale + u.bias;
    return v;
  }
};

}  // namespace skinsim::microbench::shaders
