"""Tribology of a lubricated rubber-on-steel contact: pure, vectorised functions (SI units).

* :mod:`.film` -- EHL film thickness h = f·(η·u)^0.66 of a soft lip (Organisciak et al.,
  AGMA 14FTM14, Eq. 5) and the film ratio Λ = h/σ;
* :mod:`.shear` -- Couette shear of the film and the duty parameter G = η·ω·b/F';
* :mod:`.film` also scales the film with the lip load and modulus (soft EHL, Hamrock & Dowson)
  and says when a run leaves the film range the law was measured in;
* :mod:`.contact` -- share of the lip load carried by the shaft's asperities across the film
  (Greenwood & Williamson 1966), Hertz line contact;
* :mod:`.rubber_friction` -- Grosch's master curve of rubber friction over the WLF-shifted
  sliding speed (:class:`GroschMasterCurve`);
* :mod:`.inverse_hydrodynamics` -- the film of a reciprocating seal from its contact pressure
  profile (Blok; Müller & Nau 1998; Kanters 1990), the flow and fluid transport per stroke;
* :mod:`.mixed_lubrication` -- asperity load share (Greenwood–Williamson with the rubber's
  modulus) and the friction of a reciprocating seal from its contact pressure profile;
* :mod:`.squeeze_film` -- how fast that film drains when the seal stops (Reynolds' squeeze
  film under the load the fluid carries).

The rotary lip seal model (:mod:`sealsim.rotary.friction`) and the friction tables of
reciprocating seals (:mod:`sealsim.pneumatic.friction_tables`) compose them.

>>> from sealsim.tribology import film_ratio
>>> float(film_ratio(0.5e-6, 0.25e-6))
2.0
"""

from sealsim.tribology.contact import (
    asperity_load_share,
    asperity_pressure,
    greenwood_williamson_integral,
    hertz_line_half_width,
    separation_at_asperity_pressure,
)
from sealsim.tribology.film import (
    EHL_EXPONENT,
    FILM_FLOOR,
    MEASURED_FILM_RANGE,
    SKF_FIT_COEFFICIENT,
    SKF_FIT_EXPONENT,
    SKF_FIT_RANGE,
    FilmRangeWarning,
    film_coefficient_matching_fit,
    film_range_note,
    film_ratio,
    film_thickness,
    soft_ehl_load_modulus_factor,
)
from sealsim.tribology.inverse_hydrodynamics import (
    film_at_pressure_maximum,
    film_left_on_surface,
    flow_per_circumference,
    ihl_film_profile,
    max_inlet_gradient,
    starved_film,
    stroke_transport,
)
from sealsim.tribology.mixed_lubrication import (
    ContactFriction,
    ihl_load_share,
    reciprocating_friction,
)
from sealsim.tribology.rubber_friction import (
    DEFAULT_MASTER_CURVE,
    GroschMasterCurve,
    grosch_friction_coefficient,
    hysteresis_peak_speed,
    loss_peak_frequency,
)
from sealsim.tribology.shear import duty_parameter, viscous_friction_force

__all__ = [
    "DEFAULT_MASTER_CURVE",
    "EHL_EXPONENT",
    "FILM_FLOOR",
    "MEASURED_FILM_RANGE",
    "SKF_FIT_COEFFICIENT",
    "SKF_FIT_EXPONENT",
    "SKF_FIT_RANGE",
    "ContactFriction",
    "FilmRangeWarning",
    "GroschMasterCurve",
    "asperity_load_share",
    "asperity_pressure",
    "film_at_pressure_maximum",
    "film_left_on_surface",
    "starved_film",
    "flow_per_circumference",
    "ihl_film_profile",
    "ihl_load_share",
    "max_inlet_gradient",
    "reciprocating_friction",
    "separation_at_asperity_pressure",
    "stroke_transport",
    "film_coefficient_matching_fit",
    "film_range_note",
    "film_ratio",
    "film_thickness",
    "greenwood_williamson_integral",
    "grosch_friction_coefficient",
    "hertz_line_half_width",
    "hysteresis_peak_speed",
    "loss_peak_frequency",
    "soft_ehl_load_modulus_factor",
    "duty_parameter",
    "viscous_friction_force",
]
