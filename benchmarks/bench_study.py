"""Benchmark of the study engine: 40 pneumatic cylinder cycles, serially in this process and on
a 2-worker Dask LocalCluster, in the same run.

The study: the Ø32 cylinder of examples/pneumatic/cylinder_32.toml (variant T25C, Θ-law seals
with analytic contact maps), one extend/retract cycle of 2 s, 40 Latin-hypercube samples of
load force and supply pressure; a run takes about 16 ms on an idle core, so the whole study is
about 0.6 s of work -- short enough that starting a cluster costs more than the study.  Hence
two comparisons:

* **steady state** (the targets): the study's computing phase
  (:func:`sealsim.studies.study.compute_runs`: work folder, runs, storing each run as it
  finishes) serially in this process
  (``workers=0``) against a running, warmed-up 2-worker LocalCluster (``client=``).  Serial
  and Dask alternate, :data:`REPEATS` times each; the best of each is compared (other
  processes on the machine slow either one at random) and the median is printed too.
  Writing the figures is the same for both and not timed.
* **with start-up**: ``sealsim study run STUDY --workers 0`` and ``--workers 2`` end to end in
  fresh processes (imports, the numba compilation of each process, the cluster start, every
  file and figure): what a user waits for.

What a cluster costs besides: the LocalCluster start and the workers' set-up (first run in
each worker process: imports and loading the numba-compiled right-hand side), paid once.

Definitions (W = 2 workers, N = runs):

    speed-up            serial_s / dask_s                                  (target >= 1.7)
    overhead_fraction   (W * dask_s - serial_s) / serial_s                 (target <= 0.05)
                        = wall time per run the workers do not spend on the serial work,
                        (W * dask_s - serial_s) / N, as a fraction of a serial run, serial_s / N
    cpu_overhead        (CPU s of this process + the workers during the Dask study - CPU s of
                        the serial study) / CPU s of the serial study: the extra work of Dask
                        (scheduler, client, worker bookkeeping, transfers); unlike the wall
                        times it hardly depends on what else runs on the machine
    ceiling_speedup     the same runs split into W halves on W plain worker processes (no
                        Dask, nothing stored) against one: what the machine allows

Run on an idle machine (the load average is printed; with other processes on the cores the
wall-clock speed-up is lower than the hardware allows, the CPU overhead is not)::

    .venv/bin/python benchmarks/bench_study.py [--runs 40] [--repeats 3]

The last line is one JSON object with serial_s, dask_s, speedup, runs, overhead_fraction and
the other numbers above.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import json
import multiprocessing
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RUNS = 40
WORKERS = 2
REPEATS = 3

STUDY = """
title = "benchmark: {runs} cycles of the Ø32 cylinder"
[study]
model = "pneumatic"
case = "{case}"
variant = "T25C"
design = "latin_hypercube"
samples = {runs}
seed = 1
[set]
"controller.duration" = "2 s"
[[factors]]
name = "load_force"
path = "load.force"
distribution = "uniform"
lower = "0 N"
upper = "60 N"
[[factors]]
name = "supply_pressure"
path = "air.supply_pressure"
distribution = "uniform"
lower = "5 bar"
upper = "7 bar"
[outputs]
extend_time = "extend_time_s"
friction = "mean_friction_N"
"""


def _template(study):
    from sealsim.studies.execute import RunTemplate

    return RunTemplate(study.model, study.documents, {}, str(study.base_dir))


def warm_up(path: str) -> float:
    """First run of the study in this process (imports, numba); its time [s]."""
    from sealsim.studies import load_study
    from sealsim.studies.execute import execute_run

    t0 = time.perf_counter()
    study = load_study(path)
    execute_run(_template(study), 0, study.assignments(0))
    return time.perf_counter() - t0


def run_half(path: str, part: int, parts: int) -> float:
    """Every ``parts``-th run of the study from ``part`` in this process; wall time [s]."""
    from sealsim.studies import load_study
    from sealsim.studies.execute import execute_batch

    study = load_study(path)
    jobs = [(i, study.assignments(i)) for i in range(part, study.n_runs, parts)]
    t0 = time.perf_counter()
    execute_batch(_template(study), jobs)
    return time.perf_counter() - t0


def _cpu_s(pids) -> float:
    import psutil

    total = 0.0
    for pid in pids:
        times = psutil.Process(pid).cpu_times()
        total += times.user + times.system
    return total


def _computing_phase(study, work: Path, pids, **kwargs) -> tuple[float, float, list, dict]:
    """The study's computing phase (work folder, runs, storing each run as it finishes, as
    in ``sealsim study run``): wall time [s], CPU s of ``pids``, records, info."""
    from sealsim.studies.store import WorkFolder
    from sealsim.studies.study import compute_runs

    cpu0, t0 = _cpu_s(pids), time.perf_counter()
    records, info = compute_runs(study, WorkFolder(work), **kwargs)
    return time.perf_counter() - t0, _cpu_s(pids) - cpu0, records, info


def _cli(path: Path, out: Path, workers: int) -> float:
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-c", "from sealsim.cli import main; main()", "study",
                    "run", str(path), "--out", str(out), "--workers", str(workers), "--quiet"],
                   check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=RUNS)
    parser.add_argument("--repeats", type=int, default=REPEATS)
    args = parser.parse_args()
    runs, repeats = args.runs, args.repeats

    import dask
    from distributed import Client, LocalCluster

    from sealsim.studies import load_study
    from sealsim.studies.study import analyse

    load_before = os.getloadavg()
    folder = Path(tempfile.mkdtemp(prefix="sealsim-bench-study-"))
    path = folder / "bench.toml"
    path.write_text(STUDY.format(runs=runs, case=ROOT / "examples" / "pneumatic" /
                                 "cylinder_32.toml"))
    study = load_study(path)

    # with start-up: the CLI end to end, serial and on a fresh 2-worker LocalCluster
    cli = {"serial": [], "dask": []}
    for k in range(2):
        cli["serial"].append(_cli(path, folder / f"cli_serial{k}", 0))
        cli["dask"].append(_cli(path, folder / f"cli_dask{k}", WORKERS))

    serial_setup_s = warm_up(str(path))
    t0 = time.perf_counter()
    # as sealsim.studies.engine starts its LocalCluster (no statistical profiler)
    with dask.config.set({"distributed.worker.profile.enabled": False}):
        cluster = LocalCluster(n_workers=WORKERS, threads_per_worker=1, processes=True,
                               dashboard_address=":0", silence_logs=40)
    client = Client(cluster)
    start_s = time.perf_counter() - t0
    setup = client.run(warm_up, str(path))
    worker_pids = list(client.run(os.getpid).values())
    me = [os.getpid()]
    times: dict = {"serial": [], "dask": []}
    cpu: dict = {"serial": [], "dask": []}
    results = {}
    try:
        for k in range(repeats):
            for kind, kwargs, pids in (("serial", {"workers": 0}, me),
                                       ("dask", {"client": client}, me + worker_pids)):
                wall, used, records, info = _computing_phase(study, folder / f"{kind}{k}",
                                                             pids, **kwargs)
                results[kind] = analyse(study, records, {**info, "wall_time_s": wall})
                times[kind].append(wall)
                cpu[kind].append(used)
    finally:
        cluster.close()
        client.close()

    # the machine's ceiling: the same runs in W plain processes, no Dask
    ceiling = []
    with concurrent.futures.ProcessPoolExecutor(
            WORKERS, mp_context=multiprocessing.get_context("spawn")) as pool:
        list(pool.map(warm_up, [str(path)] * WORKERS))
        for _ in range(repeats):
            one = run_half(str(path), 0, 1)
            t0 = time.perf_counter()
            list(pool.map(run_half, [str(path)] * WORKERS, range(WORKERS),
                          [WORKERS] * WORKERS))
            ceiling.append(one / (time.perf_counter() - t0))

    serial_s, dask_s = min(times["serial"]), min(times["dask"])
    serial_cpu, dask_cpu = min(cpu["serial"]), min(cpu["dask"])
    speedup = serial_s / dask_s
    overhead = (WORKERS * dask_s - serial_s) / serial_s
    cpu_overhead = (dask_cpu - serial_cpu) / serial_cpu
    serial_run = serial_s / runs
    dataset = {kind: result.dataset for kind, result in results.items()}
    identical = all((dataset["serial"][o.name].values == dataset["dask"][o.name].values).all()
                    for o in study.outputs)
    median_run = float(dataset["serial"]["wall_time_s"].median())
    cli_serial, cli_dask = min(cli["serial"]), min(cli["dask"])
    load_after = os.getloadavg()
    setup_s = max(setup.values())

    print(f"machine: {os.cpu_count()} cores; load average (1, 5, 15 min) before "
          f"{load_before[0]:.2f} {load_before[1]:.2f} {load_before[2]:.2f}, after "
          f"{load_after[0]:.2f} {load_after[1]:.2f} {load_after[2]:.2f} (other processes on "
          "the cores lower the wall-clock numbers)")
    print(f"study: {runs} pneumatic cycles, median run {median_run * 1e3:.1f} ms "
          f"(serial, in this process)")
    print("with start-up, 'sealsim study run' end to end in a fresh process (best of 2): "
          f"serial {cli_serial:.2f} s, 2-worker LocalCluster {cli_dask:.2f} s "
          f"(speed-up {cli_serial / cli_dask:.2f})")
    print(f"one-off costs: first run in this process (imports, numba) {serial_setup_s:.2f} s; "
          f"LocalCluster start {start_s:.2f} s, then worker set-up (first run in each worker "
          f"process, in parallel) {setup_s:.2f} s")
    print(f"steady state, computing phase, best (median) of {repeats} alternating repeats:")
    print(f"  serial in this process: {serial_s:.3f} s ({statistics.median(times['serial']):.3f}"
          f" s) = {serial_run * 1e3:.1f} ms per run, CPU {serial_cpu:.3f} s")
    print(f"  running 2-worker LocalCluster: {dask_s:.3f} s "
          f"({statistics.median(times['dask']):.3f} s), CPU (client + scheduler + workers) "
          f"{dask_cpu:.3f} s")
    print(f"  speed-up {speedup:.2f} (target >= 1.7); plain processes without Dask reach "
          f"{max(ceiling):.2f} on this machine now")
    print(f"  overhead per run (W*dask_s - serial_s)/N = "
          f"{(WORKERS * dask_s - serial_s) / runs * 1e3:.2f} ms = {100 * overhead:.1f} % of a "
          f"serial run (target <= 5 %); extra CPU {100 * cpu_overhead:.1f} %")
    print(f"  identical results serial and Dask: {identical}")
    print(json.dumps({
        "serial_s": round(serial_s, 4), "dask_s": round(dask_s, 4),
        "speedup": round(speedup, 3), "runs": runs, "workers": WORKERS,
        "overhead_fraction": round(overhead, 4), "cpu_overhead_fraction": round(cpu_overhead, 4),
        "ceiling_speedup": round(max(ceiling), 3), "median_run_s": round(median_run, 4),
        "serial_median_s": round(statistics.median(times["serial"]), 4),
        "dask_median_s": round(statistics.median(times["dask"]), 4),
        "cli_serial_s": round(cli_serial, 2), "cli_dask_s": round(cli_dask, 2),
        "cluster_start_s": round(start_s, 2), "worker_setup_s": round(setup_s, 2),
        "serial_setup_s": round(serial_setup_s, 2), "identical": bool(identical),
        "load_average": [round(x, 2) for x in load_before + load_after]}))


if __name__ == "__main__":
    main()
