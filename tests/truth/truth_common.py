"""What the truth tests share: failing with a message, and running a program expecting an exit."""
import subprocess
import sys


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def run_with(env, *args, expect=0):
    """Runs `args` with `env`; fails unless it exits `expect`. Returns the finished process."""
    p = subprocess.run(args, env=env, capture_output=True, text=True)
    if p.returncode != expect:
        fail(f"{' '.join(args)} exited {p.returncode}, expected {expect}:\n{p.stdout}{p.stderr}")
    return p
