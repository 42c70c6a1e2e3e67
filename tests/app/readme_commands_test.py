"""Every command line README.md shows must work as written: each line of its ```sh blocks runs
in a sandbox laid out like the repository (build/skinsim, data/, ../shared), so the paths it
names (an example profile, a sweep file, a budget file) must exist there or be made by an
earlier README line. A line runs verbatim except for a small --resolution (--resolutions for a
sweep) appended to commands that render, and one sample a pixel for `truth`, so the whole
README costs about a minute. A TOML
block the README says to "Save this as `PATH`" is written to PATH first.

Lines that build or install (scripts/*.sh, cmake), or need a scheduler, are listed in SKIPPED
with the reason; a README line matching no rule fails, so a new example is either run here
or skipped with a reason.
Usage: readme_commands_test.py README SKINSIM GLES_REPLAY|- SHARED_DIR WORK_DIR"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import time

README, SKINSIM, GLES_REPLAY, SHARED, WORK = sys.argv[1:6]
# "-" when the build has no llvmpipe cross-check; absent when that target was not built.
REPLAY_BUILT = GLES_REPLAY != "-" and pathlib.Path(GLES_REPLAY).exists()
SOURCE = pathlib.Path(README).resolve().parent
RESOLUTION = "160x120"
# Subcommands that take --resolution (not validate: its example CSV is the display's frame).
RENDERING = {"run", "export"}

# Starts of lines not run here, and why.
SKIPPED = {
    "bash scripts/": "builds and installs (scripts/test.sh is the test of it)",
    "cmake ": "configures or builds (CTest runs inside such a build)",
    "(cd build": "runs the test suite itself",
    "build/bench/": "a benchmark (minutes); bench/ has its own checks",
    "scripts/bench_vs_llvmpipe.py": "a benchmark against Mesa (minutes)",
    "scripts/slurm/sweep.sh": "needs a Slurm cluster (tests/slurm/ runs it on one)",
    "parallel ": "needs GNU parallel; the same --shard/--merge lines run above",
    "build/skinsim check data/budgets/default.toml": "CTest budget.project_budgets runs it",
}
# Lines run with a known exit status other than 0, and why the README allows it.
ALLOWED_EXIT = [
    (re.compile(r"sweep .*--merge"), {1}, "a merge lists the parts not yet run and exits 1"),
    (re.compile(r"skinsim compare "), {0, 1}, "compare exits 1 when the two differ"),
]


def commands_and_files(text):
    """The README's shell lines (continuations joined) and the files it says to save."""
    lines, files = [], {}
    for match in re.finditer(r"```(\w*)\n(.*?)```", text, re.S):
        lang, body = match.group(1), match.group(2)
        if lang == "toml":
            before = text[:match.start()].rstrip().rsplit("\n\n", 1)[-1]
            saved = re.search(r"Save this as `([^`]+)`", before)
            if saved:
                files[saved.group(1)] = body
        elif lang == "sh":
            for line in body.replace("\\\n", " ").splitlines():
                if line.strip():
                    lines.append(line.strip())
    return lines, files


def needs_scan(line, files):
    """Whether the line reads ../shared, itself or through a file the README saves."""
    return "shared/" in line or any(p in line and "shared/" in b for p, b in files.items())


def make_sandbox(root):
    """A directory laid out like the repository and its ../shared, outputs landing inside."""
    if root.exists():
        shutil.rmtree(root)
    repo = root / "repo"
    (repo / "build").mkdir(parents=True)
    os.symlink(pathlib.Path(SKINSIM).resolve(), repo / "build" / "skinsim")
    if REPLAY_BUILT:
        os.symlink(pathlib.Path(GLES_REPLAY).resolve(), repo / "build" / "gles_replay")
    os.symlink(SOURCE / "data", repo / "data")
    os.symlink(pathlib.Path(SHARED).resolve(), root / "shared")
    return repo


def cheap(words):
    """`words` with a small render size appended where the command renders a frame."""
    if len(words) < 2 or words[0] != "build/skinsim" or "--help" in words:
        return words
    sub = words[1]
    if sub in RENDERING and "--resolution" not in words:
        return words + ["--resolution", RESOLUTION]
    if sub == "sweep" and "--resolutions" not in words:  # a merge too: the same sweep
        return words + ["--resolutions", RESOLUTION]
    if sub == "truth" and "--samples" in words:  # one sample a pixel: seconds, not minutes
        at = words.index("--samples") + 1
        return words[:at] + ["1"] + words[at + 1:]
    return words


def run_line(line, repo):
    """Runs one README line (its `&&` parts in turn); returns a failure message or None."""
    words = shlex.split(line, comments=True)
    parts, part = [], []
    for w in words + ["&&"]:
        if w == "&&":
            parts.append(part)
            part = []
        else:
            part.append(w)
    for part in parts:
        if part[0] == "build/gles_replay" and not REPLAY_BUILT:
            print(f"  skipped {shlex.join(part)}: gles_replay is not built here")
            continue
        allowed, why = {0}, ""
        for pattern, codes, reason in ALLOWED_EXIT:
            if pattern.search(shlex.join(part)):
                allowed, why = codes, reason
        command = cheap(part)
        start = time.monotonic()
        result = subprocess.run(command, cwd=repo, capture_output=True, text=True, timeout=900)
        seconds = time.monotonic() - start
        note = f" ({why})" if why and result.returncode else ""
        print(f"  {shlex.join(command)}: exit {result.returncode}, {seconds:.1f} s{note}")
        if result.returncode not in allowed:
            return (f"README line `{line}` failed (exit {result.returncode}):\n"
                    f"{result.stdout[-2000:]}{result.stderr[-3000:]}")
    return None


def main():
    lines, files = commands_and_files(pathlib.Path(README).read_text())
    repo = make_sandbox(pathlib.Path(WORK))
    for path, body in files.items():
        (repo / path).parent.mkdir(parents=True, exist_ok=True)
        (repo / path).write_text(body)
        print(f"wrote {path} from the README")
    scan_present = (pathlib.Path(SHARED) / "assets" / "LeePerrySmith.glb").exists()
    failures, ran = [], 0
    for line in lines:
        first = line.split()[0]
        skipped = next((why for start, why in SKIPPED.items() if line.startswith(start)), None)
        if not skipped and not scan_present and needs_scan(line, files):
            skipped = f"the scan {SHARED}/assets/LeePerrySmith.glb is not present"
        if skipped:
            print(f"skipped `{line}`: {skipped}")
            continue
        if first not in ("build/skinsim", "cp"):
            failures.append(f"README line `{line}` matches no rule: run it here or add its "
                            "first word to SKIPPED with the reason")
            continue
        print(f"`{line}`")
        ran += 1
        failure = run_line(line, repo)
        if failure:
            failures.append(failure)
    for f in failures:
        print(f"FAIL: {f}")
    print(f"{ran} README lines run, {len(failures)} failed")
    return 1 if failures or not ran else 0


if __name__ == "__main__":
    sys.exit(main())
