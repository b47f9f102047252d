"""Result folders that never lose data, and the run skeleton every writing command uses.

Every command that writes results does so through :class:`ResultFolder` -- most simply
through :func:`run_variants`, which adds the per-variant loop and progress reports:

* the output location is checked when the folder object is made, before any computing: an
  existing folder that holds files is refused unless ``force=True``
  (:class:`~sealsim.errors.ResultExistsError`); even with ``force``, a folder is replaced
  only if sealsim wrote it (it holds the marker file :data:`RESULT_MARKER` every committed
  result folder gets), so that a mistyped ``--out ~/Documents --force`` deletes nothing of
  the user's; refused are also a file in its place, a location
  that cannot be written, the current folder or one of its parents, and a folder that holds
  one of the run's input files;
* entering the ``with`` block takes an exclusive lock (``.NAME.lock`` next to the target,
  :func:`fcntl.flock`; it dies with the process), so a second run to the same folder is refused
  (:class:`~sealsim.errors.ResultBusyError`) instead of silently replacing the first one's
  results; ``force`` replaces only the results that existed when the run started;
* results are written into a hidden staging folder ``.NAME.PID.XXXXXXXX.partial`` next to the
  target, each file atomically (temporary name, then :func:`os.replace`), every file name
  checked by :meth:`ResultFolder.file` so that nothing is ever written outside the folder;
* only when the whole run succeeded is the staging folder moved into place (old results, with
  ``force``, are moved aside to ``.NAME.PID.old`` first and deleted afterwards; Ctrl-C and
  SIGTERM are held back until this is done).  A run that fails, is interrupted (Ctrl-C or
  SIGTERM) or cannot write (full disk: :class:`~sealsim.errors.OutputError` naming the file)
  leaves the target untouched and no half-written file behind;
* staging and backup folders of processes that died (SIGKILL, power loss) are removed by the
  next run to the same target -- a backup whose commit never happened is put back.

A command whose result is one file (``sealsim fmu build``) writes it through
:class:`ResultFile`, which gives the same guarantees (checked first, locked, staged next to
the target, moved into place only on success, never replacing a file without ``force``).
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import tempfile
import warnings
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any, TypeVar

from sealsim.errors import InputError, OutputError, ResultExistsError
# re-exported: the atomic writes, the result file and JSON conversion are part of the result API
from sealsim.files import (
    JSON_DIGITS,
    USER_UMASK,
    ResultFile,
    ResultTarget,
    atomic_write_bytes,
    atomic_write_text,
    committed_folders,
    json_ready,
    netcdf_ready,
    os_error_reason,
)

__all__ = ["JSON_DIGITS", "RESULT_MARKER", "ResultFile", "ResultFolder", "atomic_write_bytes",
           "atomic_write_text", "committed_folders", "json_ready", "run_variants"]

#: the file in every result folder sealsim commits: ``--force`` replaces only folders with it
RESULT_MARKER = ".sealsim-results"

class ResultFolder(ResultTarget):
    """A result folder written all-or-nothing, locked against concurrent runs.

    Parameters
    ----------
    path : str or Path
        Target folder.
    force : bool
        Replace a result folder sealsim wrote (:data:`RESULT_MARKER`) that already holds files
        (only the results that were there when this object was made: a folder committed
        meanwhile by another run is not replaced).
    inputs : iterable of path-like
        Files the run reads (the case file, a duty-cycle CSV): refused if they lie inside
        ``path``, where committing the results would delete them.

    Raises
    ------
    InputError
        Unusable location (a file, not writable, the current folder or a parent of it, holds
        an input file) -- when the object is made, i.e. before any computing.
    ResultExistsError
        ``path`` holds results and ``force`` is not set, or it holds files but no
        :data:`RESULT_MARKER` (sealsim did not write it: not even ``force`` replaces it).
    ResultBusyError
        (on entering) another run is writing to ``path``.
    OutputError
        (inside the block) a result file could not be written, e.g. the disk is full.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "run"
    >>> with ResultFolder(out) as folder:
    ...     _ = folder.write_text("note.txt", "hello")
    >>> (out / "note.txt").read_text()
    'hello'
    >>> try:
    ...     ResultFolder(out)
    ... except ResultExistsError as err:
    ...     print("refused:", "--force" in str(err))
    refused: True
    """

    def __init__(self, path: str | Path, force: bool = False, inputs: Iterable[str | Path] = ()):
        super().__init__(path, force)
        self._staging: Path | None = None
        self._check_location(inputs)
        self._at_start = self._identity()

    # -- checks before any computing -----------------------------------------------------------
    def _check_location(self, inputs: Iterable[str | Path]) -> None:
        shown = self._shown()
        cwd = Path.cwd().resolve()
        if self.path == cwd or self.path in cwd.parents or self.path.parent == self.path:
            raise InputError(f"output folder {shown!r} is the current folder or one of its "
                             "parents; give a new sub-folder, e.g. --out results/run")
        for item in inputs:
            item = Path(item).resolve()
            if self.path in item.parents:
                raise InputError(f"input file {str(item)!r} lies inside the output folder "
                                 f"{shown!r}; writing the results would delete it: choose "
                                 "another output folder or move the file")
        if self.path.exists() and not self.path.is_dir():
            raise InputError(f"output path {shown!r} is a file, expected a folder")
        self._check_parent()
        if self._holds_results():
            if not self.force:
                raise ResultExistsError(
                    f"output folder {shown!r} already holds results; "
                    "choose another folder or pass --force to replace them")
            if not (self.path / RESULT_MARKER).is_file():
                found = sorted(p.name for p in self.path.iterdir())
                raise ResultExistsError(
                    f"output folder {shown!r} was not written by sealsim (it holds "
                    f"{', '.join(map(repr, found[:3]))}{', ...' if len(found) > 3 else ''} "
                    f"and no {RESULT_MARKER} file); --force replaces only sealsim's result "
                    "folders, whose files it would delete: choose another folder, or empty "
                    "this one yourself")

    def _holds_results(self) -> bool:
        try:
            return self.path.is_dir() and any(self.path.iterdir())
        except OSError as exc:
            raise InputError(f"cannot read output folder {self._shown()!r}: "
                             f"{exc.strerror or exc}") from None

    def _identity(self) -> tuple[int, int] | None:
        """Which results the target holds: (device, inode) of a non-empty folder, else None."""
        if not self._holds_results():
            return None
        st = self.path.stat()
        return st.st_dev, st.st_ino

    # -- lock, staging, commit -------------------------------------------------------------------
    @property
    def staging(self) -> Path:
        if self._staging is None:
            raise RuntimeError("ResultFolder is used outside its 'with' block")
        return self._staging

    def __enter__(self) -> ResultFolder:
        self._open()
        try:
            if self._clean_stale():
                raise ResultExistsError(
                    f"output folder {self._shown()!r} was restored: an earlier run was killed "
                    "while replacing it; check the results, then run again (with --force to "
                    "replace them)")
            if self._identity() != self._at_start:
                raise ResultExistsError(
                    f"output folder {self._shown()!r} was written by another run after this "
                    "one started; --force replaces only the results that existed when a run "
                    "started: check them, then run again")
            try:
                self._staging = Path(tempfile.mkdtemp(
                    dir=self.path.parent, prefix=f".{self.path.name}.{os.getpid()}.",
                    suffix=".partial"))
                os.chmod(self._staging, 0o777 & ~USER_UMASK)
            except OSError as exc:
                raise InputError(f"cannot create output folder {self._shown()!r}: "
                                 f"{exc.strerror or exc}") from exc
            self._sigterm_raises()
        except BaseException:
            self._abandon()
            raise
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        staging, self._staging = self._staging, None
        if exc_type is not None:
            shutil.rmtree(staging, ignore_errors=True)
            self._abandon()
            return
        self._finish(lambda: self._commit(staging))

    def _commit(self, staging: Path) -> None:
        backup = None
        try:
            atomic_write_text(staging / RESULT_MARKER,
                              "Written by sealsim: --force may replace this folder.\n")
            if self.path.exists():
                backup = self.path.with_name(f".{self.path.name}.{os.getpid()}.old")
                os.replace(self.path, backup)
            try:
                os.replace(staging, self.path)
            except OSError:
                if backup is not None:
                    os.replace(backup, self.path)
                raise
        except OSError as exc:
            shutil.rmtree(staging, ignore_errors=True)
            raise OutputError(f"cannot move the results into {self._shown()!r}: "
                              f"{exc.strerror or exc}; the folder is unchanged") from exc
        self._committed()
        if backup is not None:
            shutil.rmtree(backup, ignore_errors=True)

    def _clean_stale(self) -> bool:
        """Remove staging/backup folders of dead processes (we hold the target's lock).

        Returns True if old results were put back (a run died between moving them aside and
        committing its own)."""
        restored = False
        for entry in list(self._stale(r"[a-z0-9_]{8}\.partial|old")):
            if entry.name.endswith(".old") and not self.path.exists():
                os.replace(entry, self.path)  # died before its commit: the old results return
                restored = True
            else:
                shutil.rmtree(entry, ignore_errors=True)
        return restored

    # -- writers -------------------------------------------------------------------------
    def file(self, name: str) -> Path:
        """Path of result file ``name`` (e.g. ``"variant/summary.json"``) in the staging folder.

        Every writer builds its path here: a name that is empty, absolute, contains ``..`` or
        would lead through a symbolic link out of the folder is refused, so that nothing is
        ever written outside it.
        """
        root = self.staging
        parts = Path(name).parts
        if (not name or "\x00" in name or Path(name).is_absolute() or ".." in parts
                or "\\" in name):
            raise InputError(f"result file name {name!r} would leave the result folder")
        target = root / name
        real_root = root.resolve()
        if not target.parent.resolve().is_relative_to(real_root):
            raise InputError(f"result file name {name!r} would leave the result folder")
        with self._writing(name):
            target.parent.mkdir(parents=True, exist_ok=True)
        if target.is_symlink() or not target.parent.resolve().is_relative_to(real_root):
            raise InputError(f"result file name {name!r} would leave the result folder")
        return target

    @contextlib.contextmanager
    def _writing(self, name: str) -> Iterator[None]:
        """An OSError (no space left, quota, I/O error) becomes one OutputError naming the file."""
        try:
            yield
        except OSError as exc:
            if isinstance(exc, OutputError):
                raise
            raise OutputError(f"cannot write result file {self._shown(name)!r}: "
                              f"{os_error_reason(exc)}; "
                              f"nothing was written, {self._shown()!r} is unchanged") from exc

    def write_bytes(self, name: str, data: bytes) -> Path:
        target = self.file(name)
        with self._writing(name):
            return atomic_write_bytes(target, data)

    def write_text(self, name: str, text: str) -> Path:
        return self.write_bytes(name, text.encode("utf-8"))

    def write_json(self, name: str, data: Any) -> Path:
        """Write JSON: numpy values and NaN made JSON-safe, floats rounded to
        :data:`JSON_DIGITS` significant digits (:func:`json_ready`)."""
        return self.write_text(name, json.dumps(json_ready(data, JSON_DIGITS), indent=2,
                                                allow_nan=False, ensure_ascii=False) + "\n")

    def write_csv(self, name: str, frame, **kwargs) -> Path:
        """Write a pandas DataFrame as CSV (no index unless asked)."""
        kwargs.setdefault("index", False)
        return self.write_text(name, frame.to_csv(**kwargs))

    def _write_via_temporary(self, name: str, write: Callable[[Path], None]) -> Path:
        target = self.file(name)
        tmp = target.with_name(f".{target.name}.tmp")
        try:
            with self._writing(name):
                write(tmp)
                os.replace(tmp, target)
        finally:
            tmp.unlink(missing_ok=True)
        return target

    def write_netcdf(self, name: str, dataset) -> Path:
        """Write an xarray Dataset to netCDF atomically (CF ``Conventions``, no fill value on
        coordinates: :func:`sealsim.files.netcdf_ready`)."""
        dataset, encoding = netcdf_ready(dataset)
        return self._write_via_temporary(
            name, lambda tmp: dataset.to_netcdf(tmp, encoding=encoding))

    def savefig(self, name: str, figure, dpi: int = 130) -> Path:
        """Save a matplotlib figure as PNG atomically.

        sealsim builds figures as :class:`matplotlib.figure.Figure` objects without pyplot, so
        no GUI backend is needed and nothing has to be closed.  Matplotlib's layout warnings
        are not shown: the figure is written either way.
        """
        def write(tmp: Path) -> None:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                figure.savefig(tmp, dpi=dpi, format="png", bbox_inches="tight")

        return self._write_via_temporary(name, write)

    def final_path(self, name: str = "") -> Path:
        """Where a file will be once the folder is committed (as the user gave the folder)."""
        return self.requested / name


CaseT = TypeVar("CaseT")
ResultT = TypeVar("ResultT")


def run_variants(
    cases: Mapping[str, CaseT],
    out: str | Path,
    simulate: Callable[[str, CaseT, Callable[[float, float], None] | None], ResultT],
    write: Callable[[ResultFolder, dict[str, ResultT]], None],
    *,
    force: bool = False,
    inputs: Iterable[str | Path] = (),
    progress: Callable[[str, float, float], None] | None = None,
    write_each: Callable[[ResultFolder, str, ResultT], None] | None = None,
) -> dict[str, ResultT]:
    """Run every variant of a validated case into the result folder ``out``.

    This is the skeleton of every command that writes results (``rotary run``, ``friction
    run``, ``pneumatic run``, ``structure run``/``map``; new long-running commands -- studies,
    fits, FMU builds -- should use it too, so the same guarantees hold):

    1. :class:`ResultFolder` checks ``out`` before anything is computed (existing results
       without ``force``, a file in the way, no write permission, an input file inside it);
    2. the folder is locked for the whole run (a second run to ``out`` is refused), files are
       staged in a hidden folder;
    3. ``simulate(name, case, report)`` runs each variant; ``report(done, total)`` is forwarded
       as ``progress(name, done, total)`` (``None`` without ``progress``); after each variant
       ``write_each(folder, name, result)`` may write its files at once;
    4. ``write(folder, results)`` writes the files of all variants (warnings raised while
       writing -- matplotlib layout notes -- are not shown);
    5. the staging folder replaces ``out`` atomically.  Any error, Ctrl-C or SIGTERM before
       that leaves ``out`` as it was and removes the staging folder.

    Parameters
    ----------
    cases : mapping
        ``{variant name: case}``, already validated (names from
        :func:`sealsim.cases.expand_variants` are safe as file names).
    out : path-like
        Result folder.
    simulate, write, write_each : callable
        See above.
    force : bool
        Replace results that ``out`` holds when the run starts.
    inputs : iterable of path-like
        Files the run reads (refused inside ``out``).
    progress : callable, optional
        ``progress(variant, done, total)``.

    Returns
    -------
    dict
        ``{variant name: result}``.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "squares"
    >>> results = run_variants(
    ...     {"two": 2, "three": 3}, out, lambda name, x, report: x * x,
    ...     lambda folder, res: folder.write_json("summary.json", res))
    >>> (out / "summary.json").read_text().split()
    ['{', '"two":', '4,', '"three":', '9', '}']
    """
    with ResultFolder(out, force, inputs) as folder:
        results: dict[str, ResultT] = {}
        for name, case in cases.items():
            report = None if progress is None else (
                lambda done, total, n=name: progress(n, done, total))
            results[name] = simulate(name, case, report)
            if write_each is not None:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")  # plot layout warnings: files are complete
                    write_each(folder, name, results[name])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            write(folder, results)
    return results
