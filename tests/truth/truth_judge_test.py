"""Judging with a truth (docs/validation.md, "Judging with the truth").
Usage: truth_judge_test.py CASE SKINSIM SKINSIM_EXR WORKDIR

  store       `run --truth cached` keeps the truth it renders in the truth store and reuses it,
              under a key naming `blender --version` (another Blender's is a miss); a truth
              named by --truth-samples/--truth-seed is only looked up (exit 2, naming the
              `skinsim truth` command, when missing) and found once that command kept it;
              a tampered image, a marker that is not JSON or is a symlink, an image replaced by
              a symlink: each is discarded with a note and rendered again; SKINSIM_CACHE_DIR=off
              renders every time. Blender is a stand-in script here (SKINSIM_BLENDER) that
              writes a seed-dependent image and counts its calls: no Blender needed.
  file        `run --truth FILE`: a PNG and an EXR of the view are judged (the reference as its
              own truth is identical and not visible); no measured floor is stated as such; a
              missing file, a file that is no image and one of another size exit 2, named,
              before the frame is rendered.
  directory   `run --truth DIR` of a directory `skinsim truth` wrote (stand-in Blender): with
              --noise-floor its two seeds measure the floor, and the frame is judged above it;
              without, one image, no floor; a truth.json without its seed exits 2, named.
  compare     `compare A B --truth cached` judges two runs by the truth both were judged with
              (stand-in Blender), in the terminal and compare.json, or by that view's truth
              of --truth-samples/--truth-seed; `--truth FILE` too; runs
              judged by no or by different truths, and a missing file, exit 2, named.
  sweep_file  `sweep --truth FILE` of two configurations, the truth being one of their own
              frames: per-configuration figures against it in results.json/csv, and the
              recommendation and that frame's verdict change to it; a missing truth exits 2
              before the sweep.
  sweep_store `sweep --truth cached` of two groups with the stand-in Blender: one
              `blender --version` a process, report.html shows each group's truth in the
              slider and crops and says what it judged; a missing named truth exits 2.
  sweep       a truth-judged sweep of two configurations with Blender Cycles (`--truth
              cached`, 64x48; exit 77 where Blender is not installed).
"""
import glob
import json
import os
import shutil
import struct
import sys

from truth_common import fail, run_with

CASE, SKINSIM, EXR_TOOL, WORK = sys.argv[1:5]
ENV = dict(os.environ, SKINSIM_CACHE_DIR=f"{WORK}/cache", SKINSIM_EXR_TOOL=EXR_TOOL)
SIZE = ["--resolution", "32x24"]

# Stands in for `blender -b ... -P cycles_render.py -- scene.json out.exr seed threads`: a flat
# grey image a little brighter for each seed, written as OpenEXR by skinsim-exr; and for
# `blender --version`, whose first line ($STAND_IN_VERSION) is in the truth's key.
FAKE_BLENDER = f"""#!/usr/bin/env python3
import json, os, struct, subprocess, sys
if sys.argv[1:] == ["--version"]:
    with open({WORK!r} + "/version_calls", "a") as f:
        f.write("version\\n")
    print("Blender " + os.environ.get("STAND_IN_VERSION", "3.4.1 (stand-in)"))
    print("\\tbuild date: today")
    sys.exit(0)
args = sys.argv[sys.argv.index("--") + 1:]
scene, exr, seed = json.load(open(args[0])), args[1], int(args[2])
w, h = scene["width"], scene["height"]
with open(exr + ".raw", "wb") as f:
    f.write(b"SKF32RGB" + struct.pack("<2I", w, h))
    f.write(struct.pack(f"<{{3 * w * h}}f", *[0.2 + 0.01 * seed + 0.002 * (i % 7) for i in range(3 * w * h)]))
subprocess.run([{EXR_TOOL!r}, "from-raw", exr + ".raw", exr], check=True)
with open({WORK!r} + "/blender_calls", "a") as f:
    f.write(f"{{seed}}\\n")
"""


def run(*args, expect=0):
    return run_with(ENV, *args, expect=expect)


def blender_calls():
    path = f"{WORK}/blender_calls"
    calls = open(path).read().split() if os.path.exists(path) else []
    if os.path.exists(path):
        os.remove(path)
    return calls


def version_calls():
    path = f"{WORK}/version_calls"
    calls = len(open(path).read().split()) if os.path.exists(path) else 0
    if os.path.exists(path):
        os.remove(path)
    return calls


def judged(out):
    with open(f"{out}/result.json") as f:
        return json.load(f)["truth"]


def run_cached(note=None):
    """One `run --truth cached`; `note`: a word the discard note must hold, or None for none."""
    p = run(SKINSIM, "run", *SIZE, "--truth", "cached", "--out", f"{WORK}/run")
    if note is None and "discarded" in p.stderr:
        fail(f"an unexpected discard: {p.stderr}")
    if note is not None and not ("discarded" in p.stderr and note in p.stderr):
        fail(f"the discard note does not say '{note}': {p.stderr}")
    return p


def use_fake_blender():
    fake = f"{WORK}/fake-blender"
    with open(fake, "w") as f:
        f.write(FAKE_BLENDER)
    os.chmod(fake, 0o755)
    ENV["SKINSIM_BLENDER"] = fake


def test_store():
    use_fake_blender()

    p = run_cached()
    if blender_calls() != ["1", "2"]:
        fail("a missing truth was not rendered with seeds 1 and 2")
    truth = judged(f"{WORK}/run")
    floor = truth["noise_floor"]
    # The stand-in's seeds differ by 0.01 everywhere: a measurable floor, never visible.
    if not floor["measured"] or floor["skin"]["visible_px"] != 0 or not floor["skin"]["flip"] > 0:
        fail(f"the noise floor: {floor}")
    for image in ("frame", "reference"):
        if "visible" not in truth[image]["skin"] or image not in p.stdout:
            fail(f"the {image} is not judged against the truth: {truth}")
    if truth["source"] != "rendered" or "noise floor" not in p.stdout or "Blender 3.4.1" not in p.stdout:
        fail(f"where the truth came from / its floor is not stated: {truth['source']}\n{p.stdout}")
    (marker,) = glob.glob(f"{WORK}/cache/truths/truth_*.json")
    stem = marker[:-len(".json")]

    run_cached()
    if blender_calls() or judged(f"{WORK}/run")["source"] != "store":
        fail("a kept truth was rendered again")
    if judged(f"{WORK}/run")["frame"] != truth["frame"]:
        fail("the kept truth judges differently from the rendered one")

    # Same size, other pixels: the digest tells.
    shutil.copy(f"{WORK}/run/frame.png", stem + ".png")
    run_cached("not the ones its marker describes")
    if blender_calls() != ["1", "2"]:
        fail("a tampered truth was used")
    with open(marker, "w") as f:
        f.write("{not json")
    run_cached("truth marker")
    blender_calls()
    os.remove(stem + "_second.png")
    os.symlink(f"{WORK}/run/frame.png", stem + "_second.png")
    run_cached("not regular files")
    blender_calls()
    if os.path.islink(stem + "_second.png"):
        fail("the planted symlink is still in the store")
    shutil.move(marker, f"{WORK}/marker.json")
    os.symlink(f"{WORK}/marker.json", marker)
    run_cached("truth marker")
    blender_calls()
    version_calls()
    run_cached()
    if blender_calls():
        fail("the truth kept after the discards is not reused")

    if judged(f"{WORK}/run")["key"]["blender"] != "Blender 3.4.1 (stand-in)" or version_calls() != 1:
        fail("the key does not name the Blender of `blender --version`, asked once a run")
    # Another Blender: its truth is another judge, a miss, rendered again and kept beside.
    ENV["STAND_IN_VERSION"] = "4.2.0 (stand-in)"
    run_cached()
    if blender_calls() != ["1", "2"] or judged(f"{WORK}/run")["key"]["blender"] != "Blender 4.2.0 (stand-in)":
        fail("a truth of another Blender was reused")
    del ENV["STAND_IN_VERSION"]
    run_cached()
    if blender_calls():
        fail("the first Blender's truth is no longer found")

    # A named truth is only looked up: missing, exit 2 naming the options and the command.
    named = ["--truth-samples", "8", "--truth-seed", "5"]
    p = run(SKINSIM, "run", *SIZE, "--truth", "cached", *named, "--out", f"{WORK}/n", expect=2)
    for words in ("--truth-samples 8 --truth-seed 5", "8 samples and seeds 5 and 6",
                  "skinsim truth --resolution 32x24 --samples 8 --seed 5 --noise-floor"):
        if words not in p.stderr:
            fail(f"a missing named truth: the error does not say '{words}': {p.stderr}")
    if blender_calls() or os.path.exists(f"{WORK}/n"):
        fail("a missing named truth was rendered, or left an output directory")
    p = run(SKINSIM, "run", *SIZE, "--truth", f"{WORK}/run/frame.png", "--truth-samples", "8",
            "--out", f"{WORK}/n", expect=2)
    if "only with --truth cached" not in p.stderr:
        fail(f"--truth-samples with a file: {p.stderr}")
    # `skinsim truth --samples 8 --seed 5 --noise-floor` keeps it where the run then finds it.
    run(SKINSIM, "truth", *SIZE, "--samples", "8", "--seed", "5", "--noise-floor",
        "--out", f"{WORK}/t8")
    if blender_calls() != ["5", "6"]:
        fail("skinsim truth did not render seeds 5 and 6")
    run(SKINSIM, "run", *SIZE, "--truth", "cached", *named, "--out", f"{WORK}/n")
    key = judged(f"{WORK}/n")["key"]
    if blender_calls() or (key["samples"], key["seed"]) != (8, 5):
        fail(f"the named truth kept by `skinsim truth` was not used: {key}")

    ENV["SKINSIM_CACHE_DIR"] = "off"
    run_cached()
    run_cached()
    if blender_calls() != ["1", "2", "1", "2"]:
        fail("with the store off the truth is not rendered each time")


def test_file():
    ENV["SKINSIM_BLENDER"] = f"{WORK}/no-blender"  # a file truth needs no Blender
    run(SKINSIM, "run", *SIZE, "--out", f"{WORK}/first")
    # The reference as the truth: a PNG is taken as seen, so it is its own truth exactly.
    p = run(SKINSIM, "run", *SIZE, "--truth", f"{WORK}/first/reference.png", "--out", f"{WORK}/png")
    truth = judged(f"{WORK}/png")
    if truth["reference"]["skin"]["psnr_db"] != "inf" or truth["reference"]["skin"]["visible"]:
        fail(f"the reference against itself: {truth['reference']}")
    if truth["noise_floor"]["measured"] or "not measured" not in p.stdout:
        fail(f"a single image's floor is not stated as not measured: {truth['noise_floor']}\n{p.stdout}")
    # A linear EXR of the same view: the reference's pixels decoded from sRGB.
    run(EXR_TOOL, "to-raw", f"{WORK}/first/reference.png", f"{WORK}/ref.raw")
    with open(f"{WORK}/ref.raw", "rb") as f:
        data = f.read()
    values = struct.unpack(f"<{(len(data) - 16) // 4}f", data[16:])
    linear = [v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4 for v in values]
    with open(f"{WORK}/lin.raw", "wb") as f:
        f.write(data[:16] + struct.pack(f"<{len(linear)}f", *linear))
    run(EXR_TOOL, "from-raw", f"{WORK}/lin.raw", f"{WORK}/truth.exr")
    run(SKINSIM, "run", *SIZE, "--truth", f"{WORK}/truth.exr", "--out", f"{WORK}/exr")
    skin = judged(f"{WORK}/exr")["reference"]["skin"]
    if not (skin["psnr_db"] == "inf" or skin["psnr_db"] > 50.0) or skin["visible_px"] != 0:
        fail(f"the reference against its linear EXR (8-bit rounding only): {skin}")

    with open(f"{WORK}/not-an-image.exr", "w") as f:
        f.write("hello")
    for truth, words in ((f"{WORK}/nowhere.exr", ["nowhere.exr", "no such"]),
                         (f"{WORK}/not-an-image.exr", ["--truth", "not-an-image.exr"]),
                         (f"{WORK}/first/reference.png", ["32x24", "48x36", "--resolution"])):
        size = ["--resolution", "48x36"] if "reference" in truth else SIZE
        p = run(SKINSIM, "run", *size, "--truth", truth, "--out", f"{WORK}/bad", expect=2)
        if not all(w in p.stderr for w in words) or "Traceback" in p.stderr:
            fail(f"--truth {truth}: the error does not say {words}: {p.stderr}")
        if os.path.exists(f"{WORK}/bad"):
            fail("a refused truth left an output directory")


def test_directory():
    use_fake_blender()
    truth = f"{WORK}/truth"
    run(SKINSIM, "truth", *SIZE, "--samples", "8", "--noise-floor", "--out", truth)
    if blender_calls() != ["1", "2"]:
        fail("skinsim truth --noise-floor did not render seeds 1 and 2")
    p = run(SKINSIM, "run", *SIZE, "--truth", truth, "--out", f"{WORK}/dir")
    judged_by = judged(f"{WORK}/dir")
    floor = judged_by["noise_floor"]
    # The stand-in's seeds differ by 0.01 everywhere: a measured floor, never visible.
    if not floor["measured"] or not floor["skin"]["flip"] > 0 or floor["skin"]["visible_px"] != 0:
        fail(f"a truth directory's two seeds do not make the floor: {floor}")
    if (judged_by["source"], judged_by["samples"], judged_by["second_seed"]) != ("directory", 8, 2):
        fail(f"where the truth came from: {judged_by}")
    if "8 samples, seeds 1 and 2" not in p.stdout or blender_calls():
        fail(f"the run does not say which truth judged, or rendered one:\n{p.stdout}")

    run(SKINSIM, "truth", *SIZE, "--samples", "8", "--out", f"{WORK}/one")
    blender_calls()
    p = run(SKINSIM, "run", *SIZE, "--truth", f"{WORK}/one", "--out", f"{WORK}/one_run")
    if judged(f"{WORK}/one_run")["noise_floor"]["measured"] or "no second seed" not in p.stdout:
        fail(f"a truth directory of one seed is not stated as such:\n{p.stdout}")

    with open(f"{truth}/truth.json", "w") as f:
        json.dump({"samples": 8}, f)
    p = run(SKINSIM, "run", *SIZE, "--truth", truth, "--out", f"{WORK}/bad", expect=2)
    if "truth.json" not in p.stderr or "'seed'" not in p.stderr or os.path.exists(f"{WORK}/bad"):
        fail(f"a truth.json without its seed: {p.stderr}")


def test_compare():
    use_fake_blender()
    a, b, other = f"{WORK}/a", f"{WORK}/b", f"{WORK}/other"
    run(SKINSIM, "run", *SIZE, "--truth", "cached", "--out", a)
    run(SKINSIM, "run", *SIZE, "--scale", "0.25", "--truth", "cached", "--out", b)
    if blender_calls() != ["1", "2"]:
        fail("two runs of one view did not share one truth")
    p = run(SKINSIM, "compare", a, b, "--truth", "cached", "--out", f"{WORK}/cmp", expect=1)
    with open(f"{WORK}/cmp/compare.json") as f:
        truth = json.load(f)["truth"]
    closer = "a" if truth["a"]["skin"]["flip"] < truth["b"]["skin"]["flip"] else "b"
    if truth["closer"] != closer or not truth["noise_floor"]["measured"]:
        fail(f"compare.json's truth: {truth}")
    for line in ("A vs truth: skin PSNR", "B vs truth: skin PSNR", "noise floor: skin"):
        if line not in p.stdout:
            fail(f"compare does not print '{line}':\n{p.stdout}")
    # The same view's truth of other samples: missing, exit 2 naming the options; once
    # `skinsim truth` has kept it, both runs are judged by it.
    named = ["--truth-samples", "8", "--truth-seed", "3"]
    p = run(SKINSIM, "compare", a, b, "--truth", "cached", *named, expect=2)
    if "--truth-samples 8 --truth-seed 3" not in p.stderr or "skinsim truth" not in p.stderr:
        fail(f"compare of a missing named truth: {p.stderr}")
    run(SKINSIM, "truth", *SIZE, "--samples", "8", "--seed", "3", "--noise-floor", "--out",
        f"{WORK}/t8")
    blender_calls()
    p = run(SKINSIM, "compare", a, b, "--truth", "cached", *named, "--out", f"{WORK}/cmp8",
            expect=1)
    with open(f"{WORK}/cmp8/compare.json") as f:
        key = json.load(f)["truth"]["truth"]["key"]
    if (key["samples"], key["seed"], key["second_seed"]) != (8, 3, 4) or blender_calls():
        fail(f"compare did not judge by the kept 8-sample truth: {key}")
    p = run(SKINSIM, "compare", a, b, "--truth", f"{a}/reference.png", expect=1)
    if "noise floor: not measured" not in p.stdout:
        fail(f"a file's floor is not stated: {p.stdout}")
    run(SKINSIM, "run", *SIZE, "--out", other)
    run(SKINSIM, "run", "--resolution", "48x36", "--truth", "cached", "--out", f"{WORK}/small")
    run(SKINSIM, "run", *SIZE, "--light-azimuth", "30", "--truth", "cached", "--out", f"{WORK}/lit")
    for args, words in (([a, other, "--truth", "cached"], [other, "not judged by a cached truth"]),
                        ([a, f"{WORK}/small", "--truth", "cached"], ["32x24", "48x36"]),
                        ([a, f"{WORK}/lit", "--truth", "cached"], ["different truths"]),
                        ([a, b, "--truth", f"{WORK}/nowhere.png"], ["nowhere.png", "no such"])):
        p = run(SKINSIM, "compare", *args, "--out", f"{WORK}/bad", expect=2)
        if not all(w in p.stderr for w in words) or os.path.exists(f"{WORK}/bad"):
            fail(f"compare {args}: the error does not say {words}, or --out was written: {p.stderr}")


SWEEP = ["sweep", "--resolutions", "64x48", "--scales", "1,0.25", "--luts", "32x128", "--no-charts"]


def sweep_truth(out, floor):
    """results.json, checked for the truth's columns (the floor's only with a measured floor)."""
    with open(f"{out}/results.json") as f:
        results = json.load(f)
    with open(f"{out}/results.csv") as f:
        header = f.readline().strip().split(",")
    # PSNR is left out where it is infinite (a frame identical to the truth).
    columns = ["truth_ssim_skin", "truth_flip_skin", "truth_visible_skin",
               "truth_visible_skin_pct", "truth_visible_frame_px"]
    if ("truth_floor_flip_skin" in header) != floor:
        fail(f"truth_floor_flip_skin in results.csv: {not floor}, with a measured floor: {floor}")
    for column in columns + (["truth_floor_flip_skin"] if floor else []):
        if column not in header or any(column not in r["quality"] for r in results["rows"]):
            fail(f"{column} is missing from results.csv/json")
    if "truth_psnr_skin" not in header:
        fail("truth_psnr_skin is missing from results.csv")
    return results


def test_sweep_file():
    ENV["SKINSIM_BLENDER"] = f"{WORK}/no-blender"
    p = run(SKINSIM, *SWEEP, "--truth", f"{WORK}/nowhere.exr", "--out", f"{WORK}/s", expect=2)
    if "nowhere.exr" not in p.stderr or os.path.exists(f"{WORK}/s"):
        fail(f"a missing truth is not refused before the sweep: {p.stderr}")
    run(SKINSIM, *SWEEP, "--out", f"{WORK}/s")
    (cheap,) = [c for c in json.load(open(f"{WORK}/s/results.json"))["rows"]
                if c["knobs"]["scale"] == "0.25"]
    shutil.copy(f"{WORK}/s/{cheap['frame_image']}", f"{WORK}/truth.png")
    p = run(SKINSIM, *SWEEP, "--truth", f"{WORK}/truth.png", "--out", f"{WORK}/s")
    print(p.stdout, end="")
    results = sweep_truth(f"{WORK}/s", floor=False)
    (group,) = results["truth"]
    mine = [c for c in results["rows"] if c["id"] == cheap["id"]][0]
    if mine["quality"]["truth_flip_skin"] != 0.0 or mine["quality"]["truth_visible_skin"] != 0.0:
        fail(f"a frame against itself as truth: {mine['quality']}")
    if group["recommended_by_truth"] != cheap["id"] or group["noise_floor"]["measured"]:
        fail(f"the truth's own frame is not recommended: {group}")
    if group["recommendation_same"] != (group["recommended_by_reference"] == cheap["id"]):
        fail(f"recommendation_same is wrong: {group}")
    changed = [c["id"] for c in group["visibility_verdicts_changed"]]
    if (cheap["visible_vs_reference"] != (cheap["id"] in changed)) or "judged by the truth" not in p.stdout:
        fail(f"the verdicts that changed: {changed}, against the reference {cheap['visible_vs_reference']}")


def test_sweep_store():
    use_fake_blender()
    sweep = SWEEP + ["--resolutions", "64x48,32x24"]
    sweep.remove("64x48")
    sweep.remove("--resolutions")
    p = run(SKINSIM, *sweep, "--truth", "cached", "--out", f"{WORK}/s")
    results = sweep_truth(f"{WORK}/s", floor=True)
    if len(blender_calls()) != 4 or version_calls() != 1:
        fail("two groups' truths: not 4 renders and one `blender --version` a process")
    for g in results["truth"]:
        if not os.path.isfile(f"{WORK}/s/{g['image']}"):
            fail(f"the truth image {g['image']} is not written")
    if p.stdout.count("judged by the truth") != 2:
        fail(f"one line per group: {p.stdout}")
    if "no charts or report.html" in p.stdout + p.stderr:  # -DSKINSIM_BUILD_REPORTS=OFF
        if os.path.exists(f"{WORK}/s/report.html"):
            fail("a build without reports left a report.html")
    else:
        check_truth_in_report(f"{WORK}/s/report.html", results)
    # A named truth nobody rendered: exit 2 naming it (the configurations are kept).
    p = run(SKINSIM, *sweep, "--truth", "cached", "--truth-seed", "9", "--out", f"{WORK}/s",
            expect=2)
    if "--truth-samples 64 --truth-seed 9" not in p.stderr or blender_calls():
        fail(f"a sweep's missing named truth: {p.stderr}")


def check_truth_in_report(path, results):
    """The truth in each group's slider and crops, and the section on what it says."""
    with open(path) as f:
        page = f.read()
    for words in ("<h2>Judged by truth</h2>", ">truth (path-traced)</option>",
                  "<th>truth (path-traced)</th>", "<th>|recommended - truth| x 8</th>",
                  "sRGB transfer function", "noise floor", "Recommendation: "):
        if words not in page:
            fail(f"report.html does not show '{words}'")
    if "cannot separate" not in page and "this truth separates them" not in page:
        fail("report.html does not say whether the truth separates the configurations")
    for g in results["truth"]:
        if f'value="{g["image"]}"' not in page:
            fail(f"the truth image {g['image']} is not in the slider")


def test_sweep():
    blender = ENV.get("SKINSIM_BLENDER", "blender")
    if shutil.which(blender) is None:
        print(f"SKIP: Blender ({blender}) is not installed; scripts/install-deps.sh installs it")
        sys.exit(77)
    p = run(SKINSIM, *SWEEP, "--truth", "cached", "--out", f"{WORK}/s")
    print(p.stdout, end="")
    results = sweep_truth(f"{WORK}/s", floor=True)
    (group,) = results["truth"]
    floor = group["noise_floor"]
    if not floor["measured"] or not 0.0 < floor["skin"]["flip"] < 1.0:
        fail(f"the truth's noise floor: {floor}")
    if group["recommended_by_reference"] is None or "recommendation_same" not in group:
        fail(f"the group's verdicts: {group}")
    for c in results["rows"]:
        q = c["quality"]
        if not (0.0 < q["truth_flip_skin"] < 1.0 and q["truth_flip_skin"] >= 0.0):
            fail(f"{c['id']}: implausible figures against the truth: {q}")
    if "judged by the truth" not in p.stdout or "noise floor" not in p.stdout:
        fail("the sweep does not say what the truth judged")


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    {"store": test_store, "file": test_file, "directory": test_directory, "compare": test_compare,
     "sweep_file": test_sweep_file, "sweep_store": test_sweep_store, "sweep": test_sweep}[CASE]()
    print("ok")


main()
