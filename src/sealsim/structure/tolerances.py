r"""Size tolerances of gland parts and O-rings: ISO 286 limits and fits, ISO 3601-1 O-rings.

Metal parts (ISO 286-1:2010, *Geometrical product specifications -- ISO code system for
tolerances on linear sizes -- Part 1*):

* the standard tolerance of grade ITn for nominal sizes up to 500 mm (Table 1), derived from
  the tolerance unit :math:`i = 0.45\,\sqrt[3]{D} + 0.001\,D` [µm] with D the geometric mean of
  the size step [mm] (IT5 = 7 i, IT6 = 10 i, IT7 = 16 i, IT8 = 25 i, IT9 = 40 i, IT10 = 64 i,
  IT11 = 100 i, rounded as the standard prescribes);
* the fundamental deviations of the clearance-fit shafts d, e, f, g, h (upper deviation es,
  Table 2) and holes D, E, F, G, H (lower deviation EI = -es of the same letter, the rule for
  A to H), and js/JS (±IT/2) -- the fits used on seal glands (bore H8/H9, rod f7/f8, groove
  bottom h9, ...).

O-rings (ISO 3601-1:2012, *Fluid power systems -- O-rings -- Part 1: Inside diameters,
cross-sections, tolerances and designation codes*): the cross-section d2 tolerance by size
range and the inside-diameter d1 tolerance ±(0.009·d1^0.95 + 0.11) mm (d1 in mm), as
tabulated by seal makers (e.g. R.T. Dygert, *Tolerances for metric O-rings*,
rtdygert.com/tolerances-for-metric-o-rings.html: "±[(ID^0.95 × 0.009) + 0.11]", cross-sections
±0.08 mm up to 2.25 mm ... ±0.15 mm up to 8.40 mm).

All inputs and outputs in metres.

>>> lo, hi = iso286_deviations(0.025, "H8")
>>> round(lo * 1e6), round(hi * 1e6)
(0, 33)
>>> lo, hi = iso286_deviations(0.020, "f7")
>>> round(lo * 1e6), round(hi * 1e6)
(-41, -20)
"""

from __future__ import annotations

import bisect
import math
import re

from sealsim.errors import InputError

__all__ = ["FUNDAMENTAL_DEVIATIONS_UM", "IT_GRADES_UM", "SIZE_STEPS_MM",
           "iso286_deviations", "iso3601_cord_tolerance", "iso3601_inner_diameter_tolerance",
           "standard_tolerance"]

#: Upper limits of the ISO 286-1 size steps up to 500 mm [mm] ("over a up to and including b";
#: the first step is 0 ... 3 mm).
SIZE_STEPS_MM = (3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500)

#: Standard tolerances IT5 ... IT11 [µm] per size step (ISO 286-1:2010, Table 1).
IT_GRADES_UM = {
    5: (4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27),
    6: (6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40),
    7: (10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63),
    8: (14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97),
    9: (25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155),
    10: (40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250),
    11: (60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400),
}

#: Upper deviation es of the shafts d, e, f, g, h [µm] per size step (ISO 286-1:2010, Table 2;
#: the hole of the same capital letter has EI = -es).
FUNDAMENTAL_DEVIATIONS_UM = {
    "d": (-20, -30, -40, -50, -65, -80, -100, -120, -145, -170, -190, -210, -230),
    "e": (-14, -20, -25, -32, -40, -50, -60, -72, -85, -100, -110, -125, -135),
    "f": (-6, -10, -13, -16, -20, -25, -30, -36, -43, -50, -56, -62, -68),
    "g": (-2, -4, -5, -6, -7, -9, -10, -12, -14, -15, -17, -18, -20),
    "h": (0,) * 13,
}

_FIT = re.compile(r"\s*([A-Za-z]{1,2})\s*(\d{1,2})\s*")


def _step(nominal_mm: float, field: str) -> int:
    if not (math.isfinite(nominal_mm) and 0.0 < nominal_mm <= SIZE_STEPS_MM[-1]):
        raise InputError(f"{field}: ISO 286 fits are tabulated here for nominal sizes "
                         f"0 ... 500 mm, got {nominal_mm:g} mm; give explicit limits instead "
                         "(upper and lower deviations)")
    return bisect.bisect_left(SIZE_STEPS_MM, nominal_mm)


def standard_tolerance(nominal: float, grade: int, field: str = "size") -> float:
    """Standard tolerance ITgrade [m] of a nominal size [m] (ISO 286-1, Table 1).

    Examples
    --------
    >>> round(standard_tolerance(0.025, 7) * 1e6)
    21
    """
    if grade not in IT_GRADES_UM:
        raise InputError(f"{field}: tolerance grade IT{grade} is not tabulated here; use "
                         f"IT{min(IT_GRADES_UM)} ... IT{max(IT_GRADES_UM)} or explicit limits")
    return IT_GRADES_UM[grade][_step(nominal * 1e3, field)] * 1e-6


def iso286_deviations(nominal: float, fit: str, field: str = "fit") -> tuple[float, float]:
    """Lower and upper deviation [m] of a tolerance class such as ``"H8"`` or ``"f7"``.

    Parameters
    ----------
    nominal : float
        Nominal size [m], 0 ... 0.5 m.
    fit : str
        Tolerance class: a hole (capital letter: D, E, F, G, H, JS) or a shaft (small letter:
        d, e, f, g, h, js) and a grade 5 ... 11.
    field : str
        Case field, for error messages.

    Returns
    -------
    (float, float)
        (lower deviation, upper deviation) [m]; the limits are nominal + deviations.

    Examples
    --------
    >>> [round(x * 1e6) for x in iso286_deviations(0.032, "h9")]
    [-62, 0]
    >>> [round(x * 1e6, 1) for x in iso286_deviations(0.012, "js8")]
    [-13.5, 13.5]
    """
    match = _FIT.fullmatch(str(fit))
    letters = "d, e, f, g, h, js (shafts) or D, E, F, G, H, JS (holes)"
    if match is None:
        raise InputError(f"{field}: {fit!r} is not an ISO 286 tolerance class; write a letter "
                         f"and a grade, e.g. 'H8' or 'f7' ({letters})")
    letter, grade = match[1], int(match[2])
    tol = standard_tolerance(nominal, grade, field)
    if letter in ("js", "JS"):
        return -tol / 2.0, tol / 2.0
    if letter.lower() not in FUNDAMENTAL_DEVIATIONS_UM or len(letter) != 1:
        raise InputError(f"{field}: tolerance class {fit!r} is not tabulated here; use "
                         f"{letters}, or explicit limits")
    es = FUNDAMENTAL_DEVIATIONS_UM[letter.lower()][_step(nominal * 1e3, field)] * 1e-6
    if letter.islower():        # shaft: upper deviation es, lower es - IT
        return es - tol, es
    return -es, -es + tol       # hole: lower deviation EI = -es, upper EI + IT


#: ISO 3601-1 cross-section tolerances: (largest d2 of the range [mm], ± tolerance [mm]).
_CORD_TOLERANCES_MM = ((2.25, 0.08), (3.15, 0.09), (4.50, 0.10), (6.30, 0.13), (8.40, 0.15))
_CORD_RANGE_MM = (0.80, 8.40)


def iso3601_cord_tolerance(cord_diameter: float) -> float:
    """± tolerance [m] of an O-ring cross-section d2 [m] (ISO 3601-1, 0.80 < d2 <= 8.40 mm).

    Examples
    --------
    >>> round(iso3601_cord_tolerance(3.53e-3) * 1e3, 2)
    0.1
    """
    d2 = cord_diameter * 1e3
    lo, hi = _CORD_RANGE_MM
    if not (lo < d2 <= hi):
        raise InputError(f"ring.cord_diameter: ISO 3601-1 tolerances cover cross-sections "
                         f"{lo} ... {hi} mm, got {d2:g} mm; give ring.cord_tolerance")
    return next(t for upper, t in _CORD_TOLERANCES_MM if d2 <= upper) * 1e-3


def iso3601_inner_diameter_tolerance(inner_diameter: float) -> float:
    """± tolerance [m] of an O-ring inside diameter d1 [m]: ±(0.009·d1^0.95 + 0.11) mm.

    Examples
    --------
    >>> round(iso3601_inner_diameter_tolerance(20e-3) * 1e3, 2)
    0.26
    """
    d1 = inner_diameter * 1e3
    if not (math.isfinite(d1) and d1 > 0.0):
        raise InputError(f"ring.inner_diameter: {d1!r} mm must be > 0")
    return (0.009 * d1**0.95 + 0.11) * 1e-3
