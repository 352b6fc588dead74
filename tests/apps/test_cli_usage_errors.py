#!/usr/bin/python3
"""Every mistake on the command line is exit 2 with a plain message: an unknown command, a
missing deck, a directory given as deck, an unreadable deck, a bad (or empty) --threads or
--restart-interval, an unknown option,
and an output directory that cannot be written (the default one beside a deck in a read-only
directory included). --help and --version still succeed."""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ABUT = os.environ["ABUT_EXE"]
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(*args, user=None):
    return subprocess.run([ABUT, *args], capture_output=True, text=True, timeout=600, user=user)


def usage_error(result, message, what):
    check(result.returncode == 2, f"{what}: exit 2 (got {result.returncode})")
    check(message in result.stderr, f"{what}: says '{message}' (got {result.stderr.strip()!r})")


DECK = """*UNIT_SYSTEM
SI
*TIME
1.0e-6
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"cube"
1, 1
*END
"""

with tempfile.TemporaryDirectory() as tmp:
    tmp = Path(tmp)
    deck = tmp / "cube.k"
    deck.write_text(DECK)

    usage_error(run("xyz", str(deck)), "unknown command 'xyz'; use run, check or info", "unknown command")
    usage_error(run(), "a command is required; use run, check or info", "no command")
    for command in ["run", "check", "info"]:
        usage_error(run(command, str(tmp / "missing.k")), f"deck '{tmp / 'missing.k'}' not found",
                    f"{command} with a missing deck")
    usage_error(run("run", str(tmp)), "is a directory, not a deck", "a directory as deck")
    for bad in ["", "0", "-1", "abc", "2.5", "100000000000000000000"]:
        r = run("run", str(deck), "-q", "--threads", bad)
        usage_error(r, "--threads must be a whole number between 1 and 1024", f"--threads {bad}")
        check(len(r.stderr) < 200, f"--threads {bad}: a short message")
    usage_error(run("run", str(deck), "-q", "--restart-interval", ""),
                "--restart-interval must be a positive model time", "an empty --restart-interval")
    usage_error(run("run", str(deck), "--frobnicate"), "frobnicate", "an unknown option")
    usage_error(run("run"), "deck", "run without a deck")

    r = run("--help")
    check(r.returncode == 0 and "run" in r.stdout, "--help exits 0")
    r = run("run", "--help")
    check(r.returncode == 0 and "--threads" in r.stdout, "run --help exits 0")
    r = run("--version")
    check(r.returncode == 0 and r.stdout.startswith("abut "), "--version exits 0")

    # An output directory below a file cannot be made.
    usage_error(run("run", str(deck), "-q", "-o", str(deck / "out")), "-o DIR", "an output directory below a file")
    (tmp / "taken").write_text("a file\n")
    usage_error(run("run", str(deck), "-q", "-o", str(tmp / "taken")), "is a file, not a directory",
                "a file as output directory")

    # A deck in a read-only directory: its default output directory beside it cannot be made.
    # Root writes anywhere, so as root the program runs as nobody.
    user = "nobody" if os.geteuid() == 0 else None
    readonly = tmp / "readonly"
    readonly.mkdir()
    locked_deck = readonly / "cube.k"
    locked_deck.write_text(DECK)
    unreadable = tmp / "unreadable.k"
    unreadable.write_text(DECK)
    unreadable.chmod(0o000)
    readonly.chmod(0o555)
    tmp.chmod(0o755)
    r = run("run", str(locked_deck), "-q", user=user)
    usage_error(r, f"cannot write the output directory '{readonly / 'cube_out'}'", "a deck in a read-only directory")
    check("-o DIR" in r.stderr, "a read-only directory: the message suggests -o DIR")
    usage_error(run("check", str(unreadable), user=user), f"cannot read the deck '{unreadable}'", "an unreadable deck")
    readonly.chmod(0o755)

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all usage error checks passed")
