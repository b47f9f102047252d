"""Rubber friction master curve (Grosch 1963).

Grosch (Proc. R. Soc. A 274 (1963) 21) measured the friction of rubbers on glass and silicon
carbide over wide ranges of speed and temperature and showed that all curves collapse onto one
master curve against log10(a_T·v), with a_T the WLF shift factor of the rubber: friction is a
viscoelastic loss process.  On smooth counterfaces the curve is a bell in log(a_T·v) whose peak
lies at the speed v_max ≈ λ·f_max, where f_max is the frequency of the loss-modulus peak and
λ ≈ 6 nm (the adhesion length Grosch found); on rough surfaces a second, hysteresis peak appears
at v ≈ (asperity spacing)·f_max.

sealsim represents the curve by a Gaussian bell in log10 of the reduced speed,

    μ(v, T) = μ_low + (μ_peak − μ_low)·exp(−½·[log10(a_T·v / v_peak,ref) / w]²),   (1)

where v_peak,ref = λ·f_max,ref is the peak speed at the WLF reference temperature, w the
half-width in decades and μ_low the friction far from the peak.  The defaults describe the
adhesion peak of a nitrile-type rubber on a ground steel shaft in a boundary-lubricated contact
(see :data:`DEFAULT_MASTER_CURVE`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["DEFAULT_MASTER_CURVE", "GroschMasterCurve", "grosch_friction_coefficient"]

#: Grosch's ratio of peak sliding speed to loss-peak frequency, λ ≈ 6 nm.
GROSCH_ADHESION_LENGTH = 6e-9  # m


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


#: Default master curve for the ``μ_dry`` of seed 000 Eq. 3 (reasoning, not a fit):
#:
#: * μ_peak = 1.0, μ_low = 0.3: NBR on smooth dry steel ≈ 0.6--1.0, boundary-lubricated
#:   rubber 0.1--0.3 (reference notes §4, §6.3);
#: * peak speed λ·f_max at the WLF reference temperature Tg: λ = 6 nm (Grosch) and a loss peak
#:   at 0.01 Hz at the calorimetric Tg (a relaxation time of ≈ 100 s defines the DSC glass
#:   transition, Ferry, *Viscoelastic Properties of Polymers*, 1980).  With universal WLF
#:   constants this puts the peak of an NBR (Tg −25 °C) at ≈ 1--2 cm/s at 20 °C, the order of
#:   Grosch's measured adhesion peaks at room temperature;
#: * a width of 1.5 decades: Grosch's curves fall from the peak to about a third over
#:   2--3 decades.
DEFAULT_MASTER_CURVE = GroschMasterCurve(
    mu_peak=1.0, mu_low=0.3, peak_speed_reference=GROSCH_ADHESION_LENGTH * 0.01,
    width_decades=1.5)


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
    >>> # NBR at 20 °C (log10 a_T = -8.1 with universal WLF at Tg = -25 °C)
    >>> round(float(grosch_friction_coefficient(0.01, -8.1)), 2)
    1.0
    >>> round(float(grosch_friction_coefficient(10.0, -8.1)), 2)
    0.38
    """
    v = np.abs(np.asarray(speed, dtype=float))
    with np.errstate(divide="ignore"):
        x = np.log10(v) + np.asarray(log10_shift_factor, dtype=float) - np.log10(
            curve.peak_speed_reference)
    bell = np.exp(-0.5 * (x / curve.width_decades) ** 2)
    bell = np.where(v > 0, bell, 0.0)
    return curve.mu_low + (curve.mu_peak - curve.mu_low) * bell
