"""abut.contact: the contact library on numpy arrays. References: seed 000's penalty law (two flat
facets of area A overlapping by d carry p A = pfac d A, pfac the smaller of the two) and
Coulomb's law (a sliding point carries mu N), as tests/contact/test_interface.cpp for C++."""
import numpy as np
import pytest

import abut
from abut.contact import Interface, Surface

PFAC, D = 3e6, 0.01


def two_facets(gap=-D):
    """A 1 x 1 facet at z = 0 facing up (nodes 0-3) and one at z = gap facing down (4-7)."""
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    x = np.zeros((8, 3))
    x[:4, :2] = square
    x[4:, :2] = square
    x[4:, 2] = gap
    lower = Surface(np.array([[0, 1, 2, 3]]), penalty=PFAC, thickness=1.0, part=2)
    upper = Surface(np.array([[4, 7, 6, 5]]), penalty=PFAC, thickness=1.0, part=1)
    return lower, upper, x, np.ones(8)


def test_pressed_facets_carry_penalty_times_area_times_penetration():
    lower, upper, x, mass = two_facets()
    contact = Interface(upper, lower, mass, x, damping=0.0)
    f = contact.apply(x, np.zeros_like(x), time=0.0, dt=1e-6)
    assert f.shape == (8, 3)
    assert f[4:, 2].sum() == pytest.approx(PFAC * D, rel=1e-12)   # up on the upper facet
    assert f[:4, 2].sum() == pytest.approx(-PFAC * D, rel=1e-12)  # and down on the lower
    assert contact.stats["normal_force"] == pytest.approx(PFAC * D, rel=1e-12)
    assert contact.stats["elastic_energy"] == pytest.approx(0.5 * PFAC * D * D, rel=1e-12)
    # Added to an array of the host's own.
    mine = np.ones((8, 3))
    assert contact.apply(x, np.zeros_like(x), time=0.0, dt=1e-6, forces=mine) is not None
    assert mine[4:, 2].sum() == pytest.approx(4 + PFAC * D, rel=1e-12)


def test_a_sliding_facet_carries_mu_times_the_normal_force():
    lower, upper, x, mass = two_facets()
    contact = Interface(upper, lower, mass, x, damping=0.0, friction=0.3)
    v = np.zeros_like(x)
    v[4:, 0] = 1.0
    dt = 1e-3
    for step in range(20):
        f = contact.apply(x, v, time=step * dt, dt=dt)
        x = x + v * dt
    n = contact.stats["normal_force"]
    assert f[4:, 0].sum() == pytest.approx(-0.3 * n, rel=1e-9)  # against the motion
    assert contact.stats["tangential_force"] == pytest.approx(0.3 * n, rel=1e-9)


def test_settings_and_surfaces_at_fault_are_named():
    lower, upper, x, mass = two_facets()
    with pytest.raises(abut.ContactSetupError) as raised:
        Interface(upper, lower, mass, x, frction=0.3)
    assert raised.value.setting == "frction" and "friction" in str(raised.value)
    beyond = Surface(np.array([[0, 1, 2, 99]]), penalty=PFAC, thickness=1.0)
    with pytest.raises(abut.ContactSetupError) as raised:
        Interface(beyond, lower, mass, x)
    assert raised.value.setting == "surface1"
    with pytest.raises(ValueError):
        Surface(np.array([0, 1, 2, 3]), penalty=PFAC, thickness=1.0)  # not (n, 4)
    with pytest.raises(ValueError):
        Interface(upper, lower, mass, x).apply(x[:5], x[:5], time=0.0, dt=0.0)


def test_saved_state_continues_bitwise():
    lower, upper, x0, mass = two_facets()
    v = np.zeros_like(x0)
    v[4:, 0] = 0.5
    dt = 1e-3

    def steps(contact, x, first, count):
        out = []
        for step in range(first, first + count):
            out.append(contact.apply(x, v, time=step * dt, dt=dt))
            x = x + v * dt
        return out, x

    one = Interface(upper, lower, mass, x0, friction=0.3)
    _, x = steps(one, x0, 0, 10)
    state = one.save_state()
    after, _ = steps(one, x, 10, 10)
    two = Interface(upper, lower, mass, x0, friction=0.3)
    two.restore_state(state)
    again, _ = steps(two, x, 10, 10)
    assert all(np.array_equal(a, b) for a, b in zip(after, again))
