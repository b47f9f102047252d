"""The results of a study: an xarray Dataset and a tidy table of all runs.

Dataset (written as ``study.nc``):

* dimensions: one per grid factor (coordinate: its values, ``units`` attribute), and
  ``sample`` for sampled designs (the sampled factors are coordinates along it);
* variables: each named output (``units``, ``long_name`` = its summary path), ``status``
  (1 finished, 0 failed), ``error`` (text, empty if finished), ``wall_time_s``; the requested
  series with their own dimensions (``time``, ``state`` or the map's ``squeeze``,
  ``temperature``, ``pressure``), NaN where a run failed or ended earlier;
* attributes: title, model, design, seed, the study file and the resolved base case (TOML
  text), the sealsim version.

Table (``runs.csv``): one row per run, columns ``run``, (``sample``), the factors and outputs
with their unit in the column name (``cord_diameter_mm``, ``F_N_N``), ``status``, ``error``,
``wall_time_s``, ``worker``.
"""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import xarray as xr

from sealsim import __version__

__all__ = ["assemble", "column_name", "unit_token"]


def unit_token(unit: str) -> str:
    """A unit as it is written at the end of a column name.

    Examples
    --------
    >>> unit_token("mm"), unit_token("degC"), unit_token("N m"), unit_token("m/s")
    ('mm', 'C', 'Nm', 'm_s')
    >>> unit_token("1"), unit_token("dm ** 3 / bar / s")
    ('', 'dm3_bar_s')
    """
    if unit in ("", "1", "dimensionless"):
        return ""
    text = unit.replace("degC", "C").replace("degF", "F").replace("µ", "u").replace("**", "")
    text = re.sub(r"\s*/\s*", "_", text)
    text = re.sub(r"[\s*()]", "", text)
    return re.sub(r"[^A-Za-z0-9_]", "", text)


def column_name(name: str, unit: str) -> str:
    """``name`` with its unit appended unless it already ends with it (``F_N`` + N ->
    ``F_N_N``, ``torque_Nm`` + N m -> ``torque_Nm``)."""
    token = unit_token(unit)
    if not token or name.endswith("_" + token) or name == token:
        return name
    return f"{name}_{token}"


def _describe(factor) -> str:
    if factor.kind == "grid":
        return "grid values"
    params = ", ".join(f"{k}={v:.6g}" for k, v in factor.params.items())
    return f"{factor.distribution}({params}) {factor.unit}".strip()


def _factor_name(factor) -> str:
    """A readable ``long_name``: the factor's description, else what it changes."""
    if factor.description:
        return factor.description
    if factor.path:
        return f"{factor.name}: the case field {factor.path}"
    return f"{factor.name}: a free variable of the [set] expressions"


def assemble(study, records: list[dict]) -> tuple[xr.Dataset, pd.DataFrame]:
    """Dataset and tidy table of a complete study (``records[i]`` is run ``i``)."""
    shape, dims = study.shape, study.dims
    coords: dict = {}
    for f in study.grid_factors:
        coords[f.name] = (f.name, np.asarray(f.coords),
                          {"units": f.unit or "1", "long_name": _factor_name(f),
                           "description": f.description, "factor": _describe(f)})
    if study.sampled:
        coords["sample"] = ("sample", np.arange(study.n_samples),
                            {"long_name": "number of the sample (from 0)"})
        for j, f in enumerate(study.sampled_factors):
            coords[f.name] = ("sample", study.sample_values[:, j],
                              {"units": f.unit or "1", "long_name": _factor_name(f),
                               "description": f.description, "factor": _describe(f)})
    ok = np.array([r["status"] == "ok" for r in records])
    data_vars: dict = {}
    for out in study.outputs:
        values = np.array([_number(r["summary"].get(out.path)) for r in records], dtype=float)
        data_vars[out.name] = (dims, values.reshape(shape), {
            "units": out.unit, "long_name": f"{out.name}: {out.path} of the {study.model} "
                                            "model's summary"})
    data_vars["status"] = (dims, ok.astype(np.int8).reshape(shape),
                           {"long_name": "1: run finished, 0: run failed (see error)"})
    data_vars["error"] = (dims, np.array([r["error"] for r in records], dtype=object
                                         ).reshape(shape), {"long_name": "error of a failed run"})
    data_vars["wall_time_s"] = (dims, np.array([r["wall_s"] for r in records]).reshape(shape),
                                {"units": "s", "long_name": "computing time of the run"})
    dataset = xr.Dataset(data_vars, coords=coords, attrs={
        "title": study.title, "description": study.description,
        "model": study.model, "design": study.design, "seed": study.seed,
        "runs": len(records), "failed_runs": int((~ok).sum()),
        "sealsim_version": __version__, "source": str(study.source),
        "study": study.text, **{f"resolved_{k}".replace(".", "_"): v
                                for k, v in study.resolved_cases().items()},
        "comment": "one dimension per grid factor, 'sample' for sampled factors; units in "
                   "the 'units' attributes; NaN where a run failed",
    })
    series = _series(study, records)
    if series is not None:
        dataset = dataset.merge(series)
    return dataset, _table(study, records)


def _number(value) -> float:
    return np.nan if value is None else float(value)


def _series(study, records: list[dict]) -> xr.Dataset | None:
    """Series of all runs on common coordinates; a run that ended earlier (or failed) is
    padded with NaN.  A coordinate that differs between runs (a map whose squeeze is a
    factor) becomes a plain position, its values per run the variable ``<dim>_values``."""
    finished = [r for r in records if r.get("series")]
    if not finished:
        return None
    # a series dimension named like a factor (a map's "squeeze") is renamed "series_squeeze"
    clash = {d: f"series_{d}" for d in study.dims}
    finished = [dict(r, series={_rename(n, clash): (tuple(clash.get(d, d) for d in dims), a)
                                for n, (dims, a) in r["series"].items()}) for r in finished]
    runs_coords: dict[str, list] = {}
    for r in finished:
        for name, (_, arr) in r["series"].items():
            if name.startswith("coord:"):
                runs_coords.setdefault(name[6:], []).append((r["index"], arr))
    coords, varying = {}, {}
    for dim, items in runs_coords.items():
        longest = max((arr for _, arr in items), key=len)
        if all(np.array_equal(arr, longest[:len(arr)]) for _, arr in items):
            coords[dim] = longest
        else:
            coords[dim] = np.arange(len(longest))
            varying[dim] = items
    variables = {}

    def stack(dims, arrays) -> np.ndarray:
        full = tuple(len(coords[d]) for d in dims)
        data = np.full((len(records), *full), np.nan)
        for index, arr in arrays:
            data[(index, *(slice(0, n) for n in np.shape(arr)))] = arr
        return data.reshape(study.shape + full)

    for name, (dims, _) in finished[0]["series"].items():
        if not name.startswith("coord:"):
            arrays = [(r["index"], r["series"][name][1]) for r in finished]
            variables[name] = (study.dims + tuple(dims), stack(dims, arrays),
                               {"long_name": f"{name} over {', '.join(dims)} in each run "
                                             f"(series of the {study.model} model)"})
    for dim, items in varying.items():
        variables[f"{dim}_values"] = (study.dims + (dim,), stack((dim,), items),
                                      {**_SERIES_UNITS.get(dim.removeprefix("series_"), {}),
                                       "long_name": f"{dim} of each run"})
    return xr.Dataset(variables, coords={d: (d, c, {} if d in varying else
                                             _SERIES_UNITS.get(d.removeprefix("series_"), {}))
                                         for d, c in coords.items()})


def _rename(name: str, clash: dict) -> str:
    if name.startswith("coord:") and name[6:] in clash:
        return "coord:" + clash[name[6:]]
    return name


#: units of the series coordinates (maps: SI, as in map.nc)
_SERIES_UNITS = {"time": {"units": "s"}, "state": {"long_name": "load state (from 0)"},
                 "temperature": {"units": "K"}, "pressure": {"units": "Pa"},
                 "squeeze": {"units": "1"}}


def _table(study, records: list[dict]) -> pd.DataFrame:
    rows = []
    for r in records:
        i = r["index"]
        row = {"run": i}
        if study.sampled:
            row["sample"] = study.position(i)[-1]
        values = study.factor_values(i)
        for f in study.factors:
            row[column_name(f.name, f.unit)] = values[f.name]
        for out in study.outputs:
            row[column_name(out.name, out.unit)] = _number(r["summary"].get(out.path))
        row.update(status=r["status"], error=r["error"], wall_time_s=r["wall_s"],
                   worker=r.get("worker", ""))
        rows.append(row)
    return pd.DataFrame(rows)
