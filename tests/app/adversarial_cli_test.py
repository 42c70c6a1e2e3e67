"""Adversarial CLI input: every numeric option of `skinsim run` given a value that is not a
plain finite number in range must exit 2 with a message naming the option (or its knob), and
must never render; `skinsim validate`'s measurements file, whatever it holds or is (binary,
a FIFO, a device, a directory), exits 2 naming it. Also the raw-argument checks: `--opt=` with no value, unknown subcommands,
and a non-UTF-8 scene path that must not crash the JSON step.
Usage: adversarial_cli_test.py SKINSIM WORK_DIR"""
import concurrent.futures
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys

SKINSIM, WORK = sys.argv[1], pathlib.Path(sys.argv[2])
shutil.rmtree(WORK, ignore_errors=True)
WORK.mkdir(parents=True)
OUT = str(WORK / "out")
failures = []

# Option -> the names a message may use for it (the flag, or the knob a budget file types).
# The scene and device options by hand; every knob that takes numbers from the knob table
# (`skinsim knobs --json`), so a knob added there is tested here without an edit.
NUMERIC_OPTIONS = {
    "--threads": ["--threads"],
    "--head-triangles": ["--head-triangles"],
    "--texture-size": ["--texture-size"],
    "--units-per-mm": ["--units-per-mm"],
}
# A knob whose values are only words ("on or off", "ks_lut, ks, ggx or dual_ggx") takes none.
WORDS_ONLY = re.compile(r"[a-z_-]+((, | or )[a-z_-]+)*")
KNOBS = json.loads(subprocess.run([SKINSIM, "knobs", "--json"], capture_output=True,
                                  check=True).stdout)
for knob in KNOBS:
    if not WORDS_ONLY.fullmatch(knob["values"]):
        NUMERIC_OPTIONS[knob["option"]] = [knob["option"], knob["name"]]
if len(NUMERIC_OPTIONS) < 4 + 25:
    sys.exit(f"FAIL: only {len(NUMERIC_OPTIONS) - 4} numeric knobs in `skinsim knobs --json`")
BAD_VALUES = ["nan", "inf", "-inf", "1e308", "0x10", " 1", "1 ", ""]


def run(args):
    p = subprocess.run([SKINSIM, *args], capture_output=True)
    return p.returncode, (p.stdout + p.stderr).decode("utf-8", "replace")


def expect_bad_input(args, names):
    code, out = run(args)
    if code != 2 or not any(n in out for n in names):
        failures.append(f"{args!r}: expected exit 2 naming {names}, got {code}:\n{out}")
    if "internal error" in out or len(out) > 2000:
        failures.append(f"{args!r}: message is not a readable user error:\n{out[:2000]}")


cases = []
for option, names in NUMERIC_OPTIONS.items():
    for value in BAD_VALUES:
        cases.append((["run", option, value, "--no-reference", "--out", OUT], names))
    # "--opt=" must not take the next argument as its value.
    cases.append((["run", option + "=", "--no-reference", "--out", OUT], names))
    cases.append((["run", option + "=nan", "--no-reference", "--out", OUT], names))
# The sequence options, given the sequence they need.
for option in ("--frames", "--fps"):
    for value in BAD_VALUES + ["0", "-1"]:
        cases.append((["run", "--sequence", "push-in", option, value, "--no-reference", "--out",
                       OUT], [option]))
# ~200 processes, each mostly the dynamic loader binding VTK's libraries: run them on every
# core (failures are collected in order either way).
with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
    list(pool.map(lambda case: expect_bad_input(*case), cases))

# Out-of-range values print readably, not as hundreds of digits.
code, out = run(["run", "--scale", "1e30", "--no-reference", "--out", OUT])
if code != 2 or "scale must be in (0, 1], got 1e+30" not in out:
    failures.append(f"--scale 1e30: expected a {{:g}}-style range message, got {code}:\n{out}")

code, out = run(["rnu", "--help"])
if code != 2 or "unknown subcommand 'rnu'" not in out or "run" not in out:
    failures.append(f"unknown subcommand: got {code}:\n{out}")

# Nothing above may have rendered.
if pathlib.Path(OUT).exists():
    failures.append(f"a rejected run wrote {OUT}")

# `validate`: its knob options are run's (bad values exit 2 naming the option, before any
# rendering), and its measurements file is refused readably whatever it holds or is.
good_csv = WORK / "measured.csv"
good_csv.write_text("skin,1\n")
for option, names in list(NUMERIC_OPTIONS.items())[:6]:
    expect_bad_input(["validate", str(good_csv), option, "nan"], names)
bad_files = {
    "binary.csv": (b"\x00\xff\xfe\x01,2\n", ["binary.csv:1"]),
    "garbage.csv": (bytes(range(1, 256)) * 4, ["garbage.csv:1"]),
    "huge_number.csv": (b"skin,1e999\n", ["huge_number.csv:1: field 'ms'"]),
    "negative_zero_header.csv": (b"pass,ms\nskin,-0.0001\n", ["negative_zero_header.csv:2"]),
    "crlf_quoted.csv": (b'skin,1\r\n"blur_h",2\r\n', ["crlf_quoted.csv:2"]),
}
for name, (content, names) in bad_files.items():
    (WORK / name).write_bytes(content)
    expect_bad_input(["validate", str(WORK / name), "--resolution", "64x48"], names)
fifo = WORK / "measured.fifo"
os.mkfifo(fifo)
expect_bad_input(["validate", str(fifo)], [str(fifo)])
expect_bad_input(["validate", "/dev/zero"], ["/dev/zero"])
expect_bad_input(["validate", str(WORK)], [str(WORK)])

# A scene path that is not UTF-8 renders and writes valid JSON (invalid bytes replaced).
lee = os.environ.get("SKINSIM_TEST_LEE", "")
if lee and pathlib.Path(lee).is_file():
    odd = WORK / b"head-\xff\xfe.glb".decode("utf-8", "surrogateescape")
    os.symlink(lee, odd)
    out_dir = WORK / "utf8"
    code, out = run(["run", "--scene", str(odd), "--resolution", "128x96", "--no-reference",
                     "--texture-space-size", "64", "--out", str(out_dir)])
    result = out_dir / "result.json"
    if code != 0 or not result.is_file():
        failures.append(f"non-UTF-8 scene path: expected exit 0, got {code}:\n{out}")
    else:
        import json
        scene = json.loads(result.read_bytes().decode("utf-8"))["scene"]
        if "\ufffd" not in scene:
            failures.append(f"non-UTF-8 scene path: expected U+FFFD in {scene!r}")

for f in failures:
    print("FAIL:", f)
print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
