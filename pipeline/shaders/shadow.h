// The shadow pass's only program: positions into the light's clip space. The pass has no
// colour target, so no fragment program runs (the ISP writes depth; render_pass.h).
#pragma once

#include <glm/glm.hpp>

#include "sim/shader_io.h"

namespace skinsim::pipeline::shaders {

struct ShadowVS {
  static constexpr const char* kName = "shadow_vs";
  struct Uniforms {
    glm::mat4 light_view_proj{1.0f};
  };
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    using vec4 = typename L::vec4;
    out.position = u.light_view_proj * vec4(in.position(), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders
