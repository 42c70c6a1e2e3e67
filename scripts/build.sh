#!/usr/bin/env bash
# Configures and builds skinsim into build/ (Release). Extra arguments go to cmake's configure.
# Usage: scripts/build.sh [BUILD_DIR=build] [--target NAME]... [cmake configure arguments]
# Without --target it builds everything (tests and benchmarks included); with it, only NAME
# and what NAME needs.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ccache-env.sh
jobs=$(nproc 2>/dev/null || echo 2)
build_dir=build
if (($#)) && [[ "$1" != -* ]]; then build_dir=$1; shift; fi
targets=()
while (($#)) && [[ "$1" == --target ]]; do
  targets+=(--target "$2")
  shift 2
done
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${ccache_args[@]}" "$@"
cmake --build "$build_dir" -j "$jobs" "${targets[@]}"
