"""The Θ rate-and-state law (Heipl & Murrenhoff Eq. 4/5 as reconstructed in
sealsim.friction.theta)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pydantic import TypeAdapter
from scipy.integrate import solve_ivp

from test_friction_helpers import THETA_INPUTS
from sealsim.friction import ContactInputs, Theta
from sealsim.friction.bench import (
    breakaway_forces,
    loop_areas,
    profile_type,
    simulate_displacement,
    simulate_mass,
    simulate_velocity,
)

V = TypeAdapter(profile_type("velocity"))
X = TypeAdapter(profile_type("length"))
LAW = Theta.from_parameter_set("pneumatic_demo")       # τ = 2 s, α = 0.1 m, f_a .5, f_b .1
P = LAW.params


def test_steady_theta_matches_closed_form_and_ode():
    """Θ_ss = |v|/(|v| + v*), v* = (α/τ)(F_N/F_ref)^n; also the rest point of the ODE
    integrated independently with solve_ivp (rtol 1e-10) from Θ = 0 for 40 τ."""
    for fn in (50.0, 100.0, 300.0):
        for v in (-0.4, 0.02, 0.05, 1.3):
            vstar = P.alpha / P.tau * (fn / P.reference_normal_force) ** P.load_exponent
            closed = abs(v) / (abs(v) + vstar)

            def rhs(t, th, v=v, fn=fn):
                rate = abs(v) / P.alpha * (P.reference_normal_force / fn)
                return -th / P.tau + rate * (1 - th)

            sol = solve_ivp(rhs, (0, 40 * P.tau), [0.0], method="Radau", rtol=1e-10,
                            atol=1e-14)
            inputs = ContactInputs(normal_force=fn, contact_width=1e-3)
            assert LAW.steady_state(np.array([v]), inputs)[0, 0] == pytest.approx(closed,
                                                                                 rel=1e-12)
            assert sol.y[0, -1] == pytest.approx(closed, rel=1e-8)   # ODE tolerance


def _dwell_run(dwell):
    law = LAW
    drive = V.validate_python({"kind": "piecewise",
                               "times": [0, 2, 2.001, 2.001 + dwell, 2.002 + dwell],
                               "values": [0.02, 0.02, 0.0, 0.0, 0.02]})
    return simulate_mass(law, 1.0, 4.0 + dwell, 1e-3, stiffness=2000.0, drive_velocity=drive,
                         inputs=THETA_INPUTS)


def test_breakaway_grows_with_dwell_and_saturates():
    """Break-away after a dwell (seed 001: dwell-time dependent break-away force).

    Reference: closed form F_brk = F_N[f_a − (f_a − f_b)·Θ_stop·e^{−t_rest/τ}], with Θ_stop
    and the rest time read from the run.  Tolerance 0.1 N: the spring force rises 2000 N/m ·
    0.02 m/s · 1 ms = 0.04 N per step, so the detected break-away is within one step of it.
    """
    forces = []
    for dwell in (0.5, 2.0, 5.0, 12.0):
        res = _dwell_run(dwell)
        stuck = res.stuck
        # last sticking phase before the final slip
        start_motion = np.where(~stuck[:-1] & stuck[1:])[0]
        rest_start = start_motion[-1] + 1
        rest_end = rest_start + np.argmax(~stuck[rest_start:])     # first slipping sample
        # no creep: the position does not change while stuck (exactly)
        assert np.ptp(res.position[rest_start:rest_end]) == 0.0
        theta_stop = res.states[rest_start, 0]
        t_rest = res.time[rest_end - 1] - res.time[rest_start]
        closed = 100.0 * (P.f_a - (P.f_a - P.f_b) * theta_stop * np.exp(-t_rest / P.tau))
        brk = abs(res.force[rest_end - 1])                   # static friction just before slip
        assert brk == pytest.approx(closed, abs=0.1)
        forces.append(breakaway_forces(res)[1][-1])
    assert forces[0] < forces[1] < forces[2] <= forces[3] + 0.05
    # saturates at the dry level F_N·f_a = 50 N (within the 0.1 N resolution)
    assert forces[3] == pytest.approx(100.0 * P.f_a, abs=0.1)
    assert forces[3] - forces[2] < 0.2 * (forces[1] - forces[0])


def _loop_area(law, w, inputs, what):
    prof = V.validate_python({"kind": "harmonic", "mean": 0.15, "amplitude": 0.1,
                              "angular_frequency": w})
    per = 2 * np.pi / w
    z0 = law.steady_state(np.array([0.25]), inputs)
    res = simulate_velocity(law, prof, 4 * per, per / 2000, inputs, z0)
    res.period = per
    if what == "force":
        return loop_areas(res)["force_velocity_N_m_s"]
    sel = res.time >= res.time[-1] - per - 1e-12
    return abs(np.trapezoid(res.states[sel, 0], res.velocity[sel]))


def test_fv_hysteresis_widens_with_frequency():
    """v = 0.15 + 0.1 cos ωt m/s: the F–v and Θ–v loop areas grow with ω while ω·τ_eff < 1
    (τ_eff = 1/(1/τ + |v|/α) ≈ 0.5–0.8 s here); ω → 0 gives the steady curve (area → 0)."""
    ws = (0.03, 0.1, 0.3, 0.8)
    f_areas = [_loop_area(LAW, w, THETA_INPUTS, "force") for w in ws]
    th_areas = [_loop_area(LAW, w, THETA_INPUTS, "theta") for w in ws]
    assert all(a < b for a, b in zip(f_areas, f_areas[1:]))
    assert all(a < b for a, b in zip(th_areas, th_areas[1:]))
    assert f_areas[0] < 0.1 * f_areas[-1]


def test_higher_load_gives_weaker_transition():
    """Seed 001 Fig. 6: with a higher F_N the state moves less towards hydrodynamic friction.

    Crank x = 0.1 m·sin(t): over the last cycle the high-load Θ stays below the low-load Θ at
    every sample and its largest value is lower; the friction coefficient F/F_N falls less from
    its dry value f_a.
    """
    crank = X.validate_python({"kind": "harmonic", "amplitude": 0.1, "angular_frequency": 1.0,
                               "phase": -np.pi / 2})
    runs = {}
    for fn in (60.0, 150.0):
        inputs = ContactInputs(normal_force=fn, contact_width=1e-3)
        res = simulate_displacement(LAW, crank, 4 * 2 * np.pi, 1e-3, inputs)
        last = res.time >= res.time[-1] - 2 * np.pi
        runs[fn] = (res.states[last, 0], np.abs(res.force[last]) / fn)
    low, high = runs[60.0], runs[150.0]
    assert np.all(high[0] < low[0])
    assert high[0].max() < low[0].max()
    # lowest friction coefficient of the cycle (most hydrodynamic) stays nearer f_a at high load
    assert high[1].min() > low[1].min()


@settings(max_examples=60, deadline=None)
@given(
    theta0=st.floats(0.0, 1.0),
    steps=st.lists(st.tuples(st.floats(-50.0, 50.0), st.floats(0.0, 1e3),
                             st.floats(1e-6, 1e6)), min_size=1, max_size=40),
    bristle=st.booleans(),
)
def test_theta_stays_in_unit_interval(theta0, steps, bristle):
    """Θ ∈ [0, 1] for any sequence of velocities, step lengths and loads (exact step)."""
    law = Theta.from_parameter_set("pneumatic_demo", **(
        {"bristle_stiffness": 1e6} if bristle else {}))
    z = law.initial_state(1)
    z[0] = theta0
    for v, dt, fn in steps:
        inputs = ContactInputs(normal_force=fn, contact_width=1e-3)
        z = law.step(z, np.array([v]), dt, inputs)
        assert 0.0 <= z[0, 0] <= 1.0
        assert np.all(np.isfinite(z))
    v = np.array([s[0] for s in steps])
    dt = np.array([s[1] for s in steps])
    traj = law.trajectory(law.initial_state(1) + np.array([[theta0]] + (
        [[0.0]] if bristle else [])), v, dt, THETA_INPUTS)
    assert np.all((traj[:, 0] >= 0.0) & (traj[:, 0] <= 1.0))


def test_dwell_relaxation_is_exponential():
    """At rest Θ(t) = Θ0·e^{−t/τ} (state term only), also across many short steps."""
    z = np.array([[0.8]])
    for _ in range(100):
        z = LAW.step(z, np.array([0.0]), 0.03, THETA_INPUTS)
    assert z[0, 0] == pytest.approx(0.8 * np.exp(-3.0 / P.tau), rel=1e-12)


def test_a_break_away_below_the_sliding_level_and_a_pressure_below_vacuum_are_refused():
    # f_a is the dry coefficient (Θ = 0, the break-away after a long dwell), f_b the full-film
    # one (Θ = 1); f_b > f_a and a gauge p_A below -1 atm ran without a word
    from sealsim.errors import InputError
    from sealsim.friction.case import load_friction_cases

    case = {"friction": {"law": "theta", "parameter_set": "pneumatic_demo", "f_a": 0.2,
                         "f_b": 0.4},
            "inputs": {"normal_force": "100 N", "contact_width": "1 mm",
                       "pressure_a": "-3 bar", "pressure_b": "-1 atm"},
            "bench": {"mode": "velocity", "duration": "1 s", "time_step": "10 ms",
                      "velocity": {"kind": "constant", "level": "1 mm/s"}}}
    with pytest.raises(InputError) as info:
        load_friction_cases(case, "case")
    message = " ".join(str(info.value).split())
    assert ("friction: f_b = 0.4 is larger than f_a = 0.2: f_b (the full-film friction "
            "coefficient, Theta = 1) must be <= f_a") in message
    assert ("inputs.pressure_a: a gauge pressure below vacuum is not possible: it must be >= "
            "-1.01325 bar (-1 atm, vacuum) (got '-3 bar')") in message
    assert "pressure_b" not in message                      # exactly vacuum is allowed
    # equal coefficients (no Stribeck drop) are allowed
    equal = {**case, "friction": {**case["friction"], "f_b": 0.2},
             "inputs": {**case["inputs"], "pressure_a": "-0.5 bar"}}
    assert load_friction_cases(equal, "case")["base"].friction.f_b == 0.2
