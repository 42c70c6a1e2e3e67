"""Adversarial use of what skinsim writes and keeps: output directories it does not own, outputs
that are also inputs, cached references and sweep directories damaged, swapped or planted,
JSON nested without end, shard status files edited by hand, and the Slurm script's paths.
Each case sets up its own directory, runs skinsim (tiny frames) and checks exit code, message
and that no file skinsim did not write was touched. Table-driven: CASES at the bottom.
Usage: adversarial_outputs_test.py SKINSIM SLURM_SWEEP_SH WORK_DIR"""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import time

SKINSIM, SLURM_SWEEP = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
WORK = pathlib.Path(sys.argv[3])
shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)

# Tiny frames: every case renders in well under a second.
FRAME = ["--resolution", "64x48", "--head-triangles", "2000", "--texture-size", "64"]
SWEEP = ["--scales", "1,0.5", "--luts", "8x32", "--resolutions", "64x48", "--head-triangles",
         "2000", "--texture-size", "64", "--no-charts"]


def run(args, cwd=None, env=None, cache="off", timeout=300):
    environment = dict(os.environ, SKINSIM_CACHE_DIR=str(cache), **(env or {}))
    start = time.monotonic()
    p = subprocess.run([SKINSIM, *map(str, args)], capture_output=True, cwd=cwd,
                       env=environment, timeout=timeout)
    out = (p.stdout + p.stderr).decode("utf-8", "replace")
    return p.returncode, out, time.monotonic() - start


def expect(result, code, *texts):
    """"" when `result` exited `code` and printed every text, else what went wrong."""
    got, out, _ = result
    if got != code or not all(t in out for t in texts):
        return f"expected exit {code} and {texts}, got {got}:\n{out[-3000:]}"
    if "internal error" in out:
        return f"internal error:\n{out[-3000:]}"
    return ""


def write(path, text):
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def sweep_dir(d, *extra):
    """A finished tiny sweep in d/sweep."""
    out = d / "sweep"
    code, text, _ = run(["sweep", *SWEEP, "--out", out, *extra])
    assert code == 0, text
    return out


# --- output directories ------------------------------------------------------------------


def run_never_replaces_a_foreign_directory(d):
    write(d / "thesis" / "result.json", "{}")
    write(d / "thesis" / "thesis.tex", "precious")
    write(d / "thesis" / "src" / "main.c", "int main;")
    r = run(["run", *FRAME, "--no-reference", "--out", d / "thesis"])
    lost = not (d / "thesis" / "thesis.tex").exists() or not (d / "thesis" / "src").exists()
    return expect(r, 2, str(d / "thesis"), "thesis.tex") or ("files lost" if lost else "")


def run_keeps_a_file_added_to_its_own_directory(d):
    assert run(["run", *FRAME, "--no-reference", "--out", d / "r"])[0] == 0
    write(d / "r" / "notes.txt", "mine")
    r = run(["run", *FRAME, "--no-reference", "--out", d / "r"])
    kept = (d / "r" / "notes.txt").exists()
    return expect(r, 2, "notes.txt", "did not write") or ("" if kept else "notes.txt deleted")


def run_replaces_its_own_directory(d):
    assert run(["run", *FRAME, "--no-reference", "--out", d / "r"])[0] == 0
    return expect(run(["run", *FRAME, "--no-reference", "--out", d / "r"]), 0)


def export_does_not_replace_a_run(d):
    assert run(["run", *FRAME, "--no-reference", "--out", d / "r"])[0] == 0
    r = run(["export", "--out", d / "r"])
    kept = (d / "r" / "frame.png").exists()
    return expect(r, 2, "skinsim run directory") or ("" if kept else "run replaced")


def compare_out_does_not_replace_a_run(d):
    for name in ("a", "b", "c"):
        assert run(["run", *FRAME, "--no-reference", "--out", d / name])[0] == 0
    r = run(["compare", d / "a", d / "b", "--out", d / "c"])
    kept = (d / "c" / "frame.png").exists()
    return expect(r, 2, "skinsim run directory") or ("" if kept else "run replaced")


def sweep_does_not_write_into_a_run(d):
    assert run(["run", *FRAME, "--no-reference", "--out", d / "r"])[0] == 0
    r = run(["sweep", *SWEEP, "--out", d / "r"])
    mixed = (d / "r" / "configs").exists()
    return expect(r, 2, "skinsim run directory") or ("mixed" if mixed else "")


# --- outputs that are inputs ---------------------------------------------------------------

BUDGET = """[[budget]]
name = "tiny"
device = "ipad4"
resolution = "64x48"
[budget.scene]
head_triangles = 2000
texture_size = 64
[budget.limits]
"frame.ms" = "<= 1000"
"""


def unchanged(path, text):
    return "" if pathlib.Path(path).read_text() == text else f"{path} was overwritten"


def check_junit_is_not_the_budget_file(d):
    b = write(d / "b.toml", BUDGET)
    r = run(["check", b, "--junit", b])
    return expect(r, 2, "--junit", "the budget file") or unchanged(b, BUDGET)


def check_junit_is_not_a_hard_link_of_the_budget_file(d):
    b = write(d / "b.toml", BUDGET)
    os.link(b, d / "link.xml")
    r = run(["check", b, "--junit", d / "link.xml"])
    return expect(r, 2, "--junit", "the budget file") or unchanged(b, BUDGET)


def baseline_update_is_not_the_budget_file(d):
    b = write(d / "b.toml", BUDGET)
    r = run(["baseline", b, "--baseline", b, "--update"])
    return expect(r, 2, "--baseline", "the budget file") or unchanged(b, BUDGET)


def validate_json_is_not_the_measurements(d):
    m = write(d / "m.csv", "pass,ms\nskin,1.0\n")
    r = run(["validate", m, "--json", m, *FRAME])
    return expect(r, 2, "--json", "the measurements") or unchanged(m, "pass,ms\nskin,1.0\n")


# --- bounded readers -----------------------------------------------------------------------


def compare_refuses_deeply_nested_json(d):
    for name in ("a", "b"):
        write(d / name / "result.json", "[" * 20000)
    return expect(run(["compare", d / "a", d / "b"]), 2, "nests deeper than 64")


def validate_finds_a_duplicate_in_linear_time(d):
    lines = ["pass,ms"] + [f"p{i},1" for i in range(300000)] + ["p0,1"]
    m = write(d / "m.csv", "\n".join(lines) + "\n")
    r = run(["validate", m, *FRAME])
    # Quadratic took 242 s here, linear 0.8 s: 60 s tells them apart on a loaded machine and
    # under the sanitizers.
    slow = f"took {r[2]:.1f} s" if r[2] > 60 else ""
    return expect(r, 2, "'p0' is measured twice") or slow


def shard_status_counts_are_bounded(d):
    out = sweep_dir(d)
    write(out / "shards" / "shard-0-of-2147483647.json",
          json.dumps({"shard": 0, "count": 2147483647, "state": "running", "host": "h",
                      "configurations": [], "failed": []}))
    shutil.rmtree(out / "configs")
    # Unbounded, the count ran past 60 s (killed); bounded, the merge takes about a second.
    r = run(["sweep", *SWEEP, "--out", out, "--merge"], timeout=120)
    slow = f"took {r[2]:.1f} s" if r[2] > 60 else ""
    return expect(r, 1, "are missing") or slow


def shard_status_text_is_sanitised(d):
    out = sweep_dir(d, "--shard", "0/1")
    status = out / "shards" / "shard-0-of-1.json"
    j = json.loads(status.read_text())
    j["state"] = "running"
    j["host"] = "node\x1b]0;owned\x07\x1b[31m"
    status.write_text(json.dumps(j))
    shutil.rmtree(out / "configs")
    r = run(["sweep", *SWEEP, "--out", out, "--merge"])
    if "\x1b" in r[1] or "\x07" in r[1]:
        return f"escape sequence printed:\n{r[1]!r}"
    j["state"], j["failed"] = "failed", [{"id": c, "reason": "x" * 5000000}
                                         for c in j["configurations"]]
    status.write_text(json.dumps(j))
    r = run(["sweep", *SWEEP, "--out", out, "--merge"])
    return expect(r, 1, "failed it") or ("" if len(r[1]) < 20000 else f"{len(r[1])} bytes printed")


# --- shards and sweep directories ----------------------------------------------------------


def shard_of_another_sweep_refuses_the_directory(d):
    out = sweep_dir(d)
    before = {p: p.read_bytes() for p in (out / "configs").glob("*.json")}
    r = run(["sweep", *SWEEP, "--set", "blur_iterations=2", "--out", out, "--shard", "0/1"])
    changed = [p for p, b in before.items() if p.read_bytes() != b]
    return expect(r, 2, "another sweep's results", "--shard 0/1") or (
        f"overwrote {changed}" if changed else "")


def damaged_configuration_is_recomputed(d):
    out = sweep_dir(d)
    frame = sorted((out / "configs").glob("*_frame.png"))[0]
    frame.write_bytes(frame.read_bytes()[:200])
    r = run(["sweep", *SWEEP, "--out", out, "--merge"])
    error = expect(r, 1, "not the image it wrote")
    if error:
        return error
    return expect(run(["sweep", *SWEEP, "--out", out]), 0, "1 computed")


def empty_merge_leaves_no_stale_report(d):
    out = sweep_dir(d)
    write(out / "report.html", "<html>an earlier sweep</html>")
    r = run(["sweep", *SWEEP, "--set", "blur_iterations=2", "--out", out, "--merge"])
    stale = (out / "report.html").exists()
    # A build without the report library (the sanitizer stage) says so instead.
    said = "no finished configuration" if "no charts or report.html" not in r[1] else ""
    return expect(r, 1, said) or ("report.html left" if stale else "")


def set_on_a_swept_knob_is_refused(d):
    return expect(run(["sweep", *SWEEP, "--set", "scale=0", "--out", d / "s"]), 2,
                  "--set scale=0", "also swept")


def empty_shard_is_refused(d):
    r = run(["sweep", *SWEEP, "--shard", "", "--out", d / "s"])
    return expect(r, 2, "--shard") or ("computed" if (d / "s" / "configs").exists() else "")


def open_range_edge_is_refused(d):
    # docs/knobs.md: --camera-distance in (0.05, 1000]; 0.05 as a float lies just above 0.05.
    return expect(run(["run", *FRAME, "--camera-distance", "0.05", "--out", d / "r"]), 2,
                  "camera_distance_m must be in (0.05, 1000]")


def extreme_aspect_names_the_resolution(d):
    r = run(["run", "--resolution", "16x8192", "--out", d / "r"])
    return expect(r, 2, "resolution 16x8192", "0.1..10") or (
        "an internal name" if "DefaultSceneOptions" in r[1] else "")


def four_component_tint_says_three_numbers(d):
    return expect(run(["run", *FRAME, "--shadow-tint", "1,1,1,1", "--out", d / "r"]), 2,
                  "expected three numbers 'r,g,b', got '1,1,1,1'")


def sweep_file_budget_inf_is_refused_with_its_line(d):
    f = write(d / "s.toml", '[axes]\nscale = [1, 0.5]\n\n[report]\nbudget_ms = inf\n')
    return expect(run(["sweep", "--sweep-file", f, "--out", d / "s"]), 2, f"{f}:5",
                  "finite")


def budget_resolution_given_twice_is_refused(d):
    b = write(d / "b.toml", BUDGET.replace("[budget.scene]",
                                           '[budget.pipeline]\nresolution = "32x24"\n'
                                           "[budget.scene]"))
    return expect(run(["check", b]), 2, "resolution", "give it once")


# --- the reference store -------------------------------------------------------------------


def cache_dir_off_in_any_case(d):
    r = run(["run", *FRAME, "--out", d / "r"], cwd=d, cache="OFF")
    return expect(r, 0) or ("created a directory OFF" if (d / "OFF").exists() else "")


def swapped_cached_reference_is_not_used(d):
    cache = d / "cache"
    first = run(["run", *FRAME, "--out", d / "a"], cache=cache)
    assert first[0] == 0, first[1]
    assert run(["run", *FRAME, "--light-azimuth", "90", "--out", d / "b"], cache=cache)[0] == 0
    store = cache / "references"
    markers = sorted(store.glob("*.json"))
    assert len(markers) == 2
    # Each entry's image replaced by the other's: same size, other pixels.
    for m in markers:
        stem = m.with_suffix("")
        other = [o for o in markers if o != m][0].with_suffix("")
        shutil.copy(f"{other}.png", f"{stem}.png.swap")
    for m in markers:
        os.replace(f"{m.with_suffix('')}.png.swap", f"{m.with_suffix('')}.png")
    r = run(["run", *FRAME, "--out", d / "c"], cache=cache)
    psnr = [line for line in first[1].splitlines() if line.startswith("quality vs reference")]
    return expect(r, 0, "discarded the reference kept in", *psnr)


def cached_reference_of_another_size_is_not_used(d):
    cache = d / "cache"
    assert run(["run", *FRAME, "--out", d / "a"], cache=cache)[0] == 0
    small = [a if a != "64x48" else "32x24" for a in FRAME]
    assert run(["run", *small, "--out", d / "b"], cache=cache)[0] == 0
    store = cache / "references"
    sizes = {}
    for m in store.glob("*.json"):
        sizes[json.loads(m.read_text())["images"]["width"]] = m.with_suffix("")
    for suffix in (".png", "_skin.png"):
        shutil.copy(f"{sizes[32]}{suffix}", f"{sizes[64]}{suffix}")
    return expect(run(["run", *FRAME, "--out", d / "c"], cache=cache), 0,
                  "discarded the reference kept in")


def planted_symlink_in_the_store_is_not_written_through(d):
    cache = d / "cache"
    assert run(["run", *FRAME, "--out", d / "a"], cache=cache)[0] == 0
    victim = write(d / "victim.txt", "not skinsim's")
    for f in (cache / "references").iterdir():
        f.unlink()
        f.symlink_to(victim)
    r = run(["run", *FRAME, "--out", d / "b"], cache=cache)
    return expect(r, 0) or unchanged(victim, "not skinsim's")


def previous_run_reference_of_another_size_is_not_used(d):
    assert run(["run", *FRAME, "--out", d / "r"])[0] == 0
    assert run(["run", "--resolution", "32x24", *FRAME[2:], "--out", d / "small"])[0] == 0
    for name in ("reference.png", "reference_skin.png"):
        shutil.copy(d / "small" / name, d / "r" / name)
    return expect(run(["run", *FRAME, "--out", d / "r"]), 0, "discarded the reference kept in")


# --- the Slurm script ----------------------------------------------------------------------


def slurm_stub_dir(d):
    """sbatch, scontrol and scancel that only record their arguments."""
    bin_dir = d / "bin"
    for tool in ("sbatch", "scontrol", "scancel"):
        write(bin_dir / tool, f'#!/bin/sh\necho "$@" >> "{d}/{tool}.log"\necho 42\n')
        (bin_dir / tool).chmod(0o755)
    return bin_dir


def slurm(d, args, env=None):
    environment = dict(os.environ, PATH=f"{slurm_stub_dir(d)}:{os.environ['PATH']}",
                       **(env or {}))
    p = subprocess.run(["bash", SLURM_SWEEP, "--skinsim", SKINSIM, *args], capture_output=True,
                       cwd=d, env=environment, timeout=60)
    return p.returncode, (p.stdout + p.stderr).decode("utf-8", "replace"), 0.0


def slurm_out_ignores_cdpath(d):
    (d / "elsewhere" / "out").mkdir(parents=True)
    r = slurm(d, ["--shards", "2", "--out", "out"], env={"CDPATH": str(d / "elsewhere")})
    log = (d / "sbatch.log").read_text() if (d / "sbatch.log").exists() else ""
    wrong = str(d / "elsewhere") in log or "\n" + str(d / "out") in log
    return expect(r, 0) or ("" if str(d / "out") in log and not wrong else f"sbatch got:\n{log}")


def slurm_refuses_a_directory_it_does_not_own(d):
    write(d / "mine" / "thesis.tex", "precious")
    r = slurm(d, ["--shards", "2", "--out", "mine"])
    submitted = (d / "sbatch.log").exists()
    return expect(r, 2, "not a skinsim sweep directory") or ("submitted" if submitted else "")


def slurm_shards_are_bounded(d):
    return expect(slurm(d, ["--shards", "99999999999999999999", "--out", "o"]), 2, "--shards")


CASES = [
    run_never_replaces_a_foreign_directory,
    run_keeps_a_file_added_to_its_own_directory,
    run_replaces_its_own_directory,
    export_does_not_replace_a_run,
    compare_out_does_not_replace_a_run,
    sweep_does_not_write_into_a_run,
    check_junit_is_not_the_budget_file,
    check_junit_is_not_a_hard_link_of_the_budget_file,
    baseline_update_is_not_the_budget_file,
    validate_json_is_not_the_measurements,
    compare_refuses_deeply_nested_json,
    validate_finds_a_duplicate_in_linear_time,
    shard_status_counts_are_bounded,
    shard_status_text_is_sanitised,
    shard_of_another_sweep_refuses_the_directory,
    damaged_configuration_is_recomputed,
    empty_merge_leaves_no_stale_report,
    set_on_a_swept_knob_is_refused,
    empty_shard_is_refused,
    sweep_file_budget_inf_is_refused_with_its_line,
    open_range_edge_is_refused,
    extreme_aspect_names_the_resolution,
    four_component_tint_says_three_numbers,
    budget_resolution_given_twice_is_refused,
    cache_dir_off_in_any_case,
    swapped_cached_reference_is_not_used,
    cached_reference_of_another_size_is_not_used,
    planted_symlink_in_the_store_is_not_written_through,
    previous_run_reference_of_another_size_is_not_used,
    slurm_out_ignores_cdpath,
    slurm_refuses_a_directory_it_does_not_own,
    slurm_shards_are_bounded,
]

only = os.environ.get("ONLY", "")
failures = []
for case in CASES:
    if only and only not in case.__name__:
        continue
    d = WORK / case.__name__
    d.mkdir()
    try:
        problem = case(d)
    except Exception as e:  # a setup step failed: that is a failure of the case too
        problem = f"{type(e).__name__}: {e}"
    print(f"{'FAIL' if problem else 'ok  '} {case.__name__}", flush=True)
    if problem:
        failures.append(f"{case.__name__}: {problem}")

if failures:
    print("\n\n".join(failures))
    sys.exit(1)
