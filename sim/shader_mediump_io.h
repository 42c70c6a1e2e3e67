// The Exec language at mediump: what a fragment program whose default precision is mediump
// (`precision mediump float;`) computes on FP16 hardware. Its values are the recording type
// CVec (shader_lang.h), which rounds every value it makes to FP16 inside a mediump
// PrecisionScope; with no OpRecorder live it records nothing, so it is an FP16 interpreter
// of the unchanged shader code. The adapters here hand it the Exec inputs and texture unit.
//
// Independent texture reads fetch at the iterators' full precision: the hardware issues
// them before the program runs (hardware.md, "dependent reads"), so the program's precision
// does not reach their coordinates; the value the program itself reads is rounded.
// Computed coordinates are mediump values like any other.
#pragma once

#include "sim/shader_io.h"

namespace skinsim::sim {

// A varying as a mediump program sees it: value and derivatives rounded to FP16, and the
// iterated coordinates an independent read fetches with.
template <int N>
struct MediumpVarying {
  sl::CVec<N> value;
  sl::CVec<N> ddx;
  sl::CVec<N> ddy;
  Varying<N> iterated;

  explicit MediumpVarying(const Varying<N>& v)
      : value(sl::CVec<N>::computed(v.value)),
        ddx(sl::CVec<N>::computed(v.ddx)),
        ddy(sl::CVec<N>::computed(v.ddy)),
        iterated(v) {}
};

// scaled() for a mediump varying: the iterated coordinates are scaled (texture_unit.h), and
// the program sees them rounded, as for any varying.
inline MediumpVarying<2> scaled(const MediumpVarying<2>& uv, float s) {
  return MediumpVarying<2>(scaled(uv.iterated, s));
}

class MediumpFragIn {
 public:
  explicit MediumpFragIn(const ExecFragIn& in) : in_(in) {}
  sl::CFloat f(int slot) const { return sl::CFloat::computed(glm::vec1(in_.f(slot))); }
  sl::CVec<2> v2(int slot) const { return sl::CVec<2>::computed(in_.v2(slot)); }
  sl::CVec<3> v3(int slot) const { return sl::CVec<3>::computed(in_.v3(slot)); }
  sl::CVec<4> v4(int slot) const { return sl::CVec<4>::computed(in_.v4(slot)); }
  MediumpVarying<2> texcoord(int slot) const { return MediumpVarying<2>(in_.texcoord(slot)); }
  MediumpVarying<3> direction(int slot) const { return MediumpVarying<3>(in_.direction(slot)); }
  MediumpVarying<2> screen_texcoord() const { return MediumpVarying<2>(in_.screen_texcoord()); }
  sl::CVec<2> frag_coord() const { return sl::CVec<2>::computed(in_.frag_coord()); }

 private:
  const ExecFragIn& in_;
};

// Texture results come back at mediump (the sampler's value in an FP16 register).
class MediumpTexUnit {
 public:
  explicit MediumpTexUnit(ExecTexUnit& tex) : tex_(tex) {}
  sl::CVec<4> sample(int b, const MediumpVarying<2>& uv) { return v4(tex_.sample(b, uv.iterated)); }
  sl::CVec<4> sample(int b, const sl::CVec<2>& uv) { return v4(tex_.sample(b, uv.v)); }
  sl::CVec<4> sample_lod(int b, const sl::CVec<2>& uv, const sl::CFloat& lod) {
    return v4(tex_.sample_lod(b, uv.v, lod.v.x));
  }
  sl::CVec<4> sample_cube(int b, const MediumpVarying<3>& d) {
    return v4(tex_.sample_cube(b, d.iterated));
  }
  sl::CVec<4> sample_cube_lod(int b, const sl::CVec<3>& d, const sl::CFloat& lod) {
    return v4(tex_.sample_cube_lod(b, d.v, lod.v.x));
  }
  sl::CFloat sample_shadow(int b, const MediumpVarying<3>& coord) {
    return sl::CFloat::computed(glm::vec1(tex_.sample_shadow(b, coord.iterated)));
  }
  sl::CFloat sample_shadow(int b, const sl::CVec<3>& coord) {
    return sl::CFloat::computed(glm::vec1(tex_.sample_shadow(b, coord.v)));
  }

 private:
  static sl::CVec<4> v4(const glm::vec4& v) { return sl::CVec<4>::computed(v); }
  ExecTexUnit& tex_;
};

// Fragment programs only: vertex programs stay highp, the GLSL ES vertex default.
struct ExecMediump {
  static constexpr bool kExecutes = true;
  using f32 = sl::CFloat;
  using vec2 = sl::CVec<2>;
  using vec3 = sl::CVec<3>;
  using vec4 = sl::CVec<4>;
  using FragIn = MediumpFragIn;
  using TexUnit = MediumpTexUnit;
};

}  // namespace skinsim::sim
