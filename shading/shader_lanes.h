// The Exec language over four fragments at once: each value is a structure of arrays,
// component i of the four fragments in one SSE register (Lanes<N>::c[i]). A shader run in
// this language (Exec4, shader_exec4_io.h) computes, lane by lane, exactly what the Exec
// language computes for each fragment alone: every operation is the same IEEE operation in
// the same order as the glm code it stands for (glm/detail/func_geometric.inl's dot and cross,
// func_common.inl's min/max/abs/step), packed operations round each lane as the scalar ones
// do, and the transcendentals call the same libm functions lane by lane. The build targets
// baseline x86-64 (SSE2, no FMA), so no multiply-add is contracted in either language.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

#include "util/float_lanes.h"

namespace skinsim::sim::sl {

inline constexpr int kLanes = 4;  // fragments per batch
using F4 = Float4;                // one component of the four fragments
using skinsim::splat;

template <int N>
struct Lanes;

namespace lanes_detail {
template <typename T>
struct Width;
template <>
struct Width<float> {
  static constexpr int value = 1;
};
template <int M>
struct Width<glm::vec<M, float>> {
  static constexpr int value = M;
};
template <int M>
struct Width<Lanes<M>> {
  static constexpr int value = M;
};
[[gnu::always_inline]] inline void put(F4* c, int& k, float s) {
  c[k++] = splat(s);
}
template <int M>
[[gnu::always_inline]] inline void put(F4* c, int& k, const glm::vec<M, float>& v) {
  for (int i = 0; i < M; ++i) c[k++] = splat(v[i]);
}
template <int M>
[[gnu::always_inline]] inline void put(F4* c, int& k, const Lanes<M>& v) {
  for (int i = 0; i < M; ++i) c[k++] = v.c[i];
}
}  // namespace lanes_detail

// N components of four fragments. Constants (floats, glm vectors of uniforms) convert as
// they do to glm's types: a float to a scalar implicitly, to a vector explicitly.
template <int N>
struct Lanes {
  F4 c[N];

  Lanes() : c{} {}
  Lanes(float s) requires(N == 1) : c{splat(s)} {}  // NOLINT: constants convert
  explicit Lanes(float s) requires(N > 1) {
    for (int i = 0; i < N; ++i) c[i] = splat(s);
  }
  Lanes(const glm::vec<N, float>& v) requires(N > 1) {  // NOLINT: uniforms convert
    for (int i = 0; i < N; ++i) c[i] = splat(v[i]);
  }
  template <int M>
  requires(M == 1 && N > 1) explicit Lanes(const Lanes<M>& s) {
    for (int i = 0; i < N; ++i) c[i] = s.c[0];
  }
  template <typename... Parts>
  requires(sizeof...(Parts) >= 2) Lanes(const Parts&... parts) {  // NOLINT: as glm's
    static_assert((lanes_detail::Width<Parts>::value + ...) == N, "components must add up");
    int k = 0;
    (lanes_detail::put(c, k, parts), ...);
  }

  // Lane `l` as the Exec language holds it.
  auto lane(int l) const {
    if constexpr (N == 1) {
      return c[0][l];
    } else {
      glm::vec<N, float> v;
      for (int i = 0; i < N; ++i) v[i] = c[i][l];
      return v;
    }
  }
  void set_lane(int l, const glm::vec<N, float>& v) {
    for (int i = 0; i < N; ++i) c[i][l] = v[i];
  }
  void set_lane(int l, float v) requires(N == 1) { c[0][l] = v; }
};
using LFloat = Lanes<1>;

// ---------------------------------------------------------------------------------------
// Arithmetic: element-wise, a scalar operand broadcast over a vector's components (glm's
// vec op scalar), constants converted.
namespace lanes_detail {
constexpr int result_width(int n, int m) {
  return n > m ? n : m;
}
template <int N>
[[gnu::always_inline]] inline const F4& part(const Lanes<N>& v, int i) {
  return v.c[N == 1 ? 0 : i];
}
}  // namespace lanes_detail

#define SKINSIM_SL_LANES_BINOP(op)                                                        \
  template <int N, int M>                                                                 \
  [[gnu::always_inline]] inline Lanes<lanes_detail::result_width(N, M)> operator op(      \
      const Lanes<N>& a, const Lanes<M>& b) requires(N == M || N == 1 || M == 1) {        \
    constexpr int R = lanes_detail::result_width(N, M);                                   \
    Lanes<R> r;                                                                           \
    for (int i = 0; i < R; ++i) {                                                         \
      r.c[i] = lanes_detail::part(a, i) op lanes_detail::part(b, i);                      \
    }                                                                                     \
    return r;                                                                             \
  }                                                                                       \
  template <int N>                                                                        \
  [[gnu::always_inline]] inline Lanes<N> operator op(const Lanes<N>& a, float b) {        \
    return a op LFloat(b);                                                                \
  }                                                                                       \
  template <int N>                                                                        \
  [[gnu::always_inline]] inline Lanes<N> operator op(float a, const Lanes<N>& b) {        \
    return LFloat(a) op b;                                                                \
  }                                                                                       \
  template <int N>                                                                        \
  [[gnu::always_inline]] inline Lanes<N> operator op(                                     \
      const Lanes<N>& a, const glm::vec<N, float>& b) requires(N > 1) {                   \
    return a op Lanes<N>(b);                                                              \
  }                                                                                       \
  template <int N>                                                                        \
  [[gnu::always_inline]] inline Lanes<N> operator op(const glm::vec<N, float>& a,         \
                                                     const Lanes<N>& b) requires(N > 1) { \
    return Lanes<N>(a) op b;                                                              \
  }

SKINSIM_SL_LANES_BINOP(+)
SKINSIM_SL_LANES_BINOP(-)
SKINSIM_SL_LANES_BINOP(*)
SKINSIM_SL_LANES_BINOP(/)
#undef SKINSIM_SL_LANES_BINOP

template <int N>
[[gnu::always_inline]] inline Lanes<N> operator-(const Lanes<N>& a) {
  Lanes<N> r;
  for (int i = 0; i < N; ++i) r.c[i] = -a.c[i];
  return r;
}

// ---------------------------------------------------------------------------------------
// Components.
template <int N>
[[gnu::always_inline]] inline LFloat component(const Lanes<N>& v, int i) {
  LFloat r;
  r.c[0] = v.c[i];
  return r;
}
template <int N>
[[gnu::always_inline]] inline LFloat x(const Lanes<N>& v) {
  return component(v, 0);
}
template <int N>
[[gnu::always_inline]] inline LFloat y(const Lanes<N>& v) {
  return component(v, 1);
}
template <int N>
[[gnu::always_inline]] inline LFloat z(const Lanes<N>& v) {
  return component(v, 2);
}
template <int N>
[[gnu::always_inline]] inline LFloat w(const Lanes<N>& v) {
  return component(v, 3);
}
template <int N>
[[gnu::always_inline]] inline Lanes<2> xy(const Lanes<N>& v) requires(N > 2) {
  return Lanes<2>(x(v), y(v));
}
[[gnu::always_inline]] inline Lanes<3> xyz(const Lanes<4>& v) {
  return Lanes<3>(x(v), y(v), z(v));
}

// ---------------------------------------------------------------------------------------
// Built-in functions, each the Exec overload's operations (shader_lang.h) lane by lane.
template <int N>
[[gnu::always_inline]] inline LFloat dot(const Lanes<N>& a, const Lanes<N>& b) {
  const Lanes<N> t = a * b;  // glm's compute_dot: the products, then their sum in this order
  LFloat r;
  if constexpr (N == 2) {
    r.c[0] = t.c[0] + t.c[1];
  } else if constexpr (N == 3) {
    r.c[0] = t.c[0] + t.c[1] + t.c[2];
  } else {
    r.c[0] = (t.c[0] + t.c[1]) + (t.c[2] + t.c[3]);
  }
  return r;
}
template <int N>
[[gnu::always_inline]] inline LFloat dot(const Lanes<N>& a, const glm::vec<N, float>& b) {
  return dot(a, Lanes<N>(b));
}
template <int N>
[[gnu::always_inline]] inline LFloat dot(const glm::vec<N, float>& a, const Lanes<N>& b) {
  return dot(Lanes<N>(a), b);
}

namespace lanes_detail {
template <int N, class Fn>
[[gnu::always_inline]] inline Lanes<N> each_lane(const Lanes<N>& v, Fn fn) {
  Lanes<N> r;
  for (int i = 0; i < N; ++i) {
    for (int l = 0; l < kLanes; ++l) r.c[i][l] = fn(v.c[i][l]);
  }
  return r;
}
// glm::min/max (func_common.inl): (y < x) ? y : x and (x < y) ? y : x, NaN operands included.
[[gnu::always_inline]] inline F4 min(const F4& a, const F4& b) {
  return b < a ? b : a;
}
[[gnu::always_inline]] inline F4 max(const F4& a, const F4& b) {
  return a < b ? b : a;
}
template <int N, class Fn>
[[gnu::always_inline]] inline Lanes<N> each_component(const Lanes<N>& v, Fn fn) {
  Lanes<N> r;
  for (int i = 0; i < N; ++i) r.c[i] = fn(v.c[i]);
  return r;
}
}  // namespace lanes_detail

// Transcendentals: the Exec language's libm calls, lane by lane; sqrt and the reciprocals are
// correctly rounded IEEE operations, packed.
#define SKINSIM_SL_LANES_LIBM(name, expr)                            \
  template <int N>                                                   \
  [[gnu::always_inline]] inline Lanes<N> name(const Lanes<N>& a) {   \
    return lanes_detail::each_lane(a, [](float v) { return expr; }); \
  }
SKINSIM_SL_LANES_LIBM(exp2, std::exp2(v))
SKINSIM_SL_LANES_LIBM(log2, std::log2(v))
SKINSIM_SL_LANES_LIBM(sin, std::sin(v))
SKINSIM_SL_LANES_LIBM(cos, std::cos(v))
SKINSIM_SL_LANES_LIBM(floor, std::floor(v))
#undef SKINSIM_SL_LANES_LIBM

template <int N>
[[gnu::always_inline]] inline Lanes<N> sqrt(const Lanes<N>& a) {
  return lanes_detail::each_component(a, [](const F4& v) { return __builtin_ia32_sqrtps(v); });
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> rsqrt(const Lanes<N>& a) {
  return 1.0f / sqrt(a);
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> rcp(const Lanes<N>& a) {
  return 1.0f / a;
}
template <int N>
[[gnu::always_inline]] inline Lanes<N> fract(const Lanes<N>& a) {
  return a - floor(a);
}
// glm::clamp(v, 0, 1) = min(max(v, 0), 1).
template <int N>
[[gnu::always_inline]] inline Lanes<N> saturate(const Lanes<N>& a) {
  return lanes_detail::each_component(
      a, [](const F4& v) { return lanes_detail::min(lanes_detail::max(v, F4{}), splat(1.0f)); });
}
// A scalar's abs is std::fabs (clears the sign); a vector's is glm's x >= 0 ? x : -x.
template <int N>
[[gnu::always_inline]] inline Lanes<N> abs(const Lanes<N>& a) {
  if constexpr (N == 1) {
    return lanes_detail::each_lane(a, [](float v) { return std::fabs(v); });
  } else {
    return lanes_detail::each_component(a, [](const F4& v) { return v >= F4{} ? v : -v; });
  }
}

#define SKINSIM_SL_LANES_BINARY(name, expr)                                                  \
  template <int N, int M>                                                                    \
  [[gnu::always_inline]] inline Lanes<lanes_detail::result_width(N, M)> name(                \
      const Lanes<N>& a, const Lanes<M>& b) requires(N == M || M == 1) {                     \
    constexpr int R = lanes_detail::result_width(N, M);                                      \
    Lanes<R> r;                                                                              \
    for (int i = 0; i < R; ++i) {                                                            \
      const F4& p = lanes_detail::part(a, i);                                                \
      const F4& q = lanes_detail::part(b, i);                                                \
      r.c[i] = expr;                                                                         \
    }                                                                                        \
    return r;                                                                                \
  }                                                                                          \
  template <int N>                                                                           \
  [[gnu::always_inline]] inline Lanes<N> name(const Lanes<N>& a, float b) {                  \
    return name(a, LFloat(b));                                                               \
  }                                                                                          \
  template <int N>                                                                           \
  [[gnu::always_inline]] inline Lanes<N> name(float a, const Lanes<N>& b) requires(N == 1) { \
    return name(LFloat(a), b);                                                               \
  }                                                                                          \
  template <int N>                                                                           \
  [[gnu::always_inline]] inline Lanes<N> name(const Lanes<N>& a,                             \
                                              const glm::vec<N, float>& b) requires(N > 1) { \
    return name(a, Lanes<N>(b));                                                             \
  }

SKINSIM_SL_LANES_BINARY(min, lanes_detail::min(p, q))
SKINSIM_SL_LANES_BINARY(max, lanes_detail::max(p, q))
// glm::step(edge, x): x < edge ? 0 : 1.
SKINSIM_SL_LANES_BINARY(step, q < p ? F4{} : splat(1.0f))
#undef SKINSIM_SL_LANES_BINARY

[[gnu::always_inline]] inline Lanes<3> cross(const Lanes<3>& a, const Lanes<3>& b) {
  return Lanes<3>(y(a) * z(b) - y(b) * z(a), z(a) * x(b) - z(b) * x(a), x(a) * y(b) - x(b) * y(a));
}
// select(c, a, b): c > 0 ? a : b per lane.
template <int N>
[[gnu::always_inline]] inline Lanes<N> select(const LFloat& c, const Lanes<N>& a,
                                              const Lanes<N>& b) {
  Lanes<N> r;
  for (int i = 0; i < N; ++i) r.c[i] = c.c[0] > F4{} ? a.c[i] : b.c[i];
  return r;
}

}  // namespace skinsim::sim::sl
