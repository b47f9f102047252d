"""A seal's friction from its own contact (issue 23) in both FMUs (issue 27): the C port of the
friction table's interpolant (fmu/c/contact_table.c) against the numba kernel, the friction
FMU of a Θ law with ``steady = "contact"`` (build check, FMPy validation, the bench against
sealsim's law, a wrong table caught), and the whole-cylinder FMU of a case whose seal takes its
steady friction from its contact (right-hand-side check, FMPy validation, the cycle against
``sealsim pneumatic run``)."""

from __future__ import annotations

import ctypes
import subprocess
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmpy.validation import validate_fmu

from session_builds import built, session_build
from sealsim.cases import load_toml
from sealsim.errors import ModelError
from sealsim.fmu import LoadedFMU, build_fmu
from sealsim.fmu.builder import find_compiler, platform_folder
from sealsim.fmu.cosim import run_velocity
from sealsim.fmu.cylinder_export import cylinder_system, run_fmu
from sealsim.fmu.friction_export import friction_check
from sealsim.friction.bench import simulate_velocity
from sealsim.friction.case import build_law, load_friction_cases
from sealsim.friction.compiled import contact_steady
from sealsim.friction.contact_table import SteadyFrictionTable, contact_table_point
from sealsim.friction.kernels import theta_contact_level
from sealsim.pneumatic.bench import bench_inputs
from sealsim.pneumatic.case import load_pneumatic_cases
from sealsim.pneumatic.simulation import run
from sealsim.pneumatic.summary import stroke_times

ROOT = Path(__file__).resolve().parents[1]
BENCH = ROOT / "examples" / "friction" / "theta_contact_stribeck.toml"
CYLINDER = ROOT / "examples" / "pneumatic" / "heipl_rod_seal.toml"
SOURCES = ROOT / "src" / "sealsim" / "fmu" / "c"


@pytest.fixture(scope="module")
def c_table(tmp_path_factory):
    """contact_table.c compiled alone into a shared library (the FMU's compiler flags)."""
    compiler = find_compiler()
    if compiler is None:
        pytest.skip("no C compiler")
    lib = tmp_path_factory.mktemp("contact_table") / "contact_table.so"
    subprocess.run([compiler, "-shared", "-fPIC", "-O2", "-std=c99", "-ffp-contract=off",
                    str(SOURCES / "contact_table.c"), "-o", str(lib), "-lm"], check=True)
    so = ctypes.CDLL(str(lib))
    dbl, lng = ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_long)
    so.contact_table_point.argtypes = [lng, dbl] + [ctypes.c_double] * 3 + [dbl] * 3
    so.contact_steady.argtypes = [lng, dbl] + [ctypes.c_double] * 6 + [dbl] * 4
    so.film_decay_rate.argtypes = [lng, dbl] + [ctypes.c_double] * 3
    so.film_decay_rate.restype = ctypes.c_double
    so.theta_contact_level.argtypes = [ctypes.c_double] * 7
    so.theta_contact_level.restype = ctypes.c_double
    so.film_speed_rate.argtypes = [ctypes.c_double] * 4
    so.film_speed_rate.restype = ctypes.c_double
    so.film_speed_affine.argtypes = [ctypes.c_double] * 4 + [dbl] * 2
    return so


def test_c_table_lookup_is_the_numba_kernel(c_table):
    # an asymmetric random table (both stroke directions differ) on uneven axes: the C code
    # reads the node layout and forms each cell coefficient as HermiteGrid does, then sums in
    # the kernel's order (no FMA contraction), so the values agree to rounding -- 1e-14 of
    # the table's largest value is asserted (measured: equal)
    rng = np.random.default_rng(23)
    t = np.sort(rng.uniform(250.0, 380.0, 5))
    p = np.concatenate([[0.0], np.sort(rng.uniform(1e4, 8e5, 4))])
    u = np.logspace(-7.0, 1.0, 9)
    values = rng.uniform(0.0, 500.0, (t.size, p.size, u.size, 7))
    values[..., 4:6] *= 1e-8                                 # films [m]
    values[..., 6] *= 2.0                                    # the film's decay rate [1/s]
    table = SteadyFrictionTable(t, p, u, values)
    row, data = table.tables()                       # numba: cell coefficients
    nodes_row, nodes = table.node_tables()           # C: node values and derivatives
    assert nodes.size < data.size / 4           # (8x on a large grid)
    row_c = np.ascontiguousarray(nodes_row, dtype=np.int64).ctypes.data_as(ctypes.POINTER(
        ctypes.c_long))
    data_c = nodes.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
    out = [ctypes.c_double() for _ in range(3)]
    worst = 0.0
    scale = np.max(np.abs(values[..., :4]))
    # inside, outside the axes (clamped), at nodes, both directions, speed 0
    temps = np.concatenate([rng.uniform(230.0, 400.0, 300), t])
    for k, temp in enumerate(temps):
        pressure = p[k % p.size] if k % 7 == 0 else rng.uniform(-1e5, 9e5)
        speed = 0.0 if k % 50 == 0 else rng.choice([-1.0, 1.0]) * 10.0 ** rng.uniform(-9, 2)
        want = contact_table_point(row, data, temp, pressure, speed)
        c_table.contact_table_point(row_c, data_c, temp, pressure, speed,
                                    *(ctypes.byref(o) for o in out))
        worst = max(worst, max(abs(o.value - w) for o, w in zip(out[:2], want[:2])) / scale,
                    abs(out[2].value - want[2]) / np.max(values[..., 4:6]))
        par = np.zeros(16)
        par[13], par[15] = 0.3, np.pi * 0.02                 # mu_b, pi D
        # the film formed for: none, the steady film |v|, any speed (inside and beyond the
        # speed axis, and a negative one: the slowest node as none)
        film = (0.0, abs(speed), 10.0 ** rng.uniform(-9, 2), -1e-3)[k % 4]
        steady, boundary, viscous, decay = contact_steady(par, row, data, temp, pressure,
                                                          -1.0, speed, film)
        fss, fb, fv, kappa = (ctypes.c_double() for _ in range(4))
        c_table.contact_steady(row_c, data_c, temp, pressure, -speed, film, par[15], par[13],
                               ctypes.byref(fss), ctypes.byref(fb), ctypes.byref(fv),
                               ctypes.byref(kappa))
        worst = max(worst, abs(fss.value - steady) / (scale * par[15]),
                    abs(fb.value - boundary) / (scale * par[15]),
                    abs(fv.value - viscous) / (scale * par[15]),
                    abs(kappa.value - decay) / np.max(values[..., 6]))
        args = (rng.uniform(0, 1), speed, steady, boundary, 0.5, rng.uniform(0, 1), viscous)
        level = c_table.theta_contact_level(*args)
        worst = max(worst, abs(level - theta_contact_level(*args)) / (scale * par[15]))
    assert worst <= 1e-14


def test_c_table_reads_the_load_at_the_film_speed(c_table):
    # the independent check of the film in contact_steady: a table whose asperity load is
    # linear in log10 u (cubic Hermite reproduces it exactly) and whose viscous part is
    # another linear function -- F_ss = pi D (mu_b L(phi) + V(|v|)), L at the film's speed,
    # V at the sliding speed, phi = 0 the slowest node, its boundary part pi D mu_b L(phi) (the
    # base of the dwell drop), at rest no viscous part (1e-12: rounding of the sums)
    t, p, u = np.array([280.0, 320.0]), np.array([0.0, 5e5]), np.logspace(-6.0, 1.0, 8)
    log_u = np.log10(u)[None, None, :]
    values = np.zeros((t.size, p.size, u.size, 7))
    values[..., 0] = values[..., 2] = 100.0 - 10.0 * log_u          # load [N/m], both ways
    values[..., 1] = values[..., 3] = 5.0 + 2.0 * log_u             # viscous [N/m]
    values[..., 6] = 30.0 + 3.0 * log_u                              # decay rate [1/s]
    table = SteadyFrictionTable(t, p, u, values)
    nodes_row, nodes = table.node_tables()
    row_c = np.ascontiguousarray(nodes_row, dtype=np.int64).ctypes.data_as(ctypes.POINTER(
        ctypes.c_long))
    data_c = nodes.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
    circumference, mu = np.pi * 0.02, 0.3
    out = [ctypes.c_double() for _ in range(4)]
    for speed, film in ((0.1, 0.1), (-0.1, 1e-3), (0.1, 0.0), (2.0, 1e-8), (1e-3, 5.0),
                        (0.0, 1e-3), (0.0, 0.0)):
        c_table.contact_steady(row_c, data_c, 300.0, 2e5, speed, film, circumference, mu,
                               *(ctypes.byref(o) for o in out))
        phi = np.clip(film, u[0], u[-1])                 # the table clamped to its speeds
        load = 100.0 - 10.0 * np.log10(phi)
        viscous = 5.0 + 2.0 * np.log10(abs(speed)) if speed else 0.0
        assert out[0].value == pytest.approx(circumference * (mu * load + viscous), rel=1e-12)
        assert out[1].value == pytest.approx(circumference * mu * load, rel=1e-12)
        assert out[2].value == pytest.approx(circumference * viscous, abs=1e-12)
        # the film's decay rate at φ, whatever the direction (also alone: film_decay_rate)
        assert out[3].value == pytest.approx(30.0 + 3.0 * np.log10(phi), rel=1e-12)
        assert c_table.film_decay_rate(row_c, data_c, 300.0, 2e5, film) == out[3].value


def test_c_film_speed_is_the_numba_kernel(c_table):
    # film_speed_rate and film_speed_affine in C against the kernels over random inputs
    # (contact widths down to 0: the 1 µm floor), same formulas in the same order: rounding
    # only, 1e-14 relative to the terms' scale (measured: equal)
    from sealsim.friction.kernels import film_speed_affine, film_speed_rate

    rng = np.random.default_rng(5)
    a, c = ctypes.c_double(), ctypes.c_double()
    worst = 0.0
    for k in range(2000):
        v = 0.0 if k % 20 == 0 else rng.choice([-1.0, 1.0]) * 10.0 ** rng.uniform(-8, 1)
        b = 0.0 if k % 17 == 0 else 10.0 ** rng.uniform(-7, -2)
        # κ, the film's decay rate at rest [1/s]: 0 (no film) and the tables' range
        decay = 0.0 if k % 13 == 0 else 10.0 ** rng.uniform(-5, 3)
        dt, phi = 10.0 ** rng.uniform(-6, 0), rng.uniform(0, 3)
        scale = (abs(v) + phi) * (abs(v) / max(b, 1e-6) + decay) + 1e-300
        worst = max(worst, abs(c_table.film_speed_rate(phi, v, b, decay)
                               - film_speed_rate(phi, v, b, decay)) / scale)
        c_table.film_speed_affine(v, dt, b, decay, ctypes.byref(a), ctypes.byref(c))
        want_a, want_c = film_speed_affine(v, dt, b, decay)
        worst = max(worst, abs(a.value - want_a), abs(c.value - want_c) / max(abs(v), 1e-300))
    assert worst <= 1e-14


# -- the friction FMU on the seal's contact -------------------------------------------------
@pytest.fixture(scope="module")
def bench_case():
    case = load_friction_cases(load_toml(BENCH))["fast_sweep_4s"]
    law = build_law(case)
    inputs, _ = bench_inputs(case, law, BENCH.parent)
    return case, law, inputs


@session_build("contact_fmus", cost=50, needs=("pneumatic_numba",))
def build_contact_fmus(folder):
    """The friction FMU of theta_contact_stribeck.toml (FMI 2) and the whole-cylinder FMU of
    heipl_rod_seal.toml, T25C (FMI 3), both with the build checks."""
    friction = build_fmu(BENCH, folder / "contact.fmu", variant="fast_sweep_4s")
    cylinder = build_fmu(CYLINDER, folder / "heipl.fmu", variant="T25C", fmi_version=3)
    return {"friction": {"path": friction.path, "report": friction.report},
            "cylinder": {"path": cylinder.path, "report": cylinder.report}}


@pytest.fixture(scope="module")
def contact_fmus(tmp_path_factory, worker_id):
    return built(tmp_path_factory, worker_id, "contact_fmus")


def test_friction_fmu_carries_the_friction_table(contact_fmus):
    fmu = contact_fmus["friction"]
    assert validate_fmu(fmu["path"]) == []
    report = fmu["report"]
    # the build check drove the FMU through rest, sliding, reversal and dwells against
    # sealsim's Θ law reading the same table: 1e-9 relative is its limit (measured: equal)
    assert max(report["build_check"]["max_relative_difference"][k]
               for k in ("force", "states", "derivatives")) <= 1e-9
    assert report["friction_table"]["sliding_diameter_m"] == pytest.approx(0.012)
    assert report["friction_table"]["velocity_direction"] == 1.0
    with zipfile.ZipFile(fmu["path"]) as zf:
        assert "sources/contact_table.c" in zf.namelist()
        names = zf.read("modelDescription.xml").decode()
    for name in ("boundary_friction", "dwell_drop", "sliding_diameter", "velocity_direction"):
        assert f'name="{name}"' in names
    assert 'name="f_a"' not in names and 'name="gamma"' not in names


def test_friction_fmu_runs_the_bench_of_sealsim(contact_fmus, bench_case):
    # the fast Stribeck sweep (-1 ... 1 ... -1 m/s in 4 s, 0.1 ms steps): the FMU's Θ state,
    # film speed and force against sealsim's bench with the same exact step, 1e-9 relative
    # (the same formulas on the same table)
    case, law, inputs = bench_case
    b = case.bench
    native = simulate_velocity(law, b.velocity, b.duration, b.time_step, inputs=inputs,
                               initial_state=law.steady_state(
                                   np.array([b.velocity.value(0.0)]), inputs))
    t = native.time
    v_step = np.diff(b.velocity.integral(t)) / np.diff(t)
    assert law.state_names == ("theta", "film_speed")
    with LoadedFMU(contact_fmus["friction"]["path"]) as fmu:
        fmu.set(theta=float(native.states[0, 0]), film_speed=float(native.states[0, 1]))
        out = run_velocity(fmu, t, v_step, native.velocity, inputs)
    scale = np.max(np.abs(native.force))
    assert np.max(np.abs(out["F"] - native.force)) <= 1e-9 * scale
    assert np.max(np.abs(out["theta"] - native.states[:, 0])) <= 1e-9
    assert np.max(np.abs(out["film_speed"] - native.states[:, 1])) <= 1e-9 * np.max(
        np.abs(native.velocity))


def test_friction_fmu_film_state_follows_the_kernels(contact_fmus, bench_case):
    # the friction FMU's state film_speed φ against the kernels at random states and inputs:
    # the co-simulation step is film_speed_affine (exact for v and the film's decay rate κ
    # held, κ at the step's start), the model-exchange derivative film_speed_rate, with κ and
    # the force those of sealsim's law with that φ -- the same formulas on the same table,
    # 1e-9 relative (rounding)
    from dataclasses import replace

    from sealsim.fmu.cosim import _contact_inputs
    from sealsim.friction.kernels import film_speed_affine, film_speed_rate

    case, law, inputs = bench_case
    rng = np.random.default_rng(11)
    path = contact_fmus["friction"]["path"]
    with LoadedFMU(path) as cs, LoadedFMU(path, "me") as me:
        for k in range(40):
            v = 0.0 if k % 10 == 0 else rng.choice([-1.0, 1.0]) * 10.0 ** rng.uniform(-5, 0)
            dt = 10.0 ** rng.uniform(-5, 0)
            theta, film = rng.uniform(0.0, 1.0), (0.0, abs(v), rng.uniform(0.0, 1.0))[k % 3]
            z = np.array([[theta], [film]])
            for fmu in (cs, me):
                fmu.reset()
                fmu.set(v=v, theta=theta, film_speed=film, **_contact_inputs(inputs))
                fmu.initialize()
            force, fn, b, dp = cs.get("F", "F_N", "b", "dp")
            assert b == pytest.approx(float(inputs.contact_width), rel=1e-3)   # the map table
            fmu_inputs = replace(inputs, normal_force=fn, contact_width=b,
                                 pressure_difference=dp)       # the FMU's contact table
            want = float(law.force(z, np.array([v]), fmu_inputs)[0])
            assert force == pytest.approx(want, rel=1e-9, abs=1e-12)
            me.set_continuous_states([theta, film])
            decay = float(law.film_decay(np.array([v]), fmu_inputs, np.array([film]))[0])
            assert decay > 0.0
            assert me.derivatives()[1] == pytest.approx(film_speed_rate(film, v, b, decay),
                                                        rel=1e-9, abs=1e-300)
            cs.do_step(0.0, dt)
            a, c = film_speed_affine(v, dt, b, decay)
            assert cs.get("film_speed")[0] == pytest.approx(a * film + c, rel=1e-9, abs=1e-300)
        # sliding at a constant speed the film forms for it (φ → |v|) and the force reaches
        # sealsim's steady curve (independent: Theta.steady_force, 1e-9)
        cs.reset()
        cs.set(v=0.05, **_contact_inputs(inputs))
        cs.initialize()
        for _ in range(20):
            cs.do_step(0.0, 1.0)
        film, force, fn, b, dp = cs.get("film_speed", "F", "F_N", "b", "dp")
    assert film == pytest.approx(0.05, rel=1e-12)
    fmu_inputs = replace(inputs, normal_force=fn, contact_width=b, pressure_difference=dp)
    assert force == pytest.approx(float(law.steady_force(np.array([0.05]), fmu_inputs)[0]),
                                  rel=1e-9)


def test_friction_fmu_with_bristles_on_the_contact(tmp_path):
    # the Θ law on its contact with bristles: states theta, z, film_speed; the bristle step
    # takes the level of the step's mid-state, the film's speed at mid-step included
    # (Theta.step).  The build check runs the FMU (co-simulation and model exchange) against
    # sealsim's law through rest, sliding, reversal and dwells: 1e-9 relative (measured:
    # equal; the level at the start film speed instead of the mid-step one gave 0.15 in F)
    import tomli_w

    data = load_toml(BENCH)
    data["friction"].update(bristle_stiffness="1e5 N/m", bristle_damping="30 N*s/m")
    case = tmp_path / "bristles.toml"
    case.write_text(tomli_w.dumps(data))
    result = build_fmu(case, tmp_path / "bristles.fmu", variant="fast_sweep_4s")
    assert max(result.report["build_check"]["max_relative_difference"][k]
               for k in ("force", "states", "derivatives")) <= 1e-9
    with LoadedFMU(result.path, "me") as fmu:
        fmu.initialize()
        assert len(fmu.derivatives()) == 3             # theta, z, film_speed
        assert fmu.get("film_speed") == [0.0]            # no film at the start


def test_friction_fmu_refuses_a_negative_film_speed(contact_fmus):
    # the film's speed is a speed it formed for: a negative start value is named, not run
    with LoadedFMU(contact_fmus["friction"]["path"]) as fmu:
        fmu.set(film_speed=-0.1)
        with pytest.raises(ModelError, match=r"film_speed \(-0.1 m/s\).*must be >= 0"):
            fmu.initialize()


def test_friction_check_finds_a_wrong_table(tmp_path, bench_case):
    # the check can fail: the friction table's data scaled by 1 % in the sources
    from sealsim.fmu.friction_export import contact_table, friction_spec, steady_table
    from sealsim.pneumatic.bench import bench_contact_map

    case, law, inputs = bench_case
    out = build_fmu(BENCH, tmp_path / "c.fmu", variant="fast_sweep_4s", kind="cs",
                    compile=False).path
    folder = tmp_path / "unpacked"
    zipfile.ZipFile(out).extractall(folder)
    config = folder / "sources" / "config.h"
    text = config.read_text()
    start = text.index("static const double FRIC_DATA[] = {") + len(
        "static const double FRIC_DATA[] = {")
    end = text.index("}", start)
    values = np.array([float(x) for x in text[start:end].split(", ")])
    row = inputs.contact_table.tables()[0]
    axes = int(row[0] + row[1] + row[2])
    values[axes:] *= 1.01                    # the node values and derivatives
    config.write_text(text[:start] + ", ".join(repr(float(x)) for x in values) + text[end:])
    sub, suffix = platform_folder(2)
    binary = folder / "binaries" / sub / f"c{suffix}"
    binary.parent.mkdir(parents=True)
    subprocess.run([find_compiler(), "-shared", "-fPIC", "-O2", "-std=c99", "-I",
                    str(folder / "sources"), str(folder / "sources" / "all.c"), "-o",
                    str(binary), "-lm"], check=True)
    cmap = bench_contact_map(case, BENCH.parent)
    steady = steady_table(law, cmap, 0.012, 1.0)
    tab = contact_table(cmap)
    spec = friction_spec(law, "c", table=tab, steady=steady)
    with pytest.raises(ModelError, match="does not reproduce"):
        friction_check(law, spec, cmap, tab, ("cs",), steady)(folder, "")


# -- the whole-cylinder FMU with a contact-law seal ------------------------------------------
def test_cylinder_fmu_with_contact_friction(contact_fmus):
    fmu = contact_fmus["cylinder"]
    assert validate_fmu(fmu["path"]) == []
    report = fmu["report"]
    # the C right-hand side (contact_table.c inside) against the numba one at 400 random
    # states per stick/slip mode: 1e-9 of each quantity's range (measured: equal)
    assert max(report["rhs_check"]["max_relative_difference"].values()) <= 1e-9
    assert report["seals"][0]["friction_table"] is True
    # the build's co-simulation over the case's cycle: stroke times within 0.5 % (issue 27)
    assert max(report["cycle_check"]["relative_difference"].values()) < 5e-3


@pytest.mark.parametrize("kind", ["cs", "me"])
def test_cylinder_fmu_reproduces_sealsim_pneumatic_run(contact_fmus, kind):
    # FMPy (a host that does not know sealsim) over the 2 s cycle of heipl_rod_seal.toml at
    # 25 degC: extend and retract times within 0.5 % of sealsim pneumatic run (issue 27);
    # co-simulation integrates with the same BDF method (~1e-4), model exchange with FMPy's
    # CVode (~1e-3)
    case = load_pneumatic_cases(load_toml(CYLINDER))["T25C"]
    system = cylinder_system(case, CYLINDER.parent)
    frame = run(system).timeseries
    ref = stroke_times(frame["time_s"].to_numpy(), frame["x_m"].to_numpy(), case)
    res = run_fmu(system, contact_fmus["cylinder"]["path"], kind)
    got = stroke_times(res["time"], res["x"], case)
    for name in ("extend_time_s", "retract_time_s"):
        assert got[name] == pytest.approx(ref[name], rel=5e-3 if kind == "me" else 5e-4)
