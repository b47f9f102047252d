"""Chamber air temperature against a measurement: the blow-down of an air vessel through an
orifice (measured pressure and gas temperature), simulated with the chamber equations of
:mod:`sealsim.pneumatic.chambers`, the ISO 6358 flow of a nozzle and free convection at the
chamber pressure.

No published air-temperature record of a pneumatic cylinder chamber with the data needed to
simulate it could be retrieved (Carneiro & de Almeida 2007, Al-Ibrahim & Otis 1992, Kagawa et
al.); the cylinder default h = 38 W/(m²·K) is checked against the polytropic exponent of Richer &
Hurmuzlu 2000 in ``test_pneumatic_chambers.py``.  The vessel here is the closest measured case:
the same physics (a closed chamber of air discharged through an orifice, cooled air warmed by
its wall), a larger and quiescent chamber.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from sealsim.pneumatic.chambers import (
    AIR_CP,
    chamber_energy_rate,
    chamber_wall_area,
    free_convection_coefficient,
    gas_mass,
    gas_pressure,
    gas_temperature,
    internal_energy,
    wall_heat_flow,
)
from sealsim.pneumatic.valve import iso6358_mass_flow, nozzle_conductance

# Blow-down of a horizontal steel vessel, Ø200 × 515 mm inside (16.2 litres), wall 8.2 mm, from
# 7.9 bar abs and 298 K through a 2.71 mm orifice (C_d = 0.84) to 1 bar; the mean gas
# temperature and the pressure were measured.  Data as digitised in the validation set of
# HydDown (A. Andreasen, "HydDown: A Python package for calculation of hydrogen (or other gas)
# pressure vessel filling and discharge", J. Open Source Softw. 6(66), 3695, 2021;
# github.com/andr1976/HydDown, validation/Air_790kPa_21mm.yml, commit 1040d75, MIT licence).
# The file names no source; HydDown's reference list cites for air charging/discharging
# G. Thorncroft, J. S. Patton, R. G. Gordon, "Modeling compressible air flow in a charging or
# discharging vessel and assessment of polytropic exponent", ASEE Annual Conference 2007,
# paper AC 2007-2695, doi:10.18260/1-2--2911 (fast-response thermocouple) -- not verified.
VESSEL_DIAMETER, VESSEL_LENGTH = 0.20, 0.515          # m
ORIFICE_DIAMETER, DISCHARGE_COEFFICIENT = 2.71e-3, 0.84
P0, T_WALL, P_BACK = 7.90e5, 298.0, 1.0e5              # Pa, K, Pa
MEASURED_T_TIME = np.array([3.58, 7.65, 11.4, 15.2, 19.2, 23.2, 26.8, 30.8, 34.7, 38.6, 42.5,
                            46.2, 50.1, 54.0])                                       # s
MEASURED_T = np.array([285.9, 275.3, 265.8, 261.1, 257.8, 256.4, 256.7, 257.8, 260.4, 264.2,
                       268.6, 272.6, 276.0, 278.9])                                  # K
MEASURED_P_TIME = np.array([0.226, 4.14, 8.06, 12.0, 15.7, 19.6, 23.6, 27.6, 31.5, 35.2, 39.2,
                            43.2, 47.1, 50.8, 54.8])                                 # s
MEASURED_P = np.array([7.6883, 5.6748, 4.2327, 3.2582, 2.6213, 2.0884, 1.7112, 1.412, 1.2037,
                       1.0863, 1.0209, 1.0074, 1.0069, 1.0064, 1.0059])              # bar abs


def blow_down(heat_transfer_coefficient, t_end=56.0):
    """Closed vessel discharged through the orifice: states (m, U), dm/dt = −G,
    dU/dt = −c_p·T·G + h·A·(T_wall − T); the wall stays at 298 K (24.6 kg of steel against
    0.15 kg of air: the wall cools < 0.4 K).  ``heat_transfer_coefficient(p, T)`` [W/(m²·K)].
    Returns the dense solution as functions p(t) [bar], T(t) [K]."""
    volume = np.pi / 4 * VESSEL_DIAMETER**2 * VESSEL_LENGTH
    area = chamber_wall_area(VESSEL_LENGTH, VESSEL_DIAMETER, np.pi / 4 * VESSEL_DIAMETER**2)
    conductance, critical = nozzle_conductance(np.pi / 4 * ORIFICE_DIAMETER**2,
                                               DISCHARGE_COEFFICIENT)

    def rhs(t, y):
        mass, energy = y
        p, temp = gas_pressure(energy, volume), gas_temperature(mass, energy)
        flow = iso6358_mass_flow(p, P_BACK, temp, conductance, critical)
        heat = wall_heat_flow(heat_transfer_coefficient(p, temp), area, T_WALL, temp)
        return [-flow, chamber_energy_rate(0.0, AIR_CP * temp * flow, p, 0.0, heat)]

    m0 = gas_mass(P0, volume, T_WALL)
    sol = solve_ivp(rhs, (0.0, t_end), [m0, internal_energy(m0, T_WALL)], method="LSODA",
                    rtol=1e-8, atol=[1e-10, 1e-5], dense_output=True, max_step=0.5)
    assert sol.success
    return (lambda t: gas_pressure(sol.sol(t)[1], volume) / 1e5,
            lambda t: gas_temperature(*sol.sol(t)))


def free_convection(p, temp):
    return free_convection_coefficient(p, temp, T_WALL, VESSEL_DIAMETER)


def test_vessel_blow_down_matches_the_measured_air_temperature_swing():
    pressure, temperature = blow_down(free_convection)
    t = np.linspace(0.0, 56.0, 5601)
    sim_t = temperature(t)
    measured_drop = MEASURED_T.min() - T_WALL                  # −41.6 K at 23.2 s
    sim_drop, sim_t_min = sim_t.min() - T_WALL, t[np.argmin(sim_t)]
    # pressure: the orifice flow and the mass balance.  rms within 0.1 bar of the 7.9 bar
    # swing (sealsim: 0.05 bar): C_d is the source's, the ISO ellipse stands in for the
    # isentropic law below choking, and the gas temperature enters the flow.
    rms_p = np.sqrt(np.mean((pressure(MEASURED_P_TIME) - MEASURED_P) ** 2))
    assert rms_p < 0.1
    # the air-temperature drop: measured −41.6 K at 23.2 s, sealsim −52.6 K at 19.8 s.
    # Tolerance 15 K and 6 s: the thermocouple lags the air (a bead's time constant is
    # seconds in still air at 1-3 bar), which flattens and delays the measured minimum, and
    # free convection from an external-cylinder correlation in an enclosure is good to about
    # ±25 % in h.  The simulation must be the colder one (a lagging sensor never overshoots).
    assert sim_drop == pytest.approx(measured_drop, abs=15.0)
    assert sim_drop <= measured_drop
    assert sim_t_min == pytest.approx(23.2, abs=6.0)
    # the whole record, drop and recovery, within 40 % of the measured swing (16.6 K):
    # sealsim runs up to 15.6 K colder in the drop and recovers faster (τ ≈ 14 s against the
    # measured 27 s at 1 bar, 42-54 s): the correlation's h ≈ 4 W/(m²·K) there against the
    # 2 W/(m²·K) the measured recovery implies (probably cold air settling in the vessel).
    assert np.max(np.abs(temperature(MEASURED_T_TIME) - MEASURED_T)) < 0.4 * abs(measured_drop)


def test_vessel_blow_down_needs_the_wall_heat_and_rejects_the_cylinder_default():
    # Adiabatic walls: the air would fall to 165 K (−133 K), three times the measured drop --
    # the swing is set by the wall heat, which is what the comparison tests.
    _, adiabatic = blow_down(lambda p, temp: 0.0)
    assert adiabatic(np.linspace(0.0, 56.0, 561)).min() - T_WALL < 3.0 * (MEASURED_T.min() - T_WALL)
    # The cylinder default h = 38 W/(m²·K) (a small chamber stirred by the port jet and the
    # piston) is too high for this quiescent 16-litre vessel: the air would be back within
    # 0.5 K of the wall at 54 s, where it is measured 19 K below -- the default is not a
    # property of air in any chamber, and free convection is the lower bound of h.
    from sealsim.pneumatic.chambers import DEFAULT_HEAT_TRANSFER_COEFFICIENT

    _, stirred = blow_down(lambda p, temp: DEFAULT_HEAT_TRANSFER_COEFFICIENT)
    assert T_WALL - stirred(54.0) < 0.5
    assert T_WALL - MEASURED_T[-1] > 15.0
