"""The cylinder with seal friction: friction opposes motion, slows it, forms hysteresis loops,
follows the seal temperature as in seed 001, sticks without creep; every friction law runs."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sealsim.cases import apply_overrides, load_toml, validate_case
from sealsim.pneumatic import PneumaticCase, simulate

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pneumatic"


def example(overrides: dict | None = None, variant: str = "T25C", seals=None,
            name: str = "cylinder_32.toml") -> PneumaticCase:
    """An example case (one variant) with overrides; ``seals`` replaces the seal list."""
    data = load_toml(EXAMPLES / name)
    data = apply_overrides(data, data.pop("variants")[variant])
    data = apply_overrides(data, overrides or {})
    if seals is not None:
        data["seals"] = seals
    return validate_case(PneumaticCase, data)


ONE_CYCLE = {"controller": {"duration": "2 s"}}


@pytest.fixture(scope="module")
def temperatures():
    """cylinder_32.toml, seals at 25 and 55 °C, one extend/retract cycle."""
    return {v: simulate(example(ONE_CYCLE, v)) for v in ("T25C", "T55C")}


def test_friction_opposes_motion(temperatures):
    # Friction acts against the sliding velocity: F·v >= 0 for every seal and the total,
    # wherever the piston moves (|v| > 0.1 mm/s, above the integration's speed resolution)
    for result in temperatures.values():
        f = result.timeseries
        v = f["v_m_s"].to_numpy()
        moving = np.abs(v) > 1e-4
        assert moving.sum() > 200
        for col in ["F_friction_N"] + [f"F_{n}_N" for n in result.seal_names]:
            assert np.all(f[col].to_numpy()[moving] * v[moving] > 0), col
        # dissipative: the work of the friction forces is positive and what the balance books
        assert result.balances["friction_work_J"] > 0


def test_friction_stroke_loop_is_hysteretic(temperatures):
    # Seed 001 Figs. 12/13: positive friction while extending, negative while retracting -- the
    # F–x loop encloses an area equal to the friction work ∮F dx (trapezoid rule on the samples
    # vs the integrated bookkeeping state: 2 % for the 1 ms sampling of the impacts)
    f = temperatures["T25C"].timeseries
    x, force, v = f["x_m"].to_numpy(), f["F_friction_N"].to_numpy(), f["v_m_s"].to_numpy()
    mid = (x > 0.04) & (x < 0.06)
    assert force[mid & (v > 0.05)].min() > 0 > force[mid & (v < -0.05)].max()
    loop = float(np.sum(0.5 * (force[1:] + force[:-1]) * np.diff(x)))
    assert loop > 0
    assert loop == pytest.approx(temperatures["T25C"].balances["friction_work_J"], rel=0.02)


def test_warmer_seal_presses_a_little_harder_but_its_thinner_grease_wins(temperatures):
    # Seed 001 Fig. 10 text: "at low temperature the piston reacts a little bit faster and more
    # dynamic due to lower contact forces and in succession lower friction".  The analytic
    # contact map with the held-seal modulus (mounted at 20 °C): from 25 to 55 °C the cord's
    # thermal expansion raises the squeeze (+4 %), the relaxed modulus falls 5 %, so F_N
    # rises by only 1-4 % (with the former E ∝ T: +14 %).  The lumped Θ law's grease term
    # γ(T) falls to 0.18 (ASTM D341), and that wins: the warm seal has less friction and the
    # piston is faster -- the opposite of the paper's claim for this illustrative law
    # (docs/guide/pneumatic.md, "Seal temperature").
    from sealsim.pneumatic.contact_maps import lindley_force_per_length, thermal_squeeze
    from sealsim.properties.elastomers import get_elastomer

    nbr = get_elastomer("NBR")
    cold, hot = temperatures["T25C"], temperatures["T55C"]
    s_cold, s_hot = cold.summary(), hot.summary()
    for seal, squeeze in (("piston", 0.10), ("rod", 0.12)):
        fn_cold = cold.timeseries[f"F_N_{seal}_N"].to_numpy()
        fn_hot = hot.timeseries[f"F_N_{seal}_N"].to_numpy()
        # unpressurised (the runs' smallest F_N, at about Δp = 0): the ratio of the hand
        # calculation, Lindley's force of the thermally grown squeeze times the held modulus
        # (within 0.5 %: the piston seal's minimum has a little pressure on it)
        hand = [lindley_force_per_length(thermal_squeeze(squeeze, nbr.thermal_expansion, t,
                                                         293.15), 2e-3,
                                         nbr.held_modulus(t, mounting_temperature=293.15))
                for t in (298.15, 328.15)]
        assert fn_hot.min() / fn_cold.min() == pytest.approx(hand[1] / hand[0], rel=0.005)
        assert 1.005 < fn_hot.min() / fn_cold.min() < 1.05
        assert 1.005 < fn_hot.max() / fn_cold.max() < 1.05
    # the grease wins: mean friction -14 %, stroke times -0.6 % (above the integration error,
    # 1e-4 of the stroke, test_pneumatic_cylinder)
    assert s_hot["mean_friction_N"] < 0.95 * s_cold["mean_friction_N"]
    assert s_hot["extend_time_s"] < 0.998 * s_cold["extend_time_s"]
    assert s_hot["retract_time_s"] < 0.998 * s_cold["retract_time_s"]


def test_stroke_times_grow_with_friction(temperatures):
    # no seals < the example's seals < the same seals with twice the friction coefficients
    base = temperatures["T25C"].summary()
    none = simulate(example(ONE_CYCLE, seals=[])).summary()
    data = load_toml(EXAMPLES / "cylinder_32.toml")["seals"]
    for s in data:
        if s["friction"]["law"] == "theta":
            s["friction"] = {**s["friction"], "f_a": 1.0, "f_b": 0.2}
    double = simulate(example(ONE_CYCLE, seals=data)).summary()
    for key in ("extend_time_s", "retract_time_s"):
        assert none[key] < base[key] < double[key], key
    assert none["peak_friction_N"] == 0.0
    assert double["mean_friction_N"] > 1.5 * base["mean_friction_N"]


def test_theta_stays_in_the_unit_interval(temperatures):
    for result in temperatures.values():
        for name in ("piston", "rod"):
            theta = result.timeseries[f"theta_{name}"].to_numpy()
            assert theta.min() >= 0.0 and theta.max() <= 1.0
            assert theta.max() > 0.5          # the film built up while sliding


def test_sticking_piston_does_not_creep():
    # A 5/3 valve with closed centre stops the piston mid-stroke: the shut-in air is a spring,
    # the seals stick (true stiction of the Θ law without bristles): x does not change at all
    # while stuck (no creep, the body is held by the set-valued friction force)
    seals = load_toml(EXAMPLES / "cylinder_32.toml")["seals"]
    for s in seals[:2]:           # a break-away 5x the running level: a clear stick margin
        s["friction"] = {**s["friction"], "f_a": 0.5, "f_b": 0.1}
    case = example({"valve": {"type": "5/3", "centre": "closed"},
                    "controller": {"duration": "1.2 s",
                                   "steps": [{"command": "extend", "duration": "0.15 s"},
                                             {"command": "centre", "duration": "2 s"}]}},
                   seals=seals)
    f = simulate(case).timeseries
    late = f[f["time_s"] > 0.6]
    assert (late["mode"] == "stick").all()
    assert 0.005 < late["x_m"].iloc[0] < 0.095          # stopped inside the stroke
    assert late["x_m"].max() - late["x_m"].min() == 0.0
    # the seals carry the force that holds the piston, within their break-away force
    assert np.all(np.abs(late["F_friction_N"]) > 0)


def test_bristle_variant_of_the_theta_law_runs_smooth():
    # Θ law with a pre-sliding bristle (no set-valued friction): one smooth ODE ("free"), same
    # stroke times as the sticking variant within 3 % (the bristle adds a small compliance)
    seals = load_toml(EXAMPLES / "cylinder_32.toml")["seals"][:2]
    for s in seals:
        s["friction"] = {**s["friction"], "bristle_stiffness": "1e5 N/m",
                         "bristle_damping": "300 N*s/m"}
    smooth = simulate(example(ONE_CYCLE, seals=seals))
    assert set(smooth.timeseries["mode"]) == {"free"}
    sticky = simulate(example(ONE_CYCLE, seals=load_toml(
        EXAMPLES / "cylinder_32.toml")["seals"][:2])).summary()
    s = smooth.summary()
    for key in ("extend_time_s", "retract_time_s"):
        assert s[key] == pytest.approx(sticky[key], rel=0.03)
    assert s["energy_balance_rel_error"] < 1e-3


@pytest.mark.parametrize("friction", [
    {"law": "stribeck", "parameter_set": "pneumatic_demo"},
    {"law": "lugre", "parameter_set": "canudas1995", "coulomb_force": "15 N",
     "static_force": "25 N", "stribeck_velocity": "0.01 m/s", "sigma2": "20 N*s/m"},
    {"law": "dahl", "parameter_set": "canudas1995", "coulomb_force": "20 N"},
], ids=lambda f: f["law"])
def test_every_friction_law_drives_the_cylinder(friction):
    # any law of sealsim.friction can be a seal; the run is finite, friction opposes motion,
    # the cylinder reaches both ends, the balances close.  (GMS runs too but its element
    # switching makes the error-controlled integrator slow: 6 s for this case, not tested here.)
    seals = [{"name": "piston", "location": "piston", "friction": friction}]
    result = simulate(example({"controller": {"duration": "1.4 s",
                                              "steps": [{"command": "extend",
                                                         "duration": "0.7 s"},
                                                        {"command": "retract",
                                                         "duration": "0.7 s"}]}},
                              seals=seals))
    f = result.timeseries
    assert np.all(np.isfinite(f.select_dtypes("number").to_numpy()))
    # laws with a bristle state (LuGre, Dahl) lag behind velocity reversals (pre-sliding
    # memory; the bounces at the end stops reverse v at 0.1 m/s), so for them opposition is
    # checked while sliding steadily mid-stroke; the work is dissipative anyway
    sliding = np.abs(f["v_m_s"]) > 1e-3
    if friction["law"] != "stribeck":
        sliding &= (np.abs(f["v_m_s"]) > 0.05) & (f["x_m"] > 0.01) & (f["x_m"] < 0.09)
    assert sliding.sum() > 100
    assert np.all(f["F_piston_N"][sliding] * f["v_m_s"][sliding] > 0)
    assert result.balances["friction_work_J"] > 0
    s = result.summary()
    assert s["extend_time_s"] is not None and s["retract_time_s"] is not None
    assert s["energy_balance_rel_error"] < 1e-3
    assert s["mass_balance_rel_error"] < 1e-12
