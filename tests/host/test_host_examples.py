#!/usr/bin/python3
"""The host examples (examples/host) as a host project builds them: abut installed into a fresh
prefix, found there by find_package(abut COMPONENTS contact), the C and the C++ program built and
run. References chosen before the runs (statics and the examples' own model, box_model.h):
- at rest, the contact under box A carries its weight, the plane both boxes' (to 1e-6: the boxes
  come to rest under mass-proportional damping, e^(-c t / 2) = e^-20 of their motion is left);
- the energy balance (host springs, motion, damping work, the contacts' stored and lost energy
  against the work of gravity) holds to 1% of the work of gravity at every output;
- the C and the C++ program (one through abut_contact.h, one through interface.hpp) print the
  same numbers: the C interface adds nothing to the library's arithmetic;
- the Fortran program (through iso_c_binding) rests its plate on the contact with its weight."""
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(os.environ["ABUT_SOURCE_DIR"])
BUILD = Path(os.environ["ABUT_BUILD_DIR"])
CXX = os.environ.get("ABUT_CXX_COMPILER", "c++")
SANITIZE = os.environ.get("ABUT_SANITIZE", "OFF") in ("ON", "1", "TRUE")
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(args, **kw):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=600, **kw)
    if done.returncode != 0:
        print(done.stdout[-4000:], done.stderr[-4000:])
        raise SystemExit(f"FAIL  {' '.join(map(str, args))} exited with {done.returncode}")
    return done.stdout


def c_compiler(cxx):
    """The C compiler beside the build's C++ compiler (g++ -> gcc, clang++ -> clang)."""
    name = Path(cxx).name
    for plus, plain in (("clang++", "clang"), ("g++", "gcc"), ("c++", "cc")):
        if plus in name:
            return str(Path(cxx).with_name(name.replace(plus, plain)))
    return "cc"


with tempfile.TemporaryDirectory() as tmp:
    prefix, host = Path(tmp) / "prefix", Path(tmp) / "host"
    run(["cmake", "--install", BUILD, "--prefix", prefix])
    check((prefix / "lib/cmake/abut/abutConfig.cmake").exists(), "the CMake package is installed")
    check((prefix / "include/abut/abut_contact.h").exists(), "the C header is installed")
    configure = ["cmake", "-S", SOURCE / "examples/host", "-B", host, "-G", "Ninja",
                 f"-DCMAKE_PREFIX_PATH={prefix}", f"-DCMAKE_CXX_COMPILER={CXX}",
                 f"-DCMAKE_C_COMPILER={c_compiler(CXX)}", "-DCMAKE_BUILD_TYPE=Release"]
    if SANITIZE:  # the installed libraries carry the sanitizers' calls: the host links their runtime
        flags = "-fsanitize=address,undefined"
        configure += [f"-DCMAKE_C_FLAGS={flags}", f"-DCMAKE_CXX_FLAGS={flags}"]
    run(configure)
    run(["cmake", "--build", host])
    outputs = {name: run([host / name]) for name in ("falling_boxes_c", "falling_boxes_cpp")}
    # Fortran through iso_c_binding (gfortran is in deps/debian-packages.txt): a plate of 4 m
    # comes to rest on a fixed square, carrying 4 m g (statics, to 1e-6 as above).
    fortran = run([host / "falling_plate_f90"])
    # The installed program and Python package (not in the sanitizer build, which has no Python
    # package): a run plotted by bin/abut, and the package imported from the prefix alone.
    package = prefix / "lib/python3/dist-packages"
    if (package / "abut/__init__.py").exists():
        deck = SOURCE / "examples/tutorials/t1_bars_collide.k"
        out = Path(tmp) / "t1_out"
        run([prefix / "bin/abut", "run", deck, "-o", out, "-q", "--plot"])
        check((out / "plots/energy.png").exists(), "the installed abut plots with the installed package")
        imported = run(["/usr/bin/python3", "-c", "import abut; print(abut.__file__)"],
                       env={**os.environ, "PYTHONPATH": str(package)}, cwd=tmp)
        check(imported.strip() == str(package / "abut/__init__.py"),
              f"the installed Python package imports from the prefix ({imported.strip()})")

for name, text in outputs.items():
    rows = [line.split() for line in text.splitlines() if re.match(r"\s*\d+\.\d+\s", line)]
    check(len(rows) == 17, f"{name}: 17 outputs over 4 s ({len(rows)})")
    worst = max(abs(float(r[4])) for r in rows)
    check(worst < 0.01, f"{name}: energy balance within 1% of gravity's work at every output "
          f"(worst {worst:.2e})")
    rest = re.search(r"N_AB / \(m_A g\) = ([\d.]+), N_floor / \(\(m_A \+ m_B\) g\) = ([\d.]+)", text)
    check(rest is not None, f"{name}: prints the forces at rest")
    if rest:
        ab, ground = float(rest.group(1)), float(rest.group(2))
        check(abs(ab - 1) < 1e-6, f"{name}: box A's contact carries its weight ({ab:.9f})")
        check(abs(ground - 1) < 1e-6, f"{name}: the plane carries both boxes ({ground:.9f})")
rest = re.search(r"N / \(4 m g\) = +([\d.]+)", fortran)
check(rest is not None and abs(float(rest.group(1)) - 1) < 1e-6,
      f"falling_plate_f90: the plate's contact carries its weight ({fortran.strip()})")
check(outputs["falling_boxes_c"] == outputs["falling_boxes_cpp"],
      "the C and the C++ host print the same numbers")

# The excerpts of docs/contact.md (a fenced block after "<!-- excerpt: FILE -->") are still lines of
# their files, in order, as the tests build them.
doc = (SOURCE / "docs/contact.md").read_text()
excerpts = re.findall(r"<!-- excerpt: (\S+) -->\n```\w*\n(.*?)```", doc, re.S)
check(len(excerpts) >= 4, f"docs/contact.md shows the host examples ({len(excerpts)} excerpts)")
for path, block in excerpts:
    want = [line.strip() for line in block.strip().splitlines()]
    have = [line.strip() for line in (SOURCE / path).read_text().splitlines()]
    found = any(have[i:i + len(want)] == want for i in range(len(have)))
    check(found, f"docs/contact.md: the excerpt starting '{want[0]}' is in {path}")

print(outputs["falling_boxes_c"])
sys.exit(1 if failures else 0)
