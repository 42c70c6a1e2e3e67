// Which SIMD width the host runs the hot loops at. A loop with an AVX path (8 float lanes)
// beside its SSE2 baseline (4 lanes, all x86-64 has) does each lane's IEEE operations in the
// baseline's order and never fuses a multiply and an add (the AVX paths are compiled for
// target("avx"), which has no FMA), so both paths give the same bits: images, counters and
// metrics do not depend on the processor. Tests force the baseline to check that.
#pragma once

#include <atomic>

namespace skinsim {

namespace detail {
inline std::atomic<bool> baseline_simd_forced{false};
}  // namespace detail

// True where the processor and the operating system support AVX (GCC's cpu check reads the
// CPUID bit and that the OS saves the YMM registers) and no BaselineSimdScope is open.
inline bool use_avx() {
  static const bool supported = __builtin_cpu_supports("avx");
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
