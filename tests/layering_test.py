"""The product's folders are layered one way: a folder includes only folders below it in LAYERS
(and itself), so the data flow of docs/architecture.md is what the includes say. A folder not
in LAYERS, or an include that points up, fails with the file, the line and both layers.
Usage: layering_test.py SOURCE_DIR"""
import pathlib
import re
import sys

# Lowest first. A nested entry ("driver/frame") is a layer of its own inside its folder; a
# file belongs to the longest entry its path starts with. Tests, benchmarks and the crosscheck
# tool sit above everything and are not listed.
LAYERS = [
    "util",
    "io",
    "results",
    "shading",
    "sim",
    "image",
    "quality",
    "scene",
    "gpu_model",
    "pipeline",
    "microbench",
    "reports",
    "driver/frame",  # one frame: the job, its outputs, references, result.json
    "driver/validate",
    "driver/sequence",  # frames in motion
    "driver/sweep",  # many configurations: runs, comparisons, crops, shards, the report
    "driver/truth",  # the path-traced judge
    "budget",
    "app",
]
UNCHECKED = {"tests", "bench", "crosscheck", "build", "cmake", "data", "docs", "scripts"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def layer_of(path):
    """The LAYERS index of a repository path, or None when no entry holds it."""
    best = None
    for i, layer in enumerate(LAYERS):
        if path == layer or path.startswith(layer + "/"):
            if best is None or len(layer) > len(LAYERS[best]):
                best = i
    return best


def main():
    source = pathlib.Path(sys.argv[1])
    failures = []
    for file in sorted(source.rglob("*")):
        if file.suffix not in (".h", ".cpp") or not file.is_file():
            continue
        path = file.relative_to(source).as_posix()
        top = path.split("/")[0]
        if top in UNCHECKED or top.startswith("build") or top.startswith("."):
            continue
        own = layer_of(path)
        if own is None:
            failures.append(f"{path}: its folder is not in LAYERS (tests/layering_test.py)")
            continue
        for number, line in enumerate(file.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match or "/" not in match.group(1):
                continue
            target = layer_of(match.group(1))
            if target is not None and target > own:
                failures.append(f"{path}:{number}: includes {match.group(1)} "
                                f"({LAYERS[target]}, above {LAYERS[own]})")
    for failure in failures:
        print(failure)
    print(f"{len(failures)} layering violation(s)" if failures else "layering is one-way")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
