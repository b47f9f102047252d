"""Where a study's runs are computed: in this process, or on a Dask cluster.

* ``workers = 0``: one after the other in this process (no Dask).
* default: a :class:`distributed.LocalCluster` on this machine, ``workers`` processes (default:
  the usable cores) with one thread each.  Processes, not threads: the models hold the GIL
  (scipy integrators, numba-compiled right-hand sides called from Python, FElupe assembly).
* ``scheduler = "tcp://host:8786"``: an existing cluster -- ``dask scheduler`` and ``dask
  worker`` started by hand, or a batch system through dask-jobqueue (see the README, section
  Studies).  Its workers must import the same sealsim and read the same case files.

Runs are sent in batches (one Dask task runs several runs), sized from the median run time so
that a task takes about :data:`TARGET_TASK_S` (smaller towards the end of the study, so that
the workers finish together): thousands of millisecond runs do not drown in scheduling
overhead, and a lost task costs little.  At most two tasks per worker are queued at
a time, so Ctrl-C or a lost worker loses little finished work; every record is handed to
``on_record`` (which stores it) as soon as its task returns.  A worker process keeps its
imports, numba compilations and loaded FE maps between tasks: set-up is paid once per worker.

Linked cases that several runs share (a seal's FE map) are prepared first, once each
(:func:`sealsim.studies.execute.prepare_links`), so that workers do not build the same map at
the same time.  A worker that dies takes its task with it; Dask gives the task to another
worker, and after three lost workers it reports the runs as failed (``KilledWorker``).
"""

from __future__ import annotations

import contextlib
import json
import logging
import os
import time
from collections import deque
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np

from sealsim.errors import InputError, ModelError
from sealsim.studies.execute import (
    RunTemplate,
    execute_batch,
    execute_run,
    one_blas_thread,
    prepare_links,
)

__all__ = ["Engine", "TARGET_TASK_S", "open_engine"]

#: wanted duration of one Dask task [s] (batches of short runs)
TARGET_TASK_S = 1.0
#: largest batch
MAX_BATCH = 1000
#: a study on a cluster without any worker stops after this long [s] (runs are kept)
NO_WORKER_TIMEOUT = 300.0


def default_workers() -> int:
    """Usable cores of this machine."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not on Linux
        return os.cpu_count() or 1


@dataclass
class Engine:
    """A way to compute runs: ``client`` None means in this process."""

    kind: str                      # "serial", "local", "scheduler", "client"
    client: Any = None
    address: str = ""

    @property
    def workers(self) -> int:
        if self.client is None:
            return 1
        return max(1, len(self.client.nthreads()))

    def describe(self) -> dict:
        return {"kind": self.kind, "workers": self.workers, "address": self.address}

    # -- running ---------------------------------------------------------------------------
    def prepare(self, template: RunTemplate, jobs: list, progress=None) -> list[str]:
        """Run :func:`prepare_links` for each job; the error texts (empty: fine)."""
        if not jobs:
            return []
        if self.client is None:
            out = []
            for k, changes in enumerate(jobs):
                out.append(prepare_links(template, changes))
                if progress:
                    progress(k + 1, len(jobs))
            return out
        from distributed import as_completed

        futures = {_cluster(self.client.submit, prepare_links, template, changes,
                            pure=False): k for k, changes in enumerate(jobs)}
        out = [""] * len(jobs)
        for done, future in enumerate(as_completed(futures), start=1):
            out[futures[future]] = _result(future, f"preparing linked case {futures[future]}")
            if progress:
                progress(done, len(jobs))
        return out

    def run(self, template: RunTemplate, jobs: list, on_record: Callable[[dict], None],
            batch_size: int | None = None) -> None:
        """Compute ``jobs`` (``(index, changes)``); ``on_record(record)`` for every run."""
        if self.client is None:
            with one_blas_thread():
                for index, changes in jobs:
                    on_record(execute_run(template, index, changes))
            return
        _run_on_dask(self.client, template, jobs, on_record, batch_size)


def _cluster(call, *args, **kwargs):
    """A call to the Dask cluster; a failure of the cluster (lost scheduler, closed
    connection) becomes one ModelError that says the finished runs are kept."""
    try:
        return call(*args, **kwargs)
    except TimeoutError:
        raise
    except Exception as exc:
        raise ModelError(f"the Dask cluster failed: {type(exc).__name__}: {exc}; the finished "
                         "runs are kept: run the study again with --resume") from None


def _result(future, what: str):
    """A task's result, or the text of a KilledWorker error (the runs are recorded as
    failed); other failures: see :func:`_cluster`."""
    from distributed import KilledWorker

    try:
        return _cluster(_killed_as_text, future, KilledWorker)
    except ModelError as exc:
        raise ModelError(f"{exc} (while {what})") from None


def _killed_as_text(future, killed):
    try:
        return future.result()
    except killed as exc:
        return f"KilledWorker: the worker processes running it died ({exc})"


def batch_size_for(run_times: list[float], remaining: int, workers: int) -> int:
    """Runs per task: about :data:`TARGET_TASK_S` of work, but at least four tasks per worker
    for the rest of the study (so that the workers finish at nearly the same time).

    Examples
    --------
    >>> batch_size_for([], 100, 2), batch_size_for([0.01] * 5, 1000, 2)
    (1, 100)
    >>> batch_size_for([0.01] * 5, 40, 2), batch_size_for([3.0], 40, 2)
    (5, 1)
    """
    if not run_times:
        return 1
    typical = max(float(np.median(run_times)), 1e-6)
    size = int(TARGET_TASK_S / typical)
    return max(1, min(size, remaining // (4 * workers), MAX_BATCH))


def _run_on_dask(client, template, jobs, on_record, batch_size) -> None:
    from distributed import wait

    queue = deque(jobs)
    in_flight: dict = {}
    run_times: list[float] = []
    no_workers_since = None
    workers = {"n": 1, "checked": -1e9}

    def worker_count() -> int:      # asks the scheduler at most once a second
        now = time.monotonic()
        if now - workers["checked"] > 1.0:
            workers["n"], workers["checked"] = len(_cluster(client.nthreads)), now
        return max(1, workers["n"])

    def fill() -> None:
        n = worker_count()
        while queue and len(in_flight) < 2 * n:
            size = batch_size or batch_size_for(run_times[-200:], len(queue), n)
            batch = [queue.popleft() for _ in range(min(size, len(queue)))]
            in_flight[_cluster(client.submit, execute_batch, template, batch,
                               pure=False)] = batch

    fill()
    while in_flight:
        try:
            done, _ = _cluster(wait, list(in_flight), timeout=5.0,
                               return_when="FIRST_COMPLETED")
        except TimeoutError:
            if _cluster(client.nthreads):
                no_workers_since = None
            elif no_workers_since is None:
                no_workers_since = time.monotonic()
            elif time.monotonic() - no_workers_since > NO_WORKER_TIMEOUT:
                raise ModelError(f"no Dask worker has been connected for "
                                 f"{NO_WORKER_TIMEOUT:.0f} s; the finished runs are kept: "
                                 "start workers and run the study again with --resume") \
                    from None
            continue
        for future in done:
            batch = in_flight.pop(future)
            records = _result(future, "running a batch of runs")
            if isinstance(records, str):   # the workers running it died
                records = [_failed(index, records) for index, _ in batch]
            for record in records:
                run_times.append(record["wall_s"])
                on_record(record)
        fill()


def _failed(index: int, error: str) -> dict:
    return {"index": index, "status": "failed", "error": error, "summary": {}, "series": {},
            "series_available": [], "notes": [], "wall_s": 0.0, "worker": ""}


@contextlib.contextmanager
def open_engine(workers: int | None = None, scheduler: str | None = None,
                client: Any = None) -> Iterator[Engine]:
    """The engine for a study (see the module docstring); closes what it started."""
    if client is not None:
        yield Engine("client", client, str(getattr(client.scheduler, "address", "")))
        return
    if scheduler is not None:
        if workers is not None:
            raise InputError("--workers sets the size of the local cluster; with --scheduler "
                             "the workers are those of the running cluster")
        from distributed import Client

        try:
            connected = Client(scheduler, timeout="10s")
        except Exception as exc:
            raise InputError(f"cannot connect to the Dask scheduler at {scheduler!r}: "
                             f"{type(exc).__name__}: {exc}; start one with 'dask scheduler' "
                             "(and workers with 'dask worker ADDRESS')") from None
        try:
            yield Engine("scheduler", connected, scheduler)
        finally:
            connected.close()
        return
    if workers is not None and workers < 0:
        raise InputError(f"--workers must be >= 0 (0: in this process), got {workers}")
    if workers == 0:
        yield Engine("serial")
        return
    from distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=workers or default_workers(), threads_per_worker=1,
                           processes=True, dashboard_address=":0",
                           silence_logs=logging.ERROR)
    local = Client(cluster)
    try:
        yield Engine("local", local, cluster.scheduler_address)
    finally:
        cluster.close()     # workers first: closing the client first makes them log errors
        local.close()


def link_key(documents: dict, links) -> str:
    """Identity of the linked cases of a run (runs with the same key share their prep)."""
    return json.dumps({".".join(map(str, k)): documents[k] for k in links}, sort_keys=True,
                      default=str)
