"""Friction torque of a radial lip seal at a given speed and contact temperature (seed 000).

Composes the physics of :mod:`sealsim.tribology` exactly as seed 000 writes it:

    T_torque   = (F_lub + F_material)·D/2                         (Eq. 2)
    F_material = μ_dry(T, u)·F_tip(T)·f(A_c)                       (Eq. 3)
    F_lub      = η(T)·u / h_e · S_contact,  S_contact = π·D·b      (Eq. 4)
    h_e        = film_factor · f · (η·u)^0.66  (≥ film floor)      (Eq. 5)

with f(A_c) the real contact area fraction (Persson's dry area × the Greenwood–Williamson
mixed-lubrication factor at Λ = h_e/σ), μ_dry from the WLF-shifted Grosch master curve of the
lip elastomer, E* from the elastomer's modulus at the asperity excitation frequency u/λ, and
F_tip from the lip force model of :mod:`sealsim.rotary.lip`.  Everything is vectorised over
speed and temperature, so the same object gives one operating point inside the transient
simulation or a whole speed × temperature map.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from sealsim.properties.elastomers import Elastomer
from sealsim.properties.oils import Oil
from sealsim.rotary.lip import LIP_FORCE_FREQUENCY, lip_force
from sealsim.tribology.contact import PERSSON_KAPPA, contact_modulus, real_contact_area_fraction
from sealsim.tribology.film import EHL_EXPONENT, FILM_FLOOR, film_ratio, film_thickness
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
    radial_force : float
        Lip force F_ref at ``radial_force_temperature`` [N].
    radial_force_temperature : float
        Temperature at which the lip force was measured [K].
    spring_share : float
        Share of the garter spring in F_ref [-].
    film_coefficient : float
        f of Eq. 5 [m/(Pa·m)^exponent].
    film_exponent : float
        Exponent of η·u [-].
    film_floor : float
        Minimum film [m].
    film_factor : float
        Lip-style film multiplier [-] (1 plain).
    roughness : float
        Composite RMS roughness σ of shaft and lip [m].
    rms_slope : float
        RMS slope of the shaft surface [-].
    asperity_wavelength : float
        Wavelength of the roughness that the lip rubber is excited by [m]; sets the frequency
        u/λ at which E* is taken.
    kappa : float
        Persson constant [-].
    master_curve : GroschMasterCurve
        μ_dry master curve.
    """

    shaft_diameter: float
    contact_width: float
    radial_force: float
    radial_force_temperature: float
    spring_share: float
    film_coefficient: float
    film_exponent: float = EHL_EXPONENT
    film_floor: float = FILM_FLOOR
    film_factor: float = 1.0
    roughness: float = 0.5e-6
    rms_slope: float = 0.2
    asperity_wavelength: float = 50e-6
    kappa: float = PERSSON_KAPPA
    master_curve: GroschMasterCurve = field(default=DEFAULT_MASTER_CURVE)


class FrictionState(NamedTuple):
    """Friction quantities at one or many operating points (arrays, SI)."""

    speed: np.ndarray  # surface speed u [m/s]
    viscosity: np.ndarray  # η at the contact temperature [Pa s]
    film: np.ndarray  # h_e [m]
    film_ratio: np.ndarray  # Λ [-]
    lip_force: np.ndarray  # F_tip [N]
    mu_dry: np.ndarray  # μ_dry [-]
    area_fraction: np.ndarray  # f(A_c) [-]
    force_lubricant: np.ndarray  # F_lub [N]
    force_material: np.ndarray  # F_material [N]
    torque: np.ndarray  # [N m], sign of the angular speed
    power: np.ndarray  # heat generated T·ω [W], ≥ 0


class LipSealFriction:
    """Friction model of one lip seal: parameters + oil + lip elastomer.

    Examples
    --------
    >>> from sealsim.properties.oils import get_oil
    >>> from sealsim.properties.elastomers import get_elastomer
    >>> from sealsim.tribology.film import film_coefficient_matching_fit
    >>> p = LipSealFrictionParameters(0.08, 2e-4, 30.0, 293.15, 0.45,
    ...                               film_coefficient_matching_fit())
    >>> model = LipSealFriction(p, get_oil("VG68"), get_elastomer("NBR"))
    >>> state = model.evaluate(157.08, 353.15)   # 1500 rpm, 80 °C
    >>> 0.1 < float(state.torque) < 1.0
    True
    """

    def __init__(self, parameters: LipSealFrictionParameters, oil: Oil, elastomer: Elastomer,
                 lip_force_model=None, contact_width_model=None):
        self.parameters = parameters
        self.oil = oil
        self.elastomer = elastomer
        # optional F_tip(T) [N] and b(T) [m] from the FE of the lip (sealsim.rotary.lip_fe)
        self.lip_force_model = lip_force_model
        self.contact_width_model = contact_width_model
        p = parameters
        self.contact_area = np.pi * p.shaft_diameter * p.contact_width
        self._modulus_reference = float(elastomer.modulus(p.radial_force_temperature,
                                                          LIP_FORCE_FREQUENCY))

    def lip_force(self, temperature):
        """F_tip at the lip temperature [N] (lip force model, :func:`~sealsim.rotary.lip.lip_force`,
        or the FE table of the lip)."""
        if self.lip_force_model is not None:
            return self.lip_force_model(temperature)
        ratio = np.asarray(self.elastomer.modulus(temperature, LIP_FORCE_FREQUENCY)) \
            / self._modulus_reference
        return lip_force(self.parameters.radial_force, self.parameters.spring_share, ratio)

    def evaluate(self, angular_speed, contact_temperature) -> FrictionState:
        """Friction at shaft angular speed ω [rad/s] and contact temperature [K] (broadcast)."""
        p = self.parameters
        omega = np.asarray(angular_speed, dtype=float)
        temp = np.asarray(contact_temperature, dtype=float)
        u = omega * p.shaft_diameter / 2.0
        speed = np.abs(u)
        eta = self.oil.dynamic_viscosity(temp)
        h = film_thickness(eta, speed, p.film_coefficient, p.film_exponent, p.film_factor,
                           p.film_floor)
        lam = film_ratio(h, p.roughness)
        f_tip = self.lip_force(temp)
        contact_area = self.contact_area if self.contact_width_model is None else \
            np.pi * p.shaft_diameter * self.contact_width_model(temp)
        pressure = f_tip / contact_area
        excitation = np.maximum(speed / p.asperity_wavelength, 1e-3)
        e_star = contact_modulus(self.elastomer.modulus(temp, excitation))
        area = real_contact_area_fraction(pressure, e_star, p.rms_slope, lam, p.kappa)
        mu = grosch_friction_coefficient(speed, self.elastomer.log10_shift_factor(temp),
                                         p.master_curve)
        f_lub = viscous_friction_force(eta, speed, h, contact_area)
        f_mat = np.where(speed > 0, mu * f_tip * area, 0.0)
        torque = np.sign(omega) * (f_lub + f_mat) * p.shaft_diameter / 2.0
        power = torque * omega
        return FrictionState(u, eta, h, lam, f_tip, mu, area, f_lub, f_mat, torque, power)

    def duty_parameter(self, state: FrictionState, angular_speed):
        """Duty parameter G = η·ω·b/W' of operating points (for Stribeck-type plots)."""
        load_per_length = state.lip_force / (np.pi * self.parameters.shaft_diameter)
        return duty_parameter(state.viscosity, np.abs(angular_speed), self.parameters.contact_width,
                              load_per_length)
