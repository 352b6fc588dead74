#!/usr/bin/python3
"""Tutorial 2: run a deck from Python and read its results (examples/tutorials/README.md).

Runs tutorial 1's deck (two steel bars collide), then reads the histories and the last state as
numpy arrays, checks the momentum and the energy balance, and writes the run's figures.
Run after `make build`:  PYTHONPATH=build/python /usr/bin/python3 examples/tutorials/t2_python_results.py
"""
import sys
from pathlib import Path

import numpy as np

import abut

here = Path(__file__).resolve().parent
out = Path(sys.argv[1]) if len(sys.argv) > 1 else here / "t2_out"

# 1. Check, then run. A mistake in the deck would raise abut.DeckError with its file and line.
summary = abut.check(here / "t1_bars_collide.k")
print(f"{summary['nodes']} nodes, {summary['contacts']} contact, "
      f"first step {summary['initial_time_step']:.3g} s")
results = abut.run(here / "t1_bars_collide.k", out=out,
                   progress=lambda t, end, cycles: None)  # or print a bar of your own
print(f"{results.report['cycles']} cycles in {results.report['wall_seconds']:.2f} s")

# 2. Histories: one numpy array per column; parts.csv has a row per part and time.
parts = results.history("parts").by("part")
striker, target = parts[1], parts[2]
v0 = striker["vx"][0]
print(f"after the impact: striker {striker['vx'][-1]:.3f} m/s, target {target['vx'][-1]:.3f} m/s "
      f"(1-D wave theory: 0 and {v0:g})")
momentum = striker["mass"] * striker["vx"] + target["mass"] * target["vx"]
drift = np.max(np.abs(momentum - momentum[0])) / abs(momentum[0])
energy = results.history("energy")
balance = np.max(np.abs(energy["balance_error"]))
print(f"momentum kept to {drift:.1e}, energy balance within {100 * balance:.3f}%")
assert drift < 1e-9, "momentum: no external force acts"
assert balance < 0.01, "energy balance: abut's standard is 1%"
assert target["vx"][-1] > striker["vx"][-1], "the target leaves faster than the striker"

# 3. States: points, cells and fields of the last state (the ParaView files, as arrays).
last = results.state(-1)
print(f"last state at t = {last.time:.3g} s: {len(last.points)} points, "
      f"fields {sorted(last.point_data)}")

# 4. Figures: energies, contact forces and part velocities as PNG files.
for png in abut.plot(out):
    print("wrote", png)
