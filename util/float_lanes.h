// Float lanes through GCC/Clang vector extensions: four (SSE2, all x86-64 has) or eight (AVX2,
// where the processor has it; util/simd_dispatch.h), and the elementary functions on them
// (FLIP's colour work, the texture unit's footprint addressing, the reference's diffusion). Every
// function is a fixed sequence of IEEE single-precision operations on each lane, independent of the
// other lanes and of the width, so a pixel's result does not depend on which pixels share its
// register, on the thread count or on the processor (neither SSE2 nor the AVX2 target has a fused
// multiply-add to contract into).
//
// log2 and exp2 are Cephes's single-precision polynomials (S. L. Moshier, Cephes Math Library
// 2.2, logf.c and exp2f.c), within 2 ulp of the exact value; pow and cbrt are built on them,
// pow within 1e-6 relative and cbrt within 4 ulp over the ranges FLIP uses them on
// (tests/quality/float_lanes_test.cpp measures each against libm in double).
//
// The functions are always inlined: eight-lane code runs only inside functions compiled for
// target("avx2"), and must become AVX2 code there rather than calls across the ABI (hence
// also -Wpsabi off: no 32-byte vector is ever passed between functions).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace skinsim {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Float8 = float __attribute__((vector_size(32)));
using Int8 = std::int32_t __attribute__((vector_size(32)));

template <class V>
constexpr int kLanes = static_cast<int>(sizeof(V) / sizeof(float));

// The integer lanes (comparison results, bit patterns) of a float vector type.
template <class V>
struct IntLanesOf;
template <>
struct IntLanesOf<Float4> {
  using type = Int4;
};
template <>
struct IntLanesOf<Float8> {
  using type = Int8;
};
template <class V>
using IntLanes = typename IntLanesOf<V>::type;

// The unsigned integer lanes of a float vector type (bit fields: shifts, masks).
using Uint4 = std::uint32_t __attribute__((vector_size(16)));
using Uint8 = std::uint32_t __attribute__((vector_size(32)));
template <class V>
using UintLanes = std::conditional_t<kLanes<V> == 4, Uint4, Uint8>;

template <class V = Float4>
[[gnu::always_inline]] inline V splat(float v) {
  V r;
  for (int lane = 0; lane < kLanes<V>; ++lane) r[lane] = v;
  return r;
}

// Lanes [0, n) from p, the others 0 (n in 1..kLanes). A full group is one unaligned load.
template <class V = Float4>
[[gnu::always_inline]] inline V load_lanes(const float* p, int n) {
  V v{};
  if (n == kLanes<V>) {
    std::memcpy(&v, p, sizeof v);
  } else {
    for (int i = 0; i < n; ++i) v[i] = p[i];
  }
  return v;
}

// Lanes [0, n) to p (n in 1..kLanes).
template <class V>
[[gnu::always_inline]] inline void store_lanes(float* p, V v, int n) {
  if (n == kLanes<V>) {
    std::memcpy(p, &v, sizeof v);
  } else {
    for (int i = 0; i < n; ++i) p[i] = v[i];
  }
}

template <class V>
[[gnu::always_inline]] inline V min_lanes(V a, V b) {
  return a < b ? a : b;
}

template <class V>
[[gnu::always_inline]] inline V max_lanes(V a, V b) {
  return a > b ? a : b;
}

template <class V>
[[gnu::always_inline]] inline V abs_lanes(V v) {
  return std::bit_cast<V>(std::bit_cast<IntLanes<V>>(v) & 0x7fffffff);
}

// Correctly rounded, as std::sqrt.
template <class V>
[[gnu::always_inline]] inline V sqrt_lanes(V v) {
  if constexpr (kLanes<V> == 4) {
    return __builtin_ia32_sqrtps(v);
  } else {
    return __builtin_ia32_sqrtps256(v);
  }
}

// floor of lanes within +-2^31, as ints.
template <class V>
[[gnu::always_inline]] inline IntLanes<V> floor_lanes(V v) {
  IntLanes<V> whole = __builtin_convertvector(v, IntLanes<V>);  // truncates toward zero
  whole += v < __builtin_convertvector(whole, V);               // true is -1: one down when below
  return whole;
}

// log2(x) for finite x >= 2^-126 (smaller ones give log2 of 2^-126's neighbourhood; callers
// clamp). x = m 2^e with m in [sqrt(1/2), sqrt(2)); ln(m) by Cephes logf's polynomial.
template <class V>
[[gnu::always_inline]] inline V log2_lanes(V x) {
  using I = IntLanes<V>;
  const I bits = std::bit_cast<I>(x);
  I e = ((bits >> 23) & 0xff) - 126;  // x = m 2^e, m in [0.5, 1)
  const I mantissa_bits = (bits & 0x007fffff) | 0x3f000000;
  const V m = std::bit_cast<V>(mantissa_bits);
  const I small = m < 0.70710678118654752440f;  // -1 where m < sqrt(1/2)
  e += small;
  const V f = (small ? m + m : m) - 1.0f;  // m - 1 in [sqrt(1/2) - 1, sqrt(2) - 1)
  const V z = f * f;
  V p = splat<V>(7.0376836292e-2f);
  p = p * f - 1.1514610310e-1f;
  p = p * f + 1.1676998740e-1f;
  p = p * f - 1.2420140846e-1f;
  p = p * f + 1.4249322787e-1f;
  p = p * f - 1.6668057665e-1f;
  p = p * f + 2.0000714765e-1f;
  p = p * f - 2.4999993993e-1f;
  p = p * f + 3.3333331174e-1f;
  const V ln_m = f + (f * z * p - 0.5f * z);  // ln(1 + f)
  return ln_m * 1.44269504088896340736f + __builtin_convertvector(e, V);
}

// 2^y for y in [-126, 127] (beyond, clamped): y = n + f, f in [-1/2, 1/2], 2^f by Cephes
// exp2f's polynomial, 2^n by the exponent bits.
template <class V>
[[gnu::always_inline]] inline V exp2_lanes(V y) {
  y = max_lanes(min_lanes(y, splat<V>(127.0f)), splat<V>(-126.0f));
  const IntLanes<V> n = floor_lanes(y + 0.5f);
  const V f = y - __builtin_convertvector(n, V);
  V p = splat<V>(1.535336188319500e-4f);
  p = p * f + 1.339887440266574e-3f;
  p = p * f + 9.618437357674640e-3f;
  p = p * f + 5.550332471162809e-2f;
  p = p * f + 2.402264791363012e-1f;
  p = p * f + 6.931472028550421e-1f;
  const V two_f = 1.0f + f * p;
  return two_f * std::bit_cast<V>((n + 127) << 23);
}

// x^y for x > 0 (x below 2^-126 counts as 2^-126).
template <class V>
[[gnu::always_inline]] inline V pow_lanes(V x, V y) {
  return exp2_lanes(y * log2_lanes(max_lanes(x, splat<V>(1.17549435e-38f))));
}

// Cube root of x >= 0 (x below 2^-126 counts as 2^-126).
template <class V>
[[gnu::always_inline]] inline V cbrt_lanes(V x) {
  return exp2_lanes(log2_lanes(max_lanes(x, splat<V>(1.17549435e-38f))) * (1.0f / 3.0f));
}

}  // namespace skinsim

#pragma GCC diagnostic pop
