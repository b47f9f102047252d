"""Dahl, GMS, Coulomb/Stribeck laws and the hybrid stick logic."""

from __future__ import annotations

import numpy as np
import pytest
from pydantic import TypeAdapter

from sealsim.friction import GMS, ContactInputs, CoulombViscous, Dahl, LuGre, Stribeck
from sealsim.friction.bench import profile_type, simulate_displacement, simulate_mass
from sealsim.friction.hybrid import resolve_stick

X = TypeAdapter(profile_type("length"))
V = TypeAdapter(profile_type("velocity"))
F = TypeAdapter(profile_type("force"))


def _cycle(law, w, cycles=3, amplitude=2e-5):
    crank = X.validate_python({"kind": "harmonic", "amplitude": amplitude,
                               "angular_frequency": w})
    per = 2 * np.pi / w
    res = simulate_displacement(law, crank, cycles * per, per / 3000)
    last = res.time >= res.time[-1] - per - 1e-12
    return res.position[last], res.force[last]


def test_dahl_loop_is_rate_independent():
    """The F–x loop at ω = 0.1 and 100 rad/s is the same curve (Dahl: dF/dx depends on x only).

    Both are sampled at the same phases (3000 per period), so the samples are at the same x;
    the forces agree to 1e-9 N (rounding; the exact step makes the discrete map rate free too).
    """
    law = Dahl(sigma0=1e5, coulomb_force=1.0, exponent=1.5)
    x1, f1 = _cycle(law, 0.1)
    x2, f2 = _cycle(law, 100.0)
    np.testing.assert_allclose(x1, x2, atol=1e-15)
    np.testing.assert_allclose(f1, f2, atol=1e-9)
    # and it is a real hysteresis loop, not a line: area ≫ 0
    assert abs(np.trapezoid(f1, x1)) > 1e-6


def test_lugre_loop_is_rate_dependent_control():
    """Control for the test above: LuGre with σ1 > 0 and a Stribeck drop is not rate free."""
    law = LuGre(sigma0=1e5, sigma1=300.0, sigma2=200.0, coulomb_force=1.0, static_force=1.5,
                stribeck_velocity=1e-3)
    _, f1 = _cycle(law, 0.1)
    _, f2 = _cycle(law, 100.0)
    assert np.max(np.abs(f1 - f2)) > 0.01


def test_dahl_alpha1_is_lugre_without_stribeck_and_damping():
    """Dahl (α = 1) ≡ LuGre with F_S = F_C, σ1 = σ2 = 0 (1995 §2): same forces to 1e-12."""
    dahl = Dahl(sigma0=1e5, coulomb_force=1.0)
    lugre = LuGre(sigma0=1e5, sigma1=0.0, sigma2=0.0, coulomb_force=1.0, static_force=1.0,
                  stribeck_velocity=1e-3)
    _, f1 = _cycle(dahl, 3.0)
    _, f2 = _cycle(lugre, 3.0)
    np.testing.assert_allclose(f1, f2, rtol=1e-12, atol=1e-14)


def test_gms_virgin_curve_is_piecewise_linear_maxwell_slip():
    """Quasi-static GMS loading from rest: F(x) = Σ_i min(k_i x, α_i F_S) + σ2·v.

    With v → 0 the Stribeck level is F_S; elements break away one by one.  Slow ramp
    x = 1e-6 m/s · t, tolerance 1e-6 relative (s(v) at 1e-6 m/s differs from F_S by 5e-7).
    """
    law = GMS.from_parameter_set("canudas1995")
    ramp = X.validate_python({"kind": "piecewise", "times": [0.0, 20.0], "values": [0.0, 2e-5]})
    res = simulate_displacement(law, ramp, 20.0, 1e-3)
    k = law.k[:, 0]
    alpha = law.alpha[:, 0]
    x = res.position
    expected = np.sum(np.minimum(k[:, None] * x[None, :], alpha[:, None] * 1.5), axis=0)
    expected += law.params.sigma2 * res.velocity
    np.testing.assert_allclose(res.force, expected, rtol=1e-6, atol=1e-9)


def test_gms_return_point_memory():
    """Non-local memory: after an inner loop the outer curve continues where it left off."""
    law = GMS.from_parameter_set("canudas1995")
    path = X.validate_python({"kind": "piecewise", "times": [0, 10, 14, 18, 28],
                              "values": [0, 1.0e-5, 0.4e-5, 1.0e-5, 2.0e-5]})
    res = simulate_displacement(law, path, 28.0, 2e-3)
    at = lambda t: res.force[np.argmin(np.abs(res.time - t))]  # noqa: E731
    assert at(18.0) == pytest.approx(at(10.0), rel=1e-5)
    # and the inner loop was a real excursion
    assert at(14.0) < at(10.0) - 0.1


def test_pressure_scaling_of_stribeck_and_coulomb():
    """Seed 001 Eq. 3: F_C = F_pr + f(p_A + p_B); F_S/F_C constant (Simscape convention)."""
    st = Stribeck(coulomb_force=15.0, static_force=25.0, stribeck_velocity=0.02, exponent=1.0,
                  viscous_coefficient=8.0, pressure_coefficient=1.5e-5)
    inputs = ContactInputs(pressure_a=6e5, pressure_b=2e5)
    fc = 15.0 + 1.5e-5 * 8e5
    assert st.breakaway_force(st.initial_state(1), inputs)[0] == pytest.approx(fc * 25 / 15)
    assert st.steady_force([10.0], inputs)[0] == pytest.approx(fc + 80.0 + (
        fc * 25 / 15 - fc) * np.exp(-500.0), rel=1e-12)
    cv = CoulombViscous(coulomb_force=15.0, pressure_coefficient=1.5e-5)
    assert cv.steady_force([-0.1], inputs)[0] == pytest.approx(-fc)


def test_resolve_stick():
    stick, force = resolve_stick([0.5, 1.5, -3.0], [1.0, 1.5, 2.0])
    assert stick.tolist() == [True, True, False]
    assert force.tolist() == [0.5, 1.5, -2.0]


@pytest.mark.parametrize("law", [
    Stribeck(coulomb_force=1.0, static_force=1.5, stribeck_velocity=1e-3, exponent=2.0,
             viscous_coefficient=0.4),
    CoulombViscous(coulomb_force=1.5),
], ids=["stribeck", "coulomb"])
def test_true_sticking_no_creep_and_breakaway(law):
    """A force of 0.99·F_brk held for 1000 s moves nothing (exactly); 1.01·F_brk breaks away."""
    hold = F.validate_python({"kind": "piecewise", "times": [0, 1, 1001],
                              "values": [0.0, 1.485, 1.485]})
    res = simulate_mass(law, 1.0, 1001.0, 0.5, applied_force=hold)
    assert np.all(res.position == 0.0) and np.all(res.velocity == 0.0)
    assert np.all(res.stuck)
    np.testing.assert_allclose(res.force, res.applied_force, rtol=0, atol=0)
    push = F.validate_python({"kind": "piecewise", "times": [0, 1, 3],
                              "values": [0.0, 1.515, 1.515]})
    res = simulate_mass(law, 1.0, 3.0, 1e-3, applied_force=push)
    assert res.position[-1] > 0 and not res.stuck[-1]
    # break-away instant: the applied force first exceeds F_brk = 1.5 N
    t_break = res.time[np.argmax(~res.stuck)]
    assert t_break == pytest.approx(1.5 / 1.515, abs=2e-3)        # one step of 1 ms
