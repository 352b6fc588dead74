#!/usr/bin/python3
"""The cost of Python's abut.contact over the library: a 100 x 100 plate of facets pressed
10 um into a 99 x 99 plate (non-matching) and sliding, surface to surface (4 points per facet of
each side: about 80k points, 20k nodes) and node to surface (the upper plate's 10k nodes).
For each, the wall time of Interface.apply from Python against the library's own time inside it
(last_apply_seconds), over 50 calls after 5 to warm up; the difference is the Python overhead
(argument checks, copies of the (n, 3) arrays into the library's buffers and of the forces
back). Run after `make build`:
    PYTHONPATH=build/python /usr/bin/python3 bench/bench_python_contact.py
"""
import statistics
import time

import numpy as np

from abut.contact import Interface, Surface


def plate(n, size, z, first, facing_up):
    """An n x n plate of facets over [0, size]^2 at height z; nodes numbered from `first`."""
    s = np.linspace(0.0, size, n + 1)
    gx, gy = np.meshgrid(s, s)
    x = np.column_stack([gx.ravel(), gy.ravel(), np.full(gx.size, z)])
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    a = (first + j * (n + 1) + i).ravel()
    quads = np.column_stack([a, a + 1, a + n + 2, a + n + 1])
    return x, quads if facing_up else quads[:, ::-1]


def measure(name, **settings):
    xl, ql = plate(99, 1.0, 0.0, 0, True)
    xu, qu = plate(100, 1.0, -1e-5, len(xl), False)
    x = np.vstack([xl, xu])
    mass = np.full(len(x), 1e-3)
    lower = Surface(ql, penalty=1e9, thickness=0.01)
    upper = Surface(qu, penalty=1e9, thickness=0.01)
    contact = Interface(upper, lower, mass, x, friction=0.2, **settings)
    v = np.zeros_like(x)
    v[len(xl):, 0] = 0.1
    forces = np.zeros_like(x)
    wall, inside = [], []
    for step in range(55):
        start = time.perf_counter()
        contact.apply(x, v, time=step * 1e-6, dt=1e-6, forces=forces)
        if step >= 5:
            wall.append(time.perf_counter() - start)
            inside.append(contact.last_apply_seconds)
        x = x + v * 1e-6
    w, c = statistics.median(wall), statistics.median(inside)
    print(f"{name:24s} {contact.point_count:7d} points  apply {w * 1e3:8.3f} ms  "
          f"library {c * 1e3:8.3f} ms  Python overhead {100 * (w - c) / w:5.2f}%  "
          f"({(w - c) * 1e6:.0f} us)")


measure("surface to surface")
measure("node to surface", node_to_surface=1, one_way=1)
