#!/usr/bin/python3
"""The abut program as a user meets it: exit codes, error messages with file and line, the
output directory of a run, and an unstable run that stops with its last good state written."""
import json
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


def run(*args, cwd=None):
    return subprocess.run([ABUT, *args], capture_output=True, text=True, cwd=cwd, timeout=600)


BLOCK = """*UNIT_SYSTEM
SI
*TIME
{t_end}
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"cube"
1, 1
{extra}*END
"""

with tempfile.TemporaryDirectory() as tmp:
    tmp = Path(tmp)

    # --version and --help
    r = run("--version")
    check(r.returncode == 0 and r.stdout.startswith("abut "), "--version prints 'abut <version>'")
    r = run("--help")
    check(r.returncode == 0 and "run" in r.stdout and "check" in r.stdout and "info" in r.stdout,
          "--help lists run, check and info")

    # A good deck: check, info, run with the default output directory beside the deck.
    good = tmp / "cube.k"
    good.write_text(BLOCK.format(t_end="1.0e-5", extra="*INITIAL_VELOCITY\nP, 1, 1.0, 0.0, 0.0\n"))
    r = run("check", str(good))
    check(r.returncode == 0 and "OK" in r.stdout, "check accepts a good deck")
    r = run("info", str(good))
    check(r.returncode == 0 and "cube" in r.stdout and "mass" in r.stdout, "info lists the part and its mass")
    r = run("run", str(good), "-q")
    out = tmp / "cube_out"
    check(r.returncode == 0, "run exits 0")
    for name in ["results.pvd", "energy.csv", "parts.csv", "summary.json"]:
        check((out / name).is_file(), f"run writes {name} into <deck stem>_out/")
    summary = json.loads((out / "summary.json").read_text())
    check(summary["status"] == "completed" and summary["cycles"] > 0, "summary.json says completed")
    check(abs(summary["parts"][0]["mass"] - 7800.0 * 1e-6) < 1e-12, "summary.json has the part's mass")
    # The run's own ParaView series opens with VTK's reader and carries the documented fields.
    import xml.etree.ElementTree as ET
    import vtk
    states = [d.get("file") for d in ET.parse(out / "results.pvd").getroot().iter("DataSet")]
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(out / states[-1]))
    reader.Update()
    grid = reader.GetOutput()
    check(grid.GetNumberOfCells() == 8 and grid.GetNumberOfPoints() == 27, "the last state opens in VTK: 8 hexahedra")
    names = [grid.GetPointData().GetArrayName(i) for i in range(grid.GetPointData().GetNumberOfArrays())]
    names += [grid.GetCellData().GetArrayName(i) for i in range(grid.GetCellData().GetNumberOfArrays())]
    for field in ["displacement", "velocity", "von_mises_stress", "pressure", "part_id"]:
        check(field in names, f"the state has the field {field}")
    vx = grid.GetPointData().GetArray("velocity").GetComponent(0, 0)
    check(abs(vx - 1.0) < 1e-6, "a free cube keeps its initial velocity of 1 m/s")
    header = (out / "energy.csv").read_text().splitlines()[0]
    check(header == "time,kinetic,internal,hourglass,contact,friction,eroded,contact_released,external_work,total,balance_error",
          "energy.csv has the documented columns")

    # A bad number: exit 2, message with file:line, keyword and field.
    bad = tmp / "bad.k"
    bad.write_text(BLOCK.format(t_end="1.0e-5", extra="").replace("7800.0", "78OO.0"))
    r = run("check", str(bad))
    check(r.returncode == 2, "a bad number exits with 2")
    check(f"{bad}:9" in r.stderr and "*MAT_ELASTIC" in r.stderr, "the error names file:line and keyword")

    # An unknown keyword.
    bad.write_text(BLOCK.format(t_end="1.0e-5", extra="*CONTCT\n1\n"))
    r = run("check", str(bad))
    check(r.returncode == 2 and "*CONTCT" in r.stderr and ":13" in r.stderr, "an unknown keyword is an error at its line")

    # An unstable run: the top face driven through the cube (bottom held) crushes the top
    # elements; their step collapses (the bulk viscosity shortens it with their thickness).
    unstable = tmp / "crush.k"
    unstable.write_text(BLOCK.format(t_end="1.0e-4", extra="""*GEOMETRY_BOX
1
-1.0, -1.0, 0.0099, 1.0, 1.0, 1.0
*CURVE
1
0.0, -2000.0
1.0, -2000.0
*BC_MOTION
G, 1, XY
V, Z, 1
*GEOMETRY_BOX
2
-1.0, -1.0, -1.0, 1.0, 1.0, 0.0001
*BC_MOTION
G, 2, XYZ
"""))
    r = run("run", str(unstable), "-q")
    out = tmp / "crush_out"
    check(r.returncode == 3, "an unstable run exits with 3")
    check("UNSTABLE" in r.stdout or "unstable" in r.stderr, "it says that it went unstable")
    summary = json.loads((out / "summary.json").read_text())
    check(summary["status"] == "unstable" and "collapsed" in summary["message"], "summary.json records why it stopped")
    pvd = (out / "results.pvd").read_text()
    check(pvd.count("<DataSet") >= 2, "the series holds the states up to the last good one")

    # An energy that overflows while the coordinates stay finite (issue 28): a rigid box of
    # 1e300 kg driven at v = 1e5 t m/s; (1/2) M v^2 passes 1.797e308 J between t = 0.18 and
    # 0.19 s. The run stops as unstable naming the quantity, its histories end at t = 0.18.
    dense = tmp / "dense.k"
    dense.write_text("""*UNIT_SYSTEM
SI
*TIME
1.0, 0.9, 0, 0.01
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 1.0, 1.0, 1.0
*MAT_RIGID
1, 1.0e300
*PART
1, 1
*CURVE
1
0.0, 0.0
1.0, 1.0e5
*BC_MOTION
P, 1, YZ, XYZ
V, X, 1
*OUTPUT
0.01, 0.01
*END
""")
    r = run("run", str(dense), "-q")
    out = tmp / "dense_out"
    check(r.returncode == 3, f"an overflowing kinetic energy exits with 3 (got {r.returncode})")
    summary = json.loads((out / "summary.json").read_text())
    check(summary["status"] == "unstable" and "kinetic energy is inf" in summary["message"],
          "summary.json names the kinetic energy")
    for name in ["energy.csv", "parts.csv"]:
        rows = [line.split(",") for line in (out / name).read_text().splitlines()[1:]]
        values = [float(v) for row in rows for v in row]
        check(rows and all(abs(v) <= 1.8e308 for v in values), f"{name} holds finite numbers only")
    last = float((out / "energy.csv").read_text().splitlines()[-1].split(",")[0])
    check(abs(last - 0.18) < 1e-9, f"energy.csv ends at the last good time 0.18 (got {last})")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all CLI checks passed")
