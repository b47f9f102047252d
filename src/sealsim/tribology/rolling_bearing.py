r"""Friction heat of the rolling bearing beside a lip seal (Palmgren), and its default size.

In a gear unit the seal sits in the bearing cap, next to the shaft's bearing: the bearing's
friction heats the shaft a few centimetres from the lip contact.  Palmgren's load-independent
(viscous) frictional moment of a rolling bearing is

.. math::

    M_0 = 10^{-7} f_0 (\nu n)^{2/3} d_m^3 \quad (\nu n \ge 2000), \qquad
    M_0 = 160\cdot 10^{-7} f_0\,d_m^3 \quad (\nu n < 2000)

with M_0 in N·mm, ν the oil's kinematic viscosity in mm²/s, n the speed in rpm, d_m the
bearing's pitch diameter in mm and f_0 a factor of bearing type and lubrication: 2 for a
deep-groove ball bearing in an oil bath (A. Palmgren, *Ball and Roller Bearing Engineering*,
3rd ed., Burbank 1959; T. A. Harris & M. N. Kotzalas, *Essential Concepts of Bearing
Technology*, 5th ed., CRC 2007, ch. 9 [L]).  The load-dependent moment M_1 = f_1·P_1·d_m needs
the bearing load of the application and is not part of the default: the heat is then a lower
bound (give the measured or computed bearing power instead).

The bearing's default size is the ISO 15 dimension series 02 deep-groove ball bearing (62xx)
whose bore is the shaft diameter: pitch diameter d_m = (d + D)/2 and width B from the ISO 15
dimension plan (table below, linear between the bores listed, proportional outside).

SI inside: kinematic viscosity in m²/s, angular speed in rad/s, lengths in m, moments in N·m.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "DEEP_GROOVE_OIL_BATH_F0",
    "SERIES_62",
    "palmgren_viscous_moment",
    "series_62_bearing",
]

#: Palmgren's f_0 of a deep-groove ball bearing lubricated by an oil bath (Palmgren 1959;
#: Harris & Kotzalas 2007, ch. 9 [L]).
DEEP_GROOVE_OIL_BATH_F0 = 2.0

#: Deep-groove ball bearings of the ISO 15 dimension series 02 (62xx): bore d, outer diameter
#: D and width B [mm].
SERIES_62 = ((10, 30, 9), (12, 32, 10), (15, 35, 11), (17, 40, 12), (20, 47, 14), (25, 52, 15),
             (30, 62, 16), (35, 72, 17), (40, 80, 18), (45, 85, 19), (50, 90, 20),
             (55, 100, 21), (60, 110, 22), (65, 120, 23), (70, 125, 24), (75, 130, 25),
             (80, 140, 26), (85, 150, 28), (90, 160, 30), (95, 170, 32), (100, 180, 34),
             (105, 190, 36), (110, 200, 38), (120, 215, 40), (130, 230, 40), (140, 250, 42),
             (150, 270, 45))


def series_62_bearing(shaft_diameter: float) -> tuple[float, float]:
    """Pitch diameter and width of the 62xx bearing with the shaft's bore (ISO 15 series 02).

    Parameters
    ----------
    shaft_diameter : float
        Bore d [m].

    Returns
    -------
    pitch_diameter, width : float
        d_m = (d + D)/2 and B [m]; between the listed bores D and B are interpolated
        linearly, outside 10-150 mm scaled with D/d and B/d of the nearest end.

    Examples
    --------
    >>> [round(x * 1e3, 1) for x in series_62_bearing(0.08)]
    [110.0, 26.0]
    """
    d_mm = shaft_diameter * 1e3
    bore, outer, width = (np.array(c, dtype=float) for c in zip(*SERIES_62))
    if bore[0] <= d_mm <= bore[-1]:
        outer_mm = float(np.interp(d_mm, bore, outer))
        width_mm = float(np.interp(d_mm, bore, width))
    else:
        k = 0 if d_mm < bore[0] else -1
        outer_mm = d_mm * outer[k] / bore[k]
        width_mm = d_mm * width[k] / bore[k]
    return 0.5 * (d_mm + outer_mm) * 1e-3, width_mm * 1e-3


def palmgren_viscous_moment(kinematic_viscosity, angular_speed, pitch_diameter,
                            f0=DEEP_GROOVE_OIL_BATH_F0):
    """Palmgren's load-independent frictional moment M_0 of a rolling bearing.

    Parameters
    ----------
    kinematic_viscosity : array_like
        ν of the oil at the bearing [m²/s].
    angular_speed : array_like
        ω of the shaft [rad/s] (its magnitude is used).
    pitch_diameter : float
        d_m [m].
    f0 : float
        Factor of bearing type and lubrication [-] (2: deep-groove ball bearing, oil bath).

    Returns
    -------
    numpy.ndarray
        M_0 [N·m], ≥ 0 (0 at standstill).

    Examples
    --------
    6216 bearing (d_m = 110 mm) at 1000 rpm in VG 68 at 80 °C (14.7 mm²/s): 0.16 N·m, 17 W.

    >>> m = palmgren_viscous_moment(14.7e-6, 1000 * math.pi / 30, 0.110)
    >>> round(float(m), 3), round(float(m) * 1000 * math.pi / 30, 1)
    (0.16, 16.7)
    """
    nu_n = np.asarray(kinematic_viscosity, dtype=float) * 1e6 * np.abs(
        np.asarray(angular_speed, dtype=float)) * 30.0 / math.pi
    dm3 = (pitch_diameter * 1e3) ** 3
    moment_nmm = np.where(nu_n >= 2000.0, 1e-7 * f0 * np.cbrt(nu_n) ** 2 * dm3,
                          160e-7 * f0 * dm3)
    return np.where(nu_n > 0.0, moment_nmm * 1e-3, 0.0)
