"""Where a study's runs are computed: in this process, or on a Dask cluster.

* ``workers = 0``: one after the other in this process (no Dask).
* default: a :class:`distributed.LocalCluster` on this machine, ``workers`` processes (default:
  the usable cores) with one thread each.  Processes, not threads: the models hold the GIL
  (scipy integrators, numba-compiled right-hand sides called from Python, FElupe assembly).
* ``scheduler = "tcp://host:8786"``: an existing cluster -- ``dask scheduler`` and ``dask
  worker`` started by hand, or a batch system through dask-jobqueue (see the documentation,
  page Studies).  Its workers must import the same sealsim and read the same case files.

Runs are sent in batches: one Dask task runs several runs one after the other, so that
thousands of millisecond runs do not drown in scheduling overhead (every task costs a few
milliseconds of scheduler, client and worker time).  How many (:class:`Batches`):

1. While the run time is unknown, tasks of one run each probe it (about two per worker).
2. Then the remaining runs are cut into tasks of equal size, a multiple of the worker count
   in number (so that the workers finish together), each about :data:`TARGET_TASK_S` of work
   at most and :data:`MIN_TASK_S` at least, and :data:`TASKS_PER_WORKER` per worker where
   the study is long enough for both: a long study gets second-long tasks, the 40 cycles of
   the benchmark (0.6 s of work) one task per worker.  The cut is made again if the run
   time turns out more than twice or less than half the estimate.

The run time is the median of the last 200 finished runs, without the first run of each worker
process: that one also pays the worker's imports and numba compilation (once per process; a
worker keeps them, and its loaded FE maps, between tasks).  There is one task per worker thread
at a time, the next one sent as soon as one finishes: a second task queued on a busy worker
may wait there while another worker idles (Dask estimates a task's duration from earlier tasks
of the same function, one-run probes included, and did not move it), and Ctrl-C or a lost
worker loses little finished work.  Every record is handed to ``on_record`` (which stores it)
as soon as its task returns.  A local cluster is started with less housekeeping
(:func:`local_cluster_config`).

Linked cases that several runs share (a seal's FE map) are prepared first, once each
(:func:`sealsim.studies.execute.prepare_links`), so that workers do not build the same map at
the same time.  A worker that dies takes its task with it; Dask gives the task to another
worker, and after three lost workers it reports the runs as failed (``KilledWorker``).
"""

from __future__ import annotations

import contextlib
import json
import logging
import math
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

__all__ = ["Batches", "Engine", "TARGET_TASK_S", "local_cluster_config", "open_engine",
           "task_sizes"]

#: longest wanted duration of one Dask task [s] (batches of short runs)
TARGET_TASK_S = 1.0
#: shortest wanted duration of one Dask task [s] (unless a run takes longer)
MIN_TASK_S = 0.2
#: tasks per worker where a study is long enough for tasks of at least MIN_TASK_S
TASKS_PER_WORKER = 2
#: largest batch
MAX_BATCH = 1000
#: a study on a cluster without any worker stops after this long [s] (runs are kept)
NO_WORKER_TIMEOUT = 300.0


def local_cluster_config() -> dict:
    """Dask settings for the local cluster of a study: less housekeeping in processes whose
    cores are meant for the runs.

    * The nanny starts workers with ``MALLOC_TRIM_THRESHOLD_=65536`` (Dask's default, so that
      workers hand freed memory back): glibc then returns freed memory at once and maps
      every array above 128 kB anew (no dynamic mmap threshold), and a short run spends
      10-15 % more CPU time in page faults (measured: 3200 instead of 1300 minor faults per
      steady rotary point).  The other variables (one BLAS/OpenMP thread) are kept.
    * The workers' statistical profiler samples the running task every 10 ms.
    * Event-loop checks 50 times a second and the system monitor twice a second in every
      process took 7 % of a core on an idle 2-worker cluster, 2.5 % at 1 s and 2 s.
    """
    import dask

    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ", {}))
    environ.pop("MALLOC_TRIM_THRESHOLD_", None)
    return {"distributed.nanny.pre-spawn-environ": environ,
            "distributed.worker.profile.enabled": False,
            "distributed.admin.tick.interval": "1s",
            "distributed.admin.system-monitor.interval": "2s"}


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


def task_sizes(run_s: float, runs: int, workers: int) -> list[int]:
    """Runs per task for ``runs`` runs of about ``run_s`` seconds on ``workers`` workers
    (see the module docstring): equal tasks, a multiple of ``workers`` in number.

    Examples
    --------
    >>> task_sizes(0.016, 36, 2)                   # 0.6 s of work: one task per worker
    [18, 18]
    >>> task_sizes(0.016, 200, 2)                  # 3.2 s: two tasks per worker of 0.8 s
    [50, 50, 50, 50]
    >>> sizes = task_sizes(0.016, 10_000, 2)       # 160 s: tasks of TARGET_TASK_S
    >>> len(sizes), min(sizes), max(sizes)
    (160, 62, 63)
    >>> task_sizes(3.0, 3, 2)                      # long runs: one each
    [1, 1, 1]
    """
    if runs <= 0:
        return []
    work = runs * max(run_s, 1e-9)
    per_worker = max(1, math.ceil(work / (workers * TARGET_TASK_S)),
                     min(TASKS_PER_WORKER, int(work / (workers * MIN_TASK_S))))
    tasks = max(min(runs, workers * per_worker), math.ceil(runs / MAX_BATCH))
    base, extra = divmod(runs, tasks)
    return [base + 1] * extra + [base] * (tasks - extra)


class Batches:
    """The tasks of a study's runs: :meth:`next` gives the runs of the next task, :meth:`done`
    takes the records of a finished one (see the module docstring).

    Examples
    --------
    >>> batches = Batches([(i, ()) for i in range(40)], workers=2)
    >>> [len(batches.next()) for _ in range(3)]          # probes
    [1, 1, 1]
    >>> batches.done([{"wall_s": 2.5, "first_in_process": True, "status": "ok"},
    ...               {"wall_s": 0.016, "first_in_process": False, "status": "ok"}])
    >>> [len(batches.next()) for _ in range(3)]          # 37 runs of 16 ms on 2 workers
    [19, 18, 0]
    """

    def __init__(self, jobs: list, workers: int, batch_size: int | None = None):
        self.queue = deque(jobs)
        self.workers = max(1, workers)
        self.fixed = batch_size
        self.warm: list[float] = []      # run times without the first run of a process
        self.cold: list[float] = []      # first runs of a process (include its set-up)
        self.planned_s: float | None = None
        self.sizes: deque = deque()

    def __len__(self) -> int:
        return len(self.queue)

    def run_time(self) -> float | None:
        """Median run time [s] of the finished runs (first runs of a process only if there
        is nothing else), None before the first finished run."""
        times = self.warm or self.cold
        return float(np.median(times)) if times else None

    def done(self, records: list[dict]) -> None:
        for record in records:
            if record["status"] == "ok":
                times = self.cold if record.get("first_in_process") else self.warm
                times.append(record["wall_s"])
                del times[:-200]         # the recent runs tell the run time

    def set_workers(self, workers: int) -> None:
        """Worker threads joined or left: the remaining runs are cut again."""
        if max(1, workers) != self.workers:
            self.workers, self.sizes = max(1, workers), deque()

    def next(self) -> list:
        if not self.queue:
            return []
        size = self.fixed or self._planned_size()
        return [self.queue.popleft() for _ in range(min(size, len(self.queue)))]

    @property
    def probing(self) -> bool:
        """The run time is not known yet (a first run in a process also pays its set-up, so
        it tells the run time only if there is nothing else)."""
        return not self.fixed and not self.warm and len(self.cold) < self.workers

    def _planned_size(self) -> int:
        if self.probing:
            return 1
        run_s = self.run_time()
        if self.planned_s is None or not 0.5 <= run_s / self.planned_s <= 2.0:
            self.sizes = deque()
        if not self.sizes:               # cut the remaining runs into equal tasks
            self.planned_s = run_s
            self.sizes = deque(task_sizes(run_s, len(self.queue), self.workers))
        return self.sizes.popleft()


def _run_on_dask(client, template, jobs, on_record, batch_size) -> None:
    from distributed import wait

    checked = {"at": -1e9, "threads": 0}

    def threads() -> int:            # of the connected workers; asks at most once a second
        if time.monotonic() - checked["at"] > 1.0:
            checked["threads"] = sum(_cluster(client.nthreads).values())
            checked["at"] = time.monotonic()
        return checked["threads"]

    batches = Batches(jobs, threads(), batch_size)
    in_flight: dict = {}
    no_workers_since = None

    def fill() -> None:             # one task per worker thread: see the module docstring
        batches.set_workers(threads())
        while batches and len(in_flight) < batches.workers:
            batch = batches.next()
            in_flight[_cluster(client.submit, execute_batch, template, batch,
                               pure=False)] = batch

    fill()
    while in_flight:
        try:
            done, _ = _cluster(wait, list(in_flight), timeout=5.0,
                               return_when="FIRST_COMPLETED")
        except TimeoutError:
            if threads():
                no_workers_since = None
                fill()                   # workers may have joined
            elif no_workers_since is None:
                no_workers_since = time.monotonic()
            elif time.monotonic() - no_workers_since > NO_WORKER_TIMEOUT:
                raise ModelError(f"no Dask worker has been connected for "
                                 f"{NO_WORKER_TIMEOUT:.0f} s; the finished runs are kept: "
                                 "start workers and run the study again with --resume") \
                    from None
            continue
        finished = [(future, in_flight.pop(future)) for future in done]
        fill()                           # keep the workers busy while the results come in
        for future, batch in finished:
            records = _result(future, "running a batch of runs")
            if isinstance(records, str):   # the workers running it died
                records = [_failed(index, records) for index, _ in batch]
            batches.done(records)
            for record in records:
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
            # not made the process's default client: a failed connection would leave dask's
            # scheduler set to a cluster that never came up (later dask work, and xarray's
            # netCDF writes through their lock, then try to reach it); the study's client is
            # the current one only while the study runs (as_current)
            connected = Client(scheduler, timeout="10s", set_as_default=False)
        except Exception as exc:
            raise InputError(f"cannot connect to the Dask scheduler at {scheduler!r}: "
                             f"{type(exc).__name__}: {exc}; start one with 'dask scheduler' "
                             "(and workers with 'dask worker ADDRESS')") from None
        try:
            with connected.as_current():
                yield Engine("scheduler", connected, scheduler)
        finally:
            connected.close()
        return
    if workers is not None and workers < 0:
        raise InputError(f"--workers must be >= 0 (0: in this process), got {workers}")
    if workers == 0:
        yield Engine("serial")
        return
    import dask
    from distributed import Client, LocalCluster

    with dask.config.set(local_cluster_config()):
        cluster = LocalCluster(n_workers=workers or default_workers(), threads_per_worker=1,
                               processes=True, dashboard_address=":0",
                               silence_logs=logging.ERROR)
    local = Client(cluster, set_as_default=False)
    try:
        with local.as_current():
            yield Engine("local", local, cluster.scheduler_address)
    finally:
        cluster.close()     # workers first: closing the client first makes them log errors
        local.close()


def link_key(documents: dict, links) -> str:
    """Identity of the linked cases of a run (runs with the same key share their prep)."""
    return json.dumps({".".join(map(str, k)): documents[k] for k in links}, sort_keys=True,
                      default=str)
