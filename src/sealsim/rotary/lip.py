"""Radial lip: default proportions, lip force vs temperature, plain and wave lip styles.

The radial lip force F_tip of a garter-spring lip seal has two shares (reference notes §4):
the garter spring (steel: its force does not change with temperature in the service range)
and the elastomer's own interference (proportional to the rubber's quasi-static modulus).
With the rubber share s_r = 1 − s_spring at the reference temperature T_ref,

    F_tip(T) = F_ref·[s_spring + (1 − s_spring)·E(T)/E(T_ref)].                 (1)

E is evaluated at a quasi-static frequency (:data:`LIP_FORCE_FREQUENCY`): the lip's
interference is held for hours, so the relaxed modulus applies, not the dynamic one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "LIP_FORCE_FREQUENCY",
    "LIP_STYLES",
    "LipStyle",
    "default_contact_width",
    "default_outer_diameter",
    "default_radial_force",
    "default_width",
    "lip_force",
]

#: Frequency at which E(T) scales the rubber share of the lip force [Hz].  0.01 Hz (time scale
#: ≈ 100 s) is the quasi-static end of DMA; for the catalogue NBR it gives a 20 % drop of the
#: rubber share from 20 to 100 °C, the short-term drop the reference notes (§4, "elastomer part
#: drops ~20-30 % from 20 to 100 °C") give for NBR lip seals.
LIP_FORCE_FREQUENCY = 0.01

#: Radial load per unit circumference of a DIN 3760 lip [N/m]: 0.15 N/mm, the middle of
#: the 0.1-0.2 N/mm of the reference notes §4 (38 N on an 80 mm shaft).
DEFAULT_LOAD_PER_LENGTH = 150.0


def lip_force(reference_force, spring_share, modulus_ratio):
    """Radial lip force at temperature, Eq. (1).

    Parameters
    ----------
    reference_force : array_like
        Lip force F_ref at the reference temperature [N].
    spring_share : array_like
        Share of the garter spring in F_ref [-], 0...1.
    modulus_ratio : array_like
        E(T)/E(T_ref) of the lip elastomer at the quasi-static frequency [-].

    Returns
    -------
    numpy.ndarray
        F_tip(T) [N].

    Examples
    --------
    >>> float(lip_force(30.0, 0.4, 0.8))
    26.4
    """
    s = np.asarray(spring_share, dtype=float)
    return np.asarray(reference_force, dtype=float) * (s + (1.0 - s) * np.asarray(
        modulus_ratio, dtype=float))


def default_radial_force(shaft_diameter):
    """Default radial lip force of a DIN 3760 seal: 0.15 N/mm of circumference.

    Parameters
    ----------
    shaft_diameter : array_like
        d [m].

    Returns
    -------
    numpy.ndarray
        F_r [N].

    Examples
    --------
    >>> round(float(default_radial_force(0.08)), 1)
    37.7
    """
    return DEFAULT_LOAD_PER_LENGTH * np.pi * np.asarray(shaft_diameter, dtype=float)


def default_outer_diameter(shaft_diameter):
    """Outer diameter of a DIN 3760 / ISO 6194 seal, D ≈ d + 2·(0.1·d + 2.5 mm).

    A fit of the common sizes 20×35, 40×52, 80×100, 120×150 (±2 mm), rounded to 1 mm.

    Parameters
    ----------
    shaft_diameter : float
        d [m].

    Returns
    -------
    float
        D [m].

    Examples
    --------
    >>> round(default_outer_diameter(0.08), 4)
    0.101
    """
    section = 0.1 * shaft_diameter + 2.5e-3
    return float(np.round((shaft_diameter + 2 * section) * 1e3) / 1e3)


def default_width(shaft_diameter):
    """Axial width of a DIN 3760 seal, b_seal ≈ 0.05·d + 5 mm, rounded to 1 mm.

    Parameters
    ----------
    shaft_diameter : float
        d [m].

    Returns
    -------
    float
        Width [m] (7 mm at d = 40 mm, 9 mm at 80 mm, 11 mm at 120 mm).

    Examples
    --------
    >>> round(default_width(0.08), 4)
    0.009
    """
    return float(np.round((0.05 * shaft_diameter + 5e-3) * 1e3) / 1e3)


def default_contact_width(shaft_diameter):
    """Default axial contact width of a run-in lip, 0.25 mm (any size).

    New lips touch over 0.1-0.2 mm, run-in lips over 0.2-0.5 mm (reference notes §4);
    seed 000 validates run-in seals, so sealsim uses a value at the lower end of run-in.

    Examples
    --------
    >>> default_contact_width(0.08)
    0.00025
    """
    return 2.5e-4


@dataclass(frozen=True)
class LipStyle:
    """How a lip style changes film and heat exchange relative to a plain lip.

    Parameters
    ----------
    name : str
        "plain" or "wave".
    film_factor : float
        Effective film thickness relative to a plain lip at the same η·u [-].
    track_amplitude : float
        Axial amplitude of the contact track on the shaft [m]; the frictional heat is spread
        over a band of width b + 2·amplitude.
    lip_heat_exchange_factor : float
        Multiplier of the oil-side heat transfer coefficient of the lip [-].
    """

    name: str
    film_factor: float
    track_amplitude: float
    lip_heat_exchange_factor: float


#: Lip styles.  Plain: the reference.  Wave (SKF WAVE; seed 000 Fig. 11: a sinusoidal contact
#: patch "enables a better lubricant flow at the vicinity of the lip and a higher lubricant film
#: in the contact.  This also enables a better heat exchange"):
#:
#: * film_factor 1.3: the inclined track of a sinusoidal edge sweeps oil into the contact like a
#:   hydrodynamic wedge; a 30 % thicker mean film is a moderate value for a wedge angle of a few
#:   degrees (sealsim assumption: no published film measurement of wave lips was found);
#: * track_amplitude 0.5 mm: the sinusoidal edge of a wave lip oscillates by about ±0.5 mm
#:   across the shaft (seed 000 Fig. 11 shows a track several contact widths wide);
#: * lip_heat_exchange_factor 2: the bi-directional pumping renews the oil at the lip, which
#:   sealsim represents as twice the oil-side heat transfer of a plain lip.
LIP_STYLES = {
    "plain": LipStyle("plain", film_factor=1.0, track_amplitude=0.0,
                      lip_heat_exchange_factor=1.0),
    "wave": LipStyle("wave", film_factor=1.3, track_amplitude=0.5e-3,
                     lip_heat_exchange_factor=2.0),
}
