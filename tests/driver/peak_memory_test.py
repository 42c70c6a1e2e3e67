#!/usr/bin/env python3
"""Peak memory of the two main jobs at their defaults stays under 830 MiB: `skinsim run` (the
2048x1536 frame, its reference and metrics) and `skinsim sweep` (the 4x4 sweep with its
reference, metrics, comparisons, crops, charts and report). Each runs as a child process and
its peak resident set comes from wait4's rusage. Measured on 2 threads: run 691 MiB, sweep 658
MiB; the limit is 20% above the larger. It moves a little from run to run with the threads'
timing, far less than a time does with the machine's load, so a fixed limit is a fair test. The charts need an X display: the sweep
runs under xvfb-run when there is one to start (as the chart tests do), else without charts.

Usage: peak_memory_test.py SKINSIM OUT_DIR
"""
import os
import shutil
import subprocess
import sys

LIMIT_KB = 830 * 1024  # ru_maxrss is in KiB on Linux


def peak_kb(command):
    """Runs `command` to completion and returns its peak resident set in KiB (the largest of
    the process and the descendants it waited for)."""
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        sys.exit(f"{' '.join(command)} failed with status {child.returncode}")
    return usage.ru_maxrss


def main():
    skinsim, out = sys.argv[1], sys.argv[2]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    xvfb_run = shutil.which("xvfb-run")
    sweep = [skinsim, "sweep", "--out", os.path.join(out, "sweep")]
    jobs = {
        "run": [skinsim, "run", "--out", os.path.join(out, "run")],
        "sweep": ([xvfb_run, "-a"] + sweep + ["--require-charts"]) if xvfb_run
        else sweep + ["--no-charts"],
    }
    over = []
    for name, command in jobs.items():
        kb = peak_kb(command)
        print(f"{name}: peak resident set {kb / 1024:.0f} MiB (limit {LIMIT_KB // 1024} MiB)")
        if kb >= LIMIT_KB:
            over.append(f"{name} ({kb / 1024:.0f} MiB)")
    if over:
        sys.exit(f"over {LIMIT_KB // 1024} MiB at peak: {', '.join(over)}")
    shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    main()
