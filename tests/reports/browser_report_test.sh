#!/usr/bin/env bash
# reports.browser: a sweep's report.html opened in a real browser (Debian's headless
# Chromium): the page's script runs without errors, it fetches nothing from the network, and
# its screenshot shows the page (not a blank or error page).
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
if grep -Eo '(src|href)="(https?:)?//[^"]*"' "$page"; then
  fail "the report fetches from the network (above); it must be self-contained"
fi

# Root needs --no-sandbox; the virtual-time budget lets the page's script run before the shot.
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
  --enable-logging=stderr --v=0 --virtual-time-budget=3000 --window-size=1200,1800 \
  --user-data-dir="$work/profile" --screenshot="$work/report.png" "file://$page" \
  >"$work/browser.log" 2>&1 || fail "chromium failed: $(tail -n 5 "$work/browser.log")"
if grep -E 'CONSOLE.*(Uncaught|Error)' "$work/browser.log"; then
  fail "the page's script reported errors (above)"
fi
[[ -s "$work/report.png" ]] || fail "no screenshot"
# A blank page is one colour: its per-channel standard deviation is 0.
stddev=$(oiiotool --stats "$work/report.png" | awk '/Stats StdDev/ {print $3; exit}')
awk -v s="${stddev:-0}" 'BEGIN { exit !(s > 5) }' ||
  fail "the screenshot looks blank (standard deviation ${stddev:-?})"
echo "browser_report_test: PASS (screenshot $work/report.png)"
