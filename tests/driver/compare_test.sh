#!/usr/bin/env bash
# driver.compare: `skinsim compare` on real outputs. Two runs of the built-in head differing by
# one knob (the BRDF LUT size): exit 1, the knob named, counters moved, compare.html and
# compare.json written, self-contained. A run against itself: exit 0. A missing directory:
# exit 2 naming it. Two tiny sweeps, one configuration apart: a per-configuration table and
# the added and removed ones named; one with 4x MSAA: its frame energy among the moved values.
#
#   tests/driver/compare_test.sh SKINSIM_EXE WORKDIR
set -euo pipefail

if (($# != 2)); then
  echo "usage: $0 SKINSIM_EXE WORKDIR" >&2
  exit 2
fi
skinsim=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
  echo "compare_test: FAIL: $*" >&2
  exit 1
}

# Runs skinsim compare with "$@", leaving its output in $out and its exit status in $status.
compare() {
  status=0
  out=$("$skinsim" compare "$@" 2>&1) || status=$?
}

small=(--resolution 256x192 --head-triangles 4000 --texture-size 128)
"$skinsim" run "${small[@]}" --lut 32x128 --out a >run_a.log 2>&1 || fail "run a: $(tail -n 3 run_a.log)"
"$skinsim" run "${small[@]}" --lut 8x32 --out b >run_b.log 2>&1 || fail "run b: $(tail -n 3 run_b.log)"

compare a b --out cmp
((status == 1)) || fail "two runs differing by --lut: exit $status, expected 1: $out"
grep -q 'lut: 32x128 -> 8x32' <<<"$out" || fail "the changed knob is not named: $out"
grep -q '^  counters\.' <<<"$out" || fail "no counter is listed as moved: $out"
grep -q '^Frame: ' <<<"$out" || fail "no frame verdict: $out"
[[ -s cmp/compare.html && -s cmp/compare.json ]] || fail "compare.html or compare.json missing"
python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); sys.exit(not (j["different"] and j["changes"][0]["name"] == "lut"))' \
  cmp/compare.json || fail "compare.json does not say what changed"
if grep -Eo '(src|href)="(https?:)?//[^"]*"' cmp/compare.html; then
  fail "compare.html fetches from the network (above); it must be self-contained"
fi
grep -q 'src="../a/frame.png"' cmp/compare.html || fail "compare.html does not link A's frame"

compare a a
((status == 0)) || fail "a run against itself: exit $status, expected 0: $out"
grep -q 'identical pixels' <<<"$out" || fail "a run against itself: frames not identical: $out"

compare a missing_run
((status == 2)) || fail "a missing directory: exit $status, expected 2: $out"
grep -q 'missing_run' <<<"$out" || fail "the missing directory is not named: $out"

sweep=(--resolutions 256x192 --luts 8x32 --head-triangles 4000 --texture-size 128 --no-charts)
"$skinsim" sweep "${sweep[@]}" --scales 0.5,0.25 --out sa >sweep_a.log 2>&1 || fail "sweep a: $(tail -n 3 sweep_a.log)"
"$skinsim" sweep "${sweep[@]}" --scales 0.5,0.125 --out sb >sweep_b.log 2>&1 || fail "sweep b: $(tail -n 3 sweep_b.log)"
compare sa sb --out scmp
((status == 1)) || fail "sweeps one configuration apart: exit $status, expected 1: $out"
grep -q 'only in B: scale0.125_lut8x32_256x192' <<<"$out" || fail "the added configuration is not named: $out"
grep -q 'only in A: scale0.25_lut8x32_256x192' <<<"$out" || fail "the removed configuration is not named: $out"
grep -q '^  scale0.5_lut8x32_256x192 .*identical pixels' <<<"$out" ||
  fail "the configuration in both is not in the table: $out"

# The same configuration with 4x MSAA: its frame energy moves, named as in a run's result.json.
"$skinsim" sweep "${sweep[@]}" --scales 0.5 --set msaa=4 --out sc >sweep_c.log 2>&1 || fail "sweep c: $(tail -n 3 sweep_c.log)"
compare sa sc --out scmp4
((status == 1)) || fail "sweeps differing by msaa: exit $status, expected 1: $out"
python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); sys.exit("energy.frame_mj" not in [m["name"] for m in j["configs"][0]["moved"]])' \
  scmp4/compare.json || fail "a sweep's frame energy is not compared: $(head -c 400 scmp4/compare.json)"

compare sa a
((status == 2)) || fail "a sweep against a run: exit $status, expected 2: $out"
echo "compare_test: PASS"
