// Which SIMD width the host runs the hot loops at. A loop with an AVX or AVX2 path (8 float
// lanes) beside its SSE2 baseline (4 lanes, all x86-64 has) does each lane's IEEE operations in
// the baseline's order and never fuses a multiply and an add (the wide paths are compiled for
// target("avx") or target("avx2"), neither of which has FMA), so every path gives the same
// bits: images, counters and metrics do not depend on the processor. AVX2 is asked for where a
// loop needs eight integer lanes too (FLIP's exponent and mantissa arithmetic).
//
// SKINSIM_SIMD=sse2 in the environment makes every loop take its baseline, as on a processor
// without AVX (tests/determinism checks whole runs both ways); unset, empty or "auto": the
// wide paths where the processor has them. Tests in one process compare the paths with
// BaselineSimdScope.
#pragma once

#include <atomic>
#include <cstdlib>
#include <string>
#include <string_view>

#include "util/user_error.h"

namespace skinsim {

namespace detail {
inline std::atomic<bool> baseline_simd_forced{false};

enum class SimdRequest { kAuto, kBaseline, kUnknown };
inline SimdRequest simd_request() {
  const char* value = std::getenv("SKINSIM_SIMD");
  const std::string_view v = value ? value : "";
  if (v.empty() || v == "auto") return SimdRequest::kAuto;
  return v == "sse2" ? SimdRequest::kBaseline : SimdRequest::kUnknown;
}
}  // namespace detail

// Reports an unknown SKINSIM_SIMD (a program calls this at start, so that a bad value is an
// error before any work rather than silently "auto").
inline void check_simd_environment() {
  if (detail::simd_request() == detail::SimdRequest::kUnknown) {
    throw UserError("environment variable SKINSIM_SIMD is '" +
                    std::string(std::getenv("SKINSIM_SIMD")) +
                    "': expected auto (AVX where the processor has it) or sse2 (the baseline)");
  }
}

// True where the processor and the operating system support AVX (GCC's cpu check reads the
// CPUID bit and that the OS saves the YMM registers), SKINSIM_SIMD does not ask for the
// baseline, and no BaselineSimdScope is open.
inline bool use_avx() {
  static const bool supported =
      __builtin_cpu_supports("avx") && detail::simd_request() != detail::SimdRequest::kBaseline;
  return supported && !detail::baseline_simd_forced.load(std::memory_order_relaxed);
}

// The same for AVX2.
inline bool use_avx2() {
  static const bool supported =
      __builtin_cpu_supports("avx2") && detail::simd_request() != detail::SimdRequest::kBaseline;
  return supported && !detail::baseline_simd_forced.load(std::memory_order_relaxed);
}

// While alive, every dispatching loop takes its SSE2 baseline (for tests that compare the
// paths). Process-wide: open it only where nothing else is running.
class BaselineSimdScope {
 public:
  BaselineSimdScope() : previous_(detail::baseline_simd_forced.exchange(true)) {}
  ~BaselineSimdScope() { detail::baseline_simd_forced.store(previous_); }
  BaselineSimdScope(const BaselineSimdScope&) = delete;
  BaselineSimdScope& operator=(const BaselineSimdScope&) = delete;

 private:
  bool previous_;
};

}  // namespace skinsim
