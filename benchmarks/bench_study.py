"""Benchmark of the study engine: the issue's two studies, serially in this process and on a
2-worker Dask LocalCluster, in the same run.

* ``rotary``: 200 steady operating points of the 80 mm lip seal of
  examples/rotary/sump_volume.toml (``rotary_steady``; Latin hypercube over speed 250-1500 rpm
  and ambient 20-40 °C, the contact below NBR's limit), a run about 25 ms: about 5 s of
  work.
* ``pneumatic``: 40 extend/retract cycles of 2 s of the Ø32 cylinder of
  examples/pneumatic/cylinder_32.toml (variant T25C, Θ-law seals with analytic contact maps;
  Latin hypercube over load force and supply pressure), a run about 16 ms: 0.6 s of work, less
  than starting a cluster.

For each, two comparisons:

* **steady state** (the targets): the study's computing phase
  (:func:`sealsim.studies.study.compute_runs`: work folder, runs, storing each run as it
  finishes) serially in this process (``workers=0``) against a running, warmed-up 2-worker
  LocalCluster (``client=``).  Serial and Dask alternate, ``--repeats`` times each; the
  serial study runs while no cluster exists (the scheduler's threads in this process would
  slow it), a new cluster is started and warmed up for each Dask repeat.  The best of each is
  compared (other processes on the machine slow either one at random), the median is printed
  too.  Writing the figures is the same for both and not timed.
* **with start-up**: ``sealsim study run STUDY --workers 0`` and ``--workers 2`` end to end in
  fresh processes (imports, numba, the cluster start and the workers' set-up, every file and
  figure): what a user waits for.  The one-off costs are printed apart: the LocalCluster start
  and the workers' set-up (first run in each worker process: imports, numba), paid once.

Definitions (W = 2 workers, N = runs):

    speed-up            serial_s / dask_s                                  (target >= 1.7)
    overhead_fraction   (W * dask_s - serial_s) / serial_s                 (target <= 0.05)
                        = worker time per run not spent on the serial work, (W * dask_s -
                        serial_s) / N, as a fraction of a serial run, serial_s / N
    cpu_overhead        (CPU s of this process and the workers during the Dask study - CPU s
                        of the serial study) / CPU s of the serial study: the extra work of
                        Dask (scheduler, client, workers' bookkeeping, transfers); unlike the
                        wall times it hardly depends on what else runs on the machine
    ceiling_speedup     the same runs as W halves in W plain processes (no Dask, nothing
                        stored) against one process: what the machine gives right now

Run it on an idle machine: the load average is printed; other processes on the cores lower
the wall-clock speed-up (and the ceiling with it), hardly the CPU overhead::

    .venv/bin/python benchmarks/bench_study.py [--study rotary|pneumatic|both] [--repeats 3]

The last line is one JSON object: serial_s, dask_s, speedup, runs, overhead_fraction and the
other numbers above of the rotary study, the same for the pneumatic study under "pneumatic".
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
WORKERS = 2
REPEATS = 3

STUDIES = {
    "rotary": (200, """
title = "benchmark: 200 steady points of the 80 mm lip seal"
[study]
model = "rotary_steady"
case = "{examples}/rotary/sump_volume.toml"
variant = "sump_0.2L"
design = "latin_hypercube"
samples = 200
seed = 1
[set]
"duty.steps" = [{{ speed = "1000 rpm", duration = "60 min" }}]
[[factors]]
name = "speed"
path = "duty.steps.0.speed"
distribution = "uniform"
lower = "250 rpm"
upper = "1500 rpm"
[[factors]]
name = "ambient"
path = "environment.ambient_temperature"
distribution = "uniform"
lower = "20 degC"
upper = "40 degC"
[outputs]
torque = "torque_Nm"
T_contact = "T_contact_C"
"""),
    "pneumatic": (40, """
title = "benchmark: 40 cycles of the Ø32 cylinder"
[study]
model = "pneumatic"
case = "{examples}/pneumatic/cylinder_32.toml"
variant = "T25C"
design = "latin_hypercube"
samples = 40
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
"""),
}


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


def run_part(path: str, part: int, parts: int) -> float:
    """Every ``parts``-th run of the study from ``part`` on, in this process; wall time [s]."""
    from sealsim.studies import load_study
    from sealsim.studies.execute import execute_batch

    study = load_study(path)
    jobs = [(i, study.assignments(i)) for i in range(part, study.n_runs, parts)]
    t0 = time.perf_counter()
    execute_batch(_template(study), jobs)
    return time.perf_counter() - t0


def _cpu_s(pids) -> float:
    import psutil

    return sum(sum(psutil.Process(pid).cpu_times()[:2]) for pid in pids)


def _computing_phase(study, work: Path, pids, **kwargs) -> tuple[float, float, list, dict]:
    """The study's computing phase (as in ``sealsim study run``): wall time [s], CPU s of
    ``pids``, records, info."""
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


def bench(name: str, folder: Path, repeats: int) -> dict:
    """Every measurement of one study; prints them, returns the JSON numbers."""
    import dask
    from distributed import Client, LocalCluster

    from sealsim.studies import load_study
    from sealsim.studies.engine import local_cluster_config
    from sealsim.studies.study import analyse

    runs, text = STUDIES[name]
    path = folder / f"{name}.toml"
    path.write_text(text.format(examples=(ROOT / "examples").as_posix()))
    study = load_study(path)
    load_before = os.getloadavg()

    cli = {"serial": [], "dask": []}               # with start-up: the CLI end to end
    for k in range(2):
        cli["serial"].append(_cli(path, folder / f"{name}_cli_serial{k}", 0))
        cli["dask"].append(_cli(path, folder / f"{name}_cli_dask{k}", WORKERS))

    serial_setup_s = warm_up(str(path))
    times: dict = {"serial": [], "dask": []}
    cpu: dict = {"serial": [], "dask": []}
    start_s, setup_s, results = [], [], {}
    for k in range(repeats):
        # serial first, with no cluster in this process (its threads would share the GIL)
        wall, used, records, info = _computing_phase(study, folder / f"{name}_serial{k}",
                                                     [os.getpid()], workers=0)
        results["serial"] = analyse(study, records, {**info, "wall_time_s": wall})
        times["serial"].append(wall)
        cpu["serial"].append(used)
        t0 = time.perf_counter()
        with dask.config.set(local_cluster_config()):    # as the study engine starts one
            cluster = LocalCluster(n_workers=WORKERS, threads_per_worker=1, processes=True,
                                   dashboard_address=":0", silence_logs=40)
        client = Client(cluster)
        try:
            start_s.append(time.perf_counter() - t0)
            setup_s.append(max(client.run(warm_up, str(path)).values()))
            pids = [os.getpid(), *client.run(os.getpid).values()]
            wall, used, records, info = _computing_phase(study, folder / f"{name}_dask{k}",
                                                         pids, client=client)
        finally:
            cluster.close()
            client.close()
        results["dask"] = analyse(study, records, {**info, "wall_time_s": wall})
        times["dask"].append(wall)
        cpu["dask"].append(used)
    start_s, setup_s = min(start_s), min(setup_s)

    ceiling = []                                   # the same runs in W plain processes
    with concurrent.futures.ProcessPoolExecutor(
            WORKERS, mp_context=multiprocessing.get_context("spawn")) as pool:
        list(pool.map(warm_up, [str(path)] * WORKERS))
        for _ in range(repeats):
            one = run_part(str(path), 0, 1)
            t0 = time.perf_counter()
            list(pool.map(run_part, [str(path)] * WORKERS, range(WORKERS), [WORKERS] * WORKERS))
            ceiling.append(one / (time.perf_counter() - t0))
    load_after = os.getloadavg()

    serial_s, dask_s = min(times["serial"]), min(times["dask"])
    serial_cpu, dask_cpu = min(cpu["serial"]), min(cpu["dask"])
    speedup = serial_s / dask_s
    overhead = (WORKERS * dask_s - serial_s) / serial_s
    cpu_overhead = (dask_cpu - serial_cpu) / serial_cpu
    data = {kind: result.dataset for kind, result in results.items()}
    identical = all(data["serial"][o.name].equals(data["dask"][o.name]) for o in study.outputs)
    failed = int((~data["dask"]["status"].values.astype(bool)).sum())
    median_run = float(data["serial"]["wall_time_s"].median())
    cli_serial, cli_dask = min(cli["serial"]), min(cli["dask"])

    print(f"== {study.title}: {runs} runs, median run {median_run * 1e3:.1f} ms in this "
          f"process; load average before {load_before[0]:.2f}, after {load_after[0]:.2f}")
    print(f"with start-up, 'sealsim study run' end to end in a fresh process (best of 2): "
          f"serial {cli_serial:.2f} s, 2-worker LocalCluster {cli_dask:.2f} s (speed-up "
          f"{cli_serial / cli_dask:.2f}); one-off costs: first run in this process (imports, "
          f"numba) {serial_setup_s:.2f} s, LocalCluster start {start_s:.2f} s, worker set-up "
          f"(first run in each worker process, in parallel) {setup_s:.2f} s")
    print(f"steady state, computing phase, best (median) of {repeats} alternating repeats: "
          f"serial {serial_s:.3f} s ({statistics.median(times['serial']):.3f} s), "
          f"CPU {serial_cpu:.3f} s; running 2-worker LocalCluster {dask_s:.3f} s "
          f"({statistics.median(times['dask']):.3f} s), CPU (client, scheduler, workers) "
          f"{dask_cpu:.3f} s")
    print(f"speed-up {speedup:.2f} (target >= 1.7; W plain processes reach {max(ceiling):.2f} "
          f"on this machine now); overhead (W*dask_s - serial_s)/N = "
          f"{(WORKERS * dask_s - serial_s) / runs * 1e3:.2f} ms per run = {100 * overhead:.1f} % "
          f"of a serial run (target <= 5 %); extra CPU {100 * cpu_overhead:.1f} %; identical "
          f"results: {identical}; failed runs: {failed}")
    return {"serial_s": round(serial_s, 4), "dask_s": round(dask_s, 4),
            "speedup": round(speedup, 3), "runs": runs, "workers": WORKERS,
            "overhead_fraction": round(overhead, 4),
            "cpu_overhead_fraction": round(cpu_overhead, 4),
            "ceiling_speedup": round(max(ceiling), 3), "median_run_s": round(median_run, 4),
            "serial_median_s": round(statistics.median(times["serial"]), 4),
            "dask_median_s": round(statistics.median(times["dask"]), 4),
            "cli_serial_s": round(cli_serial, 2), "cli_dask_s": round(cli_dask, 2),
            "cluster_start_s": round(start_s, 2), "worker_setup_s": round(setup_s, 2),
            "serial_setup_s": round(serial_setup_s, 2), "identical": bool(identical),
            "failed": failed,
            "load_average": [round(x, 2) for x in (load_before[0], load_after[0])]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--study", choices=["rotary", "pneumatic", "both"], default="both")
    parser.add_argument("--repeats", type=int, default=REPEATS)
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="sealsim-bench-study-"))
    print(f"machine: {os.cpu_count()} cores; load average (1, 5, 15 min) "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    names = ["rotary", "pneumatic"] if args.study == "both" else [args.study]
    out = {name: bench(name, folder, args.repeats) for name in names}
    first = out.pop(names[0])
    print(json.dumps({"study": names[0], **first, **out}))


if __name__ == "__main__":
    main()
