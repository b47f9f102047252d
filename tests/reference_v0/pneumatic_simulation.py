"""Frozen copy of the pre-issue-13 implementation (commit 9cdec80, pneumatic_simulation), kept as the
reference that the compiled code is tested against and as the benchmark baseline.
Docstrings removed; physics unchanged except the rod-side chamber's wall area (the rod's surface
and annular faces, fixed in sealsim too).  Do not edit otherwise."""
# ruff: noqa
from __future__ import annotations
import time as _time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any
import numpy as np
import pandas as pd
from scipy.integrate import solve_ivp
from sealsim.errors import ConvergenceError, InputError
from sealsim.friction.base import ContactInputs
from sealsim.friction.hybrid import resolve_stick
from sealsim.pneumatic._jit import jit
from sealsim.pneumatic.case import body_temperature, build_seals
from sealsim.pneumatic.chambers import AIR_CP, AIR_CV, AIR_HEAT_CAPACITY_RATIO, chamber_wall_areas, gas_mass, internal_energy, wall_heat_flow
from sealsim.pneumatic.controller import COMMANDS, CommandSchedule
from sealsim.pneumatic.cylinder import end_stop_force, load_force, piston_areas, piston_force, rest_position
from sealsim.pneumatic.seals import Seal, pressure_difference, side_pressures, smooth_abs
from sealsim.pneumatic.valve import ANR_DENSITY, CENTRES, SpoolMotion, iso6358_flow, iso6358_mass_flow, openings, port_openings, series_pair
__all__ = ['MODES', 'PneumaticResult', 'PneumaticSystem', 'simulate']
STICK, FORWARD, BACKWARD, FREE, PRESCRIBED = (0, 1, -1, 2, 3)
MODES = {STICK: 'stick', FORWARD: 'slip+', BACKWARD: 'slip-', FREE: 'free', PRESCRIBED: 'prescribed'}
_EMPTY = np.zeros(0)
_TINY_SPEED = 1e-300
_MAX_SWITCHES_PER_MS = 200

def stick_tolerance(breakaway_force):
    return 0.0001 * abs(breakaway_force) + 0.001

class _TrustedInputs(ContactInputs):

    def require(self, name, law, *, positive=False, nonnegative=False):
        value = getattr(self, name)
        if value is None:
            return super().require(name, law, positive=positive, nonnegative=nonnegative)
        return value

@dataclass
class _Group:
    law: Any
    seals: list[int]
    sticky: bool
    has_map: bool
    temperatures: Any = None
    n_states: int = 0
_DEAD1, _DEAD2, _A1, _A2, _AROD, _STROKE, _BORE, _PS, _PA, _TS, _TA, _C, _B, _M, _BETA, _CENTRE, _H, _TW, _F0, _KL, _X0L, _CL, _INCL, _MASS, _KS, _CS, _DS, _THR1, _THR2, _CU1_L, _CU1_C, _CU1_E, _CU2_L, _CU2_C, _CU2_E, _AW1, _AW1_X, _AW2, _AW2_X, _AWROD, _AWROD_X, _NCONST = range(42)
_X, _V, _P1, _P2, _T1, _T2, _G0, _G1, _G2, _G3, _H0, _H1, _H2, _H3, _Q1, _Q2, _FPRESS, _FLOAD, _FSTOP, _NOUT = range(20)
# + 'supply_return_mass' (added with it to sealsim's bookkeeping): the bookkeeping states count
# in LSODA's RMS error norm, so the reference needs as many to take the same steps
BOOKKEEPING = ('supply_mass', 'exhaust_mass', 'mass_throughput', 'enthalpy', 'enthalpy_throughput', 'heat', 'gas_work', 'work_external', 'work_stop', 'work_friction', 'supply_return_mass')
_flow = jit(iso6358_flow, iso6358_mass_flow=jit(iso6358_mass_flow))
_series = jit(series_pair)
_openings = jit(openings)
_heat = jit(wall_heat_flow)
_stop = jit(end_stop_force)
_load = jit(load_force)
_dp = jit(pressure_difference, smooth_abs=jit(smooth_abs))
_sides = jit(side_pressures)

def _cushion_conductance(distance, length, conductance, entry):
    if length <= 0.0:
        return np.inf
    u = min(max((distance - (length - entry)) / entry, 0.0), 1.0)
    closed = 1.0 - u * u * (3.0 - 2.0 * u)
    return np.inf if closed <= 0.0 else conductance / closed
_cushion = jit(_cushion_conductance)

def _core_columns(y, spool, xs, vs, prescribed, c, codes, out, dp, sides, dy, book0):
    gm1 = AIR_HEAT_CAPACITY_RATIO - 1.0
    for j in range(y.shape[1]):
        if prescribed:
            x, v = (xs[j], vs[j])
        else:
            x, v = (y[0, j], y[1, j])
        m1, m2, u1, u2 = (y[2, j], y[3, j], y[4, j], y[5, j])
        vol1 = c[_DEAD1] + c[_A1] * x
        vol2 = c[_DEAD2] + c[_A2] * (c[_STROKE] - x)
        p1 = gm1 * u1 / vol1
        p2 = gm1 * u2 / vol2
        t1 = min(max(u1 / (max(m1, 1e-12) * AIR_CV), 20.0), 3000.0)
        t2 = min(max(u2 / (max(m2, 1e-12) * AIR_CV), 20.0), 3000.0)
        pa_, ar_, pb_, br_ = _openings(spool[j], c[_CENTRE])
        ps, pa, ts, ta = (c[_PS], c[_PA], c[_TS], c[_TA])
        line1 = _series(c[_THR1], _cushion(x, c[_CU1_L], c[_CU1_C], c[_CU1_E]))
        line2 = _series(c[_THR2], _cushion(c[_STROKE] - x, c[_CU2_L], c[_CU2_C], c[_CU2_E]))
        k0 = _series(c[_C] * pa_, line1 if p1 > ps else np.inf)
        k1 = _series(c[_C] * ar_, line1 if p1 > pa else np.inf)
        k2 = _series(c[_C] * pb_, line2 if p2 > ps else np.inf)
        k3 = _series(c[_C] * br_, line2 if p2 > pa else np.inf)
        g0 = _flow(ps, ts, p1, t1, k0, c[_B], c[_M], c[_BETA])
        g1 = _flow(p1, t1, pa, ta, k1, c[_B], c[_M], c[_BETA])
        g2 = _flow(ps, ts, p2, t2, k2, c[_B], c[_M], c[_BETA])
        g3 = _flow(p2, t2, pa, ta, k3, c[_B], c[_M], c[_BETA])
        h0 = AIR_CP * (ts if ps >= p1 else t1) * g0
        h1 = AIR_CP * (t1 if p1 >= pa else ta) * g1
        h2 = AIR_CP * (ts if ps >= p2 else t2) * g2
        h3 = AIR_CP * (t2 if p2 >= pa else ta) * g3
        # physics fix applied to the frozen copy: the rod-side chamber's wall has the rod's surface
        # and two annular faces (it had two full piston faces and no rod); the areas are affine
        # in x and evaluated in sealsim's order of operations (stick/slip amplifies a last bit)
        area_rod = c[_AWROD] + c[_AWROD_X] * x
        q1 = _heat(c[_H], c[_AW1] + c[_AW1_X] * x, c[_TW], t1)
        q2 = _heat(c[_H], c[_AW2] + c[_AW2_X] * x - area_rod, c[_TW], t2) + _heat(c[_H], area_rod, c[_TW], t2)
        f_press = p1 * c[_A1] - p2 * c[_A2] - pa * c[_AROD]
        f_load = _load(x, v, c[_F0], c[_KL], c[_X0L], c[_MASS], c[_INCL], c[_CL])
        f_stop = _stop(x, v, c[_STROKE], c[_KS], c[_CS], c[_DS])
        dvol1 = c[_A1] * v
        dvol2 = -c[_A2] * v
        o = out[:, j]
        o[_X], o[_V], o[_P1], o[_P2], o[_T1], o[_T2] = (x, v, p1, p2, t1, t2)
        o[_G0], o[_G1], o[_G2], o[_G3] = (g0, g1, g2, g3)
        o[_H0], o[_H1], o[_H2], o[_H3] = (h0, h1, h2, h3)
        o[_Q1], o[_Q2], o[_FPRESS], o[_FLOAD], o[_FSTOP] = (q1, q2, f_press, f_load, f_stop)
        for i in range(codes.shape[0]):
            dp[i, j] = _dp(codes[i], p1, p2, pa, 1000.0)
            sides[2 * i, j], sides[2 * i + 1, j] = _sides(codes[i], p1, p2, pa)
        dy[0, j] = 0.0 if prescribed else v
        dy[2, j] = g0 - g1
        dy[3, j] = g2 - g3
        dy[4, j] = h0 - h1 - p1 * dvol1 + q1
        dy[5, j] = h2 - h3 - p2 * dvol2 + q2
        b = book0
        dy[b, j] = g0 + g2
        dy[b + 1, j] = g1 + g3
        dy[b + 2, j] = abs(g0) + abs(g1) + abs(g2) + abs(g3)
        dy[b + 3, j] = h0 - h1 + h2 - h3
        dy[b + 4, j] = abs(h0) + abs(h1) + abs(h2) + abs(h3)
        dy[b + 5, j] = q1 + q2
        dy[b + 6, j] = p1 * dvol1 + p2 * dvol2
        dy[b + 7, j] = -(f_load + pa * c[_AROD]) * v
        dy[b + 8, j] = f_stop * v
        dy[b + 10, j] = max(-g0, 0.0) + max(-g2, 0.0)
_core = jit(_core_columns)

class PneumaticSystem:

    def __init__(self, case, seals: list[Seal]):
        self.case = case
        self.seals = seals
        cyl, air, valve = (case.cylinder, case.air, case.valve)
        self.a1, self.a2, self.a_rod = piston_areas(cyl.bore, cyl.rod_diameter)
        self.stroke = cyl.stroke
        self.mass = cyl.piston_mass + case.load.mass
        self.p_supply = air.supply_absolute
        self.p_amb = air.ambient_pressure
        self.t_supply = air.supply_air_temperature
        self.t_amb = air.temperature
        ctrl = case.controller
        self.duration = ctrl.duration
        self.schedule = self.schedule_of(case)
        self.position = ctrl.position if ctrl.mode == 'position' else None
        self.spool = SpoolMotion(self.schedule.times, self.schedule.commands, valve.time_constant, valve.delay, self.schedule.initial)
        meter = valve.meter_out
        self.throttle = (np.inf if meter is None or meter.conductance_a is None else meter.conductance_a, np.inf if meter is None or meter.conductance_b is None else meter.conductance_b)
        self.offsets, n = ([], 6)
        for seal in seals:
            self.offsets.append(n)
            n += seal.n_states
        self.n_dynamic = n
        self.book = {name: n + j for j, name in enumerate(BOOKKEEPING)}
        self.n_states = n + len(BOOKKEEPING)
        groups: dict[int, _Group] = {}
        for i, seal in enumerate(seals):
            g = groups.setdefault(id(seal.law), _Group(seal.law, [], seal.has_stiction, seal.contact_map is not None))
            g.seals.append(i)
            if (seal.contact_map is not None) != g.has_map:
                g.has_map = False
        self.groups = list(groups.values())
        self.sticky = any((g.sticky for g in self.groups)) and self.position is None
        self._sticky_rows = [i for g in self.groups if g.sticky for i in g.seals]
        self._smooth_rows = [i for g in self.groups if not g.sticky for i in g.seals]
        es, ld = (cyl.end_stops, case.load)
        c = np.zeros(_NCONST)
        c[_DEAD1], c[_DEAD2] = (cyl.dead_volume_cap, cyl.dead_volume_rod)
        c[_A1], c[_A2], c[_AROD] = (self.a1, self.a2, self.a_rod)
        c[_STROKE], c[_BORE] = (cyl.stroke, cyl.bore)
        walls = [chamber_wall_areas(x, cyl.stroke, cyl.bore, cyl.rod_diameter, self.a1, self.a2, cyl.dead_volume_cap, cyl.dead_volume_rod) for x in (0.0, cyl.stroke)]
        for (at0, slope), start, end in zip(((_AW1, _AW1_X), (_AW2, _AW2_X), (_AWROD, _AWROD_X)), *walls):
            c[at0], c[slope] = start, (end - start) / cyl.stroke
        c[_PS], c[_PA], c[_TS], c[_TA] = (self.p_supply, self.p_amb, self.t_supply, self.t_amb)
        c[_C], c[_B], c[_M], c[_BETA] = (valve.conductance, valve.critical_pressure_ratio, valve.subsonic_index, valve.laminar_ratio)
        c[_CENTRE] = CENTRES.index(valve.centre) if valve.type == '5/3' else 0
        c[_H] = air.heat_transfer_coefficient
        c[_TW] = body_temperature(case)
        c[_F0], c[_KL], c[_X0L], c[_CL] = (ld.force, ld.stiffness, ld.spring_free_position, ld.viscous)
        c[_INCL], c[_MASS] = (cyl.incline, self.mass)
        c[_KS], c[_CS], c[_DS] = (es.stiffness, es.damping, es.damping_depth)
        c[_THR1], c[_THR2] = self.throttle
        for base, cushion in ((_CU1_L, cyl.cushion_cap), (_CU2_L, cyl.cushion_rod)):
            if cushion is not None:
                c[base], c[base + 1], c[base + 2] = (cushion.length, cushion.conductance, cushion.entry)
        self._c = c
        self._codes = np.array([seal.location_code for seal in seals], dtype=np.int64)
        self._temps = [np.array([seal.temperature]) for seal in seals]
        self._slices = [slice(off, off + seal.n_states) for off, seal in zip(self.offsets, seals)]
        for g in self.groups:
            g.temperatures = np.array([seals[i].temperature for i in g.seals])
            g.n_states = g.law.n_states
        self._jac_scale = self.tolerances(1.0)[:self.n_dynamic]
        self._check_maps()

    @staticmethod
    def schedule_of(case) -> CommandSchedule:
        ctrl = case.controller
        if ctrl.mode == 'cycle':
            return CommandSchedule.from_cycle([(s.command, s.duration) for s in ctrl.steps], ctrl.duration, initial=ctrl.initial_command)
        u = COMMANDS[ctrl.command]
        return CommandSchedule(np.array([0.0]), np.array([u]), u)

    def _check_maps(self) -> None:
        dp_max = self.p_supply - self.p_amb
        for k, s in enumerate(self.seals):
            if s.contact_map is None:
                continue
            (plo, phi), (tlo, thi) = (s.contact_map.ranges['pressure'], s.contact_map.ranges['temperature'])
            where = f'seals[{k}] ({s.name!r})'
            if not tlo - 1e-09 <= s.temperature <= thi + 1e-09:
                raise InputError(f'{where}: seal temperature {s.temperature - 273.15:.6g} degC is outside its contact map ({tlo - 273.15:.6g} ... {thi - 273.15:.6g} degC); the map is not extrapolated -- extend its temperature grid or change the temperature')
            need = 0.0 if s.location == 'wiper' else dp_max
            if need > phi * (1 + 1e-09) or plo > 1e-09 * max(phi, 1.0):
                raise InputError(f'{where}: the pressure across the seal reaches {need / 100000.0:.6g} bar (supply gauge pressure) but its contact map covers {plo / 100000.0:.6g} ... {phi / 100000.0:.6g} bar; the map is not extrapolated -- extend its pressure grid or lower air.supply_pressure')

    def initial_state(self) -> np.ndarray:
        case = self.case
        u0 = self.schedule.initial
        openings = port_openings(u0, case.valve.type, case.valve.centre)
        p1 = self.p_supply if openings[0] > 0 else self.p_amb
        p2 = self.p_supply if openings[2] > 0 else self.p_amb
        if case.initial_position is not None:
            x0 = case.initial_position
        elif self.position is not None:
            x0 = float(self.position.value(0.0))
        else:   # (the one change since v0: the start at rest in the end stop, as sealsim's)
            x0 = self.stroke if u0 > 0 else 0.0
            x0 = rest_position(x0, self.stroke, float(
                piston_force(p1, p2, self.p_amb, self.a1, self.a2, self.a_rod)
                - load_force(x0, 0.0, case.load.force, case.load.stiffness,
                             case.load.spring_free_position, self.mass, case.cylinder.incline,
                             case.load.viscous)), case.cylinder.end_stops.stiffness,
                case.load.stiffness)
        v1 = case.cylinder.dead_volume_cap + self.a1 * x0
        v2 = case.cylinder.dead_volume_rod + self.a2 * (self.stroke - x0)
        m1 = float(gas_mass(p1, v1, self.t_amb))
        m2 = float(gas_mass(p2, v2, self.t_amb))
        y = np.zeros(self.n_states)
        y[:6] = [x0, 0.0, m1, m2, float(internal_energy(m1, self.t_amb)), float(internal_energy(m2, self.t_amb))]
        for s, off in zip(self.seals, self.offsets):
            y[off:off + s.n_states] = s.law.initial_state(1)[:, 0]
        return y

    def tolerances(self, rtol: float) -> np.ndarray:
        case = self.case
        volume = case.cylinder.dead_volume_cap + self.a1 * self.stroke
        m_scale = float(gas_mass(self.p_supply, volume, self.t_amb))
        u_scale = m_scale * AIR_CV * self.t_amb
        atol = np.empty(self.n_states)
        atol[:6] = [0.1, 30.0, m_scale, m_scale, u_scale, u_scale]
        for seal, off in zip(self.seals, self.offsets):
            for j, name in enumerate(seal.law.state_names):
                atol[off + j] = 10.0 if name == 'theta' else 0.001
        atol[self.n_dynamic:] = 1000.0
        return atol * rtol

    def evaluate(self, t, y, mode, full: bool=False):
        y = np.asarray(y, dtype=float)
        column = y.ndim == 1
        if column:
            y = y[:, None]
        k = y.shape[1]
        if np.ndim(t) == 0:
            spool = np.full(k, self.spool.scalar(float(t)))
        else:
            spool = self.spool(t)
        prescribed = mode == PRESCRIBED
        if prescribed:
            tt = np.broadcast_to(np.asarray(t, dtype=float), (k,))
            xs = np.asarray(self.position.value(tt), dtype=float)
            vs = np.asarray(self.position.derivative(tt), dtype=float)
        else:
            xs = vs = _EMPTY
        nseal = len(self.seals)
        out = np.empty((_NOUT, k))
        dp = np.empty((nseal, k))
        sides = np.empty((2 * nseal, k))
        dy = np.zeros_like(y)
        _core(y, spool, xs, vs, prescribed, self._c, self._codes, out, dp, sides, dy, self.n_dynamic)
        v = out[_V]
        f_drive = out[_FPRESS] - out[_FLOAD] + out[_FSTOP]
        f_seal = np.zeros((nseal, k))
        need_brk = self.sticky and (mode == STICK or full)
        brk = np.zeros((nseal, k)) if need_brk else None
        loads = [None] * nseal
        for grp in self.groups:
            idx = grp.seals
            for i in idx:
                loads[i] = self.seals[i].loads_at(dp[i])
            if len(idx) == 1:
                i = idx[0]
                fn, width, _ = loads[i]
                z = y[self._slices[i]]
                side_a, side_b = (sides[2 * i], sides[2 * i + 1])
                temps = self._temps[i]
            else:
                fn = np.concatenate([loads[i][0] for i in idx])
                width = np.concatenate([loads[i][1] for i in idx])
                z = np.concatenate([y[self._slices[i]] for i in idx], axis=1)
                side_a = np.concatenate([sides[2 * i] for i in idx])
                side_b = np.concatenate([sides[2 * i + 1] for i in idx])
                temps = np.repeat(grp.temperatures, k)
            inputs = _TrustedInputs(normal_force=np.maximum(fn, 1e-09) if grp.has_map else None, contact_width=width if grp.has_map else None, pressure_a=side_a, pressure_b=side_b, temperature=temps)
            if not grp.sticky or mode in (FREE, PRESCRIBED):
                vv = v
            elif mode == STICK:
                vv = np.zeros(k)
            else:
                d = float(mode)
                vv = d * np.maximum(d * v, _TINY_SPEED)
            if len(idx) > 1:
                vv = np.concatenate([vv] * len(idx))
            dz = grp.law.derivatives(z, vv, inputs) if grp.n_states else None
            force = None if grp.sticky and mode == STICK else grp.law.force(z, vv, inputs)
            b_force = grp.law.breakaway_force(z, inputs) if grp.sticky and need_brk else None
            for j, i in enumerate(idx):
                sl = slice(j * k, (j + 1) * k)
                if dz is not None:
                    dy[self._slices[i]] = dz[:, sl]
                if force is not None:
                    f_seal[i] = force[sl]
                if b_force is not None:
                    brk[i] = b_force[sl]
        hold = None
        if mode == STICK:
            rows = self._sticky_rows
            hold = f_drive - f_seal[self._smooth_rows].sum(axis=0)
            total = brk[rows].sum(axis=0)
            share = brk[rows] / np.where(total > 0, total, 1.0)
            f_seal[rows] = np.where(total > 0, share, 1.0 / len(rows)) * hold
        f_fric = f_seal.sum(axis=0) if nseal > 1 else f_seal[0] if nseal else np.zeros(k)
        if mode in (FORWARD, BACKWARD, FREE):
            dy[1] = (f_drive - f_fric) / self.mass
        dy[self.n_dynamic + BOOKKEEPING.index('work_friction')] = f_fric * v
        if not full:
            return dy[:, 0] if column else dy
        return {'dy': dy, 'x': out[_X], 'v': v, 'p1': out[_P1], 'p2': out[_P2], 'T1': out[_T1], 'T2': out[_T2], 'spool': spool, 'flow': out[_G0:_G3 + 1], 'enthalpy': out[_H0:_H3 + 1], 'q1': out[_Q1], 'q2': out[_Q2], 'f_press': out[_FPRESS], 'f_load': out[_FLOAD], 'f_stop': out[_FSTOP], 'f_seal': f_seal, 'f_fric': f_fric, 'hold': hold, 'breakaway': brk, 'loads': loads}

    def jacobian(self, t, y, mode):
        n = self.n_dynamic
        f0 = self.evaluate(t, y, mode)
        h = 1.5e-08 * np.maximum(np.abs(y[:n]), self._jac_scale)
        cols = np.repeat(y[:, None], n, axis=1)
        cols[np.arange(n), np.arange(n)] += h
        f = self.evaluate(t, cols, mode)
        jac = np.zeros((y.size, y.size))
        jac[:, :n] = (f - f0[:, None]) / h
        return jac

    def stick_margin(self, t, y) -> tuple[float, float]:
        y0 = np.array(y, dtype=float)
        y0[1] = 0.0
        d = self.evaluate(t, y0, STICK, full=True)
        brk = float(d['breakaway'][self._sticky_rows].sum(axis=0)[0])
        return (float(d['hold'][0]), brk + stick_tolerance(brk))

    def next_mode_at_rest(self, t, y) -> int:
        hold, brk = self.stick_margin(t, y)
        stuck, _ = resolve_stick(hold, brk)
        if bool(stuck):
            return STICK
        return FORWARD if hold > 0 else BACKWARD

    def events(self, mode, speed_resolution=0.0):
        if mode in (FORWARD, BACKWARD):
            d = float(mode)

            def stop(t, y, *args):
                return d * y[1] + speed_resolution
            stop.terminal, stop.direction = (True, -1)
            return [stop]
        if mode == STICK:

            def breakaway(t, y, *args):
                hold, brk = self.stick_margin(t, y)
                return abs(hold) - brk
            breakaway.terminal, breakaway.direction = (True, 1)
            return [breakaway]
        return []

@dataclass
class PneumaticResult:
    case: Any
    timeseries: pd.DataFrame
    balances: dict
    stats: dict
    notes: list = field(default_factory=list)
    seal_names: list = field(default_factory=list)

    def summary(self) -> dict[str, Any]:
        from sealsim.pneumatic.summary import summarize
        return summarize(self)
TIMESERIES_COLUMNS = ['time_s', 'x_m', 'v_m_s', 'p1_bar', 'p2_bar', 'T1_C', 'T2_C', 'valve_command', 'spool', 'mode', 'F_friction_N', 'F_pressure_N']

def simulate(case, seals: list[Seal] | None=None, base_dir: str | Path='.', progress=None) -> PneumaticResult:
    if seals is None:
        seals = build_seals(case, base_dir)
    system = PneumaticSystem(case, seals)
    wall0 = _time.perf_counter()
    segments = _integrate(system, progress)
    wall = _time.perf_counter() - wall0
    frame, diag = _sample(system, segments)
    balances = _balances(system, segments)
    notes = [f'seal {s.name!r}: {n}' for s in seals for n in s.notes] + _notes(system, diag)
    stats = {'segments': len(segments), 'steps': int(sum((len(s['sol'].t) - 1 for s in segments))), 'rhs_evaluations': int(sum((s['sol'].nfev for s in segments))), 'jacobian_evaluations': int(sum((s['sol'].njev for s in segments))), 'mode_switches': int(sum((1 for a, b in zip(segments, segments[1:]) if a['mode'] != b['mode']))), 'wall_time_s': wall, 'method': case.solver.method}
    return PneumaticResult(case, frame, balances, stats, notes, [s.name for s in seals])

def _where(system: PneumaticSystem, t: float, y: np.ndarray, mode: int) -> str:
    d = system.evaluate(t, y, mode, full=True)
    return f"t = {t:.6g} s, x = {float(d['x'][0]) * 1000.0:.4g} mm, v = {float(d['v'][0]):.4g} m/s, p1 = {float(d['p1'][0]) / 100000.0:.4g} bar, p2 = {float(d['p2'][0]) / 100000.0:.4g} bar, T1 = {float(d['T1'][0]) - 273.15:.4g} degC, T2 = {float(d['T2'][0]) - 273.15:.4g} degC, mode {MODES[mode]}"

def _integrate(system: PneumaticSystem, progress=None) -> list[dict]:
    case = system.case
    end = system.duration
    rtol = case.solver.rtol
    atol = system.tolerances(rtol)
    y = system.initial_state()
    t = 0.0
    breaks = sorted({float(a) for a in system.spool.arrivals if 0.0 < a < end} | {end})
    if system.position is not None:
        mode = PRESCRIBED
    elif system.sticky:
        mode = system.next_mode_at_rest(t, y)
    else:
        mode = FREE
    segments = []
    recent: list[float] = []
    while t < end * (1 - 1e-12):
        t_next = next((b for b in breaks if b > t + 1e-12 * max(end, 1.0)))
        events = system.events(mode, 0.1 * atol[1])
        try:
            sol = solve_ivp(system.evaluate, (t, t_next), y, method=case.solver.method, rtol=rtol, atol=atol, args=(mode,), events=events or None, dense_output=True, max_step=case.solver.max_step, jac=system.jacobian)
        except (ValueError, FloatingPointError, ZeroDivisionError) as exc:
            raise ConvergenceError(f'pneumatic simulation failed at {_where(system, t, y, mode)}: {exc}') from None
        if sol.status < 0 or not np.all(np.isfinite(sol.y)):
            t_fail = float(sol.t[-1])
            y_fail = sol.y[:, -1] if np.all(np.isfinite(sol.y[:, -1])) else y
            raise ConvergenceError(f'pneumatic simulation: the integrator ({case.solver.method}) failed at {_where(system, t_fail, y_fail, mode)}: {sol.message}; try a smaller solver.max_step or a different solver.method')
        segments.append({'t0': t, 't1': float(sol.t[-1]), 'mode': mode, 'sol': sol})
        y = sol.y[:, -1].copy()
        t = float(sol.t[-1])
        if sol.status == 1:
            if mode in (FORWARD, BACKWARD):
                y[1] = 0.0
                mode = system.next_mode_at_rest(t, y)
            else:
                hold, _ = system.stick_margin(t, y)
                mode = FORWARD if hold > 0 else BACKWARD
            recent = [r for r in recent if r > t - 0.001] + [t]
            if len(recent) > _MAX_SWITCHES_PER_MS:
                raise ConvergenceError(f'pneumatic simulation: stick/slip chattering ({len(recent)} transitions within 1 ms) at {_where(system, t, y, mode)}; the contact cannot decide between sticking and sliding -- check the friction parameters')
        if progress is not None:
            progress(t, end)
    return segments

def _sample(system: PneumaticSystem, segments: list[dict]):
    case = system.case
    end = system.duration
    dt = case.output.sample_interval
    grid = np.arange(0.0, end + 0.5 * dt, dt)
    grid = grid[grid <= end * (1 + 1e-12)]
    parts = []
    for j, seg in enumerate(segments):
        last = j == len(segments) - 1
        sel = (grid >= seg['t0']) & (grid <= seg['t1'] if last else grid < seg['t1'])
        ts = grid[sel]
        if ts.size == 0:
            continue
        ys = seg['sol'].sol(ts)
        if seg['mode'] == STICK:
            ys[1] = 0.0
        parts.append(_diagnostics(system, ts, ys, seg['mode']))
    diag = {key: np.concatenate([p[key] for p in parts], axis=-1) for key in parts[0]}
    frame = _frame(system, diag)
    return (frame, diag)

def _diagnostics(system, ts, ys, mode) -> dict[str, np.ndarray]:
    d = system.evaluate(ts, ys, mode, full=True)
    out = {'time': ts, 'x': d['x'], 'v': d['v'], 'p1': d['p1'], 'p2': d['p2'], 'T1': d['T1'], 'T2': d['T2'], 'spool': np.asarray(d['spool'], dtype=float), 'command': system.schedule.command_at(ts), 'mode': np.full(ts.shape, mode), 'f_fric': d['f_fric'], 'f_press': d['f_press'], 'f_seal': d['f_seal']}
    for i, s in enumerate(system.seals):
        fn, b, dp = d['loads'][i]
        out[f'fn{i}'] = np.broadcast_to(np.asarray(fn, dtype=float), ts.shape)
        out[f'b{i}'] = np.broadcast_to(np.asarray(b, dtype=float), ts.shape)
        out[f'dp{i}'] = np.broadcast_to(np.asarray(dp, dtype=float), ts.shape)
        names = s.law.state_names
        if 'theta' in names:
            out[f'theta{i}'] = ys[system.offsets[i] + names.index('theta')]
    return out

def _frame(system, diag) -> pd.DataFrame:
    cols = {'time_s': diag['time'], 'x_m': diag['x'], 'v_m_s': diag['v'], 'p1_bar': diag['p1'] / 100000.0, 'p2_bar': diag['p2'] / 100000.0, 'T1_C': diag['T1'] - 273.15, 'T2_C': diag['T2'] - 273.15, 'valve_command': diag['command'], 'spool': diag['spool'], 'mode': [MODES[int(m)] for m in diag['mode']], 'F_friction_N': diag['f_fric'], 'F_pressure_N': diag['f_press']}
    for i, s in enumerate(system.seals):
        name = s.name
        cols[f'F_{name}_N'] = diag['f_seal'][i]
        if s.contact_map is not None:
            cols[f'F_N_{name}_N'] = diag[f'fn{i}']
            cols[f'b_{name}_mm'] = diag[f'b{i}'] * 1000.0
        cols[f'dp_{name}_bar'] = diag[f'dp{i}'] / 100000.0
        if f'theta{i}' in diag:
            cols[f'theta_{name}'] = diag[f'theta{i}']
    return pd.DataFrame(cols)

def _balances(system: PneumaticSystem, segments: list[dict]) -> dict[str, float]:
    y0 = segments[0]['sol'].y[:, 0]
    y1 = segments[-1]['sol'].y[:, -1].copy()
    if segments[-1]['mode'] == STICK:
        y1[1] = 0.0
    book = {name: float(y1[i] - y0[i]) for name, i in system.book.items()}
    if system.position is not None:
        v0 = float(system.position.derivative(segments[0]['t0']))
        v1 = float(system.position.derivative(segments[-1]['t1']))
    else:
        v0, v1 = (float(y0[1]), float(y1[1]))
    stored_mass = float(y1[2] + y1[3] - y0[2] - y0[3])
    stored_energy = float(y1[4] + y1[5] - y0[4] - y0[5])
    kinetic = 0.5 * system.mass * (v1 ** 2 - v0 ** 2)
    mass_in = book['supply_mass'] - book['exhaust_mass']
    mass_scale = max(book['mass_throughput'], float(y0[2] + y0[3]))
    if system.position is None:
        energy_in = book['enthalpy'] + book['heat'] + book['work_external'] + book['work_stop'] - book['work_friction']
        energy_change = stored_energy + kinetic
        throughput = book['enthalpy_throughput'] + abs(book['heat']) + abs(book['work_external']) + abs(book['work_stop']) + abs(book['work_friction']) + abs(kinetic)
    else:
        energy_in = book['enthalpy'] + book['heat'] - book['gas_work']
        energy_change = stored_energy
        throughput = book['enthalpy_throughput'] + abs(book['heat']) + abs(book['gas_work'])
    return {'air_mass_change_kg': stored_mass, 'supply_mass_kg': book['supply_mass'], 'exhaust_mass_kg': book['exhaust_mass'], 'air_energy_change_J': stored_energy, 'kinetic_energy_change_J': kinetic, 'enthalpy_in_J': book['enthalpy'], 'wall_heat_J': book['heat'], 'gas_work_J': book['gas_work'], 'external_work_J': book['work_external'], 'stop_work_J': book['work_stop'], 'friction_work_J': book['work_friction'], 'mass_balance_rel_error': abs(stored_mass - mass_in) / max(mass_scale, 1e-300), 'energy_balance_rel_error': abs(energy_change - energy_in) / max(throughput, 1e-300), 'air_consumption_NL': book['supply_mass'] / ANR_DENSITY * 1000.0}

def _notes(system: PneumaticSystem, diag) -> list[str]:
    notes = []
    for i, s in enumerate(system.seals):
        if s.contact_map is None:
            continue
        hi = s.contact_map.ranges['pressure'][1]
        over = diag[f'dp{i}'] > hi * (1 + 1e-09)
        if np.any(over):
            notes.append(f"seal {s.name!r}: the pressure difference exceeded its contact map ({hi / 100000.0:.4g} bar) by up to {(diag[f'dp{i}'].max() - hi) / 100000.0:.3g} bar in {over.mean() * 100:.2g} % of the samples; F_N and b were held at the map edge")
    return notes
__all__ += ['BOOKKEEPING', 'TIMESERIES_COLUMNS']


# -- added for the tests: the reference run with the frozen friction laws --------------------
def reference_seals(seals):
    """Copies of ``seals`` whose friction laws are the frozen numpy classes (one object per
    law object, so seals that shared a law still share it)."""
    import dataclasses

    from reference_v0 import friction_laws as old

    classes = {"coulomb": old.CoulombViscous, "stribeck": old.Stribeck, "lugre": old.LuGre,
               "dahl": old.Dahl, "gms": old.GMS, "theta": old.Theta}
    made = {}
    out = []
    for seal in seals:
        key = id(seal.law)
        if key not in made:
            made[key] = classes[seal.law.name](seal.law.params)
        out.append(dataclasses.replace(seal, law=made[key]))
    return out


def simulate_reference(case, seals=None, base_dir='.', progress=None):
    """The pre-issue-13 simulation of a case (frozen right-hand side and friction laws)."""
    if seals is None:
        seals = build_seals(case, base_dir)
    return simulate(case, reference_seals(seals), base_dir, progress)
