"""Compute a study's runs and analyse them (the result folder is :mod:`sealsim.runs.study`).

:func:`compute_runs` opens the study's work folder (:mod:`sealsim.studies.store`: finished runs
survive an interrupted study, ``resume`` reuses them), prepares linked cases such as FE maps
once per distinct case, and computes the missing runs on the engine
(:mod:`sealsim.studies.engine`).  :func:`analyse` turns the run records into the
:class:`StudyResult`: the xarray Dataset (:mod:`sealsim.studies.results`), one table row per
run, the summary (counts, engine, timing, statistics of every output, failures, notes) and, for
sampled designs, the distribution and Sobol' sensitivity tables
(:mod:`sealsim.studies.analysis`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import pandas as pd
import xarray as xr

from sealsim import __version__
from sealsim.errors import InputError
from sealsim.studies.analysis import distribution_table, sensitivity_table, spread
from sealsim.studies.engine import link_key, open_engine
from sealsim.studies.execute import RunTemplate
from sealsim.studies.models import MODELS
from sealsim.studies.results import assemble, column_name
from sealsim.studies.spec import Study
from sealsim.studies.store import WorkFolder

__all__ = ["StudyResult", "analyse", "compute_runs"]

#: failures listed in summary.json (all are in runs.csv)
LISTED_FAILURES = 20


@dataclass
class StudyResult:
    """A study's results: what :func:`analyse` returns and :func:`sealsim.runs.study.run_study`
    writes."""

    dataset: xr.Dataset
    table: pd.DataFrame
    summary: dict
    distribution: pd.DataFrame = field(default_factory=pd.DataFrame)
    sensitivity: pd.DataFrame = field(default_factory=pd.DataFrame)


class _OutputCheck:
    """Stops the study at the first finished run if an output or series is not in the model's
    summary: the user fixes the study file instead of waiting for useless runs."""

    def __init__(self, study: Study):
        self.study = study
        self.done = False

    def __call__(self, record: dict) -> None:
        if self.done or record["status"] != "ok":
            return
        self.done = True
        summary = record["summary"]
        where = f"study {str(self.study.source)!r}"
        for out in self.study.outputs:
            if out.path not in summary:
                shown = ", ".join(list(summary)[:60])
                raise InputError(f"{where}: output {out.name!r} = {out.path!r} is not in the "
                                 f"summary of model {self.study.model!r}; it has: {shown}"
                                 + (" ..." if len(summary) > 60 else "")
                                 + ". Fix [outputs], then run again with --resume (finished "
                                 "runs are kept)")
        wanted = self.study.series.variables if self.study.series else []
        missing = [v for v in wanted if v not in record.get("series_available", [])]
        if missing:
            raise InputError(f"{where}: series {', '.join(map(repr, missing))} not in the "
                             f"series of model {self.study.model!r}; it has: "
                             f"{', '.join(record.get('series_available', []))}. Fix [series], "
                             "then run again with --force")


def compute_runs(study: Study, work: WorkFolder, *, workers: int | None = None,
                 scheduler: str | None = None, client=None, resume: bool = False,
                 discard: bool = False,
                 progress: Callable[[str, int, int, int], None] | None = None
                 ) -> tuple[list[dict], dict]:
    """Compute every run of ``study`` that ``work`` does not hold yet.

    Parameters
    ----------
    study : Study
        From :func:`sealsim.studies.load_study`.
    work : WorkFolder
        Where finished runs are kept (only one process may use it: the caller holds the lock
        of the result folder it belongs to).
    workers : int, optional
        Processes of the local Dask cluster (default: the usable cores); 0 computes in this
        process without Dask.
    scheduler : str, optional
        Address of a running Dask scheduler (``tcp://host:8786``) instead of a local cluster.
    client : distributed.Client, optional
        A connected client to use (from Python; it is not closed).
    resume : bool
        Reuse the finished runs of an interrupted run of this study.
    discard : bool
        Drop the finished runs of an interrupted study (without ``resume``).
    progress : callable, optional
        ``progress(phase, done, total, failed)``; phase ``"prepare"`` (linked cases such as FE
        maps) or ``"runs"``.

    Returns
    -------
    records : list of dict
        One record per run, in run order (:mod:`sealsim.studies.execute`).
    info : dict
        ``engine`` (its description), ``computed`` and ``reused`` run counts.
    """
    counts = {"computed": 0, "failed": 0}
    files = study.file_digests()
    fingerprint = study.fingerprint(files)
    # the engine first: a bad --scheduler or --workers is refused before the work folder exists
    with open_engine(workers, scheduler, client) as engine:
        finished = work.start(fingerprint, str(study.source), study.n_runs, resume=resume,
                              discard=discard, files=files)
        reused = len(finished)
        engine_info = engine.describe()
        check = _OutputCheck(study)
        try:
            _compute(study, work, engine, finished, counts, check, progress)
        except BaseException:
            if not work.indices():      # nothing finished: leave no empty work folder behind
                work.remove()
            raise
    records = [work.load(i) for i in range(study.n_runs)]
    for record in records:
        check(record)
    return records, {"engine": engine_info, "computed": counts["computed"], "reused": reused}


def _compute(study: Study, work: WorkFolder, engine, finished: set[int], counts: dict,
             check: _OutputCheck, progress) -> None:
    """Compute the runs not in ``finished`` on ``engine``, each stored in ``work`` (and
    checked) when it finishes."""
    reused = len(finished)
    template = RunTemplate(
        model=study.model, documents=study.documents,
        link_names={key: path.name for key, path in study.link_files.items()},
        base_dir=str(study.base_dir),
        series_variables=tuple(study.series.variables) if study.series else (),
        series_interval=study.series_interval,
        map_workers=None if engine.client is None else 1)
    counts["failed"] = sum(1 for i in finished if work.load(i)["status"] != "ok")

    def store(record: dict) -> None:
        work.save(record)
        counts["computed"] += 1
        counts["failed"] += record["status"] != "ok"
        if progress:
            progress("runs", reused + counts["computed"], study.n_runs, counts["failed"])
        check(record)

    jobs = [(i, study.assignments(i)) for i in range(study.n_runs) if i not in finished]
    if progress:
        progress("runs", reused, study.n_runs, counts["failed"])
    jobs = _prepare(study, template, engine, jobs, store, progress)
    engine.run(template, jobs, store, batch_size=study.batch_size)


def _prepare(study, template, engine, jobs, store, progress) -> list:
    """Prepare the linked cases (FE maps) of the pending runs once per distinct case; runs
    whose preparation failed are stored as failed.  Returns the runs still to compute."""
    spec = MODELS[study.model]
    if not template.link_names or spec.prepare is None or not jobs:
        return jobs
    groups: dict[str, list] = {}
    for job in jobs:
        key = link_key(study.run_documents(job[1]), template.link_names)
        groups.setdefault(key, []).append(job)
    firsts = [members[0][1] for members in groups.values()]
    report = None if progress is None else (
        lambda done, total: progress("prepare", done, total, 0))
    errors = engine.prepare(template, firsts, report)
    remaining = []
    for members, error in zip(groups.values(), errors):
        if not error:
            remaining += members
            continue
        for index, _ in members:
            store({"index": index, "status": "failed", "summary": {}, "series": {},
                   "series_available": [], "notes": [], "wall_s": 0.0, "worker": "",
                   "error": f"preparing the linked case failed: {error}"})
    return sorted(remaining)


def analyse(study: Study, records: list[dict], info: dict) -> StudyResult:
    """The dataset, run table, summary and (sampled designs) distribution and sensitivity
    tables of a study's run records.

    Parameters
    ----------
    study : Study
        The study.
    records : list of dict
        Its run records (:func:`compute_runs`).
    info : dict
        ``engine``, ``computed``, ``reused`` (:func:`compute_runs`) and ``wall_time_s``, put
        into the summary.

    Returns
    -------
    StudyResult
    """
    dataset, table = assemble(study, records)
    ok = dataset["status"].values.astype(bool)
    failures = [{"run": r["index"], "error": r["error"]} for r in records
                if r["status"] != "ok"]
    notes: list[str] = []
    distribution = sensitivity = pd.DataFrame()
    outputs = {}
    for out in study.outputs:
        outputs[out.name] = {"path": out.path, "unit": out.unit,
                             "column": column_name(out.name, out.unit),
                             **spread(dataset[out.name].values)}
    if study.sampled:
        distribution = distribution_table(study, dataset)
        sensitivity, notes = sensitivity_table(study, dataset)
    summary = {
        "title": study.title, "source": str(study.source), "sealsim_version": __version__,
        "model": study.model, "design": study.design, "seed": study.seed,
        "samples": study.samples, "dims": dict(zip(study.dims, study.shape)),
        "runs": {"total": study.n_runs, "finished": int(ok.sum()),
                 "failed": int((~ok).sum()), "computed": info["computed"],
                 "reused": info["reused"]},
        "engine": info["engine"],
        "wall_time_s": info["wall_time_s"],
        "run_time_s": {"sum": float(dataset["wall_time_s"].sum()),
                       "median": float(dataset["wall_time_s"].median())},
        "factors": [{"name": f.name, "path": f.path, "unit": f.unit, "kind": f.kind,
                     **({"values": f.coords} if f.kind == "grid" else
                        {"distribution": f.distribution, **f.params})}
                    for f in study.factors],
        "outputs": outputs,
        "failures": failures[:LISTED_FAILURES],
        "notes": notes + sorted({n for r in records for n in r.get("notes", [])})[:50],
    }
    if not sensitivity.empty:
        summary["sensitivity"] = sensitivity.to_dict("records")
    return StudyResult(dataset, table, summary, distribution, sensitivity)
