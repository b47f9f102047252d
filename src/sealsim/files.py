"""Safe file reading and writing for every layer: bounded reads of user files, atomic writes,
JSON-ready values.

:func:`read_input_bytes` (and :func:`read_input_text`) is how every loader reads a file a user
names -- case files, measurement and duty-cycle CSVs, material and oil files, FMU sources: only
regular files (a FIFO or ``/dev/zero`` would block or read until memory runs out), at most a
size limit, and every problem is one :class:`~sealsim.errors.InputError` naming the file.
Readers that hand a path to a library (netCDF maps, DXF drawings) check it first with
:func:`check_input_file`.

:func:`atomic_write_bytes` writes a temporary file in the target's folder and renames it into
place, so a reader never sees half a file and an interrupted write leaves the old file (or
none).  Result folders (:class:`sealsim.output.ResultFolder`) are built on it, and so are the
files written below the output layer: the FE map cache (:mod:`sealsim.pneumatic.contact_maps`)
and a study's work folder (:mod:`sealsim.studies.store`).
"""

from __future__ import annotations

import contextlib
import math
import os
import signal
import stat
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

from sealsim.errors import InputError, Terminated

__all__ = ["CF_CONVENTIONS", "JSON_DIGITS", "MAX_CASE_BYTES", "MAX_DATA_BYTES", "USER_UMASK",
           "atomic_write_bytes", "atomic_write_text", "check_input_file", "json_ready",
           "netcdf_ready", "raise_terminated", "read_input_bytes", "read_input_text",
           "sigterm_as_interrupt"]

#: The process's umask: mkstemp/mkdtemp create private (0600/0700) entries, written files get
#: the user's normal modes (0o666 & ~USER_UMASK).
USER_UMASK = os.umask(0)
os.umask(USER_UMASK)

#: significant digits of floats in result JSON files: enough for any model result, and
#: ``67.99999999999949`` is written as ``68.0``
JSON_DIGITS = 12


#: largest case file (TOML) sealsim reads [bytes]: the biggest example is 7 kB
MAX_CASE_BYTES = 16 * 2**20
#: largest data file (measurement or duty-cycle CSV, netCDF map, DXF drawing) [bytes]; a rig
#: logging 8 columns at 10 kHz for an hour writes about 300 MB
MAX_DATA_BYTES = 1024 * 2**20


def _size_text(n: int) -> str:
    return f"{n / 2**20:.3g} MB" if n >= 2**20 else f"{n} bytes"


def _file_kind(mode: int) -> str:
    for test, name in ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return name
    return "not a regular file"


def _check_stat(st: os.stat_result, shown: str, limit: int) -> None:
    if not stat.S_ISREG(st.st_mode):
        raise InputError(f"{shown} is {_file_kind(st.st_mode)}, not a regular file; give "
                         "the path of a file")
    if st.st_size > limit:
        raise InputError(f"{shown} is {_size_text(st.st_size)}, more than the "
                         f"{_size_text(limit)} sealsim reads from such a file; check that it "
                         "is the right file")


def _os_error(exc: OSError, shown: str) -> InputError:
    if isinstance(exc, FileNotFoundError):
        return InputError(f"{shown} does not exist")
    return InputError(f"{shown} cannot be read: {exc.strerror or exc}")


def check_input_file(path: str | Path, what: str, limit: int = MAX_DATA_BYTES,
                     label: str | None = None) -> Path:
    """``path`` if it is a regular file of at most ``limit`` bytes, else an
    :class:`~sealsim.errors.InputError` naming it (``what``: e.g. ``"map file"``; ``label``
    replaces ``what`` and the path in the message, e.g. ``"seal.dxf 'lip.dxf'"``).

    For files a library opens itself (netCDF, DXF); sealsim's own readers use
    :func:`read_input_bytes`, which checks the file it has opened.

    Examples
    --------
    >>> check_input_file("/dev/zero", "measurement file")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: measurement file '/dev/zero' is a character device, not a \
regular file; give the path of a file
    """
    path = Path(path)
    shown = label or f"{what} {str(path)!r}"
    try:
        st = os.stat(path)
    except OSError as exc:
        raise _os_error(exc, shown) from None
    _check_stat(st, shown, limit)
    return path


def read_input_bytes(path: str | Path, what: str, limit: int = MAX_CASE_BYTES) -> bytes:
    """The content of a user's file: a regular file of at most ``limit`` bytes.

    The file is opened without blocking (a FIFO does not wait for a writer) and checked
    before it is read; at most ``limit`` bytes are read, so a file that grows meanwhile
    cannot exhaust the memory either.

    Parameters
    ----------
    path : path-like
    what : str
        What the file is, for the message: ``"case file"``, ``"measurement file"``.
    limit : int
        Largest size in bytes (:data:`MAX_CASE_BYTES`, :data:`MAX_DATA_BYTES`).

    Raises
    ------
    InputError
        The file does not exist, is a folder, a FIFO or a device, is bigger than ``limit``,
        or cannot be read; the message names it.
    """
    path = Path(path)
    shown = f"{what} {str(path)!r}"
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except IsADirectoryError:
        raise InputError(f"{shown} is a folder, not a regular file; give the path of a "
                         "file") from None
    except OSError as exc:
        raise _os_error(exc, shown) from None
    try:
        _check_stat(os.fstat(fd), shown, limit)
        chunks, size = [], 0
        while size <= limit:
            chunk = os.read(fd, min(2**20, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    except OSError as exc:
        raise _os_error(exc, shown) from None
    finally:
        os.close(fd)
    if size > limit:
        raise InputError(f"{shown} is more than the {_size_text(limit)} sealsim reads from "
                         "such a file; check that it is the right file")
    return b"".join(chunks)


def read_input_text(path: str | Path, what: str, limit: int = MAX_CASE_BYTES,
                    encoding: str = "utf-8") -> str:
    """:func:`read_input_bytes` decoded; text that is not in ``encoding`` is an
    :class:`~sealsim.errors.InputError` naming the file and the byte.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "case.toml"
    >>> _ = f.write_text('title = "x"')
    >>> read_input_text(f, "case file")
    'title = "x"'
    """
    data = read_input_bytes(path, what, limit)
    try:
        return data.decode(encoding)
    except UnicodeDecodeError as exc:
        raise InputError(f"{what} {str(path)!r} is not UTF-8 text (byte {exc.start}); save it "
                         "as UTF-8") from None


def json_ready(value: Any, digits: int | None = None) -> Any:
    """Make results JSON-safe: numpy scalars become Python numbers, NaN/inf become None.

    JSON has no NaN; a missing value (e.g. no break-away in a run) is written as null.  With
    ``digits``, floats are rounded to that many significant digits (no ``0.30000000000000004``).

    Examples
    --------
    >>> import numpy as np
    >>> json_ready({"a": np.float64(1.5), "b": [float("nan"), np.int64(2)]})
    {'a': 1.5, 'b': [None, 2]}
    >>> json_ready([67.99999999999949, 1.0e-20 / 3], digits=12)
    [68.0, 3.33333333333e-21]
    """
    if isinstance(value, dict):
        return {k: json_ready(v, digits) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(v, digits) for v in value]
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, float | np.floating):
        if not math.isfinite(value):
            return None
        return float(f"{value:.{digits}g}") if digits else float(value)
    return value


#: the CF metadata conventions sealsim's netCDF files follow (``units``, ``long_name``)
CF_CONVENTIONS = "CF-1.8"


def netcdf_ready(dataset) -> tuple[Any, dict]:
    """A dataset and the encoding to write it with, as every netCDF file of sealsim is written:
    the global attribute ``Conventions = "CF-1.8"`` and no ``_FillValue`` on coordinates (a
    coordinate has no missing values; CF tools warn about a fill value there).

    Examples
    --------
    >>> import xarray as xr
    >>> ds, encoding = netcdf_ready(xr.Dataset({"F": ("T", [1.0, 2.0])}, coords={"T": [1, 2]}))
    >>> ds.attrs["Conventions"], encoding
    ('CF-1.8', {'T': {'_FillValue': None}})
    """
    dataset = dataset.assign_attrs(Conventions=CF_CONVENTIONS)
    return dataset, {str(name): {"_FillValue": None} for name in dataset.coords}


def atomic_write_bytes(path: str | Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` via a temporary file in the same folder and a rename."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, 0o666 & ~USER_UMASK)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def atomic_write_text(path: str | Path, text: str) -> Path:
    """Text variant of :func:`atomic_write_bytes` (UTF-8)."""
    return atomic_write_bytes(path, text.encode("utf-8"))


def raise_terminated(signum, frame):
    """SIGTERM handler: raise :class:`~sealsim.errors.Terminated`, so that the clean-up that
    runs for Ctrl-C (``finally`` blocks, context managers) runs for SIGTERM too."""
    raise Terminated("SIGTERM")


@contextlib.contextmanager
def sigterm_as_interrupt() -> Iterator[None]:
    """While the block runs, SIGTERM raises :class:`~sealsim.errors.Terminated` instead of
    ending the process at once (only in the main thread, and only where SIGTERM still has its
    default action: a handler someone installed is left alone)."""
    if threading.current_thread() is not threading.main_thread() \
            or signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL:
        yield
        return
    previous = signal.signal(signal.SIGTERM, raise_terminated)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)
