r"""Cylinder chambers: mass and energy balance of an ideal gas with wall heat transfer.

Each chamber is a uniform control volume of air (ideal gas, constant specific heats) whose
volume changes with the piston.  sealsim integrates the chamber **mass m and internal energy
U = m·c_v·T** (first law for an open system, Richer & Hurmuzlu 2000 [1]_)::

    dm/dt = Σ G_in − Σ G_out
    dU/dt = Σ c_p·T_up·G_in − c_p·T·Σ G_out − p·dV/dt + Q̇_wall
    p = (γ − 1)·U/V,   T = U/(m·c_v),   Q̇_wall = h·A_w·(T_wall − T)

Flows entering carry the enthalpy of their upstream node (c_p·T_supply, or c_p·T_ambient when
air is sucked back from the exhaust); flows leaving carry the chamber's.  The same equations in
pressure and temperature (the form used in the literature, e.g. Richer & Hurmuzlu 2000) are
:func:`pressure_rate` and :func:`temperature_rate`.

Why (m, U): mass and energy are then *linear* in the states, so a closed chamber conserves its
mass exactly (dm/dt = 0 identically) and the energy bookkeeping of a run can be checked against
the enthalpy, heat and work that crossed the boundary.  A closed adiabatic chamber gives
dU = −p·dV with p = (γ − 1)U/V, i.e. U·V^(γ−1) = const and p·V^γ = const.

**Wall heat transfer.**  Q̇ = h·A_w·(T_wall − T) with the wetted wall area A_w
(:func:`chamber_wall_area`: barrel, end cap and piston face; in the rod-side chamber also the
rod's surface, and annular faces) and the wall at the temperature of the cylinder body (the
barrel is a large heat sink on the time scale of a stroke; with seal heating it is the tube
node of :mod:`.seal_heating`, and the rod's surface the rod node).  h = 0 gives adiabatic
chambers.

The default h = 38 W/(m²·K) (:data:`DEFAULT_HEAT_TRANSFER_COEFFICIENT`) is derived from a
published characterisation of actuating pneumatic cylinders: Richer & Hurmuzlu [1]_ model the
pressure change by piston motion as a polytropic process with the exponent α = 1.2 (between
isothermal 1 and adiabatic 1.4), from the air temperatures Al-Ibrahim & Otis [2]_ measured in a
cylinder during charging and discharging.  With h = 38 W/(m²·K) the rod-side chamber of the
Ø32 example, closed and compressed 2:1 in 0.3 s (a typical stroke), follows p·V^1.20 = const
(:func:`polytropic_exponent`; a test checks 1.2 ± 0.02; the former default 45 gave 1.20 while
that chamber's wall lacked the rod's surface, and 1.18 with it).  It is a single constant: a faster stroke or
a smaller cylinder runs closer to adiabatic.  The measured coefficients of Carneiro & de
Almeida [3]_ would be the better source; their values could not be retrieved for sealsim.

Free convection alone, :func:`free_convection_coefficient` (Churchill & Chu [4]_ at the
chamber pressure), is the lower bound: 6-17 W/(m²·K) for the Ø32 chamber at 1-6 bar and 30 K
(exponent 1.28-1.35 in the stroke above; the case option ``[air] heat_transfer =
"free_convection"`` evaluates it at each chamber's state and gives 1.33); the default's excess
is the stirring by the port jet and the piston.

**Measured air-temperature swing.**  No published temperature record of a cylinder chamber
could be retrieved with the data needed to simulate it.  The closest measured
case is the blow-down of a 16-litre air vessel from 7.9 bar through a 2.71 mm orifice [5]_:
measured drop 41.6 K at 23 s, recovery time constant 27 s at 1 bar.  These equations with
free convection give a drop of 52.6 K at 20 s and a recovery time constant of 14 s, every
measured point within 16 K (10 K rms); a lagging thermocouple flattens the measured minimum,
and cold air settling in the vessel probably slows its recovery.  Any constant h fits worse
(best h = 10 W/(m²·K): 15 K rms), h = 38 recovers far too fast and h = 0 drops 133 K
(``tests/test_pneumatic_air_temperature.py``).

References
----------
.. [1] E. Richer, Y. Hurmuzlu, "A high performance pneumatic force actuator system: Part I --
   nonlinear mathematical model", J. Dyn. Sys. Meas. Control 122(3), 416-425, 2000
   (chamber equations, α_in = 1.4, α_out = 1, α = 1.2).
.. [2] A. M. Al-Ibrahim, D. R. Otis, "Transient air temperature and pressure measurements
   during the charging and discharging processes of an actuating pneumatic cylinder", Proc.
   45th National Conference on Fluid Power, 1992 (as cited by [1]).
.. [3] J. F. Carneiro, F. G. de Almeida, "Heat transfer evaluation of industrial pneumatic
   cylinders", Proc. IMechE Part I: J. Systems and Control Engineering 221(1), 119-128, 2007.
.. [4] S. W. Churchill, H. H. S. Chu, "Correlating equations for laminar and turbulent free
   convection from a horizontal cylinder", Int. J. Heat Mass Transfer 18, 1049-1053, 1975
   (Incropera et al., Fundamentals of Heat and Mass Transfer, 6th ed., Eq. 9.34).
.. [5] Air blow-down of a Ø200 × 515 mm steel vessel, measured pressure and mean gas
   temperature, as digitised in the validation set of A. Andreasen, "HydDown: A Python package
   for calculation of hydrogen (or other gas) pressure vessel filling and discharge", J. Open
   Source Softw. 6(66), 3695, 2021 (``validation/Air_790kPa_21mm.yml``); the file names no
   source, HydDown's references cite for air G. Thorncroft, J. S. Patton, R. G. Gordon,
   ASEE Annual Conference 2007, paper AC 2007-2695 (not verified).
"""

from __future__ import annotations

import numpy as np

from sealsim.thermal.convection import air_properties, free_convection_horizontal_cylinder

__all__ = [
    "DEFAULT_HEAT_TRANSFER_COEFFICIENT",
    "AIR_GAS_CONSTANT",
    "AIR_HEAT_CAPACITY_RATIO",
    "AIR_CP",
    "AIR_CV",
    "STANDARD_ATMOSPHERE",
    "chamber_energy_rate",
    "chamber_wall_area",
    "chamber_wall_areas",
    "free_convection_coefficient",
    "gas_mass",
    "gas_pressure",
    "gas_temperature",
    "internal_energy",
    "polytropic_exponent",
    "pressure_rate",
    "temperature_rate",
    "wall_heat_flow",
]

#: Specific gas constant of dry air R [J/(kg·K)]
AIR_GAS_CONSTANT = 287.058
#: Heat capacity ratio of air γ [-]
AIR_HEAT_CAPACITY_RATIO = 1.4
#: Specific heat at constant volume c_v = R/(γ − 1) [J/(kg·K)]
AIR_CV = AIR_GAS_CONSTANT / (AIR_HEAT_CAPACITY_RATIO - 1.0)
#: Specific heat at constant pressure c_p = γ·R/(γ − 1) [J/(kg·K)]
AIR_CP = AIR_HEAT_CAPACITY_RATIO * AIR_CV
#: Default wall heat-transfer coefficient of the chamber air [W/(m²·K)] (module docstring:
#: the polytropic exponent 1.2 of Richer & Hurmuzlu 2000 for a 0.3 s stroke of the Ø32 example)
DEFAULT_HEAT_TRANSFER_COEFFICIENT = 38.0
#: Pressure of the air property tables (Incropera Table A.4: 1 atm) [Pa]
STANDARD_ATMOSPHERE = 101325.0


def polytropic_exponent(p_start, p_end, v_start, v_end):
    """Effective polytropic exponent n of a closed-gas process, p·V^n = const between two
    states: n = −ln(p_end/p_start)/ln(V_end/V_start).

    Examples
    --------
    >>> round(float(polytropic_exponent(1e5, 1e5 * 2 ** 1.4, 2e-5, 1e-5)), 12)   # adiabatic 2:1
    1.4
    """
    return -np.log(np.asarray(p_end, dtype=float) / p_start) / np.log(
        np.asarray(v_end, dtype=float) / v_start)


def gas_pressure(internal_energy, volume):
    """Pressure of an ideal gas with constant specific heats, p = (γ − 1)·U/V.

    Parameters
    ----------
    internal_energy : float or ndarray
        Internal energy U [J] (zero at 0 K).
    volume : float or ndarray
        Volume V [m³], > 0.

    Returns
    -------
    ndarray
        Absolute pressure p [Pa].

    Examples
    --------
    >>> float(gas_pressure(250.0, 1e-3))
    100000.0
    """
    return (AIR_HEAT_CAPACITY_RATIO - 1.0) * internal_energy / volume


def gas_temperature(mass, internal_energy):
    """Temperature of the gas, T = U/(m·c_v).

    Parameters
    ----------
    mass : float or ndarray
        Gas mass m [kg], > 0.
    internal_energy : float or ndarray
        Internal energy U [J].

    Returns
    -------
    ndarray
        T [K].

    Examples
    --------
    >>> round(float(gas_temperature(1e-3, 1e-3 * AIR_CV * 293.15)), 6)
    293.15
    """
    return internal_energy / (mass * AIR_CV)


def gas_mass(pressure, volume, temperature):
    """Mass of an ideal gas, m = p·V/(R·T).

    Parameters
    ----------
    pressure : float or ndarray
        Absolute pressure [Pa].
    volume : float or ndarray
        Volume [m³].
    temperature : float or ndarray
        Temperature [K].

    Returns
    -------
    ndarray
        m [kg].

    Examples
    --------
    >>> round(float(gas_mass(1e5, 1e-3, 293.15)) * 1e3, 4)   # one litre at 1 bar, 20 °C [g]
    1.1883
    """
    return (np.asarray(pressure, dtype=float) * volume
            / (AIR_GAS_CONSTANT * np.asarray(temperature, dtype=float)))


def internal_energy(mass, temperature):
    """Internal energy of the gas, U = m·c_v·T [J].

    Examples
    --------
    >>> round(float(internal_energy(1.0, 300.0)))
    215294
    """
    return np.asarray(mass, dtype=float) * AIR_CV * np.asarray(temperature, dtype=float)


def wall_heat_flow(heat_transfer_coefficient, area, wall_temperature, gas_temperature):
    """Heat flow from the wall into the gas, Q̇ = h·A_w·(T_wall − T) (Newton cooling).

    Parameters
    ----------
    heat_transfer_coefficient : float or ndarray
        h [W/(m²·K)], >= 0.
    area : float or ndarray
        Wetted wall area A_w [m²].
    wall_temperature : float or ndarray
        Wall temperature [K].
    gas_temperature : float or ndarray
        Gas temperature [K].

    Returns
    -------
    ndarray
        Q̇ [W] (positive: the gas is heated).

    Examples
    --------
    >>> float(wall_heat_flow(30.0, 0.01, 293.15, 313.15))
    -6.0
    """
    return heat_transfer_coefficient * area * (wall_temperature - gas_temperature)


def free_convection_coefficient(pressure, gas_temperature, wall_temperature, diameter):
    """Free-convection coefficient between quiescent chamber air and its wall.

    h = Nu·k/D with the Churchill & Chu correlation for a horizontal cylinder [4]_ (Incropera
    Eq. 9.34, :func:`sealsim.thermal.convection.free_convection_horizontal_cylinder`) evaluated
    at the chamber pressure: k and the dynamic viscosity of an ideal gas depend on T only, so
    ν and α scale with 1/p, ν(p, T) = ν(1 atm, T)·p_atm/p, and Ra ∝ p².  Properties at the
    film temperature (T + T_wall)/2, β = 1/T_film.

    It is the lower bound of the wall heat transfer: no jet from the port, no piston motion.
    An external-flow correlation stands in for the enclosure, as is usual for gas vessels
    (a test checks a measured blow-down of an air vessel against it).  Not the default.

    Parameters
    ----------
    pressure : float or ndarray
        Chamber pressure p [Pa], > 0.
    gas_temperature, wall_temperature : float or ndarray
        T and T_wall [K].
    diameter : float
        Bore or vessel diameter D [m] (the length scale of the correlation).

    Returns
    -------
    ndarray
        h [W/(m²·K)].

    Examples
    --------
    >>> round(float(free_convection_coefficient(6e5, 263.15, 293.15, 0.032)), 1)  # Ø32, 6 bar
    17.2
    >>> round(float(free_convection_coefficient(1e5, 263.15, 293.15, 0.032)), 1)  # at 1 bar
    6.3
    """
    t_film = 0.5 * np.add(gas_temperature, wall_temperature)
    nu, alpha, k, _ = air_properties(t_film)
    scale = np.divide(STANDARD_ATMOSPHERE, pressure)
    return free_convection_horizontal_cylinder(
        diameter, np.subtract(wall_temperature, gas_temperature),
        nu * scale, alpha * scale, k, 1.0 / t_film)


def chamber_wall_area(length, bore, face_area, rod_diameter=0.0):
    """Wetted wall area of a chamber: barrel π·D·l, the surface π·d·l of a rod that runs
    through it, and the two end faces.

    .. math:: A_w = \\pi (D + d)\\, l + 2 A_f

    The cap-side chamber has no rod (d = 0) and the full piston area as its faces; the
    rod-side chamber is an annulus: barrel, rod surface and two annular faces π/4·(D² − d²).

    Parameters
    ----------
    length : float or ndarray
        Length of the air column l [m] (piston travel plus dead volume / area), >= 0.
    bore : float
        Bore D [m].
    face_area : float or ndarray
        Area of one end face [m²] (piston side; the cap or head face counted equal).
    rod_diameter : float
        Diameter d [m] of a rod through the chamber (0: none).

    Returns
    -------
    ndarray
        A_w [m²].

    Examples
    --------
    >>> round(float(chamber_wall_area(0.1, 0.032, 8.04e-4)) * 1e4, 2)   # cap side [cm²]
    116.61
    >>> round(float(chamber_wall_area(0.1, 0.032, 6.91e-4, 0.012)) * 1e4, 2)   # rod side
    152.05
    """
    return np.pi * (bore + rod_diameter) * length + 2.0 * face_area


def chamber_wall_areas(x, stroke, bore, rod_diameter, a1, a2, dead_volume_1, dead_volume_2):
    """Wetted wall areas of the two chambers of a single-rod cylinder at the piston position x
    (:func:`chamber_wall_area` of each air column; its length is the chamber volume over the
    piston area, V1/A1 = x + V01/A1 and V2/A2 = L − x + V02/A2), and the rod's share of the
    rod-side one (it exchanges heat with the rod, not with the barrel).

    Parameters
    ----------
    x : float or ndarray
        Piston position [m] (0 retracted, L extended).
    stroke : float
        L [m].
    bore, rod_diameter : float
        D, d [m].
    a1, a2 : float
        Piston area π/4·D² and annulus π/4·(D² − d²) [m²].
    dead_volume_1, dead_volume_2 : float
        Dead volumes of the cap-side and rod-side chamber [m³].

    Returns
    -------
    a_w1, a_w2, a_rod2 : ndarray
        Wall area of the cap-side chamber, of the rod-side chamber (barrel, rod, two annular
        faces) and the rod's surface in it, π·d·(L − x + V02/A2) [m²].

    Examples
    --------
    Ø32/12 × 100 mm, 5 cm³ dead volume each, at mid-stroke [cm²]:

    >>> a1, a2 = np.pi / 4 * 0.032 ** 2, np.pi / 4 * (0.032 ** 2 - 0.012 ** 2)
    >>> [round(float(a) * 1e4, 2) for a in chamber_wall_areas(0.05, 0.1, 0.032, 0.012, a1, a2,
    ...                                                        5e-6, 5e-6)]
    [72.6, 92.94, 21.58]
    """
    length_1 = x + dead_volume_1 / a1
    length_2 = stroke - x + dead_volume_2 / a2
    return (chamber_wall_area(length_1, bore, a1),
            chamber_wall_area(length_2, bore, a2, rod_diameter),
            chamber_wall_area(length_2, 0.0, 0.0, rod_diameter))     # the rod alone


def chamber_energy_rate(enthalpy_in, enthalpy_out, pressure, volume_rate, heat_flow=0.0):
    """First law for the chamber, dU/dt = H_in − H_out − p·dV/dt + Q̇.

    Parameters
    ----------
    enthalpy_in : float or ndarray
        Enthalpy carried in by the inflows Σ c_p·T_up·G_in [W].
    enthalpy_out : float or ndarray
        Enthalpy carried out, c_p·T·Σ G_out [W].
    pressure : float or ndarray
        Chamber pressure p [Pa].
    volume_rate : float or ndarray
        dV/dt [m³/s].
    heat_flow : float or ndarray
        Q̇ from the wall [W].

    Returns
    -------
    ndarray
        dU/dt [W].

    Examples
    --------
    >>> float(chamber_energy_rate(0.0, 0.0, 5e5, 1e-4))   # expansion work 50 W
    -50.0
    """
    return enthalpy_in - enthalpy_out - pressure * volume_rate + heat_flow


def pressure_rate(pressure, volume, volume_rate, inflow, inflow_temperature, outflow,
                  temperature, heat_flow=0.0):
    """dp/dt of a chamber (energy equation in pressure form, Richer & Hurmuzlu 2000).

    .. math:: \\dot p = -\\gamma p \\frac{\\dot V}{V}
              + \\frac{\\gamma R}{V}(T_{in} G_{in} - T G_{out})
              + \\frac{\\gamma - 1}{V} \\dot Q

    Parameters
    ----------
    pressure : float or ndarray
        p [Pa].
    volume, volume_rate : float or ndarray
        V [m³], dV/dt [m³/s].
    inflow, outflow : float or ndarray
        Mass flows in and out [kg/s], >= 0.
    inflow_temperature : float or ndarray
        Temperature of the inflow [K].
    temperature : float or ndarray
        Chamber temperature T [K].
    heat_flow : float or ndarray
        Q̇ from the wall [W].

    Returns
    -------
    ndarray
        dp/dt [Pa/s].

    References
    ----------
    Richer & Hurmuzlu (2000); a public Julia pneumatic cylinder script after Carneiro & Almeida
    (Carneiro & de Almeida 2006 also write it so).

    Examples
    --------
    >>> float(pressure_rate(1e5, 1e-3, -1e-3, 0.0, 293.15, 0.0, 293.15))  # adiabatic: γ·p·|V̇|/V
    140000.0
    """
    g = AIR_HEAT_CAPACITY_RATIO
    p = np.asarray(pressure, dtype=float)
    return (-g * p * volume_rate / volume
            + g * AIR_GAS_CONSTANT / volume * (np.asarray(inflow_temperature) * inflow
                                              - np.asarray(temperature) * outflow)
            + (g - 1.0) / volume * heat_flow)


def temperature_rate(pressure, volume, volume_rate, inflow, inflow_temperature, outflow,
                     temperature, heat_flow=0.0):
    """dT/dt of a chamber (energy equation in temperature form, Richer & Hurmuzlu 2000).

    .. math:: \\dot T = (1-\\gamma) T \\frac{\\dot V}{V}
              + \\frac{R T}{p V}\\left[G_{in}(\\gamma T_{in} - T) - (\\gamma - 1) T G_{out}\\right]
              + \\frac{(\\gamma - 1) T}{p V} \\dot Q

    Parameters are those of :func:`pressure_rate`.

    Returns
    -------
    ndarray
        dT/dt [K/s].

    Examples
    --------
    >>> float(temperature_rate(1e5, 1e-3, -1e-3, 0.0, 293.15, 0.0, 300.0))  # (γ−1)·T·|V̇|/V
    120.0
    """
    g = AIR_HEAT_CAPACITY_RATIO
    t = np.asarray(temperature, dtype=float)
    pv = np.asarray(pressure, dtype=float) * volume
    return ((1.0 - g) * t * volume_rate / volume
            + AIR_GAS_CONSTANT * t / pv * (inflow * (g * np.asarray(inflow_temperature) - t)
                                           - (g - 1.0) * t * outflow)
            + (g - 1.0) * t / pv * heat_flow)
