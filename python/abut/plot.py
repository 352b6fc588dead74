"""PNG figures of an abut run's time histories, written with matplotlib's Agg canvas (no display).

- ``energy.png``: the energies of ``energy.csv`` over time; below them the heat of a thermal run
  and the energy balance error (in percent, as the run's log gives it);
- ``contact.png``: the normal and the tangential force of each contact (``contact.csv``);
- ``velocities.png``: the velocity components vx, vy, vz of each part's centre of mass
  (``parts.csv``; static runs have none).

A figure whose history the run did not write is left out. From Python: ``plot(out_dir)``; from
the shell: ``python3 -m abut.plot OUT_DIR [--to DIR]`` or ``abut plot OUT_DIR [--to DIR]``.
"""
import argparse
import sys
from pathlib import Path

import numpy as np

from .results import Results

__all__ = ["plot", "main"]

# energy.csv columns with panels of their own: balance_error, a fraction of the run's largest
# energy (README, "Output"), drawn in percent as the run's log states it; and the heat, an energy
# in explicit runs (heat_stored ...) and a power in static ones (heat_flow_...), often far larger
# than the mechanical energies.
_BALANCE = "balance_error"
_HEAT_PREFIX = "heat_"


def plot(out_dir, to=None):
    """Writes the figures of the output directory ``out_dir`` into ``to`` (default:
    ``out_dir/plots``, created if needed) and returns the paths written (pathlib.Path), in this
    order: ``energy.png``; ``contact.png`` if the run wrote contact.csv; ``velocities.png`` if
    it wrote parts.csv (explicit runs). Existing files of those names are replaced.

    Raises FileNotFoundError or ValueError (naming the file) for a directory that is not an abut
    output directory or a malformed history, and ImportError without matplotlib.
    """
    results = Results(out_dir)
    new_figure = _figure_maker()  # ImportError before anything is written
    to = Path(to) if to is not None else results.path / "plots"
    to.mkdir(parents=True, exist_ok=True)
    labels = _Labels(results.summary)
    written = []
    for name, history_name, draw in _FIGURES:
        if history_name not in results.histories:
            continue
        history = results.history(history_name)
        if len(history) == 0:  # a run stopped before its first output
            continue
        figure = draw(new_figure, history, labels)
        path = to / f"{name}.png"
        figure.savefig(path, dpi=110, bbox_inches="tight")
        written.append(path)
    return written


def _figure_maker():
    """matplotlib's Figure with an Agg canvas attached: no pyplot, so neither a display nor the
    backend of a user's interactive session is touched."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    def agg_figure(**kwargs):
        figure = Figure(**kwargs)
        FigureCanvasAgg(figure)
        return figure

    return agg_figure


class _Labels:
    """Axis labels and legend entries from summary.json: the run's units if it states them, the
    titles of parts and contacts, the deck's name for the figure titles."""

    def __init__(self, summary):
        units = summary.get("units")
        self.units = units if isinstance(units, str) and units else "model units"
        self.deck = Path(summary.get("deck", "")).name
        self.titles = {("part", p.get("id")): p.get("title", "") for p in summary.get("parts", [])}
        self.titles.update({("contact", c.get("id")): c.get("title", "")
                            for c in summary.get("contacts", [])})

    def axis(self, column):
        return f"{column} [{self.units}]"

    def entity(self, kind, number):
        title = self.titles.get((kind, number), "")
        return f"{kind} {number}" + (f" ({title})" if title else "")

    def title(self, what):
        return f"{self.deck}: {what}" if self.deck else what


def _legend(axes):
    # Outside the axes on the right, so it never hides a curve.
    axes.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small")


def _energy_figure(new_figure, energy, labels):
    # Columns that stay zero (no erosion, no hourglass, no face heat) are named in the title, not
    # drawn over the others.
    zero = [c for c in energy.columns[1:]
            if c not in ("total", _BALANCE) and not np.any(energy[c])]
    heat = [c for c in energy.columns[1:] if c.startswith(_HEAT_PREFIX) and c not in zero]
    mechanical = [c for c in energy.columns[1:] if c not in zero + heat + [_BALANCE]]
    heat_quantity = "heat flow" if all(c.startswith("heat_flow") for c in heat) else "heat"
    panels = [(q, columns) for q, columns in
              (("energy", mechanical), (heat_quantity, heat),
               ("balance", [_BALANCE] if _BALANCE in energy else [])) if columns]
    panels = panels or [("energy", [])]
    figure = new_figure(figsize=(9, 3 + 2 * len(panels)))
    axes = figure.subplots(len(panels), 1, sharex=True, squeeze=False,
                           gridspec_kw={"height_ratios": [2] + [1] * (len(panels) - 1)})[:, 0]
    for ax, (quantity, columns) in zip(axes, panels):
        if quantity == "balance":
            ax.plot(energy.time, 100.0 * energy[_BALANCE],
                    label=f"{_BALANCE}\n(% of the largest energy)")
            ax.axhline(0.0, color="grey", linewidth=0.8)
            ax.set_ylabel(f"{_BALANCE} [%]")
        else:
            for c in columns:
                style = {"color": "black", "linestyle": "--", "linewidth": 2} \
                    if c == "total" else {}
                ax.plot(energy.time, energy[c], label=c, **style)
            ax.set_ylabel(f"{quantity} [{labels.units}]")
        ax.grid(True, alpha=0.3)
        if columns:
            _legend(ax)
    axes[-1].set_xlabel(labels.axis("time"))
    title = labels.title("energies (energy.csv)")
    if zero:
        title += f"\nzero throughout: {', '.join(zero)}"
    axes[0].set_title(title)
    return figure


def _per_entity_figure(new_figure, history, kind, columns, title, labels, height):
    """One panel per column, one line per entity (contact or part) of a long-format history."""
    figure = new_figure(figsize=(9, height))
    axes = figure.subplots(len(columns), 1, sharex=True)
    for number, rows in history.by(kind).items():
        for ax, column in zip(axes, columns):
            ax.plot(rows.time, rows[column], label=labels.entity(kind, number))
    for ax, column in zip(axes, columns):
        ax.set_ylabel(labels.axis(column))
        ax.grid(True, alpha=0.3)
        _legend(ax)
    axes[-1].set_xlabel(labels.axis("time"))
    axes[0].set_title(labels.title(title))
    return figure


def _contact_figure(new_figure, contact, labels):
    return _per_entity_figure(new_figure, contact, "contact", ("normal_force", "tangential_force"),
                              "contact forces (contact.csv)", labels, 7)


def _velocity_figure(new_figure, parts, labels):
    return _per_entity_figure(new_figure, parts, "part", ("vx", "vy", "vz"),
                              "velocity of each part's centre of mass (parts.csv)", labels, 8)


# (figure, the history it draws, how), in the order plot() writes them.
_FIGURES = (("energy", "energy", _energy_figure),
            ("contact", "contact", _contact_figure),
            ("velocities", "parts", _velocity_figure))


def main(argv=None):
    """``python3 -m abut.plot OUT_DIR [--to DIR]``: writes the figures and prints their paths.
    Exit code 0 on success, 2 for a directory that is not an abut output directory (or a
    malformed file in it), 1 without matplotlib or when a figure cannot be written."""
    parser = argparse.ArgumentParser(
        prog="python3 -m abut.plot",
        description="PNG figures of an abut output directory: energy.png, contact.png, "
                    "velocities.png")
    parser.add_argument("out_dir", help="output directory of an abut run")
    parser.add_argument("--to", help="directory for the figures (default: OUT_DIR/plots)")
    args = parser.parse_args(argv)
    try:
        Results(args.out_dir)
    except (FileNotFoundError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    try:
        written = plot(args.out_dir, args.to)
    except ImportError as e:
        print(f"error: plotting needs matplotlib (Debian: apt install python3-matplotlib): {e}",
              file=sys.stderr)
        return 1
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"error: cannot write the figures: {e}", file=sys.stderr)
        return 1
    for path in written:
        print(path)
    if not written:
        print(f"abut.plot: {args.out_dir} has no histories to plot", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
