"""abut.run and abut.check: the same runs, checks and error locations as the program.
References: the program itself (its output files and its error message for the same deck)."""
import csv
import subprocess

import pytest

import abut
from decks import BAD_CONTACT

def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(v) for v in row] for row in rows[1:]]


def test_run_writes_what_the_program_writes(tmp_path, abut_exe, source_dir):
    deck = source_dir / "examples/bar_impact.k"
    calls = []
    results = abut.run(deck, out=tmp_path / "py", threads=1,
                       progress=lambda t, end, cycles: calls.append((t, end, cycles)))
    subprocess.run([abut_exe, "run", str(deck), "-o", str(tmp_path / "cli"), "-q",
                    "--threads", "1"], check=True, capture_output=True)
    # Bitwise the same run: the same histories, value for value.
    for name in ("energy.csv", "parts.csv"):
        assert read_csv(tmp_path / "py" / name) == read_csv(tmp_path / "cli" / name), name
    report = results.report
    assert report["stable"] and report["cycles"] > 0
    assert report["end_time"] == pytest.approx(1e-4)
    # Progress: at every hundredth and at the end, in order.
    assert 90 <= len(calls) <= 102
    assert calls[-1][0] == report["end_time"] and calls[-1][2] == report["cycles"]
    assert all(a[0] < b[0] for a, b in zip(calls, calls[1:]))


def test_deck_error_is_located_as_the_program_prints_it(tmp_path, abut_exe):
    deck = tmp_path / "bad.k"
    deck.write_text(BAD_CONTACT)
    cli = subprocess.run([abut_exe, "check", str(deck)], capture_output=True, text=True)
    assert cli.returncode == 2
    with pytest.raises(abut.DeckError) as raised:
        abut.check(deck)
    error = raised.value
    assert cli.stderr.strip() == "error: " + str(error)
    assert (error.file, error.line, error.keyword, error.field) == (str(deck), 15, "*CONTACT",
                                                                     "pfac")
    with pytest.raises(abut.DeckError):
        abut.run(deck, out=tmp_path / "out")


def test_check_summarises_a_good_deck(source_dir):
    summary = abut.check(source_dir / "examples/bar_impact.k")
    assert summary["nodes"] > 0 and summary["parts"] == 1 and summary["static_steps"] == 0
    assert summary["initial_time_step"] > 0


def test_an_exception_in_the_progress_callback_stops_the_run(tmp_path, source_dir):
    class Enough(Exception):
        pass

    def stop(t, end, cycles):
        if t > 0.3 * end:
            raise Enough()

    with pytest.raises(Enough):
        abut.run(source_dir / "examples/bar_impact.k", out=tmp_path / "out", progress=stop)
    # The run stopped as an interrupted run does: its final state and summary are written.
    assert (tmp_path / "out" / "summary.json").exists()
