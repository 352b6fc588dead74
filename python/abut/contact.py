"""abut's contact library on numpy arrays: penalty contact between two surfaces of your own mesh,
one explicit step at a time (the C++ interface is abut/contact/interface.hpp; docs/contact.md).

Nodal arrays are (n, 3) float64 arrays (coordinates, velocities, forces) and (n,) masses, indexed
like the facets' nodes; units are your own, consistent ones. A sketch::

    import numpy as np
    from abut.contact import Surface, Interface
    lower = Surface(np.array([[0, 1, 2, 3]]), penalty=1e8, thickness=0.1)   # normal up
    upper = Surface(np.array([[4, 7, 6, 5]]), penalty=1e8, thickness=0.1)   # normal down
    contact = Interface(upper, lower, mass, x, friction=0.3)
    f = contact.apply(x, v, time=t, dt=dt)        # contact forces, (n, 3)
    dt_next = min(dt_host, contact.stable_step)
"""
from . import _abut

setting_names = _abut.setting_names


class Surface:
    """A contact surface: facets of 4 node indices each, counter-clockwise seen from outside
    the body (a triangle repeats its last node).

    ``part``, ``penalty`` (the penalty stiffness pfac [stress / length]) and ``thickness`` (the
    element's size along the facet's normal [length]) are one value for every facet or one per
    facet. ``shell=True``: each facet is a shell's mid-surface of that thickness, touched on both
    sides.
    """

    def __init__(self, facets, *, penalty, thickness, part=1, shell=False):
        self._surface = _abut.ContactSurface(facets, part, penalty, thickness, shell)

    def __len__(self):
        return len(self._surface)


class Interface:
    """Contact between ``surface1`` and ``surface2`` (the same Surface: self contact).

    ``mass`` (n,) and ``x`` (n, 3) are the nodal masses and initial coordinates (which fix sharp
    edges, areas and initial penetrations). Settings are keyword arguments by name
    (``abut.contact.setting_names()``): ``friction``, ``friction_static``, ``friction_sliding``,
    ``damping`` (fraction of critical, default 0.1), ``node_to_surface`` and ``one_way`` (flags),
    ``accuracy_level``, ``detection_depth``, ``search_margin``, ``begin_time``, ``end_time``,
    ``initial_offset``, ``initial_max``, ``edge_angle``, ``tangential_penalty``,
    ``stick_stress`` (meanings in abut/abut_contact.h). Node to surface: ``secondary_nodes``
    (default: every node of surface 1) are the contact points. Raises
    ``abut.ContactSetupError`` naming the setting or surface at fault.
    """

    def __init__(self, surface1, surface2, mass, x, *, secondary_nodes=None, **settings):
        self._interface = _abut.ContactInterface(surface1._surface, surface2._surface, mass, x,
                                                 settings, secondary_nodes)

    def apply(self, x, v, *, time, dt, forces=None):
        """The contact forces of the state (x, v) at ``time``, (n, 3): added to ``forces`` (a
        C-contiguous float64 (n, 3) array, returned) when given, else in a new array. ``dt`` is
        the step over which friction and damping work are integrated (explicit: v is the
        velocity of the half step before)."""
        return self._interface.apply(x, v, time, dt, forces)

    @property
    def stats(self):
        """A dict: ``force`` (on surface 1), ``normal_force``, ``tangential_force``,
        ``elastic_energy``, ``damping_energy``, ``friction_energy``, ``released_energy``,
        ``max_penetration``, ``active_points``, and the bounds ``stable_step``,
        ``approach_step``, ``kink_step`` on the next step."""
        return self._interface.stats

    @property
    def stable_step(self):
        """The largest next step the contact allows: the least of its three bounds."""
        return self._interface.stable_step

    @property
    def point_count(self):
        """The number of contact points (integration points or nodes)."""
        return self._interface.point_count

    @property
    def last_apply_seconds(self):
        """Wall time of the library's work in the last apply (without the Python call)."""
        return self._interface.last_apply_seconds

    def save_state(self):
        """The evolving state (points, friction history, statistics) as bytes, for a restart."""
        return self._interface.save_state()

    def restore_state(self, state):
        """Loads what save_state of an interface of the same model returned."""
        self._interface.restore_state(state)
