"""Linear viscoelasticity of elastomers: WLF shift, reduced time, Prony series, structural
relaxation.

Small, pure, vectorised functions (a scalar in gives a Python ``float`` out), SI units:
temperature in K, moduli in Pa, time in s.  A *frequency* is cyclic, in Hz, unless the
parameter is called ``angular_frequency`` (rad/s).

* WLF time–temperature superposition: :func:`wlf_log10_shift`, :func:`wlf_shift_factor`, the
  universal constants :data:`WLF_UNIVERSAL` and :data:`WLF_UNIVERSAL_TS`, with an optional
  slope-continuous Arrhenius continuation below a temperature (used below T_g by
  :class:`~sealsim.properties.elastomers.Elastomer`); :func:`reduced_time` and
  :func:`reduced_time_history` (thermorheologically simple materials).
* Prony series (generalised Maxwell model): :func:`prony_relaxation_modulus`,
  :func:`prony_storage_modulus`, :func:`prony_loss_modulus`.
* Structural relaxation across the glass transition: :func:`fictive_temperature_step` and
  :func:`fictive_temperature` (Tool–Narayanaswamy, in the reduced time of the WLF/Arrhenius
  shift); the thermal strain it drives is
  :func:`sealsim.properties.thermal_expansion.thermal_strain`.

Tags after a reference: [L] a standard literature or handbook value not re-checked against the
source here; [D] derived by sealsim (reproducible from the equations shown).

References
----------
- M. L. Williams, R. F. Landel, J. D. Ferry, J. Am. Chem. Soc. 77 (1955) 3701–3707 (WLF).
- J. D. Ferry, Viscoelastic Properties of Polymers, 3rd ed., Wiley 1980, ch. 11 (time–temperature
  superposition; Arrhenius-like shift in the glass) [L].
- L. W. Morland, E. H. Lee, Trans. Soc. Rheol. 4 (1960) 233–263 (reduced time under a
  transient temperature) [L].
- N. W. Tschoegl, The Phenomenological Theory of Linear Viscoelastic Behavior, Springer 1989
  (Prony / generalised Maxwell model) [L].
- A. Q. Tool, J. Am. Ceram. Soc. 29 (1946) 240–253; O. S. Narayanaswamy, J. Am. Ceram. Soc.
  54 (1971) 491–498; C. T. Moynihan et al., Ann. N. Y. Acad. Sci. 279 (1976) 15–35
  (fictive temperature, structural relaxation, cooling-rate dependence of T_g).
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from sealsim.errors import InputError
from sealsim.properties._checks import _array, _broadcast, _out, _scalar

__all__ = [
    "WLF_UNIVERSAL",
    "WLF_UNIVERSAL_TS",
    "WLFConstants",
    "fictive_temperature",
    "fictive_temperature_step",
    "prony_loss_modulus",
    "prony_relaxation_modulus",
    "prony_storage_modulus",
    "reduced_time",
    "reduced_time_history",
    "wlf_log10_shift",
    "wlf_shift_factor",
]


class WLFConstants(NamedTuple):
    """WLF constants with the reference temperature given as an offset from T_g.

    Attributes
    ----------
    c1 : float
        C1 [-].
    c2 : float
        C2 [K].
    offset_from_tg : float
        Reference temperature minus glass transition temperature [K].
    """

    c1: float
    c2: float
    offset_from_tg: float


#: "Universal" WLF constants with T_ref = T_g (Williams, Landel & Ferry 1955) [L].
WLF_UNIVERSAL = WLFConstants(c1=17.44, c2=51.6, offset_from_tg=0.0)
#: "Universal" WLF constants with T_ref = T_s ≈ T_g + 50 K (Williams, Landel & Ferry 1955) [L].
WLF_UNIVERSAL_TS = WLFConstants(c1=8.86, c2=101.6, offset_from_tg=50.0)


# ---------------------------------------------------------------------------------------------
# WLF time–temperature superposition
# ---------------------------------------------------------------------------------------------


def _wlf_params(
    reference_temperature: float, c1: float, c2: float, arrhenius_below: float | None
) -> tuple[float, float, float, float | None]:
    t_ref = _scalar(reference_temperature, "reference_temperature", "K", lo=0.0, lo_open=True)
    c1 = _scalar(c1, "c1", "-", lo=0.0, lo_open=True)
    c2 = _scalar(c2, "c2", "K", lo=0.0, lo_open=True)
    if arrhenius_below is not None:
        arrhenius_below = _scalar(
            arrhenius_below, "arrhenius_below", "K", lo=max(t_ref - c2, 0.0), lo_open=True
        )
    return t_ref, c1, c2, arrhenius_below


def _log10_shift(
    t: np.ndarray, t_ref: float, c1: float, c2: float, t_a: float | None
) -> np.ndarray:
    """WLF with optional slope-continuous Arrhenius branch below ``t_a`` (inputs validated)."""
    def wlf(d):
        return -c1 * d / (c2 + d)

    if t_a is None:
        return wlf(t - t_ref)
    d_a = t_a - t_ref
    y_a = wlf(d_a)
    b = c1 * c2 * t_a**2 / (c2 + d_a) ** 2  # K; slope continuity at t_a

    def arrhenius(temperature):
        return y_a + b * (1.0 / temperature - 1.0 / t_a)

    if np.ndim(t) == 0:  # one temperature (a time step): its branch only, in float arithmetic
        x = float(t)
        return np.asarray(wlf(x - t_ref) if x >= t_a else arrhenius(x))
    d = np.where(t >= t_a, t - t_ref, d_a)  # keep the unused branch finite
    return np.where(t >= t_a, wlf(d), arrhenius(t))


def wlf_log10_shift(
    temperature: Any,
    reference_temperature: float,
    c1: float = WLF_UNIVERSAL.c1,
    c2: float = WLF_UNIVERSAL.c2,
    *,
    arrhenius_below: float | None = None,
) -> np.ndarray | float:
    r"""Decadic logarithm of the WLF time–temperature shift factor a_T.

    .. math::

        \log_{10} a_T = -\frac{C_1 (T - T_\mathrm{ref})}{C_2 + T - T_\mathrm{ref}}

    a_T multiplies a frequency (f_r = f·a_T) and divides a time (ξ = t/a_T); a_T = 1 at
    T_ref, a_T < 1 above it.

    The formula diverges at T = T_ref − C2. Behaviour below:

    * ``arrhenius_below=None`` (default): temperatures ≤ T_ref − C2 raise :class:`InputError`.
    * ``arrhenius_below=T_a``: below T_a the Arrhenius form
      :math:`\log_{10} a_T = \log_{10} a_T(T_a) + B\,(1/T - 1/T_a)` is used, with
      :math:`B = C_1 C_2 T_a^2/(C_2 + T_a - T_\mathrm{ref})^2` [K] so that value and slope are
      continuous at T_a (activation energy E_a = B·R·ln 10; ≈ 400 kJ/mol for the universal
      constants and T_g ≈ 250 K). WLF above and Arrhenius below T_g is the usual engineering
      convention, WLF being an equilibrium-liquid law (Ferry 1980, ch. 11) [L].
      :class:`~sealsim.properties.elastomers.Elastomer` uses T_a = T_g.

    Parameters
    ----------
    temperature : array_like
        Temperature T [K], > 0.
    reference_temperature : float
        WLF reference temperature T_ref [K] (T_g for :data:`WLF_UNIVERSAL`).
    c1 : float, default 17.44
        WLF constant C1 [-], > 0.
    c2 : float, default 51.6
        WLF constant C2 [K], > 0.
    arrhenius_below : float, optional
        Temperature T_a [K] below which the Arrhenius continuation is used; must be
        > T_ref − C2.

    Returns
    -------
    float or numpy.ndarray
        log10 a_T [-].

    References
    ----------
    Williams, Landel & Ferry, J. Am. Chem. Soc. 77 (1955) 3701.

    Examples
    --------
    NBR, T_g = −25 °C, at 20 °C (universal constants: −17.44·45/(51.6 + 45) = −8.12):

    >>> wlf_log10_shift(293.15, 248.15)
    -8.12
    """
    t_ref, c1, c2, t_a = _wlf_params(reference_temperature, c1, c2, arrhenius_below)
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    if t_a is None:
        t = _array(temperature, "temperature", "K", lo=t_ref - c2, lo_open=True)
    return _out(_log10_shift(t, t_ref, c1, c2, t_a))


def wlf_shift_factor(
    temperature: Any,
    reference_temperature: float,
    c1: float = WLF_UNIVERSAL.c1,
    c2: float = WLF_UNIVERSAL.c2,
    *,
    arrhenius_below: float | None = None,
) -> np.ndarray | float:
    r"""WLF shift factor :math:`a_T = 10^{\log_{10} a_T}` (see :func:`wlf_log10_shift`).

    Parameters
    ----------
    temperature : array_like
        Temperature T [K].
    reference_temperature : float
        WLF reference temperature T_ref [K].
    c1 : float, default 17.44
        WLF constant C1 [-].
    c2 : float, default 51.6
        WLF constant C2 [K].
    arrhenius_below : float, optional
        Temperature [K] below which the Arrhenius continuation is used.

    Returns
    -------
    float or numpy.ndarray
        a_T [-]; 1 at the reference temperature.

    References
    ----------
    Williams, Landel & Ferry, J. Am. Chem. Soc. 77 (1955) 3701.

    Examples
    --------
    >>> wlf_shift_factor(248.15, 248.15)
    1.0
    """
    return _out(
        10.0
        ** np.asarray(
            wlf_log10_shift(
                temperature, reference_temperature, c1, c2, arrhenius_below=arrhenius_below
            )
        )
    )


def _inverse_log10_shift(
    y: np.ndarray, t_ref: float, c1: float, c2: float, t_a: float | None
) -> np.ndarray:
    """Temperature [K] at which log10 a_T = y (inverse of :func:`_log10_shift`); NaN if none."""
    y = np.asarray(y, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        # WLF: d = -C2 y / (C1 + y), defined for y > -C1
        t_wlf = np.where(y > -c1, t_ref - c2 * y / (c1 + np.where(y > -c1, y, 0.0)), np.nan)
        if t_a is None:
            return t_wlf
        d_a = t_a - t_ref
        y_a = -c1 * d_a / (c2 + d_a)
        b = c1 * c2 * t_a**2 / (c2 + d_a) ** 2
        t_arr = 1.0 / (1.0 / t_a + (y - y_a) / b)
        return np.where(y > y_a, t_arr, t_wlf)


def reduced_time(time: Any, shift_factor: Any) -> np.ndarray | float:
    r"""Reduced time at constant temperature, :math:`\xi = t / a_T`.

    Parameters
    ----------
    time : array_like
        Time t [s], >= 0.
    shift_factor : array_like
        Shift factor a_T [-] at the (constant) temperature, > 0, relative to the reference
        temperature of the relaxation data used with ξ.

    Returns
    -------
    float or numpy.ndarray
        Reduced time ξ [s].

    References
    ----------
    Ferry (1980), ch. 11 [L].

    Examples
    --------
    >>> reduced_time(10.0, 1e-3)
    10000.0
    """
    t = _array(time, "time", "s", lo=0.0)
    a = _array(shift_factor, "shift_factor", "-", lo=0.0, lo_open=True)
    t, a = _broadcast(t, a, names="time and shift_factor")
    return _out(t / a)


def reduced_time_history(time: Any, shift_factor: Any) -> np.ndarray:
    r"""Reduced time for a temperature history, :math:`\xi(t) = \int_0^t dt'/a_T(T(t'))`.

    The integral is evaluated with the trapezoidal rule from ``time[0]`` (ξ = 0 there).

    Parameters
    ----------
    time : array_like
        Strictly increasing time points t [s], 1-D.
    shift_factor : array_like
        a_T(T(t)) [-] at the same points, > 0.

    Returns
    -------
    numpy.ndarray
        Reduced time ξ [s] at each time point.

    References
    ----------
    L. W. Morland, E. H. Lee, Trans. Soc. Rheol. 4 (1960) 233–263 (thermorheologically simple
    materials under transient temperature) [L].

    Examples
    --------
    >>> reduced_time_history([0.0, 1.0, 2.0], [1.0, 1.0, 0.5])
    array([0. , 1. , 2.5])
    """
    t = _array(time, "time", "s")
    a = _array(shift_factor, "shift_factor", "-", lo=0.0, lo_open=True)
    if t.ndim != 1 or t.size < 1 or a.shape != t.shape:
        raise InputError(
            f"time and shift_factor must be 1-D arrays of the same length; got shapes "
            f"{t.shape} and {a.shape}"
        )
    if np.any(np.diff(t) <= 0.0):
        raise InputError("time must be strictly increasing [s]")
    inv = 1.0 / a
    steps = 0.5 * (inv[1:] + inv[:-1]) * np.diff(t)
    return np.concatenate(([0.0], np.cumsum(steps)))


# ---------------------------------------------------------------------------------------------
# Prony series
# ---------------------------------------------------------------------------------------------


def _prony_params(e_inf: float, e_i: Any, tau_i: Any) -> tuple[float, np.ndarray, np.ndarray]:
    e_inf = _scalar(e_inf, "e_inf", "Pa", lo=0.0)
    e = np.atleast_1d(_array(e_i, "e_i", "Pa", lo=0.0))
    tau = np.atleast_1d(_array(tau_i, "tau_i", "s", lo=0.0, lo_open=True))
    if e.ndim != 1 or e.shape != tau.shape or e.size == 0:
        raise InputError(
            f"e_i and tau_i must be 1-D and of equal, non-zero length; got shapes {e.shape} "
            f"and {tau.shape}"
        )
    return e_inf, e, tau


def prony_relaxation_modulus(t: Any, e_inf: float, e_i: Any, tau_i: Any) -> np.ndarray | float:
    r"""Relaxation modulus of a Prony series (generalised Maxwell model).

    .. math::

        E(t) = E_\infty + \sum_i E_i\,e^{-t/\tau_i}

    Parameters
    ----------
    t : array_like
        Time (or reduced time) t [s], >= 0.
    e_inf : float
        Equilibrium modulus E∞ [Pa], >= 0.
    e_i : array_like
        Prony moduli E_i [Pa], >= 0.
    tau_i : array_like
        Relaxation times τ_i [s], > 0.

    Returns
    -------
    float or numpy.ndarray
        E(t) [Pa]; E(0) = E∞ + ΣE_i, E(∞) = E∞.

    References
    ----------
    Tschoegl (1989) [L].

    Examples
    --------
    >>> prony_relaxation_modulus(0.0, 1.0, [2.0, 3.0], [1.0, 10.0])
    6.0
    """
    e_inf, e, tau = _prony_params(e_inf, e_i, tau_i)
    tt = _array(t, "t", "s", lo=0.0)
    return _out(e_inf + np.sum(e * np.exp(-tt[..., None] / tau), axis=-1))


def prony_storage_modulus(
    angular_frequency: Any, e_inf: float, e_i: Any, tau_i: Any
) -> np.ndarray | float:
    r"""Storage modulus of a Prony series.

    .. math::

        E'(\omega) = E_\infty + \sum_i E_i\,\frac{\omega^2\tau_i^2}{1 + \omega^2\tau_i^2}

    Parameters
    ----------
    angular_frequency : array_like
        ω [rad/s] (ω = 2π f), >= 0.
    e_inf : float
        E∞ [Pa].
    e_i : array_like
        E_i [Pa].
    tau_i : array_like
        τ_i [s].

    Returns
    -------
    float or numpy.ndarray
        E' [Pa]; E'(0) = E∞, E'(∞) = E∞ + ΣE_i.

    References
    ----------
    Tschoegl (1989) [L].

    Examples
    --------
    >>> prony_storage_modulus(1.0, 1.0, [2.0], [1.0])
    2.0
    """
    e_inf, e, tau = _prony_params(e_inf, e_i, tau_i)
    w = _array(angular_frequency, "angular_frequency", "rad/s", lo=0.0)
    wt2 = (w[..., None] * tau) ** 2
    return _out(e_inf + np.sum(e * wt2 / (1.0 + wt2), axis=-1))


def prony_loss_modulus(
    angular_frequency: Any, e_inf: float, e_i: Any, tau_i: Any
) -> np.ndarray | float:
    r"""Loss modulus of a Prony series.

    .. math::

        E''(\omega) = \sum_i E_i\,\frac{\omega\tau_i}{1 + \omega^2\tau_i^2}

    Parameters
    ----------
    angular_frequency : array_like
        ω [rad/s], >= 0.
    e_inf : float
        E∞ [Pa] (does not enter E'').
    e_i : array_like
        E_i [Pa].
    tau_i : array_like
        τ_i [s].

    Returns
    -------
    float or numpy.ndarray
        E'' [Pa].

    References
    ----------
    Tschoegl (1989) [L].

    Examples
    --------
    >>> prony_loss_modulus(1.0, 1.0, [2.0], [1.0])
    1.0
    """
    _, e, tau = _prony_params(e_inf, e_i, tau_i)
    w = _array(angular_frequency, "angular_frequency", "rad/s", lo=0.0)
    wt = w[..., None] * tau
    return _out(np.sum(e * wt / (1.0 + wt**2), axis=-1))


# ---------------------------------------------------------------------------------------------
# structural relaxation: fictive temperature
# ---------------------------------------------------------------------------------------------


def fictive_temperature_step(
    departures: Any, temperature_change: float, reduced_time_increments: Any, weights: Any
) -> np.ndarray:
    r"""One step of the Tool–Narayanaswamy fictive temperature in reduced time.

    With a normalised relaxation function :math:`M(\xi) = \sum_i w_i e^{-\xi/\tau_i}`
    (Σ w_i = 1) the fictive temperature is (Narayanaswamy 1971)

    .. math::

        T_f(t) = T(t) - \sum_i \delta_i(t), \qquad
        \delta_i(t) = \int_0^t w_i\,e^{-(\xi(t) - \xi(t'))/\tau_i}\,\frac{dT}{dt'}\,dt',

    ξ the reduced time (dξ = dt/a_T). For T linear in ξ over a step the update is exact:

    .. math::

        \delta_i^{n+1} = e^{-x_i}\,\delta_i^n + w_i\,\Delta T\,\frac{1 - e^{-x_i}}{x_i},
        \qquad x_i = \frac{\Delta\xi}{\tau_i}.

    Quick changes (x → 0) freeze the structure (δ grows by w ΔT: T_f stays), slow ones
    (x → ∞) relax it (δ → 0: T_f = T).

    Parameters
    ----------
    departures : array_like
        δ_i^n [K] (zeros in equilibrium).
    temperature_change : float
        ΔT of the step [K].
    reduced_time_increments : array_like
        x_i = Δξ/τ_i [-], >= 0, one per term.
    weights : array_like
        w_i [-], >= 0, Σ w_i = 1.

    Returns
    -------
    numpy.ndarray
        δ_i^{n+1} [K].

    References
    ----------
    O. S. Narayanaswamy, J. Am. Ceram. Soc. 54 (1971) 491–498; A. J. Kovacs, Fortschr.
    Hochpolym.-Forsch. 3 (1964) 394–507 (volume recovery of polymers).

    Examples
    --------
    >>> fictive_temperature_step([0.0, 0.0], -10.0, [0.0, 1e3], [0.5, 0.5]).round(3).tolist()
    [-5.0, -0.005]
    """
    d = np.asarray(departures, dtype=float)
    x = np.asarray(reduced_time_increments, dtype=float)
    w = np.asarray(weights, dtype=float)
    decay = np.exp(-x)
    with np.errstate(divide="ignore", invalid="ignore"):
        # (1 - e^-x)/x, with its series below 1e-8 (no cancellation)
        gain = np.where(x > 1e-8, -np.expm1(-x) / np.where(x > 1e-8, x, 1.0), 1.0 - 0.5 * x)
    return decay * d + w * float(temperature_change) * gain


def fictive_temperature(
    temperature: Any,
    reduced_time_increments: Any,
    weights: Any,
    relaxation_times: Any,
) -> np.ndarray:
    r"""Fictive temperature T_f along a temperature history (Tool–Narayanaswamy, x = 1).

    Starts in equilibrium (T_f = T at the first point) and applies
    :func:`fictive_temperature_step` between consecutive points, T linear in reduced time
    within each interval.

    Parameters
    ----------
    temperature : array_like
        T [K] at the time points, 1-D, length n.
    reduced_time_increments : array_like
        Δξ [s] of the n − 1 intervals (Δt / a_T at the interval's mid temperature), >= 0.
    weights : array_like
        Normalised weights w_i [-] of the relaxation function (Σ w_i = 1).
    relaxation_times : array_like
        τ_i [s] on the reduced-time scale.

    Returns
    -------
    numpy.ndarray
        T_f [K] at the n points.

    References
    ----------
    Narayanaswamy (1971); C. T. Moynihan et al., Ann. N. Y. Acad. Sci. 279 (1976) 15–35.

    Examples
    --------
    Instant cooling freezes the structure; a long hold lets it relax:

    >>> fictive_temperature([300.0, 250.0, 250.0], [0.0, 1e9], [1.0], [1.0]).round(6).tolist()
    [300.0, 300.0, 250.0]
    """
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    dxi = _array(reduced_time_increments, "reduced_time_increments", "s", lo=0.0)
    w = np.atleast_1d(_array(weights, "weights", "-", lo=0.0))
    tau = np.atleast_1d(_array(relaxation_times, "relaxation_times", "s", lo=0.0, lo_open=True))
    if t.ndim != 1 or dxi.shape != (max(t.size - 1, 0),) or w.shape != tau.shape:
        raise InputError(
            "temperature (n), reduced_time_increments (n - 1), weights and relaxation_times "
            f"(equal lengths) do not match: shapes {t.shape}, {dxi.shape}, {w.shape}, "
            f"{tau.shape}")
    if abs(float(w.sum()) - 1.0) > 1e-9:
        raise InputError(f"weights must sum to 1; got {float(w.sum()):.12g}")
    out = np.empty_like(t)
    out[0] = t[0]
    d = np.zeros_like(w)
    for k in range(1, t.size):
        d = fictive_temperature_step(d, t[k] - t[k - 1], dxi[k - 1] / tau, w)
        out[k] = t[k] - d.sum()
    return out
