"""Robustness of the pneumatic simulation: random valve command sequences (hypothesis), clear
errors for bad input, failures that say where they happened."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sealsim.cases import apply_overrides, load_toml, validate_case
from sealsim.errors import ConvergenceError, InputError
from sealsim.pneumatic import PneumaticCase, simulate
from sealsim.pneumatic import integrate

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pneumatic"


def example_data(variant: str = "T25C") -> dict:
    data = load_toml(EXAMPLES / "cylinder_32.toml")
    return apply_overrides(data, data.pop("variants")[variant])


def case_with(overrides: dict, data: dict | None = None) -> PneumaticCase:
    return validate_case(PneumaticCase, apply_overrides(data or example_data(), overrides))


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(steps=st.lists(st.tuples(st.sampled_from(["extend", "retract", "centre"]),
                                st.floats(0.01, 0.3)), min_size=2, max_size=6),
       centre=st.sampled_from(["closed", "exhaust", "pressure"]),
       load=st.floats(-150.0, 300.0), bristles=st.booleans())
def test_random_command_sequences_run_clean(steps, centre, load, bristles):
    # Any PLC sequence on a 5/3 valve (switching while moving, reversals, centre positions,
    # loads pulling or pushing, sticking or bristle friction): no NaN, the piston stays between
    # its stops (within the bumper deflection), Θ in [0, 1], the balances close.
    data = example_data()
    if bristles:
        for s in data["seals"][:2]:
            s["friction"] = {**s["friction"], "bristle_stiffness": "2e5 N/m",
                             "bristle_damping": "400 N*s/m"}
    duration = sum(d for _, d in steps)
    case = case_with({
        "valve": {"type": "5/3", "centre": centre},
        "load": {"force": f"{load} N"},
        "controller": {"duration": f"{duration} s",
                       "steps": [{"command": c, "duration": f"{d} s"} for c, d in steps]},
        "output": {"sample_interval": "2 ms"}}, data)
    result = simulate(case)
    f = result.timeseries
    assert np.all(np.isfinite(f.select_dtypes("number").to_numpy()))
    assert f["x_m"].min() > -1e-3 and f["x_m"].max() < case.cylinder.stroke + 1e-3
    assert f["p1_bar_abs"].min() > 0 and f["p2_bar_abs"].min() > 0
    for name in ("piston", "rod"):
        theta = f[f"theta_{name}"]
        # (to round-off: a seal with bristles held at rest, Θ = 0, may integrate to -1e-31)
        assert theta.min() >= -1e-12 and theta.max() <= 1.0
    assert result.balances["mass_balance_rel_error"] < 1e-12
    # the energy balance measures the integration (kinetic and stop energy are not linear in
    # the states): a piston pressed into its stop from rest stores ½kδ² with δ resolved to the
    # position tolerance (1 µm at rtol 1e-5): up to 1.2e-3 with the compiled BDF, 1.5e-4 with
    # LSODA in the worst sequence hypothesis found (retract, retract, 123 N load)
    assert result.balances["energy_balance_rel_error"] < 2e-3


@pytest.mark.parametrize("overrides, expected", [
    ({"cylinder": {"rod_diameter": "40 mm"}}, "rod_diameter"),
    ({"cylinder": {"bore": "-32 mm"}}, "cylinder.bore"),
    ({"cylinder": {"stroke": "100"}}, "cylinder.stroke"),
    ({"air": {"supply_pressure": "6 kg"}}, "air.supply_pressure"),
    ({"valve": {"critical_pressure_ratio": 1.2}}, "valve.critical_pressure_ratio"),
    ({"valve": {"cushion": 1}}, "valve.cushion: unknown field"),
    ({"controller": {"steps": [{"command": "centre", "duration": "1 s"}]}}, "5/3 valve"),
    ({"controller": {"mode": "servo"}}, "controller"),
    ({"solver": {"method": "RK45"}}, "solver.method"),
])
def test_bad_input_is_one_clear_input_error(overrides, expected):
    with pytest.raises(InputError, match=expected.replace(".", r"\.").replace("(", r"\(")):
        case_with(overrides)


def test_seal_without_map_for_the_theta_law_is_refused():
    data = example_data()
    del data["seals"][0]["map"]
    with pytest.raises(InputError, match=r"seals\[0\] \('piston'\)\.map: the theta law needs"):
        simulate(case_with({}, data))


def test_contact_map_is_not_extrapolated():
    # the analytic estimate is used up to 120 °C by default; a seal at 150 °C is refused before
    # the run, naming the seal, the temperature and the range
    with pytest.raises(InputError, match=r"seals\[0\] \('piston'\).*150 degC.*outside"):
        simulate(case_with({"cylinder": {"seal_temperature": "150 degC"}}))
    data = example_data()
    data["seals"][0]["map"]["analytic"]["pressure_max"] = "4 bar"
    with pytest.raises(InputError, match=r"reaches 6 bar.*covers 0 \.\.\. 4 bar"):
        simulate(case_with({}, data))


def test_failed_integration_says_where(monkeypatch):
    # a solver failure becomes a ConvergenceError with the time and the state
    real = integrate._lsoda_step

    def failing(f, y, t, t_bound, *args):
        y1, t_new, istate = real(f, y, t, t_bound, *args)
        return y1, t_new, (-1 if t_new > 0.1 else istate)

    monkeypatch.setattr(integrate, "_lsoda_step", failing)
    with pytest.raises(ConvergenceError, match=r"failed at t = [0-9.]+ s, x = .* mm, v = .*"
                                               r"p1 = .* bar, p2 = .* bar, T1 = .* degC"):
        simulate(case_with({"controller": {"duration": "0.5 s"},
                            "solver": {"method": "LSODA"}}))


def test_failed_compiled_integration_says_where(monkeypatch):
    # the compiled driver's failure (step size too small) names the time and the state too
    real = integrate.run_interval

    def failing(t, t_end, y, mode, *args):
        result, t_new, mode, k, nseg = real(t, t_end, y, mode, *args)
        return integrate.STEP_FAILED, t_new, mode, k, nseg

    monkeypatch.setattr(integrate, "run_interval", failing)
    with pytest.raises(ConvergenceError, match=r"compiled BDF\) failed at t = [0-9.]+ s, "
                                               r"x = .* mm, v = .* m/s, p1 = .* bar, .*mode"):
        simulate(case_with({"controller": {"duration": "0.5 s"}}))
