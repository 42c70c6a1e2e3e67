#!/usr/bin/env bash
# One command that installs what is missing, builds, and passes the tests:
#   1. Release build with warnings as errors, every CTest test (chart tests run under xvfb-run);
#   2. ASan + UBSan build of the unit tests with the emulator's contracts on (SKINSIM_DEBUG_CHECKS
#      follows SKINSIM_SANITIZE); no VTK charts, no benchmarks, no llvmpipe replay (Mesa's
#      allocations would read as leaks); tests not labelled slow or lint (the format check
#      reads sources, so one run of it is enough).
# Builds go through ccache when it is installed (scripts/ccache-env.sh), so a second run
# recompiles only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

bash scripts/build.sh build -DSKINSIM_WERROR=ON
(cd build && ctest --output-on-failure -j "$jobs")

# -O1 -g1 (line tables: stack traces keep files and lines) compiles in half the CPU time of
# RelWithDebInfo's -O2 -g (driver/sweep/sweep_run.cpp: 13.6 against 27.8 s); ASan's own
# documentation recommends -O1 for usable speed.
bash scripts/build.sh build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DSKINSIM_SANITIZE=ON -DSKINSIM_WERROR=ON \
  -DSKINSIM_BUILD_REPORTS=OFF -DSKINSIM_BUILD_BENCH=OFF -DSKINSIM_BUILD_CROSSCHECK=OFF
# The golden tests compare thread counts in the first stage; here one render per technique
# (2 threads, the parallel paths) is enough for the sanitizers.
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  SKINSIM_GOLDEN_THREADS=2 ctest --output-on-failure -j "$jobs" -LE "slow|lint")
