"""Parameter studies: sweeps, tolerance (Monte-Carlo) and sensitivity studies, on Dask.

A study sits above the models: it changes fields of a model's case (``seal.cord_diameter``,
``oil.name``, a linked FE map case's material hardness), runs the model's own run function for
every combination or sample, collects named numbers of the model's summary (and optionally its
time series) and analyses them; :func:`sealsim.runs.study.run_study` writes the result folder
of ``sealsim study run``::

    from sealsim.runs.study import run_study
    from sealsim.studies import load_study

    study = load_study("examples/studies/gearbox_oils.toml")
    result = run_study(study, "results/gearbox_oils", workers=2)
    result.dataset["torque"].sel(oil="VG68-mineral")

* :mod:`~sealsim.studies.spec` -- the study file and its validation;
* :mod:`~sealsim.studies.paths` -- dotted paths into case data (and linked case files);
* :mod:`~sealsim.studies.design` -- grids, Monte-Carlo, Latin-hypercube, Saltelli samples;
* :mod:`~sealsim.studies.models` -- the models and the numbers of their summaries;
* :mod:`~sealsim.studies.engine` -- in this process, a local Dask cluster, or a running one;
* :mod:`~sealsim.studies.store` -- finished runs kept for ``--resume``;
* :mod:`~sealsim.studies.results`, :mod:`~sealsim.studies.analysis` -- Dataset, table,
  percentiles, Sobol' indices; :mod:`~sealsim.studies.study` -- the runs of a study computed
  and analysed.
"""

__all__ = ["Study", "StudyResult", "analyse", "compute_runs", "load_study"]

_WHERE = {"Study": "spec", "load_study": "spec", "StudyResult": "study", "analyse": "study",
          "compute_runs": "study"}


def __getattr__(name: str):
    # lazy: a Dask worker imports sealsim.studies.execute and needs none of this
    if name in _WHERE:
        import importlib

        return getattr(importlib.import_module(f"sealsim.studies.{_WHERE[name]}"), name)
    raise AttributeError(f"module 'sealsim.studies' has no attribute {name!r}")
