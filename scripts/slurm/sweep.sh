#!/usr/bin/env bash
# Runs a `skinsim sweep` on a Slurm cluster as a job array of shards plus a merge job.
#
#   scripts/slurm/sweep.sh --shards N --out DIR [options] [-- <skinsim sweep arguments>]
#
# Submits an array of N tasks, task K running
#   skinsim sweep <arguments> --out DIR --shard K/N
# and a merge job that starts once every task has succeeded (afterok) and runs
#   skinsim sweep <arguments> --out DIR --merge
# which writes DIR/results.csv, results.json and report.html. DIR must be on a file system
# every node sees. Logs: DIR/slurm/shard-K.log and DIR/slurm/merge.log (appended to, so a
# resubmission keeps the earlier runs' output). Submitting again into the same DIR resumes:
# configurations already computed are not computed again.
#
# Options:
#   --shards N            number of array tasks (shards), N >= 1
#   --out DIR             sweep directory (created; made absolute)
#   --wait                block until the merge job ends and exit with its status; exit 1
#                         with a message if a shard failed, so the merge can never run
#   --partition P         Slurm partition of every job
#   --time T              time limit of every job (sbatch --time syntax)
#   --cpus-per-task C     CPUs of each shard task; skinsim gets --threads C
#   --skinsim PATH        skinsim executable (default: build/skinsim of this repository if
#                         built, else skinsim on PATH)
#   --sbatch-arg ARG      extra sbatch argument for every job (repeatable), e.g.
#                         --sbatch-arg=--account=proj --sbatch-arg=--mem=4G
#   -h, --help            this text
#
# Prints the job ids. Exit status: 0 submitted (or, with --wait, merge succeeded), 1 failure,
# 2 usage error, 130 interrupted while waiting (the jobs keep running).
# Environment: SWEEP_POLL_SECONDS, how often --wait asks Slurm (default 10).
set -euo pipefail

prog=${0##*/}
# Paths are made absolute with realpath, not `cd DIR && pwd`: cd obeys an exported CDPATH (and
# then prints the directory it found, which the substitution would capture) and treats '-' as
# the previous directory.
script_dir=$(dirname -- "$(realpath -e -- "${BASH_SOURCE[0]}")")

usage() { sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//'; }
die_usage() {
  echo "$prog: $*" >&2
  echo "Try '$prog --help'." >&2
  exit 2
}
die() {
  echo "$prog: $*" >&2
  exit 1
}
log() { echo "$prog: $*" >&2; }

# --- Options ---------------------------------------------------------------------------

shards="" out="" wait=0 partition="" time_limit="" cpus="" skinsim=""
sbatch_extra=()
sweep_args=()

# Sets $value to an option's argument, from --opt=value or the next word; $shift_by says
# how many words the option took.
need_value() {
  local opt=$1 word=$2
  shift 2
  if [[ "$word" == *=* ]]; then
    value=${word#*=}
    shift_by=1
  elif (($# >= 1)); then
    value=$1
    shift_by=2
  else
    die_usage "$opt needs a value"
  fi
}

while (($#)); do
  opt=${1%%=*}
  case $opt in
    -h | --help)
      usage
      exit 0
      ;;
    --wait)
      [[ "$1" == --wait ]] || die_usage "--wait takes no value"
      wait=1
      shift
      ;;
    --shards | --out | --partition | --time | --cpus-per-task | --skinsim | --sbatch-arg)
      need_value "$opt" "$@"
      case $opt in
        --shards) shards=$value ;;
        --out) out=$value ;;
        --partition) partition=$value ;;
        --time) time_limit=$value ;;
        --cpus-per-task) cpus=$value ;;
        --skinsim) skinsim=$value ;;
        --sbatch-arg) sbatch_extra+=("$value") ;;
      esac
      shift "$shift_by"
      ;;
    --)
      shift
      sweep_args=("$@")
      break
      ;;
    *) die_usage "unknown option '$1' (skinsim's sweep arguments go after --)" ;;
  esac
done

[[ -n "$shards" ]] || die_usage "--shards N is required"
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || die_usage "--shards: '$shards' is not a positive integer"
# skinsim's own limit (--shard K/N), checked by length first: bash arithmetic wraps at 2^63.
max_shards=100000
if ((${#shards} > ${#max_shards})) || ((shards > max_shards)); then
  die_usage "--shards: $shards is more than the $max_shards shards skinsim accepts"
fi
[[ -n "$out" ]] || die_usage "--out DIR is required"
if [[ -n "$cpus" && ! "$cpus" =~ ^[1-9][0-9]*$ ]]; then
  die_usage "--cpus-per-task: '$cpus' is not a positive integer"
fi
for a in "${sweep_args[@]}"; do
  case $a in
    --out | --out=* | --shard | --shard=* | --merge | --merge=*)
      die_usage "do not pass '$a' among the sweep arguments: $prog adds --out, --shard and --merge"
      ;;
  esac
done

# skinsim: absolute, since the jobs run in another process, possibly on another node.
if [[ -z "$skinsim" ]]; then
  if [[ -x "$script_dir/../../build/skinsim" ]]; then
    skinsim=$script_dir/../../build/skinsim
  elif command -v skinsim >/dev/null 2>&1; then
    skinsim=$(command -v skinsim)
  else
    die_usage "no skinsim: build it (scripts/build.sh) or pass --skinsim PATH"
  fi
fi
[[ -f "$skinsim" && -x "$skinsim" ]] || die_usage "--skinsim: '$skinsim' is not an executable file"
skinsim=$(realpath -e -- "$skinsim")

# The shards share DIR; --threads follows the CPUs Slurm gives each task, unless the sweep
# arguments already set it.
if [[ -n "$cpus" ]]; then
  has_threads=0
  for a in "${sweep_args[@]}"; do
    [[ "$a" == --threads || "$a" == --threads=* ]] && has_threads=1
  done
  ((has_threads)) || sweep_args+=(--threads "$cpus")
fi

for tool in sbatch scontrol scancel; do
  command -v "$tool" >/dev/null 2>&1 || die "'$tool' not found: is this a Slurm submit host?"
done

mkdir -p -- "$out"
out=$(realpath -e -- "$out")
# The logs below go into DIR, so claim it as a sweep's first, as skinsim would
# (docs/outputs.md: a command writes only into an empty directory or one of its own kind).
marker=$out/.skinsim-output
if [[ -z "$(ls -A -- "$out")" ]]; then
  printf '{"kind":"sweep"}\n' >"$marker"
elif ! grep -qs '"kind":"sweep"' "$marker"; then
  die_usage "--out $out: is not empty and not a skinsim sweep directory (no .skinsim-output marker): choose another --out"
fi
log_dir=$out/slurm
mkdir -p "$log_dir"

# --- The job script ----------------------------------------------------------------------
# One generic batch script; what to run comes as its arguments, which sbatch hands over as
# an argument vector (no re-quoting, so arguments with spaces or quotes survive). Kept in
# DIR/slurm for the record; sbatch copies it at submission.

job_script=$log_dir/job.sh
tmp_script=$(mktemp "$log_dir/.job.sh.XXXXXX")
cat >"$tmp_script" <<'EOF'
#!/usr/bin/env bash
# Written by scripts/slurm/sweep.sh. Arguments:
#   shard SKINSIM DIR N [sweep arguments...]   (in an array task: shard $SLURM_ARRAY_TASK_ID of N)
#   merge SKINSIM DIR [sweep arguments...]
set -euo pipefail
mode=$1 skinsim=$2 out=$3
shift 3
echo "== $(date '+%F %T') job ${SLURM_JOB_ID:-?} (${SLURM_ARRAY_JOB_ID:+array $SLURM_ARRAY_JOB_ID task $SLURM_ARRAY_TASK_ID, }$mode) on $(hostname -s)"
case $mode in
  shard)
    # N is the submitted shard count, not SLURM_ARRAY_TASK_COUNT: resubmitting only some
    # tasks (--array=2,5) must not change how the configurations are split.
    shards=$1
    shift
    exec "$skinsim" sweep "$@" --out "$out" --shard "$SLURM_ARRAY_TASK_ID/$shards"
    ;;
  merge)
    exec "$skinsim" sweep "$@" --out "$out" --merge
    ;;
  *)
    echo "job.sh: unknown mode '$mode'" >&2
    exit 2
    ;;
esac
EOF
chmod +x "$tmp_script"
mv -f "$tmp_script" "$job_script"

# --- Submission --------------------------------------------------------------------------

common=(--parsable)
[[ -n "$partition" ]] && common+=(--partition="$partition")
[[ -n "$time_limit" ]] && common+=(--time="$time_limit")

shard_opts=(--job-name=skinsim-sweep --array="0-$((shards - 1))"
  --output="$log_dir/shard-%a.log" --open-mode=append)
[[ -n "$cpus" ]] && shard_opts+=(--cpus-per-task="$cpus")

# --parsable prints "jobid" or "jobid;cluster". The --sbatch-arg arguments come last, so
# that they win over ours (sbatch takes the last of a repeated option).
array_id=$(sbatch "${common[@]}" "${shard_opts[@]}" "${sbatch_extra[@]}" \
  "$job_script" shard "$skinsim" "$out" "$shards" "${sweep_args[@]}") ||
  die "sbatch of the shard array failed"
array_id=${array_id%%;*}
[[ "$array_id" =~ ^[0-9]+$ ]] || die "unexpected sbatch output '$array_id'"

# kill-on-invalid-dep: if a shard fails, Slurm cancels the merge instead of leaving it
# pending forever (DependencyNeverSatisfied) on clusters that do not do so by default.
if ! merge_id=$(sbatch "${common[@]}" --job-name=skinsim-sweep-merge \
  --dependency="afterok:$array_id" --kill-on-invalid-dep=yes \
  --output="$log_dir/merge.log" --open-mode=append "${sbatch_extra[@]}" \
  "$job_script" merge "$skinsim" "$out" "${sweep_args[@]}"); then
  scancel "$array_id" 2>/dev/null || true
  die "sbatch of the merge job failed; cancelled the shard array $array_id"
fi
merge_id=${merge_id%%;*}

echo "shards: job array $array_id (tasks 0-$((shards - 1)), logs $log_dir/shard-<task>.log)"
echo "merge:  job $merge_id (after all shards succeed, log $log_dir/merge.log)"
echo "results: $out/results.csv, $out/report.html"

((wait)) || exit 0

# --- Waiting -----------------------------------------------------------------------------

# Quoted command lines, for messages a user may paste.
quoted() {
  local s
  s=$(printf ' %q' "$@")
  echo "${s# }"
}

# Prints "STATE EXITCODE REASON" of one job (EXITCODE as Slurm's code:signal), from
# scontrol while slurmctld remembers the job (MinJobAge), else from sacct; nothing if
# neither knows it.
job_status() {
  local line state code reason
  if line=$(scontrol -o show job "$1" 2>/dev/null) && [[ -n "$line" ]]; then
    line=$(head -n 1 <<<"$line")
    state=$(grep -o ' JobState=[^ ]*' <<<" $line" | head -n 1) || state=""
    code=$(grep -o ' ExitCode=[^ ]*' <<<" $line" | head -n 1) || code=""
    reason=$(grep -o ' Reason=[^ ]*' <<<" $line" | head -n 1) || reason=""
    echo "${state#*=} ${code#*=} ${reason#*=}"
  elif command -v sacct >/dev/null 2>&1 &&
    line=$(sacct -n -X -P -j "$1" -o State,ExitCode,Reason 2>/dev/null | head -n 1) &&
    [[ -n "$line" ]]; then
    IFS='|' read -r state code reason <<<"$line"
    echo "${state%% *} ${code:-0:0} ${reason:-None}"
  fi
}

# Lists the array tasks that did not complete, with the tail of their logs.
report_failed_shards() {
  local lines line task state code
  lines=$(scontrol -o show job "$array_id" 2>/dev/null) ||
    lines=$(sacct -n -X -P -j "$array_id" -o JobID,State,ExitCode 2>/dev/null |
      awk -F'|' '{split($1, a, "_"); printf " ArrayTaskId=%s JobState=%s ExitCode=%s\n", a[2], $2, $3}') ||
    lines=""
  while IFS= read -r line; do
    task=$(grep -o ' ArrayTaskId=[^ ]*' <<<" $line" | head -n 1) || continue
    state=$(grep -o ' JobState=[^ ]*' <<<" $line" | head -n 1) || state=""
    code=$(grep -o ' ExitCode=[^ ]*' <<<" $line" | head -n 1) || code=""
    task=${task#*=} state=${state#*=} code=${code#*=}
    [[ "$state" == COMPLETED ]] && continue
    log "shard $task: $state (exit code $code), log $log_dir/shard-$task.log"
    if [[ "$task" =~ ^[0-9]+$ && -f "$log_dir/shard-$task.log" ]]; then
      tail -n 15 "$log_dir/shard-$task.log" | sed 's/^/    /' >&2
    fi
  done <<<"$lines"
}

trap 'log "stopped waiting; jobs $array_id and $merge_id keep running (scancel $array_id $merge_id stops them)"; exit 130' INT TERM

poll=${SWEEP_POLL_SECONDS:-10}
unknown=0
while :; do
  read -r state code reason <<<"$(job_status "$merge_id")" || true
  case ${state:-} in
    "")
      # Not known (yet, or any more): a few misses are tolerated (slurmctld busy).
      ((++unknown < 6)) || die "Slurm no longer knows the merge job $merge_id (no accounting?): look at $log_dir/merge.log and $out"
      ;;
    PENDING)
      if [[ "$reason" == DependencyNeverSatisfied ]]; then
        scancel "$merge_id" 2>/dev/null || true
        report_failed_shards
        die "a shard of job array $array_id failed, so the merge job $merge_id can never run (cancelled it). Configurations already computed are kept: fix the cause and submit again into $out, or merge what is there: $(quoted "$skinsim" sweep "${sweep_args[@]}" --out "$out" --merge)"
      fi
      ;;
    COMPLETED)
      log "merge job $merge_id completed: $out/results.csv"
      exit 0
      ;;
    CANCELLED*)
      if [[ "$reason" == Dependency* ]]; then
        report_failed_shards
        die "a shard of job array $array_id failed, so Slurm cancelled the merge job $merge_id. Configurations already computed are kept: fix the cause and submit again into $out, or merge what is there: $(quoted "$skinsim" sweep "${sweep_args[@]}" --out "$out" --merge)"
      fi
      die "merge job $merge_id was cancelled (reason $reason); log $log_dir/merge.log"
      ;;
    FAILED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE | PREEMPTED | REVOKED | SPECIAL_EXIT)
      rc=${code%%:*}
      [[ "$rc" =~ ^[0-9]+$ && "$rc" -ne 0 ]] || rc=1
      log "merge job $merge_id ended $state (exit code $code); log $log_dir/merge.log:"
      [[ -f "$log_dir/merge.log" ]] && tail -n 30 "$log_dir/merge.log" | sed 's/^/    /' >&2
      exit "$rc"
      ;;
    *) ;; # RUNNING, CONFIGURING, COMPLETING, REQUEUED, SUSPENDED, ...
  esac
  [[ -n "${state:-}" ]] && unknown=0
  sleep "$poll"
done
