"""abut.plot, `python3 -m abut.plot`, `abut plot` and `abut run --plot`: the figures of a run.

What is checked: each figure is written where asked, is a PNG (signature and IHDR chunk) of a
real size, and only the figures whose histories exist are written (an explicit run without
contact: energy and velocities; a static run with contact: energy and contact); a directory that
is not an output directory is exit code 2 with a message, a missing matplotlib exit code 1 with
one. The runs: examples/bar_impact.k and examples/static_block_press.k (each under 0.3 s)."""
import os
import struct
import subprocess
import sys

import pytest

from abut.plot import main, plot

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def run_abut(abut_exe, *args, env=None):
    return subprocess.run([abut_exe, *map(str, args)], capture_output=True, text=True,
                          timeout=300, env=env)


@pytest.fixture(scope="module")
def bar_out(tmp_path_factory, abut_exe, source_dir):
    out = tmp_path_factory.mktemp("bar") / "out"
    r = run_abut(abut_exe, "run", source_dir / "examples/bar_impact.k", "-o", out, "-q",
                 "--threads", "1")
    assert r.returncode == 0, r.stderr
    return out


@pytest.fixture(scope="module")
def static_out(tmp_path_factory, abut_exe, source_dir):
    out = tmp_path_factory.mktemp("static") / "out"
    r = run_abut(abut_exe, "run", source_dir / "examples/static_block_press.k", "-o", out, "-q")
    assert r.returncode == 0, r.stderr
    return out


def png_size(path):
    """(width, height) of a PNG file, asserting that it is one (signature, then IHDR)."""
    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE, path
    assert data[12:16] == b"IHDR", path
    return struct.unpack(">II", data[16:24])


def assert_figures(directory, names):
    assert sorted(p.name for p in directory.iterdir()) == sorted(f"{n}.png" for n in names)
    for name in names:
        path = directory / f"{name}.png"
        width, height = png_size(path)
        assert width > 600 and height > 400, (path, width, height)
        assert path.stat().st_size > 20_000, path  # curves, labels and legends, not a blank


def test_plot_writes_the_figures_of_the_histories_there(bar_out, static_out, tmp_path):
    written = plot(bar_out)
    assert written == [bar_out / "plots/energy.png", bar_out / "plots/velocities.png"]
    assert_figures(bar_out / "plots", ["energy", "velocities"])  # no contact.csv: no contact.png
    written = plot(static_out, to=tmp_path / "figures")
    assert written == [tmp_path / "figures/energy.png", tmp_path / "figures/contact.png"]
    assert_figures(tmp_path / "figures", ["energy", "contact"])  # static runs have no parts.csv


def test_plot_raises_for_a_directory_that_is_not_an_output_directory(tmp_path):
    with pytest.raises(FileNotFoundError, match="not an abut output directory"):
        plot(tmp_path)
    with pytest.raises(FileNotFoundError, match="nowhere"):
        plot(tmp_path / "nowhere")


def test_module_prints_the_paths_and_exits_2_for_other_directories(bar_out, tmp_path):
    # As a user runs it: the interpreter of these tests with the same PYTHONPATH.
    command = [sys.executable, "-m", "abut.plot"]
    r = subprocess.run([*command, str(bar_out), "--to", str(tmp_path / "a")],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == [str(tmp_path / "a/energy.png"), str(tmp_path / "a/velocities.png")]
    assert_figures(tmp_path / "a", ["energy", "velocities"])
    r = subprocess.run([*command, str(tmp_path / "nowhere")], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 2 and "error: output directory" in r.stderr and "nowhere" in r.stderr


def test_main_without_matplotlib_exits_1_with_a_message(bar_out, tmp_path, monkeypatch, capsys):
    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")]:
        monkeypatch.setitem(sys.modules, name, None)  # an import of it now fails
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    assert main([str(bar_out), "--to", str(tmp_path / "none")]) == 1
    assert "needs matplotlib" in capsys.readouterr().err
    assert not (tmp_path / "none").exists()


def test_abut_plot_writes_the_figures(abut_exe, bar_out, static_out, tmp_path):
    r = run_abut(abut_exe, "plot", static_out)
    assert r.returncode == 0, r.stderr
    assert_figures(static_out / "plots", ["energy", "contact"])
    r = run_abut(abut_exe, "plot", bar_out, "--to", tmp_path / "b")
    assert r.returncode == 0, r.stderr
    assert_figures(tmp_path / "b", ["energy", "velocities"])


def test_abut_plot_of_no_output_directory_is_an_error(abut_exe, tmp_path):
    r = run_abut(abut_exe, "plot", "/nonexistent")
    assert r.returncode == 2 and "'/nonexistent' not found" in r.stderr
    r = run_abut(abut_exe, "plot", tmp_path)
    assert r.returncode == 2 and "not an abut output directory" in r.stderr
    assert not (tmp_path / "plots").exists()


def test_abut_plot_without_matplotlib_exits_1(abut_exe, bar_out, tmp_path):
    # A matplotlib that cannot be imported, ahead of Debian's on the user's PYTHONPATH.
    (tmp_path / "fake/matplotlib").mkdir(parents=True)
    (tmp_path / "fake/matplotlib/__init__.py").write_text("raise ImportError('no matplotlib')\n")
    env = dict(os.environ, PYTHONPATH=str(tmp_path / "fake"))
    r = run_abut(abut_exe, "plot", bar_out, "--to", tmp_path / "c", env=env)
    assert r.returncode == 1, r.stderr
    assert "needs matplotlib" in r.stderr
    assert not (tmp_path / "c").exists()


def test_abut_run_plot_writes_the_figures_after_the_run(abut_exe, source_dir, tmp_path):
    out = tmp_path / "bar"
    r = run_abut(abut_exe, "run", source_dir / "examples/bar_impact.k", "-o", out, "-q",
                 "--threads", "1", "--plot")
    assert r.returncode == 0, r.stderr
    assert_figures(out / "plots", ["energy", "velocities"])
    assert str(out / "plots/energy.png") in r.stdout
