"""Seal friction FMUs (issue 14): validity, the C laws against sealsim's Python laws on the
friction benches, the contact table, run-time clipping and errors, the build's file rules.

The FMUs are compiled once per test session (module fixtures); each test drives them through
FMPy.
"""

from __future__ import annotations

import importlib.util
import sys
import tempfile
import warnings
import zipfile
from pathlib import Path

import numpy as np
import pytest
import tomli_w
import xarray as xr
from typer.testing import CliRunner

import fmpy  # the test extra installs FMPy
from fmpy import simulate_fmu
from session_builds import built, session_build
from hypothesis import given, settings
from hypothesis import strategies as st
from fmpy.validation import validate_fmu

from sealsim.cases import load_toml
from sealsim.cli import app
from sealsim.errors import InputError, ModelError
from sealsim.fmu import LoadedFMU, build_fmu, build_friction_fmu
from sealsim.fmu.builder import FMUCompileError, FMUDependencyError
from sealsim.fmu.cosim import FMUFrictionLaw, run_velocity
from sealsim.friction import ContactInputs, Theta
from sealsim.friction import kernels
from sealsim.friction.bench import simulate_mass, simulate_velocity
from sealsim.friction.case import build_law, load_friction_cases, make_inputs

ROOT = Path(__file__).resolve().parents[1]
FRICTION = ROOT / "examples" / "friction"
PNEUMATIC = ROOT / "examples" / "pneumatic"


def friction_cases(name):
    return load_friction_cases(load_toml(FRICTION / name), name)


def quiet_law(case):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # LuGre Table I set: not passive (documented)
        return build_law(case)


@session_build("fmus", cost=15)
def build_fmus(folder):
    """The FMUs of the tests, compiled once: LuGre (FMI 2), Θ (FMI 2), the Θ piston seal of
    the Ø32 cylinder with its analytic contact table (FMI 3)."""
    return {
        "lugre": build_fmu(FRICTION / "lugre_hysteresis.toml", folder / "lugre.fmu").path,
        "theta": build_fmu(FRICTION / "theta_dwell.toml", folder / "theta.fmu").path,
        "piston3": build_fmu(PNEUMATIC / "cylinder_32.toml", folder / "piston3.fmu",
                             seal="piston", fmi_version=3).path,
    }


@pytest.fixture(scope="module")
def fmus(tmp_path_factory, worker_id):
    return {name: Path(path) for name, path in
            built(tmp_path_factory, worker_id, "fmus").items()}


def test_every_fmu_is_valid(fmus):
    # the FMI checks of FMPy: schema, variable names, model structure, start values, units
    for name, path in fmus.items():
        assert validate_fmu(str(path)) == [], name
    md = fmpy.read_model_description(str(fmus["piston3"]))
    assert md.fmiVersion == "3.0" and md.modelExchange and md.coSimulation
    md2 = fmpy.read_model_description(str(fmus["lugre"]))
    assert md2.fmiVersion == "2.0" and md2.modelExchange and md2.coSimulation
    names = {v.name: v for v in md.modelVariables}
    assert {"v", "p_A", "p_B", "T_seal", "F", "F_N", "b", "theta", "tau"} <= set(names)
    assert names["tau"].unit == "s" and names["T_seal"].unit == "K"
    # a solver scales its tolerance of a state with the nominal: z of LuGre is F_s/σ0 = 1.5 N
    # / 1e5 N/m (canudas1995), not 1 m; Θ is of order 1
    states = {v.name: v for v in md2.modelVariables}
    assert float(states["z"].nominal) == pytest.approx(1.5e-5, rel=1e-12)
    assert names["theta"].nominal in (None, "1", 1.0)
    with zipfile.ZipFile(fmus["piston3"]) as zf:     # sources for other platforms
        files = set(zf.namelist())
    assert {"sources/all.c", "sources/buildDescription.xml", "sources/friction_model.c",
            "documentation/index.html"} <= files


def test_velocity_hysteresis_matches_the_law(fmus):
    """LuGre velocity hysteresis (1995 Fig. 3, three frequencies) through the co-simulation
    interface against sealsim's bench: the C code takes the same exact step per 1 ms."""
    for name, case in friction_cases("lugre_hysteresis.toml").items():
        law = quiet_law(case)
        b = case.bench
        z0 = law.steady_state(np.array([b.velocity.value(0.0)]))
        native = simulate_velocity(law, b.velocity, b.duration, b.time_step, initial_state=z0)
        t = native.time
        v_step = np.diff(b.velocity.integral(t)) / np.diff(t)
        with LoadedFMU(fmus["lugre"]) as fmu:
            fmu.set(z=float(z0[0, 0]))
            out = run_velocity(fmu, t, v_step, native.velocity)
        # smooth law: 1e-6 relative (issue 14); the formulas are the same, so rounding only
        scale = np.max(np.abs(native.force))
        assert np.max(np.abs(out["F"] - native.force)) <= 1e-6 * scale, name
        assert np.max(np.abs(out["z"] - native.states[:, 0])) <= 1e-6 * np.max(
            np.abs(native.states[:, 0])), name


def test_dwell_breakaway_matches_the_law(fmus):
    """Θ law, break-away after dwells (true sticking): the FMU as the friction element of
    sealsim's stick/slip stepper, which decides sticking with the FMU's F_breakaway."""
    cases = friction_cases("theta_dwell.toml")
    for name in ("dwell_2s",):
        case = cases[name]
        law = build_law(case)
        b = case.bench
        native = simulate_mass(law, b.mass, b.duration, b.time_step, stiffness=b.stiffness,
                               drive_velocity=b.drive_velocity, inputs=make_inputs(case))
        with LoadedFMU(fmus["theta"]) as fmu:
            flaw = FMUFrictionLaw(fmu)
            flaw.start()
            res = simulate_mass(flaw, b.mass, b.duration, b.time_step, stiffness=b.stiffness,
                                drive_velocity=b.drive_velocity, integrator="stepper")
        # switching law: the stick/slip decisions are the same and the velocity solve
        # converges to 1e-12 relative, so 1e-8 of the force scale bounds the difference
        assert np.array_equal(res.stuck, native.stuck), name
        scale = np.max(np.abs(native.force))
        assert np.max(np.abs(res.force - native.force)) <= 1e-8 * scale, name
        assert np.max(np.abs(res.states[:, 0] - native.states[:, 0])) <= 1e-9, name
        # break-away from rest: the dry level F_N f_a (within the last step's load
        # increase); after the dwell the film has relaxed only partly: between F_N f_b and it
        fn = make_inputs(case).normal_force
        onsets = np.flatnonzero(np.diff(res.stuck.astype(int)) == -1)
        assert len(onsets) == 2
        assert res.force[onsets[0]] == pytest.approx(fn * law.params.f_a, rel=1e-3)
        assert fn * law.params.f_b < res.force[onsets[1]] < fn * law.params.f_a


def test_stick_slip_with_a_mass_matches_the_law(fmus):
    """LuGre stick-slip (1995 Fig. 7) with a 1 kg mass and a spring, one stick and one slip
    (9 s): the FMU inside sealsim's implicit stepper against the Python law in the same
    stepper."""
    case = next(iter(friction_cases("lugre_stick_slip.toml").values()))
    law = quiet_law(case)
    b = case.bench
    duration, step = 9.0, 2e-3
    native = simulate_mass(law, b.mass, duration, step, stiffness=b.stiffness,
                           drive_velocity=b.drive_velocity, integrator="stepper")
    with LoadedFMU(fmus["lugre"]) as fmu:
        flaw = FMUFrictionLaw(fmu)
        flaw.start()
        res = simulate_mass(flaw, b.mass, duration, step, stiffness=b.stiffness,
                            drive_velocity=b.drive_velocity, integrator="stepper")
    assert np.max(native.velocity) > 0.3                  # it slipped
    # smooth law: 1e-6 relative; the velocity solves converge to 1e-12 relative
    assert np.max(np.abs(res.velocity - native.velocity)) <= 1e-6 * np.max(native.velocity)
    assert np.max(np.abs(res.force - native.force)) <= 1e-6 * np.max(np.abs(native.force))


def test_model_exchange_matches_the_exact_law(fmus):
    """Θ law through model exchange, integrated by FMPy's CVode at constant velocity: the
    exact solution is the law's own step (closed form)."""
    law = build_law(friction_cases("theta_dwell.toml")["dwell_0.5s"])
    inputs = ContactInputs(normal_force=100.0, contact_width=1e-3)
    result = simulate_fmu(str(fmus["theta"]), fmi_type="ModelExchange", stop_time=2.0,
                          start_values={"v": 0.05}, output_interval=0.1,
                          relative_tolerance=1e-10, output=["theta", "F"])
    exact = np.array([law.step(law.initial_state(1), np.array([0.05]), t, inputs)[0, 0]
                      for t in result["time"]])
    # CVode at rtol 1e-10: the integration error stays far below 1e-6 relative
    assert np.max(np.abs(result["theta"] - exact)) <= 1e-6 * np.max(exact)
    force = law.force(exact[None, :], np.full(exact.size, 0.05), inputs)
    assert np.max(np.abs(result["F"] - force)) <= 1e-6 * np.max(force)


def test_contact_table_reproduces_the_maps(fmus, tmp_path):
    """The analytic estimate is tabulated with exact node derivatives (fourth order: better
    than 1e-5 at these points, 3e-5 anywhere); F_N(T) of a held seal peaks with a kink at its
    mounting temperature (20 °C), where the table has a node and two close neighbours; an FE
    map keeps its grid and slopes: the same interpolant as SealMap."""
    from sealsim.fmu.friction_export import contact_table
    from sealsim.pneumatic.case import build_contact_map, load_pneumatic_cases
    from sealsim.pneumatic.contact_maps import FEContactMap

    case = next(iter(load_pneumatic_cases(load_toml(PNEUMATIC / "cylinder_32.toml")).values()))
    seal = case.seals[0]
    cmap = build_contact_map(seal.map, case.cylinder.bore, PNEUMATIC, "map")
    # inside the map: from its cold edge (NBR's T_g + 20 K = -5 degC; colder is clipped, see
    # test_out_of_range_inputs_are_clipped_and_logged) to its hot corner
    coldest = cmap.ranges["temperature"][0]
    assert cmap.temperature_kinks == (293.15,)
    points = [(0.0, coldest), (3e5, 298.15), (7.7e5, 330.0), (1.6e6, 393.15), (1.23e5, 271.3),
              (0.0, 293.15), (2e5, 293.4), (5e5, 292.9)]
    assert max(contact_table(cmap).max_relative_error.values()) < 3e-5
    with LoadedFMU(fmus["piston3"]) as fmu:
        fmu.set(p_A=points[0][0], T_seal=points[0][1])
        fmu.initialize()
        for p, temp in points:
            fmu.set(p_A=p, T_seal=temp)
            fn, b, dp = fmu.get("F_N", "b", "dp")
            fn_ref, b_ref = cmap.evaluate(dp, temp)
            assert abs(fn / fn_ref - 1) < 1e-5 and abs(b / b_ref - 1) < 1e-5, (p, temp)

    # an FE characteristic map (synthetic data in the format of sealsim structure map)
    temps = np.array([273.15, 293.15, 333.15, 373.15])
    press = np.linspace(0.0, 1e6, 6)
    fn = 80.0 + 6e-5 * press[None, :] + 0.3 * (temps[:, None] - 273.15) \
        + 2e-11 * press[None, :] ** 2
    width = 6e-4 + 2e-10 * press[None, :] + 1e-6 * (temps[:, None] - 273.15) + 0 * fn
    ds = xr.Dataset({"F_N": (("squeeze", "temperature", "pressure"), fn[None]),
                     "b": (("squeeze", "temperature", "pressure"), width[None])},
                    coords={"squeeze": [0.15], "temperature": temps, "pressure": press})
    ds.to_netcdf(tmp_path / "map.nc")
    fe = FEContactMap.from_file(tmp_path / "map.nc")
    law = Theta.from_parameter_set("pneumatic_demo")
    result = build_friction_fmu(law, tmp_path / "fe.fmu", contact_map=fe, kind="cs")
    assert validate_fmu(str(result.path)) == []
    with LoadedFMU(result.path) as fmu:
        fmu.initialize()
        for p, temp in [(0.0, 273.15), (2.5e5, 300.0), (9.9e5, 370.0), (4e5, 333.15)]:
            fmu.set(p_A=p, T_seal=temp)
            fn_fmu, b_fmu, dp = fmu.get("F_N", "b", "dp")
            fn_ref, b_ref = fe.evaluate(dp, temp)
            # the same C1 Hermite interpolant: rounding only
            assert abs(fn_fmu / fn_ref - 1) < 1e-12 and abs(b_fmu / b_ref - 1) < 1e-12


def test_out_of_range_inputs_are_clipped_and_logged(fmus):
    with LoadedFMU(fmus["piston3"]) as fmu:
        fmu.set(v=0.1, p_A=1e5, T_seal=298.15)
        fmu.initialize()
        inside = fmu.get("F_N")[0]
        fmu.set(p_A=40e5, T_seal=500.0)                 # 40 bar, 227 degC: beyond the table
        fmu.do_step(0.0, 1e-3)
        force, fn, clipped = fmu.get("F", "F_N", "map_clipped")
        assert np.isfinite(force) and fn > inside and clipped == 1.0
        edge = fmu.get("F_N")[0]
        fmu.set(p_A=16e5, T_seal=393.15)                # the table's corner
        assert fmu.get("F_N")[0] == pytest.approx(edge, rel=1e-12)
        warnings_logged = [m for s, _, m in fmu.messages if s == "WARNING"]
        assert any("pressure difference dp" in m and "clipped" in m for m in warnings_logged)
        assert any("seal temperature T_seal" in m for m in warnings_logged)
        fmu.set(p_A=3e5, T_seal=298.15)
        assert fmu.get("map_clipped")[0] == 0.0
        count = len(fmu.messages)
        for _ in range(3):                              # logged once per excursion
            fmu.set(p_A=30e5)
            fmu.do_step(0.0, 1e-3)
            fmu.get("F")
        assert len([m for m in fmu.messages[count:] if m[0] == "WARNING"]) == 1


def test_bad_parameters_and_inputs_give_a_clear_message(fmus):
    with LoadedFMU(fmus["theta"]) as fmu:
        fmu.set(tau=-1.0)
        with pytest.raises(ModelError, match=r"parameter tau = -1 s is not allowed: it must be "
                                             r"> 0 s"):
            fmu.initialize()
    with LoadedFMU(fmus["lugre"]) as fmu:
        fmu.set(static_force=0.5)                       # below coulomb_force = 1 N
        with pytest.raises(ModelError, match="static_force .* must be >= coulomb_force"):
            fmu.initialize()
    with LoadedFMU(fmus["lugre"]) as fmu:
        fmu.initialize()
        with pytest.raises(ModelError, match="v = nan is not allowed: the value must be "
                                             "finite"):
            fmu.set(v=float("nan"))
        fmu.set(v=0.01)                                 # the instance is still usable
        fmu.do_step(0.0, 1e-3)
        assert np.isfinite(fmu.get("F")[0])
        with pytest.raises(ModelError, match="sigma0 is fixed"):
            fmu.set(sigma0=2e5)


def test_a_break_away_below_the_sliding_level_and_a_pressure_below_vacuum_are_refused(fmus):
    # as ThetaParameters and the friction case's [inputs]: f_b (full film, theta = 1) above
    # f_a (dry, theta = 0) and a gauge p_A below -1 atm ran without a word
    with LoadedFMU(fmus["theta"]) as fmu:
        fmu.set(f_b=0.4, f_a=0.2)
        with pytest.raises(ModelError, match=r"parameter f_b = 0.4 is larger than f_a = 0.2: "
                                             r"f_b \(the full-film friction coefficient, "
                                             r"theta = 1\) must be <= f_a"):
            fmu.initialize()
    for name in ("theta", "piston3"):
        with LoadedFMU(fmus[name]) as fmu:
            fmu.initialize()
            with pytest.raises(ModelError, match=r"input p_A = -300000 Pa is not allowed: it "
                                                 r"must be >= -101325 Pa \(it was not set\)"):
                fmu.set(p_A=-3e5)
            fmu.set(p_A=-101325.0, p_B=2e5)               # vacuum itself is allowed
            fmu.do_step(0.0, 1e-3)
            assert fmu.get("p_A")[0] == -101325.0 and np.isfinite(fmu.get("F")[0])


def test_law_without_c_code_is_refused(tmp_path):
    case = {"friction": {"law": "dahl", "parameter_set": "canudas1995"},
            "bench": {"mode": "velocity", "duration": "1 s", "time_step": "1 ms",
                      "velocity": {"kind": "constant", "level": "1 mm/s"}}}
    (tmp_path / "dahl.toml").write_text(tomli_w.dumps(case))
    with pytest.raises(InputError, match="'dahl' law has no C implementation .* coulomb, "
                                         "stribeck, lugre, theta"):
        build_fmu(tmp_path / "dahl.toml", tmp_path / "dahl.fmu")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dahl.toml"]


def test_cli_writes_atomically_and_refuses_an_existing_file(tmp_path, monkeypatch):
    scratch = tmp_path / "tmp"                  # this test's own temporary folder
    scratch.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(scratch))
    runner = CliRunner()
    out = tmp_path / "seal" / "theta.fmu"
    args = ["fmu", "build", str(FRICTION / "theta_dwell.toml"), "--out", str(out), "--kind",
            "cs", "-q"]
    first = runner.invoke(app, args)
    assert first.exit_code == 0, first.output
    assert "checked against sealsim's law" in first.output
    assert sorted(p.name for p in out.parent.iterdir()) == ["theta.fmu"]  # nothing else
    stamp = out.stat().st_mtime_ns
    again = runner.invoke(app, args)
    assert again.exit_code == 2 and "already exists; use --force" in again.output
    assert out.stat().st_mtime_ns == stamp
    forced = runner.invoke(app, args + ["--force", "--fmi", "3"])
    assert forced.exit_code == 0, forced.output
    assert fmpy.read_model_description(str(out)).fmiVersion == "3.0"
    assert validate_fmu(str(out)) == []
    assert sorted(p.name for p in out.parent.iterdir()) == ["theta.fmu"]
    assert list(scratch.iterdir()) == []                 # build scratch always removed
    wrong = runner.invoke(app, ["fmu", "build", str(FRICTION / "theta_dwell.toml"), "--out",
                                str(tmp_path / "x.zip")])
    assert wrong.exit_code == 2 and "must end in .fmu" in wrong.output
    kind = runner.invoke(app, args[:4] + [str(tmp_path / "k.fmu"), "--kind", "all"])
    assert kind.exit_code == 2 and "--kind 'all' is not allowed" in kind.output
    bad = runner.invoke(app, ["fmu", "build", str(PNEUMATIC / "cylinder_32.toml"), "--out",
                              str(tmp_path / "c.fmu")])       # the cylinder: which variant?
    assert bad.exit_code == 2 and "choose one with --variant" in bad.output
    assert not (tmp_path / "c.fmu").exists()
    failed = runner.invoke(app, ["fmu", "build", str(FRICTION / "theta_dwell.toml"), "--out",
                                 str(tmp_path / "nc.fmu"), "--kind", "cs"],
                           env={"CC": str(tmp_path / "none")})
    assert failed.exit_code == 1 and (tmp_path / "nc.fmu").exists()
    assert list(scratch.iterdir()) == []                 # also after a failed compile



def test_build_writes_through_the_one_result_mechanism(tmp_path, monkeypatch):
    # the builder had its own atomic write: no lock (two builds of one file raced, the second
    # replacing the first with --force), and the temporaries of a killed build stayed forever
    import subprocess

    from sealsim.errors import ResultBusyError
    from sealsim.output import ResultFile

    out = tmp_path / "theta.fmu"
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True).stdout.strip()
    with ResultFile(out, suffix=".fmu") as running:      # another build of the same file
        with pytest.raises(ResultBusyError, match="theta.fmu' is being written by another"):
            build_fmu(FRICTION / "theta_dwell.toml", out, compile=False, force=True)
        running.write_bytes(b"the other build's FMU")
    assert out.read_bytes() == b"the other build's FMU"
    (tmp_path / f".theta.fmu.{dead}.k1ll3d00.tmp").write_bytes(b"PK half")  # a killed build's
    # a build that fails in the middle (here: its validation) leaves the file as it was
    import fmpy.validation

    monkeypatch.setattr(fmpy.validation, "validate_fmu", lambda folder: ["broken"])
    with pytest.raises(ModelError, match="not valid"):
        build_fmu(FRICTION / "theta_dwell.toml", out, compile=False, force=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["theta.fmu"]  # and no temporaries
    monkeypatch.undo()
    build_fmu(FRICTION / "theta_dwell.toml", out, compile=False, force=True)
    assert validate_fmu(str(out)) == [] and sorted(p.name for p in tmp_path.iterdir()) == [
        "theta.fmu"]


def test_build_says_which_variant_it_exports_not_that_all_run(tmp_path, caplog):
    # 'sealsim fmu build' of a case with variants printed the run commands' "runs the
    # variants T25C, T55C; the base case ... is not run", while it exports one of them
    runner = CliRunner()
    piston = runner.invoke(app, ["fmu", "build", str(ROOT / "examples" / "fmu" /
                                                     "piston_seal.toml"),
                                 "--out", str(tmp_path / "p.fmu"), "--no-compile", "-q"])
    assert piston.exit_code == 0, piston.output
    text = " ".join(piston.output.split())            # the console wraps lines
    assert "runs the variants" not in text
    assert ("cylinder_32.toml' has the variants T25C, T55C; they give the same FMU but for the "
            "start value of the input T_seal (25 degC in 'T25C'): built from the first, "
            "'T25C' (--variant chooses another)") in text
    chosen = build_fmu(ROOT / "examples" / "fmu" / "piston_seal.toml", tmp_path / "q.fmu",
                       variant="T55C", compile=False)
    assert chosen.report["notes"] == [] and chosen.report["source"].endswith(
        "variant 'T55C', seal 'piston'")
    md = fmpy.read_model_description(str(tmp_path / "q.fmu"))
    assert {v.name: v.start for v in md.modelVariables}["T_seal"] == "328.15"
    # variants that give different FMUs still have to be chosen, and the run note stays off
    load = runner.invoke(app, ["fmu", "build", str(FRICTION / "theta_load.toml"), "--out",
                               str(tmp_path / "l.fmu"), "--no-compile"])
    assert load.exit_code == 2 and "choose one with --variant" in load.output
    assert "runs the variants" not in load.output
    # ... also when they differ only in the seal whose contact map the FMU embeds (the first
    # variant was exported as if they were the same)
    squeezes = load_toml(FRICTION / "theta_contact_stribeck.toml")
    squeezes["variants"] = {"c10": {"seal": {"map": {"analytic": {"squeeze": 0.10}}}},
                            "c14": {"seal": {"map": {"analytic": {"squeeze": 0.14}}}}}
    (tmp_path / "squeezes.toml").write_text(tomli_w.dumps(squeezes))
    with pytest.raises(InputError, match="has the variants c10, c14; choose one"):
        build_fmu(tmp_path / "squeezes.toml", tmp_path / "s.fmu", compile=False)
    # the run commands still announce it
    from sealsim.cases import expand_variants
    from sealsim.friction.case import FrictionCase

    with caplog.at_level("INFO", logger="sealsim.cases"):
        expand_variants(FrictionCase, load_toml(FRICTION / "theta_load.toml"), "x")
    assert any("runs the variants" in r.getMessage() for r in caplog.records)

def test_missing_compiler_still_writes_the_source_fmu(tmp_path, monkeypatch):
    monkeypatch.setenv("CC", str(tmp_path / "no-such-compiler"))
    out = tmp_path / "src.fmu"
    with pytest.raises(FMUCompileError, match="(?s)no-such-compiler' was not found.*source "
                                              "FMU was written"):
        build_fmu(FRICTION / "lugre_stick_slip.toml", out, fmi_version=3)
    assert validate_fmu(str(out)) == []
    with zipfile.ZipFile(out) as zf:
        names = zf.namelist()
    assert "sources/buildDescription.xml" in names and "sources/fmi3Functions.h" in names
    assert not any(n.startswith("binaries/") for n in names)
    result = CliRunner().invoke(app, ["fmu", "build", str(FRICTION / "lugre_stick_slip.toml"),
                                      "--out", str(out), "--force", "-q"])
    assert result.exit_code == 1 and "was not found" in result.output


def test_missing_fmpy_is_explained(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "fmpy", None)
    with pytest.raises(FMUDependencyError, match=r"pip install 'sealsim\[fmu\]'"):
        build_fmu(FRICTION / "theta_dwell.toml", tmp_path / "t.fmu")


def test_fitted_parameters_and_named_sets(tmp_path):
    """An FMU case taking the law of a fit (fitted_parameters.toml) for a pneumatic seal; the
    FMU's parameters are the fitted values, with units."""
    fitted = {"friction": {"law": "theta", "tau": "1.5 s", "alpha": "0.08 m", "f_a": 0.42,
                           "f_b": 0.09, "gamma": "2e4 Pa*s", "reference_normal_force": "100 N",
                           "load_exponent": 1.0, "bristle_stiffness": "5000 N/m",
                           "bristle_damping": "0 N*s/m"}}
    (tmp_path / "fitted_parameters.toml").write_text("# fit\n" + tomli_w.dumps(fitted))
    (tmp_path / "seal.toml").write_text(tomli_w.dumps({
        "title": "fitted piston seal",
        "fmu": {"name": "FittedSeal", "source": str(PNEUMATIC / "cylinder_32.toml"),
                "seal": "rod", "friction_file": "fitted_parameters.toml"},
        "table": {"temperature_points": 4, "pressure_points": 9}}))
    result = build_fmu(tmp_path / "seal.toml", tmp_path / "fitted.fmu", kind="cs")
    assert validate_fmu(str(result.path)) == []
    md = fmpy.read_model_description(str(result.path))
    assert md.coSimulation.modelIdentifier == "FittedSeal" and md.modelExchange is None
    start = {v.name: v for v in md.modelVariables}
    assert float(start["tau"].start) == 1.5 and float(start["f_a"].start) == 0.42
    assert float(start["bristle_stiffness"].start) == 5000.0
    assert start["gamma"].unit == "Pa.s" and "z" in start and "F_breakaway" not in start
    assert result.report["build_check"]["max_relative_difference"]["force"] <= 1e-9


def test_fmu_case_with_its_own_law(tmp_path):
    """An FMU case with [friction] (a named set) and, for the theta law, [seal_contact]."""
    stribeck = {"title": "Stribeck rod seal", "fmu": {"name": "RodSeal"},
                "friction": {"law": "stribeck", "parameter_set": "pneumatic_demo"}}
    (tmp_path / "stribeck.toml").write_text(tomli_w.dumps(stribeck))
    result = build_fmu(tmp_path / "stribeck.toml", tmp_path / "rod.fmu", kind="me")
    assert validate_fmu(str(result.path)) == []
    with LoadedFMU(result.path, "me") as fmu:
        fmu.set(v=0.02, p_A=6e5)
        fmu.initialize()
        force, brk = fmu.get("F", "F_breakaway")
    # seed 001 Eq. 2/3 with the set: F_C(p) = 15 N + 1.5e-5 m2 * 6 bar = 24 N, F_S/F_C = 5/3
    assert brk == pytest.approx(40.0, rel=1e-12)
    assert force == pytest.approx(24.0 + 16.0 * np.exp(-1.0) + 8.0 * 0.02, rel=1e-12)
    theta = {"fmu": {}, "friction": {"law": "theta", "parameter_set": "pneumatic_demo"}}
    (tmp_path / "theta.toml").write_text(tomli_w.dumps(theta))
    with pytest.raises(InputError, match="theta law needs the seal's normal force"):
        build_fmu(tmp_path / "theta.toml", tmp_path / "theta.fmu")
    theta["seal_contact"] = {"normal_force": "100 N", "contact_width": "1 mm"}
    (tmp_path / "theta.toml").write_text(tomli_w.dumps(theta))
    result = build_fmu(tmp_path / "theta.toml", tmp_path / "theta.fmu", kind="cs")
    variables = {v.name: v for v in fmpy.read_model_description(str(result.path)).modelVariables}
    # gamma(T) of the base oil (SKF LGMT 2: 110 and 11 mm2/s): parameters with units; T_seal
    # starts at the reference temperature 25 degC, where gamma(T) = gamma
    assert variables["base_oil_nu40"].unit == "m2/s"
    assert float(variables["base_oil_nu40"].start) == pytest.approx(110e-6, rel=1e-12)
    assert float(variables["base_oil_nu100"].start) == pytest.approx(11e-6, rel=1e-12)
    assert variables["reference_temperature"].unit == "K"
    assert float(variables["T_seal"].start) == pytest.approx(298.15, rel=1e-12)


def test_cosimulation_example(tmp_path):
    """examples/fmu/stick_slip_cosim.py: FMPy drives the FMU with the mass-spring of the LuGre
    stick-slip benchmark; the explicit host and the implicit master get the native stick-slip."""
    spec = importlib.util.spec_from_file_location(
        "stick_slip_cosim", ROOT / "examples" / "fmu" / "stick_slip_cosim.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    case, law = example.load_case()
    fmu_path = build_fmu(example.CASE, tmp_path / "lugre.fmu", kind="cs").path
    assert validate_fmu(str(fmu_path)) == []
    native = example.native(case, law, 9.0)
    explicit = example.compare(example.explicit_cosimulation(fmu_path, case, 9.0, 1e-3), native)
    # the first slip: an explicit 1 ms coupling against Radau (rtol 1e-7) -- the slip
    # velocity within 1 % of its peak (0.37 m/s), the peak force within 1e-4 relative
    assert explicit["max_velocity_difference_m_s"] < 0.01 * np.max(native.velocity)
    assert explicit["peak_force_N"] == pytest.approx(np.max(native.force), rel=1e-4)


# -- the C code against the compiled law kernels (sealsim.friction.kernels) ------------------------
@session_build("kernel_fmus", cost=4)
def build_kernel_fmus(folder):
    """Coulomb and Stribeck (pressure scaling), Θ with γ(T) with bristles (constant
    contact)."""
    from sealsim.friction import CoulombViscous, Stribeck

    bristles = Theta.from_parameter_set("pneumatic_demo", bristle_stiffness=5e4,
                                        bristle_damping=20.0)
    return {
        "coulomb": build_friction_fmu(CoulombViscous.from_parameter_set("unit"),
                                      folder / "coulomb.fmu", kind="cs").path,
        "stribeck": build_friction_fmu(Stribeck.from_parameter_set("pneumatic_demo"),
                                       folder / "stribeck.fmu", kind="cs").path,
        "theta_bristles": build_friction_fmu(bristles, folder / "bristles.fmu",
                                             normal_force=100.0, contact_width=1e-3).path,
    }


@pytest.fixture(scope="module")
def kernel_fmus(fmus, tmp_path_factory, worker_id):
    """Every C law: Coulomb and Stribeck (pressure scaling), LuGre, Θ with γ(T) without and
    with bristles (constant contact)."""
    return {"lugre": fmus["lugre"], "theta": fmus["theta"],
            **{name: Path(path) for name, path in
               built(tmp_path_factory, worker_id, "kernel_fmus").items()}}


def _close(got, want, scale):
    # the C code evaluates the kernels' formulas in their order: rounding only (1e-9 of the
    # larger of the value and the scale of its terms, where terms may cancel)
    assert abs(got - want) <= 1e-9 * max(abs(want), scale), (got, want)


def _walther(params):
    from sealsim.properties.oils import walther_constants

    return walther_constants(313.15, params["base_oil_nu40"], 373.15, params["base_oil_nu100"])


_INPUTS = st.fixed_dictionaries({
    "v": st.one_of(st.floats(-2.0, 2.0), st.sampled_from([0.0, 1e-7, -1e-7])),
    "dt": st.floats(1e-5, 1.0), "p_A": st.floats(0.0, 1e6), "p_B": st.floats(0.0, 1e6),
    "T_seal": st.floats(240.0, 400.0), "state": st.floats(0.0, 1.0),
    "sign": st.sampled_from([-1.0, 1.0])})
_THETA = st.fixed_dictionaries({
    "tau": st.floats(0.1, 10.0), "alpha": st.floats(1e-3, 1.0), "f_a": st.floats(0.05, 1.0),
    "f_b_ratio": st.floats(0.01, 1.0), "gamma": st.floats(0.0, 1e5),   # f_b <= f_a
    "reference_normal_force": st.floats(10.0, 1000.0), "load_exponent": st.floats(0.0, 3.0),
    "normal_force": st.floats(1.0, 1000.0), "contact_width": st.floats(0.0, 5e-3),
    "reference_temperature": st.floats(270.0, 370.0), "base_oil_nu40": st.floats(2e-5, 5e-4),
    "viscosity_ratio": st.floats(0.05, 0.5), "bristle_stiffness": st.floats(1e3, 1e6),
    "bristle_damping": st.floats(0.0, 100.0)})
_STRIBECK = st.fixed_dictionaries({
    # F_C = 0 or a real level: a subnormal F_C scales F_S(p) = F_S F_C(p)/F_C to inf
    "coulomb_force": st.one_of(st.just(0.0), st.floats(1e-3, 50.0)),
    "excess": st.floats(0.0, 50.0),
    "stribeck_velocity": st.floats(1e-4, 1.0), "exponent": st.floats(0.2, 10.0),
    "viscous_coefficient": st.floats(0.0, 100.0), "pressure_coefficient": st.floats(0.0, 1e-4),
    "sigma0": st.floats(1e3, 1e6), "sigma1": st.floats(0.0, 500.0), "sigma2": st.floats(0.0, 10.0)})


def _start(fmu, names, params, x, state):
    fmu.reset()
    fmu.set(**{k: params[k] for k in names}, v=x["v"], p_A=x["p_A"], p_B=x["p_B"],
            T_seal=x["T_seal"], **state)
    fmu.initialize()


@settings(max_examples=40, deadline=None, derandomize=True)  # the same cases in CI
@given(x=_INPUTS, p=_THETA)
def test_theta_c_code_matches_the_kernels(kernel_fmus, x, p):
    p = {**p, "base_oil_nu100": p["base_oil_nu40"] * p["viscosity_ratio"],
         "f_b": p["f_a"] * p["f_b_ratio"]}
    names = ["tau", "alpha", "f_a", "f_b", "gamma", "reference_normal_force", "load_exponent",
             "normal_force", "contact_width", "reference_temperature", "base_oil_nu40",
             "base_oil_nu100"]
    v, dt, fn, b = x["v"], x["dt"], p["normal_force"], p["contact_width"]
    rate = (p["tau"], p["alpha"], fn, p["reference_normal_force"], p["load_exponent"])
    coefficients = (fn, p["f_a"], p["f_b"])
    gamma = p["gamma"] * kernels.walther_viscosity_ratio(
        x["T_seal"], p["reference_temperature"], *_walther(p))
    theta0 = x["state"]
    a, c = kernels.theta_affine(v, dt, *rate)
    theta1 = a * theta0 + c
    level = kernels.theta_friction_level
    scale = fn * max(p["f_a"], p["f_b"]) + abs(gamma * b * v)
    with LoadedFMU(kernel_fmus["theta"]) as fmu:
        _start(fmu, names, p, x, {"theta": theta0})
        force, brk = fmu.get("F", "F_breakaway")
        _close(force, kernels.theta_force(theta0, v, fn, b, p["f_a"], p["f_b"], gamma), scale)
        _close(brk, level(theta0, *coefficients), scale)
        fmu.do_step(0.0, dt)
        theta, force = fmu.get("theta", "F")
        _close(theta, theta1, 1.0)
        _close(force, kernels.theta_force(theta1, v, fn, b, p["f_a"], p["f_b"], gamma), scale)
    with LoadedFMU(kernel_fmus["theta"], "me") as fmu:
        _start(fmu, names, p, x, {})
        fmu.set_continuous_states([theta0])
        _close(fmu.derivatives()[0], kernels.theta_rate(theta0, v, *rate),
               1.0 / p["tau"] + abs(v) / p["alpha"])

    # with bristles: the LuGre bristle at the level of the step's mid-state
    s0, s1 = p["bristle_stiffness"], p["bristle_damping"]
    z0 = x["sign"] * x["state"] * level(theta0, *coefficients) / s0
    a_z, c_z = kernels.lugre_affine(v, dt, s0, level(0.5 * (theta0 + theta1), *coefficients))
    z1 = a_z * z0 + c_z

    def bristle_force(theta, z):
        zdot = kernels.lugre_bristle_rate(z, v, s0, level(theta, *coefficients))
        return kernels.lugre_force(z, zdot, v, s0, s1, 0.0) + gamma * b * v

    with LoadedFMU(kernel_fmus["theta_bristles"]) as fmu:
        _start(fmu, names + ["bristle_stiffness", "bristle_damping"], p, x,
               {"theta": theta0, "z": z0})
        scale_z = scale + s1 * abs(v)
        _close(fmu.get("F")[0], bristle_force(theta0, z0), scale_z)
        fmu.do_step(0.0, dt)
        theta, z, force = fmu.get("theta", "z", "F")
        _close(theta, theta1, 1.0)
        _close(z, z1, scale / s0)
        _close(force, bristle_force(theta1, z1), scale_z)
    with LoadedFMU(kernel_fmus["theta_bristles"], "me") as fmu:
        _start(fmu, names + ["bristle_stiffness", "bristle_damping"], p, x, {})
        fmu.set_continuous_states([theta0, z0])
        d_theta, d_z = fmu.derivatives()
        _close(d_theta, kernels.theta_rate(theta0, v, *rate), 1.0 / p["tau"] + abs(v) / p["alpha"])
        _close(d_z, kernels.lugre_bristle_rate(z0, v, s0, level(theta0, *coefficients)), abs(v))


@settings(max_examples=40, deadline=None, derandomize=True)  # the same cases in CI
@given(x=_INPUTS, p=_STRIBECK)
def test_stribeck_lugre_coulomb_c_code_matches_the_kernels(kernel_fmus, x, p):
    v, dt, pa, pb = x["v"], x["dt"], x["p_A"], x["p_B"]
    fc, fs = p["coulomb_force"], p["coulomb_force"] + p["excess"]
    vs, d, fv, f = (p["stribeck_velocity"], p["exponent"], p["viscous_coefficient"],
                    p["pressure_coefficient"])
    with LoadedFMU(kernel_fmus["stribeck"]) as fmu:
        _start(fmu, [], {}, x, {"coulomb_force": fc, "static_force": fs,
                                "stribeck_velocity": vs, "exponent": d,
                                "viscous_coefficient": fv, "pressure_coefficient": f})
        fcp, fsp = kernels.stribeck_scaled_levels(fc, fs, f, pa, pb)
        force, brk = fmu.get("F", "F_breakaway")
        _close(force, kernels.stribeck_force(v, fcp, fsp, vs, fv, d), fsp + abs(fv * v))
        _close(brk, fsp, fsp)
    with LoadedFMU(kernel_fmus["coulomb"]) as fmu:
        _start(fmu, [], {}, x, {"coulomb_force": fc, "viscous_coefficient": fv,
                                "pressure_coefficient": f})
        fcp = kernels.pressure_scaled_force(fc, f, pa, pb)
        force, brk = fmu.get("F", "F_breakaway")
        _close(force, kernels.coulomb_viscous_force(v, fcp, fv), fcp + abs(fv * v))
        _close(brk, fcp, fcp)
    if fc <= 0.0:
        return                                  # LuGre needs F_C > 0
    s0, s1, s2 = p["sigma0"], p["sigma1"], p["sigma2"]
    g = kernels.stribeck_level(v, fc, fs, vs, d)
    z0 = x["sign"] * x["state"] * g / s0
    a_z, c_z = kernels.lugre_affine(v, dt, s0, g)
    z1 = a_z * z0 + c_z

    def lugre_force(z):
        return kernels.lugre_force(z, kernels.lugre_bristle_rate(z, v, s0, g), v, s0, s1, s2)

    scale = g + (s1 + s2) * abs(v)
    lugre = {"sigma0": s0, "sigma1": s1, "sigma2": s2, "coulomb_force": fc, "static_force": fs,
             "stribeck_velocity": vs, "exponent": d}
    with LoadedFMU(kernel_fmus["lugre"]) as fmu:
        _start(fmu, [], {}, x, {**lugre, "z": z0})
        _close(fmu.get("F")[0], lugre_force(z0), scale)
        fmu.do_step(0.0, dt)
        z, force = fmu.get("z", "F")
        _close(z, z1, g / s0)
        _close(force, lugre_force(z1), scale)
    with LoadedFMU(kernel_fmus["lugre"], "me") as fmu:
        _start(fmu, [], {}, x, lugre)
        fmu.set_continuous_states([z0])
        _close(fmu.derivatives()[0], kernels.lugre_bristle_rate(z0, v, s0, g), abs(v))


def test_case_kinds_are_those_of_sealsim_cases(tmp_path):
    # one registry of case kinds (sealsim.cases.CASE_KINDS): an FMU case run with another
    # command is named as such, a case the FMU cannot be built from is refused with its kind
    result = CliRunner().invoke(app, ["rotary", "run", str(ROOT / "examples" / "fmu" /
                                                           "rotary_lip_seal.toml"),
                                      "--out", str(tmp_path / "out")])
    message = " ".join(result.output.split())
    assert result.exit_code == 2 and "looks like a fmu case" in message
    assert "sealsim fmu build" in message
    with pytest.raises(InputError, match=r"neither a friction case .* \(it looks like a "
                                         r"structure case\)"):
        build_fmu(ROOT / "examples" / "structure" / "oring_map.toml", tmp_path / "s.fmu")
    assert not (tmp_path / "s.fmu").exists()
