r"""The compiled right-hand side of the pneumatic cylinder (chambers, valve, seals, piston).

One numba function evaluates dy/dt for one state vector: chamber volumes, pressures and
temperatures, the spool position, the ISO 6358 flows, wall heat, the pressure difference across
every seal, its contact load F_N, b from the contact map at the seal temperature, its friction
law, the stick/slip force sharing, the piston force balance, the seal heating and the
bookkeeping integrals.  It is composed of the physics functions of the package -- compiled from
their numpy source (:mod:`._jit`) or the scalar kernels of :mod:`sealsim.friction.kernels` and
:mod:`.contact_maps` -- so each law has one implementation.  Everything a call needs is in a
few preallocated arrays built once by :class:`.system.PneumaticSystem` (the *tables* below); a
call allocates nothing.

Tables
------
``c`` (float64)
    Constants, indexed by the ``C_*`` names below.
``seal_int`` (int64, one row per seal), ``law_par`` (float64, one row per seal)
    Law code and location, state offsets, map and thermal set-up (``SI_*`` columns), the law's
    parameters (layout per law in :func:`sealsim.friction.compiled.law_parameters`) and
    thermal constants (``ST_*``).
``map_data`` (float64), ``map_int`` (int64, one row per seal)
    Contact maps: exact analytic O-ring estimate or a C¹ Hermite grid
    (:func:`sealsim.pneumatic.contact_maps.hermite_grid_point`).
``fric_data`` (float64), ``fric_int`` (int64, one row per seal: data offset, then the table's
    layout row)
    Steady friction tables from the seals' contacts
    (:func:`sealsim.friction.contact_table.contact_table_point`) for Θ laws with
    ``steady = "contact"``; a seal without one has a row of zeros.
``spool`` (float64, 3 rows) and ``profile`` (float64)
    Valve command arrivals / targets / start positions, and the prescribed position profile.

State vector ``y``: x, v, m1, m2, U1, U2, the friction states of every seal, the seal
temperatures and the rod and tube temperatures (seal heating only), then the bookkeeping
integrals (:data:`BOOKKEEPING`).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sealsim.friction.compiled import (  # noqa: F401  (law codes re-exported)
    COULOMB,
    DAHL,
    GMS,
    LAW_CODES,
    LUGRE,
    STRIBECK,
    THETA,
)
from sealsim.friction import compiled as _compiled_laws
from sealsim.friction.compiled import law_rates
from sealsim.pneumatic._jit import borrowed, jit
from sealsim.pneumatic.chambers import (
    AIR_CP,
    AIR_CV,
    AIR_HEAT_CAPACITY_RATIO,
    free_convection_coefficient,
    wall_heat_flow,
)
from sealsim.pneumatic.contact_maps import _analytic_loads, hermite_grid_point
from sealsim.pneumatic.friction_tables import table_orientation
from sealsim.pneumatic.cylinder import end_stop_force, load_force
from sealsim.pneumatic.seal_heating import sliding_contact_coefficient
from sealsim.pneumatic.seals import pressure_difference, side_pressures, smooth_abs
from sealsim.pneumatic.valve import iso6358_flow, iso6358_mass_flow, openings, series_pair
from sealsim.thermal import convection

__all__ = ["BOOKKEEPING", "MODES", "STICK", "FORWARD", "BACKWARD", "FREE", "PRESCRIBED"]

#: integration modes
STICK, FORWARD, BACKWARD, FREE, PRESCRIBED = 0, 1, -1, 2, 3
#: what :func:`evaluate_column` computes: derivatives; derivatives and every intermediate
#: quantity; the output quantities only; derivatives with the seals' contact loads of the
#: evaluation before (a Jacobian column that changes no Δp and no seal temperature)
RATES, FULL, OUTPUTS, RATES_KEPT_LOADS = 0, 1, 2, 3
MODES = {STICK: "stick", FORWARD: "slip+", BACKWARD: "slip-", FREE: "free",
         PRESCRIBED: "prescribed"}
#: bookkeeping states appended to y: time integrals of the boundary flows (kg, J);
#: ``supply_mass`` is the net flow out of the supply, ``supply_return_mass`` the flow back into
#: it alone (from a chamber above supply pressure); the
#: :data:`THERMAL_BOOKKEEPING` ones follow with seal heating only
BOOKKEEPING = ("supply_mass", "exhaust_mass", "mass_throughput", "enthalpy",
               "enthalpy_throughput", "heat", "gas_work", "work_external", "work_stop",
               "work_friction", "supply_return_mass")
_NBOOK = len(BOOKKEEPING)
THERMAL_BOOKKEEPING = ("friction_heat", "heat_to_air", "heat_to_ambient")

# -- constants (indices into c) -------------------------------------------------------------
(C_DEAD1, C_DEAD2, C_A1, C_A2, C_AROD, C_STROKE, C_BORE, C_PS, C_PA, C_TS, C_TA, C_C, C_B,
 C_M, C_BETA, C_CENTRE, C_H, C_TW, C_F0, C_KL, C_X0L, C_CL, C_INCL, C_MASS, C_KS, C_CS, C_DS,
 C_THR1, C_THR2, C_CU1_L, C_CU1_C, C_CU1_E, C_CU2_L, C_CU2_C, C_CU2_E,
 C_BOOK, C_HEAT, C_TOFF, C_TUBE_CAP, C_TUBE_G, C_ROD_CAP, C_ROD_G_X, C_TAMB,
 C_SPOOL_TAU, C_SPOOL_INIT, C_PROFILE_KIND, C_HFREE,
 C_AW1, C_AW1_X, C_AW2, C_AW2_X, C_AWROD, C_AWROD_X, C_NCONST) = range(54)
#: the chambers' wall areas A_w1, A_w2 and the rod's share of A_w2 are affine in x: their
#: values at x = 0 (C_AW1, C_AW2, C_AWROD) [m²] and slopes dA/dx (C_*_X) [m] are those of
#: :func:`sealsim.pneumatic.chambers.chamber_wall_areas`, the one formula of the Python model,
#: this right-hand side and the FMU's C (:class:`.system.PneumaticSystem`).
#: C_ROD_G_X [W/(m·K)] is the rod's conductance to the surroundings per metre of rod outside
#: the cylinder: the extension x is outside, the rest of the rod is in the rod-side chamber
#: and the head

# -- seal tables ----------------------------------------------------------------------------
#: law codes: those of :mod:`sealsim.friction.compiled` (imported above)
#: columns of seal_int
(SI_LAW, SI_LOC, SI_OFF, SI_STICKY, SI_HEATED, SI_COUNTER, SI_GROOVE, SI_NCOLS) = range(8)
#: columns of seal_therm: constant temperature [K], heat capacity [J/K], circumference π·D [m],
#: contact width without a map [m], effusivity of the counterface, static contact coefficient
#: [W/(m²·K)], conductance to the groove [W/K], to the air of chamber 1, chamber 2 and the
#: atmosphere [W/K]
(ST_TCONST, ST_CAP, ST_AC, ST_WIDTH, ST_EFF, ST_HSTAT, ST_GGROOVE, ST_AIR1, ST_AIR2, ST_AMB,
 ST_NCOLS) = range(11)
#: map kinds (map_int column 0)
MAP_NONE, MAP_ANALYTIC, MAP_GRID = 0, 1, 2
#: nodes a seal exchanges heat with (SI_COUNTER, SI_GROOVE)
NODE_TUBE, NODE_ROD = 0, 1

# -- diagnostics (rows of diag) -------------------------------------------------------------
(D_X, D_V, D_P1, D_P2, D_T1, D_T2, D_SPOOL, D_G0, D_G1, D_G2, D_G3, D_H0, D_H1, D_H2, D_H3,
 D_Q1, D_Q2, D_FPRESS, D_FLOAD, D_FSTOP, D_FFRIC, D_HOLD, D_BRK, D_TTUBE, D_TROD,
 D_NFIXED) = range(26)
#: per seal rows after the fixed ones: friction, F_N, b, Δp, break-away, temperature,
#: friction power, temperature clipped to the map (0/1)
(DS_F, DS_FN, DS_B, DS_DP, DS_BRK, DS_T, DS_POWER, DS_CLIP, DS_NROWS) = range(9)

_TINY_SPEED = 1e-300          # |v| used for sticking laws at v = 0 in a slip mode (sign only)


@njit(cache=True)
def _subsonic_power(base, index):
    """:func:`.valve.subsonic_power` compiled: the square root for ISO 6358's m = 0.5, as numpy
    computes ``array ** 0.5`` (numba's ``**`` calls the C library's ``pow``: 7 % of a
    right-hand side, and a last bit different from numpy's for one argument in 1200)."""
    if index == 0.5:
        return math.sqrt(base)
    return base ** index


_flow = jit(iso6358_flow, iso6358_mass_flow=jit(iso6358_mass_flow,
                                                subsonic_power=_subsonic_power))
_series = jit(series_pair)
_openings = jit(openings)
_heat = jit(wall_heat_flow)
_free_h = jit(free_convection_coefficient, air_properties=jit(convection.air_properties),
              free_convection_horizontal_cylinder=jit(
                  convection.free_convection_horizontal_cylinder,
                  rayleigh_number=jit(convection.rayleigh_number)))
_stop = jit(end_stop_force)
_load = jit(load_force)
_dp = jit(pressure_difference, smooth_abs=jit(smooth_abs))
_sides = jit(side_pressures)
_orient = njit(cache=True)(table_orientation)


_speed_cell = jit(_compiled_laws.speed_cell.py_func, inline=True)
#: the friction laws and the contact friction tables, inlined into the right-hand side (a
#: call takes and releases a reference to every array it is passed: with three seals a
#: tenth of an evaluation)
_law_rates = jit(law_rates.py_func, inline=True, _theta_contact=jit(
    _compiled_laws._theta_contact.py_func, inline=True,
    contact_steady=jit(_compiled_laws.contact_steady.py_func, inline=True,
                       table_cell=jit(_compiled_laws.table_cell.py_func, inline=True),
                       speed_cell=_speed_cell,
                       _film_cell=jit(_compiled_laws._film_cell.py_func, inline=True,
                                      speed_cell=_speed_cell),
                       cell_sum=jit(_compiled_laws.cell_sum.py_func, inline=True),
                       cell_sum_pair=jit(_compiled_laws.cell_sum_pair.py_func, inline=True))))
#: gridded contact maps, inlined into :func:`_seal_loads`
_grid_point = jit(hermite_grid_point.py_func, inline=True)


@njit(cache=True)
def cushion_conductance(distance, length, conductance, entry):
    """Conductance of an end cushion [m³/(s·Pa)] at ``distance`` from the end (inf: open, or
    no cushion when ``length`` is 0): the needle alone once the spear has fully entered, a
    smooth fade over the entry length."""
    if length <= 0.0:
        return np.inf
    u = min(max((distance - (length - entry)) / entry, 0.0), 1.0)
    closed = 1.0 - u * u * (3.0 - 2.0 * u)                 # smoothstep
    return np.inf if closed <= 0.0 else conductance / closed


@njit(inline="always")
def spool_position(t, spool, tau, initial):
    """Spool position s(t) [-] after the commands (see :class:`.valve.SpoolMotion`):
    ``spool`` rows are arrival times, targets and the positions at arrival."""
    k = np.searchsorted(spool[0], t, side="right") - 1
    if k < 0:
        return initial
    u = spool[1, k]
    if tau <= 0.0:
        return u
    return u + (spool[2, k] - u) * math.exp(-max(t - spool[0, k], 0.0) / tau)


@njit(cache=True)
def profile_point(t, kind, profile):
    """Prescribed position x(t) [m] and velocity dx/dt [m/s] of the test-rig profile.

    kind 1 constant (level), 2 harmonic (mean, amplitude, ω, phase), 3 piecewise linear
    (n, times..., values...): the profiles of :func:`sealsim.friction.profiles.profile_type`."""
    if kind == 1:
        return profile[0], 0.0
    if kind == 2:
        mean, amp, w, phase = profile[0], profile[1], profile[2], profile[3]
        return mean + amp * math.cos(w * t + phase), -amp * w * math.sin(w * t + phase)
    n = int(profile[0])
    times = profile[1:1 + n]
    values = profile[1 + n:1 + 2 * n]
    x = np.interp(t, times, values)
    if n < 2:
        return x, 0.0
    i = np.searchsorted(times, t, side="right") - 1
    if i < 0 or i >= n - 1:
        return x, 0.0
    return x, (values[i + 1] - values[i]) / (times[i + 1] - times[i])


@njit(cache=True)
def _path_flow(pa, ta, pb, tb, conductance, critical_ratio, subsonic_index, laminar_ratio):
    """The ISO 6358 flow a → b of a valve path [kg/s]; a closed path (conductance 0: two of the
    four whenever the spool is off centre) has none, and the law, which would give
    0 · (its finite factors) = 0, is not evaluated there."""
    if conductance == 0.0:
        return 0.0
    return _flow(pa, ta, pb, tb, conductance, critical_ratio, subsonic_index, laminar_ratio)


@njit(inline="always")
def _seal_loads(i, dp, temp, map_int, map_data):
    """(F_N [N], b [m], clipped) of seal i at Δp [Pa] and its temperature [K]."""
    kind = map_int[i, 0]
    if kind == MAP_ANALYTIC:
        off = map_int[i, 1]
        fn, b = _analytic_loads(dp, map_data[off], map_data[off + 1], map_data[off + 2],
                                map_data[off + 3])
        return fn, b, 0.0
    if kind == MAP_GRID:
        return _grid_point(map_int[i], map_data, dp, temp)
    return math.nan, math.nan, 0.0


@njit(inline="always")
def _flows_and_heat(x, p1, p2, t1, t2, s, t_wall, t_rod, c):
    """Mass flows g0..g3 [kg/s] of the paths P→A, A→R, P→B, B→R (meter-out throttles and end
    cushions in series), their enthalpy flows h0..h3 [W], the wall heat q1, q2 [W] into the
    chambers and the parts q1_rod, q2_rod of them that come from the moving metal at t_rod
    (the piston's face in chamber 1; its annular face and the rod's surface in chamber 2), at
    spool position s."""
    pa_, ar_, pb_, br_ = _openings(s, c[C_CENTRE])
    ps, pa, ts, ta = c[C_PS], c[C_PA], c[C_TS], c[C_TA]
    # restrictions on the way out of a chamber: meter-out throttle and end cushion
    line1 = _series(c[C_THR1], cushion_conductance(x, c[C_CU1_L], c[C_CU1_C], c[C_CU1_E]))
    line2 = _series(c[C_THR2], cushion_conductance(c[C_STROKE] - x, c[C_CU2_L], c[C_CU2_C],
                                                   c[C_CU2_E]))
    k0 = _series(c[C_C] * pa_, line1 if p1 > ps else np.inf)
    k1 = _series(c[C_C] * ar_, line1 if p1 > pa else np.inf)
    k2 = _series(c[C_C] * pb_, line2 if p2 > ps else np.inf)
    k3 = _series(c[C_C] * br_, line2 if p2 > pa else np.inf)
    g0 = _path_flow(ps, ts, p1, t1, k0, c[C_B], c[C_M], c[C_BETA])
    g1 = _path_flow(p1, t1, pa, ta, k1, c[C_B], c[C_M], c[C_BETA])
    g2 = _path_flow(ps, ts, p2, t2, k2, c[C_B], c[C_M], c[C_BETA])
    g3 = _path_flow(p2, t2, pa, ta, k3, c[C_B], c[C_M], c[C_BETA])
    h0 = AIR_CP * (ts if ps >= p1 else t1) * g0
    h1 = AIR_CP * (t1 if p1 >= pa else ta) * g1
    h2 = AIR_CP * (ts if ps >= p2 else t2) * g2
    h3 = AIR_CP * (t2 if p2 >= pa else ta) * g3
    hw1 = hw2 = c[C_H]                            # wall heat-transfer coefficients
    if c[C_HFREE] > 0.0:                          # free convection at the chamber's state
        hw1 = _free_h(p1, t1, t_wall, c[C_BORE])
        hw2 = _free_h(p2, t2, t_wall, c[C_BORE])
    # the piston's faces (A1, A2: one of the two end faces of each chamber) and the rod's
    # surface are the moving metal at t_rod, the rest the barrel and heads at t_wall; written
    # as corrections h·A·(t_rod − t_wall) that are exactly 0 without seal heating
    area_rod = c[C_AWROD] + c[C_AWROD_X] * x
    q1_rod = _heat(hw1, c[C_A1], t_rod, t1)
    q1 = _heat(hw1, c[C_AW1] + c[C_AW1_X] * x, t_wall, t1) + _heat(hw1, c[C_A1], t_rod, t_wall)
    q2_surface = _heat(hw2, area_rod, t_rod, t2)
    q2_rod = q2_surface + _heat(hw2, c[C_A2], t_rod, t2)
    q2 = (_heat(hw2, c[C_AW2] + c[C_AW2_X] * x - area_rod, t_wall, t2) + q2_surface
          + _heat(hw2, c[C_A2], t_rod, t_wall))
    return g0, g1, g2, g3, h0, h1, h2, h3, q1, q2, q1_rod, q2_rod


@njit(cache=True)
def evaluate_column(t, y, col, mode, tables, dy, diag, level):
    """dy/dt of column ``col`` of ``y`` (shape (n, k)) in integration mode ``mode``.

    ``level`` :data:`RATES` (0): writes dy[:, col]; :data:`FULL` (1): also every intermediate
    quantity into diag[:, col]; :data:`OUTPUTS` (2): only what the output time series and the
    stick test need (positions, pressures, temperatures, forces, contact loads) into diag --
    no flows, no heat, no derivatives: the cheaper evaluation at the output samples;
    :data:`RATES_KEPT_LOADS` (3): as RATES, but each seal's contact loads (F_N, b, clipped)
    are those in diag[:, col] from the evaluation before, not looked up in its map again --
    for a state that changes neither a Δp nor a seal temperature (:func:`jacobian_at`).  Every
    evaluation leaves the loads it used in diag.
    ``tables`` = (c, spool, profile, seal_int, law_par, seal_therm, map_int, map_data,
    fric_int, fric_data).
    """
    # every caller holds its arrays until the call returns: borrowed, the rows and slices taken
    # below count no references (called, not inlined, an evaluation with the counts took
    # 440 ns instead of 280 ns, cylinder_32.toml, level RATES)
    tables = borrowed_tables(tables)
    y, dy, diag = borrowed(y), borrowed(dy), borrowed(diag)
    full = level == FULL or level == OUTPUTS
    rates = level != OUTPUTS
    kept_loads = level == RATES_KEPT_LOADS
    (c, spool, profile, seal_int, law_par, seal_therm, map_int, map_data, fric_int,
     fric_data) = tables
    gm1 = AIR_HEAT_CAPACITY_RATIO - 1.0
    prescribed = mode == PRESCRIBED
    if prescribed:
        x, v = profile_point(t, int(c[C_PROFILE_KIND]), profile)
    else:
        x, v = y[0, col], y[1, col]
    m1, m2, u1, u2 = y[2, col], y[3, col], y[4, col], y[5, col]
    vol1 = c[C_DEAD1] + c[C_A1] * x
    vol2 = c[C_DEAD2] + c[C_A2] * (c[C_STROKE] - x)
    p1 = gm1 * u1 / vol1
    p2 = gm1 * u2 / vol2
    # Newton iterates of the solver may visit m <= 0: keep T finite there
    t1 = min(max(u1 / (max(m1, 1e-12) * AIR_CV), 20.0), 3000.0)
    t2 = min(max(u2 / (max(m2, 1e-12) * AIR_CV), 20.0), 3000.0)
    s = spool_position(t, spool, c[C_SPOOL_TAU], c[C_SPOOL_INIT])
    ps, pa = c[C_PS], c[C_PA]
    heating = c[C_HEAT] > 0.0
    toff = int(c[C_TOFF])
    nseal = seal_int.shape[0]
    if heating:                                   # the chamber walls are the tube node
        t_tube = y[toff + nseal, col]
        t_rod = y[toff + nseal + 1, col]
        t_wall = t_tube
    else:
        t_tube = t_rod = t_wall = c[C_TW]
    g0 = g1 = g2 = g3 = h0 = h1 = h2 = h3 = q1 = q2 = q1_rod = q2_rod = 0.0
    if rates:
        g0, g1, g2, g3, h0, h1, h2, h3, q1, q2, q1_rod, q2_rod = _flows_and_heat(
            x, p1, p2, t1, t2, s, t_wall, t_rod, c)
    f_press = p1 * c[C_A1] - p2 * c[C_A2] - pa * c[C_AROD]
    f_load = _load(x, v, c[C_F0], c[C_KL], c[C_X0L], c[C_MASS], c[C_INCL], c[C_CL])
    f_stop = _stop(x, v, c[C_STROKE], c[C_KS], c[C_CS], c[C_DS])
    f_drive = f_press - f_load + f_stop

    # -- seals: contact load, friction law, stick/slip sharing --------------------------------
    sticky_any = False
    f_smooth = 0.0
    brk_sum = 0.0
    f_fric = 0.0
    nsticky = 0
    base = D_NFIXED
    for i in range(nseal):
        law = seal_int[i, SI_LAW]
        sticky = seal_int[i, SI_STICKY] != 0
        temp = seal_therm[i, ST_TCONST]
        if seal_int[i, SI_HEATED] != 0:
            temp = y[toff + i, col]
        dp = _dp(seal_int[i, SI_LOC], p1, p2, pa, 1e3)
        pside_a, pside_b = _sides(seal_int[i, SI_LOC], p1, p2, pa)
        r = base + i * DS_NROWS
        if kept_loads:
            fn, b, clipped = diag[r + DS_FN, col], diag[r + DS_B, col], diag[r + DS_CLIP, col]
        else:
            fn, b, clipped = _seal_loads(i, dp, temp, map_int, map_data)
        if not sticky or mode == FREE or mode == PRESCRIBED:
            vv = v
        elif mode == STICK:
            vv = 0.0
        else:                                     # slip: hold the direction down to v = 0
            d = float(mode)
            vv = d * max(d * v, _TINY_SPEED)
        frow = fric_int[i, 1:]
        orient = _orient(seal_int[i, SI_LOC], p1, p2, pa)
        force, brk = _law_rates(law, law_par[i], y, seal_int[i, SI_OFF], vv, fn, b, pside_a,
                                pside_b, temp, dy, col, frow, fric_data[fric_int[i, 0]:], dp,
                                orient)
        if sticky:
            sticky_any = True
            nsticky += 1
            brk_sum += brk
            if mode == STICK:
                force = 0.0
        else:
            f_smooth += force
        diag[r + DS_F, col] = force
        diag[r + DS_FN, col] = fn
        diag[r + DS_B, col] = b
        diag[r + DS_BRK, col] = brk
        diag[r + DS_CLIP, col] = clipped
        if full:
            diag[r + DS_DP, col] = dp
            diag[r + DS_T, col] = temp
    hold = 0.0
    if mode == STICK and sticky_any:
        # the sticking seals carry what holds the piston, shared as their break-away forces
        hold = f_drive - f_smooth
        for i in range(nseal):
            if seal_int[i, SI_STICKY] != 0:
                r = base + i * DS_NROWS
                if brk_sum > 0.0:
                    diag[r + DS_F, col] = diag[r + DS_BRK, col] / brk_sum * hold
                else:
                    diag[r + DS_F, col] = 1.0 / nsticky * hold
    for i in range(nseal):
        f_fric += diag[base + i * DS_NROWS + DS_F, col]

    # -- derivatives ---------------------------------------------------------------------------
    q_air1 = q1
    q_air2 = q2
    if rates:
        dvol1 = c[C_A1] * v
        dvol2 = -c[C_A2] * v
        dy[0, col] = 0.0 if prescribed else v
        if mode == FORWARD or mode == BACKWARD or mode == FREE:
            dy[1, col] = (f_drive - f_fric) / c[C_MASS]
        else:
            dy[1, col] = 0.0
        book = int(c[C_BOOK])
        if heating:
            # seal nodes: friction heat in, heat to the counterface, groove, air and ambient
            cap_t = c[C_TUBE_CAP]
            q_tube = -(q1 - q1_rod + q2 - q2_rod)  # the tube gives the chamber wall heat,
            q_rod = -(q1_rod + q2_rod)             # piston and rod that of their surfaces
            q_amb = 0.0
            q_heat = 0.0
            for i in range(nseal):
                r = base + i * DS_NROWS
                power = diag[r + DS_F, col] * v
                if seal_int[i, SI_HEATED] == 0:       # no node: its heat goes to the counterface
                    if seal_int[i, SI_COUNTER] == NODE_TUBE:
                        q_tube += power
                    else:
                        q_rod += power
                    q_heat += power
                    dy[toff + i, col] = 0.0
                    continue
                ts_i = y[toff + i, col]
                t_cf = t_tube if seal_int[i, SI_COUNTER] == NODE_TUBE else t_rod
                t_gr = t_tube if seal_int[i, SI_GROOVE] == NODE_TUBE else t_rod
                par = seal_therm[i]
                width = diag[r + DS_B, col] if map_int[i, 0] != MAP_NONE else par[ST_WIDTH]
                g_cf = sliding_contact_coefficient(v, width, par[ST_EFF], par[ST_HSTAT]) * (
                    par[ST_AC] * width)
                q_cf = g_cf * (ts_i - t_cf)
                q_gr = par[ST_GGROOVE] * (ts_i - t_gr)
                qa1 = par[ST_AIR1] * (ts_i - t1)
                qa2 = par[ST_AIR2] * (ts_i - t2)
                qam = par[ST_AMB] * (ts_i - c[C_TAMB])
                dy[toff + i, col] = (power - q_cf - q_gr - qa1 - qa2 - qam) / par[ST_CAP]
                if seal_int[i, SI_COUNTER] == NODE_TUBE:
                    q_tube += q_cf
                else:
                    q_rod += q_cf
                if seal_int[i, SI_GROOVE] == NODE_TUBE:
                    q_tube += q_gr
                else:
                    q_rod += q_gr
                q_air1 += qa1
                q_air2 += qa2
                q_amb += qam
                q_heat += power
                if full:
                    diag[r + DS_POWER, col] = power
            q_tube_amb = c[C_TUBE_G] * (t_tube - c[C_TAMB])
            outside = min(max(x, 0.0), c[C_STROKE])   # the extended length of the rod
            q_rod_amb = c[C_ROD_G_X] * outside * (t_rod - c[C_TAMB])
            dy[toff + nseal, col] = (q_tube - q_tube_amb) / cap_t
            dy[toff + nseal + 1, col] = (q_rod - q_rod_amb) / c[C_ROD_CAP]
            nb = book + _NBOOK
            dy[nb, col] = q_heat
            dy[nb + 1, col] = q_air1 + q_air2          # walls (tube node) and seals into the air
            dy[nb + 2, col] = q_amb + q_tube_amb + q_rod_amb
        dy[2, col] = g0 - g1
        dy[3, col] = g2 - g3
        dy[4, col] = h0 - h1 - p1 * dvol1 + q_air1
        dy[5, col] = h2 - h3 - p2 * dvol2 + q_air2
        dy[book, col] = g0 + g2
        dy[book + 1, col] = g1 + g3
        dy[book + 2, col] = abs(g0) + abs(g1) + abs(g2) + abs(g3)
        dy[book + 3, col] = h0 - h1 + h2 - h3
        dy[book + 4, col] = abs(h0) + abs(h1) + abs(h2) + abs(h3)
        dy[book + 5, col] = q_air1 + q_air2
        dy[book + 6, col] = p1 * dvol1 + p2 * dvol2
        dy[book + 7, col] = -(f_load + pa * c[C_AROD]) * v
        dy[book + 8, col] = f_stop * v
        dy[book + 9, col] = f_fric * v
        dy[book + 10, col] = max(-g0, 0.0) + max(-g2, 0.0)
    if full:
        diag[D_X, col] = x
        diag[D_V, col] = v
        diag[D_P1, col] = p1
        diag[D_P2, col] = p2
        diag[D_T1, col] = t1
        diag[D_T2, col] = t2
        diag[D_SPOOL, col] = s
        diag[D_G0, col] = g0
        diag[D_G1, col] = g1
        diag[D_G2, col] = g2
        diag[D_G3, col] = g3
        diag[D_H0, col] = h0
        diag[D_H1, col] = h1
        diag[D_H2, col] = h2
        diag[D_H3, col] = h3
        diag[D_Q1, col] = q_air1
        diag[D_Q2, col] = q_air2
        diag[D_FPRESS, col] = f_press
        diag[D_FLOAD, col] = f_load
        diag[D_FSTOP, col] = f_stop
        diag[D_FFRIC, col] = f_fric
        diag[D_HOLD, col] = hold
        diag[D_BRK, col] = brk_sum
        diag[D_TTUBE, col] = t_tube
        diag[D_TROD, col] = t_rod


@njit(cache=True)
def _plain(y):
    """0 as a run-time value: numba compiles a function once per argument *type*, and a literal
    0 is a type of its own; calling :func:`evaluate_column` everywhere with plain int64
    arguments compiles it once instead of several times."""
    return y.shape[0] * 0


@njit(cache=True)
def derivatives(t, y, mode, tables, dy, diag):
    """dy/dt at (t, y) for a state vector y of shape (n,) into dy (shape (n,))."""
    zero = _plain(y)
    # y[:, None]: a column view without numba's general reshape (which costs a third of the
    # whole evaluation)
    evaluate_column(t, y[:, None], zero, mode + zero, tables, dy[:, None], diag, zero + RATES)


@njit(cache=True)
def jacobian(t, y, mode, tables, scale, work_y, work_dy, f0, diag, jac):
    """∂f/∂y by forward differences of the dynamic states (the bookkeeping states do not feed
    back: their columns stay zero): h_j = 1.5e-8·max(|y_j|, scale_j), one evaluation per
    state plus one at y (:func:`jacobian_at` after f0 = f(t, y))."""
    derivatives(t, y, mode, tables, f0, diag)
    jac[:, :] = 0.0
    jacobian_at(t, y, f0, mode, tables, scale, work_y, work_dy, diag, jac)


@njit(cache=True)
def jacobian_at(t, y, f0, mode, tables, scale, work_y, work_dy, diag, jac):
    """The columns j < ndyn of ∂f/∂y by forward differences from f0 = f(t, y), one evaluation
    per dynamic state (see :func:`jacobian`); the other columns of ``jac`` are not touched.

    The seals' contact loads depend on the states only through the pressures (x, U1, U2)
    and the seal temperatures: the columns of the other states (v, the masses, the friction
    states, the tube and rod temperatures) are evaluated first, the first of them looks the
    loads up, the rest take them from it (:data:`RATES_KEPT_LOADS`) -- the same numbers, a
    map lookup per seal less for half the columns (cylinder_32_fe.toml: 5.0-5.2 µs per
    Jacobian instead of 5.8-6.2 µs).  The temperature of a seal that is no thermal node is
    read by nothing: its column is 0, not evaluated."""
    ndyn = scale.shape[0]
    zero = _plain(y)
    tables = borrowed_tables(tables)      # held by the caller: no counts in the calls below
    c = tables[0]
    toff = int(c[C_TOFF])
    nseal = tables[3].shape[0]
    shifted, rates = work_y[:, None], work_dy[:, None]      # column views, made once
    looked_up = False
    seal_int = tables[3]
    for sweep in range(2):              # the columns without, then those with new loads
        for j in range(ndyn):
            new_loads = j == 0 or j == 4 or j == 5 or toff <= j < toff + nseal
            if new_loads != (sweep == 1):
                continue
            if toff <= j < toff + nseal and seal_int[j - toff, SI_HEATED] == 0:
                # the temperature slot of a seal that is no thermal node (no cord diameter:
                # seal_heating) is read by nothing: its column is 0, without an evaluation
                for i in range(y.shape[0]):
                    jac[i, j] = 0.0
                continue
            level = RATES if new_loads or not looked_up else RATES_KEPT_LOADS
            looked_up = True
            _difference_column(t, y, f0, j, mode + zero, tables, scale, work_y, work_dy,
                               shifted, rates, diag, jac, zero + level)


@njit(inline="always")
def _difference_column(t, y, f0, j, mode, tables, scale, work_y, work_dy, shifted, rates,
                       diag, jac, level):
    """Column j of ∂f/∂y by a forward difference from f0 = f(t, y), h_j =
    1.5e-8·max(|y_j|, scale_j) (``shifted``, ``rates``: column views of work_y, work_dy)."""
    n = y.shape[0]
    h = 1.5e-8 * max(abs(y[j]), scale[j])
    for i in range(n):
        work_y[i] = y[i]
    work_y[j] = y[j] + h
    evaluate_column(t, shifted, 0 * n, mode, tables, rates, diag, level)
    for i in range(n):
        jac[i, j] = (work_dy[i] - f0[i]) / h


@njit(cache=True)
def velocity_column_at(t, y, f0, mode, tables, scale, work_y, work_dy, diag, jac):
    """Column 1 of ∂f/∂y, ∂f/∂v, as :func:`jacobian_at` computes it, from f0 = f(t, y).
    Returns ∂(dv/dt)/∂v [1/s].

    The shifted evaluation looks the contact loads up at (t, y) itself, as the first column
    of :func:`jacobian_at` does: the evaluation before it need not have been at y (the BDF
    renews the column at the predicted state after a failed Newton iteration, whose last
    evaluation was at the last iterate, with other pressures)."""
    zero = _plain(y)
    tables = borrowed_tables(tables)
    _difference_column(t, y, f0, 1 + zero, mode + zero, tables, scale, work_y, work_dy,
                       work_y[:, None], work_dy[:, None], diag, jac, zero + RATES)
    return jac[1, 1]


@njit(inline="always")
def borrowed_tables(tables):
    """The tables as :func:`._jit.borrowed` arrays (not reference counted: the rows and slices
    that every evaluation takes of them, and every call they are passed to, cost no atomic
    counts) -- for a compiled function whose caller holds ``tables``."""
    c, spool, profile, seal_int, law_par, seal_therm, map_int, map_data, fric_int, \
        fric_data = tables
    return (borrowed(c), borrowed(spool), borrowed(profile), borrowed(seal_int),
            borrowed(law_par), borrowed(seal_therm), borrowed(map_int), borrowed(map_data),
            borrowed(fric_int), borrowed(fric_data))


#: :func:`evaluate_column` inlined into the loop over the output samples (the only copy of
#: it: every other caller calls it, and an inlined copy costs 17-24 s of CPU to compile): as a
#: call, an evaluation at the samples took 440 ns instead of 158 ns (cylinder_32.toml, level
#: OUTPUTS; a Jacobian column costs no more as a call)
_evaluate_column_inlined = jit(evaluate_column.py_func, inline=True)


@njit(cache=True)
def evaluate_many(ts, ys, modes, tables, dys, diag, level):
    """dy/dt and the diagnostics of ``level`` (:data:`FULL` or :data:`OUTPUTS`, see
    :func:`evaluate_column`) for every column of ys (shape (n, k)) at the times ts (k,) in
    the modes ``modes`` (k,)."""
    tables = borrowed_tables(tables)
    for col in range(ys.shape[1]):
        _evaluate_column_inlined(ts[col], ys, col, modes[col], tables, dys, diag, level)


@njit(cache=True)
def stick_margin(t, y, tables, work_y, dy, diag):
    """(F_req, F_brk) [N] with the body held at rest at (t, y): the force the sticking seals
    must carry and the sum of their break-away forces (see
    :meth:`sealsim.pneumatic.system.PneumaticSystem.stick_margin`)."""
    for i in range(y.shape[0]):
        work_y[i] = y[i]
    work_y[1] = 0.0
    zero = _plain(y)
    evaluate_column(t, work_y[:, None], zero, STICK + zero, tables, dy[:, None], diag,
                    zero + OUTPUTS)
    return diag[D_HOLD, 0], diag[D_BRK, 0]


@njit(cache=True)
def dense_values(ts, step_t, step_end, step_h, step_order, step_start, yh_data, n, out):
    """States at the times ``ts`` from LSODA's Nordsieck histories (scipy's LsodaDenseOutput:
    y(t) = Σ_p yh[:, p]·((t − t_end)/h)^p), the step chosen as scipy's OdeSolution does for
    LSODA (``searchsorted(..., side="left") − 1``).

    ``step_t`` holds the start time of the first step followed by the time every step reaches;
    step j's history is ``yh_data[step_start[j]:...]`` (n × (order + 1), column-major),
    relative to its end ``step_end[j]``."""
    nseg = step_h.shape[0]
    for k in range(ts.shape[0]):
        t = ts[k]
        j = np.searchsorted(step_t, t, side="left") - 1
        j = min(max(j, 0), nseg - 1)
        h = step_h[j]
        q = step_order[j]
        r = (t - step_end[j]) / h
        for i in range(n):
            acc = 0.0
            power = 1.0
            for p in range(q + 1):
                acc += yh_data[step_start[j] + p * n + i] * power
                power = power * r
            out[i, k] = acc
