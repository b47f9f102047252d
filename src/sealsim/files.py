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

:class:`ResultTarget` is what every result of a command shares -- the lock next to it, the
parent folders a run creates, SIGTERM as an exception while it computes, Ctrl-C held back
while the result is moved into place; :class:`sealsim.output.ResultFolder` (a folder of
results) and :class:`ResultFile` (one file: an FMU, which :mod:`sealsim.fmu` writes below the
output layer) are built on it.
"""

from __future__ import annotations

import errno
import math
import os
import re
import secrets
import shutil
import signal
import stat
import tempfile
import threading
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import numpy as np

from sealsim.errors import (
    InputError,
    OutputError,
    ResultBusyError,
    ResultExistsError,
    Terminated,
)

__all__ = ["CF_CONVENTIONS", "JSON_DIGITS", "MAX_CASE_BYTES", "MAX_DATA_BYTES", "USER_UMASK",
           "ResultFile", "ResultTarget", "atomic_write_bytes", "atomic_write_text",
           "check_input_file", "committed_folders", "file_digests", "interrupted_work_left",
           "json_ready", "netcdf_ready", "os_error_reason", "raise_terminated",
           "read_input_bytes", "read_input_text", "resume_refused", "scratch_folder"]

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


# -- work folders of long work that resumes (studies, fits) -------------------------------------
def file_digests(paths: Iterable[str | Path]) -> dict[str, str]:
    """``{path: sha256 of its content}`` of the files a run reads, part of the fingerprint of
    its work folder (a folder or a missing file is left out: its reader names it).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "cycle.csv"
    >>> _ = f.write_text("time_s,speed_rpm")
    >>> digests = file_digests([f, f.parent / "missing.csv"])
    >>> list(digests) == [str(f)], len(digests[str(f)])
    (True, 64)
    """
    import hashlib

    return {str(p): hashlib.sha256(read_input_bytes(p, "file", MAX_DATA_BYTES)).hexdigest()
            for p in paths if Path(p).is_file()}


def interrupted_work_left(kind: str, items: str, found: int, folder: str | Path) \
        -> ResultExistsError:
    """The refusal of a run that finds the finished ``items`` of an interrupted ``kind`` (a
    study, a fit) in its work folder without ``--resume`` or ``--force``."""
    return ResultExistsError(
        f"an interrupted {kind} left {found} finished {items} in {str(folder)!r}; pass "
        f"--resume to continue it (only the missing {items} are computed) or --force to "
        "start over")


def resume_refused(kind: str, items: str, found: int, folder: str | Path, old: dict,
                   files: dict[str, str], otherwise: str = "") -> InputError:
    """The refusal of ``--resume`` when the work folder's fingerprint is not the run's: names
    the input files whose content changed since (``old["files"]`` against ``files``, both
    :func:`file_digests`), else says ``otherwise``."""
    before = old.get("files") or {}
    changed = sorted(p for p in {*before, *files} if before.get(p) != files.get(p))
    why = f"; changed since: {', '.join(map(repr, changed))}" if changed else otherwise
    return InputError(
        f"cannot resume: the {found} finished {items} in {str(folder)!r} belong to another "
        f"{kind} or to an earlier version of this one ({old.get('source', 'unknown source')})"
        f"{why}; run it without --resume and with --force to start over")


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


@contextmanager
def scratch_folder(prefix: str) -> Iterator[Path]:
    """A private temporary folder (in ``tempfile.gettempdir()``), removed with its contents on
    leaving the ``with`` block, also when Ctrl-C or SIGTERM (:class:`~sealsim.errors.
    Terminated`) arrives while it is being made.

    :class:`tempfile.TemporaryDirectory` leaves its folder behind if the exception arrives
    between the folder's creation and the registration of its clean-up (seen: a SIGTERM sent
    as soon as an FMU build's scratch folder appeared, about once in 40 test runs); here the
    name is known before the folder exists, so the ``finally`` always knows what to remove.

    Examples
    --------
    >>> with scratch_folder("sealsim-doc-") as folder:
    ...     _ = (folder / "a.txt").write_text("x")
    >>> folder.exists()
    False
    """
    base = tempfile.gettempdir()
    path = None
    try:
        for _ in range(100):  # as tempfile.mkdtemp: a new random name if the name is taken
            path = os.path.join(base, prefix + secrets.token_hex(6))
            try:
                os.mkdir(path, 0o700)
                break
            except FileExistsError:
                path = None
        if path is None:  # pragma: no cover - 100 random names taken
            raise FileExistsError(errno.EEXIST, "no unused temporary folder name", base)
        yield Path(path)
    finally:
        if path is not None:
            shutil.rmtree(path, ignore_errors=True)


# -- result targets: the one write mechanism of results (see sealsim.output) ---------------------
#: every result folder or file committed by this process, in order (see
#: :func:`committed_folders`)
_COMMITTED: list[Path] = []


def committed_folders() -> tuple[Path, ...]:
    """Result folders (and files) this process has committed so far (oldest first).

    The CLI uses it to say truthfully, after Ctrl-C, whether the new results were written.
    """
    return tuple(_COMMITTED)


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # exists, owned by someone else
        return True
    return True


def _in_main_thread() -> bool:
    return threading.current_thread() is threading.main_thread()


def os_error_reason(exc: OSError) -> str:
    """The short reason of an OS error ('No space left on device')."""
    return exc.strerror or errno.errorcode.get(exc.errno or 0, "") or str(exc)


class ResultTarget:
    """What a result folder and a result file share: the target as given and as resolved, the
    lock next to it (``.NAME.lock``), the parent folders a run creates (removed again if it
    fails), SIGTERM raising :class:`~sealsim.errors.Terminated` while the run computes, and
    Ctrl-C/SIGTERM held back while the results are moved into place."""

    #: how messages name the target
    kind = "output folder"

    def __init__(self, path: str | Path, force: bool):
        self.requested = Path(path)
        self.path = Path(path).resolve()  # through links: stage next to the real target
        self.force = force
        self.committed = False
        self._lock_fd: int | None = None
        self._old_sigterm = None
        self._created: list[Path] = []

    def _shown(self, name: str = "") -> str:
        return str(self.requested / name) if name else str(self.requested)

    def _check_parent(self) -> None:
        """The nearest existing parent is a folder this process may write."""
        shown = self._shown()
        existing = self.path.parent
        while not existing.exists():
            existing = existing.parent
        if not existing.is_dir():
            raise InputError(f"cannot create {self.kind} {shown!r}: {str(existing)!r} is a "
                             "file")
        if not os.access(existing, os.W_OK | os.X_OK):
            raise InputError(f"cannot write {self.kind} {shown!r}: no write permission in "
                             f"{str(existing)!r} (or a read-only file system)")

    def _open(self) -> None:
        """Entering the ``with`` block: create the parent folders, take the lock."""
        parent = self.path.parent
        self._created = [p for p in (parent, *parent.parents) if not p.exists()]
        try:
            parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise InputError(f"cannot create {self.kind} {self._shown()!r}: "
                             f"{exc.strerror or exc}") from exc
        try:
            self._lock()
        except BaseException:
            self._remove_created()
            raise

    def _sigterm_raises(self) -> None:
        """SIGTERM raises Terminated while the run computes (so its clean-up runs)."""
        if _in_main_thread() and signal.getsignal(signal.SIGTERM) is signal.SIG_DFL:
            self._old_sigterm = signal.signal(signal.SIGTERM, raise_terminated)

    def _abandon(self) -> None:
        """The run failed: release the lock, remove the (empty) parent folders it created."""
        self._release()
        self._remove_created()

    def _remove_created(self) -> None:
        """Remove the (still empty) parent folders this run created: a failed run leaves no
        trace."""
        for folder in self._created:
            try:
                folder.rmdir()
            except OSError:
                break

    def _finish(self, commit: Callable[[], None]) -> None:
        """Run ``commit`` (the renames into place) with Ctrl-C and SIGTERM held back until it
        is done, release the lock, then act on a held-back signal."""
        if not _in_main_thread():  # signals reach Python in the main thread only
            try:
                commit()
            finally:
                self._release()
            return
        deferred: list[int] = []
        handlers = {sig: signal.signal(sig, lambda signum, frame: deferred.append(signum))
                    for sig in (signal.SIGINT, signal.SIGTERM)}
        try:
            commit()
        finally:
            for sig, handler in handlers.items():
                signal.signal(sig, handler)
            self._release()
            for signum in deferred[:1]:
                handler = handlers[signum]
                if callable(handler):
                    handler(signum, None)
                elif handler == signal.SIG_DFL:
                    raise Terminated("SIGTERM") if signum == signal.SIGTERM \
                        else KeyboardInterrupt

    def _committed(self) -> None:
        self.committed = True
        _COMMITTED.append(self.path)

    def _release(self) -> None:
        if self._old_sigterm is not None:
            signal.signal(signal.SIGTERM, self._old_sigterm)
            self._old_sigterm = None
        self._unlock()

    def _lock_path(self) -> Path:
        return self.path.with_name(f".{self.path.name}.lock")

    def _lock(self) -> None:
        import fcntl

        path = self._lock_path()
        while True:
            try:
                fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o666 & ~USER_UMASK)
            except OSError as exc:
                raise InputError(f"cannot create the lock file {str(path)!r} of {self.kind} "
                                 f"{self._shown()!r}: {exc.strerror or exc}") from exc
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                owner = os.read(fd, 32).decode("ascii", "replace").strip()
                os.close(fd)
                raise ResultBusyError(
                    f"{self.kind} {self._shown()!r} is being written by another sealsim run"
                    + (f" (process {owner})" if owner else "")
                    + "; wait for it to finish or choose another "
                    + self.kind.split()[-1]) from None
            # the holder before us may have removed the file after we opened it: retry then
            try:
                same = os.stat(path).st_ino == os.fstat(fd).st_ino
            except FileNotFoundError:
                same = False
            if same:
                break
            os.close(fd)
        os.ftruncate(fd, 0)
        os.write(fd, str(os.getpid()).encode())
        self._lock_fd = fd

    def _unlock(self) -> None:
        if self._lock_fd is not None:
            self._lock_path().unlink(missing_ok=True)  # while still holding it (see _lock)
            os.close(self._lock_fd)
            self._lock_fd = None

    def _stale(self, suffix: str) -> Iterator[Path]:
        """Entries ``.NAME.PID.<suffix>`` next to the target left by processes that died."""
        pattern = re.compile(rf"\.{re.escape(self.path.name)}\.(\d+)\.(?:{suffix})")
        for entry in self.path.parent.iterdir():
            match = pattern.fullmatch(entry.name)
            if match and int(match[1]) != os.getpid() and not _pid_alive(int(match[1])):
                yield entry


class ResultFile(ResultTarget):
    """One result file (an FMU) written all-or-nothing, locked against concurrent runs: the
    guarantees of :class:`ResultFolder` for a result that is a single file.

    * the target is checked when the object is made, before any computing: a name without
      ``suffix``, a folder in its place, one of the run's input files (writing would replace
      it) and a parent that cannot be written are refused (:class:`~sealsim.errors.InputError`),
      an existing file unless ``force`` (:class:`~sealsim.errors.ResultExistsError`);
    * entering the ``with`` block takes the lock ``.NAME.lock`` (a second run to the same file
      is refused, :class:`~sealsim.errors.ResultBusyError`) and removes temporary files of
      processes that died;
    * :meth:`write_bytes` stages the content in a hidden temporary file
      ``.NAME.PID.XXXXXXXX.tmp`` next to the target; only when the block ends without an error
      does it become the target (without ``force`` as a new link, so that a file that appeared
      meanwhile is never overwritten; with ``force`` by a rename that replaces the file that
      was there when the object was made -- one written by another run meanwhile is refused).
      Ctrl-C and SIGTERM are held back while this happens; a failed or interrupted run leaves
      the target as it was and no temporary file behind.

    Parameters
    ----------
    path : str or Path
        The file.
    force : bool
        Replace an existing file.
    inputs : iterable of path-like
        Files the run reads: refused as the target.
    suffix : str
        Required ending of the file name (e.g. ``".fmu"``); ``""``: any name.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "model.fmu"
    >>> with ResultFile(out, suffix=".fmu") as result:
    ...     _ = result.write_bytes(b"PK")
    >>> out.read_bytes(), sorted(p.name for p in out.parent.iterdir())
    (b'PK', ['model.fmu'])
    >>> try:
    ...     ResultFile(out)
    ... except ResultExistsError as err:
    ...     print(str(err).endswith("use --force to replace it"))
    True
    """

    kind = "output file"

    def __init__(self, path: str | Path, force: bool = False, inputs: Iterable[str | Path] = (),
                 suffix: str = ""):
        super().__init__(path, force)
        self._staged: Path | None = None
        self._check_location(inputs, suffix)
        self._at_start = self._identity()

    def _check_location(self, inputs: Iterable[str | Path], suffix: str) -> None:
        shown = self._shown()
        if suffix and self.requested.suffix.lower() != suffix.lower():
            raise InputError(f"output file {shown!r}: the file name must end in {suffix} "
                             f"(e.g. --out result{suffix})")
        if self.path.is_dir():
            raise InputError(f"output file {shown!r} is a folder; give the name of the file")
        for item in inputs:
            if Path(item).resolve() == self.path:
                raise InputError(f"output file {shown!r} is an input of the run; writing the "
                                 "result would replace it: choose another file name")
        if self.path.exists() and not self.force:
            raise ResultExistsError(f"{shown!r} already exists; use --force to replace it")
        self._check_parent()

    def _identity(self) -> tuple[int, int] | None:
        """Which file the target is: (device, inode), None if there is none."""
        try:
            st = self.path.stat()
        except FileNotFoundError:
            return None
        return st.st_dev, st.st_ino

    def __enter__(self) -> ResultFile:
        self._open()
        try:
            for entry in list(self._stale(r"[a-z0-9_]{8}\.tmp")):
                entry.unlink(missing_ok=True)
            if self._identity() != self._at_start:
                raise ResultExistsError(
                    f"{self._shown()!r} was written by another run after this one started; "
                    "--force replaces only the file that existed when a run started: check "
                    "it, then run again")
            self._sigterm_raises()
        except BaseException:
            self._abandon()
            raise
        return self

    def write_bytes(self, data: bytes) -> Path:
        """Stage the file's content (written to the target when the block ends)."""
        if self._lock_fd is None:
            raise RuntimeError("ResultFile is written outside its 'with' block")
        self._discard()
        try:
            fd, tmp = tempfile.mkstemp(dir=self.path.parent, suffix=".tmp",
                                       prefix=f".{self.path.name}.{os.getpid()}.")
            self._staged = Path(tmp)
            with os.fdopen(fd, "wb") as fh:
                fh.write(data)
                fh.flush()
                os.fsync(fh.fileno())
            os.chmod(tmp, 0o666 & ~USER_UMASK)
        except OSError as exc:
            self._discard()
            raise OutputError(f"cannot write {self._shown()!r}: {os_error_reason(exc)}; nothing "
                              "was written") from exc
        return self._staged

    def _discard(self) -> None:
        if self._staged is not None:
            self._staged.unlink(missing_ok=True)
            self._staged = None

    def __exit__(self, exc_type, exc, tb) -> None:
        if exc_type is not None or self._staged is None:
            self._discard()
            self._abandon()
            return
        self._finish(self._commit)

    def _commit(self) -> None:
        staged, shown = self._staged, self._shown()
        try:
            if self.force:
                os.replace(staged, self.path)
            else:
                try:
                    os.link(staged, self.path)    # fails if the file appeared meanwhile
                except FileExistsError:
                    raise ResultExistsError(f"{shown!r} already exists; use --force to "
                                            "replace it") from None
                except OSError:                   # a file system without hard links
                    if self.path.exists():
                        raise ResultExistsError(f"{shown!r} already exists; use --force to "
                                                "replace it") from None
                    os.replace(staged, self.path)
        except OSError as exc:
            if isinstance(exc, ResultExistsError):
                raise
            raise OutputError(f"cannot move the result into {shown!r}: {os_error_reason(exc)}; "
                              "nothing was written") from exc
        finally:
            self._discard()
        self._committed()
