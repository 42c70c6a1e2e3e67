#!/usr/bin/env python3
"""The llvmpipe cross-check (docs/validation.md): every registered technique is exported
(GLSL ES 3.00 with its data), replayed pass by pass on Mesa llvmpipe by gles_replay, and every
target must agree with the emulator's within the tolerances below.

Usage: llvmpipe_crosscheck_test.py SKINSIM GLES_REPLAY OUT_DIR

Tolerances, and what they allow for (docs/validation.md, "Cross-check on llvmpipe"):
- depth (the shadow map, compared by gl_FragCoord.z): at most 0.1% of pixels more than 1e-4
  apart. Both rasterise with 8 sub-pixel bits and the same fill rule; the emulator stores
  16-bit depth (half a step is 7.6e-6).
- colour, per technique: PSNR at most 3 dB below (an RMS difference at most 1.41 times)
  and at most twice the fraction of pixels more than 1.5 levels (of 255) apart of what its
  worst colour pass measured (MEASURED below). llvmpipe filters with 8-bit weights where the emulator uses float; it takes the mip
  LOD from a 2x2 quad's differences where the emulator uses the analytic derivatives; its
  float arithmetic is ordered differently, which moves the per-pixel noise of the SSAO and
  dipole rotations; and pixels on a silhouette can fall either way of an edge.
A wrong binding, a wrong state or a shader that computes something else is far outside
these (a LUT bound in place of another gave 15 dB and 57% of pixels). A technique with no
measurement fails: run the test, read its worst pass and add it. The test shows it can
fail: mobile's skin shader edited to read the normal map as albedo must break them.
"""
import json
import os
import shutil
import subprocess
import sys

RESOLUTION = "128x96"
# The worst colour pass of each technique: (PSNR in dB, fraction of pixels differing), at
# 128x96 on llvmpipe (Mesa 22.3.6, LLVM 15, 256-bit vectors). Its skin pass, except urp's
# SSAO (the per-pixel rotation noise) for the fraction.
MEASURED = {
    "mobile": (56.62, 0.00708),
    "lod": (57.17, 0.00423),
    "preintegrated": (57.21, 0.00513),
    "wrap": (56.80, 0.00366),
    "burley": (57.70, 0.00374),
    "ssss": (57.69, 0.00391),
    "texture-space": (57.62, 0.00342),
    "dipole": (57.74, 0.00366),
    "urp": (53.77, 0.02458),
}
PSNR_MARGIN_DB = 3.0
DIFFERING_FACTOR = 2.0
MAX_DIFFERING_DEPTH = 0.001


def techniques(skinsim):
    listing = subprocess.run([skinsim, "techniques", "--json"], check=True,
                             capture_output=True, text=True).stdout
    return [t["name"] for t in json.loads(listing)]


def check_replay(replay, export, result_file, env, label, technique):
    """(failures, colour PSNRs) of one replay against the technique's tolerances."""
    measured_db, measured_fraction = MEASURED[technique]
    min_psnr_db = measured_db - PSNR_MARGIN_DB
    max_differing = measured_fraction * DIFFERING_FACTOR
    run = subprocess.run([replay, export, "--result", result_file], env=env,
                         capture_output=True, text=True)
    print(f"== {label}\n{run.stdout}{run.stderr}", end="")
    if run.returncode != 0:
        return [f"{label}: gles_replay exited {run.returncode}"], []
    failures, psnrs = [], []
    if "llvmpipe" not in run.stdout:
        failures.append(f"{label}: not replayed on llvmpipe")
    with open(result_file) as f:
        for p in json.load(f)["passes"]:
            where = f"{label} {p['pass']}"
            if p["depth"]:
                if p["differing_fraction"] > MAX_DIFFERING_DEPTH:
                    failures.append(f"{where}: {p['differing_fraction']:.2%} of depth differs")
                continue
            psnr = float("inf") if p["psnr_db"] == "inf" else p["psnr_db"]
            if psnr < min_psnr_db:
                failures.append(f"{where}: PSNR {psnr:.2f} dB < {min_psnr_db:.2f}")
            if p["differing_fraction"] > max_differing:
                failures.append(f"{where}: {p['differing_fraction']:.2%} of pixels differ "
                                f"(at most {max_differing:.2%})")
            psnrs.append(psnr)
    return failures, psnrs


def main():
    skinsim, replay, out_dir = sys.argv[1:4]
    env = dict(os.environ, LIBGL_ALWAYS_SOFTWARE="1", GALLIUM_DRIVER="llvmpipe")
    failures, psnrs = [], []
    for technique in techniques(skinsim):
        if technique not in MEASURED:
            failures.append(f"{technique}: no measured agreement in MEASURED")
            continue
        export = os.path.join(out_dir, technique)
        shutil.rmtree(export, ignore_errors=True)
        # A small texture-space atlas keeps the exported targets small; the passes are the same.
        subprocess.run([skinsim, "export", "--technique", technique, "--resolution", RESOLUTION,
                        "--texture-space-size", "256", "--glsl", "es300", "--data",
                        "--out", export], check=True, stdout=subprocess.DEVNULL)
        result_file = os.path.join(out_dir, f"{technique}.json")
        f, p = check_replay(replay, export, result_file, env, technique, technique)
        failures += f
        psnrs += p
        if technique == "mobile":
            failures += mutation_is_caught(replay, export, result_file, env)
            failures += multisampled_pass_is_refused(replay, export, env)
        shutil.rmtree(export)  # tens of MB of data per technique
    for failure in failures:
        print("FAIL:", failure)
    print(f"{len(psnrs)} colour targets compared, worst PSNR {min(psnrs):.2f} dB; "
          f"{len(failures)} failures")
    return 1 if failures or not psnrs else 0


def mutation_is_caught(replay, export, result_file, env):
    """The check can fail: the skin shader reading the normal map as albedo must be out of
    tolerance (the kind of binding bug the cross-check exists for)."""
    shader = os.path.join(export, "shaders", "skin_fs.frag")
    with open(shader) as f:
        source = f.read()
    mutated = source.replace("texture(s0,", "texture(s1,")
    if mutated == source:
        return ["mutation: skin_fs.frag has no read of s0 to swap"]
    with open(shader, "w") as f:
        f.write(mutated)
    failures, _ = check_replay(replay, export, result_file, env, "mobile, albedo read from s1",
                               "mobile")
    if not any(" skin:" in failure for failure in failures):
        return ["mutation: the skin pass with the normal map as albedo passed the tolerances"]
    return []


def multisampled_pass_is_refused(replay, export, env):
    """A pass exported with MSAA samples (skinsim export --msaa 4) is refused with a message
    naming it: the replay draws 1x only, and a 1x image against a resolved 4x one would
    report a difference that is not a bug."""
    frame_file = os.path.join(export, "frame.json")
    with open(frame_file) as f:
        frame = json.load(f)
    skin = [p for p in frame["passes"] if p["name"] == "skin"]
    if not skin:
        return ["multisampled: the export has no skin pass"]
    skin[0]["samples"] = 4
    with open(frame_file, "w") as f:
        json.dump(frame, f)
    run = subprocess.run([replay, export], env=env, capture_output=True, text=True)
    if run.returncode != 2 or "pass 'skin' is multisampled (4 samples)" not in run.stderr:
        return [f"multisampled: gles_replay exited {run.returncode}: {run.stderr.strip()}"]
    return []


if __name__ == "__main__":
    sys.exit(main())
