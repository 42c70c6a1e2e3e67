"""The tables the docs hold that the code generates must be the code's: docs/techniques.md
holds `skinsim techniques --markdown` and docs/knobs.md holds `skinsim knobs --markdown`.
Usage: docs_tables_test.py SKINSIM DOCS_DIR"""
import pathlib
import subprocess
import sys

SKINSIM, DOCS = sys.argv[1], pathlib.Path(sys.argv[2])
failures = 0
for command, doc in (("techniques", "techniques.md"), ("knobs", "knobs.md")):
    table = subprocess.run([SKINSIM, command, "--markdown"], check=True, capture_output=True,
                           text=True).stdout
    if table not in (DOCS / doc).read_text():
        failures += 1
        print(f"docs/{doc} does not hold the table `skinsim {command} --markdown` prints; "
              f"paste it in:\n{table}")
print(f"{2 - failures} passed, {failures} failed")
sys.exit(1 if failures else 0)
