// The shading language of the emulated GPU: shaders are C++ templates over a "language" L,
// instantiated twice:
//   - sl::Exec: L::f32 = float, L::vec3 = glm::vec3 ... The renderer runs this one; it costs
//     nothing beyond the arithmetic itself.
//   - sl::Count: the same code over recording types. Running it once records every ALU op
//     and texture read into an OpProfile, the way an offline shader compiler reports the
//     instruction count of a program. Editing a shader therefore changes its cost.
//
// Counting rules (USSE2-like issue model; see docs/shaders.md):
//   - an arithmetic op on a 2-4 wide vector is one vector op; on a scalar, one scalar op;
//   - a multiply whose result feeds an add/sub is fused into one multiply-add (the add is
//     free), as every shader compiler of the era does;
//   - dot products are one vector op; swizzles, constructors, negation and abs are free;
//   - exp2, log2, sqrt, rsqrt, reciprocal (division), sin, cos are transcendental, one per
//     lane; pow = log2 + mul + exp2;
//   - ops whose operands are all uniforms/constants are folded (not counted);
//   - a program's ops are counted at its default precision (PrecisionScope), so the profile
//     says how many of them a device may issue at its mediump rate;
//   - texture reads: coordinates that are an interpolated varying used unmodified are
//     independent (fetched before the program runs, hardware.md "dependent reads"); any
//     computed coordinate, or an explicit LOD, makes the read dependent.
// Shaders are written branch-free (select/step/mix), as predicated GPU code is, so one
// recorded invocation is the profile of every invocation.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <type_traits>

#include "shading/fp16.h"
#include "shading/op_profile.h"

// A shader's fragment function, as every shader writes it: a template over the language L
// (Exec, Count, Emit ...) reading the interpolated inputs `in`, the texture unit `tex` and
// the shader's `Uniforms` `u`, returning the colour. Followed by the body. (The types are
// declared in sim/shader_io.h and the other *_io.h.)
#define SKINSIM_SL_FRAGMENT                                                                \
  template <class L>                                                                       \
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex, \
                                   const Uniforms& u)
// Language L's scalar and vector types under their GLSL names, in a shader function's body
// (each marked maybe_unused, as most functions use only some).
#define SKINSIM_SL_TYPES(L)                       \
  using f32 [[maybe_unused]] = typename L::f32;   \
  using vec2 [[maybe_unused]] = typename L::vec2; \
  using vec3 [[maybe_unused]] = typename L::vec3; \
  using vec4 [[maybe_unused]] = typename L::vec4

namespace skinsim::sim::sl {

// ---------------------------------------------------------------------------------------
// Default precision of the program being counted or run, the scope GLSL ES's
// `precision mediump float;` sets. At mediump every recorded value (CVec) is rounded to FP16
// when it is made, so a program run over CVec computes what FP16 hardware computes, and
// its ops are counted as mediump. Nests like OpRecorder.
class PrecisionScope {
 public:
  explicit PrecisionScope(Precision precision) : previous_(current_) { current_ = precision; }
  ~PrecisionScope() { current_ = previous_; }
  PrecisionScope(const PrecisionScope&) = delete;
  PrecisionScope& operator=(const PrecisionScope&) = delete;
  static Precision current() { return current_; }

 private:
  static inline thread_local Precision current_ = Precision::kHighp;
  Precision previous_;
};

template <int N>
inline glm::vec<N, float> at_current_precision(glm::vec<N, float> v) {
  if (PrecisionScope::current() == Precision::kMediump) {
    for (int i = 0; i < N; ++i) v[i] = round_to_fp16(v[i]);
  }
  return v;
}

// ---------------------------------------------------------------------------------------
// Op recording (Count mode only).
class OpRecorder {
 public:
  explicit OpRecorder(OpProfile* target) : previous_(current_) { current_ = target; }
  ~OpRecorder() { current_ = previous_; }
  OpRecorder(const OpRecorder&) = delete;
  OpRecorder& operator=(const OpRecorder&) = delete;

  static void alu(int lanes, int count = 1) {
    if (!current_) return;
    const bool mediump = PrecisionScope::current() == Precision::kMediump;
    if (lanes > 1) {
      current_->vector_ops += count;
      if (mediump) current_->vector_ops_mediump += count;
    } else {
      current_->scalar_ops += count;
      if (mediump) current_->scalar_ops_mediump += count;
    }
  }
  static void transcendental(int lanes) {
    if (!current_) return;
    current_->transcendental_ops += lanes;
    if (PrecisionScope::current() == Precision::kMediump) {
      current_->transcendental_ops_mediump += lanes;
    }
  }
  static void texture(bool dependent) {
    if (!current_) return;
    if (dependent) {
      ++current_->texture_reads_dependent;
    } else {
      ++current_->texture_reads_independent;
    }
  }
  static void input(int floats) {
    if (current_) current_->input_floats += floats;
  }
  static void output(int floats) {
    if (current_) current_->output_floats += floats;
  }

 private:
  static inline thread_local OpProfile* current_ = nullptr;
  OpProfile* previous_;
};

// Vector construction from parts: a vector is constant only if all its parts are.
template <int N>
struct CVec;
inline float raw(float f) {
  return f;
}
template <int N>
inline glm::vec<N, float> raw(const glm::vec<N, float>& v) {
  return v;
}
template <int N>
inline auto raw(const CVec<N>& c);
template <typename... Parts>
inline bool all_constant(const Parts&... parts);

// A recorded value: the real value at the current precision (so Count-mode runs compute
// real results, and a mediump program run over CVec computes in FP16) plus whether it is a
// constant (folded, free) and whether it is an unfused product.
template <int N>
struct CVec {
  using value_type = glm::vec<N, float>;
  value_type v{0.0f};
  bool constant = true;
  bool product = false;  // result of a multiply not yet fused into an add

  CVec() = default;
  CVec(const value_type& value)  // NOLINT: constants convert implicitly
      : v(at_current_precision<N>(value)) {}
  CVec(float s) requires(N == 1) : CVec(value_type(s)) {}  // NOLINT
  explicit CVec(float s) requires(N > 1) : CVec(value_type(s)) {}
  template <int M>
  requires(M == 1 && N > 1) explicit CVec(const CVec<M>& s) : v(s.v.x), constant(s.constant) {}
  template <typename... Parts>
  requires(sizeof...(Parts) >= 2) CVec(const Parts&... parts)
      : v(at_current_precision<N>(value_type(raw(parts)...))), constant(all_constant(parts...)) {}
  static CVec computed(const value_type& value, bool is_product = false) {
    CVec c(value);
    c.constant = false;
    c.product = is_product;
    return c;
  }
};
using CFloat = CVec<1>;

template <int N>
inline auto raw(const CVec<N>& c) {
  if constexpr (N == 1) {
    return c.v.x;
  } else {
    return c.v;
  }
}
template <typename T>
inline bool is_constant(const T& part) {
  if constexpr (std::is_arithmetic_v<T>) {
    return true;
  } else if constexpr (requires { part.constant; }) {
    return part.constant;
  } else {
    return true;  // glm constants
  }
}
template <typename... Parts>
inline bool all_constant(const Parts&... parts) {
  return (is_constant(parts) && ...);
}

namespace detail {
template <int N, int M>
constexpr int result_lanes() {
  return N > M ? N : M;
}
template <int N>
inline glm::vec<N, float> widen(const glm::vec<1, float>& s) {
  return glm::vec<N, float>(s.x);
}
template <int N>
inline glm::vec<N, float> widen(const glm::vec<N, float>& v) requires(N > 1) {
  return v;
}
}  // namespace detail

// Binary arithmetic between recorded values; a scalar operand broadcasts.
#define SKINSIM_SL_BINOP(op, is_mul, is_div)                                                  \
  template <int N, int M>                                                                     \
  inline CVec<detail::result_lanes<N, M>()> operator op(                                      \
      const CVec<N>& a, const CVec<M>& b) requires(N == M || N == 1 || M == 1) {              \
    constexpr int R = detail::result_lanes<N, M>();                                           \
    using V = glm::vec<R, float>;                                                             \
    const V av = detail::widen<R>(a.v), bv = detail::widen<R>(b.v);                           \
    const V r = av op bv;                                                                     \
    if (a.constant && b.constant) return CVec<R>(r);                                          \
    if (is_div) {                                                                             \
      OpRecorder::transcendental(M); /* reciprocal per divisor lane, then a multiply */       \
      OpRecorder::alu(R);                                                                     \
      return CVec<R>::computed(r, true);                                                      \
    }                                                                                         \
    if (!is_mul && (a.product || b.product)) return CVec<R>::computed(r); /* fused MAD */     \
    OpRecorder::alu(R);                                                                       \
    return CVec<R>::computed(r, is_mul);                                                      \
  }                                                                                           \
  template <int N>                                                                            \
  inline CVec<N> operator op(const CVec<N>& a, float b) {                                     \
    return a op CFloat(glm::vec1(b));                                                         \
  }                                                                                           \
  template <int N>                                                                            \
  inline CVec<N> operator op(float a, const CVec<N>& b) {                                     \
    return CFloat(glm::vec1(a)) op b;                                                         \
  }                                                                                           \
  template <int N>                                                                            \
  inline CVec<N> operator op(const CVec<N>& a, const glm::vec<N, float>& b) requires(N > 1) { \
    return a op CVec<N>(b);                                                                   \
  }                                                                                           \
  template <int N>                                                                            \
  inline CVec<N> operator op(const glm::vec<N, float>& a, const CVec<N>& b) requires(N > 1) { \
    return CVec<N>(a) op b;                                                                   \
  }

SKINSIM_SL_BINOP(+, false, false)
SKINSIM_SL_BINOP(-, false, false)
SKINSIM_SL_BINOP(*, true, false)
SKINSIM_SL_BINOP(/, false, true)
#undef SKINSIM_SL_BINOP

template <int N>
inline CVec<N> operator-(const CVec<N>& a) {  // source negation modifier: free
  CVec<N> r = a;
  r.v = -a.v;
  r.product = false;
  return r;
}

// ---------------------------------------------------------------------------------------
// Component access and construction. Free in both modes (register swizzles).
inline float x(float v) {
  return v;
}
template <int N>
inline float x(const glm::vec<N, float>& v) {
  return v.x;
}
template <int N>
inline float y(const glm::vec<N, float>& v) {
  return v.y;
}
template <int N>
inline float z(const glm::vec<N, float>& v) {
  return v.z;
}
template <int N>
inline float w(const glm::vec<N, float>& v) {
  return v.w;
}

template <int N>
inline CFloat component(const CVec<N>& v, int i) {
  CFloat r(glm::vec1(v.v[i]));
  r.constant = v.constant;
  return r;
}
template <int N>
inline CFloat x(const CVec<N>& v) {
  return component(v, 0);
}
template <int N>
inline CFloat y(const CVec<N>& v) {
  return component(v, 1);
}
template <int N>
inline CFloat z(const CVec<N>& v) {
  return component(v, 2);
}
template <int N>
inline CFloat w(const CVec<N>& v) {
  return component(v, 3);
}

inline glm::vec2 xy(const glm::vec3& v) {
  return {v.x, v.y};
}
inline glm::vec2 xy(const glm::vec4& v) {
  return {v.x, v.y};
}
inline glm::vec3 xyz(const glm::vec4& v) {
  return {v.x, v.y, v.z};
}
template <int N>
inline CVec<2> xy(const CVec<N>& v) {
  CVec<2> r(glm::vec2(v.v.x, v.v.y));
  r.constant = v.constant;
  return r;
}
inline CVec<3> xyz(const CVec<4>& v) {
  CVec<3> r(glm::vec3(v.v));
  r.constant = v.constant;
  return r;
}

// ---------------------------------------------------------------------------------------
// Built-in functions. Exec overloads forward to glm; Count overloads record.
template <int N>
inline float dot(const glm::vec<N, float>& a, const glm::vec<N, float>& b) {
  return glm::dot(a, b);
}
template <int N>
inline CFloat dot(const CVec<N>& a, const CVec<N>& b) {
  const CFloat r(glm::vec1(glm::dot(a.v, b.v)));
  if (a.constant && b.constant) return r;
  OpRecorder::alu(N);  // DP3/DP4 is a single vector instruction
  return CFloat::computed(r.v);
}
template <int N>
inline CFloat dot(const CVec<N>& a, const glm::vec<N, float>& b) {
  return dot(a, CVec<N>(b));
}
template <int N>
inline CFloat dot(const glm::vec<N, float>& a, const CVec<N>& b) {
  return dot(CVec<N>(a), b);
}

// Functions of one argument, per lane: on floats and vectors, and on Count values, where
// each lane costs one op of `kind` (OpRecorder::transcendental: a special-function op;
// OpRecorder::alu: one ALU instruction).
#define SKINSIM_SL_UNARY(name, expr, kind)                      \
  inline float name(float v) {                                  \
    return expr;                                                \
  }                                                             \
  template <int N>                                              \
  inline glm::vec<N, float> name(const glm::vec<N, float>& v) { \
    glm::vec<N, float> r;                                       \
    for (int i = 0; i < N; ++i) r[i] = name(v[i]);              \
    return r;                                                   \
  }                                                             \
  template <int N>                                              \
  inline CVec<N> name(const CVec<N>& a) {                       \
    glm::vec<N, float> r;                                       \
    for (int i = 0; i < N; ++i) r[i] = name(a.v[i]);            \
    if (a.constant) return CVec<N>(r);                          \
    OpRecorder::kind(N);                                        \
    return CVec<N>::computed(r);                                \
  }

SKINSIM_SL_UNARY(exp2, std::exp2(v), transcendental)
SKINSIM_SL_UNARY(log2, std::log2(v), transcendental)
SKINSIM_SL_UNARY(sqrt, std::sqrt(v), transcendental)
SKINSIM_SL_UNARY(rsqrt, 1.0f / std::sqrt(v), transcendental)
SKINSIM_SL_UNARY(rcp, 1.0f / v, transcendental)
SKINSIM_SL_UNARY(sin, std::sin(v), transcendental)
SKINSIM_SL_UNARY(cos, std::cos(v), transcendental)
// One-instruction ALU functions (min, max, clamp, saturate, step, floor, fract).
SKINSIM_SL_UNARY(saturate, glm::clamp(v, 0.0f, 1.0f), alu)
SKINSIM_SL_UNARY(floor, std::floor(v), alu)
SKINSIM_SL_UNARY(fract, v - std::floor(v), alu)
#undef SKINSIM_SL_UNARY

inline float abs(float v) {
  return std::fabs(v);
}
template <int N>
inline glm::vec<N, float> abs(const glm::vec<N, float>& v) {
  return glm::abs(v);
}
template <int N>
inline CVec<N> abs(const CVec<N>& a) {  // source modifier: free
  CVec<N> r = a;
  r.v = glm::abs(a.v);
  r.product = false;
  return r;
}

#define SKINSIM_SL_BINARY_ALU(name, fn)                                                         \
  inline float name(float a, float b) {                                                         \
    return fn(a, b);                                                                            \
  }                                                                                             \
  template <int N>                                                                              \
  inline glm::vec<N, float> name(const glm::vec<N, float>& a, const glm::vec<N, float>& b) {    \
    return fn(a, b);                                                                            \
  }                                                                                             \
  template <int N>                                                                              \
  inline glm::vec<N, float> name(const glm::vec<N, float>& a, float b) {                        \
    return fn(a, glm::vec<N, float>(b));                                                        \
  }                                                                                             \
  template <int N, int M>                                                                       \
  inline CVec<detail::result_lanes<N, M>()> name(const CVec<N>& a,                              \
                                                 const CVec<M>& b) requires(N == M || M == 1) { \
    constexpr int R = detail::result_lanes<N, M>();                                             \
    const glm::vec<R, float> r = fn(detail::widen<R>(a.v), detail::widen<R>(b.v));              \
    if (a.constant && b.constant) return CVec<R>(r);                                            \
    OpRecorder::alu(R);                                                                         \
    return CVec<R>::computed(r);                                                                \
  }                                                                                             \
  template <int N>                                                                              \
  inline CVec<N> name(const CVec<N>& a, float b) {                                              \
    return name(a, CFloat(glm::vec1(b)));                                                       \
  }                                                                                             \
  template <int N>                                                                              \
  inline CVec<N> name(float a, const CVec<N>& b) requires(N == 1) {                             \
    return name(CFloat(glm::vec1(a)), b);                                                       \
  }                                                                                             \
  template <int N>                                                                              \
  inline CVec<N> name(const CVec<N>& a, const glm::vec<N, float>& b) requires(N > 1) {          \
    return name(a, CVec<N>(b));                                                                 \
  }

namespace detail {
template <typename T>
inline T vmin(const T& a, const T& b) {
  return glm::min(a, b);
}
template <typename T>
inline T vmax(const T& a, const T& b) {
  return glm::max(a, b);
}
template <typename T>
inline T vstep(const T& edge, const T& x) {
  return glm::step(edge, x);
}
}  // namespace detail

SKINSIM_SL_BINARY_ALU(min, detail::vmin)
SKINSIM_SL_BINARY_ALU(max, detail::vmax)
SKINSIM_SL_BINARY_ALU(step, detail::vstep)
#undef SKINSIM_SL_BINARY_ALU

// Derived functions, written once for both modes so their cost follows from their code.
// Always inlined: over Exec4's lanes GCC left normalize an out-of-line call, its 48-byte
// operands passed through memory.
template <typename T, typename S>
[[gnu::always_inline]] inline T clamp(const T& v, const S& lo, const S& hi) {
  return min(max(v, lo), hi);
}
template <typename T, typename U, typename S>
[[gnu::always_inline]] inline T mix(const T& a, const U& b, const S& t) {
  return a + (b - a) * t;  // SUB + MAD
}
template <typename T>
[[gnu::always_inline]] inline auto length(const T& v) {
  return sqrt(dot(v, v));
}
template <typename T>
[[gnu::always_inline]] inline T normalize(const T& v) {
  return v * rsqrt(dot(v, v));
}
template <typename T, typename E>
[[gnu::always_inline]] inline auto pow(const T& base, const E& e) {
  return exp2(log2(base) * e);
}
inline constexpr float kLog2e = 1.4426950408889634f;
template <typename T>
[[gnu::always_inline]] inline T exp(const T& v) {
  return exp2(v * kLog2e);
}
template <typename T>
[[gnu::always_inline]] inline T reflect(const T& i, const T& n) {
  return i - n * (dot(n, i) * 2.0f);
}
inline glm::vec3 cross(const glm::vec3& a, const glm::vec3& b) {
  return glm::cross(a, b);
}
inline CVec<3> cross(const CVec<3>& a, const CVec<3>& b) {
  const glm::vec3 r = glm::cross(a.v, b.v);
  if (a.constant && b.constant) return CVec<3>(r);
  OpRecorder::alu(3, 2);  // MUL + MAD on swizzled operands
  return CVec<3>::computed(r);
}
// select(c, a, b): c > 0 ? a : b, one conditional-move instruction.
inline float select(float c, float a, float b) {
  return c > 0.0f ? a : b;
}
template <int N>
inline glm::vec<N, float> select(float c, const glm::vec<N, float>& a,
                                 const glm::vec<N, float>& b) {
  return c > 0.0f ? a : b;
}
template <int N>
inline CVec<N> select(const CFloat& c, const CVec<N>& a, const CVec<N>& b) {
  const glm::vec<N, float> r = c.v.x > 0.0f ? a.v : b.v;
  if (c.constant && a.constant && b.constant) return CVec<N>(r);
  OpRecorder::alu(N);
  return CVec<N>::computed(r);
}

}  // namespace skinsim::sim::sl

namespace skinsim::sim::sl {

// Matrix-vector products with a uniform matrix: one vector MAD per column.
inline CVec<4> operator*(const glm::mat4& m, const CVec<4>& v) {
  if (v.constant) return CVec<4>(m * v.v);
  OpRecorder::alu(4, 4);
  return CVec<4>::computed(m * v.v);
}
inline CVec<3> operator*(const glm::mat3& m, const CVec<3>& v) {
  if (v.constant) return CVec<3>(m * v.v);
  OpRecorder::alu(3, 3);
  return CVec<3>::computed(m * v.v);
}

}  // namespace skinsim::sim::sl

// The Emit instantiation's overloads (GLSL-emitting value types) must be visible
// wherever shaders are defined: they call the language qualified (`sl::max`), and a
// qualified call in a template finds only what is declared before the template.
#include "shading/shader_emit.h"  // IWYU pragma: export
// Likewise the four-fragment Exec4 instantiation's (shader_exec4_io.h).
#include "shading/shader_lanes.h"  // IWYU pragma: export
