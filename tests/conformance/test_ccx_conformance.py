#!/usr/bin/python3
"""Conformance with CalculiX: abut runs CalculiX's own contact test decks (Debian package
calculix-ccx-test) and its printed results (*NODE PRINT, *EL PRINT, *CONTACT PRINT in the .dat
layout) are compared with CalculiX's reference .dat files, block by block.

A block is one printed table: its header without the time ("displacements (vx,vy,vz) for set
NALL"), its time, and its rows keyed by the row's integer id columns (node; element and
integration point; slave node; slave element, face and row index). Blocks present in both files
at the same time are compared; every step end the reference printed must be there in abut's file.

The error of a quantity in a block is  max |abut - ref| / max |ref|  over the block's rows (the
denominator for each quantity is given with the tolerances below); the table shows the worst
block of each quantity.

fricloop, changefric and changesurfbeh have no .dat output in the package (only .frd): for them
a copy of the deck gets *NODE PRINT of U and RF for all nodes at each step end and is run by both
codes; the reference is then the `ccx` run made here (no reference, and no failure, without ccx).
So is it for punch1, hueeber2 and hueeber4, whose package .dat comes from one increment: both
codes run them with smaller increments (MAX_INCREMENT).

Decks are REQUIRED (must pass), KNOWN (run and reported, difference documented, does not fail
the test) or SKIP (run if abut accepts them, never fail).

Usage: test_ccx_conformance.py [--table] [deck ...]
  --table   print the markdown table only (docs/verification.md)
Environment: ABUT_EXE (set by ctest); without it the abut of ABUT_BUILD_DIR or of ./build.
"""
import argparse
import gzip
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

EXAMPLES = Path("/usr/share/doc/calculix-ccx-test/examples/test")

REQUIRED, KNOWN, SKIP = "REQUIRED", "KNOWN", "SKIP"

# Status of each deck, with a one-line reason for those that are not REQUIRED.
DECKS = {
    # Two cubes, face-to-face linear contact, uniform pressure: every quantity to print precision.
    "contactenergy": (REQUIRED, ""),
    # Node-to-surface with friction: press, slide +1, slide -1, *CHANGE FRICTION mu 0.2 -> 0.1.
    "friction2": (REQUIRED, ""),
    # Face-to-face with friction, loop of imposed tangential displacements (reference: ccx run).
    "fricloop": (REQUIRED, ""),
    # Face-to-face with friction, *CHANGE FRICTION mu 1e-4 -> 0.2 (reference: ccx run).
    "changefric": (REQUIRED, ""),
    # Node-based slave surface (one node), initial overlap 0.02 that CalculiX adjusts away.
    "contact3": (REQUIRED, ""),
    # As contact3 with overlap 1e-4 and K = 1e9: the overlap is a real penetration here.
    "contact6": (REQUIRED, ""),
    # Node-based slave surface (one node), exponential pressure-overclosure law.
    "contact1": (REQUIRED, ""),
    # Spring-like cube stack, node-to-surface linear contact, NLGEOM.
    "cubespring": (REQUIRED, ""),
    # 4x4 block on a plate, node-to-surface with friction, sticking.
    "friction1": (REQUIRED, ""),
    # Hueeber's 2D-in-3D Hertz-like benchmark, face-to-face, 17524 nodes.
    "hueeber1": (REQUIRED, ""),
    "hueeber3": (REQUIRED, ""),
    # The same two blocks loaded on the other one, the surfaces' roles swapped (Sslav2 on Smast2;
    # 70 slave facets on 60). Against the package's one increment U differs by 4.4e-4 (hueeber2)
    # and 1.7e-4 (hueeber4) of the largest displacement, most at the contact's free end (x = 0),
    # whatever the penalty or the cells (K = 1e16: 3.8e-4, 3 x 3 cells per facet: 3.9e-4, with
    # one pressure per cell; node to surface agreed to 7e-7): CalculiX keeps each face-to-face
    # point's place on the master and the master's normal from the start of the increment
    # (punch1 below). Both codes with increments of at most 0.1 of the step: 4.9e-5 and 3.4e-5.
    "hueeber2": (REQUIRED, ""),
    "hueeber4": (REQUIRED, ""),
    # Two C3D20 cubes, face-to-face on their quad8 faces (issue 30): abut's curved faces are
    # 4 x 4 facets that integrate the face's own shape functions (docs/contact.md, "Curved
    # faces"), and each cell's normal law is integrated point by point (mortar.hpp, CellSample):
    # U 9.8e-6. With the cell's mean gap it was 5.0e-4, falling as the cells' size squared
    # (1.1e-4 with cells half as wide, whether by more facets or more cells per facet).
    "contact4": (REQUIRED, ""),
    # A C3D20 punch pressed into a C3D20 cube, face to face, ADJUST=0.005, NLGEOM, in one
    # increment in the package's run. CalculiX makes its face-to-face contact elements at the
    # start of an increment and keeps each point's place on the master face and the master's
    # normal through the increment (springforc_f2f.f: pmastsurf): in one increment the forces
    # stay along the undeformed cube's normal, while abut's follow the dimple the punch presses
    # into the cube. Against the package's .dat U 4.0e-3 (the punch's bottom nodes move sideways
    # 2.5e-6 less than in CalculiX, on every node; finer facets made it 5.4e-3); against ccx runs
    # with increments of at most 0.1 / 0.02 of the step 3.6e-4 / 2.3e-5 (MAX_INCREMENT).
    "punch1": (REQUIRED, ""),
    # A C3D20R beam between two C3D8 plates, two face-to-face pairs, NLGEOM (reference: a ccx
    # run): U 4.1e-3 and RF 1.2e-2. Not the faces' discretisation (16 x 16 facets of 3 x 3 cells:
    # 4.7e-3, 8.6e-3), not CalculiX's increments (at most 0.02 of the step: 4.7e-3, 1.1e-2), not
    # the element (C3D20 in both codes: 3.4e-3). The beam pivots on one plate's lower edge, and
    # the codes resist the edge differently: from the nodes' displacements and the faces' shape
    # functions, the beam sinks into that edge by 1.21e-3 in CalculiX and 0.95e-3 in abut; with
    # K x 100 by 0.79e-3 in CalculiX and 0.071e-3 in abut, the penalty's 1/K: CalculiX's points
    # on the beam's faces leave a strip along the plate's edge unresisted, abut's samples of the
    # overlaps reach the edge. The deck's mesh divided 3 times (plate edge again mid-element):
    # U 7.0e-4, RF 1.0e-3, penetrations 0.87e-3 / 0.93e-3 (docs/verification.md).
    "beamcontact": (KNOWN, "U 4.1e-3, RF 1.2e-2: a plate edge into the beam; ccx's points leave a strip at the edge unresisted"),
    # Two cubes tied face to face (PRESSURE-OVERCLOSURE=TIED, stick slope 1e7), the top one
    # sheared by 0.01; the slave face of C3D10 (cubef2f1) or C3D20 (cubef2f2) on a C3D20 master
    # (reference: a ccx run, the package has no .dat). Both decks hold a node that no element uses,
    # which abut's static solver made singular until such nodes got no equations (as in ccx).
    # Tied points lie on the true faces and act through the faces' shape functions: U 8.3e-6 /
    # 1.3e-5, RF 4.2e-5 / 4.1e-5 (through the facets' corners they were 1.1e-4 / 1.4e-4, 4.5e-4).
    "cubef2f1": (REQUIRED, ""),
    "cubef2f2": (REQUIRED, ""),
    # Tied contact changed to linear in step 2.
    # Tied pair pulled apart in step 1, changed to LINEAR (it lets go) in step 2 (reference: ccx run).
    "changesurfbeh": (REQUIRED, ""),
}

# Decks whose package reference has no .dat output: both codes run a copy with these prints.
INJECTED_PRINT = "*NODE PRINT,NSET=Nall,FREQUENCY=10000\nU,RF\n"
# Decks without a set of all nodes: the sets they print instead.
INJECTED_PRINTS = {
    deck: "*NODE PRINT,NSET=Ntop,FREQUENCY=10000\nU,RF\n*NODE PRINT,NSET=Nbottom,FREQUENCY=10000\nRF\n"
    for deck in ("cubef2f1", "cubef2f2")
}

# ---------------------------------------------------------------------------------------------
# Tolerances, per quantity: (tolerance, why). Errors are max |abut - ref| / max |ref| per block.
#
# The contact laws differ in documented ways:
# - CalculiX's node-to-surface LINEAR law is p = K d (1/2 + atan(d/eps)/pi) with eps = pi s/K
#   (s = sigma_inf, the tension at large clearance): above a few eps it is p = K d - s, so its
#   penetration is larger than abut's p = K d by s/K. Measured: friction2 CDIS normal 1.0295e-5
#   vs 1.0000e-5 (s/K = 3e-7), friction1 2.2 % (s/K = 3e-7 at p/K = 1.36e-5), cubespring top
#   displacement 3.0e-6 lower (s/K = 3e-6), contact3/contact6 slave nodes 3e-7 / 3e-9 higher.
# - CalculiX's face-to-face contact integrates over the clipped slave/master polygons (28 points
#   in contactenergy), abut per integration cell of the slave facet (4, each integrated over its
#   overlaps point by point): per-point rows differ in number and place, so only totals compare.
# - CalculiX builds its face-to-face contact elements at the start of an increment and keeps
#   them through its iterations: when a slave slides, the master-side forces follow the slave's
#   position at the start of the increment (see fricloop below).
# ---------------------------------------------------------------------------------------------
TOL = {
    # Displacements: set by elasticity; the penalty offset s/K is below 1e-4 of the block's
    # largest displacement in every deck but cubespring (contact6: 3e-9 / 8.6e-5 = 3.5e-5;
    # contact3: 3e-7 / 0.02; face-to-face decks have no offset at all).
    "U": (1e-4, "elastic motion; the penalty offset s/K is < 1e-4 of the largest displacement"),
    # Reaction/nodal forces: equilibrium with the applied loads, not the contact law.
    "RF": (1e-4, "equilibrium with the applied loads, independent of the contact law"),
    # Stresses of a block pressed on a plane: the load through equilibrium.
    "S": (1e-4, "load path through equilibrium, independent of the contact law"),
    "E": (1e-4, "strain = stress / material, as S"),
    # Element and total internal energies: F u / 2, u the elastic compression.
    "ELSE": (1e-4, "elastic energy of the bodies, as S"),
    # Contact spring energy: the integral of p^2 / 2K over the contact area; the same law
    # (p = K d) in both codes for face-to-face contact, but different quadratures (clipped
    # polygons vs Gauss points of the slave facet) once the pressure is not uniform.
    "CELS": (1e-3, "p^2/2K over the area; quadratures differ (clipped polygons vs Gauss points)"),
    # Pressure at the slave nodes: equilibrium with the load; its split among the nodes of a
    # flexible block depends weakly on the penetration field, and so on the s/K offset.
    "CSTR press": (1e-3, "equilibrium with the load; the node-to-node split depends weakly on the law"),
    # Tangential traction magnitude sqrt(t1^2 + t2^2) (the codes print t1, t2 in different
    # local bases), relative to the block's largest contact stress: mu p when slipping; when
    # sticking the traction of a stiff tangential penalty, set by equilibrium too.
    "CSTR tang": (1e-3, "mu p when slipping, equilibrium when sticking; magnitude only"),
    # Normal contact displacement = the penetration, p/K in abut, (p + s)/K in CalculiX: the
    # relative difference is s/p, 3 % in friction2 (s = 3, p = 100), 2.2 % in friction1.
    "CDIS normal": (5e-2, "penetration: (p + s)/K in CalculiX vs p/K in abut, s/p <= 3 %"),
    # Relative tangential displacement: the imposed slip (1.0 in friction2) or the elastic shear
    # of a sticking node; magnitude only (bases differ).
    "CDIS tang": (1e-3, "imposed slip or elastic shear at a sticking node; magnitude only"),
}

# Per-deck tolerances where the contact law or the reference's discretization shows: (tol, why).
DECK_TOL = {
    # Penetration p/K = 100/1e6 = 1e-4 is 11 % of the top's displacement 8.7e-4, and CalculiX's
    # is larger by s/K = 3/1e6 = 3e-6: 3.4e-3 of the block's largest value, as measured.
    ("cubespring", "U"): (1e-2, "penetration is 11 % of the motion; CalculiX's is larger by s/K = 3e-6 (3.4e-3)"),
    # The top face of the master block has its z tied by *EQUATION: the printed RF there is how
    # the normal force 4 spreads over the master nodes. CalculiX's face-to-face contact elements
    # are made at the start of each increment, so the force sits where the slave was one
    # increment earlier; with ccx's own increments (last ones sliding 0.024 and 0.048) that is
    # +-0.097 on the corner nodes (8 %); both codes run with increments of at most 1/100 of the
    # step here (MAX_INCREMENT below): the lag is then 0.001 to 0.002, i.e. 1.7e-3 to 3.3e-3.
    ("fricloop", "RF"): (5e-3, "ccx's master-side forces lag one increment (0.002 of slide): 3.3e-3"),
    # *STATIC,DIRECT 0.01 in step 2: the same one-increment lag of ccx (slide 0.001) at t = 2;
    # at the end of the later steps, with the slave at rest, the codes agree to 3e-6.
    ("changefric", "RF"): (5e-3, "ccx's master-side forces lag one increment (0.001 of slide): 1.7e-3"),
    # Step 1 pulls the small cube off the large one through a TIED pair: the tie's normal penalty
    # (1e9 over the 0.04 face) is about 1e3 times the small cube's axial stiffness, so the tie
    # holds ~1e-3 of the compliance, and there the codes differ (clipped polygons against 2 x 2
    # Gauss points of the slave face, NLGEOM): 1.1e-3 in the pulling force, 5.5e-4 in U.
    ("changesurfbeh", "U"): (1e-3, "tie compliance ~1e-3 of the pull, integrated differently: 5.5e-4"),
    ("changesurfbeh", "RF"): (2e-3, "tie compliance ~1e-3 of the pull, integrated differently: 1.1e-3"),
}

# Largest increment, as a fraction of each step's period, imposed on both codes; such a deck's
# reference is a ccx run with these increments, also where the package has a .dat (fricloop: see
# DECK_TOL; punch1, hueeber2, hueeber4: see DECKS).
MAX_INCREMENT = {"fricloop": 0.01, "punch1": 0.02, "hueeber2": 0.1, "hueeber4": 0.1}

# ---------------------------------------------------------------------------------------------


def find_abut():
    exe = os.environ.get("ABUT_EXE")
    if exe:
        return exe
    build = os.environ.get("ABUT_BUILD_DIR") or str(Path(__file__).resolve().parents[2] / "build")
    return str(Path(build) / "apps" / "abut" / "abut")


def read_maybe_gz(path):
    """Text of path or of path.gz, or None when neither exists."""
    if path.is_file():
        return path.read_text(errors="replace")
    gz = Path(str(path) + ".gz")
    if gz.is_file():
        with gzip.open(gz, "rt", errors="replace") as f:
            return f.read()
    return None


# ---- .dat parsing ----------------------------------------------------------------------------

HEADER = re.compile(r"^\s*(?P<title>\S.*?)\s*(?:\band|\bfor)?\s+time\s+(?P<t>[-+]?[\d.]+(?:[EeDd][-+]?\d+)?)\s*$")
INT = re.compile(r"^[-+]?\d+$")


def to_float(tok):
    tok = tok.replace("D", "E").replace("d", "E")
    # Fortran drops the E of a three-digit exponent: 0.123456-100
    m = re.match(r"^([-+]?\d*\.\d*)([-+]\d{3})$", tok)
    if m:
        tok = m.group(1) + "E" + m.group(2)
    return float(tok)


def norm_title(title):
    return re.sub(r"\s+", "", title).lower()


def time_key(t):
    return round(t, 6)


def parse_dat(text):
    """{(normalized title, time key): {'title', 'time', 'rows': [(ids, values)]}}"""
    blocks = {}
    current = None
    for line in text.splitlines():
        if not line.strip():
            continue
        m = HEADER.match(line)
        if m and re.search(r"[a-zA-Z]{3}", m.group("title")):
            title = " ".join(m.group("title").split())
            t = to_float(m.group("t"))
            key = (norm_title(title), time_key(t))
            # A second block with the same header and time (abut prints one block per contact
            # pair, CalculiX one for all) continues the first.
            current = blocks.setdefault(key, {"title": title, "time": t, "rows": []})
            continue
        if current is None:
            continue
        toks = line.split()
        ids = []
        while toks and INT.match(toks[0]):
            ids.append(int(toks.pop(0)))
        try:
            values = [to_float(v) for v in toks]
        except ValueError:
            continue
        current["rows"].append((tuple(ids), values))
    return blocks


# ---- what a block is and how it is compared --------------------------------------------------


def classify(title):
    """(kind, [(quantity, extractor)]) for a block title; extractor(values) -> float or None."""
    t = title.lower()
    first = lambda v: v[0]
    tang = lambda v: math.hypot(v[1], v[2])
    allcols = None  # every value column
    if t.startswith("total contact spring energy"):
        return "total", [("CELS", first)]
    if t.startswith("total internal energy"):
        return "total", [("ELSE", first)]
    s2s = "slave element+face" in t
    if t.startswith("contact stress"):
        return ("s2s" if s2s else "contact"), [("CSTR press", first), ("CSTR tang", tang)]
    if t.startswith("relative contact displacement"):
        return ("s2s" if s2s else "contact"), [("CDIS normal", first), ("CDIS tang", tang)]
    if t.startswith("contact print energy"):
        return ("s2s" if s2s else "contact"), [("CELS", first)]
    if t.startswith("displacements"):
        return "plain", [("U", allcols)]
    if t.startswith("forces"):
        return "plain", [("RF", allcols)]
    if t.startswith("stresses"):
        return "plain", [("S", allcols)]
    if t.startswith("strains"):
        return "plain", [("E", allcols)]
    if t.startswith("internal energy density"):
        return "plain", [("ENER", allcols)]
    if t.startswith("internal energy"):
        return "plain", [("ELSE", allcols)]
    return "plain", [(title.split("(")[0].strip(), allcols)]


def keyed(rows, s2s):
    """Rows by id; surface-to-surface rows repeat element+face, so they get a row index too."""
    out, seen = {}, {}
    for ids, values in rows:
        if s2s:
            n = seen.get(ids, 0)
            seen[ids] = n + 1
            ids = ids + (n,)
        out[ids] = values
    return out


def compare_block(ref, got, floor=0.0):
    """[(quantity, error, scale, note)] for one pair of blocks of the same title and time.
    `floor`: the smallest denominator (see deck_scales)."""
    kind, quantities = classify(ref["title"])
    results = []
    if kind == "s2s":
        # Integration points differ (CalculiX: clipped slave/master polygons; abut: Gauss points
        # of the slave facet), so do the row counts: only the totals compare.
        nr, na = len(ref["rows"]), len(got["rows"])
        for q, _ in quantities:
            if q == "CELS":
                r = sum(v[0] for _, v in ref["rows"])
                a = sum(v[0] for _, v in got["rows"])
                scale = abs(r) or 1.0
                results.append((q, abs(a - r) / scale, abs(r), f"sum of rows ({nr} ccx, {na} abut)"))
            else:
                results.append((q, None, None, f"face-to-face rows ({nr} ccx, {na} abut) not comparable"))
        return results
    r_rows = keyed(ref["rows"], False)
    a_rows = keyed(got["rows"], False)
    note = ""
    if kind == "contact":
        # A node out of contact prints no row: it is a zero row in the other code's block.
        keys = sorted(set(r_rows) | set(a_rows))
        only_r = len(set(r_rows) - set(a_rows))
        only_a = len(set(a_rows) - set(r_rows))
        if only_r or only_a:
            note = f"{only_r} contact rows only in ccx, {only_a} only in abut (zero in the other)"
    else:
        keys = sorted(r_rows)
        missing = [k for k in keys if k not in a_rows]
        if missing:
            note = f"{len(missing)} rows missing in abut (e.g. {missing[0]})"
    width = max((len(v) for v in r_rows.values()), default=0)
    zero = [0.0] * max(width, 3)

    for q, ex in quantities:
        pairs = []  # (ref, abut, where)
        for k in keys:
            r = r_rows.get(k, zero)
            a = a_rows.get(k)
            if a is None:
                if kind != "contact":
                    continue
                a = zero
            if ex is None:
                pairs.extend((rv, av, (k, c + 1)) for c, (rv, av) in enumerate(zip(r, a)))
            else:
                pairs.append((ex(r), ex(a), (k, None)))
        if not pairs:
            results.append((q, math.inf if note else None, None, note or "empty"))
            continue
        scale = max([abs(r) for r, _, _ in pairs] + [floor])
        if q == "CSTR tang":
            # Relative to the block's largest contact stress (pressure included).
            scale = max([scale] + [abs(r_rows.get(k, zero)[0]) for k in keys])
        r, a, (k, c) = max(pairs, key=lambda p: abs(p[1] - p[0]))
        err = abs(a - r)
        where = "row " + " ".join(map(str, k)) + (f" column {c}" if c else "")
        detail = f"worst: {where}: ccx {r:.6e}, abut {a:.6e}"
        if scale == 0.0:
            rel = 0.0 if err == 0.0 else math.inf
        else:
            rel = err / scale
        if note and kind != "contact":
            rel = math.inf
        results.append((q, rel, scale, "; ".join(x for x in (note, detail) if x)))
    return results


# ---- decks ----------------------------------------------------------------------------------


def deck_scales(blocks):
    """Per block, the floor of its error denominator: 0, except for a block whose values all
    vanish (below 1e-6 of the largest |value| its title takes over the whole reference), which
    is measured against that largest value. Such a block (changesurfbeh, step 2: the released
    cube carries no force) would otherwise compare two codes' round-off and Newton residuals
    with each other."""
    largest, block_max = {}, {}
    for key, b in blocks.items():
        m = max((abs(v) for _, vals in b["rows"] for v in vals), default=0.0)
        block_max[key] = m
        largest[key[0]] = max(largest.get(key[0], 0.0), m)
    return {key: (largest[key[0]] if m < 1e-6 * largest[key[0]] else 0.0)
            for key, m in block_max.items()}


def step_end_times(deck_text):
    """Total times at the end of each step: the *STATIC time periods (default 1) summed."""
    ends, total = [], 0.0
    lines = [l for l in deck_text.splitlines() if not l.startswith("**")]
    for i, line in enumerate(lines):
        if re.match(r"^\*\s*STATIC\b", line, re.I):
            period = 1.0
            if i + 1 < len(lines) and not lines[i + 1].lstrip().startswith("*"):
                fields = [f.strip() for f in lines[i + 1].split(",")]
                if len(fields) > 1 and fields[1]:
                    period = to_float(fields[1])
            total += period
            ends.append(time_key(total))
    return ends


def inject_prints(deck_text, max_fraction=None, prints=INJECTED_PRINT):
    """The deck with *NODE PRINT of U, RF at each step end; optionally increments of at most
    max_fraction of each step's period (*STATIC: initial, period, minimum, maximum)."""
    out = re.sub(r"(?im)^\*\s*END\s+STEP", lambda m: prints + "*END STEP", deck_text)
    if max_fraction:
        def limit(m):
            f = [x.strip() for x in m.group(2).split(",")] + [""] * 4
            period = to_float(f[1]) if f[1] else 1.0
            dt = period * max_fraction
            initial = min(to_float(f[0]), dt) if f[0] else dt
            return f"{m.group(1)}{initial!r}, {period!r}, {f[2]}, {dt!r}\n"
        out = re.sub(r"(?im)^(\*\s*STATIC\b[^\n]*\n)([^*\n][^\n]*)\n", limit, out)
        # A *STATIC without a data line: CalculiX's period and first increment are 1.
        dt = max_fraction
        out = re.sub(r"(?im)^(\*\s*STATIC\b[^\n]*\n)(?=\*)",
                     lambda m: f"{m.group(1)}{dt!r}, 1.0, , {dt!r}\n", out)
    return out


def single_thread_env():
    env = dict(os.environ)
    for k in ["OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
              "CCX_NPROC_STIFFNESS", "CCX_NPROC_EQUATION_SOLVER", "CCX_NPROC_RESULTS",
              "NUMBER_OF_PROCESSORS"]:
        env[k] = "1"
    return env


def run_abut(abut, deck_path, outdir):
    t0 = time.monotonic()
    try:
        p = subprocess.run([abut, "run", str(deck_path), "-o", str(outdir), "-q"],
                           capture_output=True, text=True, timeout=300, env=single_thread_env())
        rc, err = p.returncode, (p.stderr or "").strip()
    except subprocess.TimeoutExpired:
        rc, err = -1, "timed out after 300 s"
    wall = time.monotonic() - t0
    summary = {}
    try:
        summary = json.loads((outdir / "summary.json").read_text())
    except (OSError, ValueError):
        pass
    dat = outdir / "results.dat"
    return {"rc": rc, "stderr": err, "wall": wall, "summary": summary,
            "dat": dat.read_text() if dat.is_file() else ""}


def run_ccx(ccx, deck_text, workdir, name):
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / f"{name}.inp").write_text(deck_text)
    t0 = time.monotonic()
    try:
        p = subprocess.run([ccx, "-i", name], cwd=workdir, capture_output=True, text=True,
                           timeout=300, env=single_thread_env())
        rc = p.returncode
    except subprocess.TimeoutExpired:
        rc = -1
    wall = time.monotonic() - t0
    dat = workdir / f"{name}.dat"
    ok = rc == 0 and dat.is_file()
    return {"ok": ok, "wall": wall, "dat": dat.read_text() if ok else ""}


def abut_problem(run):
    """Why abut's run is not a complete one, or ''."""
    s = run["summary"]
    if run["rc"] != 0 or s.get("status") not in (None, "completed"):
        lines = run["stderr"].splitlines()
        errors = [l for l in lines if l.startswith("error")]
        msg = s.get("message") or (errors or lines[-1:] or ["exit code %d" % run["rc"]])[0]
        return f"abut stops ({s.get('status', 'rc=%d' % run['rc'])}): {msg}"
    return ""


def check_deck(name, abut, ccx, tmp):
    """{'rows': [...], 'notes': [...], 'abut_wall', 'ccx_wall', 'ok'}"""
    status, reason = DECKS[name]
    res = {"name": name, "status": status, "reason": reason, "rows": [], "notes": [],
           "abut_wall": None, "ccx_wall": None, "source": None}
    deck_text = read_maybe_gz(EXAMPLES / f"{name}.inp")
    if deck_text is None:
        res["notes"].append("deck not installed (calculix-ccx-test)")
        res["missing"] = True
        return res
    ref_text = read_maybe_gz(EXAMPLES / f"{name}.dat.ref")
    packaged = bool(ref_text and ref_text.strip())
    # A deck with a largest increment is compared with a ccx run of it: the package's .dat, if
    # any, was made with larger increments (see MAX_INCREMENT).
    injected = not packaged or name in MAX_INCREMENT
    if injected:
        prints = "" if packaged else INJECTED_PRINTS.get(name, INJECTED_PRINT)
        deck_text = inject_prints(deck_text, MAX_INCREMENT.get(name), prints)
        ref_text = None
    work = tmp / name
    (work / "abut").mkdir(parents=True)
    deck_path = work / "abut" / f"{name}.inp"
    deck_path.write_text(deck_text)

    run = run_abut(abut, deck_path, work / "abut" / "out")
    res["abut_wall"] = run["wall"]
    res["summary"] = run["summary"]
    if ccx:
        c = run_ccx(ccx, deck_text, work / "ccx", name)
        res["ccx_wall"] = c["wall"] if c["ok"] else None
        if injected and c["ok"]:
            ref_text = c["dat"]
            res["source"] = "ccx run" + (f" (increments <= {MAX_INCREMENT[name]:g} of step)"
                                         if name in MAX_INCREMENT else "")
        elif not c["ok"]:
            res["notes"].append("ccx run failed")
    if not injected:
        res["source"] = "dat.ref"

    problem = abut_problem(run)
    if problem:
        res["notes"].append(problem)
        if status == SKIP:
            return res
    if not ref_text or not ref_text.strip():
        res["notes"].append("no reference (no .dat in the package and no ccx to run)")
        res["noref"] = True
        return res

    ref = parse_dat(ref_text)
    got = parse_dat(run["dat"])
    ends = set(step_end_times(deck_text))
    floors = deck_scales(ref)
    worst = {}  # quantity -> [err, scale, note, t]
    for key, rblock in sorted(ref.items(), key=lambda kv: kv[0][1]):
        gblock = got.get(key)
        if gblock is None:
            if key[1] in ends:
                q = classify(rblock["title"])[1][0][0]
                w = worst.setdefault(q, [None, None, "", None])
                w[0], w[2], w[3] = math.inf, f"no block at step end t={key[1]:g}", key[1]
            continue
        for q, err, scale, note in compare_block(rblock, gblock, floors.get(key, 0.0)):
            w = worst.setdefault(q, [None, None, "", None])
            if scale is not None:
                w[1] = max(w[1] or 0.0, scale)
            if err is not None and (w[0] is None or err > w[0]):
                w[0], w[3] = err, key[1]
                if note:
                    w[2] = note
            elif note and not w[2]:
                w[2] = note
    for q, (err, scale, note, t) in worst.items():
        tol, _ = DECK_TOL.get((name, q), TOL.get(q, (1e-4, "")))
        ok = err is None or err <= tol
        if problem:
            ok = False
        res["rows"].append({"q": q, "err": err, "scale": scale, "tol": tol, "ok": ok,
                            "note": note, "t": t})
    if not worst:
        res["notes"].append("no block in common")
    return res


def deck_ok(res):
    if res.get("missing") or res.get("noref"):
        return True
    if any(n.startswith("abut stops") for n in res["notes"]) or not res["rows"]:
        return False
    return all(r["ok"] for r in res["rows"])


def fmt_err(e):
    if e is None:
        return "n/a"
    if math.isinf(e):
        return "missing"
    return f"{e:.1e}"


def fmt_s(s):
    return "" if s is None else f"{s:.2f}"


def failing_verdict(res):
    if res["status"] == REQUIRED:
        return "**NO**"
    return f"{res['status'].lower()}: {res['reason']}"


def table(results, have_ccx):
    head = ["deck", "quantity", "reference", "worst error", "tolerance", "pass", "abut wall s"]
    if have_ccx:
        head.append("ccx wall s")
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for res in results:
        name = res["name"]
        label = name if res["status"] == REQUIRED else f"{name} ({res['status']})"
        timing = [fmt_s(res["abut_wall"])] + ([fmt_s(res["ccx_wall"])] if have_ccx else [])
        if not res["rows"]:
            if res.get("noref"):
                verdict = "no reference"
            elif deck_ok(res):
                verdict = "yes"
            else:
                verdict = failing_verdict(res)
                problem = next((n for n in res["notes"] if n.startswith("abut stops")), "")
                if problem and res["status"] == REQUIRED:
                    verdict += " " + problem.split(": ", 1)[0]
            cells = [label, "—", res["source"] or "—", "—", "—", verdict]
            lines.append("| " + " | ".join(cells + timing) + " |")
            continue
        for i, r in enumerate(res["rows"]):
            ref = f"{res['source']}, max {r['scale']:.3g}" if r["scale"] else res["source"]
            verdict = "yes" if r["ok"] else failing_verdict(res)
            cells = [label if i == 0 else "", r["q"], ref, fmt_err(r["err"]), f"{r['tol']:.0e}", verdict]
            cells += timing if i == 0 else [""] * len(timing)
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--table", action="store_true", help="print the markdown table only")
    ap.add_argument("decks", nargs="*", help="decks to run (default: all)")
    args = ap.parse_args()
    say = (lambda *a: None) if args.table else print

    if not EXAMPLES.is_dir():
        print(f"skipped: {EXAMPLES} not installed (Debian package calculix-ccx-test)")
        return 0
    abut = find_abut()
    if not Path(abut).is_file():
        print(f"FAIL  abut not found at {abut}")
        return 1
    ccx = shutil.which("ccx")
    names = args.decks or list(DECKS)
    results = []
    with tempfile.TemporaryDirectory(prefix="abut_ccx_") as tmp:
        for name in names:
            if name not in DECKS:
                print(f"unknown deck {name}")
                return 2
            res = check_deck(name, abut, ccx, Path(tmp))
            results.append(res)
            if res.get("missing"):
                say(f"skip  {name}: deck not installed")
                continue
            if res.get("noref"):
                verdict = "noref"
            elif deck_ok(res):
                verdict = "ok   "
            else:
                verdict = {REQUIRED: "FAIL ", KNOWN: "known", SKIP: "skip "}[res["status"]]
            summary = res.get("summary", {})
            runs = (f" ({summary.get('increments')} increments, {summary.get('iterations')} iterations)"
                    if summary.get("increments") is not None else "")
            say(f"{verdict} {name} [{res['status']}] abut {fmt_s(res['abut_wall'])} s{runs}"
                + (f", ccx {fmt_s(res['ccx_wall'])} s" if res["ccx_wall"] is not None else ""))
            for n in res["notes"]:
                say(f"        {n}")
            for r in res["rows"]:
                say(f"        {r['q']:<12} error {fmt_err(r['err']):>8} (tol {r['tol']:.0e})"
                    + (f" worst at t={r['t']:g}" if r["t"] is not None else "")
                    + (f"  [{r['note']}]" if r["note"] else ""))
            if res["status"] != REQUIRED and res["reason"]:
                say(f"        {res['status']}: {res['reason']}")

    results = [r for r in results if not r.get("missing")]
    if not args.table:
        print()
    print(table(results, ccx is not None))
    failed = [r["name"] for r in results if r["status"] == REQUIRED and not deck_ok(r)]
    fixed = [r["name"] for r in results if r["status"] == KNOWN and deck_ok(r)]
    if not args.table:
        print()
        print("Errors: max |abut - ref| / max |ref| per block, worst block shown; reference "
              "dat.ref = CalculiX's package result, ccx run = ccx on the deck with *NODE PRINT added.")
        print("Tolerances (per quantity; per deck where noted):")
        for q, (tol, why) in TOL.items():
            print(f"  {q:<12} {tol:.0e}  {why}")
        for (deck, q), (tol, why) in DECK_TOL.items():
            print(f"  {deck} {q}: {tol:.0e}  {why}")
        for r in results:
            if r["status"] != REQUIRED:
                print(f"{r['name']}: {r['status']}: {r['reason']}")
        if fixed:
            print("KNOWN decks that pass now (flip them to REQUIRED): " + ", ".join(fixed))
        print("FAIL: " + ", ".join(failed) if failed else "all REQUIRED decks pass")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
