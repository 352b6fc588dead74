#!/usr/bin/python3
"""A run as a batch system meets it: SIGINT (Ctrl-C) and SIGTERM stop it at the end of a cycle
with a final state, a valid results.pvd, summary.json status "interrupted", the log flushed and
exit 128 + signal; a second run into the same output directory is refused while the first one
runs; OpenMP threads wait passively unless the user set OMP_WAIT_POLICY."""
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

ABUT = os.environ["ABUT_EXE"]
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


# A free cube of 2 x 2 x 2 elements for 10 s of simulated time: ~10^7 cycles, far longer than
# the test waits.
DECK = """*UNIT_SYSTEM
SI
*TIME
10.0
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"cube"
1, 1
*INITIAL_VELOCITY
P, 1, 1.0, 0.0, 0.0
*END
"""


def start(deck, out, env=None, log=None):
    """Starts a run with stdout to a file (fully buffered, as in a batch job) and waits until it
    has claimed its output directory."""
    process = subprocess.Popen([ABUT, "run", str(deck), "-o", str(out), "--threads", "1"],
                               stdout=log, stderr=subprocess.PIPE, text=True,
                               env={**os.environ, **(env or {})})
    deadline = time.time() + 60
    while not (out / "results.pvd").exists() and time.time() < deadline:
        time.sleep(0.05)
    time.sleep(0.3)
    return process


def environment_of(process):
    return dict(item.split("=", 1) for item in
                Path(f"/proc/{process.pid}/environ").read_text().split("\0") if "=" in item)


def pvd_files(out):
    return [d.get("file") for d in ET.parse(out / "results.pvd").getroot().iter("DataSet")]


with tempfile.TemporaryDirectory() as tmp:
    tmp = Path(tmp)
    deck = tmp / "long.k"
    deck.write_text(DECK)

    for sig, name in [(signal.SIGINT, "SIGINT"), (signal.SIGTERM, "SIGTERM")]:
        out = tmp / f"out_{name}"
        log_path = tmp / f"{name}.log"
        with open(log_path, "w") as log:
            first = start(deck, out, log=log)
            # The run owns its directory: a second run into it stops at once, naming the first.
            second = subprocess.run([ABUT, "run", str(deck), "-q", "-o", str(out)],
                                    capture_output=True, text=True, timeout=60)
            check(second.returncode == 2, f"{name}: a second run into the same directory exits 2")
            check(f"is in use by another run (pid {first.pid})" in second.stderr,
                  f"{name}: the second run names the first ({second.stderr.strip()!r})")
            if sig == signal.SIGINT:
                check(environment_of(first).get("OMP_WAIT_POLICY") == "passive",
                      "the run waits passively by default (OMP_WAIT_POLICY=passive)")
            first.send_signal(sig)
            _, stderr = first.communicate(timeout=120)
        check(first.returncode == 128 + sig, f"{name}: exit {128 + sig} (got {first.returncode})")
        check(f"interrupted by {name}" in stderr, f"{name}: stderr says it was interrupted")
        summary = json.loads((out / "summary.json").read_text())
        check(summary["status"] == "interrupted", f"{name}: summary.json status is interrupted")
        check(0 < summary["end_time"] < 10.0 and summary["cycles"] > 0, f"{name}: summary.json has the time it stopped")
        files = pvd_files(out)
        on_disk = sorted(f"states/{p.name}" for p in (out / "states").iterdir())
        check(len(files) >= 2 and sorted(files) == on_disk,
              f"{name}: results.pvd lists the {len(on_disk)} states on disk")
        log_text = log_path.read_text()
        check("writing results to" in log_text and "INTERRUPTED after" in log_text
              and "ParaView series" in log_text, f"{name}: the redirected log is complete")
        check(not (out / ".abut.lock").exists(), f"{name}: the lock is released")

    # The user's wait policy is kept.
    out = tmp / "out_active"
    process = start(deck, out, env={"OMP_WAIT_POLICY": "active"}, log=subprocess.DEVNULL)
    check(environment_of(process).get("OMP_WAIT_POLICY") == "active", "OMP_WAIT_POLICY=active is kept")
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=120)
    check(process.returncode == 130, "the run with the user's wait policy stops on SIGINT too")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all interruption checks passed")
