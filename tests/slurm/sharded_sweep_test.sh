#!/usr/bin/env bash
# slurm.sharded_sweep: a sweep run as 3 Slurm shards plus a merge (scripts/slurm/sweep.sh
# --wait, on a throwaway single-node cluster from single_node_slurm.sh) writes the same
# results.csv, byte for byte, as the same sweep in one process.
#
#   tests/slurm/sharded_sweep_test.sh SKINSIM_EXE WORKDIR
#
# Exit 0 pass, 1 fail, 77 skip (Slurm cannot run here), 2 usage.
set -euo pipefail

if (($# != 2)); then
  echo "usage: $0 SKINSIM_EXE WORKDIR" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
skinsim=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
[[ -x "$skinsim" ]] || {
  echo "sharded_sweep_test: '$1' is not executable" >&2
  exit 2
}
rm -rf "$2"
mkdir -p "$2"
work=$(cd "$2" && pwd)

# Small enough for a test, several configurations per shard.
# shellcheck disable=SC2054  # the commas are skinsim's value lists
sweep_args=(--resolutions 128x96 --techniques mobile,wrap,burley --scales 0.5,0.25 --luts 8x32,16x64
  --no-charts)

# shellcheck source=tests/slurm/single_node_slurm.sh
source "$here/single_node_slurm.sh"

fail() {
  echo "sharded_sweep_test: FAIL: $*" >&2
  exit 1
}

show_job_logs() {
  local f
  for f in "$work"/sharded/slurm/*.log; do
    [[ -f "$f" ]] || continue
    echo "----- $f -----" >&2
    tail -n 60 "$f" >&2
  done
}

# Runs inside the cluster. timeout: --wait must not outlive the test's own TIMEOUT.
sharded_sweep() {
  SWEEP_POLL_SECONDS=1 timeout 420 bash "$repo/scripts/slurm/sweep.sh" \
    --shards 3 --wait --out "$work/sharded" --skinsim "$skinsim" -- "${sweep_args[@]}"
}

echo "== sharded: scripts/slurm/sweep.sh --shards 3 --wait -- ${sweep_args[*]}"
rc=0
single_node_slurm_run sharded_sweep || rc=$?
if ((rc == SINGLE_NODE_SLURM_SKIP)); then
  echo "sharded_sweep_test: SKIP: no Slurm cluster could be started here" >&2
  exit 77
fi
if ((rc != 0)); then
  show_job_logs
  ((rc == 124)) && fail "sweep.sh --wait did not finish within 420 s"
  fail "sweep.sh --wait exited with status $rc"
fi

echo "== single process: skinsim sweep ${sweep_args[*]}"
if ! "$skinsim" sweep "${sweep_args[@]}" --out "$work/single" >"$work/single.log" 2>&1; then
  cat "$work/single.log" >&2
  fail "the single-process sweep failed"
fi

for f in "$work/sharded/results.csv" "$work/single/results.csv"; do
  [[ -s "$f" ]] || {
    show_job_logs
    fail "$f is missing or empty"
  }
done
if ! cmp "$work/single/results.csv" "$work/sharded/results.csv"; then
  diff -u "$work/single/results.csv" "$work/sharded/results.csv" | head -n 40 >&2 || true
  show_job_logs
  fail "results.csv of the sharded sweep differs from the single-process one"
fi
echo "sharded_sweep_test: PASS: results.csv identical ($(($(wc -l <"$work/single/results.csv") - 1)) configurations)"
