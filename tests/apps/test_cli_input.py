#!/usr/bin/python3
"""Decks that ran to a silent wrong result (exit 0) or failed without a location (issue 13): the
program now stops with exit code 2, the file and line, and writes no output."""
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


def run(*args):
    return subprocess.run([ABUT, *args], capture_output=True, text=True, timeout=600)


BOX = """*UNIT_SYSTEM
SI
*TIME
1.0e-5
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 2.0, 2.0, 1.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
"""

INVERTED_RIGID = """*TIME
1.0e-5
*NODE
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, -1
6, 1, 0, -1
7, 1, 1, -1
8, 0, 1, -1
*ELEMENT_SOLID
12, 1, 1, 2, 3, 4, 5, 6, 7, 8
*MAT_RIGID
1, 7800
*PART
1, 1
"""

TINY_RIGID = BOX + """*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.0, 1.0, 1.0, 1.0, 2.0
*MAT_RIGID
2, 1e-320
*PART
2, 2
*CONTACT
3
P, 1, P, 2
"""


def refused(name, text, line, words, binary=False):
    """check, info and run each exit 2 naming <name>:<line>, and run writes nothing."""
    deck = tmp / name
    if binary:
        deck.write_bytes(text)
    else:
        deck.write_text(text)
    out = tmp / (deck.stem + "_out")
    for command in (["check"], ["info"], ["run", "-q", "-o", str(out)]):
        r = run(*command[:1], str(deck), *command[1:])
        located = f"{name}:{line}:" in r.stderr
        check(r.returncode == 2 and located and all(w in r.stderr for w in words),
              f"{command[0]} {name}: exit 2 at line {line} ({r.returncode}: {r.stderr.strip()})")
    check(not out.exists(), f"run {name} writes no output directory")


with tempfile.TemporaryDirectory() as tmp:
    tmp = Path(tmp)
    refused("inverted_rigid.k", INVERTED_RIGID, 13, ["element 12", "inverted"])
    refused("tiny_rigid.k", TINY_RIGID, 20, ["initial stable time step"])
    refused("big_density.k", BOX.replace("7800.0", "1e308"), 11, ["mass inf"])
    refused("nan_velocity.k", BOX + "*FUNCTION\n4\nacos(2)\n*INITIAL_VELOCITY\nP, 1, fcn(4), 0, 0\n",
            16, ["function 4", "expected a finite speed"])

    r = run("check", "/dev/zero")
    check(r.returncode == 2 and "not a regular file" in r.stderr, "check /dev/zero: exit 2 at once")

    # A byte-order mark and old line ends are read like any deck.
    for name, data in [("bom.k", b"\xef\xbb\xbf" + BOX.encode()),
                       ("crlf.k", BOX.replace("\n", "\r\n").encode()),
                       ("cr.k", BOX.replace("\n", "\r").encode())]:
        (tmp / name).write_bytes(data)
        r = run("check", str(tmp / name))
        check(r.returncode == 0 and "OK (18 nodes" in r.stdout, f"check {name}: OK ({r.stderr.strip()})")

if failures:
    print(f"{len(failures)} failed")
    sys.exit(1)
