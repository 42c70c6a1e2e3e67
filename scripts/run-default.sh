#!/usr/bin/env bash
# One command for a new user: installs what is missing, builds, and runs the main job on the
# built-in default scene (iPad 4 profile). Safe to run again: results land in out/default.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/skinsim run --device ipad4 --out out/default
