"""Radial lip: default proportions, lip force vs temperature, plain and wave lip styles.

**Lip force.**  The radial lip force F_tip of a garter-spring lip seal has two shares: the
garter spring (steel: its force does not change with temperature in the service range) and the
elastomer's own interference.  The rubber share is the lip ring's elastic response to being
stretched onto the shaft: a stress σ = E·ε with the hoop strain ε = δ/R of the interference δ.
Its modulus is sealsim's one convention for a held seal, the relaxed modulus after the holding
time of the rubber's master curve (:meth:`~sealsim.properties.elastomers.Elastomer.held_modulus`,
E_h; the pneumatic maps use the same), and its history matters: the lip is mounted at T_m
(``seal.mounting_temperature``), its stress relaxes there, and a later change of temperature
adds a strain increment that meets the modulus at the new temperature (Boltzmann
superposition in reduced time, Morland & Lee 1960):

    σ(T) = E_m(T)·ε(T_m) + E_h(T)·[ε(T) − ε(T_m)],                                (1)

E_m(T) = E_h(T, mounted at T_m): a lip cooled after mounting keeps the stress it relaxed to at
T_m and only the contraction increment meets the stiff cold rubber; a lip warmed after mounting
relaxes further, as if mounted warm (then Eq. 1 is E_h(T)·ε(T)).  With the rubber share
s_r = 1 − s_spring of F_ref at T_ref (a lip mounted at T_ref),

    F_tip(T) = F_ref·[s_spring + (1 − s_spring)·σ(T)/σ_ref],  σ_ref = E_h(T_ref)·ε(T_ref). (2)

The interference shrinks as the lip warms: rubber expands about fifteen times more than the
steel shaft, and the lip head hangs on a flexible membrane, so its ring grows nearly freely
(this is why lip seals carry a garter spring; Trelleborg's catalogue contrasts radial shaft
seals, whose "contact force decreases with the thermal volume increase", with axial ones).
Written as the lip ring's hoop pre-strain ε₀ = δ/R on a shaft of radius R,

    ε(T)/ε(T_ref) = max(0, 1 − [ε_th(T) − α_shaft·(T − T_ref)]/ε₀),               (3)

with the rubber's free thermal strain ε_th (rubbery coefficient above T_g, the glassy one of
Simha & Boyer below, the structure frozen at T_g:
:func:`~sealsim.properties.thermal_expansion.thermal_strain`).

**Wave lip.**  A wave lip's contact line z(θ) = A·sin(N·θ) (amplitude A, N waves around the
shaft of radius R) is inclined to the sliding direction by φ(θ), tan φ = (A·N/R)·cos(N·θ).  The
shaft carries oil across an inclined line with the normal velocity u·|sin φ|, which builds a
hydrodynamic wedge film on top of the plain lip's asperity-scale film: the pumping of inclined
lip features (hydrodynamic aids, Horve, *Shaft Seals for Dynamic Applications*, 1996; Müller &
Nau, *Fluid Sealing Technology*, 1998).  Both films follow the soft-EHL law h ∝ (η·u)^n, so

    h_wave/h_plain = 1 + c·⟨|sin φ(θ)|^n⟩_θ,                                     (3)

with c = 1 if the wedge film has the plain film's coefficient (sealsim's assumption; the film
factor can be set instead, e.g. calibrated).  The track of the wave spreads the frictional
heat over an axial band b + 2A.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from sealsim.properties.elastomers import Elastomer
from sealsim.properties.thermal_expansion import thermal_strain
from sealsim.tribology.film import EHL_EXPONENT

__all__ = [
    "DEFAULT_HOOP_PRESTRAIN",
    "LIP_STYLES",
    "AnalyticLipForce",
    "LipStyle",
    "default_contact_width",
    "default_outer_diameter",
    "default_radial_force",
    "default_width",
    "interference_ratio",
    "lip_force",
    "lip_mounting_note",
    "lip_stress_ratio",
    "wave_contact_angle",
    "wave_film_factor",
    "wave_lip_style",
]

#: Radial load per unit circumference of a DIN 3760 lip [N/m]: 0.15 N/mm, the middle of
#: the 100-200 N/m to which oil-seal radial forces are "generally chosen" (100-150 N/m for
#: high-speed seals; longest life near 100 N/m) in a seal maker's technical article
#: (http://chrisdelle.com/n1208105.htm, Chinese, unattributed -- a secondary source; no
#: primary split-shaft measurement, DIN 3761-9 / SAE J1901, could be read) -- 38 N on an
#: 80 mm shaft.
DEFAULT_LOAD_PER_LENGTH = 150.0

#: Hoop pre-strain of the lip ring on the shaft, ε₀ = δ/R [-]: 8 %, the strain at which the
#: ring tension of a 2.5 mm × 3 mm NBR lip head (E ≈ 5.5 MPa) carries the rubber share of the
#: default lip force, 0.55 × 0.15 N/mm × π·d = 2π·E·A·ε₀ (an estimate, any diameter).  With the
#: catalogue NBR (α = 1.9e-4 /K) on steel it loses 18 % of the interference over 80 K.
DEFAULT_HOOP_PRESTRAIN = 0.08

#: Linear thermal expansion of a steel shaft [1/K] (carbon and low-alloy steels 11-13e-6).
STEEL_EXPANSION = 12e-6


def interference_ratio(temperature, reference_temperature, hoop_prestrain, rubber_expansion,
                       shaft_expansion=STEEL_EXPANSION, glassy_expansion=None,
                       glass_transition=None):
    """Lip interference at temperature relative to the reference temperature, Eq. (3).

    Parameters
    ----------
    temperature : array_like
        Lip temperature T [K].
    reference_temperature : float
        T_ref at which the lip force is known [K].
    hoop_prestrain : float
        Hoop pre-strain of the mounted lip ring at T_ref, ε₀ = δ/R [-], > 0.
    rubber_expansion : float
        Linear thermal expansion of the lip rubber above T_g, α_rubber [1/K].
    shaft_expansion : float
        Linear thermal expansion of the shaft α_shaft [1/K].
    glassy_expansion : float, optional
        α of the glassy rubber [1/K], used below ``glass_transition`` (default: α_rubber).
    glass_transition : float, optional
        T_g [K] where the structure freezes on cooling (default: never).

    Returns
    -------
    numpy.ndarray
        δ(T)/δ(T_ref) [-], ≥ 0 (0: the rubber lifts off, only the spring presses).

    Examples
    --------
    >>> round(float(interference_ratio(373.15, 293.15, 0.08, 1.9e-4)), 3)
    0.822
    """
    t = np.asarray(temperature, dtype=float)
    fictive = None if glass_transition is None else np.maximum(t, glass_transition)
    strain = np.asarray(thermal_strain(t, reference_temperature, rubber_expansion,
                                       glassy_expansion, fictive), dtype=float)
    loss = (strain - shaft_expansion * (t - reference_temperature)) / hoop_prestrain
    return np.maximum(1.0 - loss, 0.0)


def lip_stress_ratio(interference, mounted_interference, mounted_modulus, modulus,
                     reference_modulus):
    """Stress of the lip ring relative to the reference state, σ(T)/σ_ref of Eq. (1)-(2).

    Parameters
    ----------
    interference : array_like
        ε(T)/ε(T_ref) at the lip temperature [-].
    mounted_interference : array_like
        ε(T_m)/ε(T_ref) at the mounting temperature [-].
    mounted_modulus : array_like
        E_m(T): modulus of the stress installed at T_m, brought to T [Pa].
    modulus : array_like
        E_h(T): held modulus at T, which the increment since mounting meets [Pa].
    reference_modulus : float
        E_h(T_ref) [Pa].

    Returns
    -------
    numpy.ndarray
        σ(T)/σ_ref [-], ≥ 0 (a ring that would pull off the shaft carries nothing).

    Examples
    --------
    Mounted at T_ref and cooled: the mounting stress stays (3.57 of 4.09 MPa), the 8.9 %
    extra interference meets the cold 16.5 MPa:

    >>> round(float(lip_stress_ratio(1.089, 1.0, 3.57e6, 16.5e6, 4.09e6)), 3)
    1.232
    """
    stress = np.asarray(mounted_modulus, dtype=float) * mounted_interference + np.asarray(
        modulus, dtype=float) * (np.asarray(interference, dtype=float) - mounted_interference)
    return np.maximum(stress / reference_modulus, 0.0)


def lip_force(reference_force, spring_share, modulus_ratio, interference=1.0):
    """Radial lip force at temperature, Eq. (2), for a stress ratio σ/σ_ref = modulus_ratio ×
    interference (a lip at its mounting temperature).

    Parameters
    ----------
    reference_force : array_like
        Lip force F_ref at the reference temperature [N].
    spring_share : array_like
        Share of the garter spring in F_ref [-], 0...1.
    modulus_ratio : array_like
        E(T)/E(T_ref) of the lip elastomer [-] (or the whole stress ratio σ/σ_ref).
    interference : array_like
        δ(T)/δ(T_ref), :func:`interference_ratio` [-].

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
        modulus_ratio, dtype=float) * np.asarray(interference, dtype=float))


@dataclass(frozen=True)
class AnalyticLipForce:
    """F_tip(T) from the spring share, the rubber's held modulus, its thermal expansion and the
    mounting temperature, Eq. (1)-(3).

    A lip-force source is any callable ``force(temperature [K]) -> F_tip [N]``; this is the
    analytic one.

    Parameters
    ----------
    reference_force : float
        F_ref [N] at ``reference_temperature`` of a lip mounted there.
    reference_temperature : float
        T_ref [K].
    spring_share : float
        Share of the garter spring in F_ref [-].
    elastomer : Elastomer
        Lip rubber: held modulus, thermal expansion (rubbery and glassy), T_g.
    hoop_prestrain : float
        ε₀ of Eq. (3) [-].
    shaft_expansion : float
        α of the shaft [1/K].
    mounting_temperature : float, optional
        T_m [K] at which the lip was mounted and relaxed; default ``reference_temperature``.

    Examples
    --------
    >>> from sealsim.properties.elastomers import get_elastomer
    >>> force = AnalyticLipForce(37.7, 293.15, 0.45, get_elastomer("NBR"), 0.08, 12e-6)
    >>> round(float(force(293.15)), 2), round(float(force(373.15)), 1)
    (37.7, 33.5)

    Cooled to −20 °C after mounting at 20 °C, against a lip mounted at −20 °C:

    >>> cold = AnalyticLipForce(37.7, 293.15, 0.45, get_elastomer("NBR"), 0.08, 12e-6, 253.15)
    >>> round(float(force(253.15)), 1), round(float(cold(253.15)), 1)
    (42.5, 107.9)
    """

    reference_force: float
    reference_temperature: float
    spring_share: float
    elastomer: Elastomer
    hoop_prestrain: float = DEFAULT_HOOP_PRESTRAIN
    shaft_expansion: float = STEEL_EXPANSION
    mounting_temperature: float | None = None

    @property
    def mounted_at(self) -> float:
        """T_m [K]."""
        return (self.reference_temperature if self.mounting_temperature is None
                else self.mounting_temperature)

    def interference(self, temperature):
        """ε(T)/ε(T_ref), Eq. (3)."""
        e = self.elastomer
        return interference_ratio(temperature, self.reference_temperature, self.hoop_prestrain,
                                  e.thermal_expansion, self.shaft_expansion,
                                  e.glassy_expansion, e.glass_transition)

    # the two constants of Eq. (1)-(2), computed once: a transient run asks for the lip force
    # at every time step
    @cached_property
    def _reference_modulus(self) -> float:
        return float(self.elastomer.held_modulus(self.reference_temperature))

    @cached_property
    def _mounted_interference(self) -> float:
        return float(self.interference(self.mounted_at))

    def stress_ratio(self, temperature):
        """σ(T)/σ_ref of Eq. (1)-(2)."""
        return self._stress_ratio_and_held_modulus(temperature)[0]

    def _stress_ratio_and_held_modulus(self, temperature):
        t = np.asarray(temperature, dtype=float)
        # lip force on the reference lip of the case (mounted at T_ref): mounted_interference 1
        # when T_m = T_ref; the held stress at T_m otherwise
        mounted, held = self.elastomer.mounted_and_held_modulus(t, self.mounted_at)
        return lip_stress_ratio(self.interference(t), self._mounted_interference, mounted, held,
                                self._reference_modulus), held

    def __call__(self, temperature):
        return lip_force(self.reference_force, self.spring_share, self.stress_ratio(temperature))

    def force_and_held_modulus(self, temperature):
        """F_tip(T) [N] and the held modulus E_h(T) [Pa] of the elastomer that Eq. (1) met on
        the way: a friction model that needs both (the film law's lip modulus) takes them from
        one evaluation."""
        ratio, held = self._stress_ratio_and_held_modulus(temperature)
        return lip_force(self.reference_force, self.spring_share, ratio), held


def lip_mounting_note(lowest_temperature: float, mounting_temperature: float,
                      history: bool = True) -> str:
    """Which case the lip force of a run is, when the lip ran colder than it was mounted.

    Parameters
    ----------
    lowest_temperature : float
        Lowest lip (contact) temperature of the run [K].
    mounting_temperature : float
        T_m [K].
    history : bool
        True: the lip force follows the mounting path (analytic Eq. 1, or the viscoelastic FE
        load path); False: it is that of a lip mounted at each temperature (the hyperelastic FE
        of a rubber without a Prony series), an upper bound below T_m.

    Returns
    -------
    str
        The note, or "" when the lip never ran more than 1 K below T_m.

    Examples
    --------
    >>> lip_mounting_note(300.0, 293.15)
    ''
    >>> lip_mounting_note(253.15, 293.15)[:47]
    'lip mounted at 20 degC and cooled to -20 degC: '
    """
    if lowest_temperature >= mounting_temperature - 1.0:
        return ""
    head = (f"lip mounted at {mounting_temperature - 273.15:.0f} degC and cooled to "
            f"{lowest_temperature - 273.15:.0f} degC: ")
    if history:
        return head + ("its stress relaxed at the mounting temperature and only the thermal "
                       "contraction since meets the stiffer cold rubber (lip force of the "
                       "mounting path, rotary/lip.py Eq. 1)")
    return head + ("the FE lip force below the mounting temperature is that of a lip mounted "
                   "cold (this rubber has no Prony series for the mounting path), an upper "
                   "bound")


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

    New lips touch over 0.1-0.2 mm, run-in lips over 0.2-0.5 mm (contact widths measured
    before and after an endurance run in Lubricants 12(4), 103, 2024); Organisciak et al.
    (SKF, AGMA 14FTM14, 2014) validate with run-in seals, so sealsim uses a value at the
    lower end of run-in.

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


def wave_contact_angle(amplitude, waves, shaft_diameter, angle):
    """Inclination φ of a wave lip's contact line to the sliding direction at angle θ.

    tan φ = (A·N/R)·cos(N·θ) for the contact line z = A·sin(N·θ) on a shaft of radius R.

    Parameters
    ----------
    amplitude : float
        Axial amplitude A of the contact line [m].
    waves : float
        Number of waves N around the circumference [-].
    shaft_diameter : float
        D = 2R [m].
    angle : array_like
        Circumferential position θ [rad].

    Returns
    -------
    numpy.ndarray
        φ [rad], signed.

    Examples
    --------
    >>> round(float(np.degrees(wave_contact_angle(0.5e-3, 8, 0.08, 0.0))), 2)
    5.71
    """
    slope = amplitude * waves / (shaft_diameter / 2.0)
    return np.arctan(slope * np.cos(waves * np.asarray(angle, dtype=float)))


def wave_film_factor(amplitude, waves, shaft_diameter, exponent=EHL_EXPONENT,
                     wedge_coefficient=1.0):
    """Film of a wave lip relative to a plain lip, Eq. (3): 1 + c·⟨|sin φ|^n⟩.

    Parameters
    ----------
    amplitude : float
        Axial amplitude A of the contact line [m].
    waves : float
        Number of waves N [-].
    shaft_diameter : float
        D [m].
    exponent : float
        Exponent n of the film law [-].
    wedge_coefficient : float
        c: film coefficient of the inclined-line wedge relative to the plain lip's [-].

    Returns
    -------
    float
        h_wave/h_plain [-] (1 for a zero amplitude).

    Examples
    --------
    >>> round(wave_film_factor(0.5e-3, 8, 0.08), 3)
    1.156
    """
    theta = (np.arange(720) + 0.5) * (2.0 * np.pi / 720) / max(waves, 1e-12)  # one wave
    phi = wave_contact_angle(amplitude, waves, shaft_diameter, theta)
    return float(1.0 + wedge_coefficient * np.mean(np.abs(np.sin(phi)) ** exponent))


#: Wave lip geometry defaults (assumptions; Organisciak et al. 2014, Fig. 11 shows the
#: sinusoidal track but is not legible): amplitude 0.5 mm (a track several contact widths wide)
#: and 8 waves, i.e. a contact line inclined by up to 5.7° on an 80 mm shaft.
DEFAULT_WAVE_AMPLITUDE = 0.5e-3
DEFAULT_WAVES = 8


def wave_lip_style(shaft_diameter, amplitude=DEFAULT_WAVE_AMPLITUDE, waves=DEFAULT_WAVES,
                   film_factor=None, lip_heat_exchange_factor=1.0) -> LipStyle:
    """The wave lip style of a seal: film factor from the geometry unless one is given.

    Parameters
    ----------
    shaft_diameter : float
        D [m].
    amplitude : float
        Axial amplitude of the contact line [m].
    waves : float
        Number of waves [-].
    film_factor : float, optional
        h_wave/h_plain [-]; default :func:`wave_film_factor` of the geometry.
    lip_heat_exchange_factor : float
        Multiplier of the lip's oil-side heat transfer coefficient [-]; default 1: the oil
        the wave pumps along its contact line, ≈ u·h/2·⟨|sin φ cos φ|⟩ per unit length
        (≈ 20 mm³/s on an 80 mm shaft at 1000 rpm), carries 0.04 W/K, negligible against
        conduction into the shaft, so no extra exchange is derived (calibratable).

    Returns
    -------
    LipStyle

    Examples
    --------
    >>> wave_lip_style(0.08).film_factor == wave_film_factor(0.5e-3, 8, 0.08)
    True
    """
    if film_factor is None:
        film_factor = wave_film_factor(amplitude, waves, shaft_diameter)
    return LipStyle("wave", film_factor, amplitude, lip_heat_exchange_factor)


#: The plain lip: the reference of the film law and of the heat exchange.
LIP_STYLES = {"plain": LipStyle("plain", film_factor=1.0, track_amplitude=0.0,
                                lip_heat_exchange_factor=1.0)}
