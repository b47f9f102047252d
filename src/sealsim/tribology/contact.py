"""Real contact area of a rubber lip on a rough shaft, with and without a lubricant film.

Dry contact (Persson 2001; Hyun, Pei, Molinari & Robbins 2004): for a soft solid pressed on a
randomly rough rigid surface the real contact area grows linearly with the load,

    A/A0 = κ · p̄ / (E* · h'_rms),                                         (1)

with p̄ the nominal pressure, E* = E/(1 − ν²) the contact modulus (rigid shaft), h'_rms the
RMS slope of the shaft surface and κ ≈ 1.6--2.5 (Persson's theory gives √(8/π) ≈ 1.6, exact
numerical contact of self-affine surfaces ≈ 2).  It is capped at 1 (full contact).

Mixed lubrication: a film of thickness h keeps the surfaces apart; only the summits that reach
across it touch.  For a Gaussian summit height distribution (Greenwood & Williamson, Proc. R.
Soc. A 295 (1966) 300) the contact area at separation h is proportional to

    F1(Λ) = ∫_Λ^∞ (s − Λ) φ(s) ds = φ(Λ) − Λ·Q(Λ),    Λ = h/σ,           (2)

(φ the standard normal density, Q its upper tail), so the dry fraction is reduced by
g(Λ) = F1(Λ)/F1(0): g(0) = 1, g(1) = 0.21, g(2) = 0.021, g(3) = 0.001.
"""

from __future__ import annotations

import numpy as np
from scipy.special import erfc

__all__ = [
    "PERSSON_KAPPA",
    "contact_modulus",
    "hertz_line_half_width",
    "dry_contact_area_fraction",
    "greenwood_williamson_f1",
    "mixed_lubrication_factor",
    "real_contact_area_fraction",
]

#: Proportionality constant κ of Eq. (1) [-]: 2.0, the value of exact numerical contact of
#: self-affine rough surfaces (Hyun et al., Phys. Rev. E 70 (2004) 026117), inside the
#: 1.6--2.5 range of the reference notes §6.3.
PERSSON_KAPPA = 2.0

_SQRT_2PI = np.sqrt(2.0 * np.pi)


def contact_modulus(youngs_modulus, poisson_ratio=0.5):
    """Contact modulus of a rubber on a rigid counterface, E* = E/(1 − ν²).

    Parameters
    ----------
    youngs_modulus : array_like
        Young's modulus of the rubber E [Pa].
    poisson_ratio : float
        ν [-]; 0.5 for (nearly) incompressible rubber.

    Returns
    -------
    numpy.ndarray
        E* [Pa].

    Examples
    --------
    >>> float(contact_modulus(6e6))
    8000000.0
    """
    return np.asarray(youngs_modulus, dtype=float) / (1.0 - poisson_ratio**2)


def hertz_line_half_width(force_per_length, radius, modulus, poisson=0.5):
    """Half-width of the Hertz line contact of a cylinder on a rigid flat.

    ``a = √(4·P·R / (π·E*))``, E* = E/(1 − ν²) (Johnson, *Contact Mechanics*, 1985, §4.2).
    Written with numpy only, so it also compiles with numba.

    Parameters
    ----------
    force_per_length : array_like
        Load per unit length P [N/m], ≥ 0.
    radius : array_like
        Cylinder radius R [m].
    modulus : array_like
        Young's modulus of the cylinder E [Pa].
    poisson : float
        ν [-]; 0.5 for rubber.

    Returns
    -------
    numpy.ndarray
        a [m]; the contact width is 2a.

    Examples
    --------
    >>> round(float(hertz_line_half_width(1000.0, 2e-3, 6e6)) * 1e3, 4)
    0.5642
    """
    e_star = modulus / (1.0 - poisson**2)
    return np.sqrt(4.0 * force_per_length * radius / (np.pi * e_star))


def dry_contact_area_fraction(pressure, modulus_star, rms_slope, kappa=PERSSON_KAPPA):
    """Dry real contact area fraction A/A0 = min(1, κ·p̄/(E*·h'_rms)), Eq. (1).

    Parameters
    ----------
    pressure : array_like
        Nominal contact pressure p̄ [Pa].
    modulus_star : array_like
        Contact modulus E* [Pa].
    rms_slope : array_like
        RMS slope of the shaft surface h'_rms [-].
    kappa : float
        Proportionality constant κ [-].

    Returns
    -------
    numpy.ndarray
        A/A0 in [0, 1].

    Examples
    --------
    >>> float(dry_contact_area_fraction(0.6e6, 8e6, 0.3))
    0.5
    """
    ratio = kappa * np.asarray(pressure, dtype=float) / (
        np.asarray(modulus_star, dtype=float) * np.asarray(rms_slope, dtype=float))
    return np.clip(ratio, 0.0, 1.0)


def greenwood_williamson_f1(separation):
    """Greenwood–Williamson integral F1(Λ) for a standard Gaussian height distribution, Eq. (2).

    Parameters
    ----------
    separation : array_like
        Separation in units of the RMS roughness Λ [-] (≥ 0 in use; any real value works).

    Returns
    -------
    numpy.ndarray
        F1(Λ) = φ(Λ) − Λ·Q(Λ) [-].

    Examples
    --------
    >>> round(float(greenwood_williamson_f1(0.0)), 4)
    0.3989
    """
    lam = np.asarray(separation, dtype=float)
    phi = np.exp(-0.5 * lam**2) / _SQRT_2PI
    tail = 0.5 * erfc(lam / np.sqrt(2.0))
    return phi - lam * tail


def mixed_lubrication_factor(film_ratio):
    """Fraction of the dry real contact area left at film ratio Λ: g = F1(Λ)/F1(0).

    Parameters
    ----------
    film_ratio : array_like
        Λ = h/σ [-]; negative values are treated as 0 (no film).

    Returns
    -------
    numpy.ndarray
        g(Λ) in (0, 1], decreasing in Λ.

    Examples
    --------
    >>> [round(float(mixed_lubrication_factor(x)), 3) for x in (0.0, 1.0, 2.0)]
    [1.0, 0.209, 0.021]
    """
    lam = np.maximum(np.asarray(film_ratio, dtype=float), 0.0)
    return greenwood_williamson_f1(lam) * _SQRT_2PI


def real_contact_area_fraction(pressure, modulus_star, rms_slope, film_ratio,
                               kappa=PERSSON_KAPPA):
    """Real contact area fraction f(A_c) = A_c/A0 under a film, Eq. (1) × g(Λ).

    This is the ``f(A_c)`` of seed 000 Eq. 3 (F_material = μ_dry·F_tip·f(A_c)).

    Parameters
    ----------
    pressure : array_like
        Nominal contact pressure p̄ [Pa].
    modulus_star : array_like
        Contact modulus E* [Pa].
    rms_slope : array_like
        RMS slope of the shaft surface [-].
    film_ratio : array_like
        Λ = h/σ [-].
    kappa : float
        Persson constant [-].

    Returns
    -------
    numpy.ndarray
        A_c/A0 in [0, 1].

    Examples
    --------
    >>> round(float(real_contact_area_fraction(0.6e6, 8e6, 0.3, 1.0)), 3)
    0.104
    """
    return dry_contact_area_fraction(pressure, modulus_star, rms_slope, kappa) * \
        mixed_lubrication_factor(film_ratio)
