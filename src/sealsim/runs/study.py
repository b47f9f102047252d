"""``sealsim study run``: a study into a result folder.

:func:`run_study` checks the result folder (:class:`sealsim.output.ResultFolder`: refused if it
holds results without ``force``, locked while the study runs), computes the missing runs in the
study's work folder (:func:`sealsim.studies.study.compute_runs`: finished runs survive an
interrupted study, ``resume`` reuses them), analyses them
(:func:`sealsim.studies.study.analyse`), then writes the results and commits them all at once:

* ``study.nc`` -- the xarray Dataset (:mod:`sealsim.studies.results`);
* ``runs.csv`` -- one row per run: factors, outputs, status, error;
* ``summary.json`` -- counts, engine, timing, statistics of every output, failures, notes;
* ``distribution.csv`` (sampled designs) -- mean, std, percentiles per output;
* ``sensitivity.csv`` (sampled designs) -- Sobol' indices per output and factor;
* ``case_resolved.toml`` (and ``case_resolved_<link>.toml`` per linked case), ``study.toml``;
* figures: ``response_<output>.png`` and ``heatmap_<output>.png`` for grids,
  ``histogram_<output>.png`` and ``scatter_<output>.png`` for samples, ``sensitivity.png``.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

from sealsim.output import ResultFolder
from sealsim.plotting import studies as plots
from sealsim.studies.spec import Study, load_study
from sealsim.studies.store import WorkFolder, work_folder_for
from sealsim.studies.study import StudyResult, analyse, compute_runs

__all__ = ["run_study", "run_study_file", "write_results"]


def run_study_file(path: str | Path, out: str | Path, **kwargs) -> StudyResult:
    """:func:`~sealsim.studies.load_study` then :func:`run_study` (keywords as there)."""
    return run_study(load_study(path), out, **kwargs)


def run_study(study: Study, out: str | Path, *, workers: int | None = None,
              scheduler: str | None = None, client=None, resume: bool = False,
              force: bool = False,
              progress: Callable[[str, int, int, int], None] | None = None) -> StudyResult:
    """Compute every run of ``study`` and write the result folder ``out``.

    Parameters
    ----------
    study : Study
        From :func:`sealsim.studies.load_study`.
    out : path-like
        Result folder (refused if it holds results, unless ``force``).
    workers : int, optional
        Processes of the local Dask cluster (default: the usable cores); 0 computes in this
        process without Dask.
    scheduler : str, optional
        Address of a running Dask scheduler (``tcp://host:8786``) instead of a local cluster.
    client : distributed.Client, optional
        A connected client to use (from Python; it is not closed).
    resume : bool
        Reuse the finished runs of an interrupted run of this study (only the missing runs
        are computed).
    force : bool
        Replace existing results; without ``resume``, also drop the finished runs of an
        interrupted study.
    progress : callable, optional
        ``progress(phase, done, total, failed)``; phase ``"prepare"`` (linked cases such as FE
        maps) or ``"runs"``.

    Returns
    -------
    StudyResult
    """
    started = time.perf_counter()
    folder = ResultFolder(out, force=force, inputs=study.inputs)   # checked before computing
    with folder:
        work = WorkFolder(work_folder_for(out))
        records, info = compute_runs(study, work, workers=workers, scheduler=scheduler,
                                     client=client, resume=resume, discard=force,
                                     progress=progress)
        result = analyse(study, records, {**info, "wall_time_s": time.perf_counter() - started})
        write_results(folder, study, result)
    work.remove()
    return result


def write_results(folder: ResultFolder, study: Study, result: StudyResult) -> None:
    """Dataset, tables, resolved cases, summary and figures of a study."""
    folder.write_netcdf("study.nc", result.dataset)
    folder.write_csv("runs.csv", result.table, float_format="%.10g")
    folder.write_text("study.toml", study.text)
    for label, text in study.resolved_cases().items():
        name = "case_resolved.toml" if label == "case" else \
            f"case_resolved_{label.replace('.', '_')}.toml"
        folder.write_text(name, text)
    dataset, outputs = result.dataset, result.summary["outputs"]
    title = study.title or study.source.stem
    if study.sampled:
        folder.write_csv("distribution.csv", result.distribution, float_format="%.10g")
        if not result.sensitivity.empty:
            folder.write_csv("sensitivity.csv", result.sensitivity, float_format="%.6g")
            folder.savefig("sensitivity.png", plots.sensitivity_figure(result.sensitivity,
                                                                       title))
        names = [f.name for f in study.sampled_factors]
        for out in study.outputs:
            folder.savefig(f"histogram_{out.name}.png", plots.histogram_figure(
                dataset, out.name, outputs[out.name], title))
            folder.savefig(f"scatter_{out.name}.png",
                           plots.scatter_figure(dataset, out.name, names, title))
    grid = study.grid_factors
    if grid:
        by_size = sorted(grid, key=lambda f: (not f.numeric, -len(f.values)))
        for out in study.outputs:
            folder.savefig(f"response_{out.name}.png",
                           plots.response_figure(dataset, out.name, by_size[0].name, title))
            if len(grid) >= 2:
                folder.savefig(f"heatmap_{out.name}.png", plots.heatmap_figure(
                    dataset, out.name, by_size[0].name, by_size[1].name, title))
    folder.write_json("summary.json", result.summary)
