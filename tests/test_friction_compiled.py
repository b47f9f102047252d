"""The compiled friction laws of sealsim.friction.compiled and the benches that use them:
the compiled stick/slip stepper against the vectorised one of sealsim.friction.hybrid (the
stepper of before issue 27, still run for law objects without a compiled form; bit for bit), the
compiled driven-mass ODE against scipy's Radau, the compiled profiles against the profile
objects, and law_rates/law_step against the law objects."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from pydantic import TypeAdapter

from sealsim.friction import ContactInputs, LuGre, Theta, kernels
from sealsim.friction.bench import profile_type, simulate_mass, summarize
from sealsim.friction.compiled import (
    LAW_CODES,
    NO_TABLE,
    TH_NU_REF,
    _theta_gamma,
    law_parameters,
    law_rates,
    law_step,
)
from sealsim.friction.hybrid import compiled_law
from sealsim.friction.profiles import profile_integral, profile_value
from sealsim.properties.oils import walther_viscosity

V = TypeAdapter(profile_type("velocity"))
DWELL = V.validate_python({"kind": "piecewise", "times": [0, 2, 2.001, 3, 3.001],
                           "values": [0.02, 0.02, 0.0, 0.0, 0.02]})
INPUTS = ContactInputs(normal_force=100.0, contact_width=1e-3)


class NumpyTheta(Theta):
    """The Θ law as a law object of its own class: the bench runs it through the vectorised
    stepper of sealsim.friction.hybrid (the path of any FrictionLaw without a compiled form)."""


def test_compiled_stepper_is_the_numpy_stepper():
    # the same algorithm and the same kernels: bit-identical forces, sticking included
    law = Theta.from_parameter_set("pneumatic_demo")
    res = simulate_mass(law, 1.0, 4.0, 1e-3, stiffness=2000.0, drive_velocity=DWELL,
                        inputs=INPUTS)
    assert res.stuck.any() and not res.stuck.all()
    assert compiled_law(law) and not compiled_law(NumpyTheta(law.params))
    ref = simulate_mass(NumpyTheta(law.params), 1.0, 4.0, 1e-3, stiffness=2000.0,
                        drive_velocity=DWELL, inputs=INPUTS)
    np.testing.assert_array_equal(res.force, ref.force)
    np.testing.assert_array_equal(res.position, ref.position)


def test_compiled_lugre_stick_slip_matches_radau():
    # examples/friction/lugre_stick_slip.toml (25 s, four slips): the compiled BDF and scipy's
    # Radau at the same rtol (1e-7) give the same stick-slip cycle -- period and largest force to
    # 1e-5 relative (each integrator is accurate to about its tolerance; the cycle is a
    # limit cycle, so small differences do not grow)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        law = LuGre.from_parameter_set("canudas1995")
    drive = V.validate_python({"kind": "constant", "level": 0.1})
    runs = [simulate_mass(law, 1.0, 25.0, 1e-3, stiffness=2.0, drive_velocity=drive,
                          integrator=i) for i in ("compiled", "radau")]
    new, ref = (summarize(r) for r in runs)
    assert new["stick_slip_period_s"] == pytest.approx(ref["stick_slip_period_s"], rel=1e-5)
    assert new["max_friction_force_N"] == pytest.approx(ref["max_friction_force_N"], rel=1e-5)
    assert new["friction_work_J"] == pytest.approx(ref["friction_work_J"], rel=1e-5)


@pytest.mark.parametrize("spec", [
    {"kind": "constant", "level": 0.1},
    {"kind": "harmonic", "mean": 0.1, "amplitude": 0.5, "angular_frequency": 3.0,
     "phase": 0.3},
    {"kind": "piecewise", "times": [0, 2, 2.001, 7], "values": [0.02, 0.02, 0.0, -0.01]}])
def test_compiled_profiles_are_the_profile_objects(spec):
    profile = V.validate_python(spec)
    kind, table = profile.table()
    for t in np.linspace(0.0, 9.0, 37):
        assert profile_value(kind, table, t) == pytest.approx(float(profile.value(t)),
                                                              rel=1e-14, abs=1e-15)
        assert profile_integral(kind, table, t) == pytest.approx(float(profile.integral(t)),
                                                                 rel=1e-14, abs=1e-15)


@pytest.mark.parametrize("bristles", [False, True])
def test_law_rates_and_step_are_the_law_objects(bristles):
    extra = {"bristle_stiffness": "2e5 N/m", "bristle_damping": "300 N*s/m"} if bristles else {}
    law = Theta.from_parameter_set("pneumatic_demo", **extra)
    par = law_parameters(law)
    rng = np.random.default_rng(3)
    contact = np.array([100.0, 1e-3, 0.0, 0.0, par[9], 0.0, 1.0])   # F_N, b, p_A, p_B, T, ...
    for _ in range(20):
        z = np.array([rng.uniform(0, 1), rng.uniform(-1e-5, 1e-5)][:law.n_states])
        v = rng.normal(0, 0.1)
        dy = np.zeros((law.n_states, 1))
        force, brk = law_rates(LAW_CODES["theta"], par, z.reshape(-1, 1), 0, v, 100.0, 1e-3,
                               0.0, 0.0, par[9], dy, 0, *NO_TABLE, 0.0, 1.0)  # T_ref: γ_ref
        assert force == pytest.approx(law.force(z[:, None], [v], INPUTS)[0], rel=1e-14)
        np.testing.assert_allclose(dy[:, 0], law.derivatives(z[:, None], [v], INPUTS)[:, 0],
                                   rtol=1e-14)
        if not bristles:
            assert brk == pytest.approx(law.breakaway_force(z[:, None], INPUTS)[0], rel=1e-14)
        z1 = np.empty(law.n_states)
        law_step(LAW_CODES["theta"], par, z, v, 1e-3, contact, *NO_TABLE, z1)
        np.testing.assert_allclose(z1, law.step(z[:, None], [v], 1e-3, INPUTS)[:, 0],
                                   rtol=1e-14)


@pytest.fixture(scope="module")
def contact_seal():
    """The Θ law on its seal's contact table (examples/friction/theta_contact_stribeck.toml:
    2 mm O-ring on a 12 mm rod, 3 bar, 20 °C) and the bench inputs of that seal."""
    from pathlib import Path

    from sealsim.cases import load_toml
    from sealsim.friction.case import build_law, load_friction_cases
    from sealsim.pneumatic.bench import bench_inputs

    path = Path(__file__).parents[1] / "examples" / "friction" / "theta_contact_stribeck.toml"
    case = next(iter(load_friction_cases(load_toml(path)).values()))
    law = build_law(case)
    inputs, _ = bench_inputs(case, law, path.parent)
    return law, inputs


@pytest.mark.parametrize("bristles", [False, True])
def test_contact_law_rates_and_step_are_the_law_objects(contact_seal, bristles):
    # steady = "contact": the compiled law reads the same table kernel (contact_table_point)
    # as the law object; only the order of a few products may differ: 1e-12 relative
    from sealsim.friction.hybrid import contact_values

    base, inputs = contact_seal
    law = Theta(base.params.model_copy(update={"bristle_stiffness": 2e5,
                                               "bristle_damping": 300.0} if bristles else {}))
    par, contact, frow, fdata = contact_values(law, inputs)
    assert par[12] == 1.0 and par[15] == pytest.approx(np.pi * 0.012)
    rng = np.random.default_rng(5)
    for v in np.concatenate([[0.0, 1e-8, -1e-8], rng.normal(0, 0.3, 20)]):
        # Θ, the bristles' z, the film's speed φ (last): lagging behind |v|, ahead, none
        z = np.array([rng.uniform(0, 1), rng.uniform(-1e-5, 1e-5)][:law.n_states - 1]
                     + [rng.choice([0.0, abs(v), rng.uniform(0.0, 0.5)])])
        dy = np.zeros((law.n_states, 1))
        force, brk = law_rates(LAW_CODES["theta"], par, z.reshape(-1, 1), 0, v, *contact[:5],
                               dy, 0, frow, fdata, contact[5], contact[6])
        assert force == pytest.approx(law.force(z[:, None], [v], inputs)[0], rel=1e-12,
                                      abs=1e-12)
        np.testing.assert_allclose(dy[:, 0], law.derivatives(z[:, None], [v], inputs)[:, 0],
                                   rtol=1e-12, atol=1e-15)
        if not bristles and v == 0.0:       # the break-away force is the level at rest
            assert brk == pytest.approx(law.breakaway_force(z[:, None], inputs)[0], rel=1e-12)
        z1 = np.empty(law.n_states)
        law_step(LAW_CODES["theta"], par, z, v, 1e-3, contact, frow, fdata, z1)
        np.testing.assert_allclose(z1, law.step(z[:, None], [v], 1e-3, inputs)[:, 0],
                                   rtol=1e-12, atol=1e-18)


def test_contact_steady_is_four_table_lookups_to_the_bit(contact_seal):
    # the compiled contact_steady shares one cell search between its four sums; each is
    # the kernel's own lookup (contact_table_point, what the law object's contact_steady
    # calls three times) bit for bit: inside and outside the axes (clamped), below the
    # slowest speed, at rest, both orientations
    from sealsim.friction.compiled import contact_steady
    from sealsim.friction.contact_table import contact_table_point
    from sealsim.friction.hybrid import contact_values

    law, inputs = contact_seal
    par, _, frow, fdata = contact_values(law, inputs)
    table = inputs.contact_table
    slow = table.speed[0]
    circumference, mu = par[15], par[13]
    rng = np.random.default_rng(11)
    (t_lo, t_hi), (p_lo, p_hi) = table.ranges["temperature"], table.ranges["pressure"]
    for k in range(400):
        temp = rng.uniform(t_lo - 20.0, t_hi + 20.0)
        dp = rng.uniform(p_lo - 1e5, p_hi + 1e5) if k % 5 else table.pressure[k % 3]
        v = 0.0 if k % 17 == 0 else rng.choice([-1.0, 1.0]) * 10.0 ** rng.uniform(-9.0, 1.5)
        orient = rng.choice([-1.0, 1.0])
        # the film's speed: steady (|v|), none (the slowest node), or any other
        film = [abs(v), 0.0, 10.0 ** rng.uniform(-9.0, 1.5)][k % 3]
        load, visc, _ = contact_table_point(frow, fdata, temp, dp, orient * v)
        if v != 0.0:         # the asperities carry the load of the film's speed
            load = contact_table_point(frow, fdata, temp, dp,
                                       np.sign(orient * v) * max(film, slow))[0]
        if v == 0.0:         # at rest: the larger load the film leaves of both directions
            load = max(contact_table_point(frow, fdata, temp, dp, s * max(film, slow))[0]
                       for s in (1.0, -1.0))
        # the level, its boundary part (the dwell drop's base), its viscous part, the film's
        # decay rate at φ (the table's own lookup, table.film_decay)
        decay = table.film_decay(max(film, slow), dp, temp).item()
        want = (circumference * (mu * load + visc), circumference * mu * load,
                circumference * visc, decay)
        assert contact_steady(par, frow, fdata, temp, dp, orient, v, film) == want


def test_compiled_stepper_carries_the_contact_table(contact_seal):
    # the stick/slip stepper on the seal's own contact: the compiled stepper and the
    # vectorised one of sealsim.friction.hybrid (law object, table.evaluate) agree; the
    # dwell sticks and breaks away
    law, inputs = contact_seal
    res = simulate_mass(law, 1.0, 4.0, 1e-3, stiffness=2000.0, drive_velocity=DWELL,
                        inputs=inputs)
    ref = simulate_mass(NumpyTheta(law.params), 1.0, 4.0, 1e-3, stiffness=2000.0,
                        drive_velocity=DWELL, inputs=inputs)
    assert res.stuck.any() and not res.stuck.all()
    np.testing.assert_array_equal(res.stuck, ref.stuck)
    np.testing.assert_allclose(res.force, ref.force, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(res.position, ref.position, rtol=1e-9, atol=1e-12)


def test_theta_viscosity_at_the_reference_temperature_is_a_parameter():
    # γ(T) = γ·ν(T)/ν(T_ref) is evaluated at every right-hand side of a heated seal: ν(T_ref)
    # (two powers and a logarithm, half of the ASTM D341 work) is a constant of the law, in its
    # parameter vector (before: evaluated again at every call, 100 ns of a 0.8 µs cylinder
    # right-hand side with two Θ seals).  The same kernel computes it: γ(T) is the number of
    # the ratio kernel bit for bit, and ν(T_ref) the base oil's viscosity of the oil module.
    law = Theta.from_parameter_set("pneumatic_demo")
    par = law_parameters(law)
    a, b = law.walther
    assert b > 0.0
    assert par[TH_NU_REF] == pytest.approx(
        float(walther_viscosity(law.params.reference_temperature, a, b)) * 1e6, rel=1e-12)
    for t in (253.15, par[9], 330.0, 393.15):
        assert _theta_gamma(par, t) == par[4] * kernels.walther_viscosity_ratio(
            t, par[9], par[10], par[11])
    assert _theta_gamma(par, 330.0) == pytest.approx(
        float(law.gamma(ContactInputs(temperature=330.0))), rel=1e-12)
    # without base-oil data γ is constant and the slot is 0
    plain = Theta.from_parameter_set("pneumatic_demo", base_oil_nu40=None, base_oil_nu100=None)
    par = law_parameters(plain)
    assert par[11] == 0.0 and par[TH_NU_REF] == 0.0
    assert _theta_gamma(par, 330.0) == plain.params.gamma
