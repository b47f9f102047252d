"""Uncertainty of fitted parameters from the Jacobian of the residuals (Gauss–Newton).

For residuals r(θ) with m samples and n parameters at the optimum θ̂, the covariance of the
estimate is approximated by (Bates & Watts 1988, §2.3)::

    C = s²·(JᵀJ)⁻¹,   s² = Σ r_i² / (m − n),   J = ∂r/∂θ at θ̂

standard errors are sqrt(diag C) and the correlation matrix C_ij/sqrt(C_ii C_jj).  When the
residuals are scaled by stated measurement uncertainties, s² can be floored at 1 (Birge 1932):
the stated uncertainty then also covers errors that do not scatter (a model's discretisation),
and a scatter smaller than stated does not shrink the standard errors.  (JᵀJ)⁻¹ is
formed from the singular value decomposition of J; directions whose singular value is below
``rcond``·σ_max carry no information from the data -- the parameters along them are *not
identifiable* (their standard error is infinite).
"""

from __future__ import annotations

import numpy as np

__all__ = ["compare_signals", "constraint_failure", "drop_constrained", "on_constraint",
           "parameter_report", "parameter_statistics", "repeat_scatter"]

#: Relative distance from a constraint of the model within which a fitted value sits on it: 10x
#: the fits' finite-difference steps, which an optimum pressed against it does not get past.
CONSTRAINT_TOLERANCE = 1e-5


def parameter_statistics(jacobian, residuals, *, rcond=1e-8, max_relative_error=0.5,
                         max_correlation=0.995, values=None, names=None,
                         min_residual_variance=0.0):
    """Standard errors, correlations and identifiability of fitted parameters.

    Parameters
    ----------
    jacobian : array_like, shape (m, n)
        ∂r/∂θ at the optimum (θ in the units the errors are wanted in).
    residuals : array_like, shape (m,)
        Residuals at the optimum.
    rcond : float
        Relative singular value below which a direction counts as undetermined.
    max_relative_error : float
        A parameter whose standard error exceeds this fraction of |value| is flagged.
    max_correlation : float
        |correlation| above which two parameters are flagged as not separable.
    values : array_like, shape (n,), optional
        Parameter values (for the relative error test).
    names : list of str, optional
        Parameter names used in the messages.
    min_residual_variance : float
        Floor of s² (1 for residuals divided by stated standard uncertainties).

    Returns
    -------
    dict
        ``standard_errors`` (n,), ``correlation`` (n, n), ``covariance`` (n, n),
        ``residual_variance`` s², ``identifiable`` (n,) bool, ``reasons`` (list of str per
        parameter, empty when identifiable), ``singular_values``.

    References
    ----------
    D. M. Bates, D. G. Watts, Nonlinear Regression Analysis and Its Applications, Wiley 1988.
    R. T. Birge, "The calculation of errors by the method of least squares", Phys. Rev. 40,
    207-227, 1932.

    Examples
    --------
    >>> x = np.linspace(0.0, 1.0, 11)
    >>> J = np.column_stack([np.ones_like(x), x])       # straight line a + b·x
    >>> r = 0.01 * np.array([1, -1] * 5 + [0])
    >>> s = parameter_statistics(J, r)
    >>> bool(s["identifiable"].all()), s["standard_errors"].round(4).tolist()
    (True, [0.0059, 0.0101])
    >>> s = parameter_statistics(np.column_stack([x, x]), r)   # two copies of one parameter
    >>> s["identifiable"].tolist()
    [False, False]
    >>> u = 0.1                # stated uncertainty, 10 x the scatter: the floor holds
    >>> s = parameter_statistics(J / u, r / u, min_residual_variance=1.0)
    >>> float(s["residual_variance"]), s["standard_errors"].round(4).tolist()
    (1.0, [0.0564, 0.0953])
    """
    J = np.atleast_2d(np.asarray(jacobian, dtype=float))
    r = np.asarray(residuals, dtype=float)
    m, n = J.shape
    names = list(names) if names is not None else [f"parameter {k}" for k in range(n)]
    dof = max(m - n, 1)
    s2 = max(float(np.sum(r ** 2) / dof), float(min_residual_variance))
    if not np.all(np.isfinite(J)):
        bad = np.full(n, np.inf)
        return {"standard_errors": bad, "correlation": np.full((n, n), np.nan),
                "covariance": np.full((n, n), np.inf), "residual_variance": s2,
                "identifiable": np.zeros(n, dtype=bool),
                "reasons": [["the model is not differentiable here (non-finite Jacobian)"]] * n,
                "singular_values": np.full(n, np.nan)}
    _, sv, vt = np.linalg.svd(J, full_matrices=False)
    keep = sv > rcond * (sv[0] if sv.size and sv[0] > 0 else 1.0)
    inv = np.zeros_like(sv)
    inv[keep] = 1.0 / sv[keep] ** 2
    cov = s2 * (vt.T * inv) @ vt
    reasons: list[list[str]] = [[] for _ in range(n)]
    # parameters with a share in a null direction are undetermined
    for k in np.flatnonzero(~keep):
        for i in np.flatnonzero(np.abs(vt[k]) > 0.1):
            reasons[i].append("the data do not determine it (its effect is zero or cancels "
                              "with other parameters)")
    se = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    se[[bool(rs) for rs in reasons]] = np.inf
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(np.sqrt(np.diag(cov)), np.sqrt(np.diag(cov)))
    for i in range(n):
        for j in range(n):
            if i != j and np.isfinite(corr[i, j]) and abs(corr[i, j]) > max_correlation:
                reasons[i].append(f"correlated with {names[j]} (r = {corr[i, j]:.4f}): the "
                                  "data determine only a combination of the two")
    if values is not None:
        vals = np.asarray(values, dtype=float)
        for i in range(n):
            if np.isfinite(se[i]) and se[i] > max_relative_error * abs(vals[i]):
                reasons[i].append(f"standard error {se[i]:.3g} is more than "
                                  f"{100 * max_relative_error:g} % of its value {vals[i]:.3g}")
    identifiable = np.array([not rs for rs in reasons])
    return {"standard_errors": se, "correlation": corr, "covariance": cov,
            "residual_variance": s2, "identifiable": identifiable, "reasons": reasons,
            "singular_values": sv}


def on_constraint(values: dict[str, float], names, refusal,
                  tolerance: float = CONSTRAINT_TOLERANCE) -> dict[str, str]:
    """The fitted parameters that sit on a constraint of the model: moved by ``tolerance``
    (relative) to one side, the model refuses them.

    A fit cannot step past a relation between parameters that the model enforces (a Θ law's
    f_b <= f_a, a Stribeck curve's F_S >= F_C): the trial is refused and the optimiser stays
    on this side.  Where the data ask for a value beyond it, the optimum ends pressed
    against it, and the value there is set by the constraint, not determined by the data.

    Parameters
    ----------
    values : dict
        The fitted values by name (SI).
    names : iterable of str
        The parameters to check.
    refusal : callable
        ``refusal(values)``: why the model refuses these values, or None if it takes them.

    Returns
    -------
    dict
        ``{name: why the model refuses the value beyond}`` of each parameter on a constraint.

    Examples
    --------
    >>> def refusal(v):
    ...     return "f_b must be <= f_a" if v["f_b"] > v["f_a"] else None
    >>> on_constraint({"f_a": 0.3, "f_b": 0.3}, ["f_a", "f_b"], refusal)
    {'f_a': 'f_b must be <= f_a', 'f_b': 'f_b must be <= f_a'}
    >>> on_constraint({"f_a": 0.3, "f_b": 0.2}, ["f_a", "f_b"], refusal)
    {}
    """
    out = {}
    for name in names:
        value = values[name]
        step = tolerance * (abs(value) or 1.0)
        for trial in (value - step, value + step):
            why = refusal({**values, name: trial})
            if why:
                out[name] = why
                break
    return out


def constraint_failure(values: dict[str, float], names: list[str], limits: list, refusal,
                       what: str, tolerance: float = CONSTRAINT_TOLERANCE) -> str | None:
    """Mark the fitted parameters on a constraint of the model (:func:`on_constraint`; those
    not already at a bound, ``limits[i]`` None) in ``limits`` as "constraint: WHY", and the
    failure that says so (None if there is none).  ``what``: the model's name in the text."""
    free = [name for name, limit in zip(names, limits) if limit is None]
    pinned = on_constraint(values, free, refusal, tolerance)
    if not pinned:
        return None
    for name, why in pinned.items():
        limits[names.index(name)] = f"constraint: {why}"
    shown = " and ".join(f"{name} = {values[name]:.6g}" for name in pinned)
    return (f"{shown} {'sit' if len(pinned) > 1 else 'sits'} on a constraint of the {what} "
            f"(one step beyond: {next(iter(pinned.values()))}): the data ask for values "
            f"beyond it, which the {what} cannot take, so the constraint set them, not the "
            "data; fix one of them or choose a model that can follow the data")


def drop_constrained(limits, standard_errors, identifiable, reasons) -> None:
    """Mark the parameters that sit on a constraint (``limits[i]`` "constraint: ...", see
    :func:`on_constraint`) as not determined, in place: no standard error (the Jacobian's
    finite differences step past the constraint into refused trials, which gave standard
    errors of 1e-13), not identifiable, with the reason."""
    for i, limit in enumerate(limits):
        if limit and limit.startswith("constraint"):
            standard_errors[i] = np.nan
            identifiable[i] = False
            reasons[i] = [*reasons[i], "it sits on a constraint of the model, which set its "
                                       "value (see the failure)"]


def parameter_report(result, texts: dict[str, str]) -> dict:
    """The ``parameters`` table of a fit's ``report.json``: per fitted parameter its value,
    the value as written in a case file (``texts[name]``), stage, start, bounds, standard
    errors (None where infinite) and identifiability with its reasons.

    ``result`` is a fit outcome with ``names``, ``values``, ``standard_errors``, ``stage_of``,
    ``initial``, ``bounds``, ``identifiable``, ``reasons`` and ``limits`` (friction and rotary
    fits alike).  ``at_limit`` says where a value sits on a bound ("lower bound", "upper
    bound") or on a constraint of the model ("constraint: WHY"): there the data did not
    determine it (None elsewhere).
    """
    table = {}
    for i, name in enumerate(result.names):
        value, se = float(result.values[i]), float(result.standard_errors[i])
        table[name] = {
            "value": value, "text": texts[name], "stage": result.stage_of[i],
            "initial": result.initial[i], "bounds": list(result.bounds[i]),
            "standard_error": se if np.isfinite(se) else None,
            "relative_standard_error": (se / abs(value) if np.isfinite(se) and value
                                        else None),
            "identifiable": bool(result.identifiable[i]),
            "at_limit": result.limits[i],
            "notes": result.reasons[i]}
    return table


def compare_signals(measured, model) -> dict[str, float | None]:
    """RMSE, largest deviation and coefficient of determination of a model signal against a
    measured one: R² = 1 − Σ(y − ŷ)²/Σ(y − ȳ)², None when the measurement does not vary.

    Examples
    --------
    >>> compare_signals(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 2.0]))
    {'rmse': 0.0, 'max_abs_error': 0.0, 'r2': 1.0}
    """
    measured = np.asarray(measured, dtype=float)
    resid = measured - np.asarray(model, dtype=float)
    ss_tot = float(np.sum((measured - measured.mean()) ** 2))
    return {"rmse": float(np.sqrt(np.mean(resid ** 2))),
            "max_abs_error": float(np.max(np.abs(resid))),
            "r2": 1.0 - float(np.sum(resid ** 2)) / ss_tot if ss_tot > 0 else None}


def repeat_scatter(measured, predicted) -> dict[str, float | int | None]:
    """Scatter of repeated measurements of one condition and a model's error against it.

    For k runs of the same seal at the same condition (measured levels y_i, the model's
    predictions ŷ_i of the same runs), after ISO 5725-2:1994 (precision of a measurement
    method from repeated tests) and JCGM 100:2008 (GUM, §4.2)::

        ȳ = Σ y_i / k,   s = √(Σ (y_i − ȳ)² / (k − 1)),   cv = s/ȳ,   u(ȳ) = s/√k
        error of the mean  e = (mean ŷ − ȳ)/ȳ,   in units of the scatter  z = (mean ŷ − ȳ)/s

    s is the standard deviation of a single run: a model whose |z| is below about 1 on one
    run is within what the rig repeats to, and the relative error of one run against the
    model cannot be resolved much below cv.

    Parameters
    ----------
    measured, predicted : array_like
        Measured and predicted friction levels of the runs [N] (same length, k >= 1).

    Returns
    -------
    dict
        ``runs`` (k), ``F_measured_mean_N``, ``F_measured_std_N`` (s, None for one run),
        ``cv`` (s/ȳ), ``F_measured_min_N``, ``F_measured_max_N``, ``standard_error_N``
        (s/√k), ``F_predicted_mean_N``, ``rel_error_of_mean`` (e), ``error_in_std`` (z).

    Examples
    --------
    Five runs of one O-ring at 5 bar (N) and a model that predicts 6.8 N for each:

    >>> r = repeat_scatter([7.18, 6.07, 8.02, 5.27, 7.20], [6.8] * 5)
    >>> r["runs"], round(r["F_measured_mean_N"], 3), round(r["cv"], 3), round(r["error_in_std"], 2)
    (5, 6.748, 0.16, 0.05)
    """
    y = np.asarray(measured, dtype=float).ravel()
    yhat = np.asarray(predicted, dtype=float).ravel()
    if y.size == 0 or y.size != yhat.size:
        raise ValueError(f"repeat_scatter: {y.size} measured and {yhat.size} predicted levels; "
                         "give one of each per run (at least one run)")
    mean, pred = float(y.mean()), float(yhat.mean())
    std = float(y.std(ddof=1)) if y.size > 1 else None
    return {"runs": int(y.size), "F_measured_mean_N": mean, "F_measured_std_N": std,
            "cv": std / mean if std is not None and mean else None,
            "F_measured_min_N": float(y.min()), "F_measured_max_N": float(y.max()),
            "standard_error_N": std / float(np.sqrt(y.size)) if std is not None else None,
            "F_predicted_mean_N": pred,
            "rel_error_of_mean": (pred - mean) / mean if mean else None,
            "error_in_std": (pred - mean) / std if std else None}
