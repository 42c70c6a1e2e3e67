"""The figures and names README.md and docs/ quote from skinsim must be skinsim's, so they
cannot go stale silently:
- docs/techniques.md and docs/knobs.md hold `skinsim techniques --markdown` and
  `skinsim knobs --markdown` verbatim;
- every `skinsim SUB ... --option` the docs show names a subcommand and an option it has;
- every shader a doc names (`*_vs`, `*_fs`) is in `skinsim shaders`, and the texture-read
  counts docs/pipeline.md quotes are what `skinsim shaders --json` counts;
- a block that shows `$ skinsim ARGS` and its output is what skinsim ARGS prints now
  (docs/validation.md's example: its figures, the uncertain-figure count);
- every output file a doc names (`results.csv`, `report.html`, ...) is written by a small run,
  sweep, compare, export or truth, or is a file the repository tracks.
Usage: docs_consistency_test.py SKINSIM SOURCE_DIR WORK_DIR"""
import json
import pathlib
import re
import shutil
import subprocess
import sys

SKINSIM, SOURCE, WORK = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
DOCS = sorted((SOURCE / "docs").glob("*.md")) + [SOURCE / "README.md"]
SMALL = ["--resolution", "64x48"]
# Output names the docs use as patterns, not literal files, and what they stand for.
PATTERNS = {"shard-K-of-N.json": "a shard's status file, K and N the shard (docs/sweeps.md)"}
failures = []


def skinsim(*args):
    return subprocess.run([SKINSIM, *args], check=True, capture_output=True, text=True).stdout


def fail(message):
    failures.append(message)
    print(f"FAIL: {message}")


def text_of(doc):
    return doc.read_text()


def check_generated_tables():
    for command, doc in (("techniques", "techniques.md"), ("knobs", "knobs.md")):
        table = skinsim(command, "--markdown")
        if table not in text_of(SOURCE / "docs" / doc):
            fail(f"docs/{doc} does not hold the table `skinsim {command} --markdown` prints; "
                 f"paste it in:\n{table}")


def options_of(sub, cache={}):
    if sub not in cache:
        cache[sub] = set(re.findall(r"(--[a-z0-9][a-z0-9-]*)", skinsim(sub, "--help")))
    return cache[sub]


def check_command_lines(subcommands):
    """Each `skinsim SUB` in a doc (inline or in a block, to the end of its line or span)."""
    checked = 0
    for doc in DOCS:
        for span in re.findall(r"`([^`\n]*)`|^(.*skinsim .*)$", text_of(doc), re.M):
            for line in span:
                for m in re.finditer(r"\bskinsim (\w[\w-]*)([^`|&;#]*)", line):
                    sub, rest = m.group(1), m.group(2)
                    if sub not in subcommands:
                        continue  # prose such as "skinsim is" or "skinsim run's result"
                    for option in re.findall(r"(?:^|\s)(--[a-z0-9][a-z0-9-]*)", rest):
                        checked += 1
                        if option not in options_of(sub):
                            fail(f"{doc.name}: `skinsim {sub}` has no option {option} "
                                 f"(in: {m.group(0).strip()})")
    print(f"{checked} options the docs show after `skinsim SUB` checked")


def check_shaders():
    shaders = {s["name"]: s for s in json.loads(skinsim("shaders", "--json"))}
    for doc in DOCS:
        for name in set(re.findall(r"`([a-z0-9_]+_(?:fs|vs))`", text_of(doc))):
            if name not in shaders:
                fail(f"{doc.name} names shader `{name}`, which `skinsim shaders` does not list")
    claim = re.search(r"the `skin_fs` row shows (\d+) independent\s+and (\d+) dependent texture "
                      r"reads \(((?:`\w+`,?\s*)+): (\d+) and (\d+)\)",
                      text_of(SOURCE / "docs" / "pipeline.md"))
    if not claim:
        fail("docs/pipeline.md: the sentence quoting skin_fs's texture reads was reworded; "
             "update this test's pattern with it")
        return
    quoted = [("skin_fs", claim.group(1), claim.group(2))]
    for name in re.findall(r"`(\w+)`", claim.group(3)):
        quoted.append((name, claim.group(4), claim.group(5)))
    for name, independent, dependent in quoted:
        s = shaders.get(name, {})
        counted = (str(s.get("texture_reads_independent")), str(s.get("texture_reads_dependent")))
        if counted != (independent, dependent):
            fail(f"docs/pipeline.md says {name} has {independent} independent and {dependent} "
                 f"dependent texture reads; `skinsim shaders --json` counts {counted}")


def check_transcripts():
    """A block that starts `$ skinsim ARGS` shows what skinsim ARGS prints, exactly."""
    for doc in DOCS:
        for block in re.findall(r"```\n\$ skinsim ([^\n]*)\n(.*?)```", text_of(doc), re.S):
            args, shown = block
            printed = subprocess.run([SKINSIM, *args.split()], cwd=SOURCE, capture_output=True,
                                     text=True).stdout
            if printed != shown:
                fail(f"{doc.name}: `skinsim {args}` now prints (paste it in):\n{printed}")


def produced_files():
    """Names of the files a small run, sweep, compare, export and truth write."""
    if WORK.exists():
        shutil.rmtree(WORK)
    run_a, run_b = WORK / "a", WORK / "b"
    skinsim("run", "--device", "ipad4", *SMALL, "--out", str(run_a))
    skinsim("run", "--device", "ipad4", *SMALL, "--scale", "0.25", "--out", str(run_b))
    subprocess.run([SKINSIM, "compare", str(run_a), str(run_b), "--out", str(WORK / "ab")],
                   capture_output=True, check=False)  # exit 1: they differ
    skinsim("sweep", "--scales", "1", "--luts", "16x64", "--resolutions", "64x48", "--out",
            str(WORK / "s"))
    skinsim("export", *SMALL, "--out", str(WORK / "x"))
    skinsim("run", "--sequence", "push-in", "--frames", "2", "--no-reference", "--no-charts", *SMALL,
            "--out", str(WORK / "q"))  # sequence.html
    # The path-traced truth of run a, one sample (Blender: scripts/install-deps.sh installs it).
    skinsim("truth", "--device", "ipad4", *SMALL, "--samples", "1", "--compare", str(run_a),
            "--out", str(WORK / "t"))
    return {p.name for p in WORK.rglob("*") if p.is_file()}


def check_output_names(produced):
    # The tracked files only: a build directory inside the tree holds test outputs.
    tracked = subprocess.run(["git", "-C", str(SOURCE), "ls-files"], capture_output=True,
                             text=True, check=True).stdout.split("\n")
    tree = {path.rsplit("/", 1)[-1] for path in tracked if path}
    for doc in DOCS:
        for path in set(re.findall(r"`([\w./{}-]+\.(?:csv|json|html|svg))`", text_of(doc))):
            name = path.rsplit("/", 1)[-1]
            if name in produced or name in tree or name in PATTERNS:
                continue
            fail(f"{doc.name} names `{path}`, which no run, sweep, compare, export or truth writes and "
                 "the repository does not hold")


def main():
    subcommands = set(re.findall(r"^  (\w+)", skinsim("--help"), re.M))
    check_generated_tables()
    check_command_lines(subcommands)
    check_shaders()
    check_transcripts()
    check_output_names(produced_files())
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
