"""The assembled pneumatic model of a case: constants, state layout, the compiled tables.

:class:`PneumaticSystem` turns a validated case and its seal objects into the tables of the
compiled right-hand side (:mod:`.rhs`) and offers the right-hand side, its Jacobian and the
stick/slip quantities as Python callables for the integrator (:mod:`.integrate`).
"""

from __future__ import annotations

import math
import weakref

import numpy as np

from sealsim.errors import InputError, ModelError
from sealsim.friction.compiled import law_parameters
from sealsim.friction.kernels import walther_viscosity_ratio
from sealsim.friction.hybrid import resolve_stick
from sealsim.pneumatic import rhs
from sealsim.pneumatic.case import body_temperature
from sealsim.pneumatic.chambers import (
    AIR_CV,
    chamber_wall_areas,
    free_convection_coefficient,
    gas_mass,
    internal_energy,
)
from sealsim.pneumatic.contact_maps import FEContactMap, glassy_reason, tabulated_map_tables
from sealsim.pneumatic.controller import command_schedule
from sealsim.pneumatic.cylinder import load_force, piston_areas, piston_force, rest_position
from sealsim.pneumatic.seal_heating import (
    METALS,
    ambient_coefficient,
    conduction_conductance,
    effusivity,
    oring_volume,
    seal_flank_area,
)
from sealsim.pneumatic.seals import Seal
from sealsim.pneumatic.valve import CENTRES, SpoolMotion, port_openings
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["PneumaticSystem", "law_parameters", "stick_tolerance"]

_LAW_WIDTH = 17          # columns of law_par (Θ: 17; GMS needs 7 + 2·N)
#: error scales of friction-law states by name (see PneumaticSystem.tolerances); others 1 mm
_STATE_SCALES = {"theta": 10.0, "film_speed": 30.0}


def stick_tolerance(breakaway_force):
    """Force [N] by which the holding force may exceed the break-away force and the contact
    still counts as sticking: 1e-4 relative plus 1 mN.

    Without it a piston creeping at the friction limit (e.g. pressed into an elastic end stop
    while the exhaust pressure decays: F_req and F_brk grow together, the creep speed is nm/s)
    would alternate between stick and slip at every step of the integrator; with it, such a
    creep advances in steps of the tolerance (a break-away force 0.01 % high)."""
    return 1e-4 * abs(breakaway_force) + 1e-3


class PneumaticSystem:
    """The assembled model of a case (SI constants, seals, controller); see
    :mod:`sealsim.pneumatic.simulation` for the equations.

    Parameters
    ----------
    case : PneumaticCase
        Validated case.
    seals : list of Seal
        Seal objects (:func:`sealsim.pneumatic.case.build_seals`).
    """

    def __init__(self, case, seals: list[Seal]):
        self.case = case
        self.seals = seals
        cyl, air, valve = case.cylinder, case.air, case.valve
        self.a1, self.a2, self.a_rod = piston_areas(cyl.bore, cyl.rod_diameter)
        self.stroke = cyl.stroke
        self.mass = cyl.piston_mass + case.load.mass
        self.p_supply = air.supply_absolute
        self.p_amb = air.ambient_pressure
        self.t_supply = air.supply_air_temperature
        self.t_amb = air.temperature
        ctrl = case.controller
        self.duration = ctrl.duration
        self.schedule = command_schedule(case)
        self.position = ctrl.position if ctrl.mode == "position" else None
        self.spool = SpoolMotion(self.schedule.times, self.schedule.commands,
                                 valve.time_constant, valve.delay, self.schedule.initial)
        meter = valve.meter_out
        throttle = (np.inf if meter is None or meter.conductance_a is None
                    else meter.conductance_a,
                    np.inf if meter is None or meter.conductance_b is None
                    else meter.conductance_b)
        thermal = case.thermal
        self.heating = thermal is not None and thermal.seal_heating
        # state layout: x, v, m1, m2, U1, U2 | friction states | temperatures | bookkeeping
        self.offsets, n = [], 6
        for seal in seals:
            self.offsets.append(n)
            n += seal.n_states
        self.temperature_offset = n
        if self.heating:
            n += len(seals) + 2                # seals, tube, rod
        self.n_dynamic = n
        names = rhs.BOOKKEEPING + (rhs.THERMAL_BOOKKEEPING if self.heating else ())
        self.book = {name: n + j for j, name in enumerate(names)}
        self.n_states = n + len(names)
        self.sticky = any(s.has_stiction for s in seals) and self.position is None

        es, ld = cyl.end_stops, case.load
        c = np.zeros(rhs.C_NCONST)
        c[rhs.C_DEAD1], c[rhs.C_DEAD2] = cyl.dead_volume_cap, cyl.dead_volume_rod
        c[rhs.C_A1], c[rhs.C_A2], c[rhs.C_AROD] = self.a1, self.a2, self.a_rod
        c[rhs.C_STROKE], c[rhs.C_BORE] = cyl.stroke, cyl.bore
        # wall areas, affine in x: the values at x = 0 and the slopes, from the one formula
        walls = (chamber_wall_areas(x, cyl.stroke, cyl.bore, cyl.rod_diameter, self.a1, self.a2,
                                    cyl.dead_volume_cap, cyl.dead_volume_rod)
                 for x in (0.0, cyl.stroke))
        for (at0, slope), start, end in zip(((rhs.C_AW1, rhs.C_AW1_X), (rhs.C_AW2, rhs.C_AW2_X),
                                             (rhs.C_AWROD, rhs.C_AWROD_X)), *walls):
            c[at0], c[slope] = start, (end - start) / cyl.stroke
        c[rhs.C_PS], c[rhs.C_PA] = self.p_supply, self.p_amb
        c[rhs.C_TS], c[rhs.C_TA] = self.t_supply, self.t_amb
        c[rhs.C_C], c[rhs.C_B], c[rhs.C_M], c[rhs.C_BETA] = (
            valve.conductance, valve.critical_pressure_ratio, valve.subsonic_index,
            valve.laminar_ratio)
        c[rhs.C_CENTRE] = CENTRES.index(valve.centre) if valve.type == "5/3" else 0
        c[rhs.C_H] = air.heat_transfer_coefficient
        c[rhs.C_HFREE] = 1.0 if air.heat_transfer == "free_convection" else 0.0
        c[rhs.C_TW] = body_temperature(case)
        c[rhs.C_F0], c[rhs.C_KL], c[rhs.C_X0L], c[rhs.C_CL] = (
            ld.force, ld.stiffness, ld.spring_free_position, ld.viscous)
        c[rhs.C_INCL], c[rhs.C_MASS] = cyl.incline, self.mass
        c[rhs.C_KS], c[rhs.C_CS], c[rhs.C_DS] = es.stiffness, es.damping, es.damping_depth
        c[rhs.C_THR1], c[rhs.C_THR2] = throttle
        for base, cushion in ((rhs.C_CU1_L, cyl.cushion_cap), (rhs.C_CU2_L, cyl.cushion_rod)):
            if cushion is not None:
                c[base], c[base + 1], c[base + 2] = (cushion.length, cushion.conductance,
                                                     cushion.entry)
        c[rhs.C_BOOK] = self.n_dynamic
        c[rhs.C_HEAT] = 1.0 if self.heating else 0.0
        c[rhs.C_TOFF] = self.temperature_offset
        c[rhs.C_TAMB] = self.t_amb
        c[rhs.C_SPOOL_TAU] = self.spool.time_constant
        c[rhs.C_SPOOL_INIT] = self.spool.initial
        self._c = c
        self._spool = np.ascontiguousarray(np.stack([self.spool.arrivals, self.spool.targets,
                                                     self.spool.starts]), dtype=float)
        c[rhs.C_PROFILE_KIND], self._profile = _profile_table(self.position)

        nseal = len(seals)
        seal_int = np.zeros((nseal, rhs.SI_NCOLS), dtype=np.int64)
        law_par = np.zeros((nseal, _LAW_WIDTH))
        seal_therm = np.zeros((nseal, rhs.ST_NCOLS))
        map_int = np.zeros((nseal, 12), dtype=np.int64)
        fric_int = np.zeros((nseal, 5), dtype=np.int64)
        map_chunks, used = [], 0
        fric_chunks, fric_used = [], 0
        for i, seal in enumerate(seals):
            diameter = cyl.bore if seal.location == "piston" else cyl.rod_diameter
            values = law_parameters(seal.law, diameter)
            if values.size > law_par.shape[1]:
                law_par = np.pad(law_par, ((0, 0), (0, values.size - law_par.shape[1])))
            law_par[i, :values.size] = values
            if seal.friction_table is not None:
                frow, fdata = seal.friction_table.tables()
                fric_int[i, 0] = fric_used
                fric_int[i, 1:] = frow
                fric_chunks.append(fdata)
                fric_used += fdata.size
            seal_int[i, rhs.SI_LAW] = rhs.LAW_CODES[seal.law.name]
            seal_int[i, rhs.SI_LOC] = seal.location_code
            seal_int[i, rhs.SI_OFF] = self.offsets[i]
            seal_int[i, rhs.SI_STICKY] = int(seal.has_stiction)
            seal_int[i, rhs.SI_HEATED] = int(self.heating)
            seal_int[i, rhs.SI_COUNTER] = rhs.NODE_TUBE if seal.location == "piston" \
                else rhs.NODE_ROD
            seal_int[i, rhs.SI_GROOVE] = rhs.NODE_ROD if seal.location == "piston" \
                else rhs.NODE_TUBE
            seal_therm[i, rhs.ST_TCONST] = seal.temperature
            row, data = self._map_tables(seal)
            if row is not None:
                row = row.copy()
                row[1] += used
                map_int[i, :row.size] = row
                map_chunks.append(data)
                used += data.size
        if not self.heating:
            _constant_viscosity(seal_int, law_par, seals)
        self._map_data = np.concatenate(map_chunks) if map_chunks else np.zeros(1)
        self._seal_int, self._law_par, self._seal_therm = seal_int, law_par, seal_therm
        self._map_int = map_int
        self.thermal_notes: list[str] = []
        if self.heating:
            self._thermal_setup()
        self._fric_int = fric_int
        self._fric_data = _joined(fric_chunks) if fric_chunks else np.zeros(1)
        self.tables = (self._c, self._spool, self._profile, self._seal_int, self._law_par,
                       self._seal_therm, self._map_int, self._map_data, self._fric_int,
                       self._fric_data)
        self.n_diag = rhs.D_NFIXED + rhs.DS_NROWS * nseal
        self._diag1 = np.zeros((self.n_diag, 1))
        self._dy = np.zeros(self.n_states)
        self._jac_scale = self.tolerances(1.0)[:self.n_dynamic]
        self._work = [np.zeros(self.n_states) for _ in range(3)]
        self._check_maps()

    # -- set-up -----------------------------------------------------------------------------
    @staticmethod
    def schedule_of(case):
        """The valve commands of a case (:func:`sealsim.pneumatic.controller.command_schedule`)."""
        return command_schedule(case)

    def _map_tables(self, seal: Seal):
        """(int row, float data) of the seal's contact map for the compiled right-hand side."""
        cm = seal.contact_map
        if cm is None:
            return None, None
        if isinstance(cm, FEContactMap):
            return cm.tables()
        preload = getattr(cm, "preload_at", None)
        if preload is not None and not self.heating:
            # the analytic estimate at the seal's constant temperature: exact, compiled
            f0, modulus = preload(float(seal.temperature))
            row = np.zeros(12, dtype=np.int64)
            row[0] = rhs.MAP_ANALYTIC
            return row, np.array([float(f0), float(modulus), cm.cord_diameter,
                                  cm.sliding_diameter])
        # any other map (or a heated seal): tabulated over its temperature range
        return tabulated_map_tables(cm, cm.ranges["temperature"])

    def _thermal_setup(self) -> None:
        """Heat capacities and conductances of the seal, tube and rod nodes
        (:mod:`.seal_heating`)."""
        from sealsim.properties.elastomers import get_elastomer

        case, th = self.case, self.case.thermal
        cyl = case.cylinder
        tube, rod = METALS[th.tube_material], METALS[th.rod_material]
        t_amb, t_body = self.t_amb, body_temperature(case)
        h_air = case.air.heat_transfer_coefficient
        if case.air.heat_transfer == "free_convection":   # a constant for the seal flanks:
            # the chamber air at supply pressure, 10 K from the body (a typical stroke's swing)
            h_air = float(free_convection_coefficient(self.p_supply, t_body - 10.0, t_body,
                                                      cyl.bore))
        for i, (seal, spec) in enumerate(zip(self.seals, case.seals)):
            cord = _cord_diameter(spec)
            if cord is None:
                self._seal_int[i, rhs.SI_HEATED] = 0
                self.thermal_notes.append(
                    f"seal {seal.name!r} has no cord diameter (thermal.cord_diameter or an "
                    "analytic map): it is not a thermal node, its friction heat goes into its "
                    "counterface")
                continue
            elastomer = get_elastomer(_elastomer_name(spec))
            diameter = cyl.bore if seal.location == "piston" else cyl.rod_diameter
            ring = diameter - cord if seal.location == "piston" else diameter + cord
            if seal.contact_map is not None:
                _, width0 = seal.contact_map.evaluate(0.0, float(seal.temperature))
                width0 = float(width0)
            else:
                width0 = 0.25 * cord       # a lightly loaded wiper lip [R]
            metal = tube if seal.location == "piston" else rod
            wall = th.tube_wall_thickness if seal.location == "piston" \
                else 0.5 * cyl.rod_diameter
            row = self._seal_therm[i]
            row[rhs.ST_CAP] = (elastomer.density * elastomer.specific_heat
                               * oring_volume(ring, cord))
            row[rhs.ST_AC] = math.pi * diameter
            row[rhs.ST_WIDTH] = width0
            row[rhs.ST_EFF] = float(effusivity(metal["conductivity"], metal["density"],
                                               metal["specific_heat"]))
            row[rhs.ST_HSTAT] = metal["conductivity"] / wall
            row[rhs.ST_GGROOVE] = float(conduction_conductance(
                elastomer.thermal_conductivity, math.pi * ring * width0, 0.5 * cord))
            flank = float(seal_flank_area(ring, cord, width0))
            # rubber (ε ≈ 0.9) at the nominal rise, as the tube and rod
            h_out = ambient_coefficient(ring, t_body + th.nominal_temperature_rise, t_amb, 0.9)
            sides = {"piston": (h_air, h_air, 0.0), "rod": (0.0, h_air, h_out),
                     "wiper": (0.0, 0.0, 2.0 * h_out)}[seal.location]
            row[rhs.ST_AIR1], row[rhs.ST_AIR2], row[rhs.ST_AMB] = (s * flank for s in sides)
        tube_od = cyl.bore + 2.0 * th.tube_wall_thickness
        tube_length = cyl.stroke + th.head_length
        rod_length = cyl.stroke + th.head_length
        c = self._c
        c[rhs.C_TUBE_CAP] = tube["density"] * tube["specific_heat"] * math.pi / 4.0 * (
            tube_od ** 2 - cyl.bore ** 2) * tube_length
        # the rod node is the moving metal, piston and rod (the piston seal's groove heats the
        # piston): cylinder.piston_mass ("piston + rod") of the rod's metal, at least the rod
        rod_mass = rod["density"] * math.pi / 4.0 * cyl.rod_diameter ** 2 * rod_length
        if cyl.piston_mass < rod_mass:
            self.thermal_notes.append(
                f"cylinder.piston_mass ({cyl.piston_mass:.4g} kg, piston + rod) is less than the "
                f"rod's own mass ({rod_mass:.4g} kg, {th.rod_material}, stroke + head_length "
                "long): the rod node has the rod's heat capacity")
        c[rhs.C_ROD_CAP] = rod["specific_heat"] * max(cyl.piston_mass, rod_mass)
        nominal = t_body + th.nominal_temperature_rise
        c[rhs.C_TUBE_G] = ambient_coefficient(tube_od, nominal, t_amb, tube["emissivity"]) * (
            math.pi * tube_od * tube_length)
        # per metre of rod outside the cylinder (the piston's extension x: see rhs.C_ROD_G_X)
        c[rhs.C_ROD_G_X] = ambient_coefficient(cyl.rod_diameter, nominal, t_amb,
                                               rod["emissivity"]) * math.pi * cyl.rod_diameter
        self.thermal_constants = {
            "tube_heat_capacity_J_K": float(c[rhs.C_TUBE_CAP]),
            "rod_heat_capacity_J_K": float(c[rhs.C_ROD_CAP]),
            "tube_to_ambient_W_K": float(c[rhs.C_TUBE_G]),
            "rod_to_ambient_extended_W_K": float(c[rhs.C_ROD_G_X] * cyl.stroke),
            "seals": {s.name: {"heat_capacity_J_K": float(self._seal_therm[i, rhs.ST_CAP]),
                               "to_groove_W_K": float(self._seal_therm[i, rhs.ST_GGROOVE]),
                               "static_contact_W_m2K": float(self._seal_therm[i, rhs.ST_HSTAT])}
                      for i, s in enumerate(self.seals) if self._seal_int[i, rhs.SI_HEATED]}}

    def _check_maps(self) -> None:
        """Refuse to extrapolate: the seal temperature and the supply pressure difference must
        lie inside each contact map."""
        dp_max = self.p_supply - self.p_amb
        for k, s in enumerate(self.seals):
            if s.contact_map is None:
                continue
            (plo, phi), (tlo, thi) = (s.contact_map.ranges["pressure"],
                                      s.contact_map.ranges["temperature"])
            where = f"seals[{k}] ({s.name!r})"
            if not (tlo - 1e-9 <= s.temperature <= thi + 1e-9):
                reason = glassy_reason(s.contact_map, s.temperature)
                raise InputError(
                    f"{where}: seal temperature {s.temperature - ZERO_CELSIUS_K:.6g} degC is "
                    f"outside its contact map ({tlo - ZERO_CELSIUS_K:.6g} ... "
                    f"{thi - ZERO_CELSIUS_K:.6g} degC)" + (reason or (
                        "; the map is not extrapolated -- extend its temperature grid or change "
                        "the temperature")))
            need = 0.0 if s.location == "wiper" else dp_max
            if need > phi * (1 + 1e-9) or plo > 1e-9 * max(phi, 1.0):
                raise InputError(
                    f"{where}: the pressure across the seal reaches {need / 1e5:.6g} bar (supply "
                    f"gauge pressure) but its contact map covers {plo / 1e5:.6g} ... "
                    f"{phi / 1e5:.6g} bar; the map is not extrapolated -- extend its pressure "
                    "grid or lower air.supply_pressure")

    def initial_state(self) -> np.ndarray:
        """Chambers at rest under the initial valve position, their air at the body temperature
        (``cylinder.temperature``), friction states relaxed, the seals, rod and tube at their
        set temperatures."""
        case = self.case
        u0 = self.schedule.initial
        openings = port_openings(u0, case.valve.type, case.valve.centre)
        p1 = self.p_supply if openings[0] > 0 else self.p_amb
        p2 = self.p_supply if openings[2] > 0 else self.p_amb
        if case.initial_position is not None:
            x0 = case.initial_position
        elif self.position is not None:
            x0 = float(self.position.value(0.0))
        else:
            x0 = self.rest_position(self.stroke if u0 > 0 else 0.0, p1, p2)
        v1 = case.cylinder.dead_volume_cap + self.a1 * x0
        v2 = case.cylinder.dead_volume_rod + self.a2 * (self.stroke - x0)
        self.check_chamber_volumes([0.0], [x0], InputError)
        # a cylinder at rest: its chamber air has taken the temperature of the body around it
        t_air = body_temperature(case)
        m1 = float(gas_mass(p1, v1, t_air))
        m2 = float(gas_mass(p2, v2, t_air))
        y = np.zeros(self.n_states)
        y[:6] = [x0, 0.0, m1, m2, float(internal_energy(m1, t_air)),
                 float(internal_energy(m2, t_air))]
        for s, off in zip(self.seals, self.offsets):
            y[off:off + s.n_states] = s.law.initial_state(1)[:, 0]
        if self.heating:
            t0 = self.temperature_offset
            y[t0:t0 + len(self.seals)] = [s.temperature for s in self.seals]
            y[t0 + len(self.seals)] = y[t0 + len(self.seals) + 1] = body_temperature(case)
        return y

    def check_chamber_volumes(self, time, position, error=ModelError) -> None:
        """Refuse positions at which a chamber has no volume left: a piston pressed into an
        end stop's bumper deeper than the dead volume of that end allows (V = V0 + A·x <= 0;
        the chamber equations then give negative pressures and absolute zero)."""
        cyl = self.case.cylinder
        x = np.asarray(position, dtype=float)
        for volume, field, area, depth in (
                (cyl.dead_volume_cap + self.a1 * x, "dead_volume_cap", self.a1, -x),
                (cyl.dead_volume_rod + self.a2 * (self.stroke - x), "dead_volume_rod", self.a2,
                 x - self.stroke)):
            if np.any(volume <= 0.0):
                k = int(np.argmin(volume))
                raise error(
                    f"cylinder.{field}: {getattr(cyl, field) * 1e6:.4g} cm^3 is less than the "
                    f"volume the piston sweeps in the end stop's bumper (t = "
                    f"{float(np.asarray(time)[k]):.6g} s: {depth[k] * 1e3:.4g} mm deep, "
                    f"{depth[k] * area * 1e6:.4g} cm^3); give the real dead volume (ports, "
                    f"tubing to the valve) or a stiffer cylinder.end_stops.stiffness "
                    f"({cyl.end_stops.stiffness:.4g} N/m)")

    def rest_position(self, end: float, p1: float, p2: float) -> float:
        """Where the piston rests in the end stop at ``end`` with the chamber pressures
        p1, p2 and the load at rest (:func:`~sealsim.pneumatic.cylinder.rest_position`)."""
        case, load = self.case, self.case.load
        force = (piston_force(p1, p2, self.p_amb, self.a1, self.a2, self.a_rod)
                 - load_force(end, 0.0, load.force, load.stiffness, load.spring_free_position,
                              self.mass, case.cylinder.incline, load.viscous))
        return rest_position(end, self.stroke, float(force), case.cylinder.end_stops.stiffness,
                             load.stiffness)

    def tolerances(self, rtol: float) -> np.ndarray:
        """Absolute tolerances per state: ``rtol`` times a scale of each quantity -- 0.1 m for
        the position, 30 m/s for the speed (1 µm and 0.3 mm/s at rtol = 1e-5: the speed
        resolution limits the steps most; with it the position stays within 0.05 % of the
        stroke and the energy balance within 0.02 % (LSODA) and 0.12 % (the compiled BDF) even
        for a piston that only settles into its stop: its deflection δ is resolved to 1 µm),
        the chamber mass and energy at supply pressure, 10 for Θ, 1 mm for bristle
        deflections, the speed's 30 m/s for the speed a contact's film has formed for (it
        enters the friction as the speed does; the table reads it on a log scale, but 1000×
        and 1e6× tighter changed the FE example's stroke times by 0.015 %, its friction by
        0.04 N at the 99th percentile and 0.3 N at most of its 37.6 N range, for 66 and 75 %
        more steps), 100 K for temperatures."""
        case = self.case
        volume = case.cylinder.dead_volume_cap + self.a1 * self.stroke
        m_scale = float(gas_mass(self.p_supply, volume, self.t_amb))
        u_scale = m_scale * AIR_CV * self.t_amb
        atol = np.empty(self.n_states)
        atol[:6] = [0.1, 30.0, m_scale, m_scale, u_scale, u_scale]
        for seal, off in zip(self.seals, self.offsets):
            for j, name in enumerate(seal.law.state_names):
                atol[off + j] = _STATE_SCALES.get(name, 1e-3)
        atol[self.temperature_offset:self.n_dynamic] = 100.0
        atol[self.n_dynamic:] = 1e3       # bookkeeping: not error controlled (see module doc)
        return atol * rtol

    # -- the right-hand side ----------------------------------------------------------------
    def rhs(self, mode: int, y_type=None):
        """``f(t, y) -> dy/dt`` for the integrator (one compiled call; the returned array is
        reused by the next call).  With ``y_type`` (an array like the ``y`` the integrator will
        pass) the compiled code is called without numba's type dispatch."""
        tables, dy, diag = self.tables, self._dy, self._diag1
        derivatives = self._entry(rhs.derivatives, (0.0, y_type, mode, tables, dy, diag)) \
            if y_type is not None else rhs.derivatives

        def f(t, y):
            derivatives(t, y, mode, tables, dy, diag)
            return dy
        return f

    def jacobian_function(self, mode: int, y_type=None):
        """``J(t, y) -> ∂f/∂y`` for the integrator (forward differences, compiled; ``y_type``
        as in :meth:`rhs`)."""
        tables, scale, diag = self.tables, self._jac_scale, self._diag1
        work_y, work_dy, f0 = self._work
        jac = np.zeros((self.n_states, self.n_states))
        args = (0.0, y_type, mode, tables, scale, work_y, work_dy, f0, diag, jac)
        compiled = self._entry(rhs.jacobian, args) if y_type is not None else rhs.jacobian

        def j(t, y):
            compiled(t, y, mode, tables, scale, work_y, work_dy, f0, diag, jac)
            return jac
        return j

    def evaluate(self, t, y, mode, full: bool = False, outputs_only: bool = False, out=None):
        """Derivatives dy/dt (and, with ``full``, every intermediate quantity) at (t, y).

        ``y`` has shape (n,) or (n, k) (k columns, ``t`` scalar or (k,)).  With
        ``outputs_only`` (and ``full``) only the quantities of the output time series are
        computed (no flows, heat or derivatives: their entries are 0), at about half the cost.
        ``out``: Fortran-ordered arrays (dy of y's shape, diagnostics (n_diag, k)) to write
        into instead of new ones; the entries the evaluation does not write keep what they
        held (zeros in new arrays).
        """
        y = np.asarray(y, dtype=float)
        column = y.ndim == 1
        # column-major: each evaluation reads and writes one contiguous column (row-major
        # columns of many samples are strided by the sample count: 20 % slower); a
        # sampler's (k, n) samples transposed are column-major already (no copy)
        ys = np.asfortranarray(y[:, None] if column else y)
        k = ys.shape[1]
        # one column is C- and F-contiguous at once, and numba types it as C: it would compile
        # the whole right-hand side a second time (about 10 s cold); as two equal columns it
        # takes the Fortran-ordered compilation of the samplers
        pair = k == 1
        if pair:
            ys = np.asfortranarray(np.repeat(ys, 2, axis=1))
        # writable copies: a read-only array is a type of its own to numba as well
        ts = np.array(np.broadcast_to(np.asarray(t, dtype=float).ravel(), (ys.shape[1],)))
        modes = np.array(np.broadcast_to(np.asarray(mode, dtype=np.int64).ravel(),
                                         (ys.shape[1],)))
        if out is None or pair:
            dy = np.zeros_like(ys, order="F")
            diag = np.zeros((self.n_diag, ys.shape[1]), order="F")
            if out is not None:
                dy[:, 1], diag[:, 1] = out[0][:, 0], out[1][:, 0]
        else:
            dy, diag = out
        rhs.evaluate_many(ts, ys, modes, self.tables, dy, diag,
                          rhs.OUTPUTS if outputs_only and full else rhs.FULL)
        if pair:
            dy, diag = dy[:, 1:], diag[:, 1:]
            if out is not None:
                out[0][:, :1], out[1][:, :1] = dy, diag
                dy, diag = out
        if not full:
            return dy[:, 0] if column else dy
        return self.unpack(dy, diag)

    def unpack(self, dy, diag) -> dict:
        """The quantities of :meth:`evaluate` (``full``) from the compiled diagnostics."""
        nseal = len(self.seals)
        per = diag[rhs.D_NFIXED:].reshape(nseal, rhs.DS_NROWS, -1) if nseal else \
            np.zeros((0, rhs.DS_NROWS, diag.shape[1]))
        loads = [(per[i, rhs.DS_FN], per[i, rhs.DS_B], per[i, rhs.DS_DP])
                 for i in range(nseal)]
        return {
            "dy": dy, "x": diag[rhs.D_X], "v": diag[rhs.D_V], "p1": diag[rhs.D_P1],
            "p2": diag[rhs.D_P2], "T1": diag[rhs.D_T1], "T2": diag[rhs.D_T2],
            "spool": diag[rhs.D_SPOOL], "flow": diag[rhs.D_G0:rhs.D_G3 + 1],
            "enthalpy": diag[rhs.D_H0:rhs.D_H3 + 1], "q1": diag[rhs.D_Q1],
            "q2": diag[rhs.D_Q2], "f_press": diag[rhs.D_FPRESS], "f_load": diag[rhs.D_FLOAD],
            "f_stop": diag[rhs.D_FSTOP], "f_seal": per[:, rhs.DS_F], "f_fric": diag[rhs.D_FFRIC],
            "hold": diag[rhs.D_HOLD], "breakaway": per[:, rhs.DS_BRK], "loads": loads,
            "seal_temperature": per[:, rhs.DS_T], "friction_power": per[:, rhs.DS_POWER],
            "temperature_clipped": per[:, rhs.DS_CLIP], "T_tube": diag[rhs.D_TTUBE],
            "T_rod": diag[rhs.D_TROD]}

    def _entry(self, dispatcher, args):
        """The compiled entry point of a numba function for the types of ``args`` (compiled or
        loaded from the cache first, looked up once per system): calling it skips numba's type
        dispatch, which costs as much as the right-hand side itself.  The caller must pass
        arguments of exactly these types."""
        entries = self.__dict__.setdefault("_entries", {})
        key = (dispatcher.__name__, args[1].shape)
        if key not in entries:
            import numba

            dispatcher(*args)
            entries[key] = dispatcher.overloads[tuple(numba.typeof(a) for a in args)].entry_point
        return entries[key]

    # -- stick/slip --------------------------------------------------------------------------
    def stick_margin(self, t, y) -> tuple[float, float]:
        """(F_req, F_brk) [N] for the body held at rest at (t, y): the force the sticking seals
        must carry and their break-away force, widened by the decision tolerance
        :func:`stick_tolerance` (so that the stick decision and the break-away event agree)."""
        work_y, work_dy, _ = self._work
        hold, brk = rhs.stick_margin(float(t), np.asarray(y, dtype=float), self.tables, work_y,
                                     work_dy, self._diag1)
        return hold, brk + stick_tolerance(brk)

    def next_mode_at_rest(self, t, y) -> int:
        """Stick or slip direction for the body at rest at (t, y)."""
        hold, brk = self.stick_margin(t, y)
        stuck, _ = resolve_stick(hold, brk)
        if bool(stuck):
            return rhs.STICK
        return rhs.FORWARD if hold > 0 else rhs.BACKWARD


#: the joined friction tables of recent systems: {ids of the parts: (weak references to the
#: parts, joined array)} -- contact friction tables are megabytes, kept per process
#: (:mod:`.friction_tables`), and every run of the same seals would copy them again
_JOINED: dict = {}


def _joined(chunks: list) -> np.ndarray:
    """The arrays ``chunks`` one after the other, as ``np.concatenate`` (read only by the
    compiled right-hand side); the same parts give the same array without a new copy."""
    if len(chunks) == 1:
        return chunks[0]
    key = tuple(id(c) for c in chunks)
    hit = _JOINED.get(key)
    if hit is not None and all(ref() is c for ref, c in zip(hit[0], chunks)):
        return hit[1]
    joined = np.concatenate(chunks)
    for stale in [k for k, (refs, _) in _JOINED.items() if any(r() is None for r in refs)]:
        del _JOINED[stale]                          # parts gone: their join is never asked for
    if len(_JOINED) >= 4:
        _JOINED.pop(next(iter(_JOINED)))
    _JOINED[key] = ([weakref.ref(c) for c in chunks], joined)
    return joined


def _constant_viscosity(seal_int, law_par, seals) -> None:
    """γ(T) of the Θ law at each seal's constant temperature, once: the same product the
    compiled law would form at every evaluation (:func:`sealsim.friction.compiled.law_rates`:
    γ·ν(T)/ν(T_ref), ASTM D341), so the results do not change -- the four powers and two
    logarithms per seal and evaluation are saved."""
    for i, seal in enumerate(seals):
        par = law_par[i]
        if seal_int[i, rhs.SI_LAW] == rhs.THETA and par[11] != 0.0:
            par[4] = par[4] * walther_viscosity_ratio(float(seal.temperature), par[9], par[10],
                                                      par[11])
            par[11] = 0.0


def _profile_table(position):
    """(kind, parameters) of a prescribed position profile for :func:`.rhs.profile_point`."""
    if position is None:
        return 0.0, np.zeros(1)
    kind = position.kind
    if kind == "constant":
        return 1.0, np.array([position.level])
    if kind == "harmonic":
        return 2.0, np.array([position.mean, position.amplitude, position.angular_frequency,
                              position.phase])
    times = np.asarray(position.times, dtype=float)
    values = np.asarray(position.values, dtype=float)
    return 3.0, np.concatenate([[times.size], times, values])


def _cord_diameter(spec):
    if spec.thermal is not None and spec.thermal.cord_diameter is not None:
        return spec.thermal.cord_diameter
    if spec.map is not None and spec.map.analytic is not None:
        return spec.map.analytic.cord_diameter
    return None


def _elastomer_name(spec) -> str:
    if spec.thermal is not None and spec.thermal.elastomer is not None:
        return spec.thermal.elastomer
    if spec.map is not None and spec.map.analytic is not None:
        return spec.map.analytic.elastomer
    return "NBR"
