"""Lubricant film under a radial lip: EHL-type film law and its measured calibration.

Organisciak et al. (SKF, AGMA 14FTM14, 2014) write the effective film thickness as
``h_e = f·(η·u)^0.66`` (Eq. 5, from soft-EHL theory) and reports a capacitance measurement on a
lip seal fitted by ``h = 3.45·(u·η)^0.68`` (Eq. 8), with h in µm, u in m/s and η in Pa·s
(units inferred by sealsim, the paper states none: with them the fit gives 0.1--1 µm in the usual
speed range, which matches the 0.25--2.5 µm literature range for lip seal films).

The exponent 0.66 is the isoviscous-elastic (soft EHL) speed exponent of Hamrock & Dowson,
J. Lubr. Technol. 100 (1978) 236: ``H ∝ U^0.64...0.65``.  Their central film of a soft
elongated contact, H_c = 7.32·(1 − 0.72·e^(−0.28k))·U^0.64·W^(−0.22) with H = h/R,
U = η·u/(E′·R) and W = w/(E′·R²), also gives the load and modulus dependence that the paper's
law leaves out: at fixed geometry h ∝ w^(−0.22)·E′^(−0.64+0.22) = w^(−0.22)·E′^(−0.42).
sealsim applies these two exponents to the paper's law, relative to the seal the law was
measured on (:func:`soft_ehl_load_modulus_factor`), so a lighter or softer lip gets a thicker
film.

Lip seal films have been measured between about 0.25 and 2.5 µm (Jagger, Proc. IMechE 171
(1957) 597; Poll & Gabelli, J. Tribol. 114 (1992) 290: sub-micron averages).  Outside that
range the law is an extrapolation; :func:`film_range_note` says so and
:class:`FilmRangeWarning` is the warning class the rotary simulation uses.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "EHL_EXPONENT",
    "FILM_FLOOR",
    "FILM_REFERENCE_LOAD",
    "FILM_REFERENCE_MODULUS",
    "FilmRangeWarning",
    "MEASURED_FILM_RANGE",
    "SOFT_EHL_LOAD_EXPONENT",
    "SOFT_EHL_MODULUS_EXPONENT",
    "SKF_FIT_COEFFICIENT",
    "SKF_FIT_EXPONENT",
    "SKF_FIT_RANGE",
    "film_coefficient_matching_fit",
    "film_range_note",
    "film_ratio",
    "film_thickness",
    "soft_ehl_load_modulus_factor",
]

#: Exponent of (η·u) in the EHL film law, Organisciak et al. (2014) Eq. 5 [-].
EHL_EXPONENT = 0.66
#: Measured film fit of Organisciak et al. (2014) Eq. 8: h[µm] = 3.45·(u[m/s]·η[Pa s])^0.68.
SKF_FIT_COEFFICIENT = 3.45e-6  # m / (Pa m)^0.68
SKF_FIT_EXPONENT = 0.68
#: Range of u·η [Pa·m] over which the fit is used here (sealsim's choice): 10 to 3000 rpm on an
#: 80 mm shaft, from VG 32 at 100 °C and 10 rpm (2e-4) to VG 68 at 48 °C or VG 220 at 73 °C and
#: 3000 rpm (0.5), with the catalogue viscosities (the paper's text does not give the axis range
#: of its Fig. 7).
SKF_FIT_RANGE = (2e-4, 0.5)
#: Thinnest film the model uses [m]: 0.02 µm, the fit of Organisciak et al. (2014, Eq. 8) at
#: 10 rpm on an 80 mm shaft with VG 68 at 80 °C, 3.45·(0.042·0.0124)^0.68 µm.  Below it
#: the contact is boundary lubricated; a thinner value would only make the viscous term diverge
#: at standstill, while the material term (which dominates there) is unaffected.
FILM_FLOOR = 2e-8
#: Range of measured lip seal film thicknesses [m] (Jagger 1957; Poll & Gabelli 1992).
MEASURED_FILM_RANGE = (0.25e-6, 2.5e-6)
#: Load and modulus exponents of the soft-EHL central film (Hamrock & Dowson 1978) [-].
SOFT_EHL_LOAD_EXPONENT = -0.22
SOFT_EHL_MODULUS_EXPONENT = -0.42
#: Lip load per unit circumference of the seal the film law was measured on [N/m]: the paper
#: does not give it; sealsim takes its default lip, 0.15 N/mm (an assumption).
FILM_REFERENCE_LOAD = 150.0
#: Held (relaxed, one hour) Young's modulus of that seal's lip [Pa]: 4 MPa, a 75 Shore A NBR
#: lip between 20 and 80 °C (the catalogue NBR's held modulus: 4.1 MPa at 20 °C, 3.8 MPa at
#: 80 °C; sealsim's convention for a held seal, properties.elastomers.HELD_SEAL_TIME); an
#: assumption like the load.
FILM_REFERENCE_MODULUS = 4.0e6


class FilmRangeWarning(UserWarning):
    """A film thickness outside the measured range of lip seal films (0.25–2.5 µm)."""


def film_coefficient_matching_fit(exponent: float = EHL_EXPONENT,
                                  fit_range: tuple[float, float] = SKF_FIT_RANGE) -> float:
    """Film coefficient f of ``h = f·(η·u)^exponent`` closest to the measured SKF fit.

    Least squares in log space over ``fit_range`` (uniform in log(η·u)), i.e. the geometric
    mean of ``3.45e-6·x^(0.68 − exponent)`` over the range.

    Parameters
    ----------
    exponent : float
        Exponent of the film law [-]; 0.66 in Organisciak et al. (2014) Eq. 5.
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
    """Effective lubricant film thickness under the lip, Organisciak et al. (2014) Eq. 5.

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
        Exponent of η·u [-], 0.66 (Organisciak et al. 2014, Eq. 5, soft EHL).
    film_factor : float or array_like
        Multiplier for the lip style [-]: 1 for a plain lip, > 1 for a wave lip whose
        sinusoidal track builds a thicker film (Organisciak et al. 2014, "Comparison between
        molded wave and trimmed plain lips").
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


def soft_ehl_load_modulus_factor(load_per_length, modulus, reference_load=FILM_REFERENCE_LOAD,
                                 reference_modulus=FILM_REFERENCE_MODULUS):
    """Film multiplier for another lip load and modulus, (W′/W′_ref)^−0.22·(E/E_ref)^−0.42.

    The soft-EHL exponents of Hamrock & Dowson (1978) applied to the film law of
    Organisciak et al. (2014), which
    holds for the reference seal.  E′ = E/(1 − ν²) of rubber on steel is proportional to E, so
    the ratio of Young's moduli is used.

    Parameters
    ----------
    load_per_length : array_like
        Radial lip load per unit circumference W′ = F_tip/(π·D) [N/m].
    modulus : array_like
        Held (relaxed) Young's modulus of the lip rubber E [Pa].
    reference_load : float
        W′ of the seal the film law was measured on [N/m].
    reference_modulus : float
        E of that seal [Pa].

    Returns
    -------
    numpy.ndarray
        Film multiplier [-]; 1 at the reference seal.

    Examples
    --------
    >>> round(float(soft_ehl_load_modulus_factor(300.0, 4e6)), 3)  # twice the load
    0.859
    """
    load = np.asarray(load_per_length, dtype=float) / reference_load
    stiffness = np.asarray(modulus, dtype=float) / reference_modulus
    return load**SOFT_EHL_LOAD_EXPONENT * stiffness**SOFT_EHL_MODULUS_EXPONENT


def film_range_note(thinnest, thickest, measured_range=MEASURED_FILM_RANGE) -> str:
    """A sentence saying where films left the measured range, or "" if they did not.

    Parameters
    ----------
    thinnest, thickest : float
        Smallest and largest film of a run [m] (sliding points only).
    measured_range : tuple of float
        (h_min, h_max) of measured lip seal films [m].

    Returns
    -------
    str
        Empty when ``measured_range[0] <= thinnest`` and ``thickest <= measured_range[1]``.

    Examples
    --------
    >>> film_range_note(0.3e-6, 3.1e-6)
    'film up to 3.1 um, above the measured range of lip seal films (0.25-2.5 um): ...'
    """
    lo, hi = measured_range
    parts = []
    if thickest > hi:
        parts.append(f"film up to {thickest * 1e6:.2g} um, above the measured range of lip seal "
                     f"films ({lo * 1e6:g}-{hi * 1e6:g} um): the film law is extrapolated there "
                     "(thicker film, less viscous torque than it may be)")
    if thinnest < lo:
        parts.append(f"film down to {thinnest * 1e6:.2g} um, below the measured range of lip "
                     f"seal films ({lo * 1e6:g}-{hi * 1e6:g} um): mixed lubrication, where the "
                     "asperity (material) term carries the friction and the film law only sets "
                     "its load share")
    return "; ".join(parts)


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
