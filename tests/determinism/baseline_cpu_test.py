#!/usr/bin/env python3
"""The same files from `skinsim run` on this processor and as on an x86-64 processor with
neither AVX nor FMA: the default frame at 2048x1536 with its reference and metrics (every
AVX path: the reference's diffusion, FLIP's and SSIM's filters) is rendered twice, the second
time with SKINSIM_SIMD=sse2 (skinsim's SSE2 baselines, util/simd_dispatch.h) and glibc's
libm on its SSE2 variants (GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA: glibc otherwise picks
FMA versions of expf, powf, sinf ... where the processor has FMA, and they differ from the SSE2
ones in rare last bits). Every file written (PNGs, result.json, timeline.svg) must be
byte-identical. On a processor without AVX both runs take the same paths, so the test says so
and exits 77, which CTest reports as skipped (SKIP_RETURN_CODE), rather than passing.

Usage: baseline_cpu_test.py SKINSIM OUT_DIR
"""
import os
import shutil
import subprocess
import sys

BASELINE_ENV = {"SKINSIM_SIMD": "sse2", "GLIBC_TUNABLES": "glibc.cpu.hwcaps=-AVX2,-FMA"}
SKIPPED = 77


def cpu_flags(cpuinfo="/proc/cpuinfo"):
    """The first processor's feature flags, as the kernel reports them (it leaves out AVX
    where the operating system does not save the AVX registers)."""
    try:
        with open(cpuinfo) as f:
            for line in f:
                if line.startswith("flags"):
                    return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def run(skinsim, out_dir, extra_env):
    shutil.rmtree(out_dir, ignore_errors=True)
    env = dict(os.environ)
    env.pop("SKINSIM_SIMD", None)
    env.pop("GLIBC_TUNABLES", None)
    env.update(extra_env)
    subprocess.run([skinsim, "run", "--threads", "2", "--out", out_dir], check=True,
                   stdout=subprocess.DEVNULL, env=env)
    return sorted(os.listdir(out_dir))


def main():
    skinsim, out = sys.argv[1], sys.argv[2]
    if "avx" not in cpu_flags():
        print("skipped: this processor has no AVX, so its paths are the baseline's")
        sys.exit(SKIPPED)
    here, baseline = os.path.join(out, "this_cpu"), os.path.join(out, "baseline_cpu")
    files = run(skinsim, here, {})
    baseline_files = run(skinsim, baseline, BASELINE_ENV)
    if files != baseline_files:
        sys.exit(f"different files written: {files} against {baseline_files}")
    differing = []
    for name in files:
        with open(os.path.join(here, name), "rb") as a, open(os.path.join(baseline, name), "rb") as b:
            if a.read() != b.read():
                differing.append(name)
    if differing:
        sys.exit(f"files that differ between this processor's paths and the baseline's: "
                 f"{differing} (in {here} and {baseline})")
    print(f"{len(files)} files byte-identical: {', '.join(files)}")


if __name__ == "__main__":
    main()
