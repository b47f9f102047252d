"""Rubber friction master curve (Grosch 1963).

Grosch (Proc. R. Soc. A 274 (1963) 21) measured the friction of rubbers on glass and silicon
carbide over wide ranges of speed and temperature and showed that all curves collapse onto one
master curve against log10(a_T·v), with a_T the WLF shift factor of the rubber: friction is a
viscoelastic loss process.  Each curve is a bell in log(a_T·v) whose peak lies where the
sliding excites the rubber at the frequency f_max of its loss peak, v_max = λ·f_max.  On smooth
glass λ ≈ 6 nm (adhesion); on rough silicon carbide λ is of the order of the asperity spacing
(≈ 0.15 mm) and the peak is the hysteresis peak of the rubber deformed by the asperities.

In an oil-wetted lip contact the adsorbed oil suppresses adhesion; what remains is the
hysteresis of the lip rubber dynamically deformed by the shaft's asperities (Organisciak et al.'s
"viscoelastic losses").  sealsim therefore places the peak at the hysteresis speed
:func:`hysteresis_peak_speed`, v_max = λ·f_max with λ the shaft's asperity wavelength, and
represents the curve by a Gaussian bell in log10 of the reduced speed,

    μ(v, T) = μ_low + (μ_peak − μ_low)·exp(−½·[log10(a_T·v / v_peak,ref) / w]²),   (1)

where v_peak,ref = λ·f_max,ref is the peak speed at the WLF reference temperature, w the
half-width in decades and μ_low the boundary-lubricated friction far from the peak.  With the
catalogue elastomers the hysteresis peak lies at tens of m/s at room temperature and moves to
higher speeds as the rubber warms (a_T falls), so at lip seal speeds μ falls with temperature:
the feedback of friction on the contact temperature is stabilising.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["DEFAULT_MASTER_CURVE", "GroschMasterCurve", "grosch_friction_coefficient",
           "hysteresis_peak_speed", "loss_peak_frequency"]

#: Grosch's ratio of adhesion-peak speed to loss-peak frequency on smooth glass, λ ≈ 6 nm.
GROSCH_ADHESION_LENGTH = 6e-9  # m
#: Asperity wavelength of a ground shaft that the lip rubber is excited by [m]: 50 µm, the
#: spacing of grinding marks of Ra 0.2-0.8 µm shafts (Grosch's silicon carbide track, a coarser
#: surface: ≈ 0.15 mm).
DEFAULT_ASPERITY_WAVELENGTH = 50e-6
#: Loss-peak frequency of the catalogue elastomers at their WLF reference temperature [Hz]
#: (the inflection of their storage-modulus master curve, 10^-2 Hz).
CATALOGUE_LOSS_PEAK_FREQUENCY = 0.01


def loss_peak_frequency(elastomer) -> float:
    """Loss-peak frequency f_max of an elastomer at its WLF reference temperature [Hz].

    The inflection of its storage-modulus master curve (``transition_location``, log10 Hz): by
    the Kramers–Kronig approximation tan δ ≈ (π/2)·d ln E′/d ln f (Booij & Thoone, Rheol. Acta
    21 (1982) 15) the loss tangent peaks where E′ rises fastest.

    Parameters
    ----------
    elastomer : sealsim.properties.elastomers.Elastomer
        The rubber.

    Returns
    -------
    float
        f_max [Hz].

    Examples
    --------
    >>> from sealsim.properties.elastomers import get_elastomer
    >>> loss_peak_frequency(get_elastomer("NBR"))
    0.01
    """
    return float(10.0 ** elastomer.transition_location)


def hysteresis_peak_speed(asperity_wavelength, loss_peak_frequency):
    """Speed of the hysteresis friction peak, v_max = λ·f_max (Grosch 1963).

    Parameters
    ----------
    asperity_wavelength : array_like
        Wavelength λ of the counterface roughness that deforms the rubber [m].
    loss_peak_frequency : array_like
        Frequency of the rubber's loss peak f_max at the reference temperature of the shift
        factor [Hz].

    Returns
    -------
    numpy.ndarray
        v_max at that reference temperature [m/s].

    Examples
    --------
    >>> float(hysteresis_peak_speed(50e-6, 0.01))
    5e-07
    """
    return np.asarray(asperity_wavelength, dtype=float) * np.asarray(loss_peak_frequency,
                                                                      dtype=float)


@dataclass(frozen=True)
class GroschMasterCurve:
    """Parameters of the bell-shaped master curve, Eq. (1).

    Parameters
    ----------
    mu_peak : float
        Friction coefficient at the peak [-].
    mu_low : float
        Friction coefficient far from the peak [-].
    peak_speed_reference : float
        Speed of the peak at the WLF reference temperature (a_T = 1) [m/s].
    width_decades : float
        Standard deviation of the bell in decades of reduced speed [-].
    """

    mu_peak: float
    mu_low: float
    peak_speed_reference: float
    width_decades: float


#: Default master curve for the ``μ_dry`` of Organisciak et al. (2014) Eq. 3 (reasoning, not a
#: fit):
#:
#: * μ_peak = 1.0: the hysteresis peak of nitrile rubber on a rough track, the lower end of the
#:   1-1.5 Grosch (1963) found on silicon carbide, the oil removing adhesion;
#: * μ_low = 0.2: boundary-lubricated rubber on steel far from the peak, the middle of
#:   0.1-0.3 (handbook range);
#: * peak at λ·f_max = 50 µm × 0.01 Hz at the WLF reference temperature (Tg for the
#:   catalogue): a catalogue NBR peaks at about 70 m/s at 20 °C and 2e5 m/s at 80 °C, so lip
#:   seal speeds lie on the rubbery flank, where μ falls as the rubber warms;
#: * a width of 2 decades: a hysteresis peak is broader than the adhesion peak, about as
#:   broad as the loss peak of a filled rubber widened by the spread of roughness wavelengths
#:   (an assumption: a full width at half maximum of about 5 decades).
DEFAULT_MASTER_CURVE = GroschMasterCurve(
    mu_peak=1.0, mu_low=0.2,
    peak_speed_reference=float(hysteresis_peak_speed(DEFAULT_ASPERITY_WAVELENGTH,
                                                     CATALOGUE_LOSS_PEAK_FREQUENCY)),
    width_decades=2.0)


def grosch_friction_coefficient(speed, log10_shift_factor, curve=DEFAULT_MASTER_CURVE):
    """Rubber friction coefficient from the WLF-shifted master curve, Eq. (1).

    Parameters
    ----------
    speed : array_like
        Sliding speed v [m/s]; its magnitude is used, v = 0 gives μ_low.
    log10_shift_factor : array_like
        log10 a_T of the rubber at the contact temperature [-] (WLF, referred to the same
        reference temperature as ``curve.peak_speed_reference``).
    curve : GroschMasterCurve
        Master curve parameters.

    Returns
    -------
    numpy.ndarray
        μ [-], between ``mu_low`` and ``mu_peak``.

    Examples
    --------
    >>> # NBR at 20 °C and 80 °C (log10 a_T = -8.1, -11.7 with universal WLF at Tg = -25 °C)
    >>> round(float(grosch_friction_coefficient(4.0, -8.1)), 2)
    0.87
    >>> round(float(grosch_friction_coefficient(4.0, -11.7)), 2)
    0.25
    """
    v = np.abs(np.asarray(speed, dtype=float))
    with np.errstate(divide="ignore"):
        x = np.log10(v) + np.asarray(log10_shift_factor, dtype=float) - np.log10(
            curve.peak_speed_reference)
    bell = np.exp(-0.5 * (x / curve.width_decades) ** 2)
    bell = np.where(v > 0, bell, 0.0)
    return curve.mu_low + (curve.mu_peak - curve.mu_low) * bell
