"""Friction torque of a radial lip seal at a given speed and contact temperature.

Composes the physics of :mod:`sealsim.tribology` as Organisciak et al. (SKF, AGMA 14FTM14,
2014) write it::

    T_torque   = (F_lub + F_material)·D/2                         (Eq. 2)
    F_material = μ_dry(T, u)·F_tip(T)·f(A_c),  f = α(Λ)            (Eq. 3)
    F_lub      = η(T)·u / h_e · S_contact,  S_contact = π·D·b      (Eq. 4)
    h_e        = film_factor·f_h·(η·u)^0.66·(W′/W′_ref)^−0.22·(E/E_ref)^−0.42
                 (≥ film floor)                                    (Eq. 5, soft EHL)

The paper leaves f(A_c) open ("a function of the real contact area").  sealsim takes the share
of the lip load carried by the shaft's asperities, α(Λ) of Greenwood–Williamson at the film
ratio Λ = h_e/σ (:func:`~sealsim.tribology.contact.asperity_load_share`): μ_dry is a
friction coefficient, so it multiplies a load; the real contact area is already inside it.
μ_dry comes from the WLF-shifted Grosch master curve of the lip elastomer with its hysteresis
peak at λ·f_max (:mod:`sealsim.tribology.rubber_friction`), F_tip from a lip-force source (a
callable of temperature, :class:`~sealsim.rotary.lip.AnalyticLipForce` by default), and the
film's load and modulus dependence from Hamrock & Dowson's soft-EHL exponents
(:mod:`sealsim.tribology.film`).  Everything is vectorised over speed and temperature, so the
same object gives one operating point inside the transient simulation or a whole
speed × temperature map.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from sealsim.properties.elastomers import Elastomer
from sealsim.properties.oils import Oil
from sealsim.tribology.contact import asperity_load_share
from sealsim.tribology.film import (
    EHL_EXPONENT,
    FILM_FLOOR,
    FILM_REFERENCE_LOAD,
    FILM_REFERENCE_MODULUS,
    film_ratio,
    film_thickness,
    soft_ehl_load_modulus_factor,
)
from sealsim.tribology.rubber_friction import (
    DEFAULT_MASTER_CURVE,
    GroschMasterCurve,
    grosch_friction_coefficient,
)
from sealsim.tribology.shear import duty_parameter, viscous_friction_force

__all__ = ["FrictionState", "LipSealFriction", "LipSealFrictionParameters"]


@dataclass(frozen=True)
class LipSealFrictionParameters:
    """Resolved (SI) parameters of the lip friction model.

    Parameters
    ----------
    shaft_diameter : float
        D [m].
    contact_width : float
        Axial contact width b [m].
    film_coefficient : float
        f_h of Eq. 5 [m/(Pa·m)^exponent].
    film_exponent : float
        Exponent of η·u [-].
    film_floor : float
        Minimum film [m].
    film_factor : float
        Lip-style film multiplier [-] (1 plain).
    roughness : float
        Composite RMS roughness σ of shaft and lip [m].
    master_curve : GroschMasterCurve
        μ_dry master curve.
    film_reference_load : float
        Lip load per circumference W′_ref of the seal the film law holds for [N/m].
    film_reference_modulus : float
        Quasi-static modulus E_ref of that seal's lip [Pa].
    """

    shaft_diameter: float
    contact_width: float
    film_coefficient: float
    film_exponent: float = EHL_EXPONENT
    film_floor: float = FILM_FLOOR
    film_factor: float = 1.0
    roughness: float = 0.5e-6
    master_curve: GroschMasterCurve = field(default=DEFAULT_MASTER_CURVE)
    film_reference_load: float = FILM_REFERENCE_LOAD
    film_reference_modulus: float = FILM_REFERENCE_MODULUS


class FrictionState(NamedTuple):
    """Friction quantities at one or many operating points (arrays, SI)."""

    speed: np.ndarray  # surface speed u [m/s]
    viscosity: np.ndarray  # η at the contact temperature [Pa s]
    film: np.ndarray  # h_e [m]
    film_ratio: np.ndarray  # Λ [-]
    lip_force: np.ndarray  # F_tip [N]
    mu_dry: np.ndarray  # μ_dry [-]
    asperity_share: np.ndarray  # α(Λ) = f(A_c) [-]
    force_lubricant: np.ndarray  # F_lub [N]
    force_material: np.ndarray  # F_material [N]
    torque: np.ndarray  # [N m], sign of the angular speed
    power: np.ndarray  # heat generated T·ω [W], ≥ 0


class LipSealFriction:
    """Friction model of one lip seal: parameters + oil + lip elastomer + lip-force source.

    Parameters
    ----------
    parameters : LipSealFrictionParameters
        Geometry, film and master curve.
    oil : Oil
        The lubricant.
    elastomer : Elastomer
        The lip rubber (shift factor of μ_dry, held modulus of the film law: the lip's contact
        deformation is held, the lip stands still).
    lip_force : callable
        ``lip_force(temperature [K]) -> F_tip [N]``, vectorised.

    Examples
    --------
    >>> from sealsim.properties.oils import get_oil
    >>> from sealsim.properties.elastomers import get_elastomer
    >>> from sealsim.rotary.lip import AnalyticLipForce
    >>> from sealsim.tribology.film import film_coefficient_matching_fit
    >>> nbr = get_elastomer("NBR")
    >>> p = LipSealFrictionParameters(0.08, 2.5e-4, film_coefficient_matching_fit())
    >>> model = LipSealFriction(p, get_oil("VG68"), nbr, AnalyticLipForce(37.7, 293.15, 0.45, nbr))
    >>> state = model.evaluate(157.08, 353.15)   # 1500 rpm, 80 °C
    >>> 0.1 < float(state.torque) < 1.0
    True
    """

    def __init__(self, parameters: LipSealFrictionParameters, oil: Oil, elastomer: Elastomer,
                 lip_force: Callable[[np.ndarray], np.ndarray],
                 contact_width: Callable[[np.ndarray], np.ndarray] | None = None):
        self.parameters = parameters
        self.oil = oil
        self.elastomer = elastomer
        self.lip_force = lip_force
        # optional b(T) [m] from the FE of the lip (sealsim.rotary.lip_fe); else constant
        self.contact_width = contact_width
        self.contact_area = np.pi * parameters.shaft_diameter * parameters.contact_width

    def evaluate(self, angular_speed, contact_temperature) -> FrictionState:
        """Friction at shaft angular speed ω [rad/s] and contact temperature [K] (broadcast)."""
        p = self.parameters
        omega = np.asarray(angular_speed, dtype=float)
        temp = np.asarray(contact_temperature, dtype=float)
        u = omega * p.shaft_diameter / 2.0
        speed = np.abs(u)
        eta = self.oil.dynamic_viscosity(temp)
        f_tip, held_modulus = self._lip_force_and_held_modulus(temp)
        scale = soft_ehl_load_modulus_factor(
            f_tip / (np.pi * p.shaft_diameter), held_modulus,
            p.film_reference_load, p.film_reference_modulus)
        h = film_thickness(eta, speed, p.film_coefficient, p.film_exponent,
                           p.film_factor * scale, p.film_floor)
        lam = film_ratio(h, p.roughness)
        share = asperity_load_share(lam)
        mu = grosch_friction_coefficient(speed, self.elastomer.log10_shift_factor(temp),
                                         p.master_curve)
        contact_area = self.contact_area if self.contact_width is None else \
            np.pi * p.shaft_diameter * np.asarray(self.contact_width(temp), dtype=float)
        f_lub = viscous_friction_force(eta, speed, h, contact_area)
        f_mat = np.where(speed > 0, mu * f_tip * share, 0.0)
        torque = np.sign(omega) * (f_lub + f_mat) * p.shaft_diameter / 2.0
        power = torque * omega
        return FrictionState(u, eta, h, lam, f_tip, mu, share, f_lub, f_mat, torque, power)

    def _lip_force_and_held_modulus(self, temp: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """F_tip [N] and the lip's held modulus [Pa] at the temperatures: both from one
        evaluation of a lip-force source that computes the held modulus of this elastomer
        anyway (:meth:`~sealsim.rotary.lip.AnalyticLipForce.force_and_held_modulus`)."""
        both = getattr(self.lip_force, "force_and_held_modulus", None)
        if both is not None and getattr(self.lip_force, "elastomer", None) is self.elastomer:
            f_tip, held = both(temp)
        else:
            f_tip, held = self.lip_force(temp), self.elastomer.held_modulus(temp)
        return np.asarray(f_tip, dtype=float), held

    def duty_parameter(self, state: FrictionState, angular_speed):
        """Duty parameter G = η·ω·b/W' of operating points (for Stribeck-type plots)."""
        load_per_length = state.lip_force / (np.pi * self.parameters.shaft_diameter)
        return duty_parameter(state.viscosity, np.abs(angular_speed), self.parameters.contact_width,
                              load_per_length)
