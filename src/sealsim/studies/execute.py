"""One run of a study, as a worker process executes it (in this process, or on Dask).

:func:`execute_batch` is the Dask task: it runs a list of runs one after the other and returns
one record per run.  A record is a plain dict (``index``, ``status`` "ok" or "failed",
``error``, ``summary``: every number of the model's summary as ``{"a.b": value}``, ``series``,
``notes``, ``wall_s``, ``worker``, ``first_in_process``: the first run of its process, whose
time includes the imports and numba compilations every later run reuses); an exception
inside a run -- invalid input for this combination of factors, a solver that does not
converge -- becomes a failed record, so one bad run never stops a study.

Runs are computed with one BLAS thread (:func:`one_blas_thread`), as on Dask workers: OpenBLAS
rounds differently with several threads, and a study must give the same numbers in this process
and on any cluster.

Linked case files (a seal's FE map case) are written for each run into a private temporary
folder under their own file name, so that the FE map cache (keyed by the resolved case) is
shared between runs, workers and later studies.
"""

from __future__ import annotations

import os
import shutil
import socket
import tempfile
import time
import traceback
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from sealsim.studies.models import MODELS, flatten
from sealsim.studies.paths import MAIN, Location, assign

__all__ = ["RunTemplate", "execute_batch", "execute_run", "one_blas_thread", "prepare_links"]


def one_blas_thread():
    """Context in which numpy/scipy use one BLAS thread (threadpoolctl).

    threadpoolctl limits the libraries loaded when the context starts: scipy's own OpenBLAS
    is loaded first, or a run that imports scipy.linalg would still use several threads."""
    import scipy.linalg  # noqa: F401
    from threadpoolctl import threadpool_limits

    return threadpool_limits(limits=1, user_api="blas")


@dataclass(frozen=True)
class RunTemplate:
    """Everything a worker needs besides a run's changes (sent with every task)."""

    model: str
    documents: dict                       # base case and linked cases (plain TOML data)
    link_names: dict                      # link keys -> file name of the linked case
    base_dir: str
    series_variables: tuple = ()
    series_interval: float | None = None
    map_workers: int | None = 1           # processes for FE maps built inside a run


#: runs started in this process (the first one pays the imports and numba compilations)
_runs_in_process = 0


def _worker_name() -> str:
    return f"{socket.gethostname()}:{os.getpid()}"


def _materialise(template: RunTemplate, changes, folder: Path):
    """The validated case of a run; linked cases validated and written into ``folder``."""
    import copy
    import importlib

    import tomli_w

    from sealsim.cases import validate_case
    from sealsim.studies.paths import LINKED_CASE_FIELDS

    documents = copy.deepcopy(template.documents)
    for location, value in changes:
        assign(documents, location, value)
    for k, (key, name) in enumerate(template.link_names.items()):
        module, model = LINKED_CASE_FIELDS[key[-1]]
        validate_case(getattr(importlib.import_module(module), model), documents[key],
                      f"linked case {'.'.join(map(str, key))}")
        target = folder / f"link{k}" / name
        target.parent.mkdir()
        target.write_text(tomli_w.dumps(documents[key]), encoding="utf-8")
        assign(documents, Location(MAIN, key), str(target))
    return validate_case(MODELS[template.model].case_class(), documents[MAIN], "case")


def _series(output, template: RunTemplate) -> tuple[dict, list[str]]:
    """Requested series of a run as ``{name: (dims, array)}`` plus coordinates, and the
    names the model offers."""
    import pandas as pd

    data = output.series
    if data is None:
        return {}, []
    available = [str(c) for c in (data.columns if hasattr(data, "columns")
                                  else data.data_vars)]
    if not template.series_variables:
        return {}, available
    if isinstance(data, pd.DataFrame):
        axis = data.index.to_numpy(dtype=float)
        if template.series_interval is not None:          # resample on a common time grid
            dt = template.series_interval
            n = int(np.floor((axis[-1] - axis[0]) / dt * (1 + 1e-12) + 1e-9)) + 1
            grid = axis[0] + dt * np.arange(n)
            out = {"coord:time": (("time",), grid)}
            for name in template.series_variables:
                if name in data.columns:
                    out[name] = (("time",), np.interp(grid, axis, data[name].to_numpy(float)))
            return out, available
        out = {"coord:state": (("state",), np.arange(len(axis), dtype=float))}
        for name in template.series_variables:
            if name in data.columns:
                out[name] = (("state",), data[name].to_numpy(float))
        return out, available
    out = {f"coord:{d}": ((d,), data[d].values.astype(float)) for d in data.dims}
    for name in template.series_variables:
        if name in data:
            out[name] = (tuple(data[name].dims), data[name].values.astype(float))
    return out, available


def _error_text(exc: Exception) -> str:
    """``Type: message``; for an error sealsim did not anticipate also where it happened."""
    from sealsim.errors import SealsimError

    text = f"{type(exc).__name__}: {exc}"
    if not isinstance(exc, SealsimError) and exc.__traceback__ is not None:
        frame = traceback.extract_tb(exc.__traceback__)[-1]
        text += f" (in {frame.name}, {Path(frame.filename).name}:{frame.lineno})"
    return text


def execute_run(template: RunTemplate, index: int, changes) -> dict[str, Any]:
    """Run one case of a study; never raises for a problem of the run itself."""
    global _runs_in_process
    t0 = time.perf_counter()
    record: dict[str, Any] = {"index": index, "worker": _worker_name(),
                              "first_in_process": _runs_in_process == 0}
    _runs_in_process += 1
    folder = Path(tempfile.mkdtemp(prefix="sealsim-study-run-")) if template.link_names \
        else None
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            case = _materialise(template, changes, folder)
            output = MODELS[template.model].run(case, Path(template.base_dir))
            series, available = _series(output, template)
        notes = list(output.notes)
        for w in caught:
            text = f"{w.category.__name__}: {w.message}"
            if str(w.message) not in notes and text not in notes:   # models note some too
                notes.append(text)
        record.update(status="ok", error="", summary=flatten(output.summary), series=series,
                      series_available=available, notes=notes)
    except Exception as exc:  # a failed run is a result, not the end of the study
        record.update(status="failed", error=_error_text(exc), summary={}, series={},
                      series_available=[], notes=[])
    finally:
        if folder is not None:
            shutil.rmtree(folder, ignore_errors=True)
    record["wall_s"] = time.perf_counter() - t0
    return record


def execute_batch(template: RunTemplate, runs: list) -> list[dict[str, Any]]:
    """The Dask task: ``runs`` is a list of ``(index, changes)``; one record per run."""
    with one_blas_thread():
        return [execute_run(template, index, changes) for index, changes in runs]


def prepare_links(template: RunTemplate, changes) -> str:
    """Build what runs with these linked cases share (a seal's FE map, cached) once; returns
    an error text, empty if all went well."""
    spec = MODELS[template.model]
    folder = Path(tempfile.mkdtemp(prefix="sealsim-study-prepare-"))
    try:
        with warnings.catch_warnings(), one_blas_thread():
            warnings.simplefilter("ignore")
            case = _materialise(template, changes, folder)
            spec.prepare(case, Path(template.base_dir), template.map_workers)
        return ""
    except Exception as exc:
        return _error_text(exc)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
