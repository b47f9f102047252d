"""Studies on Dask: the same numbers as in this process, a real cluster of separate processes,
and nothing lost when the study or a worker is killed half way.

The study is tiny: 12 LuGre stick-slip runs (a mass on the contact, Radau integration, about
0.1 s each), numbers that react to the last bit of a BLAS call, so "identical" means identical.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from sealsim.errors import ResultExistsError
from sealsim.runs.study import run_study
from sealsim.studies import load_study
from sealsim.studies.store import work_folder_for

STUDY = """
title = "stick-slip over mass and spring"
[study]
model = "friction"
design = "grid"
[base]
[base.friction]
law = "lugre"
parameter_set = "canudas1995"
[base.bench]
mode = "mass"
mass = "1 kg"
stiffness = "2 N/m"
duration = "3 s"
time_step = "1 ms"
drive_velocity = { kind = "constant", level = "0.1 m/s" }
integrator = "radau"    # scipy's Radau: runs long enough to kill a study half way
[[factors]]
name = "mass"
path = "bench.mass"
values = ["0.5 kg", "1 kg", "2 kg"]
[[factors]]
name = "stiffness"
path = "bench.stiffness"
range = { start = "1 N/m", stop = "8 N/m", num = 4 }
[outputs]
F_max = "max_friction_force_N"
work = "dissipated_energy_J"
z_max = "z_max"
"""
OUTPUTS = ("F_max", "work", "z_max")
CLI = [sys.executable, "-c", "from sealsim.cli import main; main()"]


@pytest.fixture(scope="module")
def study_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("study") / "stick.toml"
    path.write_text(STUDY)
    return path


@pytest.fixture(scope="module")
def reference(study_file, tmp_path_factory):
    """The uninterrupted study in this process (no Dask)."""
    out = tmp_path_factory.mktemp("reference") / "serial"
    return run_study(load_study(study_file), out, workers=0).dataset


def _assert_same(dataset, reference):
    for name in OUTPUTS:
        # bitwise: every run is computed by the same code with one BLAS thread
        assert np.array_equal(dataset[name].values, reference[name].values), name
    assert dataset["status"].values.all()


def _wait_for(condition, timeout: float, what: str):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if condition():
            return
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for {what}")


def _scheduler_address(scheduler_file: Path) -> str | None:
    """The address in a dask scheduler file, or None while it is missing or half written."""
    try:
        return json.loads(scheduler_file.read_text())["address"]
    except (OSError, ValueError, KeyError):
        return None


def _stored(out: Path) -> int:
    runs = work_folder_for(out) / "runs"
    return len(list(runs.glob("*.json"))) if runs.is_dir() else 0


def test_local_cluster_gives_the_serial_numbers(study_file, reference, tmp_path):
    result = run_study(load_study(study_file), tmp_path / "dask", workers=2)
    _assert_same(result.dataset, reference)
    assert result.summary["engine"]["kind"] == "local"
    assert result.summary["engine"]["workers"] == 2
    assert result.table["worker"].nunique() == 2          # both worker processes computed
    # the study's client was the current one only while it ran: this process's dask is back
    # to its own schedulers (no closed cluster left as the default client or scheduler)
    import dask
    from distributed import default_client
    assert dask.config.get("scheduler", None) != "dask.distributed"
    with pytest.raises(ValueError, match="No clients found"):
        default_client()


def test_killed_study_resumes_with_only_the_missing_runs(study_file, reference, tmp_path):
    out = tmp_path / "killed"
    proc = subprocess.Popen([*CLI, "study", "run", str(study_file), "--out", str(out),
                             "--workers", "0", "--quiet"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        _wait_for(lambda: _stored(out) >= 3, 120, "the first finished runs")
    finally:
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
    kept = _stored(out)
    assert 3 <= kept < 12                                  # killed half way
    assert not out.exists()                                # nothing committed
    study = load_study(study_file)
    with pytest.raises(ResultExistsError, match="--resume"):
        run_study(study, out, workers=0)                   # the finished runs are not dropped
    result = run_study(study, out, workers=0, resume=True)
    assert result.summary["runs"]["reused"] == kept
    assert result.summary["runs"]["computed"] == 12 - kept
    _assert_same(result.dataset, reference)
    assert not work_folder_for(out).exists()               # removed once committed
    assert sorted(p.name for p in tmp_path.iterdir()) == ["killed"]   # no staging or lock left


def test_real_scheduler_and_workers_survive_a_killed_worker(study_file, reference, tmp_path):
    scheduler_file = tmp_path / "scheduler.json"
    env = dict(os.environ, PYTHONWARNINGS="ignore")
    procs = [subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler",
                               "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                               "--scheduler-file", str(scheduler_file)], env=env,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              start_new_session=True)]
    try:
        # the scheduler creates its file before it has written it: wait for the address
        _wait_for(lambda: _scheduler_address(scheduler_file) is not None, 60, "the scheduler")
        address = _scheduler_address(scheduler_file)
        for name in ("w1", "w2"):
            procs.append(subprocess.Popen(
                [sys.executable, "-m", "distributed.cli.dask_worker", address, "--nthreads",
                 "1", "--no-nanny", "--no-dashboard", "--name", name], env=env,
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True))
        from distributed import Client

        with Client(address, timeout="30s") as client:
            client.wait_for_workers(2, timeout=60)
        out = tmp_path / "cluster"
        study = subprocess.Popen([*CLI, "study", "run", str(study_file), "--out", str(out),
                                  "--scheduler", address, "--quiet"],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        _wait_for(lambda: _stored(out) >= 2 or study.poll() is not None, 120,
                  "the first finished runs")
        os.kill(procs[1].pid, signal.SIGKILL)               # worker w1 dies half way
        assert _stored(out) < 12
        stdout, stderr = study.communicate(timeout=180)
        assert study.returncode == 0, stderr
        import xarray as xr

        with xr.open_dataset(out / "study.nc") as dataset:
            _assert_same(dataset.load(), reference)
        summary = json.loads((out / "summary.json").read_text())
        assert summary["engine"]["kind"] == "scheduler"
        assert summary["runs"]["computed"] == 12 and summary["runs"]["failed"] == 0
    finally:
        for proc in procs:
            if proc.poll() is None:
                os.kill(proc.pid, signal.SIGKILL)
            proc.wait()


# -- batching: every run once, in tasks that let the workers finish together -----------------
def _drain(batches, run_s: float) -> list[list]:
    """Tasks of ``batches`` as a cluster would see them, every run taking ``run_s``; the
    first run of each of the workers' processes also pays a set-up of 2 s."""
    tasks, cold = [], batches.workers
    while batch := batches.next():
        tasks.append(batch)
        records = [{"wall_s": run_s + 2.0 * (cold > 0), "first_in_process": cold > 0,
                    "status": "ok"} for _ in batch]
        cold = max(0, cold - len(batch))
        batches.done(records)
    return tasks


@pytest.mark.parametrize("runs, run_s, workers", [(40, 0.016, 2), (10_000, 0.016, 4),
                                                   (37, 30.0, 2), (3, 0.01, 8)])
def test_batches_give_every_run_once_in_equal_tasks(runs, run_s, workers):
    from sealsim.studies.engine import MIN_TASK_S, TARGET_TASK_S, Batches

    tasks = _drain(Batches([(i, ()) for i in range(runs)], workers), run_s)
    assert sorted(i for task in tasks for i, _ in task) == list(range(runs))
    probes = 0
    while probes < len(tasks) and len(tasks[probes]) == 1 and probes <= workers:
        probes += 1                      # one-run tasks until a warm run time is known
    sized = [len(task) for task in tasks[probes:]]
    if sized:
        assert max(sized) - min(sized) <= 1                   # equal: workers finish together
        assert len(sized) % workers == 0 or max(sized) == 1   # a multiple of the workers
        assert max(sized) * run_s <= TARGET_TASK_S + run_s    # short enough to lose little
        assert max(sized) == 1 or min(sized) * run_s >= min(
            MIN_TASK_S, (runs - probes) * run_s / workers) - run_s   # long enough to pay


def test_batches_are_cut_again_when_the_run_time_changes():
    from sealsim.studies.engine import Batches

    batches = Batches([(i, ()) for i in range(1000)], workers=2)
    batches.done([{"wall_s": 0.01, "first_in_process": False, "status": "ok"}])
    assert len(batches.next()) == 100          # 1 s tasks of 10 ms runs
    batches.done([{"wall_s": 0.1, "first_in_process": False, "status": "ok"}] * 20)
    assert len(batches.next()) == 10           # runs became 10x longer: 1 s tasks again
    batches.set_workers(4)
    assert len(batches.next()) == 10
