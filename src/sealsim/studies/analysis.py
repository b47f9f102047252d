r"""Analysis of a finished study: spread of the outputs and their sensitivity to the factors.

* :func:`distribution_table` -- per output (and per grid point of a mixed design): number of
  finished runs, mean, standard deviation, minimum, the 5th, 50th and 95th percentiles
  (linear interpolation between order statistics, Hyndman & Fan 1996 definition 7, numpy's
  default) and maximum.
* :func:`sensitivity_table` -- variance-based (Sobol') sensitivity indices of each output to
  the sampled factors, computed with SALib (Herman & Usher 2017):

  - design ``"sobol"`` (Saltelli's cross-sampled Sobol' sequence): first-order indices
    :math:`S_i = V[E(Y|X_i)]/V(Y)` and total indices :math:`S_{Ti} = E[V(Y|X_{\sim i})]/V(Y)`
    with the estimators of Saltelli et al. (2010) and bootstrap 95 % confidence intervals;
  - designs ``"latin_hypercube"`` and ``"monte_carlo"``: first-order indices only, by
    random-balance-design FAST on the given sample (Tarantola, Gatelli & Mara 2006, with the
    bias correction of Tissot & Prieur 2012); total indices need design ``"sobol"``.

  For a model that is additive in its factors, :math:`S_i = S_{Ti}` and
  :math:`\sum_i S_i = 1`; :math:`S_{Ti} - S_i` measures interactions.

References: R. J. Hyndman, Y. Fan, Am. Stat. 50 (1996) 361-365; J. Herman, W. Usher, J. Open
Source Softw. 2 (2017) 97; A. Saltelli et al., Comput. Phys. Commun. 181 (2010) 259-270;
S. Tarantola, D. Gatelli, T. A. Mara, Reliab. Eng. Syst. Saf. 91 (2006) 717-727; J.-Y. Tissot,
C. Prieur, Reliab. Eng. Syst. Saf. 107 (2012) 205-213.
"""

from __future__ import annotations

import contextlib
import io
import itertools
import warnings

import numpy as np
import pandas as pd

__all__ = ["PERCENTILES", "distribution_table", "sensitivity_table", "spread"]

#: percentiles reported for sampled studies
PERCENTILES = (5, 50, 95)
#: fewest finished runs for first-order indices from a Latin-hypercube/Monte-Carlo sample:
#: RBD-FAST (M = 4 harmonics) on 64 LHS points of a linear 3-factor model scatters by
#: about ±0.1 around the exact indices (10 seeds, sealsim check), at 40 points by more than
#: ±0.2
MIN_RBD_SAMPLES = 64
#: 95 % confidence half-width of a Sobol' index [-] beyond which a note says the sample is too
#: small: an index lies in 0 ... 1, and an interval wider than half of that cannot rank factors
MAX_INDEX_HALF_WIDTH = 0.5


def spread(values) -> dict[str, float]:
    """Statistics of the finite values of an output.

    Examples
    --------
    >>> s = spread([1.0, 2.0, 3.0, 4.0, float("nan")])
    >>> s["n"], s["mean"], s["P50"], round(s["std"], 4)
    (4, 2.5, 2.5, 1.291)
    """
    y = np.asarray(values, dtype=float)
    y = y[np.isfinite(y)]
    out: dict[str, float] = {"n": int(y.size)}
    if y.size == 0:
        return out | {k: np.nan for k in ("mean", "std", "min", "max",
                                          *(f"P{p}" for p in PERCENTILES))}
    out["mean"] = float(y.mean())
    out["std"] = float(y.std(ddof=1)) if y.size > 1 else 0.0
    out["min"] = float(y.min())
    for p, value in zip(PERCENTILES, np.percentile(y, PERCENTILES)):
        out[f"P{p}"] = float(value)
    out["max"] = float(y.max())
    return out


def _grid_points(study):
    """(label dict, index tuple) of every grid point; one empty point without grid factors."""
    grid = study.grid_factors
    for pos in itertools.product(*(range(len(f.values)) for f in grid)):
        yield {f.name: f.coords[k] for f, k in zip(grid, pos)}, pos


def distribution_table(study, dataset) -> pd.DataFrame:
    """:func:`spread` of every output (per grid point of a mixed design) of a sampled study."""
    rows = []
    for labels, pos in _grid_points(study):
        for out in study.outputs:
            y = dataset[out.name].values[pos]
            rows.append({**labels, "output": out.name, "unit": out.unit,
                         "failed": int(np.sum(~np.isfinite(y))), **spread(y)})
    return pd.DataFrame(rows)


def sensitivity_table(study, dataset) -> tuple[pd.DataFrame, list[str]]:
    """Sobol' indices of every output to the sampled factors (see the module docstring).

    Returns
    -------
    table : pandas.DataFrame
        One row per (grid point,) output and factor: ``S1``, ``S1_conf``, ``ST``, ``ST_conf``
        (NaN where not available), ``method``.
    notes : list of str
        Why indices are missing for an output (failed runs, a constant output, too few runs).
    """
    factors = study.sampled_factors
    if not study.sampled or not factors:
        return pd.DataFrame(), []
    x = study.sample_values
    problem = {"num_vars": len(factors), "names": [f.name for f in factors],
               "bounds": [[float(x[:, j].min()), float(x[:, j].max()) or 1.0]
                          for j in range(len(factors))]}
    rows, notes = [], []
    uncertain: dict[str, float] = {}        # output: widest 95 % half-width of its indices
    for labels, pos in _grid_points(study):
        where = "".join(f", {k} = {v}" for k, v in labels.items())
        for out in study.outputs:
            y = np.asarray(dataset[out.name].values[pos], dtype=float)
            finite = np.isfinite(y)
            if finite.sum() > 1 and np.ptp(y[finite]) <= 1e-12 * max(np.abs(y[finite]).max(),
                                                                     1e-300):
                notes.append(f"{out.name}{where}: constant over the sample, no indices")
                continue
            indices = _indices(study, problem, x, y, finite, f"{out.name}{where}", notes)
            if indices is None:
                continue
            method, s1, s1c, st, stc = indices
            widest = float(np.nanmax(np.r_[s1c, stc]))
            if widest > MAX_INDEX_HALF_WIDTH:
                uncertain[f"{out.name}{where}"] = widest
            for j, f in enumerate(factors):
                rows.append({**labels, "output": out.name, "factor": f.name,
                             "S1": s1[j], "S1_conf": s1c[j], "ST": st[j], "ST_conf": stc[j],
                             "method": method})
    if uncertain:
        notes.append("the sensitivity indices are uncertain, 95 % confidence half-widths up to "
                     + ", ".join(f"{w:.2g} ({name})" for name, w in uncertain.items())
                     + f" where an index lies in 0-1, from {len(x)} runs: raise study.samples "
                     "(the intervals narrow as 1/sqrt(samples))")
    return pd.DataFrame(rows), notes


def _indices(study, problem, x, y, finite, label, notes):
    nan = np.full(problem["num_vars"], np.nan)
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        if study.design == "sobol":
            if not finite.all():
                notes.append(f"{label}: {int((~finite).sum())} failed runs; Sobol' indices "
                             "need every run of the Saltelli sample")
                return None
            from SALib.analyze import sobol

            si = sobol.analyze(problem, y, calc_second_order=False, seed=study.seed)
            return ("Sobol', Saltelli 2010", np.asarray(si["S1"]), np.asarray(si["S1_conf"]),
                    np.asarray(si["ST"]), np.asarray(si["ST_conf"]))
        if finite.sum() < MIN_RBD_SAMPLES:
            notes.append(f"{label}: {int(finite.sum())} finished runs, first-order indices need "
                         f"at least {MIN_RBD_SAMPLES}")
            return None
        from SALib.analyze import rbd_fast

        si = rbd_fast.analyze(problem, x[finite], y[finite], M=4, seed=study.seed)
        return ("RBD-FAST, first order only", np.asarray(si["S1"]), np.asarray(si["S1_conf"]),
                nan, nan)
