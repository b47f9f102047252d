"""Tribology of a lubricated rubber-on-steel contact: pure, vectorised functions (SI units).

* :mod:`.film` -- EHL film thickness h = f·(η·u)^0.66 of a soft lip (Organisciak et al.,
  AGMA 14FTM14, Eq. 5) and the film ratio Λ = h/σ;
* :mod:`.shear` -- Couette shear of the film and the duty parameter G = η·ω·b/F';
* :mod:`.contact` -- real contact area of rubber on a rough shaft (Persson 2001), reduced by
  the film (Greenwood & Williamson 1966), Hertz line contact;
* :mod:`.rubber_friction` -- Grosch's master curve of rubber friction over the WLF-shifted
  sliding speed (:class:`GroschMasterCurve`).

The rotary lip seal model (:mod:`sealsim.rotary.friction`) composes them.

>>> from sealsim.tribology import film_ratio
>>> float(film_ratio(0.5e-6, 0.25e-6))
2.0
"""

from sealsim.tribology.contact import (
    PERSSON_KAPPA,
    contact_modulus,
    dry_contact_area_fraction,
    greenwood_williamson_f1,
    hertz_line_half_width,
    mixed_lubrication_factor,
    real_contact_area_fraction,
)
from sealsim.tribology.film import (
    EHL_EXPONENT,
    FILM_FLOOR,
    SKF_FIT_COEFFICIENT,
    SKF_FIT_EXPONENT,
    SKF_FIT_RANGE,
    film_coefficient_matching_fit,
    film_ratio,
    film_thickness,
)
from sealsim.tribology.rubber_friction import (
    DEFAULT_MASTER_CURVE,
    GroschMasterCurve,
    grosch_friction_coefficient,
)
from sealsim.tribology.shear import duty_parameter, viscous_friction_force

__all__ = [
    "DEFAULT_MASTER_CURVE",
    "EHL_EXPONENT",
    "FILM_FLOOR",
    "PERSSON_KAPPA",
    "SKF_FIT_COEFFICIENT",
    "SKF_FIT_EXPONENT",
    "SKF_FIT_RANGE",
    "GroschMasterCurve",
    "contact_modulus",
    "dry_contact_area_fraction",
    "duty_parameter",
    "film_coefficient_matching_fit",
    "film_ratio",
    "film_thickness",
    "greenwood_williamson_f1",
    "grosch_friction_coefficient",
    "hertz_line_half_width",
    "mixed_lubrication_factor",
    "real_contact_area_fraction",
    "viscous_friction_force",
]
