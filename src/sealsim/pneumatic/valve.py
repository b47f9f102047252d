r"""Directional valves and restrictions: ISO 6358 flow, 5/2 and 5/3 spools, meter-out throttles.

Flow through a pneumatic component (valve path, throttle, cushioning needle) follows the ISO 6358
model with the sonic conductance C [m³/(s·Pa)] and the critical pressure ratio b [-]
(ISO 6358-1:2013 §3; Sanville 1971)::

    r = p_down / p_up
    choked    (r <= b):         G = C·ρ0·p_up·sqrt(T0/T_up)
    subsonic  (b < r <= β_lam): G = C·ρ0·p_up·sqrt(T0/T_up)·[1 − ((r − b)/(1 − b))²]^m
    laminar   (r > β_lam):      G = C·ρ0·p_up·sqrt(T0/T_up)·(1 − r)/(1 − β_lam)
                                    ·[1 − ((β_lam − b)/(1 − b))²]^m

with the ISO 8778 reference atmosphere (ANR: T0 = 293.15 K, p0 = 100 kPa, ρ0 = 1.185 kg/m³),
subsonic index m = 0.5 and the laminar linearisation above β_lam = 0.999 that removes the
infinite slope dG/dp at Δp = 0 (as in Simscape's "Constant Area Pneumatic Orifice (ISO 6358)").

A valve is a set of such paths (P→A, A→R, P→B, B→R) whose conductances are the nominal C times
the *opening* of the path (0…1), a function of the spool position s ∈ [−1, 1]
(:func:`port_openings`).  The spool follows the command with a dead time and a first-order lag
(:func:`spool_response`).  Restrictions in series (valve path, one-way flow control valve,
end-cushioning needle) are combined with :func:`series_conductance`.

All functions are vectorised (numpy broadcasting), SI units.

References
----------
.. [1] ISO 6358-1:2013, Pneumatic fluid power -- Determination of flow-rate characteristics of
   components using compressible fluids -- Part 1.
.. [2] ISO 8778:2003, Pneumatic fluid power -- Standard reference atmosphere.
.. [3] F. E. Sanville, "A new method of specifying the flow capacity of pneumatic fluid power
   valves", 2nd Int. Fluid Power Symp., BHRA, 1971.
.. [4] SMC, "Flow-rate characteristics" (ISO 6358 worked example: C = 2 dm³/(s·bar), b = 0.3,
   0.4 → 0.3 MPa gauge at 20 °C: 600 dm³/min ANR choked, 420 dm³/min at that ratio).
"""

from __future__ import annotations

import numpy as np

from sealsim.pneumatic.chambers import AIR_GAS_CONSTANT, AIR_HEAT_CAPACITY_RATIO

__all__ = [
    "ANR_DENSITY",
    "ANR_PRESSURE",
    "ANR_TEMPERATURE",
    "iso6358_flow",
    "iso6358_mass_flow",
    "mass_to_anr_volume",
    "nozzle_conductance",
    "port_openings",
    "openings",
    "series_conductance",
    "series_pair",
    "SpoolMotion",
    "subsonic_power",
    "spool_response",
]

#: Density of the ISO 8778 standard reference atmosphere (ANR) [kg/m³]
ANR_DENSITY = 1.185
#: Temperature of the ISO 8778 reference atmosphere [K]
ANR_TEMPERATURE = 293.15
#: Pressure of the ISO 8778 reference atmosphere [Pa]
ANR_PRESSURE = 1.0e5


def subsonic_power(base, index):
    """base^index [-]: the power of the subsonic ellipse of :func:`iso6358_mass_flow`.

    numpy computes ``array ** 0.5`` -- ISO 6358-1's subsonic index m = 0.5 -- as the square
    root, correctly rounded; the compiled right-hand side (:mod:`.rhs`) and the FMU's C take the
    square root for m = 0.5 as well instead of the C library's ``pow``, which differs from it in
    the last bit for about one argument in 1200 and costs several times as much.

    Examples
    --------
    >>> float(subsonic_power(np.array([0.81]), 0.5)[0])
    0.9
    """
    return base ** index


def iso6358_mass_flow(upstream_pressure, downstream_pressure, upstream_temperature,
                      conductance, critical_ratio, subsonic_index=0.5, laminar_ratio=0.999):
    """Mass flow through a restriction from its upstream to its downstream side (ISO 6358).

    .. math::
        G = C\\,\\rho_0\\,p_1\\sqrt{T_0/T_1}\\,\\phi(r), \\quad
        \\phi = \\begin{cases} 1 & r \\le b \\\\
        \\left[1 - \\left(\\frac{r - b}{1 - b}\\right)^2\\right]^m & b < r \\le \\beta \\\\
        \\frac{1 - r}{1 - \\beta}\\left[1 - \\left(\\frac{\\beta - b}{1 - b}\\right)^2\\right]^m
        & r > \\beta \\end{cases}

    Parameters
    ----------
    upstream_pressure : array_like
        Absolute pressure upstream p1 [Pa], > 0.
    downstream_pressure : array_like
        Absolute pressure downstream p2 [Pa]; p2 >= p1 gives no flow (0).
    upstream_temperature : array_like
        Temperature upstream T1 [K], > 0.
    conductance : array_like
        Sonic conductance C [m³/(s·Pa)] (1 dm³/(s·bar) = 1e-8 m³/(s·Pa)), >= 0.
    critical_ratio : array_like
        Critical pressure ratio b [-], 0 <= b < 1.
    subsonic_index : array_like
        Subsonic index m [-] (ISO 6358-1: 0.5 unless measured).
    laminar_ratio : array_like
        Pressure ratio β above which the flow is linearised in Δp [-], b < β < 1.

    Returns
    -------
    ndarray
        Mass flow G [kg/s], >= 0.

    References
    ----------
    ISO 6358-1:2013; Sanville (1971); laminar linearisation as in MathWorks Simscape
    "Constant Area Pneumatic Orifice (ISO 6358)".

    Examples
    --------
    SMC worked example: C = 2 dm³/(s·bar), b = 0.3, 0.4 → 0.3 MPa gauge, 20 °C (ANR flows):

    >>> p1, p2 = 0.5e6, 0.4e6
    >>> q_choked = iso6358_mass_flow(p1, 0.1e6, 293.15, 2e-8, 0.3) / ANR_DENSITY * 60e3
    >>> q_ratio = iso6358_mass_flow(p1, p2, 293.15, 2e-8, 0.3) / ANR_DENSITY * 60e3
    >>> round(float(q_choked), 6), round(float(q_ratio), 1)   # SMC: 600 and 0.7·600 = 420
    (600.0, 419.9)
    """
    p1, p2, b, beta = upstream_pressure, downstream_pressure, critical_ratio, laminar_ratio
    r = np.minimum(np.maximum(p2 / p1, 0.0), 1.0)
    # branch-free: the ellipse at r clipped to [b, β] (1 when choked), times the laminar
    # factor (1 − r)/(1 − β) where that is below 1 (r > β)
    e = (np.minimum(np.maximum(r, b), beta) - b) / (1.0 - b)
    phi = subsonic_power(1.0 - e * e, subsonic_index) * np.minimum((1.0 - r) / (1.0 - beta), 1.0)
    g = conductance * ANR_DENSITY * p1 * np.sqrt(ANR_TEMPERATURE / upstream_temperature) * phi
    return g * (p1 > p2)


def nozzle_conductance(area, discharge_coefficient=1.0):
    """ISO 6358 parameters (C, b) of a nozzle or sharp orifice with isentropic flow.

    The choked mass flow of an ideal gas through a throat of area A with discharge coefficient
    C_d (isentropic choked flow, e.g. Anderson, *Modern Compressible Flow*, ch. 5)::

        G* = C_d·A·p·sqrt(γ/(R·T))·(2/(γ + 1))^((γ + 1)/(2(γ − 1)))

    equals the ISO 6358 choked flow C·ρ0·p·sqrt(T0/T) for
    C = C_d·A·sqrt(γ/R)·(2/(γ + 1))^((γ + 1)/(2(γ − 1)))/(ρ0·sqrt(T0)), and the isentropic
    critical ratio is b = (2/(γ + 1))^(γ/(γ − 1)) = 0.528.  Below choking the ISO ellipse stands
    in for the isentropic nozzle law.

    Parameters
    ----------
    area : float or ndarray
        Throat area A [m²], >= 0.
    discharge_coefficient : float or ndarray
        C_d [-], 0 < C_d <= 1.

    Returns
    -------
    tuple
        (C [m³/(s·Pa)], b [-]).

    Examples
    --------
    A sharp orifice of 2.71 mm, C_d = 0.84 (effective area 4.85 mm², about 5 mm² per
    dm³/(s·bar) as in pneumatic catalogues):

    >>> c, b = nozzle_conductance(3.14159265 / 4 * 2.71e-3 ** 2, 0.84)
    >>> round(float(c) * 1e8, 3), round(float(b), 3)    # [dm³/(s·bar)], [-]
    (0.965, 0.528)
    """
    g, r = AIR_HEAT_CAPACITY_RATIO, AIR_GAS_CONSTANT
    choke = (2.0 / (g + 1.0)) ** ((g + 1.0) / (2.0 * (g - 1.0)))
    conductance = (np.asarray(discharge_coefficient, dtype=float) * np.asarray(area, dtype=float)
                   * np.sqrt(g / r) * choke / (ANR_DENSITY * np.sqrt(ANR_TEMPERATURE)))
    return conductance, (2.0 / (g + 1.0)) ** (g / (g - 1.0))


def iso6358_flow(pressure_a, temperature_a, pressure_b, temperature_b, conductance,
                 critical_ratio, subsonic_index=0.5, laminar_ratio=0.999):
    """Signed mass flow from node a to node b through a restriction (ISO 6358, both ways).

    The upstream side is the one with the higher pressure; its temperature is used.  The flow
    is continuous through Δp = 0 (laminar linearisation) and odd in (a ↔ b) for equal
    temperatures.

    Parameters
    ----------
    pressure_a, pressure_b : array_like
        Absolute pressures of the nodes [Pa].
    temperature_a, temperature_b : array_like
        Gas temperatures of the nodes [K].
    conductance, critical_ratio, subsonic_index, laminar_ratio : array_like
        As in :func:`iso6358_mass_flow`.

    Returns
    -------
    ndarray
        Mass flow a → b [kg/s] (negative: from b to a).

    Examples
    --------
    >>> g = iso6358_flow(np.array([5e5, 4e5]), 293.15, np.array([4e5, 5e5]), 293.15, 2e-8, 0.3)
    >>> bool(np.isclose(g[0], -g[1]))
    True
    """
    forward = pressure_a >= pressure_b
    g = iso6358_mass_flow(np.maximum(pressure_a, pressure_b), np.minimum(pressure_a, pressure_b),
                          forward * temperature_a + (1 - forward) * temperature_b,
                          conductance, critical_ratio, subsonic_index, laminar_ratio)
    return g * (2 * forward - 1)


def mass_to_anr_volume(mass):
    """Volume [m³] of air at the ISO 8778 reference atmosphere (ANR) for a mass [kg].

    "Normal litres" (NL) in sealsim's pneumatic results are ANR litres: 20 °C, 100 kPa, 65 %
    relative humidity, ρ0 = 1.185 kg/m³ (ISO 8778), the reference of ISO 6358 flow data.

    Examples
    --------
    >>> round(float(mass_to_anr_volume(1.185e-3)) * 1e3, 9)   # 1.185 g → 1 NL
    1.0
    """
    return np.asarray(mass, dtype=float) / ANR_DENSITY


def series_conductance(*conductances):
    """Sonic conductance of restrictions in series, 1/C² = Σ 1/C_i².

    For restrictions with b = 0 this is exact: each obeys G = C_i·ρ0·sqrt(T0/T)·
    sqrt(p_in² − p_out²), so eliminating the intermediate pressures gives
    G = C·ρ0·sqrt(T0/T)·sqrt(p_1² − p_n²) with the rule above (temperature changes between the
    restrictions neglected).  For b > 0 it is an approximation [R]; the chain then keeps the
    critical ratio of the valve path.  ISO 6358-3:2014 gives a numerical method for the general
    case.  A conductance of 0 closes the chain; ``inf`` is no restriction.

    Parameters
    ----------
    *conductances : float or ndarray
        Sonic conductances C_i [m³/(s·Pa)], >= 0 (``np.inf`` allowed).

    Returns
    -------
    float or ndarray
        C [m³/(s·Pa)].

    Examples
    --------
    >>> float(series_conductance(3e-8, 4e-8)) * 1e8
    2.4
    >>> float(series_conductance(2e-8, np.inf)) * 1e8, float(series_conductance(0.0, 2e-8))
    (2.0, 0.0)
    """
    result = conductances[0]
    for other in conductances[1:]:
        result = series_pair(result, other)
    return result


def series_pair(c1, c2):
    """Two restrictions in series (:func:`series_conductance`), written as
    C_s/sqrt(1 + (C_s/C_l)²) with C_s, C_l the smaller and larger one: exact for C_l = inf
    and for C_s = 0 (both 0 gives 0).

    Examples
    --------
    >>> float(series_pair(np.inf, 2e-8)) * 1e8, float(series_pair(np.inf, np.inf))
    (2.0, inf)
    """
    small = np.minimum(c1, c2)
    large = np.maximum(c1, c2)
    # the ratio with inf capped (inf/inf → 1) and 0/0 → 0; the cap 1e100 keeps the ratio of a
    # real conductance (1e-12 ... 1e-6 m³/(s·Pa)) to an open line (inf) and its square
    # normal numbers: subnormal ones cost the CPU a hundred times more, and 1 + ratio² = 1
    s, l_ = np.minimum(small, 1e100), np.minimum(large, 1e100)
    ratio = s / (l_ + (l_ == 0.0))
    return small / np.sqrt(1.0 + ratio * ratio)


# -- spool ---------------------------------------------------------------------------------------
#: centre positions of 5/3 valves: which paths the centre position opens
CENTRES = ("closed", "exhaust", "pressure")


def port_openings(spool, valve_type="5/2", centre="closed"):
    """Openings (0…1) of the paths P→A, A→R, P→B, B→R for a spool position s ∈ [−1, 1].

    s = +1 is the "extend" position (P→A, B→R open: chamber A = cap side is filled), s = −1
    "retract" (P→B, A→R); the openings grow linearly with |s| (an ideal zero-lap spool).  A
    5/2 valve passes through s = 0 only while switching (all paths closed there).  A 5/3
    valve rests at s = 0, whose centre position opens, additionally with the weight 1 − |s|:

    * ``"closed"``: nothing (both chambers shut in, the piston is held);
    * ``"exhaust"``: A→R and B→R (both chambers exhausted, the piston floats);
    * ``"pressure"``: P→A and P→B (both chambers pressurised).

    Parameters
    ----------
    spool : float or ndarray
        Spool position s [-].
    valve_type : {"5/2", "5/3"}
        Valve type.
    centre : {"closed", "exhaust", "pressure"}
        Centre position of a 5/3 valve.

    Returns
    -------
    ndarray, shape (4, ...)
        Openings of P→A, A→R, P→B, B→R [-].

    Examples
    --------
    >>> port_openings(np.array([1.0, -1.0, 0.0]), "5/3", "exhaust")
    array([[1., 0., 0.],
           [0., 1., 1.],
           [0., 1., 0.],
           [1., 0., 1.]])
    """
    if centre not in CENTRES:
        raise ValueError(f"centre {centre!r}: choose one of {CENTRES}")
    code = CENTRES.index(centre) if valve_type == "5/3" else 0
    return np.array(openings(np.asarray(spool, dtype=float), code))


def openings(spool, centre_code):
    """The four openings (P→A, A→R, P→B, B→R) as a tuple, for a centre code (0 closed or a
    5/2 valve, 1 exhaust, 2 pressure); see :func:`port_openings`.

    Examples
    --------
    >>> [float(o) for o in openings(0.5, 1)]
    [0.5, 0.5, 0.0, 1.0]
    """
    forward = np.minimum(np.maximum(spool, 0.0), 1.0)
    back = np.minimum(np.maximum(-spool, 0.0), 1.0)
    middle = 1.0 - forward - back
    exhaust = middle * (centre_code == 1)
    pressure = middle * (centre_code == 2)
    return forward + pressure, back + exhaust, back + pressure, forward + exhaust


class SpoolMotion:
    """Spool position after a sequence of commands: dead time, then a first-order lag.

    The command u_k issued at t_k reaches the spool at a_k = t_k + t_d; from then on
    s(t) = u_k + (s(a_k) − u_k)·exp(−(t − a_k)/τ), the exact solution of τ·ds/dt = u − s
    (τ = 0: the spool jumps).  Solenoid valves are usually specified by a switching time; a
    first-order lag reaches 95 % of the stroke after 3τ.

    Parameters
    ----------
    command_times : array_like
        Times t_k at which the commands are issued [s], ascending.
    commands : array_like
        Commanded spool positions u_k [-] (+1 extend, −1 retract, 0 centre).
    time_constant : float
        τ [s], >= 0.
    delay : float
        Dead time t_d [s], >= 0.
    initial : float
        Spool position before the first command arrives [-].

    Examples
    --------
    >>> spool = SpoolMotion([0.0], [1.0], 0.01, delay=0.002)
    >>> spool([0.0, 0.002, 0.012]).round(4)
    array([0.    , 0.    , 0.6321])
    """

    def __init__(self, command_times, commands, time_constant, delay=0.0, initial=0.0):
        self.arrivals = np.asarray(command_times, dtype=float) + delay
        self.targets = np.asarray(commands, dtype=float)
        self.time_constant = float(time_constant)
        self.initial = float(initial)
        # spool position when each command arrives (the lag from the previous one)
        self.starts = np.empty(self.targets.size)
        s = self.initial
        for k, u in enumerate(self.targets):
            self.starts[k] = s
            if k + 1 < self.targets.size:
                s = u + (s - u) * self._decay(self.arrivals[k + 1] - self.arrivals[k])
        self._arrivals = self.arrivals.tolist()

    def _decay(self, elapsed):
        if self.time_constant > 0:
            return np.exp(-np.maximum(elapsed, 0.0) / self.time_constant)
        return np.zeros(np.shape(elapsed))

    def __call__(self, t):
        """s(t) [-] at time(s) t [s]."""
        t = np.asarray(t, dtype=float)
        if self.targets.size == 0:
            return np.full(t.shape, self.initial)
        k = np.searchsorted(self.arrivals, t, side="right") - 1
        kk = np.maximum(k, 0)
        u = self.targets[kk]
        s = u + (self.starts[kk] - u) * self._decay(t - self.arrivals[kk])
        return np.where(k < 0, self.initial, s)

    def scalar(self, t: float) -> float:
        """s(t) for one time (fast path of the ODE right-hand side)."""
        import bisect
        import math

        k = bisect.bisect_right(self._arrivals, t) - 1
        if k < 0:
            return self.initial
        u = float(self.targets[k])
        tau = self.time_constant
        if tau <= 0:
            return u
        return u + (float(self.starts[k]) - u) * math.exp(-max(t - self._arrivals[k], 0.0)
                                                          / tau)


def spool_response(t, command_times, commands, time_constant, delay=0.0, initial=0.0):
    """Spool position s(t) [-] after a sequence of commands (see :class:`SpoolMotion`).

    Examples
    --------
    >>> spool_response([0.0, 0.002, 0.012], [0.0], [1.0], 0.01, delay=0.002).round(4)
    array([0.    , 0.    , 0.6321])
    """
    return SpoolMotion(command_times, commands, time_constant, delay, initial)(t)
