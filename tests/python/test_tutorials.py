"""The tutorials of examples/tutorials run as a reader runs them, and their own checks hold
(momentum and energy balance of tutorial 1's deck in tutorial 2; the weight carried at rest and
the energy balance in tutorial 3: references in each tutorial's text)."""
import os
import subprocess
import sys


def run_tutorial(path, *args):
    done = subprocess.run([sys.executable, str(path), *map(str, args)], capture_output=True,
                          text=True, timeout=600, env=dict(os.environ))
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_tutorial_1_deck_runs_from_the_program(tmp_path, abut_exe, source_dir):
    deck = source_dir / "examples/tutorials/t1_bars_collide.k"
    subprocess.run([abut_exe, "run", str(deck), "-o", str(tmp_path), "-q"], check=True,
                   capture_output=True)
    subprocess.run([abut_exe, "plot", str(tmp_path)], check=True, capture_output=True)
    assert (tmp_path / "plots" / "energy.png").exists()


def test_tutorial_2_python_results(tmp_path, source_dir):
    out = run_tutorial(source_dir / "examples/tutorials/t2_python_results.py", tmp_path)
    assert "momentum kept" in out and "wrote" in out


def test_tutorial_3_contact_on_numpy_arrays(source_dir):
    out = run_tutorial(source_dir / "examples/tutorials/t3_contact_numpy.py")
    assert "at rest: contact force" in out
