#!/usr/bin/env bash
# One command for a new user: installs what is missing, builds, runs one frame of the built-in
# default scene (iPad 4 profile) into out/default, then the default sweep (4 integration-buffer
# scales x 4 BRDF LUT sizes, with the reference, quality metrics, charts and report.html) into
# out/default-sweep. Safe to run again: the sweep resumes and skips finished configurations.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh run  # the tests' packages (Blender, Chromium, Slurm) come with scripts/test.sh
# Only the program and what it links (203 of the build's 294 objects): the tests and benchmarks
# are built by scripts/test.sh, which runs them.
bash scripts/build.sh build --target skinsim
./build/skinsim run --device ipad4 --out out/default

# VTK draws the charts through an X display; without one, use a virtual one if available.
sweep=(./build/skinsim sweep --out out/default-sweep)
if [[ -z "${DISPLAY:-}" ]] && command -v xvfb-run >/dev/null; then
  xvfb-run -a "${sweep[@]}"
else
  "${sweep[@]}"
fi
