#!/usr/bin/python3
"""Writes examples/punch.inp: a steel punch pressed into a soft elastic block.

    python3 tools/make_punch_inp.py [-o examples/punch.inp]

Standard library only. The deck is a quarter model (symmetry planes x = 0 and y = 0) of a flat
cylindrical punch with a 45 degree chamfer on its edge, driven 1 mm down into a block by a
prescribed displacement of its top face, with face-to-face (SURFACE TO SURFACE) penalty contact
and Coulomb friction, NLGEOM. Units: SI (m, N, Pa).

Mesh: both bodies share one plan-view mesh, an O-grid: a square core, circles around it graded
towards the punch edge (r = a), and rings beyond that turn into the square outline of the block;
layers graded towards the contact plane (z = 0). The punch uses the part inside r = a; its
chamfer lifts the bottom nodes near the edge, blended out over the lowest layers. The sizes are
chosen for about 20 s on one core (18 s measured): friction that slips makes the tangent unsymmetric, and the
LU factorisations are almost all of abut's time.
"""
import argparse
import math
import textwrap
from pathlib import Path

# Geometry [m]
A = 5.0e-3         # punch radius
CHAMFER = 0.5e-3   # 45 degree chamfer on the punch's bottom edge
H_PUNCH = 5.0e-3   # punch height
L = 15.0e-3        # block half-width (the quarter model is L x L)
H_BLOCK = 10.0e-3  # block height
DEPTH = 1.0e-3     # prescribed punch travel

# Materials and contact
E_PUNCH, NU_PUNCH = 210.0e9, 0.3  # steel
E_BLOCK, NU_BLOCK = 100.0e6, 0.3  # soft, polymer-like block, linear elastic
PENALTY = 1.0e13                  # pressure per overclosure [Pa/m]: 25 E_block / H_MIN
STICK_SLOPE = 1.0e12              # tangential stick slope [Pa/m]: PENALTY / 10 (CalculiX's advice)
MU = 0.2

# Mesh: sized for about 30 s on one core (the LU factorisations dominate)
N = 6              # cells per 45 degrees (and per side of the square core)
CORE = 0.4 * A     # half-size of the square core
R0 = 0.7 * A       # first full circle
CORE_RINGS = 1     # rings from the core's square outline to that circle
H_MIN = 0.25e-3    # radial and vertical cell size at the punch edge and the contact plane
CHAMFER_CELLS = 2  # radial cells across the chamfer
FINE_OUT = 2       # cells of H_MIN outside r = a
GROWTH = 1.4       # cell size ratio away from the fine zone, in the block
PUNCH_GROWTH = 1.8  # layer height ratio up the punch (steel: hardly strained)
R1 = 1.6 * A       # last full circle; beyond it the rings turn into the block's square outline
SLAVE_R = A + 1.5e-3  # block top faces within this radius form the slave surface

# Measured with the deck this script writes (see the header it puts in the deck).
COMPARISON = """\
** Punch force, the sum of RF_z over NPUNCHTOP (quarter model; x 4 for the whole punch):
**   punch travel [mm]    0.25     0.50     0.75     1.00
**   abut [N]            84.66   157.96   224.91   283.73
**   ccx 2.20 [N]        84.67   157.81   224.83   283.74    (abut -0.004 % at 1 mm)
** Newton iterations per increment: abut 6 4 7 5 (22), ccx 3 5 6 5 (19). One core, otherwise
** idle machine: abut 11 s (10.6 s of it in LU factorisations: friction that slips and the
** chamfer's sloped contact make the tangent unsymmetric), ccx 8.4 s. Whole punch 4 x 284 N =
** 1.14 kN; Boussinesq's rigid flat punch on an elastic half-space gives
** 2 a E delta / (1 - nu^2) = 1.10 kN.
** CalculiX integrates over the slave faces clipped by the master faces, abut per integration
** cell of the slave faces (each cell over its overlaps, point by point): the totals agree, the
** *CONTACT PRINT rows do not match one to one."""


def header():
    """The deck's comment header: what the model is, its units, and the measured comparison."""
    def mm(v):
        return f"{v * 1e3:g}"

    def sci(v):
        mantissa, exponent = f"{v:e}".split("e")
        return f"{float(mantissa):g}e{int(exponent)}"

    paragraphs = [
        "abut example: a flat steel punch pressed into a soft elastic block. Static, NLGEOM, "
        "face-to-face (SURFACE TO SURFACE) penalty contact with Coulomb friction. Written by "
        "tools/make_punch_inp.py: edit that script, not this file.",
        "Units: SI -- m, N, Pa (the contact penalty and the stick slope in Pa/m); .inp has no "
        "unit keyword.",
        "Quarter model: symmetry planes x~=~0 (u_x~=~0) and y~=~0 (u_y~=~0). "
        f"Punch: steel cylinder, radius {mm(A)} mm, height {mm(H_PUNCH)} mm, with a "
        f"{mm(CHAMFER)} mm x 45 deg chamfer on its bottom edge; E~=~{E_PUNCH / 1e9:g}~GPa, "
        f"nu~=~{NU_PUNCH}. Block: {mm(2 * L)} x {mm(2 * L)} x {mm(H_BLOCK)} mm (whole model), "
        f"E~=~{E_BLOCK / 1e6:g}~MPa, nu~=~{NU_BLOCK}, soft (a polymer-like stiffness) so that "
        "the indentation shows; its bottom face on rollers (u_z~=~0). Both linear elastic (St "
        "Venant-Kirchhoff under NLGEOM, in abut and in CalculiX).",
        f"Contact: slave = the block's top faces within r~=~{mm(SLAVE_R)}~mm, master = the "
        f"punch's bottom and chamfer faces; LINEAR penalty {sci(PENALTY)} Pa/m, Coulomb "
        f"mu~=~{MU}, stick slope {sci(STICK_SLOPE)} Pa/m.",
        f"Load: the punch's top face moves {mm(DEPTH)} mm down (u_z prescribed, x and y free) "
        "in four increments of step time 0 .. 1 (pseudo-time; read as seconds it is a punch "
        "speed of 1 mm/s).",
        "Mesh: an O-grid in plan, graded towards the punch edge and towards the contact plane; "
        "C3D8 (full integration).",
    ]
    lines = []
    for text in paragraphs:
        # "~" keeps "nu = 0.3" and the like on one line
        lines.append(textwrap.fill(text, width=96, initial_indent="** ", subsequent_indent="** ",
                                   break_on_hyphens=False).replace("~", " "))
        lines.append("**")
    lines.append(COMPARISON)
    lines.append("**")
    lines.append("**   abut check examples/punch.inp")
    lines.append("**   abut run examples/punch.inp -o /tmp/punch --threads 1")
    lines.append("**   ccx -i punch        (CalculiX, in a directory holding a copy named "
                 "punch.inp)")
    return "\n".join(lines) + "\n"


def graded(x0, x1, h0, growth):
    """Points from x0 to x1 (either way): cells growing by `growth` from about h0, their number
    chosen so that they fit, then all scaled so that the last point is x1."""
    length = abs(x1 - x0)
    n = max(1, round(math.log(1.0 + length * (growth - 1.0) / h0) / math.log(growth)))
    cells = [h0 * growth ** k for k in range(n)]
    step = (x1 - x0) / sum(cells)
    points = [x0]
    for c in cells:
        points.append(points[-1] + c * step)
    points[-1] = x1
    return points


def ring_levels():
    """(radius, circle weight) of every ring from the core outline (0) to the block outline."""
    chamfer_rings = [A - CHAMFER * k / CHAMFER_CELLS for k in range(CHAMFER_CELLS + 1)]
    inward = graded(A - CHAMFER, R0, H_MIN * GROWTH, GROWTH)  # growing away from the chamfer
    circles_in = sorted(chamfer_rings + inward[1:])          # R0 ... a
    levels = [(CORE, 0.0)]
    levels += [(CORE + (circles_in[0] - CORE) * k / CORE_RINGS, k / CORE_RINGS)
               for k in range(1, CORE_RINGS)]
    levels += [(r, 1.0) for r in circles_in]
    outer = [A + k * H_MIN for k in range(1, FINE_OUT + 1)]
    outward = graded(outer[-1], L, H_MIN * GROWTH, GROWTH)
    for r in outer + outward[1:]:
        levels.append((r, 1.0 if r <= R1 else 1.0 - (r - R1) / (L - R1)))
    return levels


def ring_point(r, w, t):
    """Point t (0 .. 2N, from the x axis to the y axis) of a ring: w = 1 a circle of radius r,
    w = 0 the square outline of half-size r, in between a blend."""
    if t <= N:
        sx, sy = r, r * t / N
    else:
        sx, sy = r * (2 * N - t) / N, r
    phi = 0.5 * math.pi * t / (2 * N)
    return (w * r * math.cos(phi) + (1 - w) * sx, w * r * math.sin(phi) + (1 - w) * sy)


class PlanMesh:
    """The plan-view quad mesh up to ring `rings` (inclusive)."""

    def __init__(self, levels, rings):
        self.points = []
        self.index = {}
        for j in range(N + 1):
            for i in range(N + 1):
                self.index[("c", i, j)] = len(self.points)
                self.points.append((CORE * i / N, CORE * j / N))
        for q in range(1, rings + 1):
            r, w = levels[q]
            for t in range(2 * N + 1):
                self.index[("r", q, t)] = len(self.points)
                self.points.append(ring_point(r, w, t))
        self.cells = []  # (quad node indices counter-clockwise, ring of the outer edge)
        for j in range(N):
            for i in range(N):
                self.cells.append(([self.node_c(i, j), self.node_c(i + 1, j),
                                    self.node_c(i + 1, j + 1), self.node_c(i, j + 1)], 0))
        for q in range(rings):
            for t in range(2 * N):
                self.cells.append(([self.node_r(q, t), self.node_r(q + 1, t),
                                    self.node_r(q + 1, t + 1), self.node_r(q, t + 1)], q + 1))

    def node_c(self, i, j):
        return self.index[("c", i, j)]

    def node_r(self, q, t):
        if q == 0:
            return self.node_c(N, t) if t <= N else self.node_c(2 * N - t, N)
        return self.index[("r", q, t)]


def fmt(v):
    """A coordinate in metres to 0.01 um, without trailing zeros."""
    s = f"{v:.8f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def build():
    """The deck's text and its node, element, slave-face and master-face counts."""
    levels = ring_levels()
    q_edge = next(q for q, (r, w) in enumerate(levels) if w == 1.0 and abs(r - A) < 1e-12)
    block_plan = PlanMesh(levels, len(levels) - 1)
    punch_plan = PlanMesh(levels, q_edge)

    z_block = [-z for z in graded(0.0, H_BLOCK, H_MIN, GROWTH)][::-1]  # -H .. 0
    z_punch = graded(0.0, H_PUNCH, H_MIN, PUNCH_GROWTH)                # 0 .. H_PUNCH

    nodes = []  # (x, y, z)
    elements = []  # (part, [8 node ids])
    sets = {k: [] for k in ("NSYMX", "NSYMY", "NBOTTOM", "NPUNCHTOP")}
    eslave, emaster = [], []

    def add_body(plan, zs, lift):
        base = len(nodes)
        npl = len(plan.points)
        for k, z0 in enumerate(zs):
            for (x, y) in plan.points:
                dz = lift(math.hypot(x, y), z0)
                nodes.append((x, y, z0 + dz))
                nid = len(nodes)
                if abs(x) < 1e-12:
                    sets["NSYMX"].append(nid)
                if abs(y) < 1e-12:
                    sets["NSYMY"].append(nid)
        ids = []
        for k in range(len(zs) - 1):
            for quad, ring in plan.cells:
                bottom = [base + k * npl + p + 1 for p in quad]
                top = [base + (k + 1) * npl + p + 1 for p in quad]
                ids.append((k, ring, bottom + top))
        return base, npl, ids

    def flat(rho, z):
        return 0.0

    base_b, npl_b, block = add_body(block_plan, z_block, flat)
    sets["NBOTTOM"] = [base_b + p + 1 for p in range(npl_b)]
    top_layer_b = len(z_block) - 2

    def chamfer(rho, z):  # 45 degrees at the bottom, faded out over 3 chamfer heights
        return max(0.0, rho - (A - CHAMFER)) * max(0.0, 1.0 - z / (3.0 * CHAMFER))

    base_p, npl_p, punch = add_body(punch_plan, z_punch, chamfer)
    sets["NPUNCHTOP"] = [base_p + (len(z_punch) - 1) * npl_p + p + 1 for p in range(npl_p)]

    for k, ring, conn in block:
        elements.append(("EBLOCK", conn))
        if k == top_layer_b and levels[ring][0] <= SLAVE_R + 1e-12:
            eslave.append(len(elements))
    for k, ring, conn in punch:
        elements.append(("EPUNCH", conn))
        if k == 0:
            emaster.append(len(elements))

    out = [header()]
    out.append(f"*HEADING\nSteel punch pressed {DEPTH * 1e3:g} mm into a soft elastic block "
               "(quarter model, SI)\n")
    out.append("*NODE, NSET=NALL\n")
    out.extend(f"{i},{fmt(x)},{fmt(y)},{fmt(z)}\n" for i, (x, y, z) in enumerate(nodes, 1))
    for name in ("EBLOCK", "EPUNCH"):
        out.append(f"*ELEMENT, TYPE=C3D8, ELSET={name}\n")
        out.extend(f"{i},{','.join(map(str, conn))}\n"
                   for i, (part, conn) in enumerate(elements, 1) if part == name)

    def id_list(keyword, name, ids):
        out.append(f"{keyword}, {name}\n")
        for k in range(0, len(ids), 16):
            out.append(",".join(map(str, ids[k:k + 16])) + "\n")

    for name, ids in sets.items():
        id_list("*NSET", f"NSET={name}", ids)
    id_list("*ELSET", "ELSET=ESLAVE", eslave)
    id_list("*ELSET", "ELSET=EMASTER", emaster)
    out.append(f"""\
*SURFACE, NAME=SBLOCK
ESLAVE, S2
*SURFACE, NAME=SPUNCH
EMASTER, S1
*MATERIAL, NAME=STEEL
*ELASTIC
{E_PUNCH:.4g}, {NU_PUNCH}
*MATERIAL, NAME=SOFT
*ELASTIC
{E_BLOCK:.4g}, {NU_BLOCK}
*SOLID SECTION, ELSET=EPUNCH, MATERIAL=STEEL
*SOLID SECTION, ELSET=EBLOCK, MATERIAL=SOFT
*SURFACE INTERACTION, NAME=PUNCHCONTACT
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
{PENALTY:.4g}
*FRICTION
{MU}, {STICK_SLOPE:.4g}
*CONTACT PAIR, INTERACTION=PUNCHCONTACT, TYPE=SURFACE TO SURFACE
SBLOCK, SPUNCH
** symmetry planes and the block's support
*BOUNDARY
NSYMX, 1, 1
NSYMY, 2, 2
NBOTTOM, 3, 3
*STEP, NLGEOM, INC=100
Punch {DEPTH * 1e3:g} mm down
*STATIC
0.25, 1.0, 0.01, 0.25
*BOUNDARY
NPUNCHTOP, 3, 3, {-DEPTH:.4g}
*NODE PRINT, NSET=NPUNCHTOP, TOTALS=YES
RF
*CONTACT PRINT
CSTR
*END STEP
""")
    return "".join(out), len(nodes), len(elements), len(eslave), len(emaster)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    root = Path(__file__).resolve().parent.parent
    parser.add_argument("-o", "--output", type=Path, default=root / "examples" / "punch.inp")
    args = parser.parse_args()
    text, nn, ne, ns, nm = build()
    args.output.write_text(text)
    print(f"wrote {args.output}: {nn} nodes, {ne} C3D8, {ns} slave faces, {nm} master faces, "
          f"{len(text.encode()) / 1e6:.2f} MB")


if __name__ == "__main__":
    main()
