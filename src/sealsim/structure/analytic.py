r"""Analytic references for checking the FE model: Hertz line contact of a cylinder squeezed
between two rigid flats (plane strain).

For a cylinder of radius R and Young's modulus E, Poisson ratio ν, loaded by P per unit
length between two rigid flats (Johnson, *Contact Mechanics*, 1985, §4.2 and §5.6):

.. math::

    a = \sqrt{\frac{4 P R}{\pi E^*}}, \qquad p_0 = \frac{2 P}{\pi a}, \qquad
    \delta = \frac{2 P}{\pi E^*}\left(2\ln\frac{4 R}{a} - 1\right),

with :math:`E^* = E / (1 - \nu^2)` (rigid flats), contact half-width a, peak pressure p0 and
δ the total approach of the two flats (decrease of the diameter). For an incompressible
Mooney–Rivlin solid E = 6 (C10 + C01) and ν = 1/2.
"""

from __future__ import annotations

import math

from scipy.optimize import brentq

from sealsim.tribology.contact import hertz_line_half_width

__all__ = [
    "cylinder_between_flats_approach",
    "cylinder_between_flats_force",
    "hertz_line_contact",
]


def hertz_line_contact(force_per_length, radius, modulus, poisson=0.5):
    """Hertz contact half-width a [m] and peak pressure p0 [Pa] of a cylinder on a rigid flat.

    Parameters
    ----------
    force_per_length : float
        P [N/m].
    radius : float
        R [m].
    modulus : float
        Young's modulus E [Pa].
    poisson : float
        ν [-].

    Examples
    --------
    >>> a, p0 = hertz_line_contact(1000.0, 2e-3, 6e6)
    >>> round(a * 1e3, 4), round(p0 / 1e6, 4)
    (0.5642, 1.1284)
    """
    a = float(hertz_line_half_width(force_per_length, radius, modulus, poisson))
    return a, 2.0 * force_per_length / (math.pi * a)


def cylinder_between_flats_approach(force_per_length, radius, modulus, poisson=0.5):
    """Total approach δ [m] of two rigid flats squeezing a cylinder (Johnson 1985, §5.6).

    Examples
    --------
    >>> round(cylinder_between_flats_approach(1000.0, 2e-3, 6e6) * 1e3, 4)
    0.3425
    """
    e_star = modulus / (1.0 - poisson**2)
    a, _ = hertz_line_contact(force_per_length, radius, modulus, poisson)
    return 2.0 * force_per_length / (math.pi * e_star) * (2.0 * math.log(4.0 * radius / a) - 1.0)


def cylinder_between_flats_force(approach, radius, modulus, poisson=0.5):
    """Force per length P [N/m] for a total approach δ [m] (inverse of the above).

    Examples
    --------
    >>> p = cylinder_between_flats_force(0.3425e-3, 2e-3, 6e6)
    >>> round(p)
    1000
    """
    e_star = modulus / (1.0 - poisson**2)
    hi = e_star * radius
    return brentq(lambda p: cylinder_between_flats_approach(p, radius, modulus, poisson)
                  - approach, 1e-12 * hi, hi, xtol=1e-12 * hi, rtol=1e-12)
