"""Readers of rig measurements: the text tables of :mod:`sealsim.tables` (a column mapping of
quantities and units per file) and named readers of known rigs.

Named readers (:data:`FORMATS`):

* ``"tudelft"`` -- the pneumatic piston-seal friction rig of Zillen, Vallery & Smit (TU Delft
  2021, CC0): whitespace columns time [ms], laser [V], pressure [V], force [V], position [mm],
  pressure [bar gauge], rod force [N].  The friction force on the piston is
  ``p·A − F_rod`` (source convention), returned with sealsim's sign: the force the seal
  resists the motion with, positive when the velocity is positive
  (:func:`read_tudelft`).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from sealsim.errors import InputError
from sealsim.tables import QUANTITIES, ColumnSpec, Measurement, read_table
from sealsim.units import to_si

__all__ = [
    "FORMATS",
    "QUANTITIES",
    "ColumnSpec",
    "Measurement",
    "read_measurement",
    "read_table",
    "read_tudelft",
]


def read_tudelft(path: str | Path, bore: float, skip_rows: int = 15,
                 name: str | None = None) -> Measurement:
    """Read a raw file of the TU Delft pneumatic friction rig (Zillen et al. 2021).

    Columns (whitespace, no header): time [ms], laser [V], pressure [V], force [V],
    position [mm], pressure [bar gauge], rod force [N].  The friction force on the piston is

    .. math:: F_f = -(p\\,A - F_{rod}), \\qquad A = \\pi D^2/4

    with the sign flipped with respect to the source so that it is sealsim's convention (the
    force resisting the motion, the sign of the velocity): in the source's files the friction
    p·A − F_rod is negative while the position increases.

    Parameters
    ----------
    path : path
        One of the rig's ``*.csv`` files.
    bore : float
        Bore diameter D [m] (25 mm or 25.7 mm for the files of the data set).
    skip_rows : int
        Start-up samples at the top of the file (the data set's README: about 15).
    name : str, optional
        Label of the run.

    Returns
    -------
    Measurement
        Columns ``time`` [s], ``position`` [m], ``pressure`` [Pa gauge], ``force`` (rod) [N],
        ``friction`` [N].

    References
    ----------
    E. Zillen, H. Vallery, G. Smit, "3D printed pneumatic actuator", TU Delft, 2021, data
    repository EvaZillen/3D-printed-pneumatic-actuator, CC0 1.0.
    """
    if not (bore > 0 and math.isfinite(bore)):
        raise InputError(f"tudelft reader: bore must be > 0, got {bore!r} m")
    m = read_table(path, [ColumnSpec("time", 1, "ms"), ColumnSpec("position", 5, "mm"),
                          ColumnSpec("pressure", 6, "bar"), ColumnSpec("force", 7, "N")],
                   skip_rows=skip_rows, name=name)
    area = math.pi * bore ** 2 / 4.0
    m.data["friction"] = m.data["force"] - m.data["pressure"] * area
    return m


#: named rig formats: name -> (reader, required options with their dimension)
FORMATS: dict[str, tuple[Any, dict[str, str]]] = {
    "tudelft": (read_tudelft, {"bore": "length"}),
}


def read_measurement(path: str | Path, *, format: str | None = None,  # noqa: A002
                     columns: list[ColumnSpec] | None = None, options: dict | None = None,
                     name: str | None = None, **table_options) -> Measurement:
    """Read a measurement with a named format or a column mapping.

    Parameters
    ----------
    path : path
        The file.
    format : str, optional
        A key of :data:`FORMATS` (``"tudelft"``); its options (SI) in ``options``.
    columns : list of ColumnSpec, optional
        Column mapping for :func:`read_table` (when no format is given).
    options : dict, optional
        Options of the named format, quantities with their unit or SI numbers, e.g.
        ``{"bore": "25 mm"}`` or ``{"bore": 0.025}``.
    name : str, optional
        Label of the run.
    **table_options
        ``delimiter``, ``header``, ``skip_rows``, ``comment`` of :func:`read_table`.
    """
    if (format is None) == (columns is None):
        raise InputError(f"measurement {str(path)!r}: give exactly one of format = "
                         f"{' | '.join(repr(k) for k in FORMATS)} or a columns mapping")
    if format is not None:
        if format not in FORMATS:
            raise InputError(f"measurement {str(path)!r}: unknown format {format!r}; choose "
                             f"one of {', '.join(repr(k) for k in FORMATS)} or give columns")
        reader, required = FORMATS[format]
        options = dict(options or {})
        missing = [k for k in required if k not in options]
        if missing:
            raise InputError(f"measurement {str(path)!r}: format {format!r} needs "
                             f"{', '.join(missing)} (e.g. bore = '25 mm')")
        for key, dimension in required.items():
            options[key] = to_si(options[key], dimension, f"measurement {str(path)!r}: {key}")
        return reader(path, name=name, **options,
                      **{k: v for k, v in table_options.items() if k == "skip_rows"})
    return read_table(path, columns, name=name, **table_options)
