// Four float lanes (SSE2 through GCC/Clang vector extensions) and the elementary functions
// FLIP needs on them. Every function is a fixed sequence of IEEE single-precision operations
// on each lane, independent of the other lanes, so a pixel's result does not depend on which
// pixels share its register, on the thread count or on the processor (x86-64's baseline SSE2
// has no fused multiply-add to contract into).
//
// log2 and exp2 are Cephes's single-precision polynomials (S. L. Moshier, Cephes Math Library
// 2.2, logf.c and exp2f.c), within 2 ulp of the exact value; pow and cbrt are built on them,
// pow within 1e-6 relative and cbrt within 4 ulp over the ranges FLIP uses them on
// (tests/quality/float4_test.cpp measures each against libm in double).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace skinsim::quality {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

inline Float4 splat(float v) {
  return Float4{v, v, v, v};
}

// Lanes [0, n) from p, the others 0 (n in 1..4). A full group is one unaligned load.
inline Float4 load4(const float* p, int n) {
  Float4 v{};
  if (n == 4) {
    std::memcpy(&v, p, sizeof v);
  } else {
    for (int i = 0; i < n; ++i) v[i] = p[i];
  }
  return v;
}

// Lanes [0, n) to p (n in 1..4).
inline void store4(float* p, Float4 v, int n) {
  if (n == 4) {
    std::memcpy(p, &v, sizeof v);
  } else {
    for (int i = 0; i < n; ++i) p[i] = v[i];
  }
}

inline Float4 min4(Float4 a, Float4 b) {
  return a < b ? a : b;
}

inline Float4 max4(Float4 a, Float4 b) {
  return a > b ? a : b;
}

inline Float4 abs4(Float4 v) {
  return std::bit_cast<Float4>(std::bit_cast<Int4>(v) & 0x7fffffff);
}

inline Float4 sqrt4(Float4 v) {
  return __builtin_ia32_sqrtps(v);  // correctly rounded, as std::sqrt
}

// floor of lanes within +-2^31, as ints.
inline Int4 floor4(Float4 v) {
  Int4 whole = __builtin_convertvector(v, Int4);        // truncates toward zero
  whole += v < __builtin_convertvector(whole, Float4);  // true is -1: one down when below
  return whole;
}

// log2(x) for finite x >= 2^-126 (smaller ones give log2 of 2^-126's neighbourhood; callers
// clamp). x = m 2^e with m in [sqrt(1/2), sqrt(2)); ln(m) by Cephes logf's polynomial.
inline Float4 log2_4(Float4 x) {
  const Int4 bits = std::bit_cast<Int4>(x);
  Int4 e = ((bits >> 23) & 0xff) - 126;  // x = m 2^e, m in [0.5, 1)
  const Int4 mantissa_bits = (bits & 0x007fffff) | 0x3f000000;
  const Float4 m = std::bit_cast<Float4>(mantissa_bits);
  const Int4 small = m < 0.70710678118654752440f;  // -1 where m < sqrt(1/2)
  e += small;
  const Float4 f = (small ? m + m : m) - 1.0f;  // m - 1 in [sqrt(1/2) - 1, sqrt(2) - 1)
  const Float4 z = f * f;
  Float4 p = splat(7.0376836292e-2f);
  p = p * f - 1.1514610310e-1f;
  p = p * f + 1.1676998740e-1f;
  p = p * f - 1.2420140846e-1f;
  p = p * f + 1.4249322787e-1f;
  p = p * f - 1.6668057665e-1f;
  p = p * f + 2.0000714765e-1f;
  p = p * f - 2.4999993993e-1f;
  p = p * f + 3.3333331174e-1f;
  const Float4 ln_m = f + (f * z * p - 0.5f * z);  // ln(1 + f)
  return ln_m * 1.44269504088896340736f + __builtin_convertvector(e, Float4);
}

// 2^y for y in [-126, 127] (beyond, clamped): y = n + f, f in [-1/2, 1/2], 2^f by Cephes
// exp2f's polynomial, 2^n by the exponent bits.
inline Float4 exp2_4(Float4 y) {
  y = max4(min4(y, splat(127.0f)), splat(-126.0f));
  const Int4 n = floor4(y + 0.5f);
  const Float4 f = y - __builtin_convertvector(n, Float4);
  Float4 p = splat(1.535336188319500e-4f);
  p = p * f + 1.339887440266574e-3f;
  p = p * f + 9.618437357674640e-3f;
  p = p * f + 5.550332471162809e-2f;
  p = p * f + 2.402264791363012e-1f;
  p = p * f + 6.931472028550421e-1f;
  const Float4 two_f = 1.0f + f * p;
  return two_f * std::bit_cast<Float4>((n + 127) << 23);
}

// x^y for x > 0 (x below 2^-126 counts as 2^-126).
inline Float4 pow4(Float4 x, Float4 y) {
  return exp2_4(y * log2_4(max4(x, splat(1.17549435e-38f))));
}

// Cube root of x >= 0 (x below 2^-126 counts as 2^-126).
inline Float4 cbrt4(Float4 x) {
  return exp2_4(log2_4(max4(x, splat(1.17549435e-38f))) * (1.0f / 3.0f));
}

}  // namespace skinsim::quality
