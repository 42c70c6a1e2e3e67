#!/usr/bin/env bash
# Builds an optimised skinsim (and the benchmarks) with profile-guided optimisation into
# BUILD_DIR (default build-pgo): an instrumented build, a training run of the default sweep
# at 1024x768, then the build again from the measured profiles (cmake/pgo.cmake). The
# default sweep at 2048x1536 runs about 8% faster than with scripts/build.sh, with the same
# images and numbers (docs/performance-log.md, "Profile-guided optimisation"), which it checks
# before it finishes: the optimised binary must reproduce every golden frame and counter
# (tests/golden), or the script fails. It compiles twice, without ccache (the profiles differ
# from run to run), so it is opt-in and CI leaves it out (docs/testing.md). Safe to run
# again: every run trains afresh. Extra arguments go to cmake's configure.
# Usage: scripts/build-pgo.sh [BUILD_DIR=build-pgo] [cmake configure arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
build_dir=build-pgo
if (($#)) && [[ "$1" != -* ]]; then build_dir=$1; shift; fi
mkdir -p "$build_dir"
profile_dir=$(cd "$build_dir" && pwd)/pgo-profile
# Empty launchers: a build directory configured through ccache before must not reuse objects
# compiled without (or with other) profiles.
configure=(cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER_LAUNCHER=
  -DCMAKE_CXX_COMPILER_LAUNCHER= "-DSKINSIM_PGO_DIR=$profile_dir" "$@")

"${configure[@]}" -DSKINSIM_PGO=GENERATE
targets=(skinsim)
if grep -q '^SKINSIM_BUILD_BENCH:BOOL=ON$' "$build_dir/CMakeCache.txt"; then
  targets+=(bench_frame thread_scaling)
fi
cmake --build "$build_dir" -j "$jobs" --target skinsim

rm -rf "$profile_dir"
train_dir=$(mktemp -d)
trap 'rm -rf "$train_dir"' EXIT
# The sweep runs what users time: the emulated frames, the reference, FLIP, SSIM and PSNR,
# PNG coding. Charts are VTK's code, not ours, and would need an X display.
"$build_dir/skinsim" sweep --resolutions 1024x768 --no-charts --out "$train_dir/sweep" >/dev/null

"${configure[@]}" -DSKINSIM_PGO=USE
cmake --build "$build_dir" -j "$jobs" --target "${targets[@]}"
# The profiles may change speed, nothing else: branch layout and inlining cannot move a value
# (no -ffast-math, no FMA contraction on the baseline target), and the goldens prove it.
(cd "$build_dir" && ctest --output-on-failure -j "$jobs" -R '^golden\.')
echo "build-pgo: optimised binaries in $build_dir (profiles in $profile_dir)"
