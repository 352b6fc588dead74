"""abut.results: an output directory read back as numpy arrays.

References, independent of the code under test: VTK's own XML reader for every state (points,
cells and every point and cell array, compared exactly), the csv module for every history, json
for summary.json and xml.etree for results.pvd. The runs: a small contact deck with hexahedra,
tetrahedra and quad shells in one grid (an explicit run: energy, parts and contact histories) and
examples/static_block_press.k (a static run: increments.csv, a 6-component stress)."""
import csv
import json
import shutil
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import vtk
from vtk.util.numpy_support import vtk_to_numpy

from abut.results import History, Results, State

# A tetrahedral steel cube thrown at 20 m/s down and 5 m/s along x onto a hexahedral slab, a shell
# sheet beneath (not touched): contact with friction, and VTK cell types 12, 10 and 9 in one grid.
# 61 cycles, 11 states, a few hundredths of a second.
CONTACT_DECK = """*UNIT_SYSTEM
SI
*TIME
4.0e-5
*OUTPUT
4.0e-6, 1.0e-6
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 0.02, 0.02, 0.01
*COMPONENT_BOX
2, 2, 1, 1, 1
0.005, 0.005, 0.0101, 0.015, 0.015, 0.0201
*CHANGE_TO_TETRAHEDRA
P, 2, 4
*COMPONENT_SHELL_PLATE
3, 3, 2, 2
0.0, 0.0, -0.005, 0.02, 0.0, -0.005
0.0, 0.02, -0.005
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"slab"
1, 1
"cube"
2, 1
"sheet"
3, 1, , 0.001
*INITIAL_VELOCITY
P, 2, 5.0, 0.0, -20.0
*CONTACT
1
P, 2, P, 1, 0.2
*END
"""


def run_abut(abut_exe, deck, out):
    r = subprocess.run([abut_exe, "run", str(deck), "-o", str(out), "-q", "--threads", "1"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    return out


@pytest.fixture(scope="module")
def contact_out(tmp_path_factory, abut_exe):
    tmp = tmp_path_factory.mktemp("contact")
    (tmp / "contact.k").write_text(CONTACT_DECK)
    return run_abut(abut_exe, tmp / "contact.k", tmp / "out")


@pytest.fixture(scope="module")
def static_out(tmp_path_factory, abut_exe, source_dir):
    tmp = tmp_path_factory.mktemp("static")
    return run_abut(abut_exe, source_dir / "examples/static_block_press.k", tmp / "out")


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(v) for v in row] for row in rows[1:]])


def vtk_grid(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    assert reader.GetErrorCode() == 0
    return reader.GetOutput()


def vtk_arrays(data):
    """Name -> numpy array of a vtkPointData or vtkCellData."""
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
            for i in range(data.GetNumberOfArrays())}


def assert_state_is_vtks(state, path):
    """Everything State read equals what VTK reads from the same file, exactly."""
    grid = vtk_grid(path)
    assert state.points.shape == (grid.GetNumberOfPoints(), 3)
    assert state.points.dtype == np.float64
    assert np.array_equal(state.points, vtk_to_numpy(grid.GetPoints().GetData()))
    cells = grid.GetCells()
    assert np.array_equal(state.connectivity, vtk_to_numpy(cells.GetConnectivityArray()))
    # VTK keeps n + 1 offsets from 0; the file has the n end offsets.
    assert np.array_equal(state.offsets, vtk_to_numpy(cells.GetOffsetsArray())[1:])
    assert np.array_equal(state.types, vtk_to_numpy(grid.GetCellTypesArray()))
    for ours, theirs in ((state.point_data, vtk_arrays(grid.GetPointData())),
                         (state.cell_data, vtk_arrays(grid.GetCellData()))):
        assert list(ours) == list(theirs)
        for name, values in theirs.items():
            assert ours[name].shape == values.shape, name
            assert np.array_equal(ours[name], values), name


def test_every_state_equals_what_vtk_reads(contact_out):
    results = Results(contact_out)
    assert len(results.states) == 11
    for i, path in enumerate(results.states):
        state = results.state(i)
        assert state.path == path
        assert_state_is_vtks(state, path)
    last = results.state(-1)
    assert set(last.types) == {12, 10, 9}  # hexahedra, tetrahedra, quads
    assert last.point_data["velocity"].shape == (len(last.points), 3)
    assert last.cell_data["von_mises_stress"].shape == (len(last.types),)
    assert np.any(last.point_data["displacement"] != 0.0)


def test_static_states_equal_what_vtk_reads(static_out):
    results = Results(static_out)
    state = results.state(-1)
    assert state.cell_data["stress"].shape == (len(state.types), 6)
    assert_state_is_vtks(state, results.states[-1])


def test_times_and_negative_indices_follow_results_pvd(contact_out):
    results = Results(contact_out)
    datasets = ET.parse(contact_out / "results.pvd").getroot().iter("DataSet")
    series = [(float(d.get("timestep")), contact_out / d.get("file")) for d in datasets]
    assert results.times.tolist() == [t for t, _ in series]
    assert results.states == [p for _, p in series]
    for i in (-1, -len(series)):
        assert results.state(i).time == series[i][0]
        assert results.state(i).path == series[i][1]
    with pytest.raises(IndexError):
        results.state(len(series))


def test_histories_equal_the_csv_files(contact_out, static_out):
    for out, names in ((contact_out, ["contact", "energy", "parts"]),
                       (static_out, ["contact", "energy", "increments"])):
        results = Results(out)
        assert results.histories == names
        for name in names:
            columns, rows = read_csv(out / f"{name}.csv")
            history = results.history(name)
            assert history.columns == columns
            assert len(history) == len(rows) > 0
            assert np.array_equal(history.time, rows[:, 0])
            for k, column in enumerate(columns):
                assert history[column].dtype == np.float64
                assert np.array_equal(history[column], rows[:, k]), (name, column)


def test_by_splits_the_long_format_rows_exactly(contact_out, static_out):
    parts = Results(contact_out).history("parts")
    columns, rows = read_csv(contact_out / "parts.csv")
    split = parts.by("part")
    assert list(split) == [1, 2, 3]
    assert sum(len(h) for h in split.values()) == len(rows)
    for number, history in split.items():
        assert isinstance(history, History)
        assert history.columns == columns
        assert np.array_equal(history.values, rows[rows[:, 1] == number])
    # The cube's velocity along z turns from -20 m/s to a rebound.
    assert split[2]["vz"][0] == -20.0 and split[2]["vz"][-1] > 0.0

    contact = Results(contact_out).history("contact").by("contact")
    assert list(contact) == [1] and np.max(contact[1]["normal_force"]) > 0.0
    increments = Results(static_out).history("increments").by("step")
    assert list(increments) == [1, 2]
    with pytest.raises(ValueError, match="whole-number"):
        Results(contact_out).history("energy").by("kinetic")


def test_summary_is_summary_json(contact_out, tmp_path):
    assert Results(contact_out).summary == json.loads((contact_out / "summary.json").read_text())
    copy = shutil.copytree(contact_out, tmp_path / "copy")
    (copy / "summary.json").unlink()
    assert Results(copy).summary == {}


def test_missing_directories_and_files_are_named(contact_out, tmp_path):
    with pytest.raises(FileNotFoundError, match="nowhere"):
        Results(tmp_path / "nowhere")
    (tmp_path / "empty").mkdir()
    with pytest.raises(FileNotFoundError, match="not an abut output directory"):
        Results(tmp_path / "empty")
    results = Results(contact_out)
    with pytest.raises(FileNotFoundError, match="increments.csv"):
        results.history("increments")
    with pytest.raises(KeyError, match="no column 'speed'"):
        results.history("energy")["speed"]
    copy = shutil.copytree(contact_out, tmp_path / "copy")
    (copy / "states/state_0003.vtu").unlink()
    with pytest.raises(FileNotFoundError, match="state_0003.vtu"):
        Results(copy).state(3)


def test_malformed_files_raise_value_errors_naming_them(contact_out, tmp_path):
    out = shutil.copytree(contact_out, tmp_path / "copy")
    with open(out / "energy.csv", "a") as f:
        f.write("1e-4,oops\n")
    with pytest.raises(ValueError, match=r"energy\.csv:\d+"):
        Results(out).history("energy")
    (out / "parts.csv").write_text("part,mass\n1,2\n")
    with pytest.raises(ValueError, match="parts.csv"):
        Results(out).history("parts")
    (out / "summary.json").write_text("{")
    with pytest.raises(ValueError, match="summary.json"):
        Results(out).summary
    (out / "results.pvd").write_text("<VTKFile><Collection>")
    with pytest.raises(ValueError, match="results.pvd"):
        Results(out).times

    state = out / "states/state_0004.vtu"
    text = state.read_text()
    start = text.index('Name="velocity"')
    start = text.index(">", start) + 1
    state.write_text(text[:start] + text[start:].replace("A", "", 40))  # bytes lost
    with pytest.raises(ValueError, match=r"state_0004\.vtu: DataArray 'velocity'"):
        State(state)
    state.write_text(text[:len(text) // 2])  # cut off
    with pytest.raises(ValueError, match="state_0004.vtu"):
        State(state)


@pytest.mark.parametrize("mode", ["ascii", "binary"])
def test_vtks_own_encodings_read_alike(contact_out, tmp_path, mode):
    """A state written again by VTK's writer, as ascii, and as binary with VTK's UInt32 header
    encoded together with the values (abut writes a UInt64 header as a block of its own)."""
    grid = vtk_grid(contact_out / "states/state_0005.vtu")
    path = tmp_path / f"{mode}.vtu"
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetInputData(grid)
    writer.SetFileName(str(path))
    writer.SetCompressorTypeToNone()
    writer.SetHeaderTypeToUInt32()
    writer.SetDataModeToAscii() if mode == "ascii" else writer.SetDataModeToBinary()
    assert writer.Write() == 1
    state = State(path)
    assert_state_is_vtks(state, path)
    original = State(contact_out / "states/state_0005.vtu")
    assert np.array_equal(state.points, original.points)
    for name, values in original.point_data.items():
        assert np.array_equal(state.point_data[name], values)
