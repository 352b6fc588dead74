#!/usr/bin/python3
"""Restart from the command line (issue 13): a run stopped by SIGINT writes restart.abr, and
`abut run --restart FILE` continues it in the same output directory; the histories it leaves are
byte for byte those of a run that was never stopped. --restart-interval writes the file as the run
goes without changing its results. Bad options and files are exit 2 with a message."""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ABUT = os.environ["ABUT_EXE"]
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


# A metal block sliding with friction and wear on an elastic plate; outputs at fixed intervals
# (not fractions of the end time), so that runs with other end times write the same rows.
DECK = """*UNIT_SYSTEM
SI
*TIME
{end}
*OUTPUT
2.0e-4, 2.0e-5
*COMPONENT_BOX
1, 1, 4, 4, 1
0.0, 0.0, 0.0, 0.04, 0.04, 0.01
*COMPONENT_BOX
2, 2, 2, 2, 2
0.01, 0.01, 0.01, 0.03, 0.03, 0.03
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_METAL
2, 2700.0, 70.0e9, 0.33
7
*FUNCTION
7
1.0e8 + 4.0e8*epsp
*PART
1, 1
2, 2
*INITIAL_VELOCITY
P, 2, 2.0, 0.5, -3.0
*LOAD_GRAVITY
Z, 8, , , -1.0
*CURVE
8
0.0, 9.81
100.0, 9.81
*CONTACT
3
P, 1, P, 2, 0.3
0, 0.1
9, 9
*FUNCTION
9
1.0e-12*pres*vtang
*END
"""


def run(args, timeout=600):
    return subprocess.run([ABUT, "run", *map(str, args)], capture_output=True, text=True,
                          timeout=timeout)


def text(path):
    return Path(path).read_bytes()


with tempfile.TemporaryDirectory() as tmp:
    tmp = Path(tmp)
    long_deck = tmp / "slide.k"
    long_deck.write_text(DECK.format(end="100.0"))

    # Stopped by SIGINT once it has written a few states.
    out = tmp / "split"
    process = subprocess.Popen([ABUT, "run", str(long_deck), "-o", str(out), "--threads", "1",
                                "-q"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while len(list((out / "states").glob("*.vtu"))) < 3 and time.time() < deadline:
        time.sleep(0.05)
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=120)
    check(process.returncode == 130, f"SIGINT: exit 130 (got {process.returncode})")
    check((out / "restart.abr").is_file(), "SIGINT: restart.abr written")
    match = re.search(r"INTERRUPTED after (\d+) cycles at t = (\S+)", stdout)
    check(match is not None, "SIGINT: the log gives the time of the stop")
    check("--restart" in stdout, "SIGINT: the log says how to continue")
    stopped_at = float(match.group(2)) if match else 0.0

    # Continued with an end time a little later; the output directory is the file's.
    end = f"{1.5 * stopped_at + 2.0e-4:.6g}"
    short_deck = tmp / "short.k"
    short_deck.write_text(DECK.format(end=end))
    resumed = run([short_deck, "--restart", out / "restart.abr", "-q", "--threads", "2"])
    check(resumed.returncode == 0, f"restart: exit 0 (got {resumed.returncode}: {resumed.stderr})")
    check("continuing from" in resumed.stdout, "restart: the log says where it continues from")

    # The same end time in one go.
    whole = tmp / "whole"
    reference = run([short_deck, "-o", whole, "-q", "--threads", "1"])
    check(reference.returncode == 0, "whole run: exit 0")
    for name in ["energy.csv", "parts.csv", "contact.csv", "results.pvd"]:
        check(text(whole / name) == text(out / name), f"{name}: identical to the run in one go")
    states = sorted(p.name for p in (whole / "states").glob("*.vtu"))
    check(states == sorted(p.name for p in (out / "states").glob("*.vtu")),
          f"the same {len(states)} states")
    check(all(text(whole / "states" / s) == text(out / "states" / s) for s in states),
          "every state identical")

    # --restart-interval: the file is written as the run goes, the results are unchanged.
    every = tmp / "every"
    written = run([short_deck, "-o", every, "-q", "--restart-interval", "1e-4"])
    check(written.returncode == 0 and (every / "restart.abr").is_file(),
          "--restart-interval: restart.abr written")
    check(text(every / "energy.csv") == text(whole / "energy.csv"),
          "--restart-interval: energy.csv unchanged")

    # Bad options and files: exit 2 with a message.
    for value in ["abc", "-1", "0", "nan"]:
        bad = run([short_deck, "-o", tmp / "bad", "--restart-interval", value])
        check(bad.returncode == 2 and "--restart-interval" in bad.stderr,
              f"--restart-interval {value}: exit 2 naming the option")
    missing = run([short_deck, "--restart", tmp / "none.abr"])
    check(missing.returncode == 2 and "does not exist" in missing.stderr,
          "a missing restart file: exit 2")
    other = tmp / "other.k"
    other.write_text(DECK.format(end=end).replace("1, 1, 4, 4, 1", "1, 1, 4, 5, 1"))
    unfit = run([other, "--restart", out / "restart.abr", "-o", tmp / "unfit"])
    check(unfit.returncode == 2 and "another mesh" in unfit.stderr,
          "a restart file of another mesh: exit 2")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all checks passed")
