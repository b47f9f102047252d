r"""Elastomer properties: WLF shift, modulus vs temperature, Prony series and a material catalogue.

Physics functions are small, pure and vectorised (numpy arrays in, arrays out; a scalar in
gives a Python ``float`` out). Units inside the code are SI: temperature in K, modulus and
hyperelastic constants in Pa, density in kg/m³, conductivity in W/(m·K), specific heat in
J/(kg·K), linear expansion in 1/K, time in s. A *frequency* is cyclic, in Hz, unless the
parameter is called ``angular_frequency`` (rad/s).

Contents

* WLF time–temperature superposition: :func:`wlf_log10_shift`, :func:`wlf_shift_factor`, the
  universal constants :data:`WLF_UNIVERSAL` and :data:`WLF_UNIVERSAL_TS`, with an optional
  slope-continuous Arrhenius continuation below a temperature (used below T_g by
  :class:`Elastomer`); :func:`reduced_time` and :func:`reduced_time_history`.
* Storage modulus vs temperature and frequency: :func:`master_curve_modulus` (glassy → transition
  → rubbery sigmoid in log E over log reduced frequency), :func:`modulus_vs_temperature` (adds
  the WLF shift and the entropic factor T/T_ref of the rubbery plateau) and
  :func:`modulus_from_table` (PCHIP through measured DMA points).
* Prony series: :func:`prony_relaxation_modulus`, :func:`prony_storage_modulus`,
  :func:`prony_loss_modulus`.
* Rubber elasticity and thermal expansion across the glass transition:
  :func:`entropic_modulus` (equilibrium modulus ∝ T), :func:`simha_boyer_glassy_expansion`,
  :func:`thermal_strain` (rubbery and glassy expansion through Tool's fictive temperature),
  :func:`fictive_temperature_step` and :func:`fictive_temperature` (Tool–Narayanaswamy
  structural relaxation in the reduced time of the WLF/Arrhenius shift).
* :class:`Elastomer` (frozen dataclass) and the catalogue ``data/elastomers.toml`` (NBR, HNBR,
  FKM, ACM, VMQ): :func:`list_elastomers`, :func:`get_elastomer`, :meth:`Elastomer.from_dict`,
  :func:`load_elastomer_file`.

The E(T) construction
---------------------
The small-strain storage modulus is a master curve over the reduced frequency
``f_r = f·a_T(T)`` (a_T relative to the WLF reference temperature, normally T_g):

.. math::

    \log_{10} E(T, f) = \log_{10} E_r(T) + [\log_{10} E_g - \log_{10} E_r(T)]\,S(\log_{10} f_r),
    \qquad E_r(T) = E_{r,\mathrm{ref}}\,T / T_\mathrm{ref},

with the generalised logistic (Richards 1959) sigmoid

.. math::

    S(x) = \left[1 + \nu\,\exp\!\left(-\frac{x - x_0}{w}\right)\right]^{-1/\nu}.

ν = 1 is the symmetric logistic used for asphalt master curves; ν > 1 gives the broad
low-frequency (rubbery-side) tail that filled rubbers show: S decays like
exp((x − x0)/(ν·w)) there, ν times slower than it rises to the glass (Rowe, Baumgardner &
Sharrock 2009 use the same generalised form for bituminous master curves) [L].
E_g is the glassy modulus, E_r,ref the *equilibrium* (long-time) rubbery modulus at the
material's reference temperature; the factor T/T_ref is rubber (entropy) elasticity, applied
to the rubbery part only (Treloar 1975) [L]. With ν = 4 the tail is so broad that E_r,ref is
an asymptote rather than a measurable value: for the catalogue NBR, E(23 °C, 1 Hz) ≈ 3·E_r,ref
and E(150 °C, 1 Hz) ≈ 1.4·E_r,ref·T/T_ref. The quantity that ties to measurements (and to the
hyperelastic constants, E ≈ 6·(C10 + C01)) is E at the test frequency.

Catalogue shape (same for all five materials, no DMA data at hand): x0 = −2.0 (log10 Hz at
the WLF reference temperature T_g), w = 1.1 decades, ν = 4.0, E_g = 1.5–2.5 GPa, universal
WLF constants at T_g. The shape was fitted by sealsim [D] to the statement of reference notes
§6.1 [L] that filled NBR seal compounds lose 30–50 % of their small-strain modulus between 20
and 100 °C at ~1 Hz and are flat above ~100 °C, with E(−25 °C, 1 Hz) ≈ 1 GPa (DSC T_g lies on
the glassy side of the 1 Hz DMA transition). E_r,ref was then chosen per material so that
E(20 °C, 1 Hz) is the mid-range "Rubbery E" of the §6.1 table. Resulting catalogue values
(1 Hz): NBR drops 39 % from 20 to 100 °C and has its minimum at ≈ 108 °C, FKM drops 52 %
(minimum ≈ 120 °C), VMQ (T_g = −120 °C) is rubbery from ≈ −20 °C on and rises with T.

E(T) decreases monotonically with T from the glass up to the temperature where the decay of
the transition tail becomes slower than the entropic rise of the plateau
(:meth:`Elastomer.modulus_minimum_temperature`); above it E rises ∝ T. Because the
continuation of a_T below T_g is Arrhenius (never divergent) and S is monotone, there is a
single minimum.

References
----------
- M. L. Williams, R. F. Landel, J. D. Ferry, J. Am. Chem. Soc. 77 (1955) 3701–3707 (WLF).
- J. D. Ferry, Viscoelastic Properties of Polymers, 3rd ed., Wiley 1980, ch. 11 (time–temperature
  superposition; Arrhenius-like shift in the glass) [L].
- F. J. Richards, J. Exp. Bot. 10 (1959) 290–301 (generalised logistic).
- G. Rowe, G. Baumgardner, M. Sharrock, "Functional forms for master curve analysis of
  bituminous materials", in Advanced Testing and Characterization of Bituminous Materials,
  CRC Press 2009, 81–91 [L].
- L. R. G. Treloar, The Physics of Rubber Elasticity, 3rd ed., Oxford 1975 (E ∝ T) [L].
- R. Simha, R. F. Boyer, J. Chem. Phys. 37 (1962) 1003–1007 (glassy vs liquid expansion).
- A. Q. Tool, J. Am. Ceram. Soc. 29 (1946) 240–253; O. S. Narayanaswamy, J. Am. Ceram. Soc.
  54 (1971) 491–498; C. T. Moynihan et al., Ann. N. Y. Acad. Sci. 279 (1976) 15–35
  (fictive temperature, structural relaxation, cooling-rate dependence of T_g).
- N. W. Tschoegl, The Phenomenological Theory of Linear Viscoelastic Behavior, Springer 1989
  (Prony / generalised Maxwell model) [L].
- F. N. Fritsch, R. E. Carlson, SIAM J. Numer. Anal. 17 (1980) 238–246 (PCHIP).
- sealsim reference notes ``lip_seal_friction.md`` §6.1 (property table) and §6.2 (WLF), and
  ``pneumatic_friction.md`` §3.6 (Mooney–Rivlin, Prony).
"""

from __future__ import annotations

import difflib
import functools
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.optimize import minimize_scalar

from sealsim.errors import InputError

__all__ = [
    "CATALOGUE_NAMES",
    "DEFAULT_TRANSITION_ASYMMETRY",
    "DEFAULT_TRANSITION_LOCATION",
    "DEFAULT_TRANSITION_WIDTH",
    "GLASSY_EXPANSION_RATIO",
    "SIMHA_BOYER_K1",
    "SIMHA_BOYER_K2",
    "TEMPERATURE_SCALINGS",
    "WLF_UNIVERSAL",
    "WLF_UNIVERSAL_TS",
    "Elastomer",
    "ServiceRangeWarning",
    "WLFConstants",
    "get_elastomer",
    "entropic_modulus",
    "fictive_temperature",
    "fictive_temperature_step",
    "list_elastomers",
    "load_elastomer_file",
    "master_curve_modulus",
    "modulus_from_table",
    "modulus_vs_temperature",
    "mooney_rivlin_young_modulus",
    "prony_loss_modulus",
    "prony_relaxation_modulus",
    "prony_storage_modulus",
    "reduced_time",
    "reduced_time_history",
    "simha_boyer_glassy_expansion",
    "thermal_strain",
    "shore_a_young_modulus",
    "wlf_log10_shift",
    "wlf_shift_factor",
]

ZERO_CELSIUS = 273.15  # K


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

#: Master-curve shape used by the catalogue (see the module docstring) [D].
DEFAULT_TRANSITION_LOCATION = -2.0  # log10(f_r / 1 Hz) at the WLF reference temperature
DEFAULT_TRANSITION_WIDTH = 1.1  # decades
DEFAULT_TRANSITION_ASYMMETRY = 4.0  # Richards exponent nu [-]

#: Temperature laws of the hyperelastic (sealing) stiffness, see :meth:`Elastomer.modulus_ratio`.
TEMPERATURE_SCALINGS = ("entropic", "modulus", "none")

#: Names in the shipped catalogue.
CATALOGUE_NAMES = ("NBR", "HNBR", "FKM", "ACM", "VMQ")

#: Physically meaningful range around the material (see :meth:`Elastomer.check_temperature`).
BELOW_TG_LIMIT = 100.0  # K below T_g
ABOVE_SERVICE_LIMIT = 50.0  # K above the service maximum


class ServiceRangeWarning(UserWarning):
    """A temperature is physically meaningful but outside the material's service range."""


# ---------------------------------------------------------------------------------------------
# input helpers
# ---------------------------------------------------------------------------------------------


def _range_text(lo: float | None, hi: float | None, lo_open: bool, hi_open: bool, unit: str) -> str:
    if lo is not None and hi is not None:
        return f"{lo:g} {'<' if lo_open else '<='} value {'<' if hi_open else '<='} {hi:g} {unit}"
    if lo is not None:
        return f"{'>' if lo_open else '>='} {lo:g} {unit}"
    if hi is not None:
        return f"{'<' if hi_open else '<='} {hi:g} {unit}"
    return "finite"


def _array(
    value: Any,
    name: str,
    unit: str,
    *,
    lo: float | None = None,
    hi: float | None = None,
    lo_open: bool = False,
    hi_open: bool = False,
) -> np.ndarray:
    """Float array of ``value``; InputError naming ``name`` if not finite or out of range."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise InputError(
            f"{name} must be a number or an array of numbers [{unit}]; got {value!r}"
        ) from exc
    bad = ~np.isfinite(arr)
    if lo is not None:
        bad |= (arr <= lo) if lo_open else (arr < lo)
    if hi is not None:
        bad |= (arr >= hi) if hi_open else (arr > hi)
    if np.any(bad):
        first = arr[bad].flat[0]
        n_bad = int(np.count_nonzero(bad))
        where = "" if arr.ndim == 0 else f" ({n_bad} of {arr.size} values, first shown)"
        raise InputError(
            f"{name} = {first:g} {unit}{where} is not allowed; allowed: "
            f"{_range_text(lo, hi, lo_open, hi_open, unit)}"
        )
    return arr


def _scalar(value: Any, name: str, unit: str, **kw: Any) -> float:
    arr = _array(value, name, unit, **kw)
    if arr.ndim != 0:
        raise InputError(
            f"{name} must be a single number [{unit}]; got an array of shape {arr.shape}"
        )
    return float(arr)


def _out(arr: np.ndarray) -> np.ndarray | float:
    """Return a Python float for a 0-d result, the array otherwise."""
    arr = np.asarray(arr)
    return float(arr) if arr.ndim == 0 else arr


def _broadcast(*arrays: np.ndarray, names: str) -> list[np.ndarray]:
    try:
        return list(np.broadcast_arrays(*arrays))
    except ValueError as exc:
        shapes = ", ".join(str(a.shape) for a in arrays)
        raise InputError(f"{names} cannot be broadcast together (shapes {shapes})") from exc


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
    if t_a is None:
        d = t - t_ref
        return -c1 * d / (c2 + d)
    d_a = t_a - t_ref
    y_a = -c1 * d_a / (c2 + d_a)
    b = c1 * c2 * t_a**2 / (c2 + d_a) ** 2  # K; slope continuity at t_a
    d = np.where(t >= t_a, t - t_ref, d_a)  # keep the unused branch finite
    wlf = -c1 * d / (c2 + d)
    arr = y_a + b * (1.0 / t - 1.0 / t_a)
    return np.where(t >= t_a, wlf, arr)


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
      :class:`Elastomer` uses T_a = T_g.

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
    Williams, Landel & Ferry, J. Am. Chem. Soc. 77 (1955) 3701; reference notes §6.2.

    Examples
    --------
    NBR, T_g = −25 °C, at 20 °C (notes §6.2: −8.1):

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
# storage modulus master curve and E(T, f)
# ---------------------------------------------------------------------------------------------


def _log_sigmoid(x: np.ndarray, location: float, width: float, asymmetry: float) -> np.ndarray:
    """ln S for the Richards sigmoid, overflow-free."""
    u = math.log(asymmetry) - (x - location) / width
    return -np.logaddexp(0.0, u) / asymmetry


def _shape_params(location: float, width: float, asymmetry: float) -> tuple[float, float, float]:
    return (
        _scalar(location, "transition_location", "log10 Hz"),
        _scalar(width, "transition_width", "decades", lo=0.0, lo_open=True),
        _scalar(asymmetry, "transition_asymmetry", "-", lo=0.0, lo_open=True),
    )


def _master_log10(
    x: np.ndarray, log_eg: float, log_er: np.ndarray, location: float, width: float, nu: float
) -> np.ndarray:
    s = np.exp(_log_sigmoid(x, location, width, nu))
    return log_er + (log_eg - log_er) * s


def master_curve_modulus(
    reduced_frequency: Any,
    glassy_modulus: float,
    rubbery_modulus: Any,
    transition_location: float = DEFAULT_TRANSITION_LOCATION,
    transition_width: float = DEFAULT_TRANSITION_WIDTH,
    transition_asymmetry: float = DEFAULT_TRANSITION_ASYMMETRY,
) -> np.ndarray | float:
    r"""Storage modulus master curve: glassy → transition → rubbery sigmoid in log E.

    .. math::

        \log_{10} E' = \log_{10} E_r + (\log_{10} E_g - \log_{10} E_r)\,S(\log_{10} f_r),\quad
        S(x) = \left[1 + \nu\,e^{-(x - x_0)/w}\right]^{-1/\nu}

    S rises from 0 (rubbery, low f_r) to 1 (glassy, high f_r). ν = 1 is the symmetric
    logistic; ν > 1 widens the low-frequency tail (S ∝ exp((x − x0)/(ν w)) there).

    Parameters
    ----------
    reduced_frequency : array_like
        Reduced frequency f_r = f·a_T [Hz], > 0.
    glassy_modulus : float
        Glassy modulus E_g [Pa], > ``rubbery_modulus``.
    rubbery_modulus : array_like
        Rubbery (equilibrium) modulus E_r [Pa] at the temperature considered, > 0.
    transition_location : float, default -2.0
        x0 [log10 Hz]; S(x0) = (1 + ν)^(−1/ν) (0.5 for ν = 1).
    transition_width : float, default 1.1
        w [decades of frequency], > 0.
    transition_asymmetry : float, default 4.0
        ν [-], > 0.

    Returns
    -------
    float or numpy.ndarray
        Storage modulus E' [Pa].

    References
    ----------
    Richards, J. Exp. Bot. 10 (1959) 290; Rowe, Baumgardner & Sharrock (2009) [L].

    Examples
    --------
    >>> master_curve_modulus(1e10, 2e9, 3e6) / 1e9
    2.0
    >>> master_curve_modulus(1e-20, 2e9, 3e6, transition_asymmetry=1.0) / 1e6
    3.0

    With the default ν = 4 the rubbery tail is broad: 1 % above E_r even at 1e-30 Hz.

    >>> master_curve_modulus(1e-30, 2e9, 3e6) / 1e6
    3.02
    """
    f_r = _array(reduced_frequency, "reduced_frequency", "Hz", lo=0.0, lo_open=True)
    e_r = _array(rubbery_modulus, "rubbery_modulus", "Pa", lo=0.0, lo_open=True)
    e_g = _scalar(glassy_modulus, "glassy_modulus", "Pa", lo=float(np.max(e_r)), lo_open=True)
    x0, w, nu = _shape_params(transition_location, transition_width, transition_asymmetry)
    f_r, e_r = _broadcast(f_r, e_r, names="reduced_frequency and rubbery_modulus")
    return _out(10.0 ** _master_log10(np.log10(f_r), math.log10(e_g), np.log10(e_r), x0, w, nu))


def modulus_vs_temperature(
    temperature: Any,
    frequency: Any,
    *,
    glassy_modulus: float,
    rubbery_modulus: float,
    reference_temperature: float,
    glass_transition: float,
    transition_location: float = DEFAULT_TRANSITION_LOCATION,
    transition_width: float = DEFAULT_TRANSITION_WIDTH,
    transition_asymmetry: float = DEFAULT_TRANSITION_ASYMMETRY,
    c1: float = WLF_UNIVERSAL.c1,
    c2: float = WLF_UNIVERSAL.c2,
    wlf_reference_temperature: float | None = None,
) -> np.ndarray | float:
    r"""Small-strain storage modulus E(T, f) from the WLF-shifted master curve.

    .. math::

        E(T, f) = E'_\mathrm{master}\bigl(f\,a_T(T);\ E_g,\
                  E_{r,\mathrm{ref}}\,T/T_\mathrm{ref}\bigr)

    with a_T from :func:`wlf_log10_shift` (reference ``wlf_reference_temperature``, default
    T_g; Arrhenius continuation below T_g) and the master curve of
    :func:`master_curve_modulus`. Only the rubbery plateau carries the entropic factor
    T/T_ref; the glassy modulus is taken as temperature independent.

    Parameters
    ----------
    temperature : array_like
        Temperature T [K], > 0.
    frequency : array_like
        Test or excitation frequency f [Hz], > 0; broadcast with ``temperature``.
    glassy_modulus : float
        E_g [Pa].
    rubbery_modulus : float
        Equilibrium rubbery modulus E_r,ref [Pa] at ``reference_temperature``.
    reference_temperature : float
        T_ref [K] of ``rubbery_modulus``.
    glass_transition : float
        T_g [K]; the Arrhenius continuation of a_T starts there.
    transition_location, transition_width, transition_asymmetry : float
        Sigmoid x0 [log10 Hz], w [decades], ν [-] (see :func:`master_curve_modulus`).
    c1 : float, default 17.44
        WLF C1 [-].
    c2 : float, default 51.6
        WLF C2 [K].
    wlf_reference_temperature : float, optional
        WLF reference temperature [K]; default ``glass_transition``.

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    WLF 1955; Richards 1959; Treloar 1975 [L]; reference notes §6.1–6.2.

    Examples
    --------
    Catalogue NBR at 20 °C and 1 Hz (≈ 8.5 MPa):

    >>> kw = dict(glassy_modulus=2e9, rubbery_modulus=2.68e6,
    ...           reference_temperature=296.15, glass_transition=248.15)
    >>> modulus_vs_temperature(293.15, 1.0, **kw) / 1e6
    8.5
    """
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    f = _array(frequency, "frequency", "Hz", lo=0.0, lo_open=True)
    t, f = _broadcast(t, f, names="temperature and frequency")
    t_ref = _scalar(reference_temperature, "reference_temperature", "K", lo=0.0, lo_open=True)
    t_g = _scalar(glass_transition, "glass_transition", "K", lo=0.0, lo_open=True)
    e_r = _scalar(rubbery_modulus, "rubbery_modulus", "Pa", lo=0.0, lo_open=True)
    e_g = _scalar(glassy_modulus, "glassy_modulus", "Pa", lo=e_r, lo_open=True)
    x0, w, nu = _shape_params(transition_location, transition_width, transition_asymmetry)
    t_wlf = t_g if wlf_reference_temperature is None else wlf_reference_temperature
    t_wlf, c1, c2, t_a = _wlf_params(t_wlf, c1, c2, t_g)
    x = np.log10(f) + _log10_shift(t, t_wlf, c1, c2, t_a)
    log_er = np.log10(entropic_modulus(e_r, t, t_ref))
    return _out(10.0 ** _master_log10(x, math.log10(e_g), log_er, x0, w, nu))


def modulus_from_table(
    temperature: Any, table_temperature: Any, table_modulus: Any
) -> np.ndarray | float:
    r"""Modulus from measured DMA points: monotone PCHIP in log10 E vs T, no extrapolation.

    .. math::

        E(T) = 10^{P(T)},\qquad P = \mathrm{PCHIP}\{(T_k, \log_{10} E_k)\}

    PCHIP (Fritsch & Carlson 1980) passes through every point and is monotone between
    monotone data, so it does not overshoot at the knee of the glass transition.
    Temperatures outside [T_1, T_n] raise :class:`InputError`: a DMA curve cannot be
    extrapolated safely across a transition.

    Parameters
    ----------
    temperature : array_like
        Temperature T [K] in [table_temperature[0], table_temperature[-1]].
    table_temperature : array_like
        Strictly increasing table temperatures [K], at least 2.
    table_modulus : array_like
        Moduli [Pa] at those temperatures, > 0.

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980) 238.

    Examples
    --------
    >>> modulus_from_table(300.0, [250.0, 300.0, 350.0], [1e9, 1e7, 8e6]) / 1e6
    10.0
    """
    t_tab = _array(table_temperature, "table_temperature", "K", lo=0.0, lo_open=True)
    e_tab = _array(table_modulus, "table_modulus", "Pa", lo=0.0, lo_open=True)
    if t_tab.ndim != 1 or t_tab.size < 2 or e_tab.shape != t_tab.shape:
        raise InputError(
            "table_temperature and table_modulus must be 1-D arrays of equal length >= 2; "
            f"got shapes {t_tab.shape} and {e_tab.shape}"
        )
    if np.any(np.diff(t_tab) <= 0.0):
        raise InputError(f"table_temperature must be strictly increasing [K]; got {t_tab.tolist()}")
    t = _array(temperature, "temperature", "K", lo=float(t_tab[0]), hi=float(t_tab[-1]))
    interp = PchipInterpolator(t_tab, np.log10(e_tab), extrapolate=False)
    return _out(10.0 ** interp(t))


def mooney_rivlin_young_modulus(c10: Any, c01: Any) -> np.ndarray | float:
    r"""Small-strain Young's modulus of an incompressible Mooney–Rivlin solid.

    .. math::

        E = 6\,(C_{10} + C_{01}),\qquad G = 2\,(C_{10} + C_{01})

    Parameters
    ----------
    c10 : array_like
        C10 [Pa], > 0.
    c01 : array_like
        C01 [Pa], >= 0.

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    M. Mooney, J. Appl. Phys. 11 (1940) 582; R. S. Rivlin, Phil. Trans. R. Soc. A 241 (1948)
    379 [L].

    Examples
    --------
    >>> mooney_rivlin_young_modulus(0.8e6, 0.2e6) / 1e6
    6.0
    """
    a = _array(c10, "c10", "Pa", lo=0.0, lo_open=True)
    b = _array(c01, "c01", "Pa", lo=0.0)
    return _out(6.0 * (a + b))


def shore_a_young_modulus(hardness: Any) -> np.ndarray | float:
    r"""Small-strain Young's modulus of a rubber from its Shore A hardness (Gent 1958).

    .. math::

        E\,[\mathrm{MPa}] = \frac{0.0981\,(56 + 7.62336\,S)}{0.137505\,(254 - 2.54\,S)}

    Gent's relation follows from the elastic indentation of the Shore A durometer's truncated
    cone (ASTM D2240 / ISO 48-4 geometry and spring force): the numerator is the spring force
    [N] at reading S, the denominator the indenter geometry times its depth [mm].  Independent
    FE simulations of the durometer test with a neo-Hookean solid (Qi, Joyce & Boyce 2003)
    agree within about 5 % at 70 Shore A and 15 % at 80 Shore A.  Use it for *ratios* between
    compounds of one family (a hardness tolerance), not as a substitute for a measured
    modulus.

    Parameters
    ----------
    hardness : array_like
        Shore A hardness S [-], 0 < S < 100 (readings between 10 and 90 are meaningful,
        ASTM D2240).

    Returns
    -------
    float or numpy.ndarray
        E [Pa].

    References
    ----------
    A. N. Gent, "On the relation between indentation hardness and Young's modulus",
    Trans. Inst. Rubber Ind. 34 (1958) 46-57; H. J. Qi, K. Joyce, M. C. Boyce, "Durometer
    hardness and the stress-strain behavior of elastomeric materials", Rubber Chem. Technol.
    76 (2003) 419-435.

    Examples
    --------
    >>> round(shore_a_young_modulus(70) / 1e6, 2), round(shore_a_young_modulus(80) / 1e6, 2)
    (5.52, 9.35)
    """
    s = _array(hardness, "Shore A hardness", "", lo=0.0, hi=100.0, lo_open=True, hi_open=True)
    return _out(0.0981 * (56.0 + 7.62336 * s) / (0.137505 * (254.0 - 2.54 * s)) * 1e6)


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
    Tschoegl (1989) [L]; pneumatic_friction.md §3.6.

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
# thermal expansion across the glass transition (structural relaxation)
# ---------------------------------------------------------------------------------------------

#: Simha–Boyer constants for the volumetric expansion coefficients of amorphous polymers:
#: (α_l − α_g)·T_g ≈ 0.113 and α_l·T_g ≈ 0.164 (R. Simha, R. F. Boyer, J. Chem. Phys. 37
#: (1962) 1003–1007).
SIMHA_BOYER_K1 = 0.113
SIMHA_BOYER_K2 = 0.164
#: Glassy-to-rubbery expansion ratio α_g/α_l = 1 − K1/K2 ≈ 0.31 (Simha & Boyer 1962): the
#: glass keeps only the vibrational part of the expansion; the rest, the growth of free volume,
#: freezes at T_g. Linear and volumetric coefficients have the same ratio (α_vol = 3 α_lin).
GLASSY_EXPANSION_RATIO = 1.0 - SIMHA_BOYER_K1 / SIMHA_BOYER_K2


def entropic_modulus(
    modulus: Any, temperature: Any, reference_temperature: Any
) -> np.ndarray | float:
    r"""Equilibrium modulus of rubber elasticity at temperature T: E(T) = E_0·T/T_0.

    A network of flexible chains stores elastic energy as configurational entropy, so its
    equilibrium shear modulus is G = n k T (Treloar 1975, ch. 4) and rises with T. This is the
    modulus of a seal held at constant squeeze long enough for its viscoelastic stresses to
    relax (well above T_g). The dynamic (storage) modulus at a given rate,
    :func:`modulus_vs_temperature`, instead falls with T between T_g and ≈ 100 °C because the
    glass-transition tail relaxes faster the warmer the rubber is.

    Parameters
    ----------
    modulus : array_like
        E_0 [Pa] at T_0, > 0.
    temperature : array_like
        T [K], > 0.
    reference_temperature : array_like
        T_0 [K], > 0.

    Returns
    -------
    float or numpy.ndarray
        E(T) [Pa].

    References
    ----------
    L. R. G. Treloar, The Physics of Rubber Elasticity, 3rd ed., Oxford 1975, ch. 4.

    Examples
    --------
    >>> round(entropic_modulus(8e6, 328.15, 293.15) / 1e6, 4)
    8.9551
    """
    e0 = _array(modulus, "modulus", "Pa", lo=0.0, lo_open=True)
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    t0 = _array(reference_temperature, "reference_temperature", "K", lo=0.0, lo_open=True)
    return _out(e0 * t / t0)


def simha_boyer_glassy_expansion(rubbery_expansion: Any) -> np.ndarray | float:
    r"""Glassy thermal expansion coefficient estimated from the rubbery one (Simha–Boyer).

    .. math::

        \alpha_g = \alpha_r\,\left(1 - \frac{K_1}{K_2}\right) \approx 0.31\,\alpha_r,
        \qquad K_1 = (\alpha_l - \alpha_g)\,T_g = 0.113,\quad K_2 = \alpha_l T_g = 0.164

    Parameters
    ----------
    rubbery_expansion : array_like
        Linear CTE above T_g, α_r [1/K], > 0.

    Returns
    -------
    float or numpy.ndarray
        Linear CTE of the glass, α_g [1/K].

    References
    ----------
    R. Simha, R. F. Boyer, J. Chem. Phys. 37 (1962) 1003–1007.

    Examples
    --------
    >>> round(simha_boyer_glassy_expansion(1.9e-4) * 1e4, 3)
    0.591
    """
    a = _array(rubbery_expansion, "rubbery_expansion", "1/K", lo=0.0, lo_open=True)
    return _out(GLASSY_EXPANSION_RATIO * a)


def thermal_strain(
    temperature: Any,
    reference_temperature: Any,
    rubbery_expansion: Any,
    glassy_expansion: Any = None,
    fictive_temperature: Any = None,
) -> np.ndarray | float:
    r"""Free linear thermal strain of a rubber that may be (partly) glassy.

    .. math::

        \varepsilon_{th} = \alpha_g\,(T - T_0) + (\alpha_r - \alpha_g)\,(T_f - T_0)

    T_f is Tool's fictive temperature: the temperature at which the frozen structure (free
    volume) would be in equilibrium. In equilibrium (rubber, slow changes) T_f = T and the
    strain is α_r (T − T_0); in a glass T_f stays where the structure froze and only α_g
    remains. T_0 is a stress-free equilibrium state (T_f = T_0 there).

    Parameters
    ----------
    temperature : array_like
        T [K].
    reference_temperature : array_like
        T_0 [K] of zero strain (equilibrium).
    rubbery_expansion : array_like
        α_r [1/K] (equilibrium, above T_g).
    glassy_expansion : array_like, optional
        α_g [1/K]; default α_r (no glass transition).
    fictive_temperature : array_like, optional
        T_f [K]; default T (equilibrium).

    Returns
    -------
    float or numpy.ndarray
        ε_th [-].

    References
    ----------
    A. Q. Tool, J. Am. Ceram. Soc. 29 (1946) 240–253 (fictive temperature);
    O. S. Narayanaswamy, J. Am. Ceram. Soc. 54 (1971) 491–498.

    Examples
    --------
    Cooled 60 K, the last 30 K in the glass (T_f = T_0 − 30 K):

    >>> round(thermal_strain(233.15, 293.15, 1.9e-4, 0.6e-4, 263.15), 6)
    -0.0075
    """
    t = _array(temperature, "temperature", "K", lo=0.0, lo_open=True)
    t0 = _array(reference_temperature, "reference_temperature", "K", lo=0.0, lo_open=True)
    a_r = _array(rubbery_expansion, "rubbery_expansion", "1/K")
    a_g = a_r if glassy_expansion is None else _array(glassy_expansion, "glassy_expansion", "1/K")
    t_f = t if fictive_temperature is None else _array(
        fictive_temperature, "fictive_temperature", "K", lo=0.0, lo_open=True)
    return _out(a_g * (t - t0) + (a_r - a_g) * (t_f - t0))


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


# ---------------------------------------------------------------------------------------------
# Elastomer
# ---------------------------------------------------------------------------------------------


def _field_error(field: str, value: Any, allowed: str, unit: str = "") -> InputError:
    shown = f"{value:g} {unit}".strip() if isinstance(value, float) else repr(value)
    err = InputError(f"{field} = {shown} is not allowed; allowed: {allowed}")
    err.field = field  # type: ignore[attr-defined]
    return err


def _check_field(
    field: str,
    value: Any,
    unit: str,
    lo: float | None = None,
    hi: float | None = None,
    lo_open: bool = False,
    hi_open: bool = False,
    why: str = "",
) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise _field_error(field, value, f"a number [{unit}]") from None
    if (
        not math.isfinite(v)
        or (lo is not None and (v <= lo if lo_open else v < lo))
        or (hi is not None and (v >= hi if hi_open else v > hi))
    ):
        allowed = _range_text(lo, hi, lo_open, hi_open, unit) + (f" ({why})" if why else "")
        raise _field_error(field, v, allowed, unit)
    return v


@dataclass(frozen=True)
class Elastomer:
    """An elastomer compound: thermal, hyperelastic and viscoelastic properties (SI units).

    All temperatures in K, moduli and hyperelastic constants in Pa. Build one from the
    catalogue (:func:`get_elastomer`), from a TOML table (:meth:`from_dict`,
    :func:`load_elastomer_file`) or directly; the constructor validates every field and
    raises :class:`InputError` naming it.

    Attributes
    ----------
    name : str
        Short name, e.g. "NBR".
    description : str
        One-line description.
    glass_transition : float
        T_g (DSC) [K]; 100–400 K.
    density : float
        ρ [kg/m³]; 800–2500.
    thermal_conductivity : float
        k [W/(m·K)]; 0.05–2.
    specific_heat : float
        c_p [J/(kg·K)]; 500–3000.
    thermal_expansion : float
        Linear CTE of the rubber (equilibrium, above T_g) α_r [1/K]; 1e-5–1e-3.
    c10, c01 : float
        Mooney–Rivlin constants [Pa] at ``reference_temperature`` (C10 > 0, C01 >= 0).
    bulk_modulus : float
        K [Pa]; > 10× the shear modulus 2(C10 + C01) (nearly incompressible).
    reference_temperature : float
        T_ref [K] of c10, c01, bulk_modulus, rubbery_modulus; > T_g.
    wlf_c1, wlf_c2 : float
        WLF constants C1 [-], C2 [K] (> 0).
    wlf_reference_temperature : float
        WLF reference temperature [K]; must satisfy T_g > T_wlf − C2.
    glassy_modulus : float
        E_g [Pa]; > 2 × rubbery_modulus.
    rubbery_modulus : float
        Equilibrium rubbery modulus E_r [Pa] at ``reference_temperature`` (low-frequency
        asymptote of the master curve, below the modulus at the test frequency).
    transition_location, transition_width, transition_asymmetry : float
        Master-curve sigmoid x0 [log10 Hz at the WLF reference temperature], w [decades],
        ν [-] (see :func:`master_curve_modulus`).
    test_frequency : float
        Frequency [Hz] at which ``modulus`` is evaluated by default and at which the
        hyperelastic constants are taken to hold.
    service_range : tuple of float
        (T_min, T_max) [K] of service.
    source : str
        Where the values come from.
    dma_table : tuple, optional
        ((T_k, ...), (E_k, ...)) [K], [Pa] measured at ``dma_frequency``; overrides the
        parametric curve.
    dma_frequency : float, optional
        Frequency [Hz] of the DMA table; default ``test_frequency``.
    prony : tuple, optional
        (E∞, (E_i, ...), (τ_i, ...)) [Pa], [Pa], [s] at ``prony_reference_temperature``.
    prony_reference_temperature : float, optional
        [K]; default ``reference_temperature``.
    hardness_shore_a : float, optional
        Shore A hardness [-] (information only).

    Examples
    --------
    >>> nbr = get_elastomer("nbr")
    >>> nbr.modulus(293.15) / 1e6
    8.5
    """

    name: str
    description: str
    glass_transition: float
    density: float
    thermal_conductivity: float
    specific_heat: float
    thermal_expansion: float
    c10: float
    c01: float
    bulk_modulus: float
    reference_temperature: float
    wlf_c1: float
    wlf_c2: float
    wlf_reference_temperature: float
    glassy_modulus: float
    rubbery_modulus: float
    transition_location: float = DEFAULT_TRANSITION_LOCATION
    transition_width: float = DEFAULT_TRANSITION_WIDTH
    transition_asymmetry: float = DEFAULT_TRANSITION_ASYMMETRY
    test_frequency: float = 1.0
    service_range: tuple[float, float] = (233.15, 373.15)
    source: str = ""
    dma_table: tuple[tuple[float, ...], tuple[float, ...]] | None = None
    dma_frequency: float | None = None
    prony: tuple[float, tuple[float, ...], tuple[float, ...]] | None = None
    prony_reference_temperature: float | None = None
    hardness_shore_a: float | None = None

    # -- validation ---------------------------------------------------------------------------

    def __post_init__(self) -> None:
        set_ = functools.partial(object.__setattr__, self)
        if not isinstance(self.name, str) or not self.name.strip():
            raise _field_error("name", self.name, "a non-empty string")
        for f in ("description", "source"):
            if not isinstance(getattr(self, f), str):
                raise _field_error(f, getattr(self, f), "a string")
        tg = _check_field("glass_transition", self.glass_transition, "K", 100.0, 400.0)
        set_("glass_transition", tg)
        set_("density", _check_field("density", self.density, "kg/m3", 800.0, 2500.0))
        set_(
            "thermal_conductivity",
            _check_field("thermal_conductivity", self.thermal_conductivity, "W/(m K)", 0.05, 2.0),
        )
        set_(
            "specific_heat",
            _check_field("specific_heat", self.specific_heat, "J/(kg K)", 500.0, 3000.0),
        )
        set_(
            "thermal_expansion",
            _check_field("thermal_expansion", self.thermal_expansion, "1/K", 1e-5, 1e-3),
        )
        t_ref = _check_field(
            "reference_temperature",
            self.reference_temperature,
            "K",
            tg,
            600.0,
            lo_open=True,
            why="above glass_transition",
        )
        set_("reference_temperature", t_ref)
        c10 = _check_field("c10", self.c10, "Pa", 0.0, 1e9, lo_open=True)
        c01 = _check_field("c01", self.c01, "Pa", 0.0, 1e9)
        set_("c10", c10)
        set_("c01", c01)
        set_(
            "bulk_modulus",
            _check_field(
                "bulk_modulus",
                self.bulk_modulus,
                "Pa",
                20.0 * (c10 + c01),
                1e11,
                lo_open=True,
                why="> 10 x shear modulus 2(c10 + c01)",
            ),
        )
        c1 = _check_field("wlf_c1", self.wlf_c1, "-", 0.0, 100.0, lo_open=True)
        c2 = _check_field("wlf_c2", self.wlf_c2, "K", 0.0, 1000.0, lo_open=True)
        set_("wlf_c1", c1)
        set_("wlf_c2", c2)
        t_wlf = _check_field(
            "wlf_reference_temperature",
            self.wlf_reference_temperature,
            "K",
            0.0,
            tg + c2,
            lo_open=True,
            hi_open=True,
            why="below glass_transition + wlf_c2, so that WLF is finite at T_g",
        )
        set_("wlf_reference_temperature", t_wlf)
        e_r = _check_field("rubbery_modulus", self.rubbery_modulus, "Pa", 1e4, 1e9)
        set_("rubbery_modulus", e_r)
        set_(
            "glassy_modulus",
            _check_field(
                "glassy_modulus",
                self.glassy_modulus,
                "Pa",
                2.0 * e_r,
                1e11,
                lo_open=True,
                why="> 2 x rubbery_modulus",
            ),
        )
        set_(
            "transition_location",
            _check_field("transition_location", self.transition_location, "log10 Hz", -30, 30),
        )
        set_(
            "transition_width",
            _check_field(
                "transition_width", self.transition_width, "decades", 0.0, 10.0, lo_open=True
            ),
        )
        set_(
            "transition_asymmetry",
            _check_field(
                "transition_asymmetry", self.transition_asymmetry, "-", 0.0, 100.0, lo_open=True
            ),
        )
        set_(
            "test_frequency",
            _check_field("test_frequency", self.test_frequency, "Hz", 0.0, None, lo_open=True),
        )
        try:
            t_min, t_max = (float(v) for v in self.service_range)
        except (TypeError, ValueError):
            raise _field_error(
                "service_range", self.service_range, "a pair (T_min, T_max) of numbers [K]"
            ) from None
        if not (math.isfinite(t_min) and math.isfinite(t_max) and 0.0 < t_min < t_max):
            raise _field_error("service_range", self.service_range, "0 < T_min < T_max [K]")
        if t_max <= tg:
            raise _field_error("service_range", self.service_range, f"T_max > T_g = {tg:g} K")
        set_("service_range", (t_min, t_max))
        if self.dma_table is not None:
            self._validate_dma(set_)
        if self.prony is not None:
            self._validate_prony(set_)
        if self.hardness_shore_a is not None:
            set_(
                "hardness_shore_a",
                _check_field("hardness_shore_a", self.hardness_shore_a, "Shore A", 0.0, 100.0),
            )

    def _validate_dma(self, set_: Any) -> None:
        try:
            t_tab, e_tab = self.dma_table  # type: ignore[misc]
            t_tab = tuple(float(v) for v in t_tab)
            e_tab = tuple(float(v) for v in e_tab)
        except (TypeError, ValueError):
            raise _field_error(
                "dma_table", self.dma_table, "a pair ((T_k, ...) [K], (E_k, ...) [Pa])"
            ) from None
        try:
            modulus_from_table(t_tab[0] if t_tab else 1.0, t_tab, e_tab)
        except InputError as exc:
            raise _field_error("dma_table", self.dma_table, str(exc)) from None
        set_("dma_table", (t_tab, e_tab))
        f = self.test_frequency if self.dma_frequency is None else self.dma_frequency
        set_("dma_frequency", _check_field("dma_frequency", f, "Hz", 0.0, None, lo_open=True))

    def _validate_prony(self, set_: Any) -> None:
        try:
            e_inf, e_i, tau_i = self.prony  # type: ignore[misc]
            e_inf, e_i, tau_i = _prony_params(e_inf, e_i, tau_i)
        except (TypeError, ValueError) as exc:
            raise _field_error(
                "prony", self.prony, f"(E_inf [Pa], (E_i, ...) [Pa], (tau_i, ...) [s]): {exc}"
            ) from None
        set_("prony", (e_inf, tuple(e_i.tolist()), tuple(tau_i.tolist())))
        t_p = (
            self.reference_temperature
            if self.prony_reference_temperature is None
            else (self.prony_reference_temperature)
        )
        set_(
            "prony_reference_temperature",
            _check_field("prony_reference_temperature", t_p, "K", self.glass_transition, 600.0),
        )

    # -- temperature range ------------------------------------------------------------------

    @property
    def allowed_range(self) -> tuple[float, float]:
        """Physically meaningful temperature range [K]: (T_g − 100 K, T_max,service + 50 K).

        Below T_g − 100 K the material is a deep glass far from any seal use; above the
        service maximum + 50 K it degrades within hours. The lower bound is also kept > 1 K.
        """
        return (
            max(self.glass_transition - BELOW_TG_LIMIT, 1.0),
            self.service_range[1] + ABOVE_SERVICE_LIMIT,
        )

    def check_temperature(self, temperature: Any, *, warn: bool = True) -> np.ndarray:
        """Validate temperatures for this material.

        Raises :class:`InputError` outside :attr:`allowed_range` (T_g − 100 K to service
        maximum + 50 K) and, if ``warn``, issues a :class:`ServiceRangeWarning` for values
        inside it but outside :attr:`service_range`.

        Parameters
        ----------
        temperature : array_like
            Temperature [K].
        warn : bool, default True
            Warn outside the service range.

        Returns
        -------
        numpy.ndarray
            The temperatures as a float array.

        Examples
        --------
        >>> get_elastomer("FKM").check_temperature(373.15)
        array(373.15)
        """
        return self._check(temperature, warn, stacklevel=3)

    def _check(self, temperature: Any, warn: bool, stacklevel: int) -> np.ndarray:
        """check_temperature; ``stacklevel`` makes the warning point at the user's call."""
        lo, hi = self.allowed_range
        t = _array(temperature, f"temperature for {self.name}", "K", lo=lo, hi=hi)
        s_lo, s_hi = self.service_range
        if warn and np.any((t < s_lo) | (t > s_hi)):
            out = t[(t < s_lo) | (t > s_hi)]
            shown = f"{float(out.min()):.2f}" + (
                f"–{float(out.max()):.2f}" if out.min() != out.max() else ""
            )
            warnings.warn(
                f"temperature {shown} K is outside the service range {s_lo:.2f}–{s_hi:.2f} K "
                f"of {self.name}",
                ServiceRangeWarning,
                stacklevel=stacklevel,
            )
        return t

    # -- shift factor and modulus -------------------------------------------------------------

    def _log10_shift(self, t: np.ndarray) -> np.ndarray:
        return _log10_shift(
            t, self.wlf_reference_temperature, self.wlf_c1, self.wlf_c2, self.glass_transition
        )

    def log10_shift_factor(
        self, temperature: Any, reference_temperature: float | None = None
    ) -> np.ndarray | float:
        """log10 a_T [-] (WLF above T_g, Arrhenius continuation below; see :func:`wlf_log10_shift`).

        Parameters
        ----------
        temperature : array_like
            T [K].
        reference_temperature : float, optional
            Temperature [K] at which a_T = 1; default the WLF reference temperature.

        Returns
        -------
        float or numpy.ndarray
            log10 a_T [-].

        Examples
        --------
        >>> get_elastomer("NBR").log10_shift_factor(373.15)
        -12.3
        """
        return _out(self._shift_checked(temperature, reference_temperature))

    def _shift_checked(self, temperature: Any, reference_temperature: float | None) -> np.ndarray:
        t = self._check(temperature, True, stacklevel=4)
        y = self._log10_shift(t)
        if reference_temperature is not None:
            t0 = self._check(reference_temperature, False, stacklevel=4)
            if t0.ndim != 0:
                raise InputError("reference_temperature must be a single number [K]")
            y = y - self._log10_shift(t0)
        return y

    def shift_factor(
        self, temperature: Any, reference_temperature: float | None = None
    ) -> np.ndarray | float:
        """Shift factor a_T [-] (10 ** :meth:`log10_shift_factor`).

        Parameters
        ----------
        temperature : array_like
            T [K].
        reference_temperature : float, optional
            Temperature [K] at which a_T = 1; default the WLF reference temperature.

        Returns
        -------
        float or numpy.ndarray
            a_T [-].

        Examples
        --------
        >>> get_elastomer("NBR").shift_factor(296.15, reference_temperature=296.15)
        1.0
        """
        return _out(10.0 ** self._shift_checked(temperature, reference_temperature))

    def _modulus(self, t: np.ndarray, f: np.ndarray) -> np.ndarray:
        """E [Pa] for validated, broadcast t [K] and f [Hz] (no warnings)."""
        if self.dma_table is not None:
            t_tab, e_tab = self.dma_table
            if np.all(f == self.dma_frequency):
                t_eq = t
            else:
                # time–temperature superposition: the table temperature with the same f·a_T
                y = self._log10_shift(t) + np.log10(f / self.dma_frequency)
                t_eq = _inverse_log10_shift(
                    y,
                    self.wlf_reference_temperature,
                    self.wlf_c1,
                    self.wlf_c2,
                    self.glass_transition,
                )
                if np.any(~np.isfinite(t_eq)):
                    raise InputError(
                        f"frequency/temperature of {self.name} lie beyond the WLF range: no "
                        f"equivalent temperature of the DMA table exists"
                    )
            try:
                return np.asarray(modulus_from_table(t_eq, t_tab, e_tab))
            except InputError as exc:
                raise InputError(
                    f"{self.name}: the DMA table covers {t_tab[0]:.2f}–{t_tab[-1]:.2f} K at "
                    f"{self.dma_frequency:g} Hz; the requested temperature/frequency maps outside "
                    f"it ({exc})"
                ) from None
        x = np.log10(f) + self._log10_shift(t)
        log_er = np.log10(entropic_modulus(self.rubbery_modulus, t, self.reference_temperature))
        return 10.0 ** _master_log10(
            x,
            math.log10(self.glassy_modulus),
            log_er,
            self.transition_location,
            self.transition_width,
            self.transition_asymmetry,
        )

    def _t_f(self, temperature: Any, frequency: Any, warn: bool) -> tuple[np.ndarray, np.ndarray]:
        t = self._check(temperature, warn, stacklevel=4)
        f = self.test_frequency if frequency is None else frequency
        f = _array(f, "frequency", "Hz", lo=0.0, lo_open=True)
        t, f = _broadcast(t, f, names="temperature and frequency")
        return t, f

    def modulus(self, temperature: Any, frequency: Any = None) -> np.ndarray | float:
        r"""Small-strain Young's (storage) modulus E(T, f) [Pa].

        From the DMA table if one is given (PCHIP in log E vs T; at another frequency the
        table is read at the WLF-equivalent temperature, without vertical shift), otherwise
        from :func:`modulus_vs_temperature` with this material's parameters.

        Parameters
        ----------
        temperature : array_like
            T [K], inside :attr:`allowed_range` (warning outside the service range).
        frequency : array_like, optional
            f [Hz]; default ``test_frequency``.

        Returns
        -------
        float or numpy.ndarray
            E [Pa].

        Examples
        --------
        >>> get_elastomer("NBR").modulus(373.15) / 1e6
        5.2
        """
        t, f = self._t_f(temperature, frequency, warn=True)
        return _out(self._modulus(t, f))

    def shear_modulus(self, temperature: Any, frequency: Any = None) -> np.ndarray | float:
        """Small-strain shear modulus G = E/3 [Pa] (incompressible).

        Parameters
        ----------
        temperature : array_like
            T [K].
        frequency : array_like, optional
            f [Hz]; default ``test_frequency``.

        Returns
        -------
        float or numpy.ndarray
            G [Pa].

        Examples
        --------
        >>> get_elastomer("NBR").shear_modulus(293.15) / 1e6
        2.83
        """
        t, f = self._t_f(temperature, frequency, warn=True)
        return _out(self._modulus(t, f) / 3.0)

    def mooney_rivlin(
        self, temperature: Any, frequency: Any = None, *, scale_bulk: bool = False
    ) -> tuple[np.ndarray | float, np.ndarray | float, np.ndarray | float]:
        r"""Mooney–Rivlin constants (C10, C01, K) [Pa] at temperature T.

        .. math::

            C_{10}(T) = C_{10}\,\frac{E(T)}{E(T_\mathrm{ref})},\quad
            C_{01}(T) = C_{01}\,\frac{E(T)}{E(T_\mathrm{ref})},\quad K(T) = K

        with E at ``frequency`` (default the test frequency). This is how temperature enters
        the hyperelastic FE model: the shape of the strain-energy function (C01/C10) is kept,
        its stiffness follows the small-strain modulus. The bulk modulus is kept constant by
        default: K of a rubber is set by intermolecular forces and changes little with T,
        whereas scaling it by E(T) would give absurd values in the glass. ``scale_bulk=True``
        scales it too (keeps the Poisson ratio constant). The hyperelastic model is only
        meaningful in the rubbery region (T above ≈ T_g + 25 K at 1 Hz).

        Parameters
        ----------
        temperature : array_like
            T [K].
        frequency : array_like, optional
            f [Hz]; default ``test_frequency``.
        scale_bulk : bool, default False
            Also scale K by E(T)/E(T_ref).

        Returns
        -------
        tuple
            (C10 [Pa], C01 [Pa], K [Pa]).

        References
        ----------
        Mooney 1940; Rivlin 1948 [L]; fe_notes.md.

        Examples
        --------
        >>> c10, c01, k = get_elastomer("NBR").mooney_rivlin(296.15)
        >>> round(c10 / 1e6, 3), round(c01 / 1e6, 3), k / 1e6
        (1.064, 0.266, 2000.0)
        """
        t, f = self._t_f(temperature, frequency, warn=True)
        ratio = self._modulus(t, f) / self._modulus(np.asarray(self.reference_temperature), f)
        k = self.bulk_modulus * ratio if scale_bulk else self.bulk_modulus * np.ones_like(ratio)
        return _out(self.c10 * ratio), _out(self.c01 * ratio), _out(k)

    def modulus_ratio(
        self,
        temperature: Any,
        reference_temperature: float | None = None,
        scaling: str = "entropic",
        frequency: Any = None,
    ) -> np.ndarray | float:
        r"""Stiffness of the seal at T relative to T_ref, E(T)/E(T_ref), for the hyperelastic
        constants and the analytic contact estimate (one law for both).

        * ``"entropic"`` (default): T/T_ref, the equilibrium modulus of rubber elasticity
          (:func:`entropic_modulus`). It is the stiffness of a seal held at constant squeeze
          long enough for the viscoelastic stresses to relax -- an installed static or slowly
          moving seal well above T_g -- and it rises with T.
        * ``"modulus"``: E(T, f)/E(T_ref, f) of :meth:`modulus`, the dynamic (storage) modulus
          at the rate of interest f. Between T_g and ≈ 100 °C it falls with T (the
          glass-transition tail relaxes faster when warm): the stiffness of a deformation
          that lasts about 1/f, not of a long-held squeeze.
        * ``"none"``: 1.

        Parameters
        ----------
        temperature : array_like
            T [K] (allowed range of the material; no service-range warning).
        reference_temperature : float, optional
            T_ref [K]; default the material's reference temperature.
        scaling : {"entropic", "modulus", "none"}
            See above.
        frequency : float, optional
            f [Hz] for ``"modulus"``; default ``test_frequency``.

        Returns
        -------
        float or numpy.ndarray
            E(T)/E(T_ref) [-].

        References
        ----------
        Treloar (1975), ch. 4 [L]; J. D. Ferry, Viscoelastic Properties of Polymers, 3rd ed.,
        Wiley 1980, ch. 11 and 12 (transition zone) [L].

        Examples
        --------
        From 25 to 55 °C the equilibrium stiffness of NBR rises 10 %, its 1 Hz modulus falls 26 %:

        >>> nbr = get_elastomer("NBR")
        >>> [round(nbr.modulus_ratio(328.15, 298.15, s), 3) for s in ("entropic", "modulus")]
        [1.101, 0.742]
        """
        t_ref = (self.reference_temperature if reference_temperature is None
                 else reference_temperature)
        if scaling not in TEMPERATURE_SCALINGS:
            raise InputError(f"temperature scaling {scaling!r} is not allowed; choose one of "
                             f"{', '.join(TEMPERATURE_SCALINGS)}")
        t = self._check(temperature, False, stacklevel=3)
        t0 = self._check(t_ref, False, stacklevel=3)
        if t0.ndim != 0:
            raise InputError("reference_temperature must be a single number [K]")
        if scaling == "entropic":
            return _out(entropic_modulus(1.0, t, t0))
        if scaling == "none":
            return _out(np.ones_like(t))
        t, f = self._t_f(t, frequency, warn=False)
        return _out(self._modulus(t, f) / self._modulus(t0, f[()] if f.ndim == 0 else f))

    def relaxation_modulus(self, time: Any, temperature: Any) -> np.ndarray | float:
        r"""Relaxation modulus E(t, T) [Pa] from the Prony series and time–temperature shift.

        .. math::

            E(t, T) = E_\infty\,\frac{T}{T_p}
                      + \sum_i E_i\,\exp\!\left(-\frac{t}{a_T\,\tau_i}\right),
            \quad a_T = \frac{a_T(T)}{a_T(T_p)}

        T_p is ``prony_reference_temperature``; as in the master curve only the equilibrium
        part carries the entropic factor.

        Parameters
        ----------
        time : array_like
            t [s], >= 0.
        temperature : array_like
            T [K] (constant during the relaxation), broadcast with ``time``.

        Returns
        -------
        float or numpy.ndarray
            E [Pa].

        Examples
        --------
        >>> nbr = get_elastomer("NBR")
        >>> nbr.relaxation_modulus(1e9, 296.15) / 1e6
        2.68
        """
        if self.prony is None:
            raise InputError(
                f"{self.name} has no Prony series: give one in the [{self.name}.prony] table"
            )
        tt = _array(time, "time", "s", lo=0.0)
        t = self._check(temperature, True, stacklevel=3)
        tt, t = _broadcast(tt, t, names="time and temperature")
        e_inf, e_i, tau_i = self.prony
        t_p = float(self.prony_reference_temperature)  # type: ignore[arg-type]
        a = 10.0 ** (self._log10_shift(t) - self._log10_shift(np.asarray(t_p)))
        xi = tt / a
        e = e_inf * t / t_p + np.sum(
            np.asarray(e_i) * np.exp(-xi[..., None] / np.asarray(tau_i)), axis=-1
        )
        return _out(e)

    def modulus_minimum_temperature(self, frequency: float | None = None) -> float:
        """Temperature [K] where E(T, f) stops decreasing (the entropic rise takes over).

        E decreases from T_g − 40 K (or the lower end of the DMA table) up to this temperature.
        Found on a 0.25 K grid over the allowed range and refined with a bounded scalar
        minimisation; if E decreases throughout, the upper end is returned.

        Parameters
        ----------
        frequency : float, optional
            f [Hz]; default ``test_frequency``.

        Returns
        -------
        float
            T* [K].

        Examples
        --------
        >>> round(get_elastomer("NBR").modulus_minimum_temperature() - 273.15)
        108
        """
        f = (
            self.test_frequency
            if frequency is None
            else _scalar(frequency, "frequency", "Hz", lo=0.0, lo_open=True)
        )
        lo, hi = self.allowed_range
        lo = max(lo, self.glass_transition - 40.0)
        if self.dma_table is not None:
            lo, hi = max(lo, self.dma_table[0][0]), min(hi, self.dma_table[0][-1])
        grid = np.linspace(lo, hi, max(int((hi - lo) / 0.25), 3) + 1)
        log_e = np.log10(self._modulus(grid, np.full_like(grid, f)))
        i = int(np.argmin(log_e))
        if i == grid.size - 1:
            return float(hi)
        if i == 0:
            return float(lo)
        res = minimize_scalar(
            lambda x: float(np.log10(self._modulus(np.asarray(x), np.asarray(f)))),
            bounds=(grid[i - 1], grid[i + 1]),
            method="bounded",
            options={"xatol": 1e-4},
        )
        return float(res.x)

    @property
    def glassy_expansion(self) -> float:
        """Linear CTE of the glassy state α_g [1/K]: the Simha–Boyer estimate 0.31·α_r
        (:func:`simha_boyer_glassy_expansion`; no compound of the catalogue gives a measured
        glassy value).

        Examples
        --------
        >>> round(get_elastomer("NBR").glassy_expansion * 1e4, 3)
        0.591
        """
        return float(simha_boyer_glassy_expansion(self.thermal_expansion))

    @property
    def structural_relaxation(self) -> tuple[np.ndarray, np.ndarray] | None:
        """Normalised weights w_i [-] and times τ_i [s] (at the Prony reference temperature)
        of the volume (structural) relaxation, or None without a Prony series.

        Assumption [D]: the volume relaxes with the spectrum of the shear relaxation,
        w_i = E_i / Σ E_j, and the same shift factor a_T(T) (thermorheologically simple, the
        x = 1 case of Narayanaswamy's shift). Check (tests): cooled at 10 K/min, the catalogue
        NBR freezes at T_f = −30 °C, 5 K below its DSC T_g of −25 °C, and the freezing
        temperature moves by 2.8 K per decade of cooling rate as Moynihan's relation
        d(1/T_f')/d log10 q = −1/B predicts for the Arrhenius shift below T_g.
        """
        if self.prony is None:
            return None
        e_i = np.asarray(self.prony[1])
        if e_i.sum() <= 0.0:
            return None
        return e_i / e_i.sum(), np.asarray(self.prony[2])

    def fictive_temperature(self, time: Any, temperature: Any) -> np.ndarray:
        r"""Fictive temperature T_f [K] along a temperature history T(t).

        :func:`fictive_temperature` with :attr:`structural_relaxation` and the shift factor of
        this material at each interval's mid temperature (relative to the Prony reference
        temperature); equilibrium (T_f = T) at the start. The free thermal strain then is
        :func:`thermal_strain` with α_r = ``thermal_expansion``, α_g = :attr:`glassy_expansion`.

        Parameters
        ----------
        time : array_like
            Strictly increasing times t [s], 1-D.
        temperature : array_like
            T [K] at those times (allowed range of the material).

        Returns
        -------
        numpy.ndarray
            T_f [K].

        Examples
        --------
        Cooling the catalogue NBR at 1 K/min from 20 °C to −60 °C: the structure freezes
        near −33 °C.

        >>> T = np.linspace(293.15, 213.15, 161)
        >>> t = (T[0] - T) * 60.0
        >>> round(float(get_elastomer("NBR").fictive_temperature(t, T)[-1]) - 273.15, 1)
        -33.0
        """
        spectrum = self.structural_relaxation
        if spectrum is None:
            raise InputError(
                f"{self.name} has no Prony series, so its structural relaxation (glass "
                f"transition of the thermal expansion) is not defined; give [{self.name}.prony]")
        tt = _array(time, "time", "s")
        t = self._check(temperature, False, stacklevel=3)
        if tt.ndim != 1 or t.shape != tt.shape or np.any(np.diff(tt) <= 0.0):
            raise InputError("time must be strictly increasing and match temperature (1-D)")
        t_p = float(self.prony_reference_temperature)  # type: ignore[arg-type]
        log_a = self._log10_shift(0.5 * (t[1:] + t[:-1])) - self._log10_shift(np.asarray(t_p))
        with np.errstate(over="ignore", under="ignore"):
            dxi = np.diff(tt) / 10.0**log_a
        return fictive_temperature(t, dxi, *spectrum)

    @property
    def thermal_diffusivity(self) -> float:
        """Thermal diffusivity k/(ρ c_p) [m²/s]."""
        return self.thermal_conductivity / (self.density * self.specific_heat)

    @property
    def shear_modulus_reference(self) -> float:
        """Small-strain shear modulus 2(C10 + C01) [Pa] of the hyperelastic constants."""
        return 2.0 * (self.c10 + self.c01)

    # -- TOML construction -----------------------------------------------------------------------

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], name: str | None = None) -> Elastomer:
        """Build an elastomer from a TOML table of an elastomer file.

        The format is that of ``data/elastomers.toml`` (quantities with units, see
        :class:`sealsim.properties.catalogue.ElastomerEntry`); tables in the older format
        (units in the key names, ``glass_transition_C = -30``) are read too.  Unknown,
        missing or invalid fields raise :class:`InputError` naming the field.

        Parameters
        ----------
        data : mapping
            The material's table.
        name : str, optional
            Material name; default ``data["name"]`` (the table key when read from a file).

        Returns
        -------
        Elastomer

        Examples
        --------
        >>> d = {"glass_transition": "-30 degC", "density": "1250 kg/m^3",
        ...      "thermal_conductivity": "0.25 W/(m*K)", "specific_heat": "1700 J/(kg*K)",
        ...      "thermal_expansion": "2e-4 1/K", "c10": "1.0 MPa", "c01": "0.25 MPa",
        ...      "bulk_modulus": "2000 MPa", "service_min": "-40 degC",
        ...      "service_max": "100 degC",
        ...      "modulus": {"glassy": "2000 MPa", "rubbery": "2.7 MPa"}}
        >>> Elastomer.from_dict(d, name="myNBR").wlf_reference_temperature
        243.15
        """
        return _from_dict(data, name)


# ---------------------------------------------------------------------------------------------
# TOML format (models and reading: sealsim.properties.catalogue)
# ---------------------------------------------------------------------------------------------


def _from_dict(data: Mapping[str, Any], name: str | None) -> Elastomer:
    from sealsim.properties.catalogue import read_elastomer_table

    return _build(*read_elastomer_table(data, name))


def _build(name: str, entry: Any, where: str, names: Mapping[str, str]) -> Elastomer:
    """The Elastomer of a validated file entry; a failed physical check names the field as
    written in the file."""
    from sealsim.properties.catalogue import elastomer_key

    kwargs = {"wlf_c1": WLF_UNIVERSAL.c1, "wlf_c2": WLF_UNIVERSAL.c2,
              **entry.elastomer_arguments(name)}
    try:
        return Elastomer(**kwargs)
    except InputError as exc:
        field = getattr(exc, "field", None)
        prefix = f"{where}: field '{elastomer_key(field, names)}'" if field else where
        raise InputError(f"{prefix} (checked after conversion to SI units): {exc}") from None


def load_elastomer_file(path: str | Path) -> dict[str, Elastomer]:
    """Read every elastomer table of a TOML file in the catalogue format.

    The format (quantities with units, like case files) is described in
    :mod:`sealsim.properties.catalogue`.

    Parameters
    ----------
    path : str or pathlib.Path
        TOML file; each top-level table is one material, its key the name.

    Returns
    -------
    dict
        name → :class:`Elastomer`.

    Examples
    --------
    >>> from sealsim.properties.elastomers import _catalogue_path
    >>> sorted(load_elastomer_file(_catalogue_path()))
    ['ACM', 'FKM', 'HNBR', 'NBR', 'VMQ']
    """
    from sealsim.properties.catalogue import read_elastomer_tables, read_text_file

    text = read_text_file(path, "elastomer file")
    return {key: _build(*table) for key, table
            in read_elastomer_tables(text, f"elastomer file {str(path)!r}").items()}


# ---------------------------------------------------------------------------------------------
# catalogue
# ---------------------------------------------------------------------------------------------


def _catalogue_path() -> Path:
    return Path(str(resources.files("sealsim.properties").joinpath("data/elastomers.toml")))


@functools.lru_cache(maxsize=1)
def _catalogue() -> dict[str, Elastomer]:
    return {k.upper(): v for k, v in load_elastomer_file(_catalogue_path()).items()}


def list_elastomers() -> list[str]:
    """Names of the catalogue elastomers.

    Returns
    -------
    list of str

    Examples
    --------
    >>> list_elastomers()
    ['NBR', 'HNBR', 'FKM', 'ACM', 'VMQ']
    """
    return list(_catalogue())


def get_elastomer(name: str) -> Elastomer:
    """Catalogue elastomer by name (case-insensitive).

    Parameters
    ----------
    name : str
        "NBR", "HNBR", "FKM", "ACM" or "VMQ".

    Returns
    -------
    Elastomer

    Raises
    ------
    InputError
        Unknown name; the message lists close matches and the available names.

    Examples
    --------
    >>> get_elastomer("fkm").glass_transition
    255.15
    """
    cat = _catalogue()
    if not isinstance(name, str):
        raise InputError(f"elastomer name must be a string; got {name!r}")
    key = name.strip().upper()
    if key in cat:
        return cat[key]
    close = difflib.get_close_matches(key, list(cat), n=3, cutoff=0.4)
    hint = f" Did you mean {', '.join(close)}?" if close else ""
    raise InputError(
        f"unknown elastomer {name!r}.{hint} Available: {', '.join(cat)} ('sealsim material "
        f"list'); define others in a file given with --material-file"
    )
