"""The whole-cylinder FMU: the pneumatic model of :mod:`sealsim.pneumatic` in C.

Chambers, valve (ISO 6358 flows, meter-out throttles, end cushions), seals with their contact
maps (the analytic estimate exactly, an FE map with its own Hermite grid), friction laws and
friction tables (a Θ law with ``steady = "contact"``: the seal's steady friction from its
contact, read by ``c/contact_table.c``), end stops and load -- the right-hand side of
:mod:`sealsim.pneumatic.rhs`, ported line by line to ``c/cylinder_model.c`` and fed with the
very tables of :class:`sealsim.pneumatic.system.PneumaticSystem` (written into ``config.h``;
the friction tables in their node layout).  Co-simulation
integrates with ``c/bdf.c``, the C port of the BDF method of :mod:`sealsim.ode.bdf` that
``sealsim pneumatic run`` uses, and locates the stick/slip events inside the communication
step (while the inputs stay the same its steps run across the communication points, whose
states are the steps' dense output: the result does not depend on the communication step);
model exchange offers one event indicator and switches the stick/slip mode in event
mode.

Interface (SI):

=====================  ========  ============================================================
variable               unit      meaning
=====================  ========  ============================================================
valve_command          1         input: spool command, +1 extend, -1 retract, 0 centre (5/3);
                                 it reaches the spool after the valve's dead time
                                 (``valve_delay``), then the spool follows with the valve's
                                 time constant
F_load                 N         input: external force on the rod, resisting extension (the
                                 case's load force is its start value)
x, v                   m, m/s    states/outputs: piston position (0 retracted) and velocity
m_cap, m_rod           kg        states: air mass in the cap-end and rod-end chamber
U_cap, U_rod           J         states: internal energy of the air in them
theta_<seal>, z_<...>  -, m      states: friction states of the seals
film_speed_<seal>      m/s       state of a Θ law on its contact: the speed its film has
                                 formed for
p_cap, p_rod           Pa        outputs: absolute chamber pressures
T_cap, T_rod           K         outputs: air temperatures
spool                  1         output: spool position
F_friction             N         output: friction of all seals (acts against v)
F_pressure, F_stop     N         outputs: pressure force on the piston, end-stop force
F_<seal>, F_N_<seal>   N         outputs per seal: friction force, normal force
b_<seal>, dp_<seal>    m, Pa     outputs per seal: contact width, pressure difference
stuck                  -         output: true while the piston sticks
=====================  ========  ============================================================

Parameters: ``p_supply`` (absolute), ``moving_mass``, ``valve_conductance``, ``valve_delay``,
``heat_transfer_coefficient``; the start values of the states are the case's initial state.
Not in the FMU yet (refused with an :class:`~sealsim.errors.InputError`): seal heating,
``air.heat_transfer = "free_convection"`` and a prescribed position (test rig).
"""

from __future__ import annotations

import ctypes
import subprocess
from pathlib import Path

import numpy as np

from sealsim.errors import InputError, ModelError
from sealsim.files import scratch_folder
from sealsim.fmu.model_description import ModelSpec, Variable
from sealsim.pneumatic import rhs
from sealsim.pneumatic.chambers import AIR_CP, AIR_CV, AIR_HEAT_CAPACITY_RATIO
from sealsim.pneumatic.cylinder import GRAVITY
from sealsim.pneumatic.results import seal_columns
from sealsim.pneumatic.valve import ANR_DENSITY, ANR_TEMPERATURE

__all__ = ["cylinder_check", "cylinder_spec", "cylinder_system", "rhs_check"]

_GT0 = (">", 0.0)
#: friction states: (unit, text); others are deflections [m]
_STATE_UNITS = {"theta": (None, "lubrication state Theta"), "z": ("m", "bristle deflection"),
                "film_speed": ("m/s", "speed the film has formed for in the contact")}
#: the unit of a friction state's time derivative
_PER_SECOND = {None: None, "m": "m/s", "m/s": "m/s2"}


def cylinder_system(case, base_dir: str | Path = "."):
    """The assembled model of a pneumatic case (:class:`~sealsim.pneumatic.system.
    PneumaticSystem`), refused for what the C code does not have."""
    from sealsim.pneumatic.case import build_seals
    from sealsim.pneumatic.system import PneumaticSystem

    if case.controller.mode == "position":
        raise InputError("controller.mode = 'position' (a test rig) is not in the cylinder FMU: "
                         "export the seal (--seal) and drive it from the host")
    if case.thermal is not None and case.thermal.seal_heating:
        raise InputError("[thermal] seal_heating is not in the cylinder FMU yet; remove it "
                         "(the seals stay at their temperature) or run it with "
                         "sealsim pneumatic run")
    if case.air.heat_transfer == "free_convection":
        raise InputError("air.heat_transfer = 'free_convection' is not in the cylinder FMU yet; "
                         "give air.heat_transfer_coefficient instead")
    return PneumaticSystem(case, build_seals(case, base_dir))


def _state_variables(system) -> list[Variable]:
    """The continuous states in the layout of the compiled model (x, v, m1, m2, U1, U2, seal
    states), with their start values."""
    y0 = system.initial_state()
    names = seal_columns(s.name for s in system.seals)
    out = [
        Variable("x", "X", "output", "piston position (0: retracted)", "m", y0[0], state=True),
        Variable("v", "V", "output", "piston velocity", "m/s", y0[1], state=True),
        Variable("m_cap", "M_CAP", "output", "air mass in the cap-end chamber", "kg", y0[2],
                 state=True),
        Variable("m_rod", "M_ROD", "output", "air mass in the rod-end chamber", "kg", y0[3],
                 state=True),
        Variable("U_cap", "U_CAP", "output", "internal energy of the cap-end air", "J", y0[4],
                 state=True),
        Variable("U_rod", "U_ROD", "output", "internal energy of the rod-end air", "J", y0[5],
                 state=True),
    ]
    for i, (seal, name) in enumerate(zip(system.seals, names)):
        for j, sname in enumerate(seal.law.state_names):
            unit, text = _STATE_UNITS.get(sname, ("m", f"friction state {sname}"))
            out.append(Variable(f"{sname}_{name}", f"S{i}_{j}", "output",
                                f"{text} of the seal {seal.name}", unit,
                                y0[system.offsets[i] + j], state=True))
    return out


def cylinder_spec(system, identifier: str, *, title: str = "", source: str = "") -> ModelSpec:
    """The model of a whole-cylinder FMU (see the module docstring)."""
    n = system.n_dynamic
    names = seal_columns(s.name for s in system.seals)
    states = _state_variables(system)
    c, spool, _, seal_int, law_par, seal_therm, map_int, map_data = system.tables[:8]
    fric_int, fric_data = _friction_tables(system)
    variables = [
        Variable("time", "TIME", "independent", "simulation time", "s"),
        Variable("valve_command", "VALVE_COMMAND", "input",
                 "spool command: +1 extend, -1 retract, 0 centre (5/3); reaches the spool "
                 "after valve_delay", None, float(c[rhs.C_SPOOL_INIT])),
        Variable("F_load", "F_LOAD", "input", "external force on the rod, resisting extension",
                 "N", float(c[rhs.C_F0])),
        *states,
    ]
    units = {"x": "m/s", "v": "m/s2", "m_cap": "kg/s", "m_rod": "kg/s", "U_cap": "W",
             "U_rod": "W"}
    for st in states:
        unit = units[st.name] if st.name in units else _PER_SECOND[st.unit]   # friction states
        variables.append(Variable(f"der({st.name})", f"DER_{st.macro}", "local",
                                  f"time derivative of {st.name}", unit, derivative_of=st.name))
    variables += [
        Variable("p_cap", "P1", "output", "absolute pressure in the cap-end chamber", "Pa"),
        Variable("p_rod", "P2", "output", "absolute pressure in the rod-end chamber", "Pa"),
        Variable("T_cap", "T1", "output", "air temperature in the cap-end chamber", "K"),
        Variable("T_rod", "T2", "output", "air temperature in the rod-end chamber", "K"),
        Variable("spool", "SPOOL", "output", "spool position (+1 extend, -1 retract)", None),
        Variable("F_friction", "F_FRICTION", "output",
                 "friction force of all seals, acting against v", "N"),
        Variable("F_pressure", "F_PRESSURE", "output", "pressure force on the piston", "N"),
        Variable("F_stop", "F_STOP", "output", "end-stop force", "N"),
        Variable("stuck", "STUCK", "output", "true while the piston sticks", boolean=True),
    ]
    seal_vr = []
    for i, (seal, name) in enumerate(zip(system.seals, names)):
        row = []
        for key, macro, text, unit in (
                ("F", "F", "friction force of", "N"), ("F_N", "FN", "normal force of", "N"),
                ("b", "B", "contact width of", "m"),
                ("dp", "DP", "pressure difference across", "Pa")):
            row.append(len(variables))
            variables.append(Variable(f"{key}_{name}", f"SEAL{i}_{macro}", "output",
                                      f"{text} the seal {seal.name}", unit,
                                      exposed=key == "F" or seal.contact_map is not None))
        seal_vr.append(row)
    variables += [
        Variable("p_supply", "P_SUPPLY", "parameter", "absolute supply pressure", "Pa",
                 float(c[rhs.C_PS]), lower=(">", float(c[rhs.C_PA]))),  # as air.supply_pressure
        Variable("moving_mass", "MOVING_MASS", "parameter",
                 "moving mass: piston, rod and load", "kg", float(c[rhs.C_MASS]), lower=_GT0),
        Variable("valve_conductance", "VALVE_CONDUCTANCE", "parameter",
                 "sonic conductance C of the valve's paths (ISO 6358)", "m3/(s.Pa)",
                 float(c[rhs.C_C]), lower=_GT0),
        Variable("valve_delay", "VALVE_DELAY", "parameter",
                 "dead time of the valve: a command reaches the spool this much later", "s",
                 float(system.case.valve.delay), lower=(">=", 0.0)),
        Variable("heat_transfer_coefficient", "HEAT_TRANSFER_COEFFICIENT", "parameter",
                 "heat-transfer coefficient between the chamber air and the wall", "W/(m2.K)",
                 float(c[rhs.C_H]), lower=(">=", 0.0)),
    ]
    sticky = bool(system.sticky)
    indicators = []
    if sticky:
        variables.append(Variable("stick_slip_indicator", "STICK_SLIP_INDICATOR", "local",
                                  "event indicator of the stick/slip transitions", "N"))
        indicators = ["stick_slip_indicator"]
    rtol = system.case.solver.rtol
    atol = system.tolerances(rtol)[:n]
    defines = {
        "NSEAL": len(system.seals), "LAW_WIDTH": law_par.shape[1], "BDF_MAXN": n,
        "MODEL_TIME_EVENTS": 1,
        "STICKY": int(sticky), "RTOL": repr(rtol),
        "MAX_STEP": repr(float(system.case.solver.max_step)),
        "SPEED_RESOLUTION": repr(float(0.1 * atol[1])),
        "MODEL_WORK_DOUBLES": 400 + 24 * n + 2 * n * n,
        "AIR_GAMMA": repr(AIR_HEAT_CAPACITY_RATIO), "AIR_CP": repr(AIR_CP),
        "AIR_CV": repr(AIR_CV), "ANR_DENSITY": repr(ANR_DENSITY),
        "ANR_TEMPERATURE": repr(ANR_TEMPERATURE), "GRAVITY": repr(GRAVITY),
        "MODE_STICK": rhs.STICK, "MODE_FORWARD": rhs.FORWARD, "MODE_BACKWARD": rhs.BACKWARD,
        "MODE_FREE": rhs.FREE, "MODE_PRESCRIBED": rhs.PRESCRIBED,
        "MAP_ANALYTIC": rhs.MAP_ANALYTIC, "MAP_GRID": rhs.MAP_GRID,
        **{f"LAW_{k.upper()}": v for k, v in rhs.LAW_CODES.items()},
        **{name: getattr(rhs, name) for name in dir(rhs)
           if name.startswith(("C_", "SI_", "ST_")) and isinstance(getattr(rhs, name), int)},
    }
    seal_states = [s.n_states for s in system.seals]
    tables = "\n".join([
        _c_array("CYL_C", c),
        _c_matrix("SEAL_INT", seal_int, "long"),
        f"static const int SEAL_NSTATES[] = {{{', '.join(map(str, seal_states or [0]))}}};",
        _c_matrix("LAW_PAR", law_par),
        _c_matrix("SEAL_THERM", seal_therm),
        _c_matrix("MAP_INT", map_int, "long"),
        _c_array("MAP_DATA", map_data),
        _c_matrix("FRIC_INT", fric_int, "long"),
        _c_array("FRIC_DATA", fric_data),
        _c_array("ATOL", atol),
        _c_array("JAC_SCALE", system.tolerances(1.0)[:n]),
        "static const int SEAL_VR[][4] = {" + ", ".join(
            "{" + ", ".join(map(str, r)) + "}" for r in seal_vr or [[0, 0, 0, 0]]) + "};",
    ])
    report = {"model": "pneumatic cylinder", "seals": [
        {"name": s.name, "location": s.location, "law": s.law.name,
         "contact_map": None if s.contact_map is None else type(s.contact_map).__name__,
         "friction_table": s.friction_table is not None}
        for s in system.seals], "states": n, "event_indicators": len(indicators),
        "integrator": f"BDF (port of sealsim.ode.bdf), rtol {rtol:g}"}
    description = (f"sealsim pneumatic cylinder ({len(system.seals)} seals"
                   + (", stick/slip" if sticky else "") + ")" + (f": {title}" if title else ""))
    duration = float(system.duration)
    return ModelSpec(identifier, title or identifier, description, "cylinder_model.c",
                     variables, defines, tables, default_experiment=(0.0, duration, 1e-3),
                     report=report | {"source": source}, event_indicators=indicators,
                     extra_sources=["bdf.h", "bdf.c"])


def _friction_tables(system):
    """(FRIC_INT, FRIC_DATA): the seals' friction tables in the node layout of
    ``c/contact_table.c`` (:meth:`~sealsim.friction.contact_table.SteadyFrictionTable.
    node_tables`; a row per seal: data offset, then the layout row; zeros without a table)."""
    rows = np.zeros((len(system.seals), 5), dtype=np.int64)
    chunks, used = [], 0
    for i, seal in enumerate(system.seals):
        if seal.friction_table is not None:
            row, data = seal.friction_table.node_tables()
            rows[i, 0], rows[i, 1:] = used, row
            chunks.append(data)
            used += data.size
    return rows, np.concatenate(chunks) if chunks else np.zeros(1)


def _c_number(x: float) -> str:
    x = float(x)
    if np.isnan(x):
        return "NAN"
    if np.isinf(x):
        return "INFINITY" if x > 0 else "-INFINITY"
    return repr(x)


def _c_array(name: str, values, ctype: str = "double") -> str:
    values = np.ravel(values)
    text = ", ".join(_c_number(v) if ctype == "double" else str(int(v)) for v in values)
    return f"static const {ctype} {name}[] = {{{text or '0'}}};"


def _c_matrix(name: str, values, ctype: str = "double") -> str:
    values = np.atleast_2d(values)
    if values.shape[0] == 0:
        values = np.zeros((1, max(values.shape[1], 1)))
    rows = ", ".join("{" + ", ".join(_c_number(v) if ctype == "double" else str(int(v))
                                     for v in row) + "}" for row in values)
    return f"static const {ctype} {name}[][{values.shape[1]}] = {{{rows}}};"


# -- checks -------------------------------------------------------------------------------------
_TEST_HARNESS = r"""
#include "all.c"
/* the C right-hand side at (t, y) in a mode, with the spool moving from s0 towards u since
 * t = 0; the derivatives and the outputs (x, v, p1, p2, T1, T2, spool, friction, hold, brk,
 * per seal F, F_N, b, dp) */
__attribute__((visibility("default")))
void sealsim_rhs(double t, const double *y, int mode, double u, double s0, int rates,
                 double *dy, double *out) {
    static CylinderData m;
    Outputs o;
    for (int i = 0; i < C_NCONST; i++) m.cst[i] = CYL_C[i];
    m.command = u;
    m.s_command = s0;
    m.t_command = 0.0;
    m.npending = 0;
    evaluate(&m, spool_position(&m, t), y, mode, rates, 0, dy, &o);
    double fixed[10] = {o.x, o.v, o.p1, o.p2, o.t1, o.t2, o.spool, o.f_fric, o.hold, o.brk};
    for (int i = 0; i < 10; i++) out[i] = fixed[i];
    for (int i = 0; i < NSEAL; i++) {
        out[10 + 4 * i] = o.f[i];
        out[11 + 4 * i] = o.fn[i];
        out[12 + 4 * i] = o.b[i];
        out[13 + 4 * i] = o.dp[i];
    }
}
"""


def _random_states(system, rng, k: int) -> np.ndarray:
    """k states around the operating range: positions in and beyond the stroke (end stops),
    speeds of both signs and zero, chamber masses and temperatures between ambient and supply,
    friction states over their range (a film's speed 0, the sliding speed, or up to 1 m/s:
    each branch of the contact table's lookup)."""
    n = system.n_dynamic
    ys = np.tile(system.initial_state()[:n, None], (1, k))
    case = system.case
    cyl = case.cylinder
    ys[0] = rng.uniform(-2e-4, system.stroke + 2e-4, k)
    ys[1] = np.where(rng.random(k) < 0.2, 0.0, rng.normal(0.0, 0.3, k))
    from sealsim.pneumatic.chambers import gas_mass, internal_energy

    for j, (dead, area, length) in enumerate(((cyl.dead_volume_cap, system.a1, ys[0]),
                                              (cyl.dead_volume_rod, system.a2,
                                               system.stroke - ys[0]))):
        volume = dead + area * np.maximum(length, 0.0)
        p = rng.uniform(system.p_amb, system.p_supply, k)
        temp = rng.uniform(250.0, 330.0, k)
        m = gas_mass(p, volume, temp)
        ys[2 + j] = m
        ys[4 + j] = internal_energy(m, temp)
    for seal, off in zip(system.seals, system.offsets):
        for j, name in enumerate(seal.law.state_names):
            if name == "theta":
                ys[off + j] = rng.uniform(0.0, 1.0, k)
            elif name == "film_speed":       # no film, the steady film (|v|), and any other
                pick = rng.random(k)
                ys[off + j] = np.select([pick < 0.1, pick < 0.2],
                                        [np.zeros(k), np.abs(ys[1])], rng.uniform(0.0, 1.0, k))
            else:
                ys[off + j] = rng.uniform(-2e-5, 2e-5, k)
    return ys


def rhs_check(system, folder: Path, samples: int = 400) -> dict:
    """The C right-hand side of the FMU's sources against the compiled (numba) one at random
    states in every mode: the largest difference of each derivative and output, relative to
    its largest magnitude over the samples.  Compiles a test library from the sources (the C
    compiler of the FMU build)."""
    from sealsim.fmu.builder import find_compiler

    compiler = find_compiler()
    if compiler is None:                      # pragma: no cover - the build compiled already
        raise ModelError("the right-hand-side check needs a C compiler")
    n = system.n_dynamic
    nseal = len(system.seals)
    rng = np.random.default_rng(27)
    with scratch_folder("sealsim-rhs-") as scratch:
        harness = Path(scratch) / "harness.c"
        harness.write_text(_TEST_HARNESS, "utf-8")
        lib_path = Path(scratch) / "harness.so"
        run = subprocess.run([compiler, "-shared", "-fPIC", "-O2", "-std=c99",
                              "-ffp-contract=off", "-DFMI_VERSION=2", "-I",
                              str(folder / "sources"), str(harness), "-o", str(lib_path),
                              "-lm"], capture_output=True, text=True, timeout=300)
        if run.returncode != 0:
            raise ModelError(f"the right-hand-side check does not compile: {run.stderr[-2000:]}")
        lib = ctypes.CDLL(str(lib_path))
        f = lib.sealsim_rhs
        dbl = ctypes.POINTER(ctypes.c_double)
        f.argtypes = [ctypes.c_double, dbl, ctypes.c_int, ctypes.c_double, ctypes.c_double,
                      ctypes.c_int, dbl, dbl]
        modes = [rhs.FREE] if not system.sticky else [rhs.STICK, rhs.FORWARD, rhs.BACKWARD]
        worst: dict[str, float] = {}
        c = system.tables[0]
        for mode in modes:
            ys = _random_states(system, rng, samples)
            ts = rng.uniform(0.0, 0.05, samples)
            u = float(rng.choice([-1.0, 1.0]))
            s0 = -u
            spool = np.array([[0.0], [u], [s0]])
            tables = (c, spool, *system.tables[2:])
            # column-major, as the simulation's samplers pass them (one compilation)
            full = np.zeros((system.n_states, samples), order="F")
            full[:n] = ys
            dy_ref = np.zeros_like(full, order="F")
            diag = np.zeros((system.n_diag, samples), order="F")
            rhs.evaluate_many(ts, full, np.full(samples, mode), tables, dy_ref, diag, rhs.FULL)
            dy_c = np.zeros((samples, n))
            out_c = np.zeros((samples, 10 + 4 * nseal))
            for k in range(samples):
                y = np.ascontiguousarray(ys[:, k])
                f(ts[k], y.ctypes.data_as(dbl), mode, u, s0, 1,
                  dy_c[k].ctypes.data_as(dbl), out_c[k].ctypes.data_as(dbl))
            ref = {"dy": dy_ref[:n].T,
                   "outputs": np.stack([diag[r] for r in (
                       rhs.D_X, rhs.D_V, rhs.D_P1, rhs.D_P2, rhs.D_T1, rhs.D_T2, rhs.D_SPOOL,
                       rhs.D_FFRIC, rhs.D_HOLD, rhs.D_BRK)], axis=1)}
            per = diag[rhs.D_NFIXED:].reshape(nseal, rhs.DS_NROWS, samples)
            seal_ref = np.stack([per[:, r] for r in (rhs.DS_F, rhs.DS_FN, rhs.DS_B,
                                                     rhs.DS_DP)], axis=1)   # (nseal, 4, k)
            ref["seals"] = seal_ref.reshape(4 * nseal, samples).T
            got = {"dy": dy_c, "outputs": out_c[:, :10], "seals": out_c[:, 10:]}
            for key in ref:
                a, b = got[key], ref[key]
                finite = np.isfinite(b)
                scale = np.max(np.where(finite, np.abs(b), 0.0), axis=0)
                scale = np.where(scale > 0, scale, 1.0)
                diff = np.where(finite, np.abs(a - b), np.where(np.isnan(a) == np.isnan(b),
                                                                0.0, np.inf))
                worst[key] = max(worst.get(key, 0.0), float(np.max(diff / scale)))
    return worst


def cylinder_check(system, spec: ModelSpec, kinds=("me", "cs")):
    """A build check of the cylinder FMU: the C right-hand side against the numba one
    (:func:`rhs_check`, 1e-9 relative to each quantity's range: the same formulas, rounding
    and the C library's exp/pow against numba's), and the co-simulation over the case's
    command cycle against ``sealsim pneumatic run`` (extend and retract times within 0.5 %)."""

    def check(folder: Path, token: str) -> None:
        worst = rhs_check(system, folder)
        spec.report["rhs_check"] = {"max_relative_difference": worst}
        if max(worst.values()) > 1e-9:
            raise ModelError(f"the FMU's C right-hand side differs from sealsim's compiled one "
                             f"(largest relative differences {worst}); "
                             "sealsim/fmu/c/cylinder_model.c must follow sealsim.pneumatic.rhs")
        if "cs" in kinds:
            comparison, spec.data["cycle"] = compare_with_python(system, folder, "cs")
            spec.report["cycle_check"] = comparison
            bad = {k: v for k, v in comparison["relative_difference"].items() if v > 5e-3}
            if bad:
                raise ModelError(f"the FMU's co-simulation differs from sealsim pneumatic run "
                                 f"by more than 0.5 %: {bad}")

    return check


def command_signal(system):
    """(times, values) of the case's valve commands as steps (the FMU applies the valve's
    dead time).  Each step sits 1 ns before its command time: FMPy (like most hosts) gives
    the value before a discontinuity at the discontinuity itself, and the command issued at
    t must be the input of the communication step that starts at t."""
    schedule = system.schedule
    times, values = [0.0], [float(schedule.initial)]
    for t, u in zip(np.asarray(schedule.times, float), np.asarray(schedule.commands, float)):
        if t <= 0.0:                                   # a command at the start: the start value
            values[0] = float(u)
            continue
        t = float(t) - 1e-9
        times += [t, t]
        values += [values[-1], float(u)]
    times.append(float(system.duration))
    values.append(values[-1])
    return np.array(times), np.array(values)


def run_fmu(system, folder, kind: str, output_interval: float = 1e-3, stop_time=None):
    """The FMU (an unpacked folder or a .fmu file) over the case's command cycle in FMPy:
    the structured result array of ``fmpy.simulate_fmu``."""
    import fmpy

    times, values = command_signal(system)
    load = np.full(times.shape, float(system.tables[0][rhs.C_F0]))
    signal = np.array(list(zip(times, values, load)), dtype=[
        ("time", float), ("valve_command", float), ("F_load", float)])
    stop = float(system.duration if stop_time is None else stop_time)
    return fmpy.simulate_fmu(str(folder), fmi_type="CoSimulation" if kind == "cs"
                             else "ModelExchange", stop_time=stop,
                             output_interval=output_interval, input=signal,
                             output=["x", "v", "p_cap", "p_rod", "T_cap", "T_rod",
                                     "F_friction", "stuck"])


def compare_with_python(system, folder, kind: str = "cs"):
    """Extend and retract times (the summary's definitions) of the FMU run and of
    ``sealsim pneumatic run`` over the case's cycle, and their relative differences; and the
    two runs (position and pressures) for the documentation."""
    from sealsim.pneumatic.simulation import run
    from sealsim.pneumatic.summary import stroke_times

    result = run(system)
    fmu = run_fmu(system, folder, kind)
    keys = ("extend_time_s", "retract_time_s")
    ref = stroke_times(result.timeseries["time_s"].to_numpy(),
                       result.timeseries["x_m"].to_numpy(), system.case)
    got = stroke_times(fmu["time"], fmu["x"], system.case)
    if any(ref[k] is None or got[k] is None for k in keys):
        raise ModelError(f"the case's cycle has no complete extend and retract stroke to "
                         f"compare (sealsim: {ref}, FMU: {got})")
    ref, got = ({k: d[k] for k in keys} for d in (ref, got))
    rel = {k: abs(got[k] / ref[k] - 1.0) for k in keys}
    frame = result.timeseries
    data = {"python_t": frame["time_s"].to_numpy(), "python_x": frame["x_m"].to_numpy(),
            "python_p1": frame["p1_bar_abs"].to_numpy() * 1e5,
            "python_p2": frame["p2_bar_abs"].to_numpy() * 1e5, "fmu_t": fmu["time"],
            "fmu_x": fmu["x"], "fmu_p1": fmu["p_cap"], "fmu_p2": fmu["p_rod"]}
    return {"fmu": got, "python": ref, "relative_difference": rel, "interface": kind}, data
