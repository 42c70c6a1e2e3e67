#!/usr/bin/env bash
# reports.browser: a sweep's report.html, and the compare.html of two runs one knob apart,
# opened in a real browser (Debian's headless Chromium): each page's script runs without
# errors, it fetches nothing from the network, and its screenshot shows the page (not a blank
# or error page).
#
#   tests/reports/browser_report_test.sh SKINSIM_EXE WORKDIR
#
# Exit 0 pass, 1 fail, 77 skip (no chromium), 2 usage.
set -euo pipefail

if (($# != 2)); then
  echo "usage: $0 SKINSIM_EXE WORKDIR" >&2
  exit 2
fi
skinsim=$1
work=$2
browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z "$browser" ]]; then
  echo "browser_report_test: SKIP: no chromium (scripts/install-deps.sh installs it)" >&2
  exit 77
fi
fail() {
  echo "browser_report_test: FAIL: $*" >&2
  exit 1
}
rm -rf "$work"
mkdir -p "$work"

# Two configurations, so the report has a recommendation, a comparison panel and its slider.
"$skinsim" sweep --resolutions 256x192 --scales 0.5,0.125 --luts 8x32 --head-triangles 4000 \
  --texture-size 128 --no-charts --out "$work/sweep" >"$work/sweep.log" 2>&1 ||
  fail "the sweep failed: $(tail -n 5 "$work/sweep.log")"
page=$work/sweep/report.html
grep -q 'class="compare"' "$page" || fail "the report has no comparison panel"
# Both sides of the slider offer the reference and both configurations, and a difference view.
options=$(grep -o '<select class="left">.*</select> right' "$page" | grep -o '<option' | wc -l)
((options == 3)) || fail "the slider's left side offers $options frames, expected 3"
grep -q 'class="diff"' "$page" || fail "the slider has no difference view"

# check_page NAME PAGE: no network links, no script errors, a non-blank screenshot NAME.png.
check_page() {
  local name=$1 page=$2
  if grep -Eo '(src|href)="(https?:)?//[^"]*"' "$page"; then
    fail "$name fetches from the network (above); it must be self-contained"
  fi
  # Root needs --no-sandbox; the virtual-time budget lets the page's script run before the shot.
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --enable-logging=stderr --v=0 --virtual-time-budget=3000 --window-size=1200,1800 \
    --user-data-dir="$work/profile" --screenshot="$work/$name.png" "file://$page" \
    >"$work/$name.log" 2>&1 || fail "chromium failed on $name: $(tail -n 5 "$work/$name.log")"
  if grep -E 'CONSOLE.*(Uncaught|Error)' "$work/$name.log"; then
    fail "$name's script reported errors (above)"
  fi
  [[ -s "$work/$name.png" ]] || fail "no screenshot of $name"
  # A blank page is one colour: its per-channel standard deviation is 0.
  local stddev
  stddev=$(oiiotool --stats "$work/$name.png" | awk '/Stats StdDev/ {print $3; exit}')
  awk -v s="${stddev:-0}" 'BEGIN { exit !(s > 5) }' ||
    fail "the screenshot of $name looks blank (standard deviation ${stddev:-?})"
}
check_page report "$page"
# The same page with its slider switched to the other configuration and the difference view:
# the script that does both runs without errors in the browser.
switch='var c = document.querySelector(".compare"), l = c.querySelector("select.left");
l.selectedIndex = l.options.length - 1; l.dispatchEvent(new Event("change"));
var d = c.querySelector("input.diff"); d.checked = true; d.dispatchEvent(new Event("change"));
if (getComputedStyle(c.querySelector("img.over")).mixBlendMode !== "difference")
  throw new Error("the difference view did not switch on");'
sed "s|</body>|<script>${switch//$'\n'/ }</script></body>|" "$page" >"$work/sweep/report_difference.html"
check_page report_difference "$work/sweep/report_difference.html"

# Two runs one knob apart: compare.html with its slider and crops.
run=(--resolution 256x192 --head-triangles 4000 --texture-size 128 --no-reference)
"$skinsim" run "${run[@]}" --lut 32x128 --out "$work/a" >"$work/run.log" 2>&1 ||
  fail "run a failed: $(tail -n 5 "$work/run.log")"
"$skinsim" run "${run[@]}" --lut 8x32 --out "$work/b" >"$work/run.log" 2>&1 ||
  fail "run b failed: $(tail -n 5 "$work/run.log")"
status=0
"$skinsim" compare "$work/a" "$work/b" --out "$work/ab" >"$work/compare.log" 2>&1 || status=$?
((status == 1)) || fail "compare exited $status, expected 1: $(tail -n 5 "$work/compare.log")"
grep -q 'class="compare"' "$work/ab/compare.html" || fail "compare.html has no slider"
check_page compare "$work/ab/compare.html"
echo "browser_report_test: PASS (screenshots $work/report.png, $work/compare.png)"
