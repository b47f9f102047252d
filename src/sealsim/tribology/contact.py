"""Contact of a rubber lip on a rough shaft: Hertz line contact and mixed-lubrication load share.

Mixed lubrication (Greenwood & Williamson, Proc. R. Soc. A 295 (1966) 300): the shaft's summit
heights are Gaussian with standard deviation σ; at a mean separation h only the summits that
reach across it touch.  The number, the area and the load of the touching summits are
proportional to the integrals

    F_n(Λ) = ∫_Λ^∞ (s − Λ)^n φ(s) ds,    Λ = h/σ,                         (1)

with n = 0 (number), 1 (area) and 3/2 (load, Hertzian summits); φ is the standard normal
density.  In closed form, from the integral representation of the parabolic cylinder function
D (NIST DLMF 12.5.1),

    F_n(Λ) = Γ(n + 1)/√(2π) · e^(−Λ²/4) · D_(−n−1)(Λ).                      (2)

Friction of the rubber on the touching summits is μ times the load they carry, so the quantity
that multiplies a friction coefficient is the load share

    α(Λ) = F_3/2(Λ) / F_3/2(0),                                            (3)

the asperity load at separation Λ relative to the dry contact (Λ = 0, no separating film, the
summits carry the whole lip load): α(0) = 1, α(0.5) = 0.45, α(1) = 0.18, α(2) = 0.015.  The
real contact area does not appear on its own: a friction coefficient measured on a dry contact
already contains it (Bowden & Tabor: F = τ·A_real with A_real ∝ load), so multiplying μ by an
area fraction as well would count the area twice.
"""

from __future__ import annotations

import numpy as np
from scipy.special import gamma, pbdv

__all__ = [
    "DEFAULT_ROUGHNESS_DENSITY",
    "DEFAULT_ROUGHNESS_SLOPE",
    "asperity_load_share",
    "asperity_pressure",
    "greenwood_williamson_integral",
    "hertz_line_half_width",
    "mean_gap",
    "separation_at_asperity_pressure",
]

_SQRT_2PI = np.sqrt(2.0 * np.pi)


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


def greenwood_williamson_integral(order, separation):
    """Greenwood–Williamson integral F_n(Λ) of a standard Gaussian height distribution, Eq. (2).

    Parameters
    ----------
    order : float
        n [-], ≥ 0: 0 counts summits in contact, 1 gives their area, 3/2 their load.
    separation : array_like
        Mean separation in units of the RMS summit height, Λ [-] (any real value).

    Returns
    -------
    numpy.ndarray
        F_n(Λ) [-].

    Examples
    --------
    >>> round(float(greenwood_williamson_integral(1.0, 0.0)), 4)  # φ(0)
    0.3989
    >>> round(float(greenwood_williamson_integral(1.5, 0.0)), 4)
    0.43
    """
    lam = np.asarray(separation, dtype=float)
    d, _ = pbdv(-order - 1.0, lam)
    return gamma(order + 1.0) / _SQRT_2PI * np.exp(-0.25 * lam**2) * d


_F32_AT_ZERO = float(greenwood_williamson_integral(1.5, 0.0))
# Eq. (3) tabulated once: the parabolic cylinder function costs microseconds per point, linear
# interpolation of log α on a 0.0025 step is 20x faster and within 1e-5 of it; beyond Λ = 12,
# α < 1e-30 and is taken as 0.
_SHARE_GRID = np.linspace(0.0, 12.0, 4801)
_LOG_SHARE = np.log(greenwood_williamson_integral(1.5, _SHARE_GRID) / _F32_AT_ZERO)


def asperity_load_share(film_ratio):
    """Share of the lip load carried by shaft asperities at film ratio Λ, Eq. (3).

    Parameters
    ----------
    film_ratio : array_like
        Λ = h/σ [-]; negative values are treated as 0 (dry contact).

    Returns
    -------
    numpy.ndarray
        α in (0, 1], decreasing in Λ.

    Examples
    --------
    >>> [round(float(asperity_load_share(x)), 3) for x in (0.0, 1.0, 2.0)]
    [1.0, 0.176, 0.015]
    """
    lam = np.maximum(np.asarray(film_ratio, dtype=float), 0.0)
    share = np.exp(np.interp(lam, _SHARE_GRID, _LOG_SHARE))
    return np.where(lam <= _SHARE_GRID[-1], share, 0.0)


# -- asperity pressure of a soft seal on a rough counter surface -------------------------------
#: GW roughness density parameter η_s·β·σ [-]: 0.04, the middle of the 0.03-0.05 Greenwood &
#: Williamson (1966) found for a wide range of engineering surfaces [M].
DEFAULT_ROUGHNESS_DENSITY = 0.04
#: Ratio σ/β of RMS summit height to summit radius [-]: 0.01, summit radii of tens of µm on
#: ground or honed steel with σ of a few tenths of a µm (Greenwood & Williamson 1966,
#: Table 1 [M]).
DEFAULT_ROUGHNESS_SLOPE = 0.01
# log F_3/2(λ) tabulated once for any separation a seal meets (λ from -30, rubber pressed deep
# into the roughness, to 12, no contact); pbdv is accurate over the whole range
_GW_GRID = np.linspace(-30.0, 12.0, 8401)
_LOG_F32 = np.log(greenwood_williamson_integral(1.5, _GW_GRID))


def _f32(lam):
    """F_3/2(λ) from the table (exact to 1e-6 relative), 0 beyond λ = 12."""
    lam = np.asarray(lam, dtype=float)
    out = np.exp(np.interp(lam, _GW_GRID, _LOG_F32))
    return np.where(lam <= _GW_GRID[-1], out, 0.0)


def asperity_pressure(separation, roughness, modulus, poisson=0.5,
                      roughness_density=DEFAULT_ROUGHNESS_DENSITY,
                      roughness_slope=DEFAULT_ROUGHNESS_SLOPE):
    """Nominal pressure carried by the asperities of a rough rigid surface on a soft flat.

    Greenwood & Williamson (1966): Hertzian summits of radius β, density η_s and Gaussian
    heights of RMS σ pressed into an elastic flat at a mean separation h carry

    .. math:: p_{asp} = \\tfrac{4}{3}\\,E^*\\,(\\eta_s\\beta\\sigma)\\,\\sqrt{\\sigma/\\beta}\\,
              F_{3/2}(h/\\sigma), \\qquad E^* = E/(1-\\nu^2)

    (the rigid counter surface adds nothing to E*).  Two rough surfaces act like one with the
    combined roughness σ = √(σ1² + σ2²) (Greenwood & Tripp, Proc. IMechE 185 (1970) 625).  The
    separation may be negative: a rubber is pressed into the roughness until the summits carry
    the contact pressure.

    Parameters
    ----------
    separation : array_like
        Mean separation of the rubber surface from the summits' mean plane h [m] (any sign).
    roughness : array_like
        Combined RMS summit roughness σ [m], > 0.
    modulus : array_like
        Young's modulus of the rubber at the asperity frequency E [Pa].
    poisson : float
        ν of the rubber [-].
    roughness_density : float
        η_s·β·σ [-].
    roughness_slope : float
        σ/β [-].

    Returns
    -------
    numpy.ndarray
        p_asp [Pa].

    Examples
    --------
    >>> round(float(asperity_pressure(0.0, 0.3e-6, 10e6)) / 1e3, 1)   # kPa
    30.6
    """
    lam = np.asarray(separation, dtype=float) / np.asarray(roughness, dtype=float)
    e_star = np.asarray(modulus, dtype=float) / (1.0 - poisson**2)
    return 4.0 / 3.0 * e_star * roughness_density * np.sqrt(roughness_slope) * _f32(lam)


def separation_at_asperity_pressure(pressure, roughness, modulus, poisson=0.5,
                                    roughness_density=DEFAULT_ROUGHNESS_DENSITY,
                                    roughness_slope=DEFAULT_ROUGHNESS_SLOPE):
    """Separation at which the asperities alone carry ``pressure``: the inverse of
    :func:`asperity_pressure` (monotone; +inf for p = 0, clamped at λ = −30).

    Parameters are those of :func:`asperity_pressure`; ``pressure`` [Pa] >= 0.

    Returns
    -------
    numpy.ndarray
        h [m].

    Examples
    --------
    >>> h = separation_at_asperity_pressure(30.6e3, 0.3e-6, 10e6)
    >>> abs(float(h)) < 1e-9
    True
    """
    sigma = np.asarray(roughness, dtype=float)
    e_star = np.asarray(modulus, dtype=float) / (1.0 - poisson**2)
    stiffness = 4.0 / 3.0 * e_star * roughness_density * np.sqrt(roughness_slope)
    with np.errstate(divide="ignore"):
        target = np.log(np.asarray(pressure, dtype=float) / stiffness)
    lam = np.interp(-target, -_LOG_F32, _GW_GRID)       # log F_3/2 falls with λ
    lam = np.where(target < _LOG_F32[-1], np.inf, lam)
    return lam * sigma


def mean_gap(separation, roughness):
    """Mean gap filled by lubricant between a smooth surface and Gaussian roughness.

    .. math:: \\bar g = \\sigma\\,[\\lambda\\,\\Phi(\\lambda) + \\varphi(\\lambda)],
              \\qquad \\lambda = h/\\sigma

    (the average gap h_T of Patir & Cheng, J. Lubr. Technol. 100 (1978) 12, for Gaussian
    heights): h for λ ≳ 3, always > 0, decaying like σ·φ(λ)/λ² as the surfaces are pressed
    together.  The fluid film of a mixed contact.

    Parameters
    ----------
    separation : array_like
        Mean separation h [m] (any sign).
    roughness : array_like
        RMS roughness σ [m].

    Returns
    -------
    numpy.ndarray
        ḡ [m].

    Examples
    --------
    >>> [round(float(mean_gap(x, 1.0)), 4) for x in (-2.0, 0.0, 3.0)]
    [0.0085, 0.3989, 3.0004]
    """
    from scipy.special import ndtr

    sigma = np.asarray(roughness, dtype=float)
    lam = np.asarray(separation, dtype=float) / sigma
    with np.errstate(invalid="ignore"):
        gap = sigma * (lam * ndtr(lam) + np.exp(-0.5 * lam**2) / _SQRT_2PI)
    return np.where(np.isinf(lam) & (lam > 0), np.inf, gap)
