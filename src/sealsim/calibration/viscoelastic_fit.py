r"""Viscoelastic identification from DMA data: master curve, shift law, Prony series, T_g.

Input: storage and loss moduli E′, E″ (or |E*| and tan δ) measured in frequency sweeps at
several temperatures (isotherms).

1. **Time–temperature superposition.**  The isotherms are sorted by temperature and each is
   shifted along log f onto its colder neighbour: the shift Δ = log10 a_T(T_k+1) −
   log10 a_T(T_k) is the mean, over the warmer curve's points, of the log f at which the
   colder curve has the same storage modulus minus the point's own log f (the colder curve
   interpolated in log–log by monotone cubics and continued as a power law from its three end points where the
   two do not overlap; pairwise shifting as in Gergesova et al. 2011 and in pyvisco).  The
   storage modulus alone defines the shift: the loss modulus of many polymers carries
   secondary relaxations that do not shift with the main one, so it is the check (it should
   fall on one curve too), not the criterion.  The cumulative shifts are the measured shift
   factors; their standard errors come from the scatter of each pair's point shifts.
2. **Shift law.**  WLF, :math:`\log_{10} a_T = -C_1 (T - T_r)/(C_2 + T - T_r)` (Williams,
   Landel & Ferry 1955), or Arrhenius, :math:`\log_{10} a_T = E_a/(R\ln 10)\,(1/T - 1/T_r)`,
   fitted to the measured shift factors (with a free offset: the measured ones are relative
   to an isotherm, the law to T_r), by least squares, weighted with the shift factors'
   standard errors; C1, C2 (or E_a) with standard errors
   (:func:`sealsim.calibration.statistics.parameter_statistics`).  Shift factors found by
   pairwise shifting are sums of the pairs' shifts, with correlated errors: the law is fitted
   to the pairwise increments instead (``cumulative=True``), which are independent, and the
   measured shifts are referred to their own value at T_r (the master curve at T_r holds the
   T_r isotherm unshifted, and the law meets it there).
3. **Prony series** :math:`E(t) = E_\infty + \sum_i E_i e^{-t/\tau_i}` on the master curve at
   T_r: relaxation times fixed, ``terms_per_decade`` per decade over the reduced-frequency
   range of the data (the usual collocation choice), the moduli E∞, E_i ≥ 0 from the
   non-negative least squares of the relative residuals of E′ and E″ (Lawson & Hanson's
   NNLS; Park & Schapery 1999 for the collocation), with a second-difference (Tikhonov)
   penalty on neighbouring E_i raised step by step until the smoothness check passes (NNLS
   alone gives sparse, spiky spectra on noisy data).  Smoothness check: the fitted E″(f)
   between the data points must not ripple (a spectrum too sparse for its data shows a bump
   of E″ per relaxation time): the largest deviation of log E″ from its running mean over one
   spacing of the relaxation times is reported, more than :data:`MAX_RIPPLE` is flagged.
4. **T_g** from the tan δ peak: the temperature at which tan δ is largest at 1 Hz, from each
   isotherm's tan δ interpolated to 1 Hz (a parabola through the largest three), without the
   shift law (a DMA T_g, typically 5–15 K above the DSC value: Menard, *Dynamic Mechanical
   Analysis*, 2nd ed., CRC 2008, ch. 5).

Why not pyvisco or mastercurves: pyvisco (NREL, Prony identification) installs a Jupyter/Voila
stack (~60 packages) for its notebook interface and mastercurves (Lennon et al. 2023)
scikit-learn for its Gaussian-process superposition; the two algorithms here are the standard
ones in ~150 lines of numpy/scipy, fast enough for CI, and report standard errors.

References
----------
- M. L. Williams, R. F. Landel, J. D. Ferry, J. Am. Chem. Soc. 77 (1955) 3701-3707.
- M. Gergesova, B. Zupančič, I. Saprunov, I. Emri, J. Rheol. 55 (2011) 1-16.
- S. W. Park, R. A. Schapery, Int. J. Solids Struct. 36 (1999) 1653-1675.
- C. L. Lawson, R. J. Hanson, Solving Least Squares Problems, Prentice-Hall 1974, ch. 23.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.optimize import least_squares, nnls

from sealsim.calibration.statistics import compare_signals, parameter_statistics
from sealsim.errors import InputError
from sealsim.properties.viscoelasticity import (
    _log10_shift,
    prony_loss_modulus,
    prony_storage_modulus,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["GAS_CONSTANT", "DMAData", "PronyFit", "ShiftFit", "fit_prony", "fit_shift_law",
           "isotherm_shifts", "law_rel_rmse", "master_curve", "tan_delta_peak",
           "tan_delta_peak_temperature"]

#: molar gas constant R [J/(mol K)] (CODATA 2018, exact)
GAS_CONSTANT = 8.314462618

#: Temperatures a DMA of a polymer is measured at [K] (-173 ... +527 degC; instruments reach
#: -150 ... +500 degC): a column in degC read as kelvin falls below it
DMA_TEMPERATURE_RANGE = (100.0, 800.0)

#: Storage moduli of a polymer [Pa]: a soft rubber's plateau (0.1 MPa) down to 10 kPa, a
#: glass (1-10 GPa) up to 100 GPa (the limits of a compound's rubbery and glassy moduli,
#: :class:`~sealsim.properties.elastomers.Elastomer`): MPa read as Pa falls below it
DMA_STORAGE_RANGE = (1e4, 1e11)

#: isotherms: points within this temperature of each other belong to one [K]
ISOTHERM_TOLERANCE = 1.5

#: largest ripple [decades] of the fitted log10 E'' about its running mean over one spacing
#: of the relaxation times that counts as smooth: 0.01 decades = 2.3 % (below the scatter of
#: a good DMA measurement); one time per decade ripples by 0.027 decades, two by 0.001
MAX_RIPPLE = 0.01

#: penalty weights tried in turn (the first whose fit is smooth is kept)
SMOOTHING_LEVELS = (0.0, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0)


@dataclass(frozen=True)
class DMAData:
    """DMA points: temperature [K], frequency [Hz], storage and loss modulus [Pa]."""

    temperature: np.ndarray
    frequency: np.ndarray
    storage: np.ndarray
    loss: np.ndarray
    name: str = "DMA"

    def __post_init__(self):
        arrays = [np.asarray(getattr(self, k), dtype=float)
                  for k in ("temperature", "frequency", "storage", "loss")]
        n = arrays[0].size
        if any(a.shape != (n,) for a in arrays) or n < 3:
            raise InputError(f"{self.name}: temperature, frequency, storage and loss modulus "
                             "must be equally long lists of at least 3 values")
        t, f, e1, e2 = arrays
        for label, a in (("frequency", f), ("storage modulus", e1), ("loss modulus", e2)):
            if not np.all(np.isfinite(a)) or np.any(a <= 0):
                k = int(np.flatnonzero(~np.isfinite(a) | (a <= 0))[0])
                raise InputError(f"{self.name}: {label} of point {k + 1} is {a[k]!r}; it must "
                                 "be finite and > 0 (log-log superposition)")
        lo, hi = DMA_TEMPERATURE_RANGE
        outside = ~((t >= lo) & (t <= hi))
        if np.any(outside):
            k = int(np.flatnonzero(outside)[0])
            raise InputError(f"{self.name}: temperature of point {k + 1} is {t[k]:.6g} K "
                             f"({t[k] - ZERO_CELSIUS_K:.6g} degC), outside {lo:g}-{hi:g} K where a "
                             "polymer's DMA is measured: check the temperature column's unit")
        lo, hi = DMA_STORAGE_RANGE
        outside = ~((e1 >= lo) & (e1 <= hi))
        if np.any(outside):
            k = int(np.flatnonzero(outside)[0])
            raise InputError(f"{self.name}: storage modulus of point {k + 1} is {e1[k]:.6g} Pa, "
                             f"outside {lo:g}-{hi:g} Pa where a polymer's lies (a soft rubber "
                             "to a stiff glass): check the modulus column's unit (MPa?)")
        for k, v in zip(("temperature", "frequency", "storage", "loss"), arrays):
            object.__setattr__(self, k, v)

    def isotherms(self) -> list[np.ndarray]:
        """Indices of the points of each isotherm, by increasing temperature."""
        order = np.argsort(self.temperature, kind="stable")
        groups, current = [], [order[0]]
        for i in order[1:]:
            if self.temperature[i] - self.temperature[current[0]] <= ISOTHERM_TOLERANCE:
                current.append(i)
            else:
                groups.append(np.array(current))
                current = [i]
        groups.append(np.array(current))
        return [g[np.argsort(self.frequency[g])] for g in groups]


@dataclass
class ShiftFit:
    """Measured shift factors and the law fitted to them."""

    temperatures: np.ndarray          # isotherm mean temperatures [K]
    log_shift: np.ndarray             # measured log10 a_T, relative to reference_temperature
    log_shift_stderr: np.ndarray
    law: str                          # "wlf" or "arrhenius"
    reference_temperature: float
    parameters: dict                  # {"c1", "c2"} or {"activation_energy"} (SI)
    standard_errors: dict
    identifiable: dict
    notes: list[str] = field(default_factory=list)
    #: for WLF: the temperature [K] below which the slope-continuous Arrhenius branch holds
    #: (the compound's T_g, as :class:`~sealsim.properties.elastomers.Elastomer` evaluates
    #: it), or None for WLF at every temperature
    arrhenius_below: float | None = None

    def log10_shift(self, temperature) -> np.ndarray:
        """log10 a_T of the fitted law at T [K] (relative to the reference temperature)."""
        if self.law == "wlf":
            return _log10_shift(np.asarray(temperature, dtype=float),
                                self.reference_temperature, self.parameters["c1"],
                                self.parameters["c2"], self.arrhenius_below)
        b = self.parameters["activation_energy"] / (GAS_CONSTANT * math.log(10.0))
        return b * (1.0 / np.asarray(temperature, dtype=float) - 1.0 / self.reference_temperature)


@dataclass
class PronyFit:
    """A Prony series at the reference temperature (SI) and how well it fits."""

    equilibrium_modulus: float
    moduli: np.ndarray
    relaxation_times: np.ndarray
    standard_errors: np.ndarray       # of [E_inf, E_1, ...]; inf for terms at zero
    rel_rmse: dict                    # {"storage", "loss"}
    r2: dict
    ripple: float                     # of log10 E'' about its running mean [decades]
    smooth: bool
    smoothing: float = 0.0            # weight of the second-difference penalty used
    notes: list[str] = field(default_factory=list)

    def storage(self, frequency) -> np.ndarray:
        return np.asarray(prony_storage_modulus(2 * np.pi * np.asarray(frequency, dtype=float),
                                                self.equilibrium_modulus, self.moduli,
                                                self.relaxation_times))

    def loss(self, frequency) -> np.ndarray:
        return np.asarray(prony_loss_modulus(2 * np.pi * np.asarray(frequency, dtype=float),
                                             self.equilibrium_modulus, self.moduli,
                                             self.relaxation_times))


def _inverse(x, y):
    """log f as a function of log E' of one isotherm (E' made increasing in f; monotone cubic
    interpolation, PCHIP, so that the curvature of the curve does not bias the shift), with
    straight-line (power-law) continuation from its three end points on either side."""
    y = np.maximum.accumulate(y)
    keep = np.r_[True, np.diff(y) > 0]
    xs, ys = x[keep], y[keep]
    inner = PchipInterpolator(ys, xs) if ys.size >= 2 else None
    lo = np.polyfit(y[:3], x[:3], 1) if np.ptp(y[:3]) > 0 else None
    hi = np.polyfit(y[-3:], x[-3:], 1) if np.ptp(y[-3:]) > 0 else None

    def f(v):
        v = np.asarray(v, dtype=float)
        out = inner(np.clip(v, ys[0], ys[-1])) if inner is not None else np.full(v.shape,
                                                                                   xs[0])
        if lo is not None:
            out = np.where(v < ys[0], np.polyval(lo, v), out)
        if hi is not None:
            out = np.where(v > ys[-1], np.polyval(hi, v), out)
        return out
    return f


def _pair_shift(lower, upper):
    """Shift Δ [decades] of the warmer isotherm ``upper`` onto the colder ``lower`` (each
    (log f, log E')): the mean over the warmer curve's points of the log f at which the colder
    curve has the same storage modulus, minus its own log f (the colder curve continued as a
    power law from its ends where the two do not overlap); its standard error and the number
    of points inside the colder curve's range."""
    x0, a0 = lower
    x1, a1 = upper
    if x0.size < 3 or x1.size < 3:
        raise InputError("an isotherm needs at least 3 frequencies to be shifted")
    a_sorted = np.maximum.accumulate(a0)
    inside = (a1 >= a_sorted[0]) & (a1 <= a_sorted[-1])
    use = inside if inside.sum() >= 3 else np.ones_like(inside)
    d = _inverse(x0, a0)(a1[use]) - x1[use]
    if not np.all(np.isfinite(d)):
        raise InputError("two neighbouring isotherms cannot be superposed: the storage "
                         "modulus does not change with frequency at their ends")
    se = float(np.std(d, ddof=1) / math.sqrt(d.size)) if d.size > 1 else math.inf
    return float(np.mean(d)), se, int(inside.sum())


def isotherm_shifts(data: DMAData) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Measured log10 a_T of every isotherm relative to the coldest, by pairwise shifting.

    Returns
    -------
    temperatures, log_shift, stderr : numpy.ndarray
        Mean temperature [K], cumulative log10 a_T [-] (0 for the coldest; a_T < 1 for the
        warmer ones) and its standard error (errors of the pairs added in quadrature).

    Examples
    --------
    Two isotherms of a power law E ∝ f^0.3, one shifted by 2 decades:

    >>> f = np.logspace(-1, 2, 8)
    >>> d = DMAData(np.r_[np.full(8, 250.0), np.full(8, 270.0)], np.r_[f, f],
    ...             np.r_[f ** 0.3, (f / 100) ** 0.3] * 1e6, np.r_[f ** 0.3, (f / 100) ** 0.3] * 2e5)
    >>> T, log_a, se = isotherm_shifts(d)
    >>> round(float(log_a[1]), 6)
    -2.0
    """
    groups = data.isotherms()
    if len(groups) < 2:
        raise InputError(f"{data.name}: time-temperature superposition needs frequency "
                         "sweeps at two or more temperatures; found one isotherm")
    curves = [(np.log10(data.frequency[g]), np.log10(data.storage[g])) for g in groups]
    temps = np.array([float(np.mean(data.temperature[g])) for g in groups])
    log_a = [0.0]
    var = [0.0]
    for k in range(1, len(curves)):
        if curves[k][0].size < 2:
            raise InputError(f"{data.name}: the isotherm at {temps[k] - 273.15:.1f} degC has "
                             "fewer than 2 frequencies")
        d, se, _ = _pair_shift(curves[k - 1], curves[k])
        # the warmer curve lies on the colder at log f + d: d = log a_T(warm) − log a_T(cold)
        log_a.append(log_a[-1] + d)
        var.append(var[-1] + se ** 2)
    return temps, np.array(log_a), np.sqrt(np.array(var))


def fit_shift_law(temperatures, log_shift, stderr, reference_temperature: float,
                  law: str = "wlf", cumulative: bool = False,
                  arrhenius_below: float | None = None) -> ShiftFit:
    """WLF or Arrhenius fitted to measured shift factors (see the module docstring).

    ``arrhenius_below`` (WLF only; the compound's T_g [K]): the law fitted is the one a
    compound evaluates (:func:`sealsim.properties.viscoelasticity.wlf_log10_shift` with
    ``arrhenius_below``): WLF above that temperature, below it the Arrhenius continuation
    whose value and slope meet the WLF there (Ferry 1980, ch. 11).  Shift factors measured
    below T_g are then fitted by that branch, not by a WLF the compound does not use there.

    The measured log a_T may have any offset (relative to one isotherm); the result's
    ``log_shift`` is re-referenced to ``reference_temperature`` with the fitted offset.

    ``cumulative=True`` for the shift factors of :func:`isotherm_shifts`: each is the sum of
    the pairwise shifts below it, so their errors are correlated (a random walk) and weighting
    them as independent biases the law and understates its errors.  The law is then fitted to
    the independent pairwise increments log a_T(T_k) − log a_T(T_k−1), each weighted with its
    own standard error (generalised least squares of the sums), and the parameters' standard
    errors are scaled by the Birge ratio when the increments scatter more than their stated
    errors (R. T. Birge, Phys. Rev. 40 (1932) 207): the pair errors come from the scatter of
    interpolated points, which are themselves correlated.
    The increments leave the offset open: the measured shifts are re-referenced to their own
    value at ``reference_temperature`` (interpolated between the isotherms), so the master
    curve at T_r holds the T_r isotherm unshifted and the law, which is 0 at T_r by its
    definition, meets the data there (Ferry, *Viscoelastic Properties of Polymers*, 3rd ed.,
    1980, ch. 11); outside the measured range, the offset that fits the law best.

    Examples
    --------
    >>> T = np.linspace(250.0, 350.0, 11)
    >>> log_a = -8.86 * (T - 300.0) / (101.6 + T - 300.0) + 1.5
    >>> fit = fit_shift_law(T, log_a, np.full(11, 0.01), 300.0)
    >>> round(fit.parameters["c1"], 4), round(fit.parameters["c2"], 3)
    (8.86, 101.6)
    >>> cum = fit_shift_law(T, log_a, 0.01 * np.sqrt(np.arange(11)), 300.0, cumulative=True)
    >>> round(cum.parameters["c1"], 4), round(cum.parameters["c2"], 3)
    (8.86, 101.6)
    """
    t = np.asarray(temperatures, dtype=float)
    y = np.asarray(log_shift, dtype=float)
    se = np.asarray(stderr, dtype=float)
    # the isotherm the shifts are relative to has no error of its own: weight by the median
    w = 1.0 / np.where(se > 0, se, np.median(se[se > 0]) if np.any(se > 0) else 1.0)
    tr = float(reference_temperature)
    t_a = None if arrhenius_below is None else float(arrhenius_below)
    if cumulative:
        steps = np.sqrt(np.maximum(np.diff(se ** 2), 0.0))
        if t.size < 2 or np.any(np.diff(t) <= 0) or not np.all(steps > 0):
            raise InputError("cumulative shift factors need ascending temperatures and "
                             "standard errors that grow from one isotherm to the next")
    if law == "wlf":
        if t.size < 4:
            raise InputError("a WLF fit needs shift factors at 4 or more temperatures "
                             f"(found {t.size}): measure frequency sweeps at more "
                             "temperatures (an Arrhenius law needs 3)")

        def shape(x):
            return _log10_shift(t, tr, x[0], x[1], t_a)
        # WLF finite over the data (down to T_a where the Arrhenius branch takes over)
        lo_c2 = max(1.0, tr - (float(t.min()) if t_a is None else t_a) + 1.0)
        start = [10.0, max(100.0, lo_c2 + 20.0)]
        lower, upper = [0.0, lo_c2], [200.0, 5000.0]
        names = ["c1", "c2"]
        factor = 1.0
    elif law == "arrhenius":
        if t.size < 3:
            raise InputError("an Arrhenius fit needs shift factors at 3 or more temperatures")
        factor = 1e5                                  # E_a fitted in 100 kJ/mol

        def shape(x):
            return x[0] * factor / (GAS_CONSTANT * math.log(10.0)) * (1 / t - 1 / tr)
        start, lower, upper = [1.0], [-np.inf], [np.inf]
        names = ["activation_energy"]
    else:
        raise InputError(f"shift law {law!r} is not known; choose 'wlf' or 'arrhenius'")
    if law != "wlf" and t_a is not None:
        raise InputError("arrhenius_below is the WLF law's Arrhenius branch; an Arrhenius "
                         "law has none")
    if cumulative:
        res = least_squares(lambda x: (np.diff(shape(x)) - np.diff(y)) / steps, start,
                            bounds=(lower, upper))
        stats = parameter_statistics(res.jac, res.fun, values=res.x, names=names,
                                     min_residual_variance=1.0)
        offset, se = _reference_offset(t, y, se, w, tr, shape(res.x))
        x = np.r_[res.x, offset]
        sx = np.r_[stats["standard_errors"], np.nan]
        names = names + ["offset"]
        stats["identifiable"] = np.r_[stats["identifiable"], True]
        stats["reasons"] = list(stats["reasons"]) + [[]]
    else:
        start = start + [float(np.interp(tr, t, y))]
        res = least_squares(lambda x: (shape(x[:-1]) + x[-1] - y) * w, start,
                            bounds=(lower + [-np.inf], upper + [np.inf]))
        names = names + ["offset"]
        stats = parameter_statistics(res.jac, res.fun, values=res.x, names=names)
        x, sx = res.x.copy(), stats["standard_errors"].copy()
    x[0] *= factor                                    # E_a back to J/mol (1 for WLF)
    sx[0] *= factor
    params = {n: float(v) for n, v in zip(names[:-1], x[:-1])}
    errors = {n: (float(v) if math.isfinite(v) else None) for n, v in zip(names[:-1], sx[:-1])}
    ident = {n: bool(v) for n, v in zip(names[:-1], stats["identifiable"][:-1])}
    fit = ShiftFit(t, y - x[-1], se, law, tr, params, errors, ident,
                   arrhenius_below=t_a)
    for n, reasons in zip(names[:-1], stats["reasons"][:-1]):
        fit.notes += [f"{n}: {r}" for r in reasons]
    return fit


def law_rel_rmse(data: DMAData, shift: ShiftFit, prony: PronyFit) -> dict[str, float]:
    """RMS relative error of E′ and E″ of the Prony series moved to each isotherm's
    temperature by the fitted shift law, against every measured point: the error of the
    compound (Prony series and law) on its own data, where ``prony.rel_rmse`` is that of the
    series on the master curve built with the measured shifts.

    Examples
    --------
    Isotherms shifted exactly by an Arrhenius law: the law's error is the series' own on the
    master curve.

    >>> f = np.logspace(-1, 1, 5)
    >>> tau = 10.0 ** np.arange(-4.0, 3.0, 0.5)
    >>> temps = np.array([300.0, 310.0, 320.0])
    >>> log_a = 1e5 / (GAS_CONSTANT * math.log(10.0)) * (1 / temps - 1 / 300.0)
    >>> w = 2 * np.pi * np.concatenate([f * 10.0 ** a for a in log_a])
    >>> d = DMAData(np.repeat(temps, 5), np.tile(f, 3),
    ...             prony_storage_modulus(w, 1e6, np.full(tau.size, 1e6), tau),
    ...             prony_loss_modulus(w, 1e6, np.full(tau.size, 1e6), tau))
    >>> shift = fit_shift_law(*isotherm_shifts(d), 300.0, "arrhenius", cumulative=True)
    >>> prony = fit_prony(*master_curve(d, shift))
    >>> errors = law_rel_rmse(d, shift, prony)
    >>> round(abs(errors["storage"] - prony.rel_rmse["storage"]), 4)
    0.0
    """
    f_r, storage, loss = master_curve(data, shift, measured=False)
    return {key: float(np.sqrt(np.mean((model / measured - 1.0) ** 2)))
            for key, model, measured in (("storage", prony.storage(f_r), storage),
                                         ("loss", prony.loss(f_r), loss))}


def _reference_offset(t, y, se, w, tr: float, law) -> tuple[float, np.ndarray]:
    """Offset of cumulative shift factors ``y`` [decades] at the temperatures ``t`` [K] and
    their standard errors ``se`` referred to it.  Where the isotherms span the reference
    temperature ``tr`` (an end isotherm within :data:`ISOTHERM_TOLERANCE` counts as at
    ``tr``): their value there, and the errors of the sums of the pairwise increments between
    each isotherm and ``tr``, √|se² − se²(tr)| (0 at ``tr``); else the weighted mean (weights
    ``w``) of their distance from the fitted ``law`` values, errors as given."""
    if t.min() - ISOTHERM_TOLERANCE <= tr <= t.max() + ISOTHERM_TOLERANCE:
        return (float(np.interp(tr, t, y)),
                np.sqrt(np.abs(se ** 2 - np.interp(tr, t, se ** 2))))
    return float(np.sum(w ** 2 * (y - law)) / np.sum(w ** 2)), se


def fit_prony(frequency, storage, loss, terms_per_decade: float = 2.0,
              smoothing: float | None = None) -> PronyFit:
    """Prony series fitted to a master curve E′(f_r), E″(f_r) (see the module docstring).

    Parameters
    ----------
    frequency : array_like
        Reduced frequency f_r [Hz].
    storage, loss : array_like
        E′, E″ [Pa].
    terms_per_decade : float
        Relaxation times per decade (2: one per decade leaves a ripple of ≈ 6 % in E″).
    smoothing : float, optional
        Weight λ of a penalty λ·n·‖Δ²E_i/E_ref‖² on the second difference of the moduli of
        neighbouring relaxation times (Tikhonov; n residuals, E_ref the median E′); default:
        the smallest of :data:`SMOOTHING_LEVELS` whose fit passes the smoothness check.

    Examples
    --------
    >>> f = np.logspace(-3, 3, 25)
    >>> tau = 10.0 ** np.arange(-3.0, 3.0, 0.5)
    >>> e_i = 5e5 * np.exp(-0.5 * (np.log10(tau) / 1.5) ** 2)
    >>> w = 2 * np.pi * f
    >>> e1 = prony_storage_modulus(w, 2e6, e_i, tau)
    >>> e2 = prony_loss_modulus(w, 2e6, e_i, tau)
    >>> fit = fit_prony(f, e1, e2)
    >>> fit.rel_rmse["storage"] < 0.01, fit.rel_rmse["loss"] < 0.01, fit.smooth
    (True, True, True)
    """
    f = np.asarray(frequency, dtype=float)
    e1 = np.asarray(storage, dtype=float)
    e2 = np.asarray(loss, dtype=float)
    if not (f.shape == e1.shape == e2.shape) or f.size < 3:
        raise InputError("the master curve needs equally long frequency, storage and loss "
                         "lists of at least 3 points")
    if not terms_per_decade > 0:
        raise InputError(f"terms_per_decade = {terms_per_decade!r} must be > 0")
    w = 2 * np.pi * f
    # relaxation times on whole decades (times 1/terms_per_decade), spanning 1/ω of the data
    lo = math.floor(math.log10(1.0 / w.max()) * terms_per_decade) / terms_per_decade
    hi = math.ceil(math.log10(1.0 / w.min()) * terms_per_decade) / terms_per_decade
    tau = 10.0 ** np.arange(lo, hi + 0.5 / terms_per_decade, 1.0 / terms_per_decade)
    wt = w[:, None] * tau[None, :]
    a_storage = np.column_stack([np.ones_like(w), wt ** 2 / (1 + wt ** 2)]) / e1[:, None]
    a_loss = np.column_stack([np.zeros_like(w), wt / (1 + wt ** 2)]) / e2[:, None]
    A = np.vstack([a_storage, a_loss])
    b = np.ones(2 * f.size)
    scale = np.max(np.abs(A), axis=0)
    scale[scale == 0] = 1.0
    levels = [smoothing] if smoothing is not None else list(SMOOTHING_LEVELS)
    for level in levels:
        fit = _nnls_prony(A, b, scale, tau, float(np.median(e1)), level, f, e1, e2)
        if fit.smooth:
            break
    return fit


def _nnls_prony(A, b, scale, tau, e_ref, smoothing, f, e1, e2) -> PronyFit:
    """One NNLS solve with the penalty ``smoothing`` on the second difference of E_i/E_ref."""
    As = A / scale
    rows, rhs = As, b
    if smoothing > 0 and tau.size > 2:
        d2 = np.diff(np.eye(tau.size), 2, axis=0) / e_ref
        penalty = np.hstack([np.zeros((d2.shape[0], 1)), d2]) / scale
        rows = np.vstack([As, math.sqrt(smoothing * b.size) * penalty])
        rhs = np.r_[b, np.zeros(d2.shape[0])]
    x, _ = nnls(rows, rhs, maxiter=50 * A.shape[1])
    x = x / scale
    resid = A @ x - b
    active = x > 0
    stats = parameter_statistics(A[:, active], resid, values=x[active])
    se = np.full(x.size, np.inf)
    se[active] = stats["standard_errors"]
    fit = PronyFit(float(x[0]), x[1:], tau, se, {}, {}, 0.0, True, smoothing=smoothing)
    for key, data, model in (("storage", e1, fit.storage(f)), ("loss", e2, fit.loss(f))):
        fit.rel_rmse[key] = float(np.sqrt(np.mean(((model - data) / data) ** 2)))
        fit.r2[key] = compare_signals(np.log10(data), np.log10(model))["r2"]
    # ripple: the fitted log E'' against its running mean over one spacing of the relaxation
    # times (the period of the ripple of a sparse spectrum; a real curvature c of log E''
    # departs from such a mean by only c·w²/24)
    step = 0.01
    grid = np.log10(f.min()) + np.arange(0.0, np.log10(f.max() / f.min()) + 1e-9, step)
    g = np.log10(fit.loss(10.0 ** grid))
    spacing = float(np.median(np.diff(np.log10(tau)))) if tau.size > 1 else 1.0
    window = 2 * int(round(0.5 * spacing / step)) + 1
    if g.size > 2 * window:
        mean = np.convolve(g, np.ones(window) / window, mode="valid")
        fit.ripple = float(np.max(np.abs(g[window // 2:-(window // 2)] - mean)))
    fit.smooth = fit.ripple <= MAX_RIPPLE
    if not fit.smooth:
        fit.notes.append(f"the fitted loss modulus ripples by {fit.ripple:.3f} decades about "
                         f"its running mean (more than {MAX_RIPPLE:g}) at the "
                         f"largest smoothing tried ({smoothing:g}): use more terms per decade")
    zero = int(np.sum(~active[1:]))
    if zero:
        fit.notes.append(f"{zero} of {tau.size} relaxation times got a zero modulus (the "
                         "non-negativity bound): their standard errors are not defined")
    return fit


def tan_delta_peak(frequency, storage, loss) -> float | None:
    """Frequency [Hz] of the largest tan δ = E″/E′ (parabola through the peak in log f), or
    None if the largest value is at an end of the data (no peak inside).

    Examples
    --------
    >>> f = np.logspace(-2, 2, 41)
    >>> td = np.exp(-np.log10(f / 3.0) ** 2)
    >>> round(tan_delta_peak(f, np.ones_like(f), td), 3)
    3.0
    """
    f = np.asarray(frequency, dtype=float)
    order = np.argsort(f)
    x = np.log10(f[order])
    td = (np.asarray(loss, dtype=float) / np.asarray(storage, dtype=float))[order]
    k = int(np.argmax(td))
    if k == 0 or k == x.size - 1:
        return None
    xs, ys = x[k - 1:k + 2], td[k - 1:k + 2]
    denom = (xs[0] - xs[1]) * (xs[0] - xs[2]) * (xs[1] - xs[2])
    a = (xs[2] * (ys[1] - ys[0]) + xs[1] * (ys[0] - ys[2]) + xs[0] * (ys[2] - ys[1])) / denom
    bq = (xs[2] ** 2 * (ys[0] - ys[1]) + xs[1] ** 2 * (ys[2] - ys[0])
          + xs[0] ** 2 * (ys[1] - ys[2])) / denom
    if a >= 0:
        return float(10 ** xs[1])
    return float(10 ** (-bq / (2 * a)))


def tan_delta_peak_temperature(data: DMAData, frequency: float = 1.0) -> float | None:
    """Temperature [K] of the largest tan δ at ``frequency`` [Hz] (each isotherm's tan δ
    interpolated in log f; a parabola through the largest three isotherms), or None when the
    peak is at the coldest or warmest isotherm or no isotherm spans the frequency.

    Examples
    --------
    >>> T = np.repeat([250.0, 260.0, 270.0, 280.0, 290.0], 3)
    >>> f = np.tile([0.1, 1.0, 10.0], 5)
    >>> td = 1.0 - ((T - 272.0) / 40.0) ** 2
    >>> round(tan_delta_peak_temperature(DMAData(T, f, np.full(15, 1e6), td * 1e6)), 1)
    272.0
    """
    temps, values = [], []
    for g in data.isotherms():
        f = data.frequency[g]
        if f.min() <= frequency <= f.max():
            td = data.loss[g] / data.storage[g]
            temps.append(float(np.mean(data.temperature[g])))
            values.append(float(np.interp(math.log10(frequency), np.log10(f), td)))
    if len(temps) < 3:
        return None
    x, y = np.array(temps), np.array(values)
    k = int(np.argmax(y))
    if k == 0 or k == x.size - 1:
        return None
    a, b, _ = np.polyfit(x[k - 1:k + 2], y[k - 1:k + 2], 2)
    return float(-b / (2 * a)) if a < 0 else float(x[k])


def master_curve(data: DMAData, shift: ShiftFit, measured: bool = True):
    """Reduced frequency f·a_T [Hz], E′, E″ of every point at the shift's reference
    temperature: with the measured shift factors of each isotherm (``measured``), else with
    the fitted law."""
    f_r = np.empty_like(data.frequency)
    for g, t, log_a in zip(data.isotherms(), shift.temperatures, shift.log_shift):
        f_r[g] = data.frequency[g] * 10.0 ** (log_a if measured else shift.log10_shift(t))
    return f_r, data.storage, data.loss
