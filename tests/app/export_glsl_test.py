#!/usr/bin/env python3
"""`skinsim export` for every registered technique, as GLSL ES 1.00 and 3.00: every exported
shader compiles with Khronos' reference compiler, every draw's vertex and fragment shaders
link, and frame.json describes what the shaders declare. An unknown --glsl exits 2 naming it.

Usage: export_glsl_test.py SKINSIM GLSLANG_VALIDATOR OUT_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys

RESOLUTION = "128x96"  # small: the passes and shaders are those of any resolution


def techniques(skinsim):
    listing = subprocess.run([skinsim, "techniques", "--json"], check=True,
                             capture_output=True, text=True).stdout
    return [t["name"] for t in json.loads(listing)]


def compile_errors(validator, files):
    """The reference compiler's complaint about `files` (linked when there are two), or None."""
    command = [validator] + (["-l"] if len(files) > 1 else []) + files
    run = subprocess.run(command, capture_output=True, text=True)
    return None if run.returncode == 0 else run.stdout + run.stderr


def declared(source, pattern):
    return set(re.findall(pattern, source))


def check_export(skinsim, validator, technique, dialect, out, knobs=()):
    failures = []
    shutil.rmtree(out, ignore_errors=True)
    # A small head, textures, shadow map and texture-space atlas: the same passes and
    # shaders, a fraction of the rendering (this test also runs under the sanitizers).
    subprocess.run([skinsim, "export", "--technique", technique, "--resolution", RESOLUTION,
                    "--head-triangles", "5000", "--texture-size", "128",
                    "--shadow-map-size", "256", "--texture-space-size", "256",
                    "--glsl", dialect, "--out", out] + list(knobs), check=True,
                   stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "frame.json")) as f:
        frame = json.load(f)
    where = " ".join([technique, dialect] + list(knobs))
    if frame["technique"] != technique or frame["glsl"] != dialect:
        failures.append(f"{where}: frame.json names {frame['technique']} {frame['glsl']}")
    version = "#version 300 es" if dialect == "es300" else "#version 100"
    shaders = sorted(os.listdir(os.path.join(out, "shaders")))
    if not shaders:
        failures.append(f"{where}: no shaders exported")
    for name in shaders:
        path = os.path.join(out, "shaders", name)
        with open(path) as f:
            if not f.readline().startswith(version):
                failures.append(f"{where}: {name} is not {version}")
        error = compile_errors(validator, [path])
        if error:
            failures.append(f"{where}: {name} does not compile:\n{error}")
    seen_passes = []
    for p in frame["passes"]:
        for i, draw in enumerate(p["draws"]):
            at = f"{where}: pass {p['name']} draw {i}"
            vs = os.path.join(out, draw["vertex_shader"])
            if draw["fragment_shader"] is None:
                if p["color"] is not None:
                    failures.append(f"{at}: a colour pass draws without a fragment shader")
                continue
            fs = os.path.join(out, draw["fragment_shader"])
            error = compile_errors(validator, [vs, fs])
            if error:
                failures.append(f"{at}: {draw['vertex_shader']} and {draw['fragment_shader']} "
                                f"do not link:\n{error}")
            with open(vs) as f:
                vs_source = f.read()
            with open(fs) as f:
                fs_source = f.read()
            attributes = declared(vs_source, r"(?:attribute|in) \w+ (a_\w+);")
            if attributes != set(draw["geometry"]["attributes"]):
                failures.append(f"{at}: attributes {sorted(attributes)} declared, "
                                f"{draw['geometry']['attributes']} described")
            samplers = declared(fs_source, r"uniform (?:lowp )?sampler\w+ (s\d+);")
            described = {t["sampler"] for t in draw["textures"]}
            if samplers != described:
                failures.append(f"{at}: samplers {sorted(samplers)} declared, "
                                f"{sorted(described)} described")
            uniforms = declared(fs_source, r"uniform (?:vec\d|float) (u_\w+);")
            if uniforms != set(draw["uniforms"]):
                failures.append(f"{at}: uniforms {sorted(uniforms)} declared, "
                                f"{sorted(draw['uniforms'])} described")
            for t in draw["textures"]:
                if t["rendered_by"] is not None and t["rendered_by"] not in seen_passes:
                    failures.append(f"{at}: samples {t['texture']} from pass "
                                    f"{t['rendered_by']}, which has not run before it")
        seen_passes.append(p["name"])
    return failures


def main():
    skinsim, validator, out_dir = sys.argv[1:4]
    if not validator or not shutil.which(validator):
        print("glslangValidator not found: install glslang-tools (scripts/install-deps.sh)")
        return 1
    failures = []
    bad = subprocess.run([skinsim, "export", "--glsl", "es200", "--out",
                          os.path.join(out_dir, "bad")], capture_output=True, text=True)
    if bad.returncode != 2 or "--glsl" not in bad.stderr or os.path.exists(
            os.path.join(out_dir, "bad")):
        failures.append(f"--glsl es200: expected exit 2 naming --glsl and no output, got "
                        f"{bad.returncode}: {bad.stderr}")
    names = techniques(skinsim)
    for technique in names:
        for dialect in ("es100", "es300"):
            failures += check_export(skinsim, validator, technique, dialect,
                                     os.path.join(out_dir, f"{technique}_{dialect}"))
    # The skin shader at mediump: highp vertex shaders link with a mediump fragment shader.
    for technique in ("mobile", "urp"):
        for dialect in ("es100", "es300"):
            out = os.path.join(out_dir, f"{technique}_{dialect}_mediump")
            failures += check_export(skinsim, validator, technique, dialect, out,
                                     ("--skin-precision", "mediump"))
            mediump = [n for n in os.listdir(os.path.join(out, "shaders"))
                       if n.endswith("_mediump.frag")]
            for name in mediump:
                with open(os.path.join(out, "shaders", name)) as f:
                    if "precision mediump float;\n" not in f.read():
                        failures.append(f"{technique} {dialect}: {name} is not mediump")
            if not mediump:
                failures.append(f"{technique} {dialect} mediump: no *_mediump.frag exported")
    for failure in failures:
        print(failure)
    print(f"{len(names)} techniques x 2 GLSL versions, and 2 at mediump: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
