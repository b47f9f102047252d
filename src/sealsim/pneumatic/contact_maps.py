r"""Contact maps of a seal: normal force F_N and contact width b over pressure × temperature.

Heipl & Murrenhoff (Fig. 4, Fig. 9) feed the Θ friction law of each seal with the normal force
F_N and the contact width b taken from *characteristic diagrams* precomputed by FE.  Here a
contact map is any object with

* ``evaluate(pressure_difference, temperature) -> (normal_force, contact_width)`` -- vectorised,
  SI (Pa, K → N, m), smooth in both arguments;
* ``ranges`` -- ``{"pressure": (lo, hi), "temperature": (lo, hi)}`` [Pa], [K], the domain the
  map is valid on (it is never extrapolated: callers clamp and report, or refuse);
* ``describe()`` -- a JSON-friendly description.

Three sources:

* :class:`FEContactMap` -- the FE characteristic diagram of :mod:`sealsim.structure.maps`
  (``map.nc`` written by ``sealsim structure map``), a C¹ Hermite interpolant;
* :func:`build_or_load_fe_map` -- the same, computed on demand from a structure case file and
  cached under a hash of the resolved case;
* :class:`AnalyticContactMap` -- an engineering estimate for an O-ring when no FE map is given
  (functions below, each with its source).

The analytic estimate [R]: the cord of diameter d is squeezed by the fraction c between the
counter surface and the groove bottom; Lindley's empirical load-compression law gives the force
per unit circumference, Hertz's line contact (cylinder on a rigid flat) the contact width; a
sealed pressure difference Δp is transmitted by the nearly incompressible rubber to the contact
(the O-ring acts like a fluid: contact pressure = squeeze pressure + Δp over the width b);
temperature raises the squeeze through the free thermal expansion of the cord (the gland is
metal, its expansion is an order of magnitude smaller) and changes the modulus.

Which modulus: an installed seal is held at constant squeeze for hours to years, so its
viscoelastic stresses relax and the sealing force follows the *relaxed* modulus at the
holding time scale, taken from the rubber's viscoelastic master curve
(:meth:`sealsim.properties.elastomers.Elastomer.held_modulus`, one hour by default,
:data:`~sealsim.properties.elastomers.HELD_SEAL_TIME`) -- sealsim's one convention for a held
seal, the same the rotary lip force uses (tested across both models).  It lies well below the
1 Hz modulus the catalogue's hyperelastic constants hold for (catalogue NBR: 4.1 vs 8.5 MPa at
20 °C) and is nearly flat from 0 to 100 °C; near T_g it climbs towards the glass.  This estimate
and the FE map take the modulus from one law,
:meth:`~sealsim.properties.elastomers.Elastomer.modulus_ratio` (``temperature_scaling``:
"held" by default; "entropic" for the equilibrium modulus E ∝ T, "modulus" for the dynamic
modulus at a rate, "none"), so they agree on the sign and size of dF_N/dT for the same gland
(tested).  The estimate is rubbery: its temperature range starts
:data:`~sealsim.properties.elastomers.GLASS_TRANSITION_MARGIN` above the rubber's T_g (a lower
bound is refused with a message); near and below T_g only the viscoelastic FE material with
its glassy expansion (``material.model = "viscoelastic"``) describes the seal.
"""

from __future__ import annotations

import logging
import os
import shutil
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol, runtime_checkable

import numpy as np

from numba import njit

from sealsim.errors import InputError
from sealsim.friction.contact_table import hermite_basis, locate_on_axis
from sealsim.pneumatic._jit import jit
from sealsim.properties.elastomers import (
    GLASS_TRANSITION_MARGIN,
    TEMPERATURE_SCALINGS,
    entropic_modulus,
    get_elastomer,
    rubbery_limit_message,
)
from sealsim.tribology.contact import hertz_line_half_width

__all__ = [
    "AnalyticContactMap",
    "ContactMap",
    "analytic_loads",
    "FEContactMap",
    "build_or_load_fe_map",
    "default_cache_dir",
    "glassy_reason",
    "energised_contact_pressure",
    "energised_force_per_length",
    "hertz_contact_width",
    "kept_paths_folder",
    "lindley_force_per_length",
    "thermal_squeeze",
]

#: Logger of the FE maps built on demand: one INFO record before a build starts (tens of
#: seconds), naming the seal, the grid and the cache file.  ``sealsim`` commands print it
#: above their progress bar; from Python, ``logging.basicConfig(level=logging.INFO)`` shows it.
logger = logging.getLogger(__name__)


@runtime_checkable
class ContactMap(Protocol):
    """What the pneumatic model needs from a contact map (see the module docstring)."""

    ranges: dict[str, tuple[float, float]]

    def evaluate(self, pressure_difference, temperature):
        """(normal_force [N], contact_width [m]) at Δp [Pa] and T [K]."""

    def describe(self) -> dict[str, Any]:
        """A JSON-friendly description of the map."""


# -- analytic estimate: pure functions --------------------------------------------------------
def thermal_squeeze(squeeze, thermal_expansion, temperature, reference_temperature):
    """Squeeze of an O-ring at temperature T after free thermal expansion of the cord.

    The gland height h = d0·(1 − c0) stays (metal), the cord grows to d = d0·(1 + α·ΔT)::

        c(T) = 1 − (1 − c0)/(1 + α·(T − T0))

    Parameters
    ----------
    squeeze : float or ndarray
        Squeeze c0 at the reference temperature [-] (1 − gland height / cord diameter).
    thermal_expansion : float or ndarray
        Linear thermal expansion coefficient α of the rubber [1/K] (NBR ≈ 1.9e-4).
    temperature : float or ndarray
        Temperature T [K].
    reference_temperature : float or ndarray
        Temperature T0 at which c0 holds (installation) [K].

    Returns
    -------
    ndarray
        c(T) [-].

    Examples
    --------
    >>> round(float(thermal_squeeze(0.12, 1.9e-4, 328.15, 293.15)), 5)
    0.12582
    """
    growth = 1.0 + thermal_expansion * (temperature - reference_temperature)
    return 1.0 - (1.0 - squeeze) / growth


def lindley_force_per_length(squeeze, cord_diameter, modulus):
    """Compression force of an O-ring cord per unit circumferential length (Lindley 1967).

    .. math:: F' = E\\,d\\,(1.25\\,c^{1.5} + 50\\,c^{6})

    Parameters
    ----------
    squeeze : float or ndarray
        Fractional compression c [-] (0 … ≈ 0.4).
    cord_diameter : float or ndarray
        Cord (cross-section) diameter d [m].
    modulus : float or ndarray
        Young's modulus E [Pa] (≈ 6·(C10 + C01) for Mooney–Rivlin rubber).

    Returns
    -------
    ndarray
        F' [N/m].

    References
    ----------
    P. B. Lindley, "Compression characteristics of laterally-unrestrained rubber O-rings",
    J. Inst. Rubber Ind. 1, 209-213, 1967 [M: the widely quoted form, not re-checked].

    Examples
    --------
    >>> round(float(lindley_force_per_length(0.12, 2.5e-3, 8e6)), 1)
    1042.3
    """
    c = np.maximum(squeeze, 0.0)
    return modulus * cord_diameter * (1.25 * c ** 1.5 + 50.0 * c ** 6)


def hertz_contact_width(force_per_length, cord_diameter, modulus, poisson=0.5):
    """Contact width b = 2a of a cylinder pressed on a rigid flat (Hertz line contact).

    .. math:: a = \\sqrt{\\frac{4 F' R}{\\pi E^*}}, \\quad R = d/2, \\quad
              E^* = \\frac{E}{1 - \\nu^2}

    Parameters
    ----------
    force_per_length : float or ndarray
        F' [N/m], >= 0.
    cord_diameter : float or ndarray
        d [m].
    modulus : float or ndarray
        E [Pa].
    poisson : float
        ν [-] (0.5: incompressible rubber).

    Returns
    -------
    ndarray
        b [m].

    References
    ----------
    K. L. Johnson, Contact Mechanics, Cambridge 1985, §4.2, via
    :func:`sealsim.tribology.contact.hertz_line_half_width`.  Hertz underestimates b at large
    squeeze; FE maps (:class:`FEContactMap`) replace this estimate.

    Examples
    --------
    >>> round(float(hertz_contact_width(1042.3, 2.5e-3, 8e6)) * 1e3, 4)   # [mm]
    0.7887
    """
    return 2.0 * hertz_line_half_width(np.maximum(force_per_length, 0.0), 0.5 * cord_diameter,
                                       modulus, poisson)


def energised_force_per_length(preload_per_length, pressure_difference, cord_diameter, modulus,
                               poisson=0.5):
    """Force per length of an O-ring energised by a sealed pressure difference.

    The rubber transmits the pressure to the contact like a fluid (contact pressure = squeeze
    pressure + Δp), over the Hertz width b(F') of the loaded contact::

        F' = F'_0 + Δp·b(F'),   b(F') = k·sqrt(F'),   k = 2·sqrt(2·d/(π·E*))

    solved in closed form: sqrt(F') = (k·Δp + sqrt(k²·Δp² + 4·F'_0))/2.  Smooth and increasing
    in Δp, with dF'/dΔp → b at small Δp.

    Parameters
    ----------
    preload_per_length : float or ndarray
        F'_0 from the squeeze [N/m].
    pressure_difference : float or ndarray
        Δp across the seal [Pa], >= 0.
    cord_diameter : float or ndarray
        d [m].
    modulus : float or ndarray
        E [Pa].
    poisson : float
        ν [-].

    Returns
    -------
    ndarray
        F' [N/m].

    References
    ----------
    "O-ring acts like a fluid" (contact stress = squeeze stress + system pressure):
    Parker O-Ring Handbook ORD 5700, §1 [M]; Hertz width as in :func:`hertz_contact_width`.

    Examples
    --------
    >>> round(float(energised_force_per_length(1042.3, 6e5, 2.5e-3, 8e6)), 1)
    1635.0
    """
    e_star = modulus / (1.0 - poisson ** 2)
    k = 2.0 * np.sqrt(2.0 * cord_diameter / (np.pi * e_star))
    kdp = k * np.maximum(pressure_difference, 0.0)
    root = 0.5 * (kdp + np.sqrt(kdp ** 2 + 4.0 * preload_per_length))
    return root ** 2


def energised_contact_pressure(position, force_per_length, width, pressure_difference):
    """Contact pressure profile of an O-ring energised by a sealed pressure difference.

    The profile that :func:`energised_force_per_length` integrates: the rubber transmits Δp
    to its contact like a fluid, so the squeeze's Hertz profile (force F'_0 = F' − Δp·b over
    its own width b_0 = b·sqrt(F'_0/F'), since b ∝ sqrt(F') in Hertz's law) carries Δp on top
    of it across the loaded width b::

        p(z) = Δp + p0·sqrt(1 − (z/a0)²)   for |z| < a0 = b_0/2,
        p(z) = Δp                         for a0 <= |z| < a = b/2,   0 outside,
        p0 = 2·F'_0/(π·a0),  so that ∫p dz = F'_0 + Δp·b = F'.

    On the pressurised side the profile starts at Δp, the fluid's pressure there, and rises
    on the squeeze's flank as without pressure; on the other side it drops from Δp to 0 at
    the edge.  sealsim's FE maps of pressurised O-rings show both (2 mm cord, 12 % squeeze,
    Ø12 rod, 0–10 bar: the peak rises by 1.05·Δp, the edges rise to about Δp within two
    15 µm samples; ``tests/test_contact_friction.py``); the FE contact widens less than the
    Hertz width of F' (×1.25 instead of ×1.5 at 6 bar), so the flat shoulders are the
    estimate's, not the FE's.

    Parameters
    ----------
    position : array_like
        Axial positions z [m] from the contact's centre.
    force_per_length : float
        F' [N/m], the energised force per length (squeeze and pressure).
    width : float
        b [m], the energised contact width, > 0.
    pressure_difference : float
        Δp across the seal [Pa], >= 0.

    Returns
    -------
    ndarray
        p(z) [Pa].

    References
    ----------
    "O-ring acts like a fluid" (contact stress = squeeze stress + system pressure): Parker
    O-Ring Handbook ORD 5700, §1; Hertz line contact: K. L. Johnson, Contact Mechanics,
    Cambridge 1985, §4.2.

    Examples
    --------
    A 1635 N/m contact 1.23 mm wide at 6 bar (F'_0 = 898 N/m over 0.91 mm): a Hertz peak of
    1.25 MPa on 0.6 MPa:

    >>> z = np.array([-0.7e-3, -0.6e-3, 0.0, 0.6e-3])
    >>> (energised_contact_pressure(z, 1635.0, 1.229e-3, 6e5) / 1e6).round(3)
    array([0.   , 0.6  , 1.855, 0.6  ])
    >>> energised_contact_pressure(z, 1635.0, 0.0, 6e5)
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: energised_contact_pressure: width = 0.0 m must be > 0 and ...
    """
    if not (width > 0.0 and force_per_length >= 0.0):
        raise InputError(f"energised_contact_pressure: width = {width!r} m must be > 0 and "
                         f"force_per_length = {force_per_length!r} N/m >= 0")
    z = np.asarray(position, dtype=float)
    a = 0.5 * width
    dp = min(max(float(pressure_difference), 0.0), force_per_length / width)
    squeeze = force_per_length - dp * width
    a0 = a * np.sqrt(squeeze / force_per_length) if force_per_length > 0.0 else 0.0
    hertz = 0.0
    if a0 > 0.0:
        p0 = 2.0 * squeeze / (np.pi * a0)
        hertz = p0 * np.sqrt(np.clip(1.0 - (z / a0) ** 2, 0.0, None))
    return np.where(np.abs(z) < a, dp + hertz, 0.0)


def analytic_loads(pressure_difference, preload_per_length, modulus, cord_diameter,
                   sliding_diameter):
    """F_N [N] and b [m] of an O-ring from its preload: :func:`energised_force_per_length`
    and :func:`hertz_contact_width` on the circumference π·D.

    Examples
    --------
    >>> [round(float(v), 6) for v in analytic_loads(0.0, 1000.0, 8e6, 2.5e-3, 0.032)]
    [100.530965, 0.000773]
    """
    force = energised_force_per_length(preload_per_length, pressure_difference, cord_diameter,
                                       modulus)
    return (np.pi * sliding_diameter * force,
            hertz_contact_width(force, cord_diameter, modulus))


_analytic_loads = jit(analytic_loads,
                      energised_force_per_length=jit(energised_force_per_length),
                      hertz_contact_width=jit(
                          hertz_contact_width,
                          hertz_line_half_width=jit(hertz_line_half_width)))


def _analytic_loads_of(pressure_difference, preload, modulus, cord_diameter, diameter):
    """:func:`analytic_loads` (compiled) for any shapes of Δp, preload and modulus, always
    called with flat float64 arrays: numba compiles a function once per combination of
    argument types (scalar, array, read-only, 2-D ...), six of them for this one before, about
    40 s of compiling in a cold test session; now one.  Scalars in, floats out."""
    shape = np.broadcast_shapes(np.shape(pressure_difference), np.shape(preload),
                                np.shape(modulus))
    flat = [np.array(np.broadcast_to(np.asarray(x, dtype=float), shape)).reshape(-1)
            for x in (pressure_difference, preload, modulus)]
    force, width = _analytic_loads(*flat, float(cord_diameter), float(diameter))
    if shape == ():
        return float(force[0]), float(width[0])
    return force.reshape(shape), width.reshape(shape)


@dataclass(frozen=True)
class AnalyticContactMap:
    """Engineering estimate of F_N and b of an O-ring seal (no FE map needed) [R].

    .. math::
        c(T) &= 1 - (1 - c_0)/(1 + \\alpha (T - T_0)), \\qquad E(T) = E_0\\,r(T)/r(T_0) \\\\
        F'_0 &= E(T)\\,d\\,(1.25 c^{1.5} + 50 c^6) \\quad \\text{(Lindley 1967)} \\\\
        F' &= F'_0 + \\Delta p\\, b(F'), \\qquad b = 2\\sqrt{2 F' d/(\\pi E^*)}
              \\quad \\text{(Hertz)} \\\\
        F_N &= \\pi D F', \\qquad b

    with r(T) the stiffness law of ``temperature_scaling``
    (:meth:`sealsim.properties.elastomers.Elastomer.modulus_ratio`, the law the FE map's
    hyperelastic constants follow): "held" the relaxed modulus of ``elastomer`` after an hour
    at the squeeze relative to E0's test-frequency modulus (the default), "entropic" r = T
    (equilibrium modulus), "modulus" the catalogue's dynamic E(T, f), "none".
    See :func:`thermal_squeeze`, :func:`lindley_force_per_length`,
    :func:`energised_force_per_length`, :func:`hertz_contact_width`.  F_N rises with Δp and,
    with the default, with T from 20 to 100 °C through the thermal expansion of the cord (the
    trend of Heipl & Murrenhoff, Fig. 8 and 10).  Typical numbers: d = 2.5 mm, c0 = 12 %,
    E0 = 8 MPa (NBR of the catalogue, 6·(C10 + C01)) on D = 32 mm give F_N ≈ 53 N and
    b ≈ 0.8 mm unpressurised at 25 °C (held modulus 4.0 MPa), +140 % F_N at 6 bar, +1 % from
    25 to 55 °C (with "entropic": 108 N, +17 %; with "modulus" at 1 Hz: 96 N, −21 %).

    Parameters
    ----------
    sliding_diameter : float
        Diameter D of the sliding surface [m] (bore for a piston seal, rod for a rod seal).
    cord_diameter : float
        d [m].
    squeeze : float
        c0 at ``reference_temperature`` [-].
    modulus : float
        E0 [Pa] at ``reference_temperature``.
    thermal_expansion : float
        α [1/K].
    reference_temperature : float
        T0 [K] (installation).
    pressure_max : float
        Largest Δp [Pa] the estimate is used for.
    temperature_range : tuple of float, optional
        (T_min, T_max) [K] the estimate is used for (rubbery state); default from
        T_g + :data:`~sealsim.properties.elastomers.GLASS_TRANSITION_MARGIN` of ``elastomer``
        to 120 °C.  A T_min closer to T_g is refused.
    temperature_scaling : {"held", "entropic", "modulus", "none"}
        Temperature law of the modulus (see above).
    elastomer : str
        Catalogue elastomer whose E(T, f) the "modulus" scaling uses.
    frequency : float, optional
        f [Hz] of the "modulus" scaling (default: the elastomer's test frequency).

    Examples
    --------
    >>> m = AnalyticContactMap(0.032, 2.5e-3, 0.12, 8e6, 1.9e-4, 293.15)
    >>> fn, b = m.evaluate([0.0, 6e5], 298.15)
    >>> fn.round(1), (b * 1e3).round(3)
    (array([ 52.8, 127. ]), array([0.793, 1.229]))
    """

    sliding_diameter: float
    cord_diameter: float
    squeeze: float
    modulus: float
    thermal_expansion: float
    reference_temperature: float = 293.15
    pressure_max: float = 16e5
    temperature_range: tuple[float, float] | None = None
    temperature_scaling: str = "held"
    elastomer: str = "NBR"
    frequency: float | None = None

    def __post_init__(self):
        if self.temperature_scaling not in TEMPERATURE_SCALINGS:
            raise InputError(f"temperature_scaling = {self.temperature_scaling!r} is not "
                             f"allowed; choose one of {', '.join(TEMPERATURE_SCALINGS)}")
        rubber = get_elastomer(self.elastomer)  # unknown names fail here, not in a run
        lowest = rubber.glass_transition + GLASS_TRANSITION_MARGIN
        if self.temperature_range is None:
            object.__setattr__(self, "temperature_range", (lowest, 393.15))
        elif self.temperature_range[0] < lowest - 1e-9:
            raise InputError(rubbery_limit_message(
                "the analytic O-ring estimate", self.temperature_range[0], rubber))

    @property
    def ranges(self) -> dict[str, tuple[float, float]]:
        return {"pressure": (0.0, self.pressure_max), "temperature": self.temperature_range}

    def modulus_at(self, temperature):
        """E(T) [Pa] = E0·r(T)/r(T0) with the law of ``temperature_scaling`` ("held": E0 times
        the held modulus of a seal installed at T0 over the test-frequency modulus at the
        elastomer's reference temperature, where E0 = 6·(C10 + C01) holds)."""
        t0 = self.reference_temperature
        if self.temperature_scaling == "entropic":
            return entropic_modulus(self.modulus, temperature, t0)
        if self.temperature_scaling == "none":
            return self.modulus * np.ones_like(np.asarray(temperature, dtype=float))
        rubber = get_elastomer(self.elastomer)
        if self.temperature_scaling == "held":  # E0 is the test-frequency modulus at the
            # catalogue's reference temperature, the one 6·(C10 + C01) holds for
            return self.modulus * rubber.modulus_ratio(temperature, None, "held",
                                                       mounting_temperature=t0)
        return self.modulus * rubber.modulus_ratio(temperature, t0, self.temperature_scaling,
                                                   self.frequency)

    def _preload(self, temperature):
        """(F'_0 [N/m], E [Pa]) at T: the temperature-dependent part."""
        squeeze = thermal_squeeze(self.squeeze, self.thermal_expansion, temperature,
                                  self.reference_temperature)
        modulus = self.modulus_at(temperature)
        return lindley_force_per_length(squeeze, self.cord_diameter, modulus), modulus

    def preload_at(self, temperature: float):
        """:meth:`_preload` at one temperature, computed once per map and temperature (the
        modulus law costs half a millisecond; every simulation of the seal asks for it)."""
        cache = self.__dict__.setdefault("_cache", {})
        if temperature not in cache:
            cache[temperature] = self._preload(temperature)
        return cache[temperature]

    def evaluate(self, pressure_difference, temperature):
        """(F_N [N], b [m]) at Δp [Pa] and T [K] (vectorised)."""
        if np.ndim(temperature) == 0:     # a seal's temperature is constant during a run
            preload, modulus = self.preload_at(float(temperature))
        else:
            preload, modulus = self._preload(np.asarray(temperature, dtype=float))
        return _analytic_loads_of(pressure_difference, preload, modulus, self.cord_diameter,
                                  self.sliding_diameter)

    @property
    def temperature_kinks(self) -> tuple[float, ...]:
        """Temperatures [K] inside the range where dF_N/dT jumps: with the "held" modulus the
        installation temperature T0, where F_N(T) peaks (a seal cooled after mounting keeps
        the stress it relaxed to, one warmed relaxes further, see
        :meth:`~sealsim.properties.elastomers.Elastomer.held_modulus`); a table of the map
        puts nodes at them."""
        lo, hi = self.temperature_range
        t0 = self.reference_temperature
        return (t0,) if self.temperature_scaling == "held" and lo < t0 < hi else ()

    def loads_function(self, temperature: float):
        """``f(Δp) -> (F_N, b)`` at a fixed temperature T [K] (the fast path of a seal whose
        temperature does not change during a run)."""
        preload, modulus = self.preload_at(float(temperature))
        d, diameter = self.cord_diameter, self.sliding_diameter

        def loads(pressure_difference):
            return _analytic_loads_of(pressure_difference, preload, modulus, d, diameter)
        return loads

    def describe(self) -> dict[str, Any]:
        # shown to users (FMU documentation, plot titles, CLI): no internal verification tag
        return {"source": "analytic engineering estimate (Lindley + Hertz + pressure "
                          "energisation)",
                "sliding_diameter_m": self.sliding_diameter,
                "cord_diameter_m": self.cord_diameter, "squeeze": self.squeeze,
                "modulus_Pa": self.modulus, "thermal_expansion_per_K": self.thermal_expansion,
                "reference_temperature_K": self.reference_temperature,
                "temperature_scaling": self.temperature_scaling,
                "elastomer": self.elastomer,
                # the range is part of what a friction table built on the map covers
                "pressure_range_Pa": list(self.ranges["pressure"]),
                "temperature_range_K": list(self.ranges["temperature"]),
                **({"frequency_Hz": self.frequency}
                   if self.temperature_scaling == "modulus" else {})}


# -- FE characteristic maps -------------------------------------------------------------------
@dataclass
class FEContactMap:
    """Adapter of an FE characteristic map (:class:`sealsim.structure.maps.SealMap`).

    The map is interpolated with a C¹ Hermite scheme (no kinks for the ODE solver).  Its
    pressure axis is the gauge pressure on the upstream side of the seal with the atmosphere
    downstream; the pneumatic model evaluates it at the pressure *difference* across the seal
    (for a piston seal with both sides pressurised the mean pressure is neglected: a nearly
    incompressible rubber ring's contact forces depend on the difference).  Values outside the
    map are never extrapolated: :meth:`evaluate` clamps to the grid (the simulation checks the
    ranges before it runs and reports clamped pressures).

    Parameters
    ----------
    seal_map : sealsim.structure.maps.SealMap
        The map (loaded with ``extrapolate="clip"``).
    squeeze : float, optional
        Squeeze [-] when the map has several squeezes.
    source : str
        Where the map came from (file path), for :meth:`describe`.
    """

    seal_map: Any
    squeeze: float | None = None
    source: str = ""
    ranges: dict[str, tuple[float, float]] = field(init=False)

    def __post_init__(self):
        r = self.seal_map.ranges
        self.ranges = {"pressure": r["pressure"], "temperature": r["temperature"]}
        lo, hi = r["squeeze"]
        if hi > lo and self.squeeze is None:
            raise InputError(f"map {self.source!r} has squeezes {lo:g} … {hi:g}: give "
                             "map.squeeze for this seal")
        if self.squeeze is not None and not (lo - 1e-9 <= self.squeeze <= hi + 1e-9):
            raise InputError(f"map.squeeze = {self.squeeze:g} is outside the map {self.source!r}"
                             f" ({lo:g} … {hi:g})")

    def evaluate(self, pressure_difference, temperature):
        """(F_N [N], b [m]) at Δp [Pa] and T [K], both clamped to the map (vectorised; the
        compiled kernel :func:`hermite_grid_point`)."""
        row, data = self.tables()
        if np.ndim(pressure_difference) == 0 and np.ndim(temperature) == 0:
            fn, b, _ = hermite_grid_point(row, data, float(pressure_difference),
                                          float(temperature))
            return fn, b
        p, t = (np.array(a, dtype=float) for a in np.broadcast_arrays(
            np.asarray(pressure_difference, dtype=float), np.asarray(temperature, dtype=float)))
        fn, b = np.empty(p.shape), np.empty(p.shape)
        _hermite_grid_many(row, data, p.reshape(-1), t.reshape(-1), fn.reshape(-1),
                           b.reshape(-1))
        return fn, b

    def tables(self):
        """The map as the (int row, float data) of :func:`hermite_grid_point` (built once)."""
        cached = self.__dict__.get("_tables")
        if cached is None:
            m = self.seal_map
            grid = getattr(m, "_grid", None)
            if grid is None:       # rebuild the interpolant from the map's public data
                from sealsim.structure.maps import HermiteGrid

                data = np.stack([m.dataset[v].transpose(*m.dims).values for v in m.variables],
                                axis=-1)
                index = tuple(slice(None) if d in m.active else 0 for d in m.dims)
                grid = HermiteGrid([m.coords[d] for d in m.active], data[index])
            cached = self.__dict__["_tables"] = grid_tables(
                grid, [GRID_ROLES[d] for d in m.active],
                self.squeeze if self.squeeze is not None else float("nan"),
                self.ranges["pressure"], self.ranges["temperature"],
                m.variables.index("F_N"), m.variables.index("b"))
        return cached

    def loads_function(self, temperature: float):
        """``f(Δp) -> (F_N, b)`` at a fixed temperature T [K]."""
        return lambda pressure_difference: self.evaluate(pressure_difference, temperature)

    def describe(self) -> dict[str, Any]:
        return {"source": f"FE characteristic map {self.source}", "squeeze": self.squeeze,
                "pressure_range_Pa": list(self.ranges["pressure"]),
                "temperature_range_K": list(self.ranges["temperature"])}

    @classmethod
    def from_file(cls, path: str | Path, squeeze: float | None = None) -> FEContactMap:
        """Read a ``map.nc`` written by ``sealsim structure map``."""
        from sealsim.structure.maps import load_map

        return cls(load_map(path, extrapolate="clip"), squeeze=squeeze, source=str(path))


def glassy_reason(contact_map, temperature: float) -> str:
    """Why a map refuses ``temperature`` [K] if it lies within the T_g margin of the map's
    rubber (a rubbery map must not be used there), else '' (also for a compound whose T_g is
    not known here)."""
    name = getattr(contact_map, "elastomer", None)
    if name is None and hasattr(contact_map, "seal_map"):
        name = contact_map.seal_map.dataset.attrs.get("elastomer")
    try:
        rubber = get_elastomer(name)
    except (InputError, TypeError, KeyError):   # a custom material: no T_g known here
        return ""
    if temperature >= rubber.glass_transition + GLASS_TRANSITION_MARGIN:
        return ""
    return ("; " + rubbery_limit_message("the seal's contact map", temperature, rubber)
            + "; for colder service choose a compound with a lower T_g (analytic map: "
            "elastomer = 'compound.toml')")


def default_cache_dir() -> Path:
    """Folder of the map cache: ``$SEALSIM_CACHE`` or ``$XDG_CACHE_HOME/sealsim`` or
    ``~/.cache/sealsim``, sub-folder ``maps``."""
    root = os.environ.get("SEALSIM_CACHE")
    if root:
        return Path(root) / "maps"
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "sealsim" / "maps"


def build_or_load_fe_map(structure_case: str | Path, squeeze: float | None = None,
                         cache_dir: str | Path | None = None, progress=None,
                         workers: int | None = None, label: str = "") -> FEContactMap:
    """FE map of a structure case file, built on demand and cached.

    The case (with a ``[map]`` table, no variants) is validated and resolved (all defaults
    filled in); the key of its FE results
    (:func:`sealsim.structure.fingerprint.results_key`: the resolved case, the FE model's
    fingerprint -- model version, FElupe version, source of the structure model and the
    elastomer catalogue -- and a compound file's content) names the cache file
    ``<cache_dir>/<stem>-<hash16>.nc``.  A cached map is read (one that cannot be read, a
    damaged file, is built again with a warning); otherwise
    :func:`sealsim.structure.mapping.compute_map` runs (FE, minutes) and its result is written
    atomically to the cache; its finished FE load paths are kept meanwhile
    (:func:`kept_paths_folder`), so that a build that is interrupted computes only the missing
    paths the next time the map is needed.  Any change of the structure case or of the FE
    model gives a new map (old files stay in the cache folder until deleted).  Before a map
    is computed, the logger ``sealsim.pneumatic.contact_maps`` announces it at INFO level
    ("building FE map for seal 'rod' from rod_seal_12.toml (5 pressures x 3 temperatures, 3 FE
    load paths), cached at ...").

    Parameters
    ----------
    structure_case : path
        Structure case file (TOML), e.g. ``examples/structure/oring_map.toml``.
    squeeze : float, optional
        Squeeze [-] when the map has several.
    cache_dir : path, optional
        Cache folder (default :func:`default_cache_dir`).
    progress : callable, optional
        ``progress(done, total)`` while the map is computed (finished FE load paths: one per
        squeeze and temperature).
    workers : int, optional
        Processes for the FE map (default: the case's ``map.workers``).
    label : str, optional
        What the map is for, in the notice (e.g. ``"seal 'rod'"``).

    Returns
    -------
    FEContactMap
    """
    from sealsim.cases import dump_case_toml
    from sealsim.files import atomic_write_bytes, netcdf_ready

    try:
        from sealsim.structure.case import load_structure_cases
        from sealsim.structure.mapping import compute_map
    except ImportError as exc:  # pragma: no cover - structure package missing
        raise InputError(f"building FE maps needs sealsim.structure ({exc})") from None
    path = Path(structure_case)
    cases = load_structure_cases(path, f"structure case {str(path)!r}")
    if len(cases) != 1:
        raise InputError(f"structure case {str(path)!r} has variants; a seal map needs one case")
    case = next(iter(cases.values()))
    if case.map is None:
        raise InputError(f"structure case {str(path)!r} has no [map] table (map.pressure and "
                         "map.temperature grids) to build the seal's characteristic map from")
    text = dump_case_toml(case, header="resolved sealsim structure case (all defaults filled "
                                       "in)")
    from sealsim.structure.fingerprint import results_key

    # the resolved case, the FE model's fingerprint (a map of another FE model is not reused)
    # and the content of a compound file the case names, not only its path
    digest = results_key(case)[:16]
    folder = Path(cache_dir) if cache_dir is not None else default_cache_dir()
    target = folder / f"{path.stem}-{digest}.nc"
    damaged = target.is_file() and not _readable_netcdf(target)
    if damaged:
        logger.warning(f"the cached map {target} cannot be read (a damaged file); it is built "
                       "again")
    if damaged or not target.is_file():
        try:
            folder.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise InputError(f"cannot create the map cache folder {str(folder)!r}: {exc}") \
                from None
        logger.info(_build_notice(case, path, target, label))
        kept = kept_paths_folder(target)
        dataset = compute_map(case, workers=workers, progress=progress, case_text=text,
                              keep=kept)
        dataset, encoding = netcdf_ready(dataset)
        atomic_write_bytes(target, dataset.to_netcdf(encoding=encoding))
        shutil.rmtree(kept, ignore_errors=True)   # the map is stored: its paths are not needed
    return FEContactMap.from_file(target, squeeze=squeeze)


def kept_paths_folder(target: Path) -> Path:
    """Where the finished FE load paths of the cached map ``target`` are kept while it is
    built (``.NAME.paths`` next to it): a build interrupted by Ctrl-C, a killed process or a
    power loss computes only the missing paths when the map is needed again."""
    return target.with_name(f".{target.name}.paths")


def _readable_netcdf(path: Path) -> bool:
    """Whether ``path`` opens as a netCDF file (a cache file damaged on disk does not)."""
    import xarray as xr

    try:
        with xr.open_dataset(path):
            return True
    except Exception:  # netCDF errors come in many types
        return False


def _build_notice(case, path: Path, target: Path, label: str = "") -> str:
    """The line announcing that the FE map of structure case ``case`` (read from ``path``) is
    built and cached at ``target``."""
    spec = case.map
    squeezes = len(spec.squeeze) if spec.squeeze else 1   # else the installation's one
    grid = f"{len(spec.pressure)} pressures x {len(spec.temperature)} temperatures" + (
        f" x {squeezes} squeezes" if squeezes > 1 else "")
    paths = squeezes * len(spec.temperature)
    what = f"for {label} from {path.name}" if label else f"from {path.name}"
    return (f"building FE map {what} ({grid}, {paths} FE load path{'s' * (paths != 1)}), "
            f"cached at {target}")


# -- compiled Hermite grid (the FE maps and tabulated maps in the pneumatic right-hand side) --
#: role of a grid axis: the squeeze (fixed per seal), the temperature or the pressure difference
GRID_ROLES = {"squeeze": 0, "temperature": 1, "pressure": 2}
#: columns of a map's int row: kind (2 = grid), data offset, number of axes, role and length of
#: each of up to three axes, number of variables, index of F_N and of b among them
GRID_KIND = 2
_ROW = 12


def grid_tables(grid, roles, squeeze, pressure_range, temperature_range, fn_index, b_index):
    """The (int row, float data) of a :class:`sealsim.structure.maps.HermiteGrid` for
    :func:`hermite_grid_point`.

    ``data`` = [squeeze, p_lo, p_hi, T_lo, T_hi, axes..., cell coefficients
    (cells, 4^d, nvars) flattened]; the row holds the layout (``_ROW`` int64 columns).
    """
    if grid.ndim > 3:
        raise InputError(f"a contact map has at most 3 axes, got {grid.ndim}")
    row = np.zeros(_ROW, dtype=np.int64)
    row[0], row[1], row[2] = GRID_KIND, 0, grid.ndim
    for k, (axis, role) in enumerate(zip(grid.axes, roles)):
        row[3 + k] = role
        row[6 + k] = axis.size
    row[9], row[10], row[11] = grid.nvars, fn_index, b_index
    head = [squeeze, pressure_range[0], pressure_range[1], temperature_range[0],
            temperature_range[1]]
    data = np.concatenate([np.asarray(head, dtype=float)] + [np.asarray(a, float) for a in
                                                             grid.axes]
                          + [np.ascontiguousarray(grid.coeff, dtype=float).reshape(-1)])
    return row, data


@njit(cache=True)
def hermite_grid_point(row, data, pressure, temperature):
    """(F_N [N], b [m], clipped) of a gridded contact map at Δp [Pa] and T [K].

    The C¹ tensor-product cubic Hermite interpolant of
    :class:`sealsim.structure.maps.HermiteGrid` (PCHIP node slopes; the same cell
    coefficients), on the axes of the map (squeeze, temperature, pressure, each if it varies).
    Δp and T are clamped to the map (it is never extrapolated); ``clipped`` is 1.0 when T was
    outside the temperature range.  ``row``/``data``: :func:`grid_tables`.
    """
    o = row[1]
    d = row[2]
    plo, phi, tlo, thi = data[o + 1], data[o + 2], data[o + 3], data[o + 4]
    p = min(max(pressure, plo), phi)
    t = min(max(temperature, tlo), thi)
    clipped = 1.0 if abs(t - temperature) > 1e-9 * max(abs(temperature), 1.0) else 0.0
    pos = o + 5
    cell = 0
    u0 = u1 = u2 = 0.0
    for k in range(d):
        role = row[3 + k]
        n = row[6 + k]
        x = data[o] if role == 0 else (t if role == 1 else p)
        # the cell, searched in place (a slice is an array view, whose reference count costs
        # more than the search); x is inside the axis (Δp, T clamped, a squeeze outside the
        # map refused), so the search's own clamping changes nothing
        i, u = locate_on_axis(data, pos, n, x)
        cell = cell * (n - 1) + i
        if k == 0:
            u0 = u
        elif k == 1:
            u1 = u
        else:
            u2 = u
        pos += n
    nvars = row[9]
    fn = 0.0
    b = 0.0
    base = pos + cell * 4 ** d * nvars
    c0, c1 = base + row[10], base + row[11]
    h0, h1, h2 = hermite_basis(u0), hermite_basis(u1), hermite_basis(u2)   # once per axis
    j = 0                                   # node j = q0·4^(d-1) + ... of the cell's 4^d
    for q0 in range(4):
        if d == 1:
            w = h0[q0]
            fn += w * data[c0 + j * nvars]
            b += w * data[c1 + j * nvars]
            j += 1
            continue
        for q1 in range(4):
            if d == 2:
                w = h0[q0] * h1[q1]
                fn += w * data[c0 + j * nvars]
                b += w * data[c1 + j * nvars]
                j += 1
                continue
            for q2 in range(4):
                w = h0[q0] * h1[q1] * h2[q2]
                fn += w * data[c0 + j * nvars]
                b += w * data[c1 + j * nvars]
                j += 1
    return fn, b, clipped


@njit(cache=True)
def _hermite_grid_many(row, data, pressure, temperature, fn, b):
    for k in range(pressure.shape[0]):
        fn[k], b[k], _ = hermite_grid_point(row, data, pressure[k], temperature[k])


def tabulated_map_tables(contact_map, temperature_range, pressures=33, temperatures=25):
    """A contact map tabulated on a (temperature, Δp) grid and interpolated like an FE map:
    how a heated seal evaluates any map whose own evaluation is not compiled (the analytic
    estimate at a varying temperature).  Returns the (row, data) of :func:`grid_tables`.

    The Δp points are denser at low pressure (quadratic spacing), where the O-ring's
    energisation bends the curve most.  The tables are kept on the map object (a simulation of
    the same seals again, as in a study, does not build them again: milliseconds per run);
    callers copy them, never modify them.
    """
    from sealsim.structure.maps import HermiteGrid

    memo = getattr(contact_map, "__dict__", {}).setdefault("_tabulated_tables", {})
    key = (float(temperature_range[0]), float(temperature_range[1]), pressures, temperatures)
    if key in memo:
        return memo[key]
    (plo, phi) = contact_map.ranges["pressure"]
    tlo, thi = temperature_range
    p = plo + (phi - plo) * np.linspace(0.0, 1.0, pressures) ** 2
    t = np.linspace(tlo, thi, temperatures)
    tt, pp = np.meshgrid(t, p, indexing="ij")
    fn, b = contact_map.evaluate(pp, tt)
    grid = HermiteGrid([t, p], np.stack([np.asarray(fn, float), np.asarray(b, float)], axis=-1))
    row, data = grid_tables(grid, [1, 2], float("nan"), (plo, phi), (tlo, thi), 0, 1)
    memo[key] = row, data
    return row, data
