#!/usr/bin/python3
"""Tutorial 3: abut's contact library in a time loop of your own, on numpy arrays
(examples/tutorials/README.md).

Your code owns the mesh and the time integration; abut.contact gives the contact forces. Here a
box of 8 nodes joined by 28 springs (edges and diagonals: nearly rigid) falls 20 mm onto a fixed
plate, bounces, and comes to rest under mass-proportional damping. At rest the contact carries
the box's weight; the energy balance (motion, springs, damping, contact) holds against the work of
gravity all the way. Units: m, kg, s. Run after `make build`:
    PYTHONPATH=build/python /usr/bin/python3 examples/tutorials/t3_contact_numpy.py
"""
from itertools import combinations

import numpy as np

from abut.contact import Interface, Surface

side, node_mass, k_spring, g, c_damp = 0.1, 1.0, 2e5, 9.81, 10.0

# The box: nodes 0-3 its bottom, 4-7 its top; the plate: nodes 8-11 (held: they never move).
corners = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
x = np.zeros((12, 3))
x[0:4, :2] = corners * side
x[4:8, :2] = corners * side
x[0:4, 2], x[4:8, 2] = 0.02, 0.02 + side
x[8:12, :2] = corners * 1.0 - 0.45
mass = np.r_[np.full(8, node_mass), np.full(4, 1e6)]
moving = np.arange(8)

box_faces = np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4],
                      [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])  # outward normals
box = Surface(box_faces, penalty=1e8, thickness=side)
plate = Surface(np.array([[8, 9, 10, 11]]), penalty=1e8, thickness=side)  # normal up
contact = Interface(box, plate, mass, x, node_to_surface=1, one_way=1)

springs = np.array(list(combinations(range(8), 2)))
rest = np.linalg.norm(x[springs[:, 1]] - x[springs[:, 0]], axis=1)


def host_forces(x, v):
    """The springs and gravity on the box's nodes (the damping is in the update)."""
    d = x[springs[:, 1]] - x[springs[:, 0]]
    length = np.linalg.norm(d, axis=1)
    t = (k_spring * (length - rest) / length)[:, None] * d
    f = np.zeros_like(x)
    np.add.at(f, springs[:, 0], t)
    np.add.at(f, springs[:, 1], -t)
    f[moving, 2] -= node_mass * g
    return f


def spring_energy(x):
    d = np.linalg.norm(x[springs[:, 1]] - x[springs[:, 0]], axis=1) - rest
    return 0.5 * k_spring * np.sum(d ** 2)


# Central differences: v at half steps, x at whole steps. The energy balance is taken at whole
# steps, with the velocity there the mean of the half steps' (second-order accurate).
z0 = x[moving, 2].copy()
v = np.zeros_like(x)
t, dt, damping_work, worst, next_check = 0.0, 5e-4, 0.0, 0.0, 0.1
dt_springs = 0.5 * 2.0 / np.sqrt(2 * 7 * k_spring / node_mass)
while t < 3.0:
    f = host_forces(x, v)
    contact.apply(x, v, time=t, dt=dt, forces=f)  # adds the contact forces to f
    # Central differences with the damping force -c m v at the mean of the two half steps'
    # velocities (second order, as the rest; Belytschko, Liu & Moran 2000, section 6.2).
    v_before = v.copy()
    h = 0.5 * c_damp * dt
    v[moving] = ((1 - h) * v[moving] + f[moving] / node_mass * dt) / (1 + h)
    v_now = 0.5 * (v_before + v)[moving]  # the velocity at t
    damping_power = c_damp * node_mass * np.sum(v_now ** 2)
    damping_work += damping_power * dt / 2  # from the half step before to t
    if t >= next_check:  # every 0.1 s
        next_check += 0.1
        s = contact.stats
        held = (0.5 * node_mass * np.sum(v_now ** 2) + spring_energy(x) + damping_work +
                s["elastic_energy"] + s["damping_energy"] + s["friction_energy"] +
                s["released_energy"])
        gravity_work = node_mass * g * np.sum(z0 - x[moving, 2])
        worst = max(worst, abs(held - gravity_work) / gravity_work)
    damping_work += damping_power * dt / 2  # from t to the half step after
    x[moving] += v[moving] * dt
    t += dt
    dt = min(dt_springs, 0.9 * contact.stable_step)

weight = 8 * node_mass * g
print(f"at rest: contact force {s['normal_force']:.6f} N for a weight of {weight:.6f} N; "
      f"energy balance within {100 * worst:.2f}% of gravity's work")
assert abs(s["normal_force"] / weight - 1) < 1e-6, "at rest the contact carries the weight"
assert worst < 0.01, "energy balance: abut's standard is 1%"
