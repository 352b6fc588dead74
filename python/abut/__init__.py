"""abut: an open engine for contact in nonlinear finite-element simulation, from Python.

- ``abut.run(deck, out=...)`` runs a deck (.k or .inp) and returns its ``Results``;
- ``abut.check(deck)`` reads and validates a deck; an error is an ``abut.DeckError`` with the
  file, line, keyword and field the command-line program prints;
- ``abut.Results(out_dir)`` reads a run's output: histories and states as numpy arrays;
- ``abut.plot(out_dir)`` writes PNG figures of a run (energies, contact forces, velocities);
- ``abut.contact`` is the contact library on numpy arrays.

docs/python.md has a tour; help(abut.run) and the others say the rest.
"""
import os

from . import _abut, contact
from .errors import ContactSetupError, DeckError, InstabilityError
from .plot import plot  # the function: abut.plot(out_dir) (matplotlib is loaded when it draws)
from .results import History, Results, State

__all__ = ["run", "check", "Results", "History", "State", "plot", "contact", "DeckError",
           "InstabilityError", "ContactSetupError"]


def check(deck):
    """Reads and validates ``deck`` as ``abut check`` does, without running it.

    Returns a dict: ``nodes``, ``parts``, ``contacts``, ``static_steps``, the reader's
    ``notes`` and the contacts' ``warnings``, and for explicit runs the
    ``initial_time_step``. Raises ``DeckError`` (file, line, keyword, field) for a bad deck.
    """
    return _abut._check(os.fspath(deck))


def run(deck, out=None, *, threads=0, progress=None, echo=False):
    """Runs ``deck`` (a .k deck or a .inp file) to its end as ``abut run`` does, and returns
    the ``Results`` of its output directory ``out`` (default: ``<deck stem>_out`` beside the
    deck). ``results.report`` holds the run's report (cycles, wall time, energy balance, log).

    ``threads``: OpenMP threads (0: all). ``progress``: called as
    ``progress(time, end_time, cycles)`` at every hundredth of an explicit run and at every
    increment of a static one (an exception raised there stops the run and propagates).
    ``echo``: print the solver's log and progress bar as the program does. Ctrl-C stops the
    run with its final state written, then raises KeyboardInterrupt.

    Raises ``DeckError`` for a bad deck and ``InstabilityError`` (with ``.results``, whose last
    state is the last good one) when the run goes unstable.
    """
    deck = os.fspath(deck)
    if out is None:
        stem = os.path.splitext(os.path.basename(deck))[0]
        out = os.path.join(os.path.dirname(deck), stem + "_out")
    report = _abut._run(deck, os.fspath(out), threads, progress, echo)
    results = Results(out)
    results.report = report
    if not report["stable"]:
        raise InstabilityError(report["message"], results)
    return results

