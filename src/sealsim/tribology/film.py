"""Lubricant film under a radial lip: EHL-type film law and its measured calibration.

Seed 000 (Organisciak et al., AGMA 14FTM14, 2014) writes the effective film thickness as
``h_e = f·(η·u)^0.66`` (Eq. 5, from soft-EHL theory) and reports a capacitance measurement on a
lip seal fitted by ``h = 3.45·(u·η)^0.68`` (Eq. 8), with h in µm, u in m/s and η in Pa·s
(units as read in the reference notes, lip_seal_friction.md §1.2: they give 0.1--1 µm in the
usual speed range, which matches the 0.25--2.5 µm literature range for lip seal films).

The exponent 0.66 is the isoviscous-elastic (soft EHL) speed exponent of Hamrock & Dowson,
J. Lubr. Technol. 100 (1978) 236: ``H ∝ U^0.64...0.65``.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "EHL_EXPONENT",
    "FILM_FLOOR",
    "SKF_FIT_COEFFICIENT",
    "SKF_FIT_EXPONENT",
    "SKF_FIT_RANGE",
    "film_coefficient_matching_fit",
    "film_thickness",
    "film_ratio",
]

#: Exponent of (η·u) in the EHL film law, seed 000 Eq. 5 [-].
EHL_EXPONENT = 0.66
#: Measured film fit of seed 000 Eq. 8: h[µm] = 3.45·(u[m/s]·η[Pa s])^0.68.
SKF_FIT_COEFFICIENT = 3.45e-6  # m / (Pa m)^0.68
SKF_FIT_EXPONENT = 0.68
#: Range of u·η [Pa·m] over which the fit is used here: 10 rpm to 3000 rpm on an 80 mm shaft
#: with VG 32...VG 220 oils at 40...100 °C spans about 2e-4...0.5 Pa·m (reference notes §1.2
#: table; the seed's Fig. 7 range itself is not legible).
SKF_FIT_RANGE = (2e-4, 0.5)
#: Thinnest film the model uses [m]: 0.02 µm, the SKF fit at 10 rpm with VG 68 at 80 °C
#: (reference notes §1.2/§9).  Below it the contact is boundary lubricated; a thinner value
#: would only make the viscous term diverge at standstill, while the material term (which
#: dominates there) is unaffected.
FILM_FLOOR = 2e-8


def film_coefficient_matching_fit(exponent: float = EHL_EXPONENT,
                                  fit_range: tuple[float, float] = SKF_FIT_RANGE) -> float:
    """Film coefficient f of ``h = f·(η·u)^exponent`` closest to the measured SKF fit.

    Least squares in log space over ``fit_range`` (uniform in log(η·u)), i.e. the geometric
    mean of ``3.45e-6·x^(0.68 − exponent)`` over the range.

    Parameters
    ----------
    exponent : float
        Exponent of the film law [-]; 0.66 in seed 000 Eq. 5.
    fit_range : tuple of float
        Range of η·u [Pa·m] to match.

    Returns
    -------
    float
        Coefficient f [m / (Pa·m)^exponent].

    Examples
    --------
    >>> round(film_coefficient_matching_fit() * 1e6, 3)
    3.146
    """
    lo, hi = np.log(fit_range[0]), np.log(fit_range[1])
    mean_log_x = 0.5 * (lo + hi)
    return float(SKF_FIT_COEFFICIENT * np.exp((SKF_FIT_EXPONENT - exponent) * mean_log_x))


def film_thickness(viscosity, speed, coefficient, exponent=EHL_EXPONENT, film_factor=1.0,
                   floor=FILM_FLOOR):
    """Effective lubricant film thickness under the lip, seed 000 Eq. 5.

    ``h_e = max(film_factor · f · (η·u)^exponent, floor)``

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity of the oil at the contact temperature η [Pa·s].
    speed : array_like
        Sliding (surface) speed u [m/s]; its magnitude is used.
    coefficient : float
        Film coefficient f [m/(Pa·m)^exponent]; see :func:`film_coefficient_matching_fit`.
    exponent : float
        Exponent of η·u [-], 0.66 (seed 000 Eq. 5, soft EHL).
    film_factor : float or array_like
        Multiplier for the lip style [-]: 1 for a plain lip, > 1 for a wave lip whose
        sinusoidal track builds a thicker film (seed 000, "Comparison between molded wave and
        trimmed plain lips").
    floor : float
        Minimum film thickness [m] (boundary-lubrication limit).

    Returns
    -------
    numpy.ndarray
        Film thickness h_e [m].

    Examples
    --------
    >>> h = film_thickness(0.0124, 6.28, coefficient=film_coefficient_matching_fit())
    >>> round(float(h) * 1e6, 3)
    0.584
    """
    x = np.abs(np.asarray(speed, dtype=float)) * np.asarray(viscosity, dtype=float)
    return np.maximum(film_factor * coefficient * x**exponent, floor)


def film_ratio(film, roughness):
    """Film parameter Λ = h / σ.

    Parameters
    ----------
    film : array_like
        Film thickness h [m].
    roughness : array_like
        Composite RMS roughness σ = sqrt(σ_shaft² + σ_lip²) [m].

    Returns
    -------
    numpy.ndarray
        Λ [-]; Λ ≲ 1 boundary/mixed, Λ ≳ 3 full film.

    Examples
    --------
    >>> float(film_ratio(0.6e-6, 0.4e-6))
    1.5
    """
    return np.asarray(film, dtype=float) / np.asarray(roughness, dtype=float)
