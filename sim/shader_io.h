// What a shader sees: its inputs (vertex attributes or interpolated varyings), its outputs
// and the texture unit, in the two "languages" of shader_lang.h. Exec types do the work;
// Count types record it.
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <utility>

#include "shading/shader_lang.h"
#include "sim/texture_unit.h"
#include "sim/triangle_setup.h"
#include "util/check.h"

namespace skinsim::sim {

constexpr int kMaxVaryings = 20;  // floats per vertex after position

// ------------------------------------------------------------------ Exec mode
// Interpolated inputs of one fragment. Varyings are evaluated on demand, so a program pays
// (on the host) only for the inputs it reads.
class ExecFragIn {
 public:
  ExecFragIn(const Plane* varying_planes, const Plane& inv_w, float rel_x, float rel_y,
             glm::vec2 frag_coord, glm::vec2 inv_target_size)
      : planes_(varying_planes),
        inv_w_(inv_w),
        rx_(rel_x),
        ry_(rel_y),
        w_(1.0f / inv_w.at(rel_x, rel_y)),
        frag_coord_(frag_coord),
        inv_size_(inv_target_size) {}

  float f(int slot) const {
    SKINSIM_DCHECK_INDEX(slot, kMaxVaryings);
    return planes_[slot].at(rx_, ry_) * w_;
  }
  glm::vec2 v2(int slot) const { return {f(slot), f(slot + 1)}; }
  glm::vec3 v3(int slot) const { return {f(slot), f(slot + 1), f(slot + 2)}; }
  glm::vec4 v4(int slot) const { return {f(slot), f(slot + 1), f(slot + 2), f(slot + 3)}; }
  // A varying used directly as texture coordinates: value plus screen-space derivatives.
  Varying<2> texcoord(int slot) const { return grad<2>(slot); }
  Varying<3> direction(int slot) const { return grad<3>(slot); }
  // Pixel centre in render-target pixels (gl_FragCoord.xy).
  glm::vec2 frag_coord() const { return frag_coord_; }
  // Screen position in [0,1]^2 from a screen-linear iterator (a `noperspective` varying):
  // usable as independent texture coordinates for reading a screen-space buffer.
  Varying<2> screen_texcoord() const {
    Varying<2> r;
    r.value = frag_coord_ * inv_size_;
    r.ddx = {inv_size_.x, 0.0f};
    r.ddy = {0.0f, inv_size_.y};
    return r;
  }

 private:
  template <int N>
  [[gnu::always_inline]] Varying<N> grad(int slot) const {
    SKINSIM_DCHECK(slot >= 0 && slot + N <= kMaxVaryings);
    Varying<N> r;
    for (int i = 0; i < N; ++i) {
      const Plane& p = planes_[slot + i];
      const float u = p.at(rx_, ry_) * w_;
      r.value[i] = u;
      // d(A/B)/dx = (A_x - u B_x) / B with A = u/w, B = 1/w.
      r.ddx[i] = (p.dx - u * inv_w_.dx) * w_;
      r.ddy[i] = (p.dy - u * inv_w_.dy) * w_;
    }
    return r;
  }

  const Plane* planes_;
  const Plane& inv_w_;
  float rx_, ry_, w_;
  glm::vec2 frag_coord_;
  glm::vec2 inv_size_;
};

struct VertexAttributes {
  const glm::vec3* positions = nullptr;
  const glm::vec3* normals = nullptr;
  const glm::vec2* uvs = nullptr;
  const glm::vec4* tangents = nullptr;
  const float* thickness = nullptr;  // baked per-vertex thickness (mm), for transmission
};

class ExecVertexIn {
 public:
  ExecVertexIn(const VertexAttributes& a, std::uint32_t index) : a_(a), i_(index) {}
  glm::vec3 position() const { return a_.positions[i_]; }
  glm::vec3 normal() const { return a_.normals ? a_.normals[i_] : glm::vec3(0, 0, 1); }
  glm::vec2 uv() const { return a_.uvs ? a_.uvs[i_] : glm::vec2(0.0f); }
  glm::vec4 tangent() const { return a_.tangents ? a_.tangents[i_] : glm::vec4(1, 0, 0, 1); }
  // No baked thickness: thick everywhere (nothing transmitted).
  float thickness() const { return a_.thickness ? a_.thickness[i_] : 1e3f; }

 private:
  const VertexAttributes& a_;
  std::uint32_t i_;
};

struct ExecVertexOut {
  glm::vec4 position{0.0f};  // clip space
  float varyings[kMaxVaryings] = {};
  void set(int slot, float v) {
    SKINSIM_DCHECK_INDEX(slot, kMaxVaryings);
    varyings[slot] = v;
  }
  template <int N>
  void set(int slot, const glm::vec<N, float>& v) {
    SKINSIM_DCHECK(slot >= 0 && slot + N <= kMaxVaryings);
    for (int i = 0; i < N; ++i) varyings[slot + i] = v[i];
  }
};

// kExecutes: the language computes the image (Exec, ExecMediump), as opposed to recording
// the profile (Count) or spelling the source (Emit).
struct Exec {
  static constexpr bool kExecutes = true;
  using f32 = float;
  using vec2 = glm::vec2;
  using vec3 = glm::vec3;
  using vec4 = glm::vec4;
  using FragIn = ExecFragIn;
  using TexUnit = ExecTexUnit;
  using VertexIn = ExecVertexIn;
  using VertexOut = ExecVertexOut;
};

// ------------------------------------------------------------------ Count mode
template <int N>
struct CountVarying {
  sl::CVec<N> value;
};

// Inputs read from interpolators cost no ALU op; their values are arbitrary mid-range
// numbers (the profile does not depend on them: shaders are branch-free).
class CountFragIn {
 public:
  sl::CFloat f(int) const { return input<1>(); }
  sl::CVec<2> v2(int) const { return input<2>(); }
  sl::CVec<3> v3(int) const { return input<3>(); }
  sl::CVec<4> v4(int) const { return input<4>(); }
  CountVarying<2> texcoord(int) const { return {input<2>()}; }
  CountVarying<3> direction(int) const { return {input<3>()}; }
  CountVarying<2> screen_texcoord() const { return {input<2>()}; }
  sl::CVec<2> frag_coord() const { return sl::CVec<2>::computed(glm::vec2(0.5f)); }

 private:
  template <int N>
  static sl::CVec<N> input() {
    sl::OpRecorder::input(N);
    return sl::CVec<N>::computed(glm::vec<N, float>(0.5f));
  }
};

class CountTexUnit {
 public:
  sl::CVec<4> sample(int, const CountVarying<2>&) const { return fetch(false); }
  sl::CVec<4> sample(int, const sl::CVec<2>&) const { return fetch(true); }
  sl::CVec<4> sample_lod(int, const sl::CVec<2>&, const sl::CFloat&) const { return fetch(true); }
  sl::CVec<4> sample_cube(int, const CountVarying<3>&) const { return fetch(false); }
  sl::CVec<4> sample_cube_lod(int, const sl::CVec<3>&, const sl::CFloat&) const {
    return fetch(true);
  }
  sl::CFloat sample_shadow(int, const CountVarying<3>&) const { return compare(false); }
  sl::CFloat sample_shadow(int, const sl::CVec<3>&) const { return compare(true); }

 private:
  static sl::CVec<4> fetch(bool dependent) {
    sl::OpRecorder::texture(dependent);
    return sl::CVec<4>::computed(glm::vec4(0.5f));
  }
  static sl::CFloat compare(bool dependent) {
    sl::OpRecorder::texture(dependent);
    return sl::CFloat::computed(glm::vec<1, float>(0.5f));
  }
};

class CountVertexIn {
 public:
  sl::CVec<3> position() const { return input<3>(); }
  sl::CVec<3> normal() const { return input<3>(); }
  sl::CVec<2> uv() const { return input<2>(); }
  sl::CVec<4> tangent() const { return input<4>(); }
  sl::CFloat thickness() const { return input<1>(); }

 private:
  template <int N>
  static sl::CVec<N> input() {
    sl::OpRecorder::input(N);
    return sl::CVec<N>::computed(glm::vec<N, float>(0.5f));
  }
};

struct CountVertexOut {
  sl::CVec<4> position;
  int highest_slot = 0;  // varying floats written = highest slot + 1
  void set(int slot, const sl::CFloat&) { note(slot, 1); }
  template <int N>
  void set(int slot, const sl::CVec<N>&) {
    note(slot, N);
  }

 private:
  void note(int slot, int n) { highest_slot = std::max(highest_slot, slot + n); }
};

struct Count {
  static constexpr bool kExecutes = false;
  using f32 = sl::CFloat;
  using vec2 = sl::CVec<2>;
  using vec3 = sl::CVec<3>;
  using vec4 = sl::CVec<4>;
  using FragIn = CountFragIn;
  using TexUnit = CountTexUnit;
  using VertexIn = CountVertexIn;
  using VertexOut = CountVertexOut;
};

// N reads of one texture, coord(i) the coordinates of the i-th (a varying, or computed ones, as
// tex.sample takes them), in order: in every language what N calls of tex.sample give, served
// together by a texture unit that can (ExecTexUnit::sample_each).
namespace sl {
template <int N, class TexUnit, class Coord>
auto sample_each(TexUnit& tex, int binding, const Coord& coord) {
  if constexpr (requires { tex.template sample_each<N>(binding, coord); }) {
    return tex.template sample_each<N>(binding, coord);
  } else {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      using Value = decltype(tex.sample(binding, coord(0)));
      return std::array<Value, N>{tex.sample(binding, coord(static_cast<int>(I)))...};
    }
    (std::make_index_sequence<N>{});  // a braced list: evaluated in order
  }
}
}  // namespace sl

}  // namespace skinsim::sim

// The third language, Emit, beside Exec and Count: every shader is written against all three;
// Exec at mediump, which runs them over Count's values in FP16; and Exec over four fragments.
#include "sim/shader_emit_io.h"     // IWYU pragma: export
#include "sim/shader_exec4_io.h"    // IWYU pragma: export
#include "sim/shader_mediump_io.h"  // IWYU pragma: export
