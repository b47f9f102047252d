r"""Designs of experiments: grids, Monte-Carlo, Latin-hypercube and Saltelli (Sobol') samples.

Every sampled design first draws points ``u`` in the unit hypercube (one column per factor),
then maps each column through the inverse cumulative distribution function (ppf) of its
factor's distribution (inverse transform sampling, e.g. Devroye 1986, ch. II.2):

* ``uniform(lower, upper)``:  :math:`x = a + u\,(b - a)`;
* ``normal(mean, std)``:  :math:`x = \mu + \sigma\,\Phi^{-1}(u)`;
* ``truncnormal(mean, std, lower, upper)``: the normal distribution restricted to
  :math:`[a, b]`, :math:`x = \mu + \sigma\,\Phi^{-1}\big(\Phi(\alpha) + u\,(\Phi(\beta) -
  \Phi(\alpha))\big)` with :math:`\alpha = (a - \mu)/\sigma`, :math:`\beta = (b - \mu)/\sigma`
  -- the usual model of a tolerance band (a part outside the band is rejected by inspection).

Unit-cube points:

* Monte-Carlo: independent uniform numbers from :func:`numpy.random.default_rng` (PCG64);
* Latin hypercube: one point in each of ``n`` equal strata per factor, strata paired at random
  (McKay, Beckman & Conover 1979), :class:`scipy.stats.qmc.LatinHypercube`;
* Saltelli: the cross-sampled Sobol' sequence of Saltelli (2002) that Sobol' index estimators
  need, ``n·(d + 2)`` points (first-order and total indices), from SALib.

All are reproducible from the study's seed.  References: M. D. McKay, R. J. Beckman, W. J.
Conover, Technometrics 21 (1979) 239-245; A. Saltelli, Comput. Phys. Commun. 145 (2002)
280-297; L. Devroye, Non-Uniform Random Variate Generation, Springer 1986.
"""

from __future__ import annotations

import numpy as np

__all__ = ["DISTRIBUTIONS", "SAMPLED_DESIGNS", "ppf", "unit_samples"]

#: distribution -> its parameters (all required)
DISTRIBUTIONS = {
    "uniform": ("lower", "upper"),
    "normal": ("mean", "std"),
    "truncnormal": ("mean", "std", "lower", "upper"),
}

#: designs that draw samples (the rest, "grid", only combines listed values)
SAMPLED_DESIGNS = ("monte_carlo", "latin_hypercube", "sobol")

#: unit-cube points are kept this far from 0 and 1, so that unbounded distributions stay finite
_EDGE = 1e-12


def ppf(u, distribution: str, **params: float) -> np.ndarray:
    """Inverse cumulative distribution function: values of ``distribution`` at quantiles ``u``.

    Parameters
    ----------
    u : array_like
        Quantiles in [0, 1] (clipped to [1e-12, 1 - 1e-12]).
    distribution : {"uniform", "normal", "truncnormal"}
        See the module docstring.
    **params : float
        ``lower``/``upper`` (uniform), ``mean``/``std`` (normal), all four (truncnormal),
        in the factor's unit.

    Returns
    -------
    numpy.ndarray
        Values, same shape as ``u``.

    Examples
    --------
    >>> ppf([0.0, 0.5, 1.0], "uniform", lower=2.0, upper=4.0).round(9).tolist()
    [2.0, 3.0, 4.0]
    >>> float(ppf(0.975, "normal", mean=10.0, std=1.0)).__round__(4)
    11.96
    >>> x = ppf([0.0, 0.5, 1.0], "truncnormal", mean=2.0, std=0.1, lower=1.9, upper=2.1)
    >>> x.round(6).tolist()
    [1.9, 2.0, 2.1]
    """
    from scipy import stats

    u = np.clip(np.asarray(u, dtype=float), _EDGE, 1.0 - _EDGE)
    if distribution == "uniform":
        return params["lower"] + u * (params["upper"] - params["lower"])
    if distribution == "normal":
        return params["mean"] + params["std"] * stats.norm.ppf(u)
    if distribution == "truncnormal":
        mean, std = params["mean"], params["std"]
        a, b = (params["lower"] - mean) / std, (params["upper"] - mean) / std
        return np.clip(stats.truncnorm.ppf(u, a, b, loc=mean, scale=std),
                       params["lower"], params["upper"])
    raise ValueError(f"unknown distribution {distribution!r}")


def sample_count(design: str, samples: int, dimensions: int) -> int:
    """Points :func:`unit_samples` gives (``N·(dimensions + 2)`` for ``"sobol"``), known before
    any is generated.

    Examples
    --------
    >>> sample_count("sobol", 8, 3), sample_count("latin_hypercube", 8, 3)
    (40, 8)
    """
    return samples * (dimensions + 2) if design == "sobol" else samples


def unit_samples(design: str, samples: int, dimensions: int, seed: int) -> np.ndarray:
    """Points in the unit hypercube for a sampled design, shape ``(runs, dimensions)``.

    Parameters
    ----------
    design : {"monte_carlo", "latin_hypercube", "sobol"}
        See the module docstring.
    samples : int
        Number of samples; for ``"sobol"`` the base number N (a power of 2) of Saltelli's
        scheme, which gives ``N·(dimensions + 2)`` points.
    dimensions : int
        Number of sampled factors.
    seed : int
        Seed of the random numbers (same seed, same points).

    Examples
    --------
    >>> u = unit_samples("latin_hypercube", 4, 2, seed=1)
    >>> u.shape, sorted((u[:, 0] * 4).astype(int).tolist())   # one point per stratum
    ((4, 2), [0, 1, 2, 3])
    >>> unit_samples("sobol", 8, 3, seed=1).shape
    (40, 3)
    """
    if design == "monte_carlo":
        return np.random.default_rng(seed).random((samples, dimensions))
    if design == "latin_hypercube":
        from scipy import stats

        return stats.qmc.LatinHypercube(d=dimensions, seed=np.random.default_rng(seed)
                                        ).random(samples)
    if design == "sobol":
        from SALib.sample import sobol

        problem = {"num_vars": dimensions, "names": [f"x{i}" for i in range(dimensions)],
                   "bounds": [[0.0, 1.0]] * dimensions}
        return sobol.sample(problem, samples, calc_second_order=False, scramble=True,
                            seed=seed)
    raise ValueError(f"unknown sampled design {design!r}")
