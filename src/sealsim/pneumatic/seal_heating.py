r"""Frictional heating of the seals: a lumped thermal node per seal, the rod and the tube.

Each heated seal is one node -- the seal ring with its contact zone -- at the temperature T_s,
heated by its friction power and cooled by conduction and convection::

    C_s·dT_s/dt = F·v − G_c(v)·(T_s − T_c) − G_g·(T_s − T_g) − Σ G_air·(T_s − T_air)

* **F·v** -- the friction power of the seal's law (all of it is released in the contact zone;
  for laws with bristles F·v also contains the elastic power of the bristles, which averages
  out over a cycle);
* **G_c(v) = h_c(v)·π·D·b** -- into the sliding counterface (tube for a piston seal, rod for a
  rod seal or wiper) at T_c, through the contact of width b (:func:`sliding_contact_coefficient`);
* **G_g = k_r·π·D·b/(d/2)** -- conduction through the rubber (half the cord d) into the groove
  (the piston for a piston seal, the head for a rod seal) at T_g (Fourier's law,
  :func:`conduction_conductance`);
* **G_air = h·A** -- convection from the free flanks of the cord to the chamber air or the
  atmosphere on either side (:func:`seal_flank_area`).

C_s = ρ·c·V of the ring (:func:`oring_volume`), with ρ, c, k of the elastomer catalogue.

The metal parts are nodes as well, because they set the long-term temperature of the seals: the
sliding contact couples a seal to its counterface within a few kelvin, so a seal warms over a
long duty cycle because the rod and the tube do.  The **tube** (the barrel swept by the piston
seals, with the heads) receives the heat of the seals sliding on it and gives the chamber wall
heat to the air (the barrel and the cap and head faces are at its temperature); the **rod** --
the moving metal, piston and rod, of mass ``cylinder.piston_mass`` -- receives the heat of the
rod seal and wiper and, through the groove of the piston, of the piston seals, and gives the
chamber air the heat of the piston's two faces and of the rod's surface in the rod-side
chamber (:func:`~sealsim.pneumatic.chambers.chamber_wall_areas`).  Both lose heat to the
surroundings by free convection and radiation (:func:`ambient_coefficient`), the tube over its
whole outside, the rod over the length x the piston has extended it (the rest of the rod is in
the rod-side chamber and the head)::

    C_tube·dT_tube/dt = Σ heat from seals − Q_wall,air − G_amb,tube·(T_tube − T_amb)
    C_rod·dT_rod/dt   = Σ heat from seals − Q_rod,air − h_amb,rod·π·d·x·(T_rod − T_amb)

Not modelled: conduction along the rod into the load and along the tube into the mounting
(both would cool the metal; they make the warming an upper estimate), temperature gradients
inside the seal (the rubber is lumped: its conduction is about a hundredth of the contact
conductance, so the ring follows its contact zone).

Steady state for a seal sliding at constant speed with the other nodes held (the closed form a
test checks)::

    T_s = (P + G_c·T_c + G_g·T_g + Σ G_air·T_air)/(G_c + G_g + Σ G_air),   P = F·v

With all conductances zero the seal heats as dT_s/dt = F·v/(m·c).

References
----------
.. [1] H. S. Carslaw, J. C. Jaeger, Conduction of Heat in Solids, 2nd ed., Oxford 1959, §2.9
   (surface temperature of a semi-infinite solid under a constant flux).
.. [2] J. C. Jaeger, "Moving sources of heat and the temperature at sliding contacts",
   Proc. R. Soc. N.S.W. 76, 203-224, 1942; J. F. Archard, "The temperature of rubbing
   surfaces", Wear 2, 438-455, 1959 (band sources at high Péclet number).
.. [3] F. P. Incropera, D. P. DeWitt, T. L. Bergman, A. S. Lavine, Fundamentals of Heat and
   Mass Transfer, 6th ed., Wiley 2007: Fourier's law (Eq. 3.6), Table A.1 (metals at 300 K),
   Churchill & Chu free convection from a horizontal cylinder (Eq. 9.34), radiation.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = [
    "METALS",
    "ambient_coefficient",
    "conduction_conductance",
    "effusivity",
    "oring_volume",
    "seal_flank_area",
    "sliding_contact_coefficient",
    "steady_seal_temperature",
]

#: Metals at 300 K (Incropera et al. 2007, Table A.1): conductivity k [W/(m·K)], density ρ
#: [kg/m³], specific heat c [J/(kg·K)], and a typical emissivity ε [-] of the finished surface
#: (Incropera Table A.11: anodised aluminium 0.82; polished chromium about 0.1).
METALS = {
    "aluminium": {"conductivity": 177.0, "density": 2770.0, "specific_heat": 875.0,
                  "emissivity": 0.82, "source": "aluminium alloy 2024-T6, Incropera Table A.1;"
                                                " anodised surface"},
    "steel": {"conductivity": 63.9, "density": 7832.0, "specific_heat": 434.0,
              "emissivity": 0.1, "source": "plain carbon steel AISI 1010, Incropera Table A.1;"
                                           " hard-chromed surface"},
}


def effusivity(conductivity, density, specific_heat):
    """Thermal effusivity e = sqrt(k·ρ·c) [W·s^0.5/(m²·K)].

    Examples
    --------
    >>> round(float(effusivity(63.9, 7832.0, 434.0)))
    14738
    """
    return np.sqrt(np.asarray(conductivity, dtype=float) * density * specific_heat)


@njit(cache=True)
def sliding_contact_coefficient(v, width, effusivity, static):
    """Heat-transfer coefficient [W/(m²·K)] from a contact band into the sliding counterface.

    A surface point of the counterface passes under the contact band of width b in the time
    b/|v| and sees the flux q meanwhile; at a high Péclet number it conducts like a
    semi-infinite solid, θ(t) = 2q·sqrt(κt/π)/k (Carslaw & Jaeger §2.9), so the mean surface
    temperature rise over the band is (4/3)·(q/k)·sqrt(κ·b/(π|v|)) (Jaeger 1942) and

    .. math:: h = \\frac{3\\sqrt{\\pi}}{4}\\,e\\,\\sqrt{|v|/b}, \\qquad e = \\sqrt{k\\rho c}

    At rest (and when slower) the contact conducts through the metal behind it: ``static``
    (k/t for a wall of thickness t, or k/(d/2) for a rod), the larger of the two is used.

    Parameters
    ----------
    v : float
        Sliding speed [m/s].
    width : float
        Contact width b [m], > 0.
    effusivity : float
        e of the counterface [W·s^0.5/(m²·K)].
    static : float
        Coefficient at rest [W/(m²·K)].

    Returns
    -------
    float
        h [W/(m²·K)].

    Examples
    --------
    Chromed steel rod, b = 0.8 mm, 0.3 m/s:

    >>> round(sliding_contact_coefficient(0.3, 8e-4, 14739.0, 10650.0))
    379420
    """
    moving = 0.75 * math.sqrt(math.pi) * effusivity * math.sqrt(abs(v) / width)
    return max(moving, static)


def conduction_conductance(conductivity, area, length):
    """Conductance of a slab, G = k·A/L [W/K] (Fourier's law, Incropera Eq. 3.6).

    Parameters
    ----------
    conductivity : array_like
        k [W/(m·K)].
    area : array_like
        A [m²].
    length : array_like
        Conduction length L [m].

    Examples
    --------
    NBR (k = 0.25 W/(m·K)) from the middle of a 2 mm cord to a 0.8 mm wide groove contact on
    a 32 mm diameter:

    >>> round(float(conduction_conductance(0.25, np.pi * 0.032 * 8e-4, 1e-3)), 4)
    0.0201
    """
    return np.asarray(conductivity, dtype=float) * area / length


def oring_volume(ring_diameter, cord_diameter):
    """Volume of an O-ring V = π·D_ring·π·d²/4 [m³] (torus of mean diameter D_ring).

    Examples
    --------
    >>> round(float(oring_volume(0.030, 0.002)) * 1e9, 1)    # [mm³]
    296.1
    """
    return np.pi * np.asarray(ring_diameter, dtype=float) * np.pi * np.asarray(
        cord_diameter, dtype=float) ** 2 / 4.0


def seal_flank_area(ring_diameter, cord_diameter, contact_width):
    """Free surface of an O-ring on one side (half the cord perimeter outside the two
    contacts) [m²]: π·D_ring·(π·d − 2·b)/2.

    Examples
    --------
    >>> round(float(seal_flank_area(0.030, 0.002, 8e-4)) * 1e6, 1)    # [mm²]
    220.7
    """
    return np.pi * np.asarray(ring_diameter, dtype=float) * (
        np.pi * cord_diameter - 2.0 * np.asarray(contact_width, dtype=float)) / 2.0


def ambient_coefficient(diameter, surface_temperature, ambient_temperature, emissivity):
    """Heat-transfer coefficient of a horizontal cylinder to still air [W/(m²·K)]: free
    convection (Churchill & Chu, Incropera Eq. 9.34) plus linearised radiation, with the air
    properties at the film temperature.

    Parameters
    ----------
    diameter : float
        Outer diameter [m].
    surface_temperature, ambient_temperature : float
        [K] (their difference sets the free convection).
    emissivity : float
        ε of the surface [-].

    Examples
    --------
    A Ø40 mm anodised tube 10 K above 25 °C air:

    >>> round(float(ambient_coefficient(0.040, 308.15, 298.15, 0.82)), 2)
    9.62
    """
    from sealsim.thermal.convection import (
        air_properties,
        free_convection_horizontal_cylinder,
        radiation_coefficient,
    )

    film = 0.5 * (surface_temperature + ambient_temperature)
    nu, alpha, k, _ = air_properties(film)
    delta = max(abs(surface_temperature - ambient_temperature), 1e-3)
    h_conv = free_convection_horizontal_cylinder(diameter, delta, nu, alpha, k, 1.0 / film)
    return float(h_conv + radiation_coefficient(surface_temperature, ambient_temperature,
                                                emissivity))


def steady_seal_temperature(power, conductances, temperatures):
    """Steady temperature of a seal node [K]: T_s = (P + Σ G_k·T_k)/Σ G_k.

    Parameters
    ----------
    power : float
        Friction power P = F·v [W].
    conductances : array_like
        G_k to the neighbouring nodes [W/K].
    temperatures : array_like
        T_k of the neighbours [K].

    Examples
    --------
    >>> round(float(steady_seal_temperature(2.0, [1.0, 0.02], [300.0, 300.0])), 4)
    301.9608
    """
    g = np.asarray(conductances, dtype=float)
    return (power + float(np.sum(g * np.asarray(temperatures, dtype=float)))) / float(np.sum(g))
