#!/usr/bin/env bash
# driver.sharded_processes: `skinsim sweep --shard K/3` as three concurrent processes sharing
# one directory (and one reference), one of them killed with SIGKILL mid-sweep and run again,
# then --merge: results.csv and results.json are byte-identical to the one-process sweep, and
# the merge before the re-run names the killed shard.
#
#   tests/driver/sharded_processes_test.sh SKINSIM_EXE WORKDIR
set -euo pipefail

if (($# != 2)); then
  echo "usage: $0 SKINSIM_EXE WORKDIR" >&2
  exit 2
fi
skinsim=$1
work=$2
rm -rf "$work"
mkdir -p "$work"

fail() {
  echo "sharded_processes_test: FAIL: $*" >&2
  exit 1
}

# Mixed techniques, so the partition balances cost rather than count.
# shellcheck disable=SC2054  # the commas are skinsim's value lists
args=(--resolutions 320x240 --techniques mobile,wrap,burley --scales 0.5,0.25
  --luts 8x32,16x64 --head-triangles 4000 --texture-size 128 --no-charts --threads 1)
dir=$work/sharded

"$skinsim" sweep "${args[@]}" --out "$dir" --shard 0/3 >"$work/shard0.log" 2>&1 &
pid0=$!
"$skinsim" sweep "${args[@]}" --out "$dir" --shard 1/3 >"$work/shard1.log" 2>&1 &
pid1=$!
"$skinsim" sweep "${args[@]}" --out "$dir" --shard 2/3 >"$work/shard2.log" 2>&1 &
pid2=$!
trap 'kill -KILL $pid0 $pid1 $pid2 2>/dev/null || true' EXIT

# Kill shard 2 as soon as it has written its first configuration (its status file lists what
# it was assigned; a finished configuration is its JSON).
mapfile -t mine < <(for _ in $(seq 600); do
  if [[ -f "$dir/shards/shard-2-of-3.json" ]]; then
    python3 -c 'import json,sys; print("\n".join(json.load(open(sys.argv[1]))["configurations"]))' \
      "$dir/shards/shard-2-of-3.json" && break
  fi
  sleep 0.1
done)
((${#mine[@]} >= 2)) || fail "shard 2 was assigned ${#mine[@]} configurations; the test needs 2+"
killed=0
for _ in $(seq 1200); do
  for id in "${mine[@]}"; do
    if [[ -f "$dir/configs/$id.json" ]]; then
      kill -KILL "$pid2" 2>/dev/null && killed=1
      break 2
    fi
  done
  sleep 0.05
done
((killed)) || fail "shard 2 finished before it could be killed"
wait "$pid0" || fail "shard 0 exited with $? ($(tail -n 3 "$work/shard0.log"))"
wait "$pid1" || fail "shard 1 exited with $? ($(tail -n 3 "$work/shard1.log"))"
wait "$pid2" 2>/dev/null || true

# The merge names the missing configurations and the killed shard, and exits 1.
rc=0
"$skinsim" sweep "${args[@]}" --out "$dir" --merge >"$work/merge1.log" 2>&1 || rc=$?
((rc == 1)) || fail "--merge with a killed shard exited $rc, expected 1"
grep -q "shard 2/3 on .* did not finish: killed, or still running" "$work/merge1.log" ||
  fail "--merge did not name the killed shard: $(cat "$work/merge1.log")"

# Re-running the killed shard resumes it; the merge is then complete.
"$skinsim" sweep "${args[@]}" --out "$dir" --shard 2/3 >"$work/shard2-again.log" 2>&1 ||
  fail "re-running shard 2 failed: $(tail -n 5 "$work/shard2-again.log")"
grep -q "[1-9][0-9]* resumed" "$work/shard2-again.log" ||
  fail "the re-run shard resumed nothing: $(tail -n 3 "$work/shard2-again.log")"
"$skinsim" sweep "${args[@]}" --out "$dir" --merge >"$work/merge2.log" 2>&1 ||
  fail "--merge after the re-run exited $?: $(tail -n 5 "$work/merge2.log")"

# Rendered once, by whichever shard took the lock first.
refs=$(find "$dir/refs" -name 'reference_*_skin.png' | wc -l)
((refs == 1)) || fail "$refs references in $dir/refs, expected 1"

"$skinsim" sweep "${args[@]}" --out "$work/single" >"$work/single.log" 2>&1 ||
  fail "the one-process sweep failed: $(tail -n 5 "$work/single.log")"
for f in results.csv results.json; do
  cmp "$work/single/$f" "$dir/$f" || fail "$f differs from the one-process sweep's"
done
echo "sharded_processes_test: PASS ($(($(wc -l <"$dir/results.csv") - 1)) configurations)"
