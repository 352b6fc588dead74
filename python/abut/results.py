"""The output directory of an abut run, read back as numpy arrays (pure Python and numpy).

A run writes into its output directory (docs/python.md, "Results and plots"):

- time histories, one CSV file each: ``energy.csv``, ``parts.csv``, ``contact.csv``, for a
  static run ``increments.csv``, and ``nodes.csv`` when the deck follows nodes; a header line of
  column names, then one row per output time (per part, contact or node in ``parts.csv``,
  ``contact.csv`` and ``nodes.csv``), ``time`` first;
- ``results.pvd``, the ParaView list of the states, and ``states/state_NNNN.vtu``, one VTK XML
  UnstructuredGrid per state;
- ``summary.json``.

``Results(out_dir)`` reads them on demand::

    r = Results("rubber_sphere_out")
    e = r.history("energy")
    e.time, e["kinetic"]                    # 1-D float arrays
    r.history("parts").by("part")[1]["vz"]  # the rows of part 1
    s = r.state(-1)                         # the last state
    s.points, s.point_data["velocity"]      # (n, 3) arrays; points are the deformed positions

Nothing here imports VTK: the states' base64 arrays are decoded with the standard library.
"""
import base64
import binascii
import csv
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

__all__ = ["Results", "History", "State"]

# VTK XML DataArray types and their little-endian numpy equivalents ("VTK File Formats", XML).
_VTK_TYPES = {
    "Int8": "<i1", "UInt8": "<u1", "Int16": "<i2", "UInt16": "<u2",
    "Int32": "<i4", "UInt32": "<u4", "Int64": "<i8", "UInt64": "<u8",
    "Float32": "<f4", "Float64": "<f8",
}

# The files a run always writes: a directory with none of them is not an abut output directory.
_MARKERS = ("summary.json", "results.pvd", "energy.csv")


class History:
    """A time history: the rows of one CSV file of an output directory, as float columns.

    ``columns`` lists the column names, ``time`` first; ``h[name]`` is that column as a 1-D
    float array (one value per row); ``h.time`` is ``h["time"]``; ``len(h)`` is the number of
    rows; ``h.values`` is the whole table, a (rows, columns) float array; ``h.source`` names
    the file. Long-format files, with one row per part (``parts.csv``) or per contact
    (``contact.csv``) at each time, split with ``h.by("part")`` or ``h.by("contact")``.
    """

    def __init__(self, columns, values, source="history"):
        """``columns``: the names; ``values``: a (rows, len(columns)) array; ``source``: what
        error messages call it (normally the file's path)."""
        self.columns = list(columns)
        self.values = np.asarray(values, dtype=float).reshape(-1, len(self.columns))
        self.source = str(source)

    def __getitem__(self, column):
        """The column named ``column`` as a 1-D float array (a view of ``values``)."""
        try:
            return self.values[:, self.columns.index(column)]
        except ValueError:
            raise KeyError(f"{self.source} has no column {column!r}; its columns are "
                           f"{', '.join(self.columns)}") from None

    def __contains__(self, column):
        return column in self.columns

    def __len__(self):
        return self.values.shape[0]

    @property
    def time(self):
        """The ``time`` column: the model time of each row."""
        return self["time"]

    def by(self, column):
        """Splits the rows by the whole-number id in ``column`` (``"part"``, ``"contact"``):
        a dict {id (int): History of that id's rows, in file order}, ids ascending."""
        ids = self[column]
        if not np.all(np.isfinite(ids)) or np.any(ids != np.round(ids)):
            raise ValueError(f"{self.source}: column {column!r} does not hold whole-number ids")
        return {int(i): History(self.columns, self.values[ids == i],
                                f"{self.source} ({column} {int(i)})")
                for i in np.unique(ids)}

    def __repr__(self):
        return f"History({self.source!r}, {len(self)} rows, columns {self.columns})"


class State:
    """One state of a run: the grid and fields of one ``states/state_NNNN.vtu`` file.

    - ``time``: its model time (from ``results.pvd``);
    - ``points``: (n, 3) float64, the current (deformed) positions of the nodes;
    - ``connectivity``, ``offsets``, ``types``: the VTK cells as the file has them: cell ``c``
      has the points ``connectivity[offsets[c-1]:offsets[c]]`` (from 0 for the first) and the
      VTK cell type ``types[c]`` (12 hexahedron, 10 tetrahedron, 9 quad shell, ...);
    - ``point_data``, ``cell_data``: dicts name -> array, shaped (n,) for one component and
      (n, components) for more (``"displacement"``, ``"velocity"``, ``"von_mises_stress"``, ...);
    - ``path``: the file.
    """

    def __init__(self, path, time=float("nan")):
        """Reads the VTU file ``path``; ``time`` is the state's time (``Results.state`` gives
        it). Raises FileNotFoundError or ValueError naming the file."""
        self.path = Path(path)
        self.time = time
        try:
            root = ET.parse(self.path).getroot()
        except FileNotFoundError:
            raise FileNotFoundError(f"state file {self.path} not found") from None
        except ET.ParseError as e:
            raise ValueError(f"{self.path}: not a readable VTU file ({e})") from None
        if root.tag != "VTKFile" or root.get("type") != "UnstructuredGrid":
            raise ValueError(f"{self.path}: not a VTK XML UnstructuredGrid file")
        if root.get("compressor"):
            raise ValueError(f"{self.path}: compressed arrays ({root.get('compressor')}) are "
                             "not supported; abut writes uncompressed ones")
        pieces = root.findall("UnstructuredGrid/Piece")
        if len(pieces) != 1:
            raise ValueError(f"{self.path}: {len(pieces)} pieces; abut writes one")
        piece = pieces[0]
        reader = _ArrayReader(self.path, root)
        try:
            points = int(piece.get("NumberOfPoints"))
            cells = int(piece.get("NumberOfCells"))
        except (TypeError, ValueError):
            raise ValueError(f"{self.path}: Piece without NumberOfPoints or NumberOfCells") \
                from None
        self.points = reader.array(piece, "Points/DataArray", points)
        self.connectivity = reader.array(piece, "Cells/DataArray[@Name='connectivity']")
        self.offsets = reader.array(piece, "Cells/DataArray[@Name='offsets']", cells)
        self.types = reader.array(piece, "Cells/DataArray[@Name='types']", cells)
        self.point_data = reader.fields(piece, "PointData", points)
        self.cell_data = reader.fields(piece, "CellData", cells)

    def __repr__(self):
        return (f"State(time={self.time!r}, {len(self.points)} points, {len(self.types)} cells, "
                f"point data {list(self.point_data)}, cell data {list(self.cell_data)})")


class _ArrayReader:
    """Decodes the DataArrays of one VTU file (binary: base64 of a byte-count header, then of the
    raw values; or ascii)."""

    def __init__(self, path, root):
        self.path = path
        self.big_endian = root.get("byte_order", "LittleEndian") == "BigEndian"
        header_type = root.get("header_type", "UInt32")  # VTK's default when absent
        if header_type not in ("UInt32", "UInt64"):
            raise ValueError(f"{path}: header_type {header_type!r} is not UInt32 or UInt64")
        self.header_bytes = 4 if header_type == "UInt32" else 8

    def array(self, piece, where, count=None):
        """The DataArray at ``where`` under ``piece``, shaped (count,) or (count, components);
        a ValueError naming the file and the array if it is missing or does not fit."""
        element = piece.find(where)
        if element is None:
            raise ValueError(f"{self.path}: no {where}")
        return self.decode(element, count)

    def fields(self, piece, tag, count):
        """The DataArrays of the PointData or CellData section as a dict name -> array."""
        section = piece.find(tag)
        if section is None:
            return {}
        return {e.get("Name"): self.decode(e, count) for e in section.findall("DataArray")}

    def decode(self, element, count):
        name = element.get("Name", "?")
        where = f"{self.path}: DataArray {name!r}"
        vtk_type = element.get("type")
        if vtk_type not in _VTK_TYPES:
            raise ValueError(f"{where}: type {vtk_type!r} is not supported")
        dtype = np.dtype(_VTK_TYPES[vtk_type])
        if self.big_endian:
            dtype = dtype.newbyteorder(">")
        # The values are the element's own text; VTK's writer may add InformationKey children
        # after them (array ranges), whose text is not part of the array.
        text = (element.text or "") + "".join(child.tail or "" for child in element)
        words = text.split()
        data_format = element.get("format", "ascii")
        if data_format == "binary":
            values = np.frombuffer(self._binary_bytes("".join(words), where), dtype=dtype)
        elif data_format == "ascii":
            number = int if dtype.kind in "iu" else float  # int: Int64 ids beyond 2**53
            try:
                values = np.array([number(w) for w in words], dtype=dtype)
            except ValueError:
                raise ValueError(f"{where}: ascii values that are not numbers") from None
        else:
            raise ValueError(f"{where}: format {data_format!r} is not supported "
                             "(abut writes binary)")
        values = values.astype(dtype.newbyteorder("="))  # native order, owning its memory
        components = int(element.get("NumberOfComponents", "1"))
        if components < 1 or values.size % components != 0:
            raise ValueError(f"{where}: {values.size} values do not make whole tuples of "
                             f"{components} components")
        tuples = values.size // components
        if count is not None and tuples != count:
            raise ValueError(f"{where}: {tuples} tuples, expected {count}")
        return values.reshape(tuples, components) if components > 1 else values

    def _binary_bytes(self, text, where):
        # The byte-count header is normally a base64 block of its own (abut and VTK write it so;
        # it then ends in '=' padding, 4 and 8 bytes not being multiples of 3); otherwise header
        # and values were encoded together.
        header_chars = 4 * -(-self.header_bytes // 3)
        try:
            if text[header_chars - 1:header_chars] == "=":
                header = base64.b64decode(text[:header_chars], validate=True)
                data = base64.b64decode(text[header_chars:], validate=True)
            else:
                whole = base64.b64decode(text, validate=True)
                header, data = whole[:self.header_bytes], whole[self.header_bytes:]
        except (binascii.Error, ValueError):
            raise ValueError(f"{where}: not valid base64") from None
        if len(header) != self.header_bytes:
            raise ValueError(f"{where}: no byte-count header")
        size = int.from_bytes(header, "big" if self.big_endian else "little")
        if len(data) != size:
            raise ValueError(f"{where}: the header announces {size} bytes, the array has "
                             f"{len(data)}")
        return data


def _read_csv(path):
    """The header and the rows of a history CSV file as (columns, float array)."""
    try:
        with open(path, newline="") as f:
            rows = csv.reader(f)
            columns = next(rows, None)
            if not columns or columns[0] != "time":
                raise ValueError(f"{path}: not an abut history (the header should start with "
                                 "'time')")
            values = []
            for row in rows:
                if len(row) != len(columns):
                    raise ValueError(f"{path}:{rows.line_num}: {len(row)} values for "
                                     f"{len(columns)} columns")
                try:
                    values.append([float(v) for v in row])
                except ValueError:
                    raise ValueError(f"{path}:{rows.line_num}: a value that is not a number") \
                        from None
    except FileNotFoundError:
        raise FileNotFoundError(f"history file {path} not found") from None
    return columns, np.array(values, dtype=float).reshape(-1, len(columns))


class Results:
    """The output directory of an abut run (``abut run DECK -o OUT_DIR``), ``path``.

    - ``histories``: the names of the time histories there (``"energy"``, ``"parts"``,
      ``"contact"``, ``"increments"``...), ``history(name)`` one of them as a ``History``;
    - ``summary``: ``summary.json`` as a dict (empty if the file is absent);
    - ``times``: the state times (``results.pvd``), ``states``: their VTU files,
      ``state(i)``: state ``i`` (negative from the end) as a ``State``.

    Files are read when asked for, so a ``Results`` of a running job sees its latest rows.
    Raises FileNotFoundError if ``out_dir`` is missing or holds none of summary.json,
    results.pvd and energy.csv; a malformed file raises ValueError naming it when it is read.
    """

    def __init__(self, out_dir):
        """Opens the output directory ``out_dir`` (a str or path)."""
        self.path = Path(out_dir)
        if not self.path.is_dir():
            raise FileNotFoundError(f"output directory {self.path} not found")
        if not any((self.path / name).is_file() for name in _MARKERS):
            raise FileNotFoundError(f"{self.path} is not an abut output directory (it has none "
                                    f"of {', '.join(_MARKERS)})")

    @property
    def histories(self):
        """The sorted names of the history CSV files (their stems)."""
        return sorted(p.stem for p in self.path.glob("*.csv") if p.is_file())

    def history(self, name):
        """The history ``name`` (``"energy"``, ``"parts"``, ``"contact"``, ``"increments"``,
        ``"nodes"``) as a ``History``; FileNotFoundError if the run did not write it."""
        path = self.path / f"{name}.csv"
        if not path.is_file():
            raise FileNotFoundError(f"history file {path} not found; {self.path} has "
                                    f"{', '.join(self.histories) or 'no histories'}")
        columns, values = _read_csv(path)
        return History(columns, values, path)

    @property
    def summary(self):
        """``summary.json`` as a dict: status, cycles, final energies, parts, contacts ...;
        {} if the run has not written it."""
        path = self.path / "summary.json"
        if not path.is_file():
            return {}
        try:
            return json.loads(path.read_text())
        except ValueError as e:
            raise ValueError(f"{path}: not valid JSON ({e})") from None

    def _series(self):
        """[(time, vtu path)] from results.pvd, in its order."""
        path = self.path / "results.pvd"
        try:
            root = ET.parse(path).getroot()
        except FileNotFoundError:
            raise FileNotFoundError(f"{path} not found: the run wrote no states") from None
        except ET.ParseError as e:
            raise ValueError(f"{path}: not a readable ParaView collection ({e})") from None
        series = []
        for dataset in root.iter("DataSet"):
            try:
                series.append((float(dataset.get("timestep")), self.path / dataset.get("file")))
            except (TypeError, ValueError):
                raise ValueError(f"{path}: a DataSet without a timestep or file") from None
        return series

    @property
    def times(self):
        """The model times of the states, a 1-D float array."""
        return np.array([t for t, _ in self._series()], dtype=float)

    @property
    def states(self):
        """The VTU files of the states (paths), in time order."""
        return [p for _, p in self._series()]

    def state(self, i):
        """State ``i`` (0 the first, -1 the last) as a ``State``."""
        series = self._series()
        if not -len(series) <= i < len(series):
            raise IndexError(f"state {i} of {len(series)} in {self.path / 'results.pvd'}")
        time, path = series[i]
        return State(path, time)

    def __repr__(self):
        return f"Results({str(self.path)!r})"
