"""Text tables of numbers whose columns are mapped to quantities and units, read to SI.

A table file is a table of numbers (comma, semicolon or whitespace separated, optional header
line; decimal points, or decimal commas with ``decimal = ","`` and ``delimiter = ";"`` as
German rigs write them).  A *column mapping* says which column holds which quantity and in
which unit::

    columns = { time = { column = 1, unit = "ms" },
                position = { column = "x", unit = "mm" },      # a header name, or 1-based index
                friction = { column = 4, unit = "N" } }

Values are converted to SI with pint (:data:`sealsim.units.ureg`) and returned as a
:class:`Measurement` (a pandas DataFrame with one SI column per quantity).  Every problem in a
file -- a cell that is not a number, a missing column, a time that goes backwards, a wrong unit
-- is one :class:`~sealsim.errors.InputError` naming the file, the row (1-based line number in
the file) and the column.  A unit a header name states (``Zeit [ms]``, ``F (N)``,
``Kraft in N``, ``t / s``) must agree with the mapping's unit, or is the unit when the mapping
gives none; text may be UTF-8 (with or without byte-order mark), UTF-16 with its byte-order
mark or Windows-1252, cells may be quoted.

One reader for every table sealsim reads: rig measurements (:mod:`sealsim.measurements`, which
adds named formats of known rigs), material tests (``sealsim material fit``) and a rotary
case's duty-cycle CSV.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd
import pint

from sealsim.errors import InputError
from sealsim.files import MAX_DATA_BYTES, read_input_bytes
from sealsim.units import cycles_per_time, rotational_speed, ureg

__all__ = ["QUANTITIES", "ColumnSpec", "Measurement", "header_unit", "read_table"]

#: quantity name -> SI unit it is stored in (gauge pressures: pressures relative to ambient)
QUANTITIES: dict[str, str] = {
    "time": "s",
    "position": "m",
    "velocity": "m/s",
    "friction": "N",
    "force": "N",
    "pressure": "Pa",
    "pressure_1": "Pa",
    "pressure_2": "Pa",
    "temperature": "K",
    "torque": "N*m",
    "speed": "rad/s",
    # material tests (sealsim material fit): stress-strain curves, DMA, dilatometry
    "stretch": "dimensionless",
    "strain": "dimensionless",
    "stress": "Pa",
    "frequency": "Hz",
    "storage_modulus": "Pa",
    "loss_modulus": "Pa",
    "complex_modulus": "Pa",
    "tan_delta": "dimensionless",
    "linear_strain": "dimensionless",
    "volume_strain": "dimensionless",
}


@dataclass(frozen=True)
class ColumnSpec:
    """Where a quantity is in a table and its unit.

    Parameters
    ----------
    quantity : str
        A key of :data:`QUANTITIES`.
    column : int or str
        1-based column index, or the column's name in the header line.
    unit : str or None
        pint unit of the values in the file (``"ms"``, ``"mm"``, ``"bar"``, ``"degC"``);
        None: the unit the column's header name states (``"Zeit [ms]"``), a column whose
        header states none is refused.
    scale : float
        Factor applied before the unit conversion (e.g. −1 to flip a sign convention).
    """

    quantity: str
    column: int | str
    unit: str | None
    scale: float = 1.0


@dataclass
class Measurement:
    """A measured run: SI columns named by quantity (``time`` [s], ``position`` [m],
    ``friction`` [N], ``pressure`` [Pa gauge], ...; see :data:`QUANTITIES`).

    Parameters
    ----------
    name : str
        Label of the run.
    source : str
        The file it was read from (for messages).
    data : pandas.DataFrame
        One column per quantity, SI.
    conditions : dict
        Conditions not measured (``{"temperature": 293.15}``), SI.
    """

    name: str
    source: str
    data: pd.DataFrame
    conditions: dict[str, float] = field(default_factory=dict)

    def has(self, quantity: str) -> bool:
        return quantity in self.data.columns

    def column(self, quantity: str) -> np.ndarray:
        """A quantity as a float array; an InputError names the run if it is missing."""
        if quantity not in self.data.columns:
            raise InputError(f"measurement {self.name!r} ({self.source}): has no {quantity} "
                             f"column (it has {', '.join(self.data.columns)})")
        return self.data[quantity].to_numpy(dtype=float)

    @property
    def time(self) -> np.ndarray:
        return self.column("time")


def _si_factor(unit: str, quantity: str, where: str):
    """A function converting magnitudes in ``unit`` to the SI unit of ``quantity``."""
    if quantity not in QUANTITIES:
        raise InputError(f"{where}: unknown quantity {quantity!r}; choose from "
                         f"{', '.join(sorted(QUANTITIES))}")
    target = QUANTITIES[quantity]
    if re.search(r"(\*\*|\^)\s*\d{3,}", unit):
        raise InputError(f"{where}: unit {unit!r} has an exponent that is too large")
    if quantity == "speed" and re.search(r"hz|hertz", unit, re.IGNORECASE):
        raise InputError(f"{where}: unit {unit!r} is ambiguous for a rotational speed (pint "
                         "reads 1 Hz as 1 rad/s); use rpm, 1/min, rev/s or rad/s")

    def as_quantity(values):
        if quantity == "speed":  # 1/min, U/min are revolutions per minute (DIN 1301)
            return rotational_speed(values, unit)
        if quantity == "frequency":  # an angular frequency (rad/s, a rheometer's) is 2π f
            q = ureg.Quantity(values, unit)
            return cycles_per_time(q) if q.dimensionality == {"[time]": -1} else q
        return ureg.Quantity(values, unit)

    try:
        as_quantity(1.0).to(target)
    except pint.errors.DimensionalityError:
        raise InputError(f"{where}: unit {unit!r} is not a unit of {quantity} "
                         f"(expected something convertible to {target})") from None
    except Exception:
        raise InputError(f"{where}: unknown unit {unit!r} for {quantity} "
                         f"(e.g. {target!r})") from None

    def convert(values: np.ndarray) -> np.ndarray:
        return np.asarray(as_quantity(values).to(target).magnitude, dtype=float)
    return convert


def _split(line: str, delimiter: str | None) -> list[str]:
    cells = line.split() if delimiter is None else line.split(delimiter)
    return [_unquoted(cell.strip()) for cell in cells]


def _unquoted(cell: str) -> str:
    """A cell without the double quotes some exports put around every header name or value
    (``"Zeit [s]"``, ``"0.25"``)."""
    if len(cell) >= 2 and cell[0] == cell[-1] == '"':
        return cell[1:-1].strip()
    return cell


def _not_numbers(cells: list[str], decimal: str) -> bool:
    """Whether no cell of a row is a number (a units row, a second header line)."""
    for cell in cells:
        try:
            _number(cell, decimal)
            return False
        except ValueError:
            pass
    return True


_NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?|[-+]?(nan|inf|infinity)",
                     re.IGNORECASE)


def _number(cell: str, decimal: str) -> float:
    """A table cell as a float: plain decimal notation only (Python's float would also take
    ``20_0.1234`` as 200.1234)."""
    if decimal == ",":
        if "." in cell:  # a thousands separator, or a decimal point in a decimal-comma file
            raise ValueError(cell)
        cell = cell.replace(",", ".")
    if not _NUMBER.fullmatch(cell):
        raise ValueError(cell)
    return float(cell)


def _delimiter_hint(line: str, delimiter: str | None, cell: str = "", decimal: str = ".") -> str:
    """Why a header or a cell may not have split as meant: ';' as delimiter, decimal commas."""
    if delimiter != ";" and ";" in line:
        return ("; the line contains ';': set delimiter = ';' (and decimal = ',' if the numbers "
                "have decimal commas)")
    if delimiter not in ("\t", None) and "\t" in line:
        return "; the line contains tabs: set delimiter = '\\t'"
    if decimal == "." and re.fullmatch(r"[-+]?\d+,\d+", cell):
        return "; for decimal commas set decimal = ',' (with another delimiter, e.g. ';')"
    return ""


#: a unit at the end of a header name: "Zeit [s]", "F (N)", "Kraft in N", "t / ms"
_HEADER_UNIT = re.compile(r".*?(?:\[\s*(?P<b>[^\[\]]+?)\s*\]|\(\s*(?P<p>[^()]+?)\s*\)"
                          r"|\s+in\s+(?P<i>\S+)|\S\s*/\s*(?P<s>[^/\s]+(?:/[^/\s]+)?))\s*")


def header_unit(name: str) -> str | None:
    """The unit a header name states at its end, if it states one.

    Examples
    --------
    >>> [header_unit(n) for n in ("Zeit [ms]", "F (N)", "Kraft in kN", "t / s", "speed_rpm")]
    ['ms', 'N', 'kN', 's', None]
    """
    match = _HEADER_UNIT.fullmatch(name)
    if match is None:
        return None
    return next(u for u in match.group("b", "p", "i", "s") if u is not None)


def _unit_of(unit: str, quantity: str) -> bool:
    """Whether ``unit`` is a unit of ``quantity``."""
    try:
        _si_factor(unit, quantity, "")
    except InputError:
        return False
    return True


def _check_header_unit(name: str, spec: ColumnSpec, convert, where: str) -> None:
    """Refuse a column whose header states a unit that reads its numbers differently from the
    mapping's unit (a ``[ms]`` column mapped with ``unit = "s"``): a wrong number that looks
    right.  A header unit that is no unit of the quantity (a raw ``[V]`` channel, a word in
    brackets) is not checked."""
    unit = header_unit(name)
    if unit is None:
        return
    try:
        stated = _si_factor(unit, spec.quantity, where)
    except InputError:
        return
    probe = np.array([1.0, 10.0])
    if not np.allclose(stated(probe), convert(probe), rtol=1e-9, atol=0.0):
        si = QUANTITIES[spec.quantity]
        raise InputError(f"{where}: the header names the column {name!r}, in {unit!r}, but the "
                         f"column mapping says unit = {spec.unit!r} (a value 1 would be read as "
                         f"{convert(probe)[0]:.6g} {si}, not {stated(probe)[0]:.6g} {si}); set "
                         f"unit = {unit!r} if the header is right, or read the file without "
                         "its header (header = false, skip_rows = 1, column indices) if it is "
                         "not")


def _decoded(data: bytes, label: str) -> str:
    """The text of a table file: UTF-8 (with or without the byte-order mark some
    spreadsheets write), UTF-16 with its byte-order mark (Excel's "Unicode text"), else
    Windows-1252 (Latin-1), in which German loggers write "°C" or "µm" in their headers.
    Numbers are ASCII in all three: only header names depend on the guess."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        try:
            return data.decode("utf-16")
        except UnicodeDecodeError as exc:
            raise InputError(f"{label}: not UTF-16 text after its UTF-16 byte-order mark "
                             f"(byte {exc.start}); save it as UTF-8") from None
    if b"\x00" in data[:65536]:
        raise InputError(f"{label} is not a text file (it holds NUL bytes): give it as a "
                         "text table, e.g. CSV")
    try:
        return data.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as exc:
        try:
            return data.decode("cp1252")
        except UnicodeDecodeError:
            line = data[:exc.start].count(b"\n") + 1
            raise InputError(f"{label}, row {line}: byte 0x{data[exc.start]:02x} is neither "
                             "UTF-8 nor Windows-1252 text; save the file as UTF-8") from None


def read_table(path: str | Path, columns: list[ColumnSpec], *, delimiter: str | None = None,
               header: bool = False, skip_rows: int = 0, comment: str = "#",
               name: str | None = None, index: str | None = "time",
               decimal: str = ".", min_rows: int = 3,
               what: str = "measurement file", index_may_repeat: bool = False,
               header_units: Mapping[str, str] | None = None) -> Measurement:
    """Read a text table of numbers with a column mapping (see the module docstring).

    Parameters
    ----------
    path : path
        The file.
    columns : list of ColumnSpec
        Which quantities to read; ``time`` is required.
    delimiter : str, optional
        Column separator (``","``, ``";"``, ``"\\t"``); None: any whitespace.
    header : bool
        The first line after ``skip_rows`` names the columns.
    skip_rows : int
        Lines to skip at the top (start-up samples, preambles).
    comment : str
        Lines starting with this are ignored.
    name : str, optional
        Label of the run (default: the file stem).
    index : str or None
        The quantity that must be present and strictly increasing (``"time"``); None for
        tables without one (a stress-strain curve, a DMA table).
    decimal : {".", ","}
        Decimal separator of the numbers (``","``: ``0,25``; then the delimiter must be
        another character, e.g. ``";"``).
    min_rows : int
        Fewest data rows the table must have (a measurement 3, a duty cycle 2).
    what : str
        What the file is, for the messages about the file itself (missing, too large).
    index_may_repeat : bool
        The index may repeat a value (a jump of a piecewise-linear profile: two rows at one
        time); it must still not decrease.
    header_units : mapping, optional
        Header names that state their column's unit without brackets (``{"time_s": "s"}``),
        for columns whose unit comes from the header (``ColumnSpec.unit`` None).

    Returns
    -------
    Measurement

    Raises
    ------
    InputError
        Missing file, a cell that is not a finite number (file, row, column named; digits
        grouped with ``_`` are refused, not joined), a missing column, an index (time) that
        does not increase, a temperature at or below absolute zero, fewer than
        ``min_rows`` rows, a column without a unit.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "run.csv"
    >>> _ = f.write_text("t,x,F\\n0,0,1.5\\n10,0.1,1.6\\n20,0.2,1.4\\n")
    >>> m = read_table(f, [ColumnSpec("time", "t", "ms"), ColumnSpec("position", "x", "mm"),
    ...                    ColumnSpec("friction", "F", "N")], delimiter=",", header=True)
    >>> m.data["time"].tolist(), m.data["position"].tolist()
    ([0.0, 0.01, 0.02], [0.0, 0.0001, 0.0002])
    """
    path = Path(path)
    label = str(path)
    text = _decoded(read_input_bytes(path, what, MAX_DATA_BYTES), label)
    if index is not None and index not in {c.quantity for c in columns}:
        raise InputError(f"{label}: the column mapping needs a {index} column")
    if decimal not in (".", ","):
        raise InputError(f"{label}: decimal must be '.' or ',', got {decimal!r}")
    if decimal == "," and delimiter in (None, ","):
        raise InputError(f"{label}: decimal = ',' needs another column delimiter, e.g. "
                         "delimiter = ';'")
    lines = [(k + 1, line) for k, line in enumerate(text.splitlines())]
    lines = lines[skip_rows:]
    lines = [(n, s) for n, s in lines if s.strip() and not s.lstrip().startswith(comment)]
    names: list[str] = []
    header_line = ""
    if header:
        if not lines:
            raise InputError(f"{label}: no header line found")
        names = _split(lines[0][1], delimiter)
        header_row, header_line = lines[0]
        lines = lines[1:]
    if len(lines) < min_rows:
        raise InputError(f"{label}: only {len(lines)} data rows; it needs at least {min_rows}")
    if header and delimiter is None and len(names) != len(_split(lines[0][1], None)):
        # split at blanks, "Zeit [s]" is two names: every name after it points one column off
        if any(isinstance(spec.column, str) for spec in columns):
            raise InputError(f"{label}, row {header_row}: the header line {header_line!r} has "
                             f"{len(names)} names split at blanks, the rows have "
                             f"{len(_split(lines[0][1], None))} columns; header names with "
                             "spaces need the file's delimiter, e.g. delimiter = '\\t' or ';'")
        names = []  # not aligned with the columns: no unit checks against it
    indices = []
    for spec in columns:
        where = f"{label}, column {spec.column!r} ({spec.quantity})"
        if isinstance(spec.column, str):
            if spec.column not in names:
                raise InputError(f"{where}: no column named {spec.column!r}"
                                 + (f"; the header has {', '.join(map(repr, names))}" if names
                                    else "; set header = true or give a 1-based column index")
                                 + _delimiter_hint(header_line, delimiter))
            indices.append(names.index(spec.column))
        else:
            if spec.column < 1:
                raise InputError(f"{where}: column indices start at 1")
            indices.append(spec.column - 1)
    values = np.empty((len(lines), len(columns)))
    for r, (lineno, line) in enumerate(lines):
        cells = _split(line, delimiter)
        for c, (idx, spec) in enumerate(zip(indices, columns)):
            if idx >= len(cells):
                raise InputError(f"{label}, row {lineno}: has {len(cells)} columns, column "
                                 f"{idx + 1} ({spec.quantity}) is missing"
                                 + _delimiter_hint(line, delimiter))
            try:
                value = _number(cells[idx], decimal)
            except ValueError:
                # a wrong delimiter first: it also makes a row look like a header or units row
                hint = _delimiter_hint(line, delimiter, cells[idx], decimal)
                if hint:
                    pass
                elif names and cells[:len(names)] == names:
                    hint = ("; the row repeats the header line (a logger restarted?): remove "
                            "it, or split the file there")
                elif header and r == 0 and _not_numbers(cells, decimal):
                    hint = (f"; a units row under the header? Read the file with header = "
                            f"false, skip_rows = {lineno} and 1-based column indices")
                raise InputError(f"{label}, row {lineno}, column {idx + 1} ({spec.quantity}): "
                                 f"{cells[idx]!r} is not a number{hint}") from None
            if not math.isfinite(value):
                raise InputError(f"{label}, row {lineno}, column {idx + 1} ({spec.quantity}): "
                                 f"{cells[idx]!r} is not a finite number")
            values[r, c] = value
    data = {}
    for c, spec in enumerate(columns):
        unit, from_header = spec.unit, spec.unit is None
        if from_header:  # the unit the header states
            named = names[indices[c]] if indices[c] < len(names) else None
            unit = None if named is None else (
                (header_units or {}).get(named) or header_unit(named))
            if unit is None:
                stated = (f"its header {named!r} states none" if named is not None
                          else "the file has no header line")
                fitting = [n for n, u in (header_units or {}).items()
                           if _unit_of(u, spec.quantity)]
                also = f", or name the column {' or '.join(map(repr, fitting))}" if fitting else ""
                raise InputError(f"{label}, column {indices[c] + 1} ({spec.quantity}): no unit "
                                 f"is given and {stated}; write it in the header, e.g. "
                                 f"'{spec.quantity} [{QUANTITIES[spec.quantity]}]'{also}")
            spec = ColumnSpec(spec.quantity, spec.column, unit, spec.scale)
        convert = _si_factor(unit, spec.quantity, f"{label}, column {spec.column!r}")
        if not from_header and indices[c] < len(names):
            _check_header_unit(names[indices[c]], spec, convert,
                               f"{label}, column {indices[c] + 1} ({spec.quantity})")
        data[spec.quantity] = convert(values[:, c] * spec.scale)
        if QUANTITIES[spec.quantity] == "K":  # an absolute temperature
            cold = np.flatnonzero(~(data[spec.quantity] > 0))
            if cold.size:
                r = int(cold[0])
                raise InputError(f"{label}, row {lines[r][0]}, column {indices[c] + 1} "
                                 f"({spec.quantity}): {values[r, c]:g} {spec.unit} is "
                                 f"{data[spec.quantity][r]:.6g} K, not above absolute zero; "
                                 "check the column's unit")
    if index is not None:
        c = [spec.quantity for spec in columns].index(index)
        step = np.diff(data[index])
        bad = np.flatnonzero(step < 0 if index_may_repeat else step <= 0)
        if bad.size:
            r = int(bad[0]) + 1
            rule = "must not decrease" if index_may_repeat else "must be strictly increasing"
            raise InputError(f"{label}, row {lines[r][0]}, column {indices[c] + 1} ({index}): "
                             f"{index} {values[r, c]:g} after {values[r - 1, c]:g} in the "
                             f"previous row; the {index} column {rule}")
    return Measurement(name or path.stem, label, pd.DataFrame(data))
