#!/usr/bin/python3
"""CalculiX's solid elements against CalculiX as a peer: one elastic cantilever, 100 x 10 x 10 mm
(E = 200 GPa, nu = 0.3, units N, mm, MPa), clamped at x = 0, tip load along z, meshed with each
of C3D8 (reference), C3D20, C3D20R, C3D10, C3D4 and C3D6; abut and ccx run the same generated
deck and their step-end .dat blocks are compared: tip displacements (*NODE PRINT U), the total
support reaction (RF, TOTALS=ONLY) and the stresses, strains and energy densities at the
integration points of a few root elements (*EL PRINT S, E, ENER).

Step 1: small strain (*STATIC, one increment, no NLGEOM), tip load 1 kN. Step 2: NLGEOM, 15 kN
(tip deflection about a quarter of the length), four fixed increments (*STATIC, DIRECT), and
*CONTROLS that make both codes iterate to convergence (residual and correction 1e-9 of their
references instead of the defaults 0.005 and 0.02, manual "*CONTROLS" and "Convergence
criteria"): with the defaults each code stops up to 2e-5 (relative) short of the equilibrium
here, at different iterates.

Meshes: C3D8 20x2x4; C3D20, C3D20R 10x1x2 with midside nodes; C3D10: each hex of a 10x2x2 grid
split into 6 tetrahedra around its main diagonal (Kuhn split, the same in every hex, so the
face diagonals and their midside nodes are shared between neighbours); C3D4 the same split of
20x2x4; C3D6: each hex of 20x2x4 split into 2 wedges (triangles in x-y, wedge axis along z).
Connectivity follows the CalculiX manual (ccx 2.20, theory chapter, section "Element Types": the
node numbering of C3D8, C3D20, C3D10, C3D4, C3D6); every element's volume is checked positive in
that convention.
The tip load is the consistent load of a uniform shear traction on the tip face (manual,
"Facial distributed loading", figures of the equivalent nodal forces: quadratic quad faces
-1/12 at the corners and 1/3 at the midsides, quadratic triangles 0 and 1/3, linear faces
equal shares), so the deflections can be read against beam theory.

Integration points: both codes must print the same points in the same order and convention
(docs/notes/ccx_element_conventions.md: C3D20 27, C3D20R 8, C3D10 4, C3D4 1, C3D8 8).

C3D6 differs on purpose: CalculiX integrates it with 2 points (the triangle's centroid on two
levels), which leaves one element a spurious zero-energy mode (its triangles turning opposite ways
about its axis); abut uses 6 (the triangle's 3-point rule on each level) and has none
(tests/element/test_solid_full.cpp). The two rules are consistent, so on refinement both converge
to the same solution and their difference falls with the mesh size h as h^2: the test checks that
the tip deflections' difference falls by at least 3 (h^2 predicts 4) from 20x2x4 to 40x4x8
(measured: 6.6% -> 1.8%, and 0.47% at 80x8x16).

Tolerances, max |abut - ccx| / max |ccx| per block: same mesh, same elements, same Gauss points,
the same linear elasticity, so the codes differ only by round-off, the linear solvers and (step 2)
where each stops its Newton iterations: 1e-6 in the linear step, 1e-5 with NLGEOM (abut's own
convergence tolerance; measured with C3D8, which abut has: 0 in step 1, 3.9e-7 in step 2). Each
file prints 7 significant digits and rounds on its own: one unit in the last digit of the block's
largest value (<= 1e-6 of it) is added to both tolerances.

Without ccx (Debian calculix-ccx) the test prints SKIP and passes. Each element type is reported;
the exit code is 1 if any type fails (abut stops, a block is missing or differs).
"""
import itertools
import shutil
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import test_ccx_conformance as conf  # noqa: E402

LENGTH, WIDTH, HEIGHT = 100.0, 10.0, 10.0
E_MOD, NU = 200000.0, 0.3
LOADS = (1000.0, 15000.0)      # tip load [N], step 1 (linear) and step 2 (NLGEOM)
TOLERANCE = (1e-6, 1e-5)       # per step, relative to the block's largest value
PRINT_DIGIT = 1e-6             # one unit in the 7th significant digit, relative
# Both codes iterate to convergence in the NLGEOM step (see above).
CONTROLS = ["*CONTROLS,PARAMETERS=FIELD,FIELD=DISPLACEMENT", "1e-9,1e-9"]

# type: (nx, ny, nz, split of each hex, quadratic)
TYPES = {
    "C3D8": (20, 2, 4, "hex", False),
    "C3D20": (10, 1, 2, "hex", True),
    "C3D20R": (10, 1, 2, "hex", True),
    "C3D10": (10, 2, 2, "tet", True),
    "C3D4": (20, 2, 4, "tet", False),
    "C3D6": (20, 2, 4, "wedge", False),
}
# Midside nodes (CalculiX numbering): the edges of nodes 9..20 (C3D20) and 5..10 (C3D10).
HEX_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
             (0, 4), (1, 5), (2, 6), (3, 7)]
TET_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]


def det3(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


def cells(etype):
    """Corner lists of the elements of one unit hex (offsets 0/1 along x, y, z), in CalculiX's
    node order with positive volume."""
    split = TYPES[etype][3]
    if split == "hex":
        return [[(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                 (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]]
    if split == "wedge":  # bottom triangle counter-clockwise seen from +z, then the top one
        return [[(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1)],
                [(0, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1), (0, 1, 1)]]
    tets = []  # Kuhn: the paths 000 -> 111 along the axes in each of the 6 orders
    for perm in itertools.permutations(range(3)):
        v = [(0, 0, 0)]
        for axis in perm:
            v.append(tuple(x + (1 if i == axis else 0) for i, x in enumerate(v[-1])))
        if det3(*[[b - a for a, b in zip(v[0], p)] for p in v[1:]]) < 0:
            v[1], v[2] = v[2], v[1]
        tets.append(v)
    return tets


def cantilever(etype, refine=1):
    """The deck of the cantilever meshed with `etype`, its mesh refined `refine` times."""
    nx, ny, nz, split, quadratic = TYPES[etype]
    nx, ny, nz = refine * nx, refine * ny, refine * nz
    q = 2 if quadratic else 1  # lattice points per element edge
    dims = (q * nx, q * ny, q * nz)
    nid = lambda p: 1 + p[0] + (dims[0] + 1) * (p[1] + (dims[1] + 1) * p[2])
    xyz = lambda p: (LENGTH * p[0] / dims[0], WIDTH * p[1] / dims[1], HEIGHT * p[2] / dims[2])
    elements, root = [], []
    for k, j, i in itertools.product(range(nz), range(ny), range(nx)):
        for corners in cells(etype):
            pts = [(q * (i + a), q * (j + b), q * (k + d)) for a, b, d in corners]
            if quadratic:
                edges = HEX_EDGES if split == "hex" else TET_EDGES
                pts += [tuple((u + v) // 2 for u, v in zip(pts[a], pts[b])) for a, b in edges]
            x = [xyz(p) for p in pts]
            # the edges from node 1 along the natural axes: to 2, 4, 5 (hex) or 2, 3, 4
            axes = (1, 3, 4) if split == "hex" else (1, 2, 3)
            vol = det3(*[[b - a for a, b in zip(x[0], x[m])] for m in axes])
            assert vol > 0, f"{etype}: negative volume in cell {i, j, k}"
            elements.append([nid(p) for p in pts])
            if i == 0 and j == 0 and k in (0, nz - 1):
                root.append(len(elements))
    used = sorted({n for e in elements for n in e})
    coords = {nid(p): xyz(p) for p in itertools.product(*(range(d + 1) for d in dims))}
    fix = [n for n in used if coords[n][0] == 0.0]
    tip = [n for n in used if coords[n][0] == LENGTH]

    # Consistent nodal forces of a unit total shear traction on the tip face.
    share = dict.fromkeys(tip, 0.0)
    face_area = WIDTH * HEIGHT / (ny * nz)
    tipset = set(tip)
    for e in elements:
        ncorner = {"hex": 8, "wedge": 6, "tet": 4}[split]
        corners = [n for n in e[:ncorner] if n in tipset]
        if len(corners) < 3:
            continue
        area = face_area * (1.0 if len(corners) == 4 else 0.5)
        mids = [n for n in e[ncorner:] if n in tipset]
        if not quadratic:
            for n in corners:
                share[n] += area / len(corners)
        else:
            corner, mid = (-1 / 12, 1 / 3) if len(corners) == 4 else (0.0, 1 / 3)
            for n in corners:
                share[n] += area * corner
            for n in mids:
                share[n] += area * mid
    total = sum(share.values())

    out = ["*HEADING", f"elastic cantilever, {etype} (abut peer test)", "*NODE"]
    out += [f"{n},{coords[n][0]:.10g},{coords[n][1]:.10g},{coords[n][2]:.10g}" for n in used]
    out.append(f"*ELEMENT,TYPE={etype},ELSET=EALL")
    for number, e in enumerate(elements, 1):
        ids = [str(number)] + [str(n) for n in e]
        out += [",".join(ids[:16]) + ("," if len(ids) > 16 else "")]
        if len(ids) > 16:
            out.append(",".join(ids[16:]))
    out += ["*NSET,NSET=FIX"] + [",".join(map(str, fix[m:m + 12])) for m in range(0, len(fix), 12)]
    out += ["*NSET,NSET=TIP"] + [",".join(map(str, tip[m:m + 12])) for m in range(0, len(tip), 12)]
    out += ["*ELSET,ELSET=ROOT", ",".join(map(str, root)),
            "*MATERIAL,NAME=STEEL", "*ELASTIC", f"{E_MOD},{NU}",
            "*SOLID SECTION,ELSET=EALL,MATERIAL=STEEL", "*BOUNDARY", "FIX,1,3"]
    prints = ["*NODE PRINT,NSET=TIP", "U", "*NODE PRINT,NSET=FIX,TOTALS=ONLY", "RF",
              "*EL PRINT,ELSET=ROOT", "S,E,ENER"]
    for number, load in enumerate(LOADS):
        out += ["*STEP" if number == 0 else "*STEP,NLGEOM,INC=100",
                "*STATIC" if number == 0 else "*STATIC,DIRECT",
                *([] if number == 0 else ["0.25,1."] + CONTROLS), "*CLOAD"]
        out += [f"{n},3,{load * share[n] / total:.10g}" for n in tip if share[n] != 0.0]
        out += prints + ["*END STEP"]
    return "\n".join(out) + "\n"


def tip_deflection(blocks, time):
    """Mean u_z of the tip nodes at `time`, from the parsed .dat."""
    for (title, t), b in blocks.items():
        if title.startswith("displacements") and t == conf.time_key(time):
            return sum(v[2] for _, v in b["rows"]) / len(b["rows"])
    return None


def compare(deck, ccx_dat, abut_dat):
    """Failures (strings) of one element type; prints one line per block."""
    failures = []
    ref, got = conf.parse_dat(ccx_dat), conf.parse_dat(abut_dat)
    ends = [conf.time_key(t) for t in conf.step_end_times(deck)]
    for key, block in sorted(ref.items(), key=lambda kv: kv[1]["time"]):
        if key[1] not in ends:
            continue
        step = ends.index(key[1])
        tol = TOLERANCE[step] + PRINT_DIGIT
        other = got.get(key)
        if other is None:
            failures.append(f"abut printed no '{block['title']}' at time {block['time']:g}")
            continue
        for quantity, err, _, note in conf.compare_block(block, other):
            ok = err is not None and err <= tol
            print(f"  {'ok  ' if ok else 'FAIL'} step {step + 1} {quantity:12s} error "
                  f"{err if err is not None else float('nan'):.2e} (tolerance {tol:.1e}); {note}")
            if not ok:
                failures.append(f"{quantity} in step {step + 1}: {err}")
    return failures


# Types whose integration rule differs from CalculiX's (see above): the codes' difference must
# fall by at least this factor when the mesh is refined twice.
CONVERGING = {"C3D6": 3.0}


def converging(etype, ccx, abut, work, ccx_coarse, abut_coarse):
    """Failures of a type checked by the convergence of the two codes' tip deflections."""
    deck = cantilever(etype, refine=2)
    c = conf.run_ccx(ccx, deck, work / "ccx2", "beam")
    (work / "abut2").mkdir(parents=True)
    (work / "abut2" / "beam.inp").write_text(deck)
    a = conf.run_abut(abut, work / "abut2" / "beam.inp", work / "abut2" / "out")
    problem = conf.abut_problem(a)
    if not c["ok"] or problem:
        return [problem or "ccx did not run the refined deck"]
    ccx_fine = tip_deflection(conf.parse_dat(c["dat"]), 1.0)
    abut_fine = tip_deflection(conf.parse_dat(a["dat"]), 1.0)
    coarse = abs(abut_coarse - ccx_coarse) / abs(ccx_coarse)
    fine = abs(abut_fine - ccx_fine) / abs(ccx_fine)
    ok = fine * CONVERGING[etype] <= coarse
    print(f"  {'ok  ' if ok else 'FAIL'} tip deflection, abut against ccx: {coarse:.2%} "
          f"(ccx {ccx_coarse:.5f}, abut {abut_coarse:.5f}), with h halved {fine:.2%} "
          f"(ccx {ccx_fine:.5f}, abut {abut_fine:.5f}); at least {CONVERGING[etype]:g}x smaller required")
    return [] if ok else [f"difference {coarse:.2%} -> {fine:.2%} on refinement"]


def main():
    ccx = shutil.which("ccx")
    if not ccx:
        print("SKIP: ccx (Debian calculix-ccx) is not installed")
        return 0
    abut = conf.find_abut()
    have_abut = Path(abut).is_file()
    verdicts, deflections = {}, {}
    with tempfile.TemporaryDirectory(prefix="abut_elements_") as tmp:
        for etype in TYPES:
            work = Path(tmp) / etype
            deck = cantilever(etype)
            print(f"{etype}:")
            c = conf.run_ccx(ccx, deck, work / "ccx", "beam")
            if not c["ok"]:
                verdicts[etype] = ["ccx did not run the generated deck"]
                print("  FAIL ccx did not run the generated deck")
                continue
            ref = conf.parse_dat(c["dat"])
            row = [tip_deflection(ref, t) for t in (1.0, 2.0)]
            if not have_abut:
                verdicts[etype] = [f"abut not found at {abut}"]
                deflections[etype] = row + [None]
                continue
            (work / "abut").mkdir(parents=True)
            (work / "abut" / "beam.inp").write_text(deck)
            a = conf.run_abut(abut, work / "abut" / "beam.inp", work / "abut" / "out")
            problem = conf.abut_problem(a)
            if problem:
                verdicts[etype] = [problem]
                print(f"  FAIL {problem}")
                deflections[etype] = row + [None]
                continue
            mine = tip_deflection(conf.parse_dat(a["dat"]), 1.0)
            if etype in CONVERGING:
                verdicts[etype] = converging(etype, ccx, abut, work, row[0], mine)
            else:
                verdicts[etype] = compare(deck, c["dat"], a["dat"])
            deflections[etype] = row + [mine]
            print(f"  abut {a['wall']:.2f} s, ccx {c['wall']:.2f} s")

    inertia = WIDTH * HEIGHT ** 3 / 12.0
    bending = LOADS[0] * LENGTH ** 3 / (3.0 * E_MOD * inertia)
    shear = LOADS[0] * LENGTH / (5.0 / 6.0 * E_MOD / (2.0 * (1.0 + NU)) * WIDTH * HEIGHT)
    print(f"\nTip deflection, mean u_z of the tip nodes [mm]; step 1 ({LOADS[0]:g} N): "
          f"Euler-Bernoulli PL^3/(3EI) = {bending:.5f}, Timoshenko (k = 5/6) = "
          f"{bending + shear:.5f}")
    print(f"{'type':7s} {'ccx step 1':>11s} {'/ Timoshenko':>12s} {'abut step 1':>12s} "
          f"{'ccx step 2 (NLGEOM, ' + format(LOADS[1], 'g') + ' N)':>30s}")
    fmt = lambda v: "—" if v is None else f"{v:.5f}"
    for etype, (lin, nonlin, mine) in deflections.items():
        ratio = "—" if lin is None else f"{lin / (bending + shear):.4f}"
        print(f"{etype:7s} {fmt(lin):>11s} {ratio:>12s} {fmt(mine):>12s} {fmt(nonlin):>30s}")

    print()
    for etype, failures in verdicts.items():
        print(f"{'ok  ' if not failures else 'FAIL'} {etype}"
              + ("" if not failures else ": " + "; ".join(failures[:3])))
    return 1 if any(verdicts.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
