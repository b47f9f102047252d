"""Convective heat transfer coefficients for shafts, seals and housings.

Sources: Incropera, DeWitt, Bergman & Lavine, *Fundamentals of Heat and Mass Transfer*, 6th ed.
(2007): rotating cylinder (Kays & Bjorklund 1958, §7.8), horizontal cylinder in free convection
(Churchill & Chu 1975, Eq. 9.34), vertical plate (Churchill & Chu 1975, Eq. 9.26); linearised
grey-body radiation.  Rotating shaft in a stationary annulus (Taylor–Couette flow): Staton &
Cavagnino, IEEE Trans. Ind. Electron. 55 (2008) 3509, Eq. 21–23, the correlations from Taylor's
tests on smooth concentric cylinders (reviewed by Fénot et al., Int. J. Therm. Sci. 50 (2011)
1138, and Howey, Childs & Holmes, IEEE Trans. Ind. Electron. 59 (2012) 1367).  Air properties
are evaluated from simple fits valid 250--400 K.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "STEFAN_BOLTZMANN",
    "air_properties",
    "annulus_wall_coefficient",
    "free_convection_horizontal_cylinder",
    "free_convection_vertical_plate",
    "radiation_coefficient",
    "rayleigh_number",
    "rotating_annulus_coefficient",
    "rotating_annulus_nusselt",
    "rotating_cylinder_coefficient",
    "rotating_cylinder_nusselt",
    "taylor_number",
]

STEFAN_BOLTZMANN = 5.670374419e-8  # W/(m² K⁴)
GRAVITY = 9.80665  # m/s²


def rotating_cylinder_nusselt(reynolds, prandtl):
    """Nusselt number of a cylinder rotating in a quiescent fluid (Kays & Bjorklund).

    ``Nu_D = 0.133·Re_D^(2/3)·Pr^(1/3)``, Re_D = Ω·D²/ν, stated for Re_D < 4.3e5 and
    0.7 < Pr < 670 (Incropera §7.8).  sealsim also uses it for Pr up to a few thousand
    (cold gear oil); the Pr^(1/3) dependence is the laminar-boundary-layer scaling.

    Parameters
    ----------
    reynolds : array_like
        Rotational Reynolds number Ω·D²/ν [-].
    prandtl : array_like
        Prandtl number of the fluid [-].

    Returns
    -------
    numpy.ndarray
        Nu_D [-].

    Examples
    --------
    >>> round(float(rotating_cylinder_nusselt(6.8e4, 190)), 0)
    1274.0
    """
    re = np.maximum(np.asarray(reynolds, dtype=float), 0.0)
    return 0.133 * re ** (2.0 / 3.0) * np.asarray(prandtl, dtype=float) ** (1.0 / 3.0)


def rotating_cylinder_coefficient(angular_speed, diameter, kinematic_viscosity, conductivity,
                                  prandtl):
    """Heat transfer coefficient of a rotating shaft, h = Nu_D·k/D with Kays & Bjorklund.

    Parameters
    ----------
    angular_speed : array_like
        Ω [rad/s] (its magnitude is used).
    diameter : float
        Shaft diameter D [m].
    kinematic_viscosity : array_like
        ν of the fluid [m²/s].
    conductivity : array_like
        k of the fluid [W/(m·K)].
    prandtl : array_like
        Pr of the fluid [-].

    Returns
    -------
    numpy.ndarray
        h [W/(m²·K)].

    Examples
    --------
    >>> round(float(rotating_cylinder_coefficient(157.1, 0.08, 1.48e-5, 0.127, 190)), -1)
    2020.0
    """
    re = np.abs(np.asarray(angular_speed, dtype=float)) * diameter**2 / np.asarray(
        kinematic_viscosity, dtype=float)
    return rotating_cylinder_nusselt(re, prandtl) * np.asarray(conductivity, dtype=float) / diameter


def taylor_number(angular_speed, inner_radius, gap, kinematic_viscosity):
    """Taylor number of the flow in an annulus around a rotating shaft (Staton & Cavagnino Eq. 21).

    ``Ta = Re·√(δ/R)``, ``Re = δ·u/ν`` with the gap δ, the shaft radius R and its surface speed
    u = Ω·R; the outer cylinder stands still.

    Parameters
    ----------
    angular_speed : array_like
        Ω of the inner cylinder [rad/s] (its magnitude is used).
    inner_radius : float
        R [m].
    gap : float
        Radial width δ of the annulus [m], > 0.
    kinematic_viscosity : array_like
        ν of the fluid [m²/s].

    Returns
    -------
    numpy.ndarray
        Ta [-].

    Examples
    --------
    >>> round(float(taylor_number(104.7, 0.04, 0.0105, 1.47e-5)))
    1533
    """
    speed = np.abs(np.asarray(angular_speed, dtype=float)) * inner_radius
    reynolds = gap * speed / np.asarray(kinematic_viscosity, dtype=float)
    return reynolds * np.sqrt(gap / inner_radius)


def rotating_annulus_nusselt(taylor, prandtl):
    """Nusselt number across an annulus with a rotating inner cylinder (Taylor–Couette flow).

    Staton & Cavagnino (2008) Eq. 21–23, from Taylor's tests on smooth concentric cylinders,
    with Nu = h·(2δ)/k based on the hydraulic diameter 2δ of the gap:

    * Ta < 41, laminar Couette flow: Nu = 2 (conduction across the gap);
    * 41 ≤ Ta < 100, Taylor vortices: Nu = 0.202·Ta^0.63·Pr^0.27;
    * Ta ≥ 100, turbulent: Nu = 0.386·Ta^0.5·Pr^0.27.

    sealsim applies it to gear oil (Pr 10²–10³); the Pr^0.27 factor is the correlation's
    own fluid dependence, extrapolated beyond the gases and liquids it was measured with.
    Taylor's annuli were long (length ≫ gap); the ``gearbox`` set-up's annulus between seal
    and bearing is half as long as its gap, an end-wall cavity, where it is an extrapolation
    too (there of little weight: its coefficient ×¼ … ×4 moves the 80 mm contact at 1000 rpm
    by +0.3 … −0.8 K; docs/guide/validation_rotary.md, finding 1).

    Parameters
    ----------
    taylor : array_like
        Ta of :func:`taylor_number` [-].
    prandtl : array_like
        Pr of the fluid [-].

    Returns
    -------
    numpy.ndarray
        Nu [-].

    Examples
    --------
    >>> [round(float(rotating_annulus_nusselt(ta, 1.0)), 2) for ta in (20.0, 60.0, 400.0)]
    [2.0, 2.66, 7.72]
    """
    ta = np.asarray(taylor, dtype=float)
    pr = np.asarray(prandtl, dtype=float) ** 0.27
    vortex = 0.202 * np.maximum(ta, 0.0) ** 0.63 * pr
    turbulent = 0.386 * np.sqrt(np.maximum(ta, 0.0)) * pr
    return np.where(ta < 41.0, 2.0, np.where(ta < 100.0, vortex, turbulent))


def rotating_annulus_coefficient(angular_speed, inner_diameter, gap, kinematic_viscosity,
                                 conductivity, prandtl):
    """Heat transfer coefficient of a shaft rotating in a fluid-filled annulus, h = Nu·k/(2δ).

    :func:`rotating_annulus_nusselt` at :func:`taylor_number`; the same h applies to the
    stationary outer wall.

    Parameters
    ----------
    angular_speed : array_like
        Ω [rad/s].
    inner_diameter : float
        Shaft diameter D [m].
    gap : float
        Radial width δ of the annulus [m].
    kinematic_viscosity : array_like
        ν of the fluid [m²/s].
    conductivity : array_like
        k of the fluid [W/(m·K)].
    prandtl : array_like
        Pr of the fluid [-].

    Returns
    -------
    numpy.ndarray
        h [W/(m²·K)].

    Examples
    --------
    80 mm shaft at 1000 rpm in VG 68 at 80 °C, 10.5 mm annulus (a DIN 3760 seal's bore):

    >>> round(float(rotating_annulus_coefficient(104.7, 0.08, 0.0105, 1.47e-5, 0.127, 190)), -1)
    380.0
    """
    ta = taylor_number(angular_speed, inner_diameter / 2.0, gap, kinematic_viscosity)
    return rotating_annulus_nusselt(ta, prandtl) * np.asarray(conductivity, dtype=float) / (
        2.0 * gap)


def annulus_wall_coefficient(across, inner_diameter, gap):
    """Heat transfer coefficient of each wall of an annulus to the oil between them.

    :func:`rotating_annulus_coefficient` is the coefficient *across* the gap, from the inner
    cylinder to the outer one (Staton & Cavagnino 2008: heat transfer across the air gap, rotor
    to stator; its laminar Nu = 2 is conduction from wall to wall).  Where the fluid in the gap
    is a node of its own (the sump's oil, at its bulk temperature), the heat crosses two wall
    layers in series.  With the same coefficient h_w on both walls (the mixed core halfway
    between them on a thin gap),

    ``1/(h_w·A_i) + 1/(h_w·A_o) = 1/(h_across·A_i)``  →  ``h_w = h_across·(1 + R_i/R_o)``,

    so shaft → oil → bore gives back the across-gap conductance of the correlation.

    Parameters
    ----------
    across : array_like
        Coefficient across the gap, per inner-cylinder area [W/(m²·K)].
    inner_diameter : float
        Shaft diameter D [m].
    gap : float
        Radial width δ of the annulus [m], > 0.

    Returns
    -------
    numpy.ndarray
        h_w [W/(m²·K)], of either wall to the fluid.

    Examples
    --------
    80 mm shaft, 10.5 mm annulus: R_i/R_o = 40/50.5.

    >>> round(float(annulus_wall_coefficient(380.0, 0.08, 0.0105)), 1)
    681.0
    """
    radius = inner_diameter / 2.0
    return np.asarray(across, dtype=float) * (1.0 + radius / (radius + gap))


def rayleigh_number(length, delta_t, kinematic_viscosity, diffusivity, expansion):
    """Rayleigh number Ra = g·β·|ΔT|·L³/(ν·α) of free convection (Incropera Eq. 9.25).

    Parameters
    ----------
    length : float
        Characteristic length L [m].
    delta_t : array_like
        |T_surface − T_fluid| [K].
    kinematic_viscosity, diffusivity : array_like
        ν and α of the fluid [m²/s].
    expansion : array_like
        Volumetric expansion coefficient β [1/K].

    Returns
    -------
    numpy.ndarray
        Ra [-].

    Examples
    --------
    >>> f"{float(rayleigh_number(0.1, 10.0, 1.6e-5, 2.2e-5, 1/300)):.3g}"
    '9.29e+05'
    """
    return (GRAVITY * length**3 * np.multiply(expansion, np.abs(delta_t))
            / np.multiply(kinematic_viscosity, diffusivity))


def free_convection_horizontal_cylinder(diameter, delta_t, kinematic_viscosity, diffusivity,
                                        conductivity, expansion):
    """Free convection from a horizontal cylinder, Churchill & Chu (Incropera Eq. 9.34).

    ``Nu = {0.60 + 0.387·Ra^(1/6) / [1 + (0.559/Pr)^(9/16)]^(8/27)}²``, Ra = gβΔT D³/(να).

    Parameters
    ----------
    diameter : float
        D [m].
    delta_t : array_like
        |T_surface − T_fluid| [K].
    kinematic_viscosity, diffusivity : array_like
        ν and α of the fluid [m²/s].
    conductivity : array_like
        k of the fluid [W/(m·K)].
    expansion : array_like
        Volumetric expansion coefficient β [1/K].

    Returns
    -------
    numpy.ndarray
        h [W/(m²·K)].

    Examples
    --------
    >>> nu, alpha, k = air_properties(300.0)[:3]
    >>> round(float(free_convection_horizontal_cylinder(0.08, 20.0, nu, alpha, k, 1/300)), 1)
    4.7
    """
    ra = rayleigh_number(diameter, delta_t, kinematic_viscosity, diffusivity, expansion)
    pr = np.divide(kinematic_viscosity, diffusivity)
    nusselt = (0.60 + 0.387 * ra ** (1 / 6) / (1 + (0.559 / pr) ** (9 / 16)) ** (8 / 27)) ** 2
    return nusselt * np.divide(conductivity, diameter)


def free_convection_vertical_plate(height, delta_t, kinematic_viscosity, diffusivity,
                                   conductivity, expansion):
    """Free convection from a vertical plate, Churchill & Chu (Incropera Eq. 9.26).

    ``Nu_L = {0.825 + 0.387·Ra^(1/6) / [1 + (0.492/Pr)^(9/16)]^(8/27)}²``.

    Parameters
    ----------
    height : float
        Plate height L [m].
    delta_t : array_like
        |T_surface − T_fluid| [K].
    kinematic_viscosity, diffusivity : array_like
        ν and α [m²/s].
    conductivity : array_like
        k [W/(m·K)].
    expansion : array_like
        β [1/K].

    Returns
    -------
    numpy.ndarray
        h [W/(m²·K)].

    Examples
    --------
    >>> nu, alpha, k = air_properties(313.0)[:3]
    >>> round(float(free_convection_vertical_plate(0.3, 40.0, nu, alpha, k, 1/313)), 1)
    5.2
    """
    ra = rayleigh_number(height, delta_t, kinematic_viscosity, diffusivity, expansion)
    pr = np.asarray(kinematic_viscosity, dtype=float) / np.asarray(diffusivity, dtype=float)
    nusselt = (0.825 + 0.387 * ra ** (1 / 6) / (1 + (0.492 / pr) ** (9 / 16)) ** (8 / 27)) ** 2
    return nusselt * np.asarray(conductivity, dtype=float) / height


def radiation_coefficient(surface_temperature, surroundings_temperature, emissivity=0.9):
    """Linearised radiation coefficient h_r = εσ(T_s + T_∞)(T_s² + T_∞²).

    Parameters
    ----------
    surface_temperature, surroundings_temperature : array_like
        Temperatures [K].
    emissivity : float
        Grey-body emissivity ε [-] (painted cast iron ≈ 0.9).

    Returns
    -------
    numpy.ndarray
        h_r [W/(m²·K)].

    Examples
    --------
    >>> round(float(radiation_coefficient(333.15, 293.15)), 1)
    6.3
    """
    ts = np.asarray(surface_temperature, dtype=float)
    ta = np.asarray(surroundings_temperature, dtype=float)
    return emissivity * STEFAN_BOLTZMANN * (ts + ta) * (ts**2 + ta**2)


def air_properties(temperature):
    """Properties of dry air at 1 atm: ν [m²/s], α [m²/s], k [W/(m·K)], Pr [-].

    Power-law fits to Incropera Table A.4 (250--400 K, within 2 %).

    Parameters
    ----------
    temperature : array_like
        T [K].

    Returns
    -------
    tuple of numpy.ndarray
        (ν, α, k, Pr).

    Examples
    --------
    >>> nu, alpha, k, pr = air_properties(300.0)
    >>> round(float(nu) * 1e6, 2), round(float(k), 4), round(float(pr), 3)
    (15.89, 0.0263, 0.707)
    """
    t = np.divide(temperature, 300.0)
    nu = 15.89e-6 * t**1.72
    k = 0.0263 * t**0.83
    pr = 0.707 * t**-0.04
    return nu, nu / pr, k, pr
