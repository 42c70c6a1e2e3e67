#!/usr/bin/env python3
"""The emulator's frame time beside Mesa llvmpipe's for the same frame (issues 18, 19).

Runs bench_frame's BM_SkinFrame (the default 2048x1536 frame: shadow map, irradiance, two
blurs, skin, with every counter and the texture-cache model) and, with the same host thread
count, two llvmpipe anchors (rendering only):
- replay: that very frame, exported by `skinsim export --glsl es300 --data` and replayed by
  gles_replay (the same shaders, meshes, textures and passes; docs/validation.md);
- skinbench: the shared benchmark of an equivalent four-pass frame
  (../shared/anchors/llvmpipe/README.md), when it was built.
It alternates them ROUNDS times so that a noisy shared machine slows all alike, and prints
each one's median and the ratio skinsim / replay.
Both use every host thread they are given: skinsim's tiles shade on any thread and each
emulated core's texture cache replays its tiles' requests in order (docs/performance-log.md,
"Host threads beyond the emulated cores"). BUILD_DIR may be a profile-guided build
(scripts/build-pgo.sh) holding gles_replay and llvmpipe_skinbench, or links to them.

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
import tempfile


def llvmpipe_ms(program, threads, frames):
    env = dict(os.environ, EGL_PLATFORM="surfaceless", LIBGL_ALWAYS_SOFTWARE="1",
               GALLIUM_DRIVER="llvmpipe", LP_NUM_THREADS=str(threads))
    out = subprocess.run([program, "3", str(frames)], env=env, check=True,
                         capture_output=True, text=True).stdout
    match = re.search(r"A full frame\s+median\s+([0-9.]+) ms", out)
    if not match:
        sys.exit(f"bench_vs_llvmpipe: no 'A full frame' median in {program}'s output:\n{out}")
    return float(match.group(1))


def replay_ms(program, export, threads, frames):
    env = dict(os.environ, LIBGL_ALWAYS_SOFTWARE="1", GALLIUM_DRIVER="llvmpipe",
               LP_NUM_THREADS=str(threads))
    out = subprocess.run([program, export, "--time", str(frames)], env=env, check=True,
                         capture_output=True, text=True).stdout
    match = re.search(r"llvmpipe frame: ([0-9.]+) ms", out)
    if not match:
        sys.exit(f"bench_vs_llvmpipe: no 'llvmpipe frame' time in {program}'s output:\n{out}")
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
    parser.add_argument("--rounds", type=int, default=3, help="alternations of the programs")
    parser.add_argument("--frames", type=int, default=10, help="llvmpipe's timed frames per run")
    args = parser.parse_args()
    bench = os.path.join(args.build_dir, "bench", "bench_frame")
    skinsim = os.path.join(args.build_dir, "skinsim")
    replay = os.path.join(args.build_dir, "gles_replay")
    skinbench = os.path.join(args.build_dir, "bench", "llvmpipe_skinbench")
    for program in (bench, skinsim, replay):
        if not os.access(program, os.X_OK):
            sys.exit(f"bench_vs_llvmpipe: {program} is missing: build with benchmarks on and "
                     "libegl-dev, libgles-dev installed (scripts/install-deps.sh)")
    has_skinbench = os.access(skinbench, os.X_OK)
    with tempfile.TemporaryDirectory() as tmp:
        export = os.path.join(tmp, "frame")
        subprocess.run([skinsim, "export", "--glsl", "es300", "--data", "--out", export],
                       check=True, stdout=subprocess.DEVNULL)
        print(f"{'threads':>7}  {'skinsim ms':>10}  {'replay ms':>9}  {'ratio':>5}"
              + (f"  {'skinbench ms':>12}" if has_skinbench else "")
              + f"  (medians of {args.rounds} alternating runs: llvmpipe {args.frames} frames, "
              "skinsim frames for >= 3 s)")
        for threads in (int(t) for t in args.threads.split(",")):
            emulated, replayed, anchored = [], [], []
            for _ in range(args.rounds):
                replayed.append(replay_ms(replay, export, threads, args.frames))
                if has_skinbench:
                    anchored.append(llvmpipe_ms(skinbench, threads, args.frames))
                emulated.append(skinsim_ms(bench, threads))
            e, r = statistics.median(emulated), statistics.median(replayed)
            print(f"{threads:>7}  {e:>10.1f}  {r:>9.1f}  {e / r:>5.2f}"
                  + (f"  {statistics.median(anchored):>12.1f}" if has_skinbench else ""),
                  flush=True)


if __name__ == "__main__":
    main()
