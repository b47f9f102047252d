"""The whole-cylinder FMU (sealsim.fmu.cylinder_export): valid FMI 2 and 3, its C right-hand
side against the compiled (numba) one, co-simulation and model exchange in FMPy -- a host
that knows nothing of sealsim -- against ``sealsim pneumatic run`` over the example cycle,
the valve's dead time, FMU states, and the refusals."""

from __future__ import annotations

from pathlib import Path

import fmpy
import numpy as np
import pytest
import tomli_w
from fmpy.validation import validate_fmu

from session_builds import built, session_build
from sealsim.cases import load_toml
from sealsim.errors import InputError, ModelError
from sealsim.fmu import build_fmu
from sealsim.fmu.cylinder_export import cylinder_system, rhs_check, run_fmu
from sealsim.fmu.instance import LoadedFMU
from sealsim.pneumatic.case import load_pneumatic_cases
from sealsim.pneumatic.simulation import run
from sealsim.pneumatic.summary import stroke_times

ROOT = Path(__file__).resolve().parents[1]
PNEUMATIC = ROOT / "examples" / "pneumatic"


def example_case(variant="T25C", **updates):
    case = load_pneumatic_cases(load_toml(PNEUMATIC / "cylinder_32.toml"))[variant]
    return case.model_copy(update=updates)


@session_build("cylinders", cost=10, needs=("pneumatic_numba",))
def build_cylinder_fmus(folder):
    """The Ø32 cylinder (T25C) as FMI 2 and FMI 3 FMUs, model exchange and co-simulation;
    every build runs the build check (C right-hand side, co-simulation over the cycle)."""
    out = {}
    for version in (2, 3):
        result = build_fmu(PNEUMATIC / "cylinder_32.toml", folder / f"cyl{version}.fmu",
                           variant="T25C", fmi_version=version)
        out[f"fmi{version}"] = {"path": result.path, "report": result.report}
    return out


@pytest.fixture(scope="module")
def cylinders(tmp_path_factory, worker_id):
    return built(tmp_path_factory, worker_id, "cylinders")


@pytest.fixture(scope="module")
def reference():
    system = cylinder_system(example_case(), PNEUMATIC)
    result = run(system)
    frame = result.timeseries
    return system, stroke_times(frame["time_s"].to_numpy(), frame["x_m"].to_numpy(),
                                system.case), frame


def test_cylinder_fmus_are_valid_fmi_2_and_3(cylinders):
    for key, version in (("fmi2", "2.0"), ("fmi3", "3.0")):
        path = cylinders[key]["path"]
        assert validate_fmu(path) == []
        md = fmpy.read_model_description(path)
        assert md.fmiVersion == version and md.modelExchange and md.coSimulation
        # the case's title describes both variants ("seals at 25 vs 55 degC"); the FMU holds
        # one of them, and its name and description say which
        title = "Ø32 cylinder, rectangular command, seals at 25 vs 55 degC (variant T25C)"
        assert md.modelName == title and md.description.endswith(f": {title}")
        assert md.coSimulation.modelIdentifier == f"cyl{version[0]}"     # the file's name
        names = {v.name for v in md.modelVariables}
        assert {"valve_command", "F_load", "x", "v", "p_cap", "p_rod", "T_cap", "T_rod",
                "F_friction", "F_piston", "F_rod", "F_wiper", "F_N_piston", "theta_piston",
                "valve_delay"} <= names
        described = {v.name: v.description for v in md.modelVariables}
        assert described["dp_piston"] == "pressure difference across the seal piston"
        assert described["F_N_rod"] == "normal force of the seal rod"
        # Θ seals without bristles and a Coulomb wiper stick truly: one event indicator
        assert md.numberOfEventIndicators == 1
        if version == "3.0":
            assert [v.variable.name for v in md.eventIndicators] == ["stick_slip_indicator"]


def test_c_right_hand_side_is_the_compiled_one(cylinders):
    # the build check compared the C right-hand side with sealsim.pneumatic.rhs at 400
    # random states per mode (stick, slip+, slip-): the same formulas on the same tables,
    # so the difference is rounding at most -- 1e-9 of each quantity's range is the limit
    # (gcc and numba both without FMA contraction give identical bits on this machine)
    for key in ("fmi2", "fmi3"):
        worst = cylinders[key]["report"]["rhs_check"]["max_relative_difference"]
        assert set(worst) == {"dy", "outputs", "seals"}
        assert max(worst.values()) <= 1e-9


_COUNTING_HARNESS = r"""
#include <math.h>
/* calls of the C library functions the right-hand side uses: sin once per evaluation (the
 * load's weight on the incline), exp per spool position, tanh per seal pressure difference,
 * sqrt 7 per chamber's flows (valve and cushion lines, ISO 6358) and 3 per analytic contact
 * map lookup */
static long n_sin, n_exp, n_tanh, n_minmax, n_sqrt;
static double counted_sin(double x) { n_sin++; return (sin)(x); }
static double counted_exp(double x) { n_exp++; return (exp)(x); }
static double counted_tanh(double x) { n_tanh++; return (tanh)(x); }
static double counted_fmin(double a, double b) { n_minmax++; return (fmin)(a, b); }
static double counted_fmax(double a, double b) { n_minmax++; return (fmax)(a, b); }
static double counted_sqrt(double x) { n_sqrt++; return (sqrt)(x); }
#define sin(x) counted_sin(x)
#define exp(x) counted_exp(x)
#define tanh(x) counted_tanh(x)
#define fmin(a, b) counted_fmin(a, b)
#define fmax(a, b) counted_fmax(a, b)
#define sqrt(x) counted_sqrt(x)
#include "all.c"

static CylinderData m;
static Problem p;

static void setup(int mode) {
    memset(&m, 0, sizeof m);
    for (int i = 0; i < C_NCONST; i++) m.cst[i] = CYL_C[i];
    m.command = 1.0;                /* the spool moving from -1 towards +1 since t = 0 */
    m.s_command = -1.0;
    problem_init(&p, &m);
    p.mode = mode;
}

static void take(long *counts) {
    counts[0] = n_sin;
    counts[1] = n_exp;
    counts[2] = n_tanh;
    counts[3] = n_minmax;
    counts[4] = n_sqrt;
    n_sin = n_exp = n_tanh = n_minmax = n_sqrt = 0;
}

/* the integrator's calls at (t, y): f = fun(t, y), the Jacobian from it, the velocity's column
 * renewed from it; the library calls of each in counts[0:5], [5:10], [10:15] */
__attribute__((visibility("default")))
void sealsim_jacobian(double t, const double *y, int mode, double *f, double *jac,
                      double *renewed, long *counts) {
    setup(mode);
    take(counts);
    p.bp.fun(&p, t, y, f);
    take(counts);
    p.bp.jac(&p, t, y, f, jac);
    take(counts + 5);
    p.bp.renew(&p, t, y, f, renewed);
    take(counts + 10);
}

/* the right-hand side at (t, y) in a fresh problem */
__attribute__((visibility("default")))
void sealsim_rates(double t, const double *y, int mode, double *f) {
    setup(mode);
    p.bp.fun(&p, t, y, f);
}
"""


def test_a_jacobian_costs_one_right_hand_side_per_state(cylinders, tmp_path):
    # The integrator hands the Jacobian f(t, y), which its Newton iteration has evaluated
    # (sealsim.ode.bdf does the same): 8 evaluations for the 8 states, one for a renewal of
    # the velocity's column -- the C core evaluated f(t, y) again for each (9 and 2).  Within
    # them the spool's position (an exp) is computed once per time, not per evaluation; fmin
    # and fmax are inlined, not 76 calls into libm per evaluation; each seal's pressure
    # difference is the smoothed |dp| of its own side only (2 tanh per evaluation, not 6);
    # and a column keeps the valve and wall flows at y of the chambers whose air it leaves as
    # it is (v and the friction states: both, m1 and U1: the rod end's, m2 and U2: the cap
    # end's): 8 chambers' flows per Jacobian instead of 18.  Together with the BDF's
    # constants (no sums per use) the 10 s cycle of the benchmark took 41.8 million
    # instructions before, 31.0 million after (valgrind --tool=callgrind), with bitwise the
    # same states.  The columns are the forward differences of f itself, to the bit.
    import ctypes
    import subprocess
    import zipfile

    from sealsim.fmu.builder import find_compiler
    from sealsim.pneumatic import rhs

    folder = tmp_path / "unpacked"
    zipfile.ZipFile(cylinders["fmi2"]["path"]).extractall(folder)
    (folder / "sources" / "harness.c").write_text(_COUNTING_HARNESS, "utf-8")
    lib_path = tmp_path / "harness.so"
    subprocess.run([find_compiler(), "-shared", "-fPIC", "-O2", "-std=c99",
                    "-ffp-contract=off", "-fvisibility=hidden", "-DFMI_VERSION=2", "-I",
                    str(folder / "sources"), str(folder / "sources" / "harness.c"), "-o",
                    str(lib_path), "-lm"], check=True, capture_output=True, timeout=300)
    lib = ctypes.CDLL(str(lib_path))
    dbl, lng = ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_long)
    lib.sealsim_jacobian.argtypes = [ctypes.c_double, dbl, ctypes.c_int, dbl, dbl, dbl, lng]
    lib.sealsim_rates.argtypes = [ctypes.c_double, dbl, ctypes.c_int, dbl]

    system = cylinder_system(example_case(), PNEUMATIC)
    n = system.n_dynamic
    y = np.ascontiguousarray(system.initial_state()[:n])
    y[0], y[1] = 0.03, 0.2                      # mid-stroke, extending
    t = 0.012                                   # the spool on its way (6 ms dead time)
    f = np.zeros(n)
    jac, renewed = np.zeros((n, n)), np.zeros((n, n))
    counts = np.zeros(15, dtype=np.int64)
    lib.sealsim_jacobian(t, y.ctypes.data_as(dbl), rhs.FORWARD, f.ctypes.data_as(dbl),
                         jac.ctypes.data_as(dbl), renewed.ctypes.data_as(dbl),
                         counts.ctypes.data_as(lng))
    rate_seals = sum(1 for s in system.seals if s.location in ("piston", "rod"))
    assert n == 8 and rate_seals == 2
    # (sin, exp, tanh, fmin + fmax, sqrt): f(t, y) itself is one evaluation, one spool
    # position, both chambers' flows and both maps looked up (7 + 7 + 3 + 3 square roots)
    assert counts[:5].tolist() == [1, 1, rate_seals, 0, 20]
    # the Jacobian: 8 evaluations, 8 chambers' flows (the v column's 2, x's 2 and one for
    # each of m1, m2, U1, U2), the maps looked up in 4 columns (v, x, U1, U2); was
    # (9, 9, 54, 676, 156)
    assert counts[5:10].tolist() == [n, 0, rate_seals * n, 0, 7 * 8 + 3 * rate_seals * 4]
    # the renewal of the velocity's column: one evaluation (was (2, 2, 12, 150, 34))
    assert counts[10:15].tolist() == [1, 0, rate_seals, 0, 20]
    # the columns: (f(y + h e_j) - f(y)) / h, h = 1.5e-8 max(|y_j|, scale_j), to the bit
    scale = system.tolerances(1.0)[:n]
    shifted_f = np.zeros(n)
    for j in range(n):
        h = 1.5e-8 * max(abs(y[j]), scale[j])
        shifted = y.copy()
        shifted[j] = y[j] + h
        lib.sealsim_rates(t, shifted.ctypes.data_as(dbl), rhs.FORWARD,
                          shifted_f.ctypes.data_as(dbl))
        np.testing.assert_array_equal(jac[:, j], (shifted_f - f) / h)
    np.testing.assert_array_equal(renewed[:, 1], jac[:, 1])


def test_rhs_check_finds_a_wrong_c_model(tmp_path):
    # the check can fail: sources with a changed constant (the end-stop stiffness) differ
    import zipfile

    system = cylinder_system(example_case(), PNEUMATIC)
    out = build_fmu(PNEUMATIC / "cylinder_32.toml", tmp_path / "c.fmu", variant="T25C",
                    kind="cs", compile=False).path
    folder = tmp_path / "unpacked"
    zipfile.ZipFile(out).extractall(folder)
    config = folder / "sources" / "config.h"
    text = config.read_text()
    c0 = text.index("static const double CYL_C[] = {")
    values = text[c0:text.index("}", c0)].split("{")[1].split(", ")
    from sealsim.pneumatic import rhs

    values[rhs.C_KS] = repr(float(values[rhs.C_KS]) * 1.01)
    config.write_text(text[:c0] + "static const double CYL_C[] = {" + ", ".join(values)
                      + text[text.index("}", c0):])
    worst = rhs_check(system, folder, samples=200)
    assert worst["dy"] > 1e-4


@pytest.mark.parametrize("key, kind", [("fmi2", "cs"), ("fmi3", "cs"), ("fmi2", "me"),
                                       ("fmi3", "me")])
def test_fmu_reproduces_sealsim_pneumatic_run(cylinders, reference, key, kind):
    # the 4 s cycle of examples/pneumatic/cylinder_32.toml (T25C) driven from FMPy with the
    # case's commands; extend and retract times within 0.5 % of sealsim pneumatic run (the
    # issue's acceptance limit).  Co-simulation integrates with the same BDF method and
    # tolerance and restarts at the same points: ~1e-4; model exchange runs FMPy's CVode
    # with its own error control: ~1e-3.
    system, times, _ = reference
    res = run_fmu(system, cylinders[key]["path"], kind, output_interval=1e-3)
    got = stroke_times(res["time"], res["x"], system.case)
    for name in ("extend_time_s", "retract_time_s"):
        assert got[name] == pytest.approx(times[name], rel=5e-3 if kind == "me" else 5e-4)


def test_cosimulation_states_at_coarse_communication_steps(cylinders, reference):
    # 20 ms communication steps (the speed setting of the benchmark): the FMU keeps its
    # integrator's history between steps, so the states at the communication points match
    # sealsim pneumatic run sampled there -- position within 0.1 % of the stroke, pressures
    # within 0.5 % of the supply pressure
    system, _, frame = reference
    res = run_fmu(system, cylinders["fmi2"]["path"], "cs", output_interval=0.02)
    t_ref = frame["time_s"].to_numpy()
    x_ref = np.interp(res["time"], t_ref, frame["x_m"].to_numpy())
    p_ref = np.interp(res["time"], t_ref, frame["p1_bar_abs"].to_numpy() * 1e5)
    assert np.max(np.abs(res["x"] - x_ref)) < 1e-3 * system.stroke
    assert np.max(np.abs(res["p_cap"] - p_ref)) < 5e-3 * system.p_supply


def _states_at_whole_seconds(path, step):
    """x, v, p_cap, p_rod, T_cap, T_rod after each second of a 4 s extend/retract cycle driven
    through doSteps of ``step`` (a power of 2 in s: the command changes at exact seconds)."""
    rows = []
    with LoadedFMU(path, "cs") as fmu:
        fmu.set(valve_command=1.0)
        fmu.initialize()
        per_second = round(1.0 / step)
        for k in range(4 * per_second):
            fmu.set(valve_command=1.0 if (k // per_second) % 2 == 0 else -1.0)
            fmu.do_step(k * step, step)
            if (k + 1) % per_second == 0:
                rows.append(fmu.get("x", "v", "p_cap", "p_rod", "T_cap", "T_rod"))
    return np.array(rows)


def test_cosimulation_does_not_depend_on_the_communication_step(cylinders):
    # While the inputs stay the same the integrator neither restarts nor cuts its steps at a
    # communication point (the state there is the dense output of the step across it), so
    # 1/64 s and 1 s communication steps take the same steps: the same states after every
    # second to round-off.  Cutting the steps at every communication point took 3149 instead
    # of 1933 steps for the 10 s cycle at 20 ms (25722 at 1 ms) and moved the states by
    # ~1e-8 relative, the integrator's own error.
    coarse = _states_at_whole_seconds(cylinders["fmi2"]["path"], 1.0)
    fine = _states_at_whole_seconds(cylinders["fmi2"]["path"], 2.0 ** -6)
    assert coarse[0, 0] > 0.09 and coarse[1, 0] < 0.01          # it extends and retracts
    scale = np.max(np.abs(coarse), axis=0) + np.array([0.0, 1e-3, 0.0, 0.0, 0.0, 0.0])
    assert np.max(np.abs(fine - coarse) / scale) < 1e-12


def test_valve_dead_time_and_fmu_state(cylinders):
    # a command reaches the spool valve_delay later; get/set FMU state restores the
    # integrator's history: the same result again
    path = cylinders["fmi2"]["path"]
    with LoadedFMU(path, "cs") as fmu:
        fmu.set(valve_command=-1.0)
        fmu.initialize()
        fmu.set(valve_command=1.0)
        fmu.do_step(0.0, 0.005)                    # 5 ms < 6 ms dead time: no motion yet
        spool, = fmu.get("spool")
        assert spool == -1.0
        fmu.do_step(0.005, 0.005)
        assert fmu.get("spool")[0] > -1.0
        state = fmu.get_state()
        fmu.do_step(0.01, 0.2)
        first = fmu.get("x", "p_cap")
        fmu.set_state(state)
        fmu.do_step(0.01, 0.2)
        assert fmu.get("x", "p_cap") == first
        assert first[0] > 0.01                     # it extends
        fmu.free_state(state)


def test_bad_command_is_refused(cylinders):
    with LoadedFMU(cylinders["fmi2"]["path"], "cs") as fmu:
        fmu.initialize()
        fmu.set(valve_command=2.0)
        with pytest.raises(ModelError, match="valve_command = 2 is not allowed"):
            fmu.do_step(0.0, 0.01)


def test_a_step_of_the_load_breaks_a_stuck_piston_away_in_cosimulation(cylinders):
    # The retracted piston sticks; F_load steps from 20 N to -2000 N (pulling, 4x the 415 N
    # of 6 bar on the rod side).  Co-simulation restarted its integrator with the holding
    # force already beyond the break-away -- no crossing left to find -- and the seals held
    # 2020 N for ever (model exchange, with its event indicator, extended).
    with LoadedFMU(cylinders["fmi2"]["path"], "cs") as fmu:
        fmu.set(valve_command=-1.0)
        fmu.initialize()
        fmu.do_step(0.0, 0.1)
        assert fmu.get("stuck", "x")[0] == 1.0
        fmu.set(F_load=-2000.0)
        for k in range(10):
            fmu.do_step(0.1 + 0.01 * k, 0.01)
        stuck, x, friction = fmu.get("stuck", "x", "F_friction")
        # pulled out to the rod-end stop (stroke 100 mm) within 0.1 s; seal friction tens of N
        assert stuck == 0.0 and x > 0.099 and abs(friction) < 100.0


@pytest.mark.parametrize("version", ["fmi2", "fmi3"])
def test_a_load_that_empties_a_chamber_is_refused(cylinders, version):
    # 1 MN on the rod pushed the retracted piston 0.5 m into the cap-end bumper, and the FMU
    # went on with p_cap = -13 MPa absolute; sealsim pneumatic run refuses such a position
    # (check_chamber_volumes), and so does the FMU.  The step that gets there reports it: the
    # outputs were computed lazily, so doStep said OK and the error came at the host's next
    # read (or never, for a host that reads nothing)
    with LoadedFMU(cylinders[version]["path"], "cs") as fmu:
        fmu.set(valve_command=-1.0)
        fmu.initialize()
        fmu.do_step(0.0, 0.01)
        saved = fmu.get_state()
        fmu.set(F_load=1e6)
        with pytest.raises(ModelError, match=r"doStep failed \(at t = [\d.]+ s the piston is "
                                             r"[\d.]+ mm deep in the cap-end end stop's bumper "
                                             r".*F_load = 1e\+06 N\): more than the dead "
                                             r"volume of that chamber \(5 cm\^3\)"):
            for k in range(100):
                fmu.do_step(0.01 * (k + 1), 0.01)
        assert k < 10
        # FMI: after an error a host may go on from a saved FMU state
        fmu.set_state(saved)
        fmu.free_state(saved)
        fmu.set(F_load=20.0)
        fmu.do_step(0.01, 0.01)
        assert fmu.get("x")[0] == pytest.approx(0.0, abs=1e-3)


def test_a_supply_pressure_at_or_below_ambient_is_refused(cylinders):
    # p_supply is absolute; 6 (bar meant) ran the cylinder on 6 Pa.  The case's
    # air.supply_pressure is a gauge pressure > 0: the FMU asks p_supply > ambient.
    with LoadedFMU(cylinders["fmi2"]["path"], "cs") as fmu:
        fmu.set(p_supply=6.0)
        with pytest.raises(ModelError, match=r"parameter p_supply = 6 Pa is not allowed: it "
                                             r"must be > 101325 Pa"):
            fmu.initialize()


def test_unsupported_cases_are_refused(tmp_path):
    from sealsim.pneumatic.case import ThermalModel

    with pytest.raises(InputError, match="seal_heating is not in the cylinder FMU"):
        cylinder_system(example_case(thermal=ThermalModel()), PNEUMATIC)
    rig = load_pneumatic_cases(load_toml(PNEUMATIC / "friction_rig.toml"))
    with pytest.raises(InputError, match="test rig"):
        cylinder_system(next(iter(rig.values())), PNEUMATIC)


def test_fe_map_in_c_is_the_compiled_interpolant(tmp_path):
    # a seal with a gridded (FE) contact map: the C port of the Hermite grid interpolant
    # gives the numba one's values (the build's right-hand-side check, 1e-9 of the range)
    import xarray as xr

    p = np.linspace(0.0, 8e5, 9)
    t = np.array([283.15, 303.15, 333.15])
    pp, tt = np.meshgrid(p, t, indexing="ij")
    fn = 30.0 + 6e-5 * pp + 0.2 * (tt - 293.15) + 5e-12 * pp ** 2
    b = 5e-4 + 4e-10 * pp + 1e-6 * (tt - 293.15)
    dims = ("squeeze", "temperature", "pressure")
    xr.Dataset({"F_N": (dims, fn.T[None]), "b": (dims, b.T[None])},
               coords={"squeeze": [0.12], "temperature": t, "pressure": p}).to_netcdf(
        tmp_path / "map.nc")
    data = load_toml(PNEUMATIC / "cylinder_32.toml")
    data.pop("variants")
    data["seals"][1]["map"] = {"file": str(tmp_path / "map.nc")}
    case_file = tmp_path / "fe.toml"
    case_file.write_text(tomli_w.dumps(data))
    result = build_fmu(case_file, tmp_path / "fe.fmu", kind="me")
    assert result.report["seals"][1]["contact_map"] == "FEContactMap"
    assert max(result.report["rhs_check"]["max_relative_difference"].values()) <= 1e-9
