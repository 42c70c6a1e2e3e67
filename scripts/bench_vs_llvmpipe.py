#!/usr/bin/env python3
"""The emulator's frame time beside Mesa llvmpipe's for the same frame (issue 19).

Runs bench_frame's BM_SkinFrame (the default 2048x1536 frame: irradiance, two blurs, skin,
with every counter and the texture-cache model) and llvmpipe_skinbench (the same four passes
on llvmpipe, rendering only: ../shared/anchors/llvmpipe/README.md) with the same host
thread count, alternating the two ROUNDS times so that a noisy shared machine slows both
alike, and prints each one's median and the ratio skinsim / llvmpipe.
Host threads beyond the device's emulated cores (4 on the iPad 4) are not used by skinsim
(docs/performance.md says why), so counts above that measure llvmpipe's scaling alone.

Usage: scripts/bench_vs_llvmpipe.py [BUILD_DIR=build] [--threads 1,2] [--rounds 3]
       [--frames 10]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys


def llvmpipe_ms(program, threads, frames):
    env = dict(os.environ, EGL_PLATFORM="surfaceless", LIBGL_ALWAYS_SOFTWARE="1",
               GALLIUM_DRIVER="llvmpipe", LP_NUM_THREADS=str(threads))
    out = subprocess.run([program, "3", str(frames)], env=env, check=True,
                         capture_output=True, text=True).stdout
    match = re.search(r"A full frame\s+median\s+([0-9.]+) ms", out)
    if not match:
        sys.exit(f"bench_vs_llvmpipe: no 'A full frame' median in {program}'s output:\n{out}")
    return float(match.group(1))


def skinsim_ms(program, threads):
    out = subprocess.run([program, f"--benchmark_filter=^BM_SkinFrame/{threads}/",
                          "--benchmark_format=json"],
                         check=True, capture_output=True, text=True).stdout
    runs = [b for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    if len(runs) != 1:
        sys.exit(f"bench_vs_llvmpipe: expected one BM_SkinFrame/{threads} result from {program}")
    return runs[0]["real_time"]  # ms (the benchmark's unit), mean over its >= 3 s of frames


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build_dir", nargs="?", default="build")
    parser.add_argument("--threads", default="1,2", help="host thread counts, e.g. 1,2,4")
    parser.add_argument("--rounds", type=int, default=3, help="alternations of the two")
    parser.add_argument("--frames", type=int, default=10, help="llvmpipe's timed frames per run")
    args = parser.parse_args()
    bench = os.path.join(args.build_dir, "bench", "bench_frame")
    anchor = os.path.join(args.build_dir, "bench", "llvmpipe_skinbench")
    for program in (bench, anchor):
        if not os.access(program, os.X_OK):
            sys.exit(f"bench_vs_llvmpipe: {program} is missing: build with benchmarks on "
                     "(the anchor also needs ../shared/anchors/llvmpipe and libegl-dev, "
                     "libgles-dev; scripts/install-deps.sh installs them)")
    print(f"{'threads':>7}  {'skinsim ms':>10}  {'llvmpipe ms':>11}  {'ratio':>5}  "
          f"(medians of {args.rounds} alternating runs: llvmpipe {args.frames} frames, "
          "skinsim frames for >= 3 s)")
    for threads in (int(t) for t in args.threads.split(",")):
        skinsim, llvmpipe = [], []
        for _ in range(args.rounds):
            llvmpipe.append(llvmpipe_ms(anchor, threads, args.frames))
            skinsim.append(skinsim_ms(bench, threads))
        s, l = statistics.median(skinsim), statistics.median(llvmpipe)
        print(f"{threads:>7}  {s:>10.1f}  {l:>11.1f}  {s / l:>5.2f}", flush=True)


if __name__ == "__main__":
    main()
