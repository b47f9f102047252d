"""LuGre benchmarks of Canudas de Wit et al. (1995) and the passivity check (Åström 2008)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from pydantic import TypeAdapter
from scipy.integrate import solve_ivp

from test_friction_helpers import classic_lugre, passive_lugre
from sealsim.friction import LuGre, PassivityWarning
from sealsim.friction.bench import (
    loop_areas,
    profile_type,
    simulate_mass,
    simulate_velocity,
    stick_slip_period,
)
from sealsim.friction.lugre import lugre_passivity_margin

V = TypeAdapter(profile_type("velocity"))
F = TypeAdapter(profile_type("force"))
S0, S1, S2, FC, FS, VS = 1e5, np.sqrt(1e5), 0.4, 1.0, 1.5, 1e-3     # 1995 Table I


def test_classic_set_is_not_passive_and_warns():
    """Table I violates Eq. 7 (needs σ2 > 158.1 N·s/m); a passive set does not warn."""
    assert lugre_passivity_margin(S1, S2, FC, FS) == pytest.approx(0.4 - S1 * 0.5, rel=1e-12)
    with pytest.warns(PassivityWarning, match=r"158.1"):
        law = LuGre.from_parameter_set("canudas1995")
    assert not law.is_passive()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert passive_lugre().is_passive()


def test_presliding_bristle_bounded_and_no_gross_sliding():
    """Force ramped to 0.95·F_S and back (1995 Fig. 5).

    * |z| <= F_S/σ0 all the time (1995 Property 1: bristles never deflect beyond F_S/σ0).
    * The body only pre-slides: the displacement follows the quasi-static LuGre pre-sliding
      curve x(F) = −(F_S/σ0)·ln(1 − F/F_S) (from dz/dx = 1 − σ0 z/F_S at v → 0), within 3 %
      at F = 0.95 F_S for a slow ramp (v ≈ 3e-6 m/s ≪ v_s keeps g(v) within 1e-5 of F_S).
      Note: this is 3·F_S/σ0 = 45 µm, i.e. LuGre's pre-sliding *displacement* is not bounded
      by F_S/σ0 near F_S (its compliance grows without bound as F → F_S), only z is.
    """
    law = classic_lugre()
    ramp = F.validate_python({"kind": "piecewise", "times": [0, 100, 300, 400],
                              "values": [0.0, 0.95 * FS, -0.95 * FS, 0.0]})
    res = simulate_mass(law, 1.0, 400.0, 0.05, applied_force=ramp)
    z = res.states[:, 0]
    assert np.max(np.abs(z)) <= FS / S0 * (1 + 1e-9)          # rounding margin only
    i_peak = np.argmin(np.abs(res.time - 100.0))
    x_qs = -(FS / S0) * np.log(1 - 0.95)
    assert res.position[i_peak] == pytest.approx(x_qs, rel=0.03)
    # no gross sliding: after the cycle the body is within a few F_S/σ0 of the start
    assert np.max(np.abs(res.position)) < 5 * FS / S0


def test_presliding_example_ramp_keeps_bristles_bounded():
    """The example's faster ramp (4 s to 1.425 N): |z| <= F_S/σ0 still (Property 1)."""
    law = classic_lugre()
    ramp = F.validate_python({"kind": "piecewise", "times": [0, 4, 12, 20, 24],
                              "values": [0, 1.425, -1.425, 1.425, 0]})
    res = simulate_mass(law, 1.0, 24.0, 2e-3, applied_force=ramp)
    assert np.max(np.abs(res.states[:, 0])) <= FS / S0 * (1 + 1e-9)
    assert np.max(np.abs(res.velocity)) < 1e-3            # never reaches gross sliding (v_s)


def test_velocity_hysteresis_widens_with_omega():
    """1995 Fig. 3: v = 1e-3(cos ωt + 1.5); the F–v loop area grows with ω = 1, 10, 25 rad/s.

    The quasi-static reference is the steady curve (zero area); at ω = 1 the loop is already
    thin, so its area must also be small against the ω = 25 loop (< 30 %).
    """
    law = classic_lugre()
    areas = []
    for w in (1.0, 10.0, 25.0):
        prof = V.validate_python({"kind": "harmonic", "mean": 1.5e-3, "amplitude": 1e-3,
                                  "angular_frequency": w})
        per = 2 * np.pi / w
        z0 = law.steady_state(np.array([2.5e-3]))
        res = simulate_velocity(law, prof, 3 * per, per / 4000, initial_state=z0)
        res.period = per
        areas.append(loop_areas(res)["force_velocity_N_m_s"])
    assert areas[0] < areas[1] < areas[2]
    assert areas[0] < 0.3 * areas[2]


def _reference_stick_slip(duration):
    """Independent integration of the 1995 stick-slip benchmark (own RHS, Radau rtol 1e-10)."""
    k, vd, m = 2.0, 0.1, 1.0

    def rhs(t, y):
        x, v, z = y
        g = FC + (FS - FC) * np.exp(-(v / VS) ** 2)
        zd = v - S0 * abs(v) * z / g
        return [v, (k * (vd * t - x) - (S0 * z + S1 * zd + S2 * v)) / m, zd]

    sol = solve_ivp(rhs, (0, duration), [0.0, 0.0, 0.0], method="Radau", rtol=1e-10,
                    atol=[1e-12, 1e-12, 1e-15], dense_output=True, max_step=1e-2)
    t = np.linspace(0, duration, 200001)
    v = sol.sol(t)[1]
    thr = 0.5 * v.max()
    i = np.where((v[:-1] < thr) & (v[1:] >= thr))[0]
    cross = t[i] + (thr - v[i]) / (v[i + 1] - v[i]) * (t[i + 1] - t[i])
    return np.mean(np.diff(cross)[1:]), v


def test_stick_slip_period_matches_independent_integration():
    """k = 2 N/m pulled at 0.1 m/s, m = 1 kg: stick-slip appears, period within 2 %."""
    law = classic_lugre()
    res = simulate_mass(law, 1.0, 25.0, 1e-3, stiffness=2.0,
                        drive_velocity=V.validate_python({"kind": "constant", "level": 0.1}))
    period = stick_slip_period(res)
    ref_period, ref_v = _reference_stick_slip(25.0)
    assert period is not None
    # stick-slip, not steady sliding: the body rests (|v| < 1 mm/s) between slips that reach
    # several times the drive speed
    assert res.velocity.max() > 3 * 0.1
    assert np.mean(np.abs(res.velocity) < 1e-3) > 0.3
    assert period == pytest.approx(ref_period, rel=0.02)       # the tolerance


def test_no_stick_slip_with_strong_viscous_damping():
    """Control: with σ2 = 10 N·s/m the body keeps sliding after break-away (never sticks).

    Without the test above could pass for a bench that sticks for any reason.
    """
    with pytest.warns(PassivityWarning):
        law = LuGre(sigma0=S0, sigma1=S1, sigma2=10.0, coulomb_force=FC, static_force=FS,
                    stribeck_velocity=VS)
    res = simulate_mass(law, 1.0, 25.0, 1e-3, stiffness=2.0,
                        drive_velocity=V.validate_python({"kind": "constant", "level": 0.1}))
    late = res.time > 15.0
    assert np.min(res.velocity[late]) > 0.5 * 0.1          # slides at about the drive speed
    assert stick_slip_period(res) is None
