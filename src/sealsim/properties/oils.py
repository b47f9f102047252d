"""Lubricating oils: viscosity--temperature, viscosity index and thermophysical properties.

Two layers, as everywhere in sealsim:

* **Pure, vectorised physics functions** (numpy array in, array out; a Python float in gives a
  Python float out), all in SI units: temperature in K, kinematic viscosity in m^2/s, dynamic
  viscosity in Pa s, density in kg/m^3, pressure in Pa, thermal conductivity in W/(m K) and
  specific heat in J/(kg K):
  :func:`walther_viscosity`, :func:`walther_constants` (ASTM D341),
  :func:`viscosity_index` (ASTM D2270), :func:`density` and :func:`expansion_d1250` (ASTM
  D1250), :func:`thermal_conductivity_cragoe`,
  :func:`specific_heat_cragoe` (Cragoe, NBS 1929) and :func:`barus_viscosity`.
* **The** :class:`Oil` **record** (frozen dataclass) and a small catalogue of typical gear and
  circulating oils (``data/oils.toml``): :func:`list_oils`, :func:`get_oil`,
  :func:`load_oil_file`.

Range-check contract
--------------------
The property methods of :class:`Oil` (``kinematic_viscosity``, ``dynamic_viscosity``,
``density``, ...) are called in solver loops, so they do **not** check the oil's range of use:
they neither warn nor raise for a temperature below the oil's ``min_temperature`` or for a
viscosity below the 2 mm^2/s validity limit of ASTM D341.  They only raise :class:`InputError`
for a temperature that is not finite (it would give a NaN) or outside 150-700 K (which
almost always means degC were given instead of K).  A simulation calls
:meth:`Oil.check_temperature` once on its input temperatures and on its resulting
temperatures: it raises :class:`InputError` below
``min_temperature`` and emits :class:`OilRangeWarning` where the viscosity is below 2 mm^2/s.

Oil file format (catalogue and user files)
------------------------------------------
TOML, one table per oil under ``[oils]``; quantities are strings with units, as in case
files (:mod:`sealsim.properties.catalogue` has the models and every field)::

    [oils."VG68-mineral"]
    family = "mineral"                 # mineral | PAO | PAG | ester | other
    nu40 = "68 mm^2/s"                 # kinematic viscosity at 40 degC
    nu100 = "8.7 mm^2/s"               # kinematic viscosity at 100 degC
    density15 = "880 kg/m^3"           # density at 15 degC
    source = "datasheet of ..."        # where the numbers come from

Instead of ``nu40``/``nu100`` an entry may give ``walther_A`` and ``walther_B`` (ASTM D341
constants for mm^2/s and K).  Optional: ``min_temperature``,
``pressure_viscosity_coefficient``, ``thermal_conductivity``, ``specific_heat``,
``thermal_expansion``.  The built-in catalogue may also give ``aliases`` (a list of names);
user files may not.  Unknown fields are an error.  Files in the older format (plain numbers,
unit in the key name: ``nu40_mm2_s = 68.0``) are still read.
"""

from __future__ import annotations

import difflib
import math
import re
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from os import PathLike
from typing import Any

import numpy as np

from sealsim.errors import InputError
from sealsim.properties.oil_limits import (
    EXPANSION_MAX,
    PRESSURE_VISCOSITY_MAX,
    RHO15_RANGE,
    SPECIFIC_HEAT_RANGE,
    THERMAL_CONDUCTIVITY_RANGE,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = [
    "FAMILIES",
    "Oil",
    "OilRangeWarning",
    "barus_viscosity",
    "density",
    "expansion_d1250",
    "get_oil",
    "list_oils",
    "load_oil_file",
    "specific_heat_cragoe",
    "thermal_conductivity_cragoe",
    "viscosity_index",
    "walther_constants",
    "walther_viscosity",
]

#: Offset between degC and K [K].
T0 = ZERO_CELSIUS_K
#: Reference temperatures of the viscosity index [K].
T40 = T0 + 40.0
T100 = T0 + 100.0
#: Lower validity limit of the ASTM D341 (+0.7) form and of ASTM D2270 [m^2/s] (2 mm^2/s).
NU_MIN_D341 = 2.0e-6
#: Upper plausibility limit for kinematic viscosity inputs [m^2/s] (catches mm^2/s given as m^2/s).
_NU_MAX = 1.0
#: Plausible temperature range of all oil functions [K] (-123 to 427 degC): wider than any use
#: of a lubricating oil; its purpose is to catch degC given where K is expected.
T_RANGE = (150.0, 700.0)
#: Density of water at 15 degC used for the specific gravity s15 = rho15 / 999.0 [kg/m^3].
RHO_WATER_15 = 999.0
#: K1 of the lubricating-oil group of ASTM D1250 / API MPMS 11.1 at 15 degC [kg/(m^3 K)]
#: (0.34878 kg/m^3 per degF at 60 degF, times 1.8): alpha_15 = K1 / rho15.
D1250_K1_LUBRICATING = 0.34878 * 1.8

#: Oil families.
FAMILIES = ("mineral", "PAO", "PAG", "ester", "other")

#: Default Barus pressure-viscosity coefficient per family [1/Pa].  Mineral oils: Stachowiak &
#: Batchelor, Engineering Tribology, Table 2.3 (heavy machine oils 23.7-34.6 GPa^-1 at 30 degC,
#: 15.8-19.5 GPa^-1 at 100 degC); PAO 13-18, PAG/ester 10-15 GPa^-1 are typical literature
#: ranges, not checked against a primary source.  One temperature-independent value per
#: family, chosen for the 60-100 degC of a seal contact.  alpha*p <= 0.1 at lip pressures, so
#: this choice matters little.
DEFAULT_PRESSURE_VISCOSITY = {
    "mineral": 20e-9,
    "PAO": 15e-9,
    "PAG": 12e-9,
    "ester": 12e-9,
    "other": 20e-9,
}

#: Constant thermal conductivity [W/(m K)] and specific heat [J/(kg K)] used for synthetic
#: families when no value is given: middle of typical literature ranges, not checked against a
#: primary source (PAO k 0.14-0.15, c_p 2.1-2.3 kJ/(kg K); PAG k 0.15-0.17, c_p
#: 1.9-2.1 kJ/(kg K)).  Cragoe's correlation is fitted to petroleum oils and gives
#: ~0.11 W/(m K) for a PAG of s15 = 1.02.  Families not listed (mineral, ester, other) use the
#: Cragoe correlations.
DEFAULT_THERMAL = {
    "PAO": (0.145, 2200.0),
    "PAG": (0.160, 2000.0),
}

#: Typical lower temperature of use (pour-point-like) [degC] of mineral industrial oils, by
#: ISO VG grade: typical values, not from a datasheet.  Between grades the default is
#: interpolated linearly in log10(nu40); outside VG 32-460 the end values are used.
MINERAL_MIN_TEMPERATURE_C = {32: -30.0, 46: -27.0, 68: -24.0, 100: -21.0, 150: -18.0,
                             220: -15.0, 320: -12.0, 460: -10.0}
#: Typical lower temperature of use [degC] of the other families (typical, not datasheet).
#: "other" uses the mineral rule (conservative).
FAMILY_MIN_TEMPERATURE_C = {"PAO": -40.0, "PAG": -35.0, "ester": -30.0}


class OilRangeWarning(UserWarning):
    """An oil is used outside the validity range of its correlations (e.g. nu < 2 mm^2/s)."""


# ----------------------------------------------------------------------------------------------
# input validation helpers
# ----------------------------------------------------------------------------------------------


def _out(x: Any) -> Any:
    """Return a Python float for a 0-d result, the array otherwise."""
    return float(x) if np.ndim(x) == 0 else x


def _array(value: Any, name: str, unit: str, *, lo: float | None = None,
           hi: float | None = None, lo_open: bool = False, hint: str = "") -> np.ndarray:
    """Convert ``value`` to a float array, checking that it is finite and inside [lo, hi].

    ``lo_open`` makes the lower bound exclusive.  Raises InputError naming ``name``.
    """
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} = {value!r} is not a number; give a value in {unit}") from None
    if arr.ndim == 0:  # the scalar call of every time step: checked without array reductions
        x = float(arr)
        if math.isfinite(x) and (lo is None or (x > lo if lo_open else x >= lo)) and (
                hi is None or x <= hi):
            return arr
    finite = np.isfinite(arr)
    if not finite.all():
        bad = arr[~finite].flat[0] if arr.ndim else arr
        raise InputError(f"{name} = {float(bad)} {unit} is not a finite number")
    bad_mask = np.zeros(arr.shape, dtype=bool)
    if lo is not None:
        bad_mask |= (arr <= lo) if lo_open else (arr < lo)
    if hi is not None:
        bad_mask |= arr > hi
    if bad_mask.any():
        bad = float(arr[bad_mask].flat[0]) if arr.ndim else float(arr)
        if lo is not None and hi is not None:
            allowed = f"{lo:g} {unit} {'<' if lo_open else '<='} {name} <= {hi:g} {unit}"
        elif lo is not None:
            allowed = f"{name} {'>' if lo_open else '>='} {lo:g} {unit}"
        else:
            allowed = f"{name} <= {hi:g} {unit}"
        raise InputError(f"{name} = {bad:g} {unit} is out of range; allowed: {allowed}{hint}")
    return arr


def _temperature(value: Any, name: str = "temperature") -> np.ndarray:
    return _array(value, name, "K", lo=T_RANGE[0], hi=T_RANGE[1],
                  hint=" (temperatures are absolute, in K: add 273.15 to degC)")


def _kinematic(value: Any, name: str, lo: float = 0.0) -> np.ndarray:
    return _array(value, name, "m^2/s", lo=lo, lo_open=lo == 0.0, hi=_NU_MAX,
                  hint=" (kinematic viscosity is in m^2/s: 1 mm^2/s = 1 cSt = 1e-6 m^2/s)")


def _rho15(value: Any, name: str = "rho15") -> np.ndarray:
    lo, hi = RHO15_RANGE
    hint = " (density is in kg/m^3: 0.88 g/ml = 880 kg/m^3)"
    return _array(value, name, "kg/m^3", lo=lo, hi=hi, hint=hint)


# ----------------------------------------------------------------------------------------------
# ASTM D341 (Ubbelohde-Walther)
# ----------------------------------------------------------------------------------------------


def walther_viscosity(temperature, A, B):
    r"""Kinematic viscosity from the ASTM D341 (Ubbelohde-Walther) equation.

    .. math::

        \log_{10}\log_{10}(\nu + 0.7) = A - B \log_{10} T

    with :math:`\nu` in mm^2/s and :math:`T` in K, so that
    :math:`\nu = 10^{10^{A - B \log_{10} T}} - 0.7`; the result is converted to m^2/s.

    The +0.7 form of ASTM D341 is valid for :math:`\nu \ge 2` mm^2/s.  Below 2 mm^2/s (hot, thin
    oils) the standard adds correction terms to :math:`\nu + 0.7`; this function does not, so
    such values are an extrapolation outside the validity of the fit (see
    :meth:`Oil.check_temperature`).  Where the viscosity exceeds the float range (far below any
    pour point) the result is ``inf``.

    Parameters
    ----------
    temperature : array_like
        Temperature [K], 150-700 K (see :data:`T_RANGE`).
    A : array_like
        ASTM D341 intercept [-] (for nu in mm^2/s and T in K).
    B : array_like
        ASTM D341 slope [-] (for nu in mm^2/s and T in K), > 0.

    Returns
    -------
    numpy.ndarray or float
        Kinematic viscosity [m^2/s].

    References
    ----------
    ASTM D341-20, Standard Practice for Viscosity-Temperature Equations and Charts for Liquid
    Petroleum or Hydrocarbon Products, ASTM International.

    Examples
    --------
    ISO VG 68 mineral oil (A = 9.3097, B = 3.6244) at 40 degC:

    >>> round(walther_viscosity(313.15, 9.3097, 3.6244) * 1e6, 1)
    68.0
    """
    t = _temperature(temperature)
    a = _array(A, "A", "-")
    b = _array(B, "B", "-", lo=0.0, lo_open=True)
    with np.errstate(over="ignore"):
        nu_mm2 = 10.0 ** (10.0 ** (a - b * np.log10(t))) - 0.7
    return _out(nu_mm2 * 1e-6)


def walther_constants(t1, nu1, t2, nu2):
    r"""ASTM D341 constants A and B through two (temperature, viscosity) points.

    .. math::

        W_i = \log_{10}\log_{10}(\nu_i + 0.7), \qquad
        B = \frac{W_1 - W_2}{\log_{10} T_2 - \log_{10} T_1}, \qquad
        A = W_1 + B \log_{10} T_1

    with :math:`\nu` in mm^2/s and :math:`T` in K (converted inside).  The colder point must
    have the higher viscosity (B > 0).  The fit is valid for viscosities >= 2 mm^2/s; points
    down to 0.3 mm^2/s (where the double logarithm exists) are accepted.

    Parameters
    ----------
    t1, t2 : array_like
        Temperatures of the two points [K], 150-700 K and different.
    nu1, nu2 : array_like
        Kinematic viscosities at ``t1`` and ``t2`` [m^2/s], > 0.3e-6.

    Returns
    -------
    A, B : numpy.ndarray or float
        ASTM D341 constants [-] for nu in mm^2/s and T in K.

    References
    ----------
    ASTM D341-20, Standard Practice for Viscosity-Temperature Equations and Charts for Liquid
    Petroleum or Hydrocarbon Products, ASTM International.

    Examples
    --------
    >>> A, B = walther_constants(313.15, 68e-6, 373.15, 8.7e-6)
    >>> round(A, 4), round(B, 4)
    (9.3097, 3.6244)
    """
    t1a, t2a = _temperature(t1, "t1"), _temperature(t2, "t2")
    n1 = _kinematic(nu1, "nu1", lo=0.3e-6)
    n2 = _kinematic(nu2, "nu2", lo=0.3e-6)
    same = np.broadcast_to(t1a == t2a, np.broadcast_shapes(t1a.shape, t2a.shape))
    if same.any():
        bad = float(np.broadcast_to(t1a, same.shape)[same].flat[0])
        raise InputError(f"t1 and t2 must differ; both are {bad:g} K")
    with np.errstate(divide="ignore", invalid="ignore"):
        w1 = np.log10(np.log10(n1 * 1e6 + 0.7))
        w2 = np.log10(np.log10(n2 * 1e6 + 0.7))
    # Points at 0.3 mm^2/s exactly give log10(0) = -inf: treat as invalid.
    if not (np.isfinite(w1).all() and np.isfinite(w2).all()):
        raise InputError("nu1 and nu2 must be > 0.3e-6 m^2/s (0.3 mm^2/s) for ASTM D341")
    b = (w1 - w2) / (np.log10(t2a) - np.log10(t1a))
    if np.any(b <= 0):
        raise InputError(
            "the colder point must have the higher viscosity: got "
            f"nu1 = {np.ravel(n1)[0]:g} m^2/s at t1 = {np.ravel(t1a)[0]:g} K and "
            f"nu2 = {np.ravel(n2)[0]:g} m^2/s at t2 = {np.ravel(t2a)[0]:g} K")
    a = w1 + b * np.log10(t1a)
    return _out(a), _out(b)


# ----------------------------------------------------------------------------------------------
# ASTM D2270 viscosity index
# ----------------------------------------------------------------------------------------------

# ASTM D2270 Table 1: L and H [mm^2/s] as functions of the kinematic viscosity at 100 degC,
# 2.0-70.0 mm^2/s (steps 0.1 to 20, 0.2 to 30, 0.5 to 70).  Values as in ASTM D2270 Table 1,
# transcribed via the public tables of sherzodr/libvisc (libvisc.h) and
# dzyanisca/viscosity-chart (calcs/l_and_h.js), which agree row for row.
_D2270_NU100 = np.round(np.concatenate([
    np.arange(20, 201) / 10.0,          # 2.0 ... 20.0 step 0.1
    np.arange(101, 151) / 5.0,          # 20.2 ... 30.0 step 0.2
    np.arange(61, 141) / 2.0,           # 30.5 ... 70.0 step 0.5
]), 1)
_D2270_L = np.array([
    7.994, 8.64, 9.309, 10, 10.71, 11.45, 12.21, 13, 13.8, 14.63, 15.49, 16.36, 17.26, 18.18,
    19.12, 20.09, 21.08, 22.09, 23.13, 24.19, 25.32, 26.5, 27.75, 29.07, 30.48, 31.96, 33.52,
    35.13, 36.79, 38.5, 40.23, 41.99, 43.76, 45.53, 47.31, 49.09, 50.87, 52.64, 54.42, 56.2,
    57.97, 59.74, 61.52, 63.32, 65.18, 67.12, 69.16, 71.29, 73.48, 75.72, 78, 80.25, 82.39,
    84.53, 86.66, 88.85, 91.04, 93.2, 95.43, 97.72, 100, 102.3, 104.6, 106.9, 109.2, 111.5,
    113.9, 116.2, 118.5, 120.9, 123.3, 125.7, 128, 130.4, 132.8, 135.3, 137.7, 140.1, 142.7,
    145.2, 147.7, 150.3, 152.9, 155.4, 158, 160.6, 163.2, 165.8, 168.5, 171.2, 173.9, 176.6,
    179.4, 182.1, 184.9, 187.6, 190.4, 193.3, 196.2, 199, 201.9, 204.8, 207.8, 210.7, 213.6,
    216.6, 219.6, 222.6, 225.7, 228.8, 231.9, 235, 238.1, 241.2, 244.3, 247.4, 250.6, 253.8,
    257, 260.1, 263.3, 266.6, 269.8, 273, 276.3, 279.6, 283, 286.4, 289.7, 293, 296.5, 300,
    303.4, 306.9, 310.3, 313.9, 317.5, 321.1, 324.6, 328.3, 331.9, 335.5, 339.2, 342.9, 346.6,
    350.3, 354.1, 358, 361.7, 365.6, 369.4, 373.3, 377.1, 381, 384.9, 388.9, 392.7, 396.7,
    400.7, 404.6, 408.6, 412.6, 416.7, 420.7, 424.9, 429, 433.2, 437.3, 441.5, 445.7, 449.9,
    454.2, 458.4, 462.7, 467, 471.3, 475.7, 479.7, 483.9, 488.6, 493.2, 501.5, 510.8, 519.9,
    528.8, 538.4, 547.5, 556.7, 566.4, 575.6, 585.2, 595, 604.3, 614.2, 624.1, 633.6, 643.4,
    653.8, 663.3, 673.7, 683.9, 694.5, 704.2, 714.9, 725.7, 736.5, 747.2, 758.2, 769.3, 779.7,
    790.4, 801.6, 812.8, 824.1, 835.5, 847, 857.5, 869, 880.6, 892.3, 904.1, 915.8, 927.6,
    938.6, 951.2, 963.4, 975.4, 987.1, 998.9, 1011, 1023, 1055, 1086, 1119, 1151, 1184, 1217,
    1251, 1286, 1321, 1356, 1391, 1427, 1464, 1501, 1538, 1575, 1613, 1651, 1691, 1730, 1770,
    1810, 1851, 1892, 1935, 1978, 2021, 2064, 2108, 2152, 2197, 2243, 2288, 2333, 2380, 2426,
    2473, 2521, 2570, 2618, 2667, 2717, 2767, 2817, 2867, 2918, 2969, 3020, 3073, 3126, 3180,
    3233, 3286, 3340, 3396, 3452, 3507, 3563, 3619, 3676, 3734, 3792, 3850, 3908, 3966, 4026,
    4087, 4147, 4207, 4268, 4329, 4392, 4455, 4517, 4580, 4645, 4709, 4773, 4839, 4905,
])
_D2270_H = np.array([
    6.394, 6.894, 7.41, 7.944, 8.496, 9.063, 9.647, 10.25, 10.87, 11.5, 12.15, 12.82, 13.51,
    14.21, 14.93, 15.66, 16.42, 17.19, 17.97, 18.77, 19.56, 20.37, 21.21, 22.05, 22.92, 23.81,
    24.71, 25.63, 26.57, 27.53, 28.49, 29.46, 30.43, 31.4, 32.37, 33.34, 34.32, 35.29, 36.26,
    37.23, 38.19, 39.17, 40.15, 41.13, 42.14, 43.18, 44.24, 45.33, 46.44, 47.51, 48.57, 49.61,
    50.69, 51.78, 52.88, 53.98, 55.09, 56.2, 57.31, 58.45, 59.6, 60.74, 61.89, 63.05, 64.18,
    65.32, 66.48, 67.64, 68.79, 69.94, 71.1, 72.27, 73.42, 74.57, 75.73, 76.91, 78.08, 79.27,
    80.46, 81.67, 82.87, 84.08, 85.3, 86.51, 87.72, 88.95, 90.19, 91.4, 92.65, 93.92, 95.19,
    96.45, 97.71, 98.97, 100.2, 101.5, 102.8, 104.1, 105.4, 106.7, 108, 109.4, 110.7, 112,
    113.3, 114.7, 116, 117.4, 118.7, 120.1, 121.5, 122.9, 124.2, 125.6, 127, 128.4, 129.8,
    131.2, 132.6, 134, 135.4, 136.8, 138.2, 139.6, 141, 142.4, 143.9, 145.3, 146.8, 148.2,
    149.7, 151.2, 152.6, 154.1, 155.6, 157, 158.6, 160.1, 161.6, 163.1, 164.6, 166.1, 167.7,
    169.2, 170.7, 172.3, 173.8, 175.4, 177, 178.6, 180.2, 181.7, 183.3, 184.9, 186.5, 188.1,
    189.7, 191.3, 192.9, 194.6, 196.2, 197.8, 199.4, 201, 202.6, 204.3, 205.9, 207.6, 209.3,
    211, 212.7, 214.4, 216.1, 217.7, 219.4, 221.1, 222.8, 224.5, 226.2, 227.7, 229.5, 233,
    236.4, 240.1, 243.5, 247.1, 250.7, 254.2, 257.8, 261.5, 264.9, 268.6, 272.3, 275.8, 279.6,
    283.3, 286.8, 290.5, 294.4, 297.9, 301.8, 305.6, 309.4, 313, 317, 320.9, 324.9, 328.8,
    332.7, 336.7, 340.5, 344.4, 348.4, 352.3, 356.4, 360.5, 364.6, 368.3, 372.3, 376.4, 380.6,
    384.6, 388.8, 393, 396.6, 401.1, 405.3, 409.5, 413.5, 417.6, 421.7, 432.4, 443.2, 454,
    464.9, 475.9, 487, 498.1, 509.6, 521.1, 532.5, 544, 555.6, 567.1, 579.3, 591.3, 603.1, 615,
    627.1, 639.2, 651.8, 664.2, 676.6, 689.1, 701.9, 714.9, 728.2, 741.3, 754.4, 767.6, 780.9,
    794.5, 808.2, 821.9, 835.5, 849.2, 863, 876.9, 890.9, 905.3, 919.6, 933.6, 948.2, 962.9,
    977.5, 992.1, 1007, 1021, 1036, 1051, 1066, 1082, 1097, 1112, 1127, 1143, 1159, 1175, 1190,
    1206, 1222, 1238, 1254, 1270, 1286, 1303, 1319, 1336, 1352, 1369, 1386, 1402, 1419, 1436,
    1454, 1471, 1488, 1506, 1523, 1541, 1558,
])
assert _D2270_NU100.shape == _D2270_L.shape == _D2270_H.shape == (311,)


def _d2270_l_h(nu100_mm2):
    """L and H [mm^2/s] of ASTM D2270 for nu100 [mm^2/s] >= 2 (table, formulas above 70)."""
    y = np.asarray(nu100_mm2, dtype=float)
    l_tab = np.interp(y, _D2270_NU100, _D2270_L)
    h_tab = np.interp(y, _D2270_NU100, _D2270_H)
    l_big = 0.8353 * y**2 + 14.67 * y - 216.0
    h_big = 0.1684 * y**2 + 11.85 * y - 97.0
    big = y > 70.0
    return np.where(big, l_big, l_tab), np.where(big, h_big, h_tab)


def viscosity_index(nu40, nu100):
    r"""Viscosity index from the kinematic viscosities at 40 and 100 degC (ASTM D2270).

    With :math:`U = \nu_{40}` and :math:`Y = \nu_{100}` in mm^2/s, and L, H from ASTM D2270
    Table 1 (linear interpolation, 2 <= Y <= 70 mm^2/s) or, for Y > 70 mm^2/s,
    :math:`L = 0.8353 Y^2 + 14.67 Y - 216` and :math:`H = 0.1684 Y^2 + 11.85 Y - 97`:

    * Procedure A (VI <= 100, i.e. U >= H): :math:`VI = 100 (L - U)/(L - H)`
    * Procedure B (VI > 100, i.e. U < H):
      :math:`N = (\log_{10} H - \log_{10} U)/\log_{10} Y`,
      :math:`VI = (10^N - 1)/0.00715 + 100`

    The result is not rounded (ASTM D2270 reports the nearest integer).

    Parameters
    ----------
    nu40 : array_like
        Kinematic viscosity at 40 degC [m^2/s], > 0.
    nu100 : array_like
        Kinematic viscosity at 100 degC [m^2/s], >= 2e-6 (VI is not defined below 2 mm^2/s).

    Returns
    -------
    numpy.ndarray or float
        Viscosity index [-].

    References
    ----------
    ASTM D2270-10, Standard Practice for Calculating Viscosity Index from Kinematic Viscosity
    at 40 and 100 degC, ASTM International (ISO 2909 is equivalent).

    Examples
    --------
    The two worked examples of ASTM D2270:

    >>> round(viscosity_index(73.30e-6, 8.86e-6))
    92
    >>> round(viscosity_index(22.83e-6, 5.05e-6))
    156
    """
    u = _kinematic(nu40, "nu40") * 1e6
    y = _kinematic(nu100, "nu100", lo=NU_MIN_D341 * (1 - 1e-9)) * 1e6
    if np.any(u <= y):
        raise InputError(
            f"nu40 must be greater than nu100; got nu40 = {np.ravel(u)[0]:g} mm^2/s and "
            f"nu100 = {np.ravel(y)[0]:g} mm^2/s (values in m^2/s: nu40 = "
            f"{np.ravel(u)[0] * 1e-6:g}, nu100 = {np.ravel(y)[0] * 1e-6:g})")
    L, H = _d2270_l_h(y)
    vi_a = 100.0 * (L - u) / (L - H)
    n = (np.log10(H) - np.log10(u)) / np.log10(y)
    vi_b = (10.0**n - 1.0) / 0.00715 + 100.0
    return _out(np.where(u >= H, vi_a, vi_b))


# ----------------------------------------------------------------------------------------------
# Thermophysical properties
# ----------------------------------------------------------------------------------------------


def expansion_d1250(rho15):
    r"""Thermal expansion coefficient at 15 degC of a petroleum lubricating oil (ASTM D1250).

    .. math:: \alpha_{15} = K_1 / \rho_{15}, \qquad K_1 = 0.6278\ \mathrm{kg/(m^3\,K)}

    the lubricating-oil group of the petroleum measurement tables (API MPMS 11.1 / ASTM
    D1250: :math:`K_0 = 0`, :math:`K_1 = 0.34878` kg/m^3 per degF at 60 degF, i.e. 0.6278 per
    K, as in Table 54D at 15 degC).  The tables hold for 800-1164 kg/m^3; synthetic oils (PAO,
    PAG, esters) expand differently: give their datasheet value.

    Parameters
    ----------
    rho15 : array_like
        Density at 15 degC [kg/m^3], 600-1300.

    Returns
    -------
    numpy.ndarray or float
        Thermal expansion coefficient at 15 degC [1/K].

    References
    ----------
    API MPMS Chapter 11.1 / ASTM D1250-04 (IP 200/04), Temperature and Pressure Volume
    Correction Factors for Generalized Crude Oils, Refined Products, and Lubricating Oils.

    Examples
    --------
    >>> round(expansion_d1250(880.0) * 1e4, 2)
    7.13
    """
    return _out(D1250_K1_LUBRICATING / _rho15(rho15))


def density(temperature, rho15, expansion=None):
    r"""Density of a lubricating oil over temperature (ASTM D1250 volume correction).

    .. math::

        \rho(T) = \rho_{15}\,\exp[-\alpha_{15}\,\Delta T\,(1 + 0.8\,\alpha_{15}\,\Delta T)],
        \qquad \Delta T = T - 288.15\ \mathrm{K}

    the volume correction factor of the petroleum measurement tables, with the expansion
    coefficient :math:`\alpha_{15}` of :func:`expansion_d1250` unless one is given.

    Parameters
    ----------
    temperature : array_like
        Temperature [K], 150-700 K (see :data:`T_RANGE`).
    rho15 : array_like
        Density at 15 degC [kg/m^3], 600-1300.
    expansion : array_like, optional
        Thermal expansion coefficient at 15 degC, alpha_15 [1/K], 0-2e-3.  Default
        :func:`expansion_d1250` (880 kg/m^3: 7.13e-4 1/K).

    Returns
    -------
    numpy.ndarray or float
        Density [kg/m^3].

    References
    ----------
    API MPMS Chapter 11.1 / ASTM D1250-04 (IP 200/04), Temperature and Pressure Volume
    Correction Factors for Generalized Crude Oils, Refined Products, and Lubricating Oils.

    Examples
    --------
    >>> round(density(353.15, 880.0), 1)
    838.7
    """
    t = _temperature(temperature)
    r = _rho15(rho15)
    alpha = (D1250_K1_LUBRICATING / r if expansion is None else
             _array(expansion, "expansion", "1/K", lo=0.0, hi=EXPANSION_MAX))
    dt = t - (T0 + 15.0)
    return _out(r * np.exp(-alpha * dt * (1.0 + 0.8 * alpha * dt)))


def thermal_conductivity_cragoe(temperature, rho15):
    r"""Thermal conductivity of a petroleum oil (Cragoe, NBS 1929).

    .. math::

        k = \frac{0.1172}{s_{15}}\,(1 - 0.00054\,\vartheta)\ \mathrm{W/(m\,K)},
        \qquad s_{15} = \rho_{15} / 999.0\ \mathrm{kg/m^3}

    with :math:`\vartheta` the temperature in degC.  Fitted to petroleum oils; synthetic oils
    (PAO, PAG) conduct more heat (see :class:`Oil`).

    Parameters
    ----------
    temperature : array_like
        Temperature [K], 150-700 K (see :data:`T_RANGE`).
    rho15 : array_like
        Density at 15 degC [kg/m^3], 600-1300.

    Returns
    -------
    numpy.ndarray or float
        Thermal conductivity [W/(m K)].

    References
    ----------
    C. S. Cragoe, Thermal Properties of Petroleum Products, NBS Miscellaneous Publication 97,
    1929 (converted to SI units).

    Examples
    --------
    >>> round(thermal_conductivity_cragoe(353.15, 0.88 * 999.0), 3)
    0.127
    """
    t = _temperature(temperature)
    s15 = _rho15(rho15) / RHO_WATER_15
    return _out(0.1172 / s15 * (1.0 - 0.00054 * (t - T0)))


def specific_heat_cragoe(temperature, rho15):
    r"""Specific heat capacity of a petroleum oil (Cragoe, NBS 1929).

    .. math::

        c_p = \frac{1.685 + 0.00339\,\vartheta}{\sqrt{s_{15}}}\ \mathrm{kJ/(kg\,K)},
        \qquad s_{15} = \rho_{15} / 999.0\ \mathrm{kg/m^3}

    with :math:`\vartheta` the temperature in degC; returned in J/(kg K).

    Parameters
    ----------
    temperature : array_like
        Temperature [K], 150-700 K (see :data:`T_RANGE`).
    rho15 : array_like
        Density at 15 degC [kg/m^3], 600-1300.

    Returns
    -------
    numpy.ndarray or float
        Specific heat capacity [J/(kg K)].

    References
    ----------
    C. S. Cragoe, Thermal Properties of Petroleum Products, NBS Miscellaneous Publication 97,
    1929 (converted to SI units).

    Examples
    --------
    >>> round(specific_heat_cragoe(353.15, 0.88 * 999.0))
    2085
    """
    t = _temperature(temperature)
    s15 = _rho15(rho15) / RHO_WATER_15
    return _out(1e3 * (1.685 + 0.00339 * (t - T0)) / np.sqrt(s15))


def barus_viscosity(eta0, alpha, pressure):
    r"""Dynamic viscosity under pressure (Barus equation).

    .. math::

        \eta = \eta_0\, e^{\alpha p}

    Parameters
    ----------
    eta0 : array_like
        Dynamic viscosity at the reference pressure [Pa s], > 0.
    alpha : array_like
        Pressure-viscosity coefficient [1/Pa], 0-1e-7 (oils: 1e-8 to 3.5e-8).
    pressure : array_like
        Pressure above the reference pressure of ``eta0`` [Pa], |p| <= 5e9.  Negative values
        (sub-ambient film pressure) are allowed.

    Returns
    -------
    numpy.ndarray or float
        Dynamic viscosity [Pa s].

    References
    ----------
    C. Barus, Isothermals, isopiestics and isometrics relative to viscosity, American Journal
    of Science 45 (1893) 87-96; coefficients: G. W. Stachowiak, A. W. Batchelor, Engineering
    Tribology, Table 2.3.

    Examples
    --------
    >>> round(barus_viscosity(0.0124, 20e-9, 3e6), 5)
    0.01317
    """
    e0 = _array(eta0, "eta0", "Pa s", lo=0.0, lo_open=True)
    a = _array(alpha, "alpha", "1/Pa", lo=0.0, hi=PRESSURE_VISCOSITY_MAX,
               hint=" (alpha is in 1/Pa: 20 GPa^-1 = 20e-9 1/Pa)")
    p = _array(pressure, "pressure", "Pa", lo=-5e9, hi=5e9)
    return _out(e0 * np.exp(a * p))


# ----------------------------------------------------------------------------------------------
# Oil record
# ----------------------------------------------------------------------------------------------


def default_min_temperature(family: str, nu40: float) -> float:
    """Typical lower temperature of use [K] for an oil family and ``nu40`` [m^2/s].

    PAO -40 degC, PAG -35 degC, ester -30 degC; mineral and other oils by ISO VG grade from
    :data:`MINERAL_MIN_TEMPERATURE_C` (VG 32 -30 degC ... VG 460 -10 degC), interpolated in
    log10(nu40) and held constant outside VG 32-460.  Typical values, not from a datasheet:
    give the datasheet pour point when known.

    Examples
    --------
    >>> round(default_min_temperature("mineral", 68e-6) - 273.15, 1)
    -24.0
    """
    if family in FAMILY_MIN_TEMPERATURE_C:
        return round(FAMILY_MIN_TEMPERATURE_C[family] + T0, 9)
    grades = np.log10(np.array(list(MINERAL_MIN_TEMPERATURE_C)) * 1e-6)
    values = np.array(list(MINERAL_MIN_TEMPERATURE_C.values()))
    return round(float(np.interp(np.log10(nu40), grades, values)) + T0, 9)


@dataclass(frozen=True)
class Oil:
    """A lubricating oil: ASTM D341 viscosity-temperature fit plus thermophysical data.

    Build one with :meth:`from_datasheet` (nu40/nu100 pair), :meth:`from_walther` (A, B) or
    :func:`get_oil` (catalogue).  All values in SI units.

    Attributes
    ----------
    name : str
        Name of the oil.
    family : str
        One of ``"mineral"``, ``"PAO"``, ``"PAG"``, ``"ester"``, ``"other"``.
    walther_A, walther_B : float
        ASTM D341 constants [-] (for nu in mm^2/s and T in K), B > 0.
    rho15 : float
        Density at 15 degC [kg/m^3], 600-1300.
    pressure_viscosity_coefficient : float, optional
        Barus alpha [1/Pa], temperature independent.  Default per family from
        :data:`DEFAULT_PRESSURE_VISCOSITY` (mineral 20e-9, PAO 15e-9, PAG and ester 12e-9).
    min_temperature : float, optional
        Lowest temperature of use [K] (pour-point-like).  Default from
        :func:`default_min_temperature` (typical values, not a datasheet).
    thermal_conductivity_value : float or None, optional
        Constant thermal conductivity [W/(m K)].  ``None``: Cragoe correlation, except PAO
        (0.145) and PAG (0.160), which get constants from :data:`DEFAULT_THERMAL`.
    specific_heat_value : float or None, optional
        Constant specific heat [J/(kg K)].  ``None``: Cragoe correlation, except PAO (2200)
        and PAG (2000).
    thermal_expansion : float, optional
        Thermal expansion coefficient at 15 degC [1/K] of :func:`density`; default
        :func:`expansion_d1250` of ``rho15`` (ASTM D1250 lubricating oils: 880 kg/m^3 gives
        7.13e-4).
    source : str, optional
        Where the numbers come from.

    Notes
    -----
    The property methods are vectorised and do not check the oil's range of use (they are
    called in solver loops); call :meth:`check_temperature` on a simulation's input and result
    temperatures.  They raise :class:`InputError` only for a temperature that is not finite or
    outside :data:`T_RANGE` (150-700 K).

    Examples
    --------
    >>> oil = Oil.from_datasheet("my VG 68", 68e-6, 8.7e-6, 880.0)
    >>> round(oil.kinematic_viscosity(353.15) * 1e6, 1)
    14.7
    >>> round(oil.viscosity_index)
    99
    """

    name: str
    family: str
    walther_A: float
    walther_B: float
    rho15: float
    pressure_viscosity_coefficient: float | None = None
    min_temperature: float | None = None
    thermal_conductivity_value: float | None = None
    specific_heat_value: float | None = None
    thermal_expansion: float | None = None
    source: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise InputError(f"oil name = {self.name!r} must be a non-empty string")
        if self.family not in FAMILIES:
            raise InputError(f"oil {self.name!r}: family = {self.family!r} is not one of "
                             f"{', '.join(FAMILIES)}")
        where = f"oil {self.name!r}: "

        def num(field: str, unit: str, **limits: Any) -> float:
            try:
                return float(_array(getattr(self, field), field, unit, **limits))
            except InputError as err:
                raise InputError(where + str(err)) from None

        object.__setattr__(self, "walther_A", num("walther_A", "-"))
        object.__setattr__(self, "walther_B", num("walther_B", "-", lo=0.0, lo_open=True))
        object.__setattr__(self, "rho15", num("rho15", "kg/m^3", lo=RHO15_RANGE[0],
                                              hi=RHO15_RANGE[1],
                                              hint=" (0.88 g/ml = 880 kg/m^3)"))
        if self.thermal_expansion is None:
            object.__setattr__(self, "thermal_expansion", expansion_d1250(self.rho15))
        object.__setattr__(self, "thermal_expansion",
                           num("thermal_expansion", "1/K", lo=0.0, hi=EXPANSION_MAX))
        nu100 = self.nu100
        if not nu100 >= NU_MIN_D341 * (1 - 1e-6):
            raise InputError(
                f"{where}nu100 = {nu100:.4g} m^2/s ({nu100 * 1e6:.4g} mm^2/s) from walther_A = "
                f"{self.walther_A}, walther_B = {self.walther_B} is below 2 mm^2/s, the lower "
                "limit of ASTM D341/D2270; allowed: nu100 >= 2e-6 m^2/s")
        if self.pressure_viscosity_coefficient is None:
            object.__setattr__(self, "pressure_viscosity_coefficient",
                               DEFAULT_PRESSURE_VISCOSITY[self.family])
        object.__setattr__(self, "pressure_viscosity_coefficient",
                           num("pressure_viscosity_coefficient", "1/Pa", lo=0.0,
                               hi=PRESSURE_VISCOSITY_MAX,
                               hint=" (20 GPa^-1 = 20e-9 1/Pa)"))
        if self.min_temperature is None:
            object.__setattr__(self, "min_temperature",
                               default_min_temperature(self.family, self.nu40))
        object.__setattr__(self, "min_temperature",
                           num("min_temperature", "K", lo=0.0, lo_open=True,
                               hint=" (in K: add 273.15 to degC)"))
        k_default, cp_default = DEFAULT_THERMAL.get(self.family, (None, None))
        if self.thermal_conductivity_value is None and k_default is not None:
            object.__setattr__(self, "thermal_conductivity_value", k_default)
        if self.specific_heat_value is None and cp_default is not None:
            object.__setattr__(self, "specific_heat_value", cp_default)
        if self.thermal_conductivity_value is not None:
            object.__setattr__(self, "thermal_conductivity_value",
                               num("thermal_conductivity_value", "W/(m K)",
                                   lo=THERMAL_CONDUCTIVITY_RANGE[0],
                                   hi=THERMAL_CONDUCTIVITY_RANGE[1]))
        if self.specific_heat_value is not None:
            object.__setattr__(self, "specific_heat_value",
                               num("specific_heat_value", "J/(kg K)", lo=SPECIFIC_HEAT_RANGE[0],
                                   hi=SPECIFIC_HEAT_RANGE[1],
                                   hint=" (in J/(kg K): 2.1 kJ/(kg K) = 2100 J/(kg K))"))
        if not isinstance(self.source, str):
            raise InputError(f"{where}source = {self.source!r} must be a string")

    # -- constructors -------------------------------------------------------------------------

    @classmethod
    def from_datasheet(cls, name: str, nu40: float, nu100: float, rho15: float,
                       family: str = "mineral", *,
                       pressure_viscosity_coefficient: float | None = None,
                       min_temperature: float | None = None,
                       thermal_conductivity_value: float | None = None,
                       specific_heat_value: float | None = None,
                       thermal_expansion: float | None = None,
                       source: str = "user datasheet") -> Oil:
        """Oil from datasheet viscosities at 40 and 100 degC.

        Parameters
        ----------
        name : str
            Name of the oil.
        nu40, nu100 : float
            Kinematic viscosity at 40 and 100 degC [m^2/s]; nu40 > nu100 >= 2e-6.
        rho15 : float
            Density at 15 degC [kg/m^3], 600-1300.
        family : str, optional
            ``"mineral"`` (default), ``"PAO"``, ``"PAG"``, ``"ester"`` or ``"other"``.
        pressure_viscosity_coefficient, min_temperature, thermal_conductivity_value, \
specific_heat_value, thermal_expansion, source
            See :class:`Oil`.

        Returns
        -------
        Oil

        Examples
        --------
        >>> oil = Oil.from_datasheet("PAO 68", 68e-6, 10.3e-6, 845.0, family="PAO")
        >>> round(oil.walther_B, 3)
        3.238
        """
        where = f"oil {name!r}: "
        try:
            n40 = float(_kinematic(nu40, "nu40"))
            n100 = float(_kinematic(nu100, "nu100"))
            _rho15(rho15)
        except InputError as err:
            raise InputError(where + str(err)) from None
        if n100 < NU_MIN_D341:
            raise InputError(f"{where}nu100 = {n100:g} m^2/s ({n100 * 1e6:g} mm^2/s) is below "
                             "2 mm^2/s, the lower limit of ASTM D341/D2270; allowed: "
                             "nu100 >= 2e-6 m^2/s")
        if not n40 > n100:
            raise InputError(f"{where}nu40 = {n40 * 1e6:g} mm^2/s must be greater than nu100 = "
                             f"{n100 * 1e6:g} mm^2/s (an oil is thinner at 100 degC than at "
                             "40 degC: are the two swapped?)")
        A, B = walther_constants(T40, n40, T100, n100)
        return cls(name=name, family=family, walther_A=A, walther_B=B, rho15=rho15,
                   pressure_viscosity_coefficient=pressure_viscosity_coefficient,
                   min_temperature=min_temperature,
                   thermal_conductivity_value=thermal_conductivity_value,
                   specific_heat_value=specific_heat_value,
                   thermal_expansion=thermal_expansion, source=source)

    @classmethod
    def from_walther(cls, name: str, A: float, B: float, rho15: float,
                     family: str = "mineral", *,
                     pressure_viscosity_coefficient: float | None = None,
                     min_temperature: float | None = None,
                     thermal_conductivity_value: float | None = None,
                     specific_heat_value: float | None = None,
                     thermal_expansion: float | None = None,
                     source: str = "user ASTM D341 constants") -> Oil:
        """Oil from ASTM D341 constants A and B (nu in mm^2/s, T in K).

        The fit must give nu100 >= 2 mm^2/s; B > 0.  Other parameters as
        :meth:`from_datasheet`.

        Examples
        --------
        >>> oil = Oil.from_walther("VG 220", 8.8222, 3.3867, 895.0)
        >>> round(oil.nu40 * 1e6)
        220
        """
        return cls(name=name, family=family, walther_A=A, walther_B=B, rho15=rho15,
                   pressure_viscosity_coefficient=pressure_viscosity_coefficient,
                   min_temperature=min_temperature,
                   thermal_conductivity_value=thermal_conductivity_value,
                   specific_heat_value=specific_heat_value,
                   thermal_expansion=thermal_expansion, source=source)

    # -- properties ---------------------------------------------------------------------------

    def kinematic_viscosity(self, temperature):
        """Kinematic viscosity from the oil's ASTM D341 fit (no range check).

        Parameters
        ----------
        temperature : array_like
            Temperature [K], 150-700 K.

        Returns
        -------
        numpy.ndarray or float
            Kinematic viscosity [m^2/s], see :func:`walther_viscosity`.

        Examples
        --------
        >>> round(get_oil("VG68").kinematic_viscosity(373.15) * 1e6, 2)
        8.7
        """
        return walther_viscosity(temperature, self.walther_A, self.walther_B)

    def density(self, temperature):
        """Density, linear in temperature from 15 degC (see :func:`density`).

        Parameters
        ----------
        temperature : array_like
            Temperature [K], 150-700 K.

        Returns
        -------
        numpy.ndarray or float
            Density [kg/m^3].

        Examples
        --------
        >>> round(get_oil("VG68").density(288.15), 1)
        880.0
        """
        return density(temperature, self.rho15, self.thermal_expansion)

    def dynamic_viscosity(self, temperature, pressure=0.0):
        r"""Dynamic viscosity, with the Barus pressure correction.

        .. math:: \eta = \rho(T)\,\nu(T)\,e^{\alpha p}

        Parameters
        ----------
        temperature : array_like
            Temperature [K], 150-700 K.
        pressure : array_like, optional
            Pressure above ambient [Pa], default 0 (see :func:`barus_viscosity`).

        Returns
        -------
        numpy.ndarray or float
            Dynamic viscosity [Pa s].

        Examples
        --------
        >>> oil = Oil.from_datasheet("VG 68", 68e-6, 8.7e-6, 880.0)
        >>> round(oil.dynamic_viscosity(353.15) * 1e3, 1)
        12.3
        """
        eta0 = self.density(temperature) * self.kinematic_viscosity(temperature)
        if np.ndim(pressure) == 0 and pressure == 0:
            return eta0
        return barus_viscosity(eta0, self.pressure_viscosity_coefficient, pressure)

    def thermal_conductivity(self, temperature):
        """Thermal conductivity: ``thermal_conductivity_value`` if set, else Cragoe.

        Parameters
        ----------
        temperature : array_like
            Temperature [K], 150-700 K.

        Returns
        -------
        numpy.ndarray or float
            Thermal conductivity [W/(m K)], see :func:`thermal_conductivity_cragoe`.

        Examples
        --------
        >>> round(get_oil("VG68").thermal_conductivity(353.15), 3)
        0.127
        >>> get_oil("VG220-PAG").thermal_conductivity(353.15)
        0.16
        """
        if self.thermal_conductivity_value is None:
            return thermal_conductivity_cragoe(temperature, self.rho15)
        t = _temperature(temperature)
        return _out(np.full(t.shape, self.thermal_conductivity_value))

    def specific_heat(self, temperature):
        """Specific heat: ``specific_heat_value`` if set, else Cragoe.

        Parameters
        ----------
        temperature : array_like
            Temperature [K], 150-700 K.

        Returns
        -------
        numpy.ndarray or float
            Specific heat capacity [J/(kg K)], see :func:`specific_heat_cragoe`.

        Examples
        --------
        >>> round(get_oil("VG68").specific_heat(353.15))
        2084
        """
        if self.specific_heat_value is None:
            return specific_heat_cragoe(temperature, self.rho15)
        t = _temperature(temperature)
        return _out(np.full(t.shape, self.specific_heat_value))

    @property
    def nu40(self) -> float:
        """Kinematic viscosity at 40 degC [m^2/s]."""
        return walther_viscosity(T40, self.walther_A, self.walther_B)

    @property
    def nu100(self) -> float:
        """Kinematic viscosity at 100 degC [m^2/s]."""
        return walther_viscosity(T100, self.walther_A, self.walther_B)

    @property
    def viscosity_index(self) -> float:
        """Viscosity index [-] (ASTM D2270, unrounded) from :attr:`nu40` and :attr:`nu100`."""
        return viscosity_index(self.nu40, self.nu100)

    # -- range check --------------------------------------------------------------------------

    def check_temperature(self, temperature, name: str = "temperature") -> np.ndarray:
        """Check that the oil may be used at ``temperature`` [K].

        Raises :class:`InputError` if any temperature is below :attr:`min_temperature` (or is
        not finite or outside :data:`T_RANGE`).  Warns :class:`OilRangeWarning` if the
        viscosity is below 2 mm^2/s anywhere (outside the validity of ASTM D341: the value is
        extrapolated).

        Parameters
        ----------
        temperature : array_like
            Temperature(s) [K].
        name : str, optional
            Name of the quantity for the messages, e.g. ``"sump temperature"``.

        Returns
        -------
        numpy.ndarray
            ``temperature`` as a float array.

        Examples
        --------
        >>> Oil.from_datasheet("VG 68", 68e-6, 8.7e-6, 880.0).check_temperature(353.15)
        array(353.15)
        """
        t = _temperature(temperature, name)
        if np.any(t < self.min_temperature):
            t_min = float(np.min(t))
            raise InputError(
                f"{name} = {t_min - T0:.1f} degC is below the minimum temperature of oil "
                f"{self.name!r} ({self.min_temperature - T0:.1f} degC, {self.min_temperature:.2f}"
                " K); allowed: temperature >= min_temperature (set min_temperature from the "
                "datasheet pour point if it is lower)")
        nu = np.asarray(self.kinematic_viscosity(t))
        if np.any(nu < NU_MIN_D341):
            t_max = float(np.max(t))
            warnings.warn(
                f"oil {self.name!r}: {name} up to {t_max - T0:.1f} degC gives a kinematic "
                f"viscosity of {float(np.min(nu)) * 1e6:.2f} mm^2/s, below 2 mm^2/s where the "
                "ASTM D341 fit is valid; the viscosity is extrapolated",
                OilRangeWarning, stacklevel=2)
        return t


# ----------------------------------------------------------------------------------------------
# Catalogue and oil files
# ----------------------------------------------------------------------------------------------

def _normalise(name: str) -> str:
    """Lookup key: case-insensitive, ignoring spaces/punctuation and a leading 'ISO'."""
    key = re.sub(r"[^0-9a-z]", "", name.casefold())
    return key[3:] if key.startswith("isovg") else key


def _read_oils(text: str, origin: str, catalogue: bool
               ) -> tuple[dict[str, Oil], dict[str, str]]:
    """Oils of an oil file's text (validated by :mod:`sealsim.properties.catalogue`) and the
    catalogue's aliases ``{alias: name}``; names and aliases must not clash."""
    from sealsim.properties.catalogue import read_oil_tables

    oils: dict[str, Oil] = {}
    aliases: dict[str, str] = {}
    seen: dict[str, str] = {}
    for oil_name, (entry, note) in read_oil_tables(text, origin, catalogue).items():
        kwargs = entry.oil_arguments(origin)
        try:
            if entry.nu40 is not None:
                oil = Oil.from_datasheet(oil_name, entry.nu40, entry.nu100, entry.density15,
                                         **kwargs)
            else:
                oil = Oil.from_walther(oil_name, entry.walther_A, entry.walther_B,
                                       entry.density15, **kwargs)
        except InputError as err:
            raise InputError(f"{origin}: {err}{note}") from None
        for alias in [oil_name, *getattr(entry, "aliases", [])]:
            key = _normalise(alias)
            if key in seen:
                raise InputError(f"{origin}: oil name or alias {alias!r} of {oil_name!r} clashes "
                                 f"with {seen[key]!r} (names are case-insensitive)")
            seen[key] = oil_name
            if alias != oil_name:
                aliases[alias] = oil_name
        oils[oil_name] = oil
    return oils, aliases


@lru_cache(maxsize=1)
def _catalogue() -> tuple[dict[str, Oil], dict[str, str]]:
    path = resources.files("sealsim.properties").joinpath("data", "oils.toml")
    return _read_oils(path.read_text(encoding="utf-8"), "sealsim catalogue oils.toml",
                      catalogue=True)


def list_oils() -> list[str]:
    """Names of the built-in catalogue oils.

    Names are ``VG<grade>-<family>``; :func:`get_oil` also accepts aliases such as ``"VG68"``
    (mineral), ``"ISO VG 68"`` or ``"PAO VG 68"``, case-insensitive.

    Examples
    --------
    >>> list_oils()[:2]
    ['VG32-mineral', 'VG46-mineral']
    """
    return list(_catalogue()[0])


def load_oil_file(path: str | PathLike[str]) -> dict[str, Oil]:
    """Read user oils from a TOML file in the catalogue format (see
    :mod:`sealsim.properties.catalogue`).

    Parameters
    ----------
    path : str or path-like
        TOML file with ``[oils."NAME"]`` tables.

    Returns
    -------
    dict of str to Oil
        Oils by name, in file order.  Pass it to :func:`get_oil` as ``extra``.

    Raises
    ------
    InputError
        If the file cannot be read or an entry is invalid; the message names the file, the oil
        and the field.
    """
    from sealsim.files import read_input_text

    return _read_oils(read_input_text(path, "oil file"), str(path), catalogue=False)[0]


def get_oil(name: str | Oil, extra: Mapping[str, Oil] | None = None) -> Oil:
    """Look up an oil by name (case-insensitive) in ``extra`` and the built-in catalogue.

    Parameters
    ----------
    name : str or Oil
        Catalogue name (see :func:`list_oils`), alias (``"VG68"`` is the mineral oil) or a key
        of ``extra``.  An :class:`Oil` is returned unchanged.
    extra : mapping of str to Oil, optional
        User oils, e.g. from :func:`load_oil_file`; searched first, so they may shadow
        catalogue names.

    Returns
    -------
    Oil

    Raises
    ------
    InputError
        Unknown name; the message lists close matches.

    Examples
    --------
    >>> get_oil("iso vg 68").name
    'VG68-mineral'
    """
    if isinstance(name, Oil):
        return name
    if not isinstance(name, str):
        raise InputError(f"oil = {name!r} must be an oil name (str) or an Oil")
    catalogue, aliases = _catalogue()
    key = _normalise(name)
    candidates: dict[str, Oil] = {}
    for mapping in (extra or {}, catalogue):
        for oil_name, oil in mapping.items():
            candidates.setdefault(_normalise(oil_name), oil)
    for alias, oil_name in aliases.items():
        candidates.setdefault(_normalise(alias), catalogue[oil_name])
    if key in candidates:
        return candidates[key]
    shown = {_normalise(n): n for n in [*(extra or {}), *catalogue, *aliases]}
    close = difflib.get_close_matches(key, list(shown), n=5, cutoff=0.6)
    hint = (f"; close matches: {', '.join(repr(shown[c]) for c in close)}" if close
            else "")
    raise InputError(f"unknown oil {name!r}{hint}; 'sealsim oil list' shows the catalogue; "
                     "give your own oil by its datasheet values nu40, nu100 and density15 in "
                     "the case's [oil] table (or an oil file for 'sealsim oil ... --oil-file')")

