#!/usr/bin/env bash
# Installs the Debian 12 packages skinsim needs. Idempotent: apt skips what is present.
# Usage: scripts/install-deps.sh [run|all]   (default: all)
#   run: what building skinsim and its default job need (scripts/run-default.sh), so a new
#        user's first frame does not wait for the test-only packages (Blender, Chromium,
#        Slurm, Mesa: about a fifth of the download);
#   all: everything, the tests included (scripts/test.sh).
set -euo pipefail
set_name=${1:-all}
[[ "$set_name" == run || "$set_name" == all ]] || {
  echo "install-deps: unknown package set '$set_name' (use run or all)" >&2
  exit 2
}

# CMake's configure step needs GoogleTest, Google Benchmark, clang-format (the format test) and
# OpenImageIO (skinsim-exr) even when only skinsim is built, so they are in the run set.
packages=(
  cmake g++ make pkg-config ccache clang-format
  libglm-dev libtinygltf-dev libstb-dev libtbb-dev
  libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libembree-dev  # ray casting: the reference's shadows and the thickness bake
  libxxhash-dev  # XXH3: keys of the render-pass memo that lets sweeps replay shared passes
  libdeflate-dev  # deflate for the PNGs skinsim writes (stb_image_write, from libstb-dev, the container)
  libvtk9-dev xvfb xauth
  libglx-dev  # GLX: charts check the X display offers the OpenGL VTK needs (reports/)
  libopenimageio-dev  # skinsim-exr: reads and writes OpenEXR (truths, --linear-exr)
)
test_packages=(
  glslang-tools  # glslangValidator checks the exported GLSL ES in the tests
  # Mesa llvmpipe through EGL/GLES: the speed anchor (bench/, scripts/bench_vs_llvmpipe.py)
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  python3  # the budget CLI test parses JUnit XML with its standard library
  slurmctld slurmd slurm-client munge  # tests/slurm: a throwaway single-node Slurm cluster
  chromium  # tests/reports: report.html checked in a real (headless) browser
  ffmpeg  # a sequence's frames as a VP9 WebM for the run's and the sweep's pages (docs/sequences.md)
  openimageio-tools  # oiiotool: tests/reports measures the browser's screenshots with it
  # skinsim truth (docs/validation.md): Blender's Cycles path-traces the ground truth
  # (3.4; ~80 MB download, ~264 MB installed on top of the rest)
  blender
)
[[ "$set_name" == run ]] || packages+=("${test_packages[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
