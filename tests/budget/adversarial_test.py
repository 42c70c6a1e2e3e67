"""Adversarial budget files and baselines, table-driven: wrong types, NaN/inf, huge integers,
unknown keys, empty names, control characters, duplicate names, bad limit expressions and
missing files. Each case must exit 2 with a message naming the field at fault (never a crash,
exit 1 or exit 3). Usage: adversarial_test.py SKINSIM WORK_DIR"""
import json
import os
import pathlib
import shutil
import subprocess
import sys

SKINSIM, WORK = sys.argv[1], pathlib.Path(sys.argv[2])
shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)
failures = []


def budget(name='"small"', extra="", pipeline="", limits='"frame.ms" = "<= 1000"'):
    return f"""
[[budget]]
name = {name}
device = "ipad4"
resolution = "256x192"
{extra}
[budget.scene]
head_triangles = 6000
texture_size = 128
[budget.pipeline]
{pipeline}
[budget.limits]
{limits}
"""


# (case, budget file text, text the message must contain)
BUDGET_CASES = [
    ("name of wrong type", budget(name="5"), "budget[0].name must be a string"),
    ("empty name", budget(name='""'), "budget[0].name is empty"),
    ("control character in name", budget(name='"a\\u001b[31mred"'), "name contains a control"),
    ("newline in name", budget(name='"a\\nb"'), "name contains a control"),
    ("duplicate names", budget() + budget(), "duplicate budget name 'small'"),
    ("unknown key", budget(extra="colour = 1"), "unknown key 'colour'"),
    ("target_fps inf", budget(extra="target_fps = inf"), "target_fps must be a finite number"),
    ("target_fps nan", budget(extra="target_fps = nan"), "target_fps must be a finite number"),
    ("target_fps huge", budget(extra="target_fps = 1e308"), "target_fps must be in (0, 1000], got 1e+308"),
    ("target_fps string", budget(extra='target_fps = "60"'), "target_fps must be a number"),
    ("units_per_mm inf", budget().replace("texture_size = 128", "texture_size = 128\nunits_per_mm = inf"),
     "units_per_mm must be a finite number"),
    ("units_per_mm huge", budget().replace("texture_size = 128", "texture_size = 128\nunits_per_mm = 1e308"),
     "units_per_mm must be in (0, 1e+06], got 1e+308"),
    ("huge head_triangles", budget().replace("6000", "9223372036854775807"), "head_triangles"),
    ("scale nan string", budget(pipeline='scale = "nan"'), "scale"),
    ("scale inf float", budget(pipeline="scale = inf"), "scale"),
    ("scale hex", budget(pipeline='scale = "0x10"'), "scale"),
    ("scale padded", budget(pipeline='scale = " 0.5"'), "scale"),
    ("scale huge", budget(pipeline="scale = 1e300"), "scale"),
    ("huge integer knob", budget(pipeline="blur_iterations = 4294967297"), "blur_iterations"),
    ("knob of wrong type", budget(pipeline="wrap = [1]"), "wrap must be a string or a number"),
    ("unknown knob", budget(pipeline="buffer_scale = 0.5"), "unknown pipeline knob 'buffer_scale'"),
    ("limit nan", budget(limits='"frame.ms" = "<= nan"'), "limit 'frame.ms'"),
    ("limit inf", budget(limits='"frame.ms" = "<= inf"'), "limit 'frame.ms'"),
    ("limit overflow", budget(limits='"frame.ms" = "<= 1e999"'), "limit 'frame.ms'"),
    ("limit hex", budget(limits='"frame.ms" = "<= 0x10"'), "limit 'frame.ms'"),
    ("limit factor inf", budget(limits='"frame.ms" = "<= baseline * inf"'), "limit 'frame.ms'"),
    ("limit without bound", budget(limits='"frame.ms" = "<="'), "limit 'frame.ms'"),
    ("limit of wrong type", budget(limits='"frame.ms" = 5'), "must be a string"),
    ("unknown metric", budget(limits='"frame.speed" = "<= 1"'), "no such metric"),
]


def run(*args):
    p = subprocess.run([SKINSIM, *args], capture_output=True)
    return p.returncode, (p.stdout + p.stderr).decode("utf-8", "replace")


def expect_bad_input(case, args, needle):
    code, out = run(*args)
    if code != 2 or needle not in out or "internal error" in out:
        failures.append(f"{case}: expected exit 2 and '{needle}', got {code}:\n{out}")
    if "\x1b" in out:
        failures.append(f"{case}: a control character reached the terminal:\n{out!r}")


for i, (case, text, needle) in enumerate(BUDGET_CASES):
    path = WORK / f"case{i}.toml"
    path.write_text(text)
    expect_bad_input(case, ["check", str(path)], needle)

expect_bad_input("missing budget file", ["check", str(WORK / "none.toml")],
                 "none.toml: No such file or directory")

# Baselines: a relative limit against a baseline value that is not a finite number.
relative = WORK / "relative.toml"
relative.write_text(budget(limits='"frame.ms" = "<= baseline * 1.05"'))
expect_bad_input("missing baseline", ["check", str(relative)], "cannot read the baseline file")


def baseline(metrics):
    return {"format": "skinsim-budget-baseline/1", "skinsim_version": "0",
            "budgets": {"small": {"device": "ipad4", "device_hash": "x", "metrics": metrics}}}


BASELINE_CASES = [
    ("baseline inf", baseline({"frame.ms": "inf"}), "the baseline value is inf"),
    ("baseline nan", baseline({"frame.ms": "nan"}), "the baseline value is nan"),
    ("baseline overflow", '{"format": "skinsim-budget-baseline/1", "skinsim_version": "0", '
     '"budgets": {"small": {"device": "ipad4", "device_hash": "x", "metrics": {"frame.ms": 1e999}}}}',
     "number overflow parsing '1e999'"),
    ("baseline metric of wrong type", baseline({"frame.ms": "fast"}), "budgets.small.metrics.frame.ms"),
    ("baseline device of wrong type",
     {"format": "skinsim-budget-baseline/1", "skinsim_version": "0",
      "budgets": {"small": {"device": 4, "device_hash": "x", "metrics": {}}}}, "budgets.small"),
    ("baseline not JSON", "{", "malformed baseline"),
]
for case, content, needle in BASELINE_CASES:
    path = WORK / "relative.baseline.json"
    path.write_text(content if isinstance(content, str) else json.dumps(content))
    expect_bad_input(case, ["check", str(relative)], needle)

# A scan without skin (its skin materials named wrongly): a limit on a skin metric names the
# reason and what to pass; a budget with frame limits only still runs.
LEE = os.environ.get("SKINSIM_TEST_LEE", "")
if os.path.exists(LEE):
    scan = f'path = "{LEE}"\nskin_materials = ["nosuch"]'
    path = WORK / "no_skin.toml"
    path.write_text(budget(limits='"quality.psnr_skin" = ">= 30"').replace(
        "head_triangles = 6000\ntexture_size = 128", scan))
    expect_bad_input("skin limit without skin", ["check", str(path)],
                     "limit 'quality.psnr_skin': no skin in the frame: --skin-materials nosuch")
    path.write_text(budget().replace("head_triangles = 6000\ntexture_size = 128", scan))
    code, out = run("check", str(path))
    if code != 0:
        failures.append(f"frame limits without skin: expected exit 0, got {code}:\n{out}")

for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
