"""`skinsim check` and `skinsim baseline` end to end: exit codes (0 pass, 1 a limit exceeded,
2 bad input), messages naming the file and line, JUnit XML that parses and counts failures,
and provenance warnings. Usage: cli_test.py SKINSIM WORK_DIR"""
import json
import pathlib
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

SKINSIM, WORK = sys.argv[1], pathlib.Path(sys.argv[2])
shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)
failures = []

SMALL = """
[[budget]]
name = "small"
device = "ipad4"
resolution = "256x192"
[budget.scene]
head_triangles = 6000
texture_size = 128
[budget.limits]
"""


def run(*args):
    p = subprocess.run([SKINSIM, *args], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def expect(cond, what, output=""):
    if not cond:
        failures.append(f"{what}\n{output}")


def write(name, text):
    path = WORK / name
    path.write_text(text)
    return str(path)


# Passing and failing absolute limits, JUnit counts.
budgets = write("abs.toml", SMALL + '"frame.ms" = "<= 1000"\n"skin.ms" = "<= 0.000001"\n'
                '"skin.fragments_shaded" = ">= 1"\n')
junit = WORK / "abs.xml"
code, out, err = run("check", budgets, "--junit", str(junit), "--threads", "2")
expect(code == 1, f"a failing limit exits 1, got {code}", out + err)
expect("FAIL small / skin.ms" in out and "-bound (" in out, "failure message in the table", out)
root = ET.parse(junit).getroot()
cases = root.findall(".//testcase")
expect(len(cases) == 3, f"one testcase per limit, got {len(cases)}")
expect(root.get("failures") == "1", f"failures=1, got {root.get('failures')}")
failed = [c for c in cases if c.find("failure") is not None]
expect(len(failed) == 1 and failed[0].get("name").startswith("skin.ms"), "the skin.ms case failed")
expect("the skin pass is" in failed[0].find("failure").get("message"), "failure message in XML")

# Relative limits: a missing baseline is bad input; recorded, it passes; --update is needed
# to replace it; a changed device profile warns.
budgets = write("rel.toml", SMALL + '"frame.ms" = "<= baseline * 1.05"\n'
                '"quality.ssim_skin" = ">= baseline - 0.01"\n')
code, out, err = run("check", budgets)
expect(code == 2 and "rel.baseline.json" in err, "missing baseline exits 2 naming it", err)
code, out, err = run("baseline", budgets)
expect(code == 0 and (WORK / "rel.baseline.json").exists(), "baseline recorded", out + err)
code, out, err = run("baseline", budgets)
expect(code == 2 and "--update" in err, "an existing baseline needs --update", err)
code, out, err = run("check", budgets, "--threads", "1")
expect(code == 0 and "2 of 2 limits in 1 budgets passed" in out, "passes its baseline", out + err)
expect("warning" not in err, "no provenance warning for an unchanged setup", err)

# Editing what a budget measures (here its resolution) after recording warns and says how to
# re-record; the baseline itself is left alone.
(WORK / "rel.toml").write_text(pathlib.Path(budgets).read_text().replace("256x192", "320x240"))
code, out, err = run("check", budgets)
expect("budget 'small': its device, scene, resolution or knobs changed" in err
       and "skinsim baseline" in err and "--update" in err, "definition change warns", err)
(WORK / "rel.toml").write_text(pathlib.Path(budgets).read_text().replace("320x240", "256x192"))


def edit_baseline(name, frame_ms_factor, **fields):
    """Scales the recorded frame.ms of budget 'small' and overrides top-level/budget fields."""
    path = WORK / name
    baseline = json.loads(path.read_text())
    baseline["budgets"]["small"]["metrics"]["frame.ms"] *= frame_ms_factor
    baseline["skinsim_version"] = fields.get("skinsim_version", baseline["skinsim_version"])
    if "device_hash" in fields:
        baseline["budgets"]["small"]["device_hash"] = fields["device_hash"]
    path.write_text(json.dumps(baseline))


edit_baseline("rel.baseline.json", 0.5, skinsim_version="0.0.0-old",
              device_hash="fnv1a64:0000000000000000")
code, out, err = run("check", budgets)
expect(code == 1, f"a frame twice its baseline exits 1, got {code}", out + err)
expect("skinsim 0.0.0-old" in err and "device profile 'ipad4' changed" in err,
       "provenance warnings", err)
expect("frame.ms rose from" in out and "+100.0%" in out, "relative failure says how much", out)

# Two-sided limits: a frame cheaper than its baseline beyond the tolerance fails too.
budgets = write("lower.toml",
                SMALL + '"frame.ms" = ["<= baseline * 1.05", ">= baseline * 0.95"]\n')
code, out, err = run("baseline", budgets)
expect(code == 0, "lower-limit baseline recorded", out + err)
edit_baseline("lower.baseline.json", 2.0)
code, out, err = run("check", budgets)
expect(code == 1, f"a frame half its baseline exits 1, got {code}", out + err)
expect("frame.ms fell from" in out and "did work go missing?" in out,
       "lower-limit failure says work may be missing", out)

# Bad input: exit 2 and the message names the file and line.
bad = {
    "malformed.toml": ("[[budget]\n", "malformed.toml:1:"),
    "device.toml": (SMALL.replace('"ipad4"', '"ipad9"') + '"frame.ms" = "<= 5"\n',
                    "device.toml:2: budget 'small', device 'ipad9'"),
    "pass.toml": (SMALL + '"skn.ms" = "<= 5"\n', "pass.toml:10: budget 'small', limit 'skn.ms'"),
    "metric.toml": (SMALL + '"skin.speed" = "<= 5"\n', "metric.toml:10:"),
    "limit.toml": (SMALL + '"skin.ms" = "less than 5"\n', "limit.toml:10:"),
    "knob.toml": (SMALL + '"skin.ms" = "<= 5"\n[budget.pipeline]\nscale = 9\n', "knob.toml:11: budget 'small', pipeline: scale must be in"),
}
for name, (text, where) in bad.items():
    code, out, err = run("check", write(name, text))
    expect(code == 2, f"{name}: exit 2, got {code}", out + err)
    expect(where in err, f"{name}: message names '{where}'", err)
code, out, err = run("check", str(WORK / "absent.toml"))
expect(code == 2 and "absent.toml" in err, "a missing budget file exits 2", err)

if failures:
    print("\n\n".join(failures))
    sys.exit(1)
print("budget CLI: all checks passed")
