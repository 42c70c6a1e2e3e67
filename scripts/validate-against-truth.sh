#!/usr/bin/env bash
# Regenerates the quality section of docs/validation.md ("The reference and every technique
# against truth"): for the built-in head and the scan (life size), path-traced truths of both
# reference profiles (two seeds each: the noise floor), every technique at its defaults, the
# figures against truth and against skinsim's own reference, and the images.
#
# Usage: scripts/validate-against-truth.sh [OUT=out/validate-truth]
# Environment: SAMPLES (Cycles samples per pixel, default 256), RESOLUTION (default 256x192),
#   SKINSIM (default build/skinsim), SCAN (default ../shared/assets/LeePerrySmith.glb),
#   IMAGES (where the figures go, default docs/images/truth; empty: none).
# Writes OUT/table.md (the section's tables) and the images; a stage whose output exists is
# not redone, so an interrupted run resumes (delete OUT to start over).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/validate-truth}
samples=${SAMPLES:-256}
resolution=${RESOLUTION:-256x192}
skinsim=${SKINSIM:-build/skinsim}
scan=${SCAN:-../shared/assets/LeePerrySmith.glb}
images=${IMAGES-docs/images/truth}
techniques=(mobile lod preintegrated wrap burley ssss texture-space dipole urp)
export SKINSIM_CACHE_DIR=off  # every reference is rendered here, none shared

# The two scenes: the built-in head, and the scan at life size (sized from its head, 225 mm
# crown to chin) in the ColorChecker's light-skin colour (its own material is lavender).
scene_args() {
  case $1 in
    head) ;;
    scan) echo "--scene $scan --skin-albedo 194,150,130" ;;
  esac
}

# truth SCENE PROFILE: Cycles at $samples, seeds 1 and 2.
truth() {
  local dir=$out/$1/truth_$2
  [[ -f $dir/truth.json ]] && return
  # shellcheck disable=SC2046
  "$skinsim" truth $(scene_args "$1") --resolution "$resolution" --reference-profile "$2" \
    --samples "$samples" --noise-floor --out "$dir"
}

# run SCENE PROFILE TECHNIQUE: the technique's frame and the reference, judged by the truth.
run() {
  local dir=$out/$1/run_$2_$3
  [[ -f $dir/result.json ]] && return
  # shellcheck disable=SC2046
  "$skinsim" run $(scene_args "$1") --resolution "$resolution" --reference-profile "$2" \
    --technique "$3" --truth "$out/$1/truth_$2" --out "$dir" >"$dir.log"
}

# 1:1 crops (40x40 pixels of the 256x192 view, shown 3x with nearest-neighbour) per scene:
# the key light's shadow edge (the nose's shadow), the lips, an ear and a silhouette.
crops() {
  case $1 in
    head) echo "shadow:120+96 lips:104+140 ear:26+66 silhouette:186+8" ;;
    scan) echo "shadow:118+100 lips:108+126 ear:62+92 silhouette:150+36" ;;
  esac
}

# The |image - truth| x 4 of sRGB values, appended to the array `args` as oiiotool arguments.
error_args() { args+=("$1" --ch "R,G,B" "$2" --ch "R,G,B" --absdiff --mulc 4); }

for scene in head scan; do
  for profile in six_gaussian dipole; do truth "$scene" "$profile"; done
  run "$scene" dipole mobile  # the dipole reference against the dipole's truth
  for technique in "${techniques[@]}"; do run "$scene" six_gaussian "$technique"; done
done
python3 scripts/truth/validation_table.py "$out" "${techniques[@]}" >"$out/table.md"
echo "wrote $out/table.md"
[[ -z $images ]] && exit 0

mkdir -p "$images"
for scene in head scan; do
  d=$out/$scene
  six=$d/run_six_gaussian_mobile dip=$d/run_dipole_mobile
  # The references: truth | reference | error, six Gaussians above, the dipole below.
  args=()
  for pair in "six_gaussian $six" "dipole $dip"; do
    read -r profile run_dir <<<"$pair"
    args+=("$d/truth_$profile/truth.png" --ch "R,G,B" "$run_dir/reference.png" --ch "R,G,B")
    error_args "$run_dir/reference.png" "$d/truth_$profile/truth.png"
  done
  oiiotool "${args[@]}" --mosaic 3x2 -o "$images/${scene}_references.png"
  # Every technique's frame, and its error against the truth, 3 x 3 in the order above.
  frames=()
  args=()
  for t in "${techniques[@]}"; do
    frames+=("$d/run_six_gaussian_$t/frame.png" --ch "R,G,B")
    error_args "$d/run_six_gaussian_$t/frame.png" "$d/truth_six_gaussian/truth.png"
  done
  oiiotool "${frames[@]}" --mosaic 3x3 -o "$images/${scene}_techniques.png"
  oiiotool "${args[@]}" --mosaic 3x3 -o "$images/${scene}_techniques_error.png"
  # Crops: a row per region; the truth, the reference, then each technique.
  sources=("$d/truth_six_gaussian/truth.png" "$six/reference.png")
  for t in "${techniques[@]}"; do sources+=("$d/run_six_gaussian_$t/frame.png"); done
  rows=()
  for region in $(crops "$scene"); do
    cells=()
    for image in "${sources[@]}"; do
      cells+=("$image" --ch "R,G,B" --cut "40x40+${region#*:}" --origin +0+0 --fullpixels
        --resample 120x120)
    done
    oiiotool "${cells[@]}" --mosaic "${#sources[@]}x1" -o "$d/crop_${region%%:*}.png"
    rows+=("$d/crop_${region%%:*}.png")
  done
  oiiotool "${rows[@]}" --mosaic "1x${#rows[@]}" -o "$images/${scene}_crops.png"
done
echo "wrote the images into $images/"
