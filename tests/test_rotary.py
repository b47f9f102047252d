"""Rotary lip seal model (seed 000): claims of the seed, references, invariants, interface."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
import scipy.sparse.linalg as spla
from hypothesis import given, settings
from hypothesis import strategies as st
from rotary_reference import reference_steady_state
from scipy.special import i0e, i1e
from typer.testing import CliRunner

import sealsim
from sealsim.cases import validate_case
from sealsim.cli import app
from sealsim.errors import InputError, ModelError, SealsimWarning
from sealsim.properties.elastomers import get_elastomer
from sealsim.properties.oils import get_oil
from sealsim.rotary.case import SETUPS, RotaryCase
from sealsim.rotary.friction import LipSealFriction
from sealsim.rotary.lip import (
    STEEL_EXPANSION,
    default_radial_force,
    interference_ratio,
    lip_force,
    wave_film_factor,
)
from sealsim.rotary.simulation import (
    RotaryModel,
    bearing_geometry,
    friction_map,
    housing_defaults,
    lip_seal_friction,
    simulate,
    steady_state,
)
from sealsim.rotary.simulation import load_rotary_case
from sealsim.thermal.conduction import AxisymmetricConduction, Solid, ThermalNetwork
from sealsim.tribology.film import FilmRangeWarning
from sealsim.tribology.rolling_bearing import palmgren_viscous_moment

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "rotary"
RPM = math.pi / 30

# films below 0.25 µm (low speeds) are announced by a FilmRangeWarning; tested on its own below
pytestmark = pytest.mark.filterwarnings("ignore::sealsim.tribology.film.FilmRangeWarning")


def _case(**sections) -> RotaryCase:
    data = {"seal": {"shaft_diameter": "80 mm"},
            "duty": {"steps": [{"speed": "1000 rpm", "duration": "5 min"}]}}
    for key, value in sections.items():  # merge into the seal, replace other sections
        data[key] = {**data["seal"], **value} if key == "seal" else value
    return validate_case(RotaryCase, data)


@pytest.fixture(scope="module")
def speed_cycle():
    return {name: simulate(case) for name, case in
            load_rotary_case(EXAMPLES / "speed_cycle.toml").items()}


@pytest.fixture(scope="module")
def sump_volume():
    return {name: simulate(case) for name, case in
            load_rotary_case(EXAMPLES / "sump_volume.toml").items()}


def _wave_vs_plain(speed_cycle):
    plain, wave = speed_cycle["plain"].steps, speed_cycle["wave"].steps
    reductions = [1 - w["torque_Nm"] / p["torque_Nm"] for p, w in zip(plain, wave, strict=True)
                  if p["speed_rpm"] >= 100]
    return np.array(reductions), plain[-1]["T_groove_C"] - wave[-1]["T_groove_C"], \
        plain[-1]["T_contact_C"] - wave[-1]["T_contact_C"]


def test_wave_lip_has_less_torque_and_runs_cooler(speed_cycle):
    # Seed 000 ("Comparison between molded wave and trimmed plain lips"), the direction: with
    # the film factor derived from the wave geometry (no assumed factor) the wave lip has less
    # torque at every step >= 100 rpm (last-30-s averages) and ends the cycle cooler.
    reductions, groove, contact = _wave_vs_plain(speed_cycle)
    assert np.all(reductions > 0.05)
    assert groove > 0 and contact > 0
    # ... and within what SKF states for its WAVE lips: "up to 20% less friction ... resulting
    # in up to 30% lower temperatures" than plain lips (SKF radial shaft seals, "Sealing lip
    # design"; bounds, no test conditions given).  Temperature: the contact's rise above
    # ambient at the end of the cycle (today 13-17 % and 15 %).
    assert np.all(reductions <= 0.20)
    ambient = speed_cycle["plain"].case.environment.ambient_temperature - 273.15
    rise = {k: r.steps[-1]["T_contact_C"] - ambient for k, r in speed_cycle.items()}
    assert 0.0 < 1.0 - rise["wave"] / rise["plain"] <= 0.30


@pytest.mark.xfail(strict=True, reason="seed claim not reproduced by the derived wave "
                   "mechanism: -15 % torque, 5 K cooler groove (docs/guide/validation_rotary.md)")
def test_wave_lip_reproduces_seed_magnitudes(speed_cycle):
    # Seed 000: "about 20 %" less torque and "more than 10 °C" less self-induced temperature;
    # the band 15-25 % (mean over steps >= 100 rpm) and >= 10 K at the groove.
    reductions, groove, _ = _wave_vs_plain(speed_cycle)
    assert 0.15 <= np.mean(reductions) <= 0.25
    assert groove >= 10.0


def test_bigger_sump_is_cooler_and_has_more_friction(sump_volume):
    # Seed 000 Fig. 13: 3 L runs cooler than 0.2 L, its oil is more viscous, friction is higher
    small, big = sump_volume["sump_0.2L"].steps, sump_volume["sump_3L"].steps
    for s, b in zip(small, big, strict=True):
        assert b["T_sump_C"] < s["T_sump_C"]
        assert b["T_groove_C"] < s["T_groove_C"]
        assert b["torque_Nm"] > s["torque_Nm"]


def test_energy_balance_closes(speed_cycle, sump_volume):
    # heat generated = stored + dissipated; backward Euler conserves it exactly, so the 1 %
    # requirement is met with a margin of many orders of magnitude
    for result in [*speed_cycle.values(), *sump_volume.values()]:
        assert result.energy["rel_error"] < 1e-6
        assert result.energy["generated"] > 0


def test_temperatures_finite_and_friction_non_negative(speed_cycle):
    for result in speed_cycle.values():
        frame = result.timeseries
        assert np.all(np.isfinite(frame.select_dtypes("number").to_numpy()))
        assert (frame["torque_Nm"] >= 0).all() and (frame["power_W"] >= 0).all()
        assert (frame["F_lub_N"] >= 0).all() and (frame["F_material_N"] >= 0).all()


ISO_CASES = [(d, n) for d in (40, 80, 120) for n in (1000, 2000, 3000)]


@pytest.mark.parametrize(("diameter_mm", "rpm"), ISO_CASES)
def test_torque_within_factor_1p5_of_iso_tr_14179_2(diameter_mm, rpm):
    # ISO/TR 14179-2: P = 7.69e-6·d²·n [W] (d mm, n rpm), the gearbox-efficiency standard's seal
    # loss; VG 68, sump held at 80 °C, steady state, default seal of that size.  The issue
    # accepts a factor 1.5 (the ISO value is one constant for all seals, oils and temperatures).
    case = _case(seal={"shaft_diameter": f"{diameter_mm} mm"}, oil={"name": "VG68-mineral"},
                 environment={"sump_temperature": "80 degC"})
    result = steady_state(case, rpm * RPM)
    iso = 7.69e-6 * diameter_mm**2 * rpm
    assert 1 / 1.5 <= result["power_W"] / iso <= 1.5


def test_torque_rises_only_weakly_with_speed_in_lubricated_range():
    # Lubricated (hydrodynamic) branch, above the Stribeck minimum (≈ 1000 rpm at 80 °C):
    # F_lub ∝ (ηu)^0.34 at constant temperature (seed Eq. 4 and 5) while the rubber part falls
    # as the film grows, so the total rises, but by less than the viscous part's 3^0.34 = 1.45
    # from 1000 to 3000 rpm.
    frame = friction_map(_case(), [1000.0, 2000.0, 3000.0], [80.0])
    torque = frame["torque_Nm"].to_numpy()
    assert np.all(np.diff(torque) > 0)
    assert torque[-1] / torque[0] < 3**0.34


@pytest.mark.filterwarnings("ignore::sealsim.properties.elastomers.ServiceRangeWarning")
@settings(max_examples=60, deadline=None)
@given(rpm=st.floats(-6000, 6000), temperature=st.floats(-20, 140))
def test_friction_opposes_sliding(rpm, temperature):
    friction = lip_seal_friction(_case())
    state = friction.evaluate(rpm * RPM, temperature + 273.15)
    assert float(state.torque) * rpm >= 0  # torque has the sign of the speed: it opposes it
    assert float(state.power) >= 0  # dissipation is never negative
    assert float(state.force_lubricant) >= 0 and float(state.force_material) >= 0


def test_lip_force_spring_share_stays():
    # spring share constant, rubber share ∝ E(T)/E(Tref)·δ(T)/δ(Tref)
    assert lip_force(30.0, 0.45, 0.0) == pytest.approx(0.45 * 30.0)
    assert lip_force(30.0, 0.45, 1.0, 0.0) == pytest.approx(0.45 * 30.0)
    friction = lip_seal_friction(_case())
    forces = friction.lip_force(np.array([20.0, 60.0, 100.0]) + 273.15)
    assert np.all(np.diff(forces) < 0)  # the rubber softens and expands from 20 to 100 °C
    assert forces[0] == pytest.approx(float(default_radial_force(0.08)), rel=1e-3)


def test_lip_interference_shrinks_with_the_rubbers_thermal_expansion():
    # Finding 6.  The issue: "about 20 % less interference over 80 K".  Eq. (2) with the
    # catalogue NBR (α = 1.9e-4 /K, the rubbery CTE) on steel (12e-6 /K) and the default hoop
    # pre-strain 0.08: (1.9e-4 - 1.2e-5)·80/0.08 = 17.8 %; accepted 15-25 % (the issue's
    # "about"); then the rubber share of the force is E-ratio x interference-ratio exactly.
    nbr = get_elastomer("NBR")
    loss = 1 - float(interference_ratio(373.15, 293.15, 0.08, nbr.thermal_expansion,
                                        STEEL_EXPANSION))
    assert loss == pytest.approx((nbr.thermal_expansion - STEEL_EXPANSION) * 80 / 0.08,
                                 rel=1e-12)
    assert 0.15 <= loss <= 0.25
    case = _case()
    seal = case.seal
    e_ratio = nbr.held_modulus(373.15) / nbr.held_modulus(293.15)
    expected = seal.radial_force * (seal.spring_share + (1 - seal.spring_share) * e_ratio
                                    * (1 - loss))
    assert lip_seal_friction(case).lip_force(373.15) == pytest.approx(expected, rel=1e-12)
    # a lip ring heated beyond its pre-strain lifts off: only the spring presses
    assert interference_ratio(600.0, 293.15, 0.02, nbr.thermal_expansion) == 0.0


def test_lip_cooled_after_mounting_keeps_its_relaxed_stress():
    # Issue 24, finding 2.  A lip mounted at 20 °C and cooled to -20 °C: the stress it relaxed
    # to at 20 °C stays (its modulus E_m keeps the mounting relaxation), only the thermal
    # contraction since -- the ring shrinks onto the shaft by (α_r - α_shaft)·40 K -- meets
    # the stiff cold held modulus.  Hand calculation of the increment, then the same below T_g
    # (-40 °C), where the glass contracts with the Simha-Boyer coefficient.
    nbr = get_elastomer("NBR")
    seal = _case().seal
    force, share, eps0, mounted = (seal.radial_force, seal.spring_share, seal.hoop_prestrain,
                                   seal.mounting_temperature)
    reference = nbr.held_modulus(mounted)
    lip = lip_seal_friction(_case()).lip_force
    for cold, contraction in (
            (253.15, (nbr.thermal_expansion - STEEL_EXPANSION) * 40.0),
            (233.15, nbr.thermal_expansion * (mounted - nbr.glass_transition)
             + nbr.glassy_expansion * (nbr.glass_transition - 233.15) - STEEL_EXPANSION * 60.0)):
        increment = contraction / eps0  # extra interference relative to the mounted one
        hand = force * (share + (1 - share) * (
            nbr.held_modulus(cold, mounting_temperature=mounted)
            + nbr.held_modulus(cold) * increment) / reference)
        assert lip(cold) == pytest.approx(hand, rel=1e-12)
        # the mounted-cold bound (the lip mounted at that temperature) is far above it
        mounted_cold = lip_seal_friction(_case(seal={"mounting_temperature":
                                                     f"{cold - 273.15} degC"})).lip_force(cold)
        assert lip(cold) < 0.6 * mounted_cold
    # a lip warmed after mounting relaxes further: the same as mounted warm
    warm = lip_seal_friction(_case(seal={"mounting_temperature": "80 degC"})).lip_force(353.15)
    assert lip(353.15) == pytest.approx(warm, rel=1e-12)
    # torque at a -20 °C sump: below the mounted-cold bound, and the result says which case
    env = {"sump_temperature": "-20 degC"}
    cooled = steady_state(_case(environment=env), 100 * RPM)
    bound = steady_state(_case(seal={"mounting_temperature": "-20 degC"}, environment=env),
                         100 * RPM)
    assert cooled["lip_force_N"] < bound["lip_force_N"]
    assert cooled["torque_Nm"] < bound["torque_Nm"]
    assert cooled["lip_note"].startswith("lip mounted at 20 degC and cooled to")
    assert bound["lip_note"] == ""


def test_same_rubber_seal_and_temperature_give_one_modulus_in_both_models():
    # Issue 24, finding 3: one convention for a held seal -- the relaxed modulus after an hour
    # from the master curve (Elastomer.held_modulus).  The rotary lip's installed stress, the
    # FE lip, an O-ring FE map and the analytic O-ring estimate of the pneumatic model must
    # give the same modulus for the same rubber and temperature (mounted at 20 °C).  The maps
    # scale the catalogue's rounded constants, 6·(C10 + C01) = 7.98 MPa for NBR against the
    # master curve's 7.978 MPa at 23 °C and 1 Hz: agreement within 0.1 %.
    from sealsim.pneumatic.contact_maps import AnalyticContactMap
    from sealsim.rotary.lip_fe import lip_structure_case
    from sealsim.rotary.simulation import lip_force_source
    from sealsim.structure.build import build_material
    from sealsim.structure.case import StructureCase

    for name in ("NBR", "FKM"):
        rubber = get_elastomer(name)
        case = _case(seal={"material": name})
        lip = lip_force_source(case)
        fe_lip = build_material(lip_structure_case(case.seal, case.lip, 293.15))
        oring = build_material(validate_case(StructureCase, {
            "seal": {"cord_diameter": "2 mm", "inner_diameter": "12 mm"},
            "gland": {"arrangement": "rod", "sealing_diameter": "12 mm",
                      "groove_width": "2.7 mm"},
            "material": {"elastomer": name}, "load": {"squeeze": [0.12]}}))
        analytic = AnalyticContactMap(12e-3, 2e-3, 0.12, 6 * (rubber.c10 + rubber.c01),
                                      rubber.thermal_expansion, 293.15, elastomer=name)
        for temperature in (278.15, 293.15, 333.15, 373.15):
            # the rotary lip's installed stress: the stress ratio without the increment
            installed = rubber.held_modulus(temperature, mounting_temperature=293.15)
            if temperature >= 293.15:
                rotary = float(lip.stress_ratio(temperature) / lip.interference(temperature)
                               * rubber.held_modulus(293.15))
                assert rotary == pytest.approx(installed, rel=1e-12)
            for material in (fe_lip, oring):
                c10, c01, _ = material.constants(temperature)
                assert 6 * (c10 + c01) == pytest.approx(installed, rel=1e-3)
            assert analytic.modulus_at(temperature) == pytest.approx(installed, rel=1e-3)


def test_friction_takes_any_lip_force_source():
    # The lip force is a function of temperature only, so another source (an FE map) can slot
    # in: with a constant 20 N source the model reports 20 N and F_material = μ·α·20 N.
    base = lip_seal_friction(_case())
    fe_like = LipSealFriction(base.parameters, base.oil, base.elastomer,
                              lambda t: np.full(np.shape(t), 20.0))
    state = fe_like.evaluate(100 * RPM, 353.15)
    assert float(state.lip_force) == 20.0
    assert float(state.force_material) == pytest.approx(
        float(state.mu_dry * state.asperity_share) * 20.0, rel=1e-12)


def test_analytic_lip_force_gives_its_held_modulus_with_the_force():
    # The friction takes F_tip and the film law's held modulus E_h(T) from one evaluation of
    # the analytic lip force (Eq. 1 meets E_h on the way): exactly the separate values, and a
    # friction model whose lip-force source is any other callable of the same law (which has
    # to ask the elastomer for E_h) gives the same state, bit for bit, cooled below the
    # mounting temperature and warmed above it, for one point and for a map.
    base = lip_seal_friction(_case())
    force = base.lip_force
    for temperature in (253.15, 293.15, 353.15):
        f_tip, held = force.force_and_held_modulus(temperature)
        assert f_tip == force(temperature)
        assert held == base.elastomer.held_modulus(temperature)
    other = LipSealFriction(base.parameters, base.oil, base.elastomer, lambda t: force(t))
    for omega, temperature in ((100 * RPM, 253.15), (1500 * RPM, 353.15),
                               (np.array([10.0, 100.0]), np.array([[280.0], [330.0]]))):
        for a, b in zip(base.evaluate(omega, temperature), other.evaluate(omega, temperature),
                        strict=True):
            assert np.array_equal(a, b)


def test_effective_friction_coefficient_in_measured_range_for_the_right_reason():
    # Finding 3.  Measured lip seal μ_eff = F_friction/F_radial: 0.2-0.6 (issue; typical
    # literature values are 0.1-0.6, not checked against a primary source).  Checked from 10 to 3000 rpm at 40-120 °C.  The right reason:
    # at 10 rpm (mixed lubrication) the asperities carry most of the load (α > 0.8 at >= 40 °C)
    # and μ_dry·α is most of μ_eff -- no real-area factor of about 0.2 in front of μ_dry.
    frame = friction_map(_case(), np.geomspace(10, 3000, 9), [40.0, 60.0, 80.0, 100.0, 120.0])
    assert frame["mu_eff"].between(0.2, 0.6).all()
    slow = frame[frame["speed_rpm"] == 10.0]
    assert (slow["asperity_share"] > 0.8).all()
    material_part = slow["mu_dry"] * slow["asperity_share"]
    assert np.all(material_part > 0.5 * slow["mu_eff"])


def test_wave_film_factor_follows_the_contact_line_geometry():
    # Finding 2.  Eq. (3): 1 + <|sin φ|^n>, tan φ = (A N/R) cos Nθ.  Small-slope closed form
    # <|s cos|^n> = s^n Γ((n+1)/2)/(√π Γ(n/2+1)); the arctan/sin differ by O(s²) ≈ 1 % at
    # s = 0.1 (tolerance 1 %).
    from scipy.special import gamma
    n, slope = 0.66, 0.5e-3 * 8 / 0.04
    closed = 1 + slope**n * gamma((n + 1) / 2) / (math.sqrt(math.pi) * gamma(n / 2 + 1))
    assert wave_film_factor(0.5e-3, 8, 0.08) == pytest.approx(closed, rel=0.01)
    assert wave_film_factor(0.0, 8, 0.08) == 1.0
    assert wave_film_factor(0.5e-3, 16, 0.08) > wave_film_factor(0.5e-3, 8, 0.08)
    # the wave variant's film is the plain film times the factor (same lip force, viscosity)
    plain = friction_map(_case(), [1000.0], [80.0])
    wave = friction_map(_case(seal={"lip_style": "wave"}), [1000.0], [80.0])
    assert wave["film_um"].iloc[0] / plain["film_um"].iloc[0] == pytest.approx(
        wave_film_factor(0.5e-3, 8, 0.08), rel=1e-12)
    # a calibrated factor replaces the derived one
    calibrated = friction_map(_case(seal={"lip_style": "wave", "wave": {"film_factor": 1.4}}),
                              [1000.0], [80.0])
    assert calibrated["film_um"].iloc[0] / plain["film_um"].iloc[0] == pytest.approx(1.4)


def _rise_over_sump(environment, rpm, diameter="80 mm"):
    case = _case(seal={"shaft_diameter": diameter},
                 environment={"sump_temperature": "80 degC", **environment})
    return steady_state(case, rpm * RPM)["T_contact_C"] - 80.0


def test_setups_fill_documented_defaults():
    for name, setup in SETUPS.items():
        env = _case(environment={"setup": name}).environment
        assert env.shaft_length_air_side == setup.shaft_length_air_side
        assert env.shaft_oil_end == setup.shaft_oil_end
        assert env.shaft_air_end == setup.shaft_air_end
        assert env.air_side == setup.air_side
        assert env.housing_heat_transfer == setup.housing_heat_transfer
    # explicit fields win over the set-up
    assert _case(environment={"shaft_air_end": "housing"}).environment.shaft_air_end == "housing"


def test_gearbox_housing_coefficient_is_radiation_plus_free_convection():
    # SETUPS' 12 W/(m² K): grey-body radiation (ε = 0.9) of a 60 °C wall in a 20 °C room plus
    # Churchill & Chu's free convection of a 0.3 m vertical wall 40 K above it (air at the
    # 40 °C film): 6.3 + 5.2 = 11.5, within 5 % (the rounding to 12).  The comment gave
    # 7.5 + 4.8 until 2026-11-28: its 7.5 is a wall at 80 °C in a 40 °C room.
    from sealsim.thermal.convection import (
        air_properties,
        free_convection_vertical_plate,
        radiation_coefficient,
    )
    nu, alpha, k, _ = air_properties(313.15)
    h = float(radiation_coefficient(333.15, 293.15)) + float(
        free_convection_vertical_plate(0.3, 40.0, nu, alpha, k, 1 / 313.15))
    assert SETUPS["gearbox"].housing_heat_transfer == pytest.approx(h, rel=0.05)


def test_contact_is_above_a_held_sump_at_4_m_s_in_both_setups():
    # Finding 1, the wrong sign: with the air-side shaft an infinite fin to 20 °C ambient the
    # 80 mm contact ran 1.5 K BELOW an 80 °C sump at 1000 rpm (4.2 m/s).  In both documented
    # set-ups it runs above it, and the rise grows with speed (3000 rpm, 12.6 m/s).
    old = {"shaft_oil_end": "fin", "shaft_air_end": "fin", "shaft_length_oil_side": "60 mm",
           "shaft_length_air_side": "80 mm", "air_side": "ambient"}
    assert _rise_over_sump(old, 1000) < 0
    for environment in ({"setup": "gearbox"}, {"setup": "test_rig"}):
        slow, fast = _rise_over_sump(environment, 1000), _rise_over_sump(environment, 3000)
        assert 0 < slow < fast


# Published contact over-temperatures above the sump (docs/guide/validation_rotary.md, finding 1): seal
# makers put the lip 20-50 K above the sealed oil (svks-rubberseal.com, 2018, oil-seal selection
# guidance); the summary of rig thermocouple/thermography studies: 15-30 K at about
# 4 m/s, 30-50 K at 10-13 m/s.  Rig set-up, 80 mm NBR seal, VG 68, 80 °C sump.


def test_rig_contact_rise_at_12_6_m_s_within_published_range():
    # The oil-side shaft is cooled by Taylor-Couette flow in the annulus between shaft and
    # housing bore (Staton & Cavagnino 2008), not by a cylinder in an open bath (Kays &
    # Bjorklund gave +21 K here); no parameter was fitted.  The band is the published one.
    assert 30 <= _rise_over_sump({"setup": "test_rig"}, 3000) <= 50


@pytest.mark.xfail(strict=True, reason="at 4.2 m/s the rig set-up gives +10.8 K (+14.0 K "
                   "before the annulus's oil got its own wall layers), below the 15-30 K of "
                   "the issue's summary; its oil side is all annulus (L/gap = 2.9), so the "
                   "unknown chamber matters (40 mm gap: +13.6 K; the annulus coefficient x1/2: "
                   "+14.7 K, with no source for it) (docs/guide/validation_rotary.md, finding 1)")
def test_rig_contact_rise_at_4_2_m_s_within_published_range():
    assert 15 <= _rise_over_sump({"setup": "test_rig"}, 1000) <= 30


def test_gearbox_contact_runs_cooler_than_the_rig():
    # In the gearbox the shaft continues as a rotating fin in the sump (≈ 7 W/K on 80 mm at
    # 1000 rpm) and into the motor as a fin in the adapter's air: at equal speed the 80 mm
    # gearbox contact rises less above the sump than the rig's (insulated shaft ends), even
    # with the bearing's heat (on 40 mm at 1000 rpm the gearbox is the warmer, +4.1 / +3.4 K).
    for rpm in (1000, 3000):
        assert _rise_over_sump({"setup": "gearbox"}, rpm) < _rise_over_sump(
            {"setup": "test_rig"}, rpm)


# Issue 24, finding 1: the default gearbox set-up has no boundary of fixed temperature on the
# oil side: the shaft passes the bearing beside the seal (a heat source, Palmgren) and
# continues as a rotating fin in the sump.  The bands of the issue (80 mm, VG 68, sump held at
# 80 °C, 20 °C ambient) are the references; those the physics misses are strict xfails with
# the measured number (README, Validation).
GEARBOX_RPM = [10, 100, 300, 1000, 2000, 3000, 5000]


def test_gearbox_contact_rise_at_12_6_m_s_within_published_band():
    assert 20 <= _rise_over_sump({}, 3000) <= 60


@pytest.mark.xfail(strict=True, reason="the default gearbox gives +8.8 K at 1000 rpm (36 W): "
                   "the rotating fin in the sump (≈ 7 W/K), the shaft under the bearing "
                   "(5.3 W/K) and the motor shaft, a fin in the adapter's air at the housing "
                   "temperature (73 °C), cool the shaft; none of the candidates re-examined on "
                   "2026-11-28 is a sourced correction: the short annulus's coefficient x1/4..x4 "
                   "gives +9.1..+7.9 K, a motor shaft as warm as the seal's end +10.3 K, a "
                   "housing held at the sump +10.1 K (docs/guide/validation_rotary.md, finding 1; "
                   "examples/rotary/contact_rise_candidates.py)")
def test_gearbox_contact_rise_at_4_2_m_s_within_published_band():
    assert 10 <= _rise_over_sump({}, 1000) <= 40


def test_gearbox_small_shaft_contact_rises_3_k_at_1000_rpm():
    # 9 W of friction on 40 mm: +4.1 K.  Before the air side was enclosed in the motor adapter
    # (20 °C room air along the shaft, coupling held at the housing temperature) it was -0.5 K.
    assert _rise_over_sump({}, 1000, "40 mm") >= 3.0


@pytest.mark.xfail(strict=True, reason="at 10-100 rpm the contact is 0.5-2.1 K below the 80 °C "
                   "sump (0.3-3.6 W of friction): the seal sits in a housing at 69-70 °C, 10 K "
                   "below the held sump (oil to wall 100 W/(m2 K)), and the shaft leads into "
                   "the adapter's air at that temperature; the heat that holds the sump leaves "
                   "through the housing, so the housing is colder than its oil, and with it "
                   "held at the sump's temperature the contact is never below the sump (next "
                   "test): the band assumes a wall at the oil's temperature")
def test_gearbox_contact_never_below_the_sump_with_cold_ambient():
    assert min(_rise_over_sump({}, rpm) for rpm in GEARBOX_RPM) >= 0.0


def test_a_contact_below_a_held_sump_says_why():
    # lip_seal_torque at 10 rpm in the default gearbox gave a contact of 77.9 °C with the sump
    # held at 80 °C and no word of the cause, so a new user filed it as a bug (issue 24): the
    # housing, at 69.2 °C, was not even in the result.  Now it is a column, and a note names
    # it, in lip_seal_torque and in a rotary run; a contact above the sump gets no such note.
    with pytest.warns(SealsimWarning):
        slow = sealsim.lip_seal_torque("80 mm", "10 rpm", "VG68", "80 degC")
    assert slow["T_housing_C"] < slow["T_contact_C"] < 80.0 - 0.1
    ours = [n for n in slow["notes"] if "below the sump held at 80.0 degC" in n]
    assert len(ours) == 1 and f"housing (down to {slow['T_housing_C']:.1f} degC)" in ours[0]
    assert f"contact down to {slow['T_contact_C']:.1f} degC" in ours[0]
    fast = sealsim.lip_seal_torque("80 mm", "1000 rpm", "VG68", "80 degC")
    assert fast["T_contact_C"] > 80.0 and not [n for n in fast["notes"] if "held at" in n]
    run = simulate(_case(environment={"sump_temperature": "80 degC"},
                         duty={"steps": [{"speed": "10 rpm", "duration": "20 min"}]}))
    assert run.timeseries["T_contact_C"].min() < 80.0 - 0.1
    assert [n for n in run.notes if "below the sump held at 80.0 degC" in n]


@pytest.mark.parametrize("rpm", GEARBOX_RPM)
def test_gearbox_contact_never_below_the_sump_when_the_housing_is_held_at_it(rpm):
    # Maximum principle of the steady heat network: in the gearbox set-up with the housing
    # held at the sump's 80 °C every node the shaft and seal give heat to is at 80 °C (sump,
    # housing, the motor adapter's air), the seal's friction and the bearing's heat are
    # sources, so no temperature can lie below 80 °C.  It locates the cause of the xfail above:
    # the colder housing, not the seal's network.  Tolerance 1e-6 K: the solver's 1e-8 K
    # tolerance on the updates, with margin.
    assert _rise_over_sump({"housing_temperature": "80 degC"}, rpm) >= -1e-6


@pytest.mark.parametrize("environment", [
    {"sump_temperature": "80 degC"},                          # gearbox, held sump
    {"setup": "test_rig", "sump_volume": "3 L"},              # rig, free sump
    {"sump_temperature": "80 degC", "air_side": "ambient", "shaft_air_end": "housing"},
])
@pytest.mark.parametrize("rpm", [10, 1000, 3000])
def test_heat_paths_carry_away_what_the_seal_and_bearing_put_in(environment, rpm):
    # Energy conservation of the steady state: the heat leaving shaft and seal through the
    # oil side, the housing and the air side is the seal's friction heat plus the bearing's
    # shaft share (bearing.shaft_share of its heat enters under the inner ring); both sides
    # are computed independently (network flows vs friction and bearing laws); the steady
    # state converges to 1e-8 K, so 1e-6 relative.
    case = _case(environment=environment)
    r = steady_state(case, rpm * RPM)
    heat_in = r["power_W"] + case.environment.bearing.shaft_share * r["bearing_power_W"]
    heat_out = r["heat_oil_side_W"] + r["heat_housing_W"] + r["heat_air_side_W"]
    assert heat_out == pytest.approx(heat_in, rel=1e-6)


def test_heat_paths_all_leave_when_nothing_is_colder_than_the_sump():
    # Housing and room held at the sump temperature: by the maximum principle no temperature
    # of shaft, seal or air pocket is below 80 °C, so no path can bring heat in (to round-off).
    case = _case(environment={"sump_temperature": "80 degC", "housing_temperature": "80 degC",
                              "ambient_temperature": "80 degC"})
    r = steady_state(case, 1000 * RPM)
    for path in ("heat_oil_side_W", "heat_housing_W", "heat_air_side_W"):
        assert r[path] >= -1e-9, path


def test_motor_adapter_shields_the_air_side_from_the_room():
    # In a gear motor the air-side shaft turns in the closed adapter bolted to the housing:
    # with the housing held, the room's temperature cannot reach the seal (to round-off),
    # whereas a free input shaft in the room (air_side = "ambient") feels a 40 K colder room.
    held = {"sump_temperature": "80 degC", "housing_temperature": "75 degC"}
    rises = {air: [_rise_over_sump({**held, "air_side": air, "ambient_temperature": t}, 1000)
                   for t in ("0 degC", "40 degC")] for air in ("adapter", "ambient")}
    assert rises["adapter"][0] == pytest.approx(rises["adapter"][1], abs=1e-9)
    assert rises["ambient"][1] - rises["ambient"][0] > 1.0


def test_motor_shaft_end_conditions_bracket_the_default():
    # The motor's temperature is unknown: holding the coupling at the housing temperature
    # (a sink) and a motor shaft as warm as the seal's end (no heat through the coupling)
    # bracket the default rotating fin; each step must move the contact the right way.
    rise = {end: _rise_over_sump({"shaft_air_end": end}, 1000)
            for end in ("housing", "fin", "insulated")}
    assert rise["housing"] < rise["fin"] < rise["insulated"]


def test_gearbox_contact_never_below_the_sump_when_nothing_is_colder():
    # The maximum principle of heat conduction: with the seal and the bearing as the only
    # sources and no boundary colder than the held sump (ambient at the sump temperature),
    # no temperature of the model can fall below the sump, at any speed.  The old set-up met
    # this too; it is the invariant the gearbox must keep (rounding: 1e-6 K).
    for diameter in ("80 mm", "40 mm"):
        for rpm in GEARBOX_RPM:
            case = _case(seal={"shaft_diameter": diameter},
                         environment={"sump_temperature": "80 degC",
                                      "ambient_temperature": "80 degC"})
            result = steady_state(case, rpm * RPM)
            assert result["T_contact_C"] >= 80.0 - 1e-6
            assert result["T_groove_C"] >= 80.0 - 1e-6


def test_gearbox_oil_side_fin_equals_a_long_modelled_shaft():
    # The semi-infinite fin at the oil-side end (conductance √(hPkA), Incropera §3.6.4) must
    # give the contact temperature of a shaft modelled four decay lengths further into the
    # gear case with the same coefficient: e^-4 = 2 % of the end's temperature excess is
    # left, so within 2 % of the rise above the sump.
    short = _case(environment={"sump_temperature": "80 degC", "ambient_temperature": "80 degC"})
    model = RotaryModel(short)
    h = model.coefficients(1000 * RPM, 353.15)["shaft_end_oil"]
    decay = 45.0 / h  # 1/m = √(4h/(k d)) and h_end = √(4 h k/d): 1/m = k/h_end
    long = _case(environment={"sump_temperature": "80 degC", "ambient_temperature": "80 degC",
                              "shaft_length_oil_side":
                                  f"{(model.section.shaft_length_oil + 4 * decay) * 1e3} mm"})
    rise_short = steady_state(short, 1000 * RPM)["T_contact_C"] - 80
    rise_long = steady_state(long, 1000 * RPM)["T_contact_C"] - 80
    assert rise_short == pytest.approx(rise_long, rel=0.02)


def test_bearing_heat_enters_the_gearbox_and_the_energy_balance():
    # The bearing beside the seal heats the shaft (Palmgren's viscous moment × ω: 96 W at
    # 3000 rpm in VG 68 for the 6216 of an 80 mm shaft, sump at 80 °C; half into the shaft): the
    # contact runs hotter than without it, and the transient books its heat.
    with_bearing = _rise_over_sump({}, 3000)
    without = _rise_over_sump({"bearing": {"model": "none"}}, 3000)
    assert with_bearing > without
    given = steady_state(_case(environment={"sump_temperature": "80 degC",
                                            "bearing": {"model": "power", "power": "50 W"}}),
                         3000 * RPM)
    assert given["bearing_power_W"] == 50.0
    case = _case(environment={"sump_volume": "0.5 L"},
                 duty={"steps": [{"speed": "2000 rpm", "duration": "5 min"}]})
    result = simulate(case)
    assert result.energy["generated_bearing"] > 0.1 * result.energy["generated"]
    assert result.energy["rel_error"] < 1e-9


def test_bearing_runs_on_its_own_oil_temperature():
    # Palmgren's ν is that at the bearing's operating temperature (the mean of the shaft under
    # its inner ring and the housing), not the sump's.  Hand check of the steady state at a
    # sump held at 0 °C: the reported heat is Palmgren's moment at the mean ring temperature of
    # the converged network (to the solver's 1e-8 K), below the 285 W the 0 °C oil would give.
    case = _case(environment={"sump_temperature": "0 degC"})
    model = RotaryModel(case)
    r = steady_state(case, 1000 * RPM)
    pitch = bearing_geometry(case)[0]
    cold = float(palmgren_viscous_moment(model.oil.kinematic_viscosity(273.15), 1000 * RPM,
                                         pitch)) * 1000 * RPM
    assert cold == pytest.approx(284.9, rel=1e-3)
    assert r["bearing_power_W"] < 0.5 * cold
    # the contact cannot be hotter above a colder held sump (at the sump's viscosity the
    # bearing made 0 °C hotter than 20 °C, and -20 °C stopped at NBR's 150 °C limit):
    # monotone within the solver's tolerance, each converged in a few iterations
    results = [steady_state(_case(environment={"sump_temperature": f"{t} degC"}), 1000 * RPM)
               for t in (-20, 0, 20, 50, 80)]
    contacts = [x["T_contact_C"] for x in results]
    assert all(a < b for a, b in zip(contacts, contacts[1:])), contacts
    assert max(x["iterations"] for x in results) <= 20


def test_bearing_temperature_is_the_mean_of_its_rings():
    # inner ring: the shaft surface under it (network cells weighted by width); outer ring: the
    # housing, here held; checked on a made-up temperature field with the shaft at 90 °C
    case = _case(environment={"sump_temperature": "80 degC",
                              "housing_temperature": "60 degC"})
    model = RotaryModel(case)
    temps = np.full(model.network.n, 363.15)
    assert model.bearing_temperature(temps) == pytest.approx(0.5 * (363.15 + 333.15), abs=1e-9)
    rig = RotaryModel(_case(environment={"setup": "test_rig", "sump_temperature": "80 degC"}))
    assert rig.bearing_heat(1000 * RPM, np.full(rig.network.n, 300.0)) == 0.0


def test_open_bath_convection_cools_the_shaft_more_than_the_annulus():
    # Kays & Bjorklund's cylinder in a quiescent bath gives more than twice the annulus's shaft
    # coefficient at 1000 rpm in VG 68 at 80 °C (≈ 1600 vs 680 W/(m² K), 380 across the whole
    # gap): the rig contact runs
    # cooler with it; a wider annulus cools less (h ∝ gap^-1/4).
    annulus = _rise_over_sump({"setup": "test_rig"}, 1000)
    assert _rise_over_sump({"setup": "test_rig", "shaft_oil_convection": "open"}, 1000) < annulus
    assert _rise_over_sump({"setup": "test_rig", "oil_gap": "40 mm"}, 1000) > annulus


def test_annulus_correlation_is_across_the_gap_from_shaft_to_bore():
    # Staton & Cavagnino's Taylor-Couette h is across the gap, shaft to bore (its laminar Nu = 2
    # is conduction from wall to wall).  The oil in the gap is the sump node, so shaft -> oil
    # and oil -> bore (a link to the housing) in series must give back h·A_shaft; until
    # 2026-11-28 the whole across-gap h stood between the shaft and the oil and the bore took
    # nothing.  Flooded annulus (no air share), rig set-up (no bearing), 1000 rpm, 80 °C.
    from sealsim.thermal.convection import rotating_annulus_coefficient
    omega, ts = 1000 * RPM, 353.15
    env = {"setup": "test_rig", "oil_level_wetting": 1.0}
    model = RotaryModel(_case(environment=env))
    oil = model.oil
    nu, k = float(oil.kinematic_viscosity(ts)), float(oil.thermal_conductivity(ts))
    alpha = k / float(oil.density(ts) * oil.specific_heat(ts))
    across = float(rotating_annulus_coefficient(omega, 0.08, model.oil_gap, nu, k, nu / alpha))
    h = model.coefficients(omega, ts)
    # the shaft's own wall layer: h·(1 + R_i/R_o), 681 W/(m² K) on 80 mm in a 10.5 mm gap
    # against the 380 of the whole gap (exact, 1e-12)
    assert h["shaft_oil"] == pytest.approx(across * (1 + 0.04 / (0.04 + model.oil_gap)),
                                           rel=1e-12)
    b, faces = model.grid.conduction.boundary, model.grid.face_groups["shaft_oil"]
    shaft_area = b.area[faces][b.z[faces] < model.section.oil_face].sum()
    # the bore: radius R + gap over the same length (exact, 1e-12)
    assert model.annulus_bore_area == pytest.approx(shaft_area * (0.04 + model.oil_gap) / 0.04,
                                                    rel=1e-12)
    shaft, bore = h["shaft_oil"] * shaft_area, h["annulus_bore"] * model.annulus_bore_area
    assert 1.0 / (1.0 / shaft + 1.0 / bore) == pytest.approx(across * shaft_area, rel=1e-12)
    # the bore link is in the network: sump-housing coupling = wetted wall + bore (free sump)
    k_matrix, _ = model.assemble(omega, ts)
    i, j = model.network.node_index["sump"], model.network.node_index["housing"]
    wetted = housing_defaults(model.case.environment.sump_volume)[1]
    assert -k_matrix[i, j] == pytest.approx(100.0 * wetted + bore, rel=1e-12)


def test_contact_band_spreading_resistance_is_resolved_by_the_grid():
    # The 0.25 mm band concentrates the frictional heat; its constriction into the shaft is
    # most of the band's temperature rise.  Reference: the exact series solution for a solid
    # cylinder (radius R, ends at z = ±L held at 0, lateral surface adiabatic except the band
    # |z| < b/2 with uniform flux q): T = Σ A_n I0(k_n r) cos(k_n z), k_n = (2n+1)π/(2L),
    # A_n = q_n/(k·k_n·I1(k_n R)), q_n = 2q·sin(k_n b/2)/(L·k_n); band mean
    # Σ A_n I0(k_n R)·2 sin(k_n b/2)/(b k_n).  The rotary grid's shaft (rig set-up, 30 mm each
    # side) with its band source must match within 1 % (measured 0.5 %; 0.06 % refined 2×).
    model = RotaryModel(_case(environment={"setup": "test_rig"}))
    grid = model.grid.conduction
    radius, band = model.section.radius, model.section.contact_band
    length, k, power = model.section.shaft_length_oil, 45.0, 10.0
    assert model.section.shaft_length_air == length  # symmetric, as the series assumes
    shaft = AxisymmetricConduction(grid.r_edges, grid.z_edges,
                                   np.where(grid.material == 0, 0, -1), [Solid("s", k, 1, 1)])
    ends = np.nonzero((shaft.boundary.void < 0) & (shaft.boundary.side >= 2))[0]
    network = ThermalNetwork(shaft, {}, ["end"], {"ends": (ends, "end")})
    matrix, _ = network.assemble({"ends": 1e12})
    row = int(np.argmin(np.abs(grid.r_edges - radius))) - 1
    in_band = np.abs(shaft.z_centres) < band / 2
    cells, widths = shaft.index[row, in_band], np.diff(shaft.z_edges)[in_band]
    source = np.zeros(network.n)
    source[cells] = power * widths / widths.sum()
    numeric = spla.spsolve(matrix.tocsc(), source)[cells] @ (widths / widths.sum())
    kn = (2 * np.arange(200_000) + 1) * np.pi / (2 * length)
    q = power / (2 * np.pi * radius * band)
    qn = 2 * q * np.sin(kn * band / 2) / (length * kn)
    exact = np.sum(qn / (k * kn) * i0e(kn * radius) / i1e(kn * radius)
                   * 2 * np.sin(kn * band / 2) / (band * kn))
    uniform = power * length / (2 * k * np.pi * radius**2)  # no constriction: 1D conduction
    assert numeric == pytest.approx(exact, rel=0.01)
    assert exact > 2 * uniform  # the constriction matters: it is worth resolving


@pytest.mark.parametrize(("environment", "rpm"), [
    ({"sump_temperature": "80 degC"}, 1500),
    ({"sump_volume": "1 L", "ambient_temperature": "23 degC"}, 1000),
    ({"setup": "test_rig", "sump_volume": "3 L"}, 300),
])
def test_steady_state_matches_the_refactorising_reference(environment, rpm):
    # Issue 13: one factorisation per operating point instead of one per fixed-point
    # iteration.  Both solve the same equations, so run to convergence (reference tol 1e-9 K)
    # they must agree to round-off; required: torque within 1e-9 relative, contact and sump
    # temperatures within 1e-6 K (measured: < 3e-11 and < 4e-9 K).
    case = _case(environment=environment)
    new = steady_state(case, rpm * RPM)
    reference = reference_steady_state(case, rpm * RPM, tol=1e-9, max_iter=400)
    assert new["torque_Nm"] == pytest.approx(reference["torque_Nm"], rel=1e-9)
    for column in ("T_contact_C", "T_sump_C"):
        assert new[column] == pytest.approx(reference[column], abs=1e-6)


def test_transient_with_one_ordering_is_the_transient_ordering_every_matrix(monkeypatch):
    # The stepper orders the network's pattern once (thermal.conduction.PatternFactoriser);
    # the reference orders every matrix anew (factorise, the code before).  Both are the same
    # elimination in another column order, so they agree to round-off, on a run that
    # factorises 26 matrices (Δt ramp after the speed change, 2 K sump bins) from one
    # ordering: the temperatures (the solution, in K) within 1e-10 relative (measured 9e-11 K
    # at most, 3e-13); every other column within 1e-9 of its largest value (measured 2.9e-11,
    # the housing's heat: conductances times differences of a few K, which lose 2-3 digits).
    import sealsim.thermal.conduction as conduction

    case = _case(duty={"steps": [{"speed": "1000 rpm", "duration": "3 min"},
                                 {"speed": "3000 rpm", "duration": "3 min"}]})
    ordered = []
    real = conduction.factorise
    monkeypatch.setattr(conduction, "factorise", lambda m: ordered.append(1) or real(m))
    result = simulate(case)
    factorisations = result.statistics["factorisations"]
    assert len(ordered) == 1 and factorisations >= 20, (len(ordered), factorisations)
    monkeypatch.setattr(conduction.PatternFactoriser, "__call__", lambda self, m: real(m))
    reference = simulate(case).timeseries
    frame = result.timeseries
    assert list(frame.columns) == list(reference.columns) and len(frame) == len(reference)
    for column in frame.columns:
        new, old = frame[column].to_numpy(float), reference[column].to_numpy(float)
        if column.startswith("T_"):
            new, old, rel = new + 273.15, old + 273.15, 1e-10
        else:
            rel = 1e-9
        assert np.max(np.abs(new - old)) <= rel * max(np.max(np.abs(old)), 1e-300), column


def test_run_starts_at_the_held_sump_temperature():
    # issue 16: with the sump held at 70 °C the run started at 20 °C (a 0.42 N m start-up
    # spike); now shaft, seal and oil start at 70 °C, so the first torque is the 70 °C torque
    # and changes by less than 10 % while the contact warms by a few kelvin.
    case = _case(environment={"sump_temperature": "70 degC"},
                 duty={"steps": [{"speed": "1500 rpm", "duration": "3 min"}]})
    frame = simulate(case).timeseries
    assert frame["T_contact_C"].iloc[0] == pytest.approx(70.0)
    assert frame["T_groove_C"].iloc[0] == pytest.approx(70.0)
    assert abs(frame["torque_Nm"].iloc[0] / frame["torque_Nm"].iloc[-1] - 1) < 0.1


def test_run_until_steady_ends_at_the_steady_state():
    # duty.until_steady holds the last speed until all temperatures change slower than
    # duty.steady_rate; the end must match the directly solved steady state within 2 % of the
    # temperature rise (what is left at 0.05 K/min) and 1 % of the torque.
    case = _case(environment={"sump_temperature": "60 degC"},
                 duty={"steps": [{"speed": "1500 rpm", "duration": "2 min"}], "until_steady": True},
                 numerics={"max_time_step": "20 s"})
    result = simulate(case)
    last = result.timeseries.iloc[-1]
    steady = steady_state(case, 1500 * RPM)
    assert result.steps[-1]["end_s"] > 120.0 and "steady" in result.notes[0]
    assert last["torque_Nm"] == pytest.approx(steady["torque_Nm"], rel=0.01)
    assert last["T_contact_C"] - 60 == pytest.approx(steady["T_contact_C"] - 60, rel=0.02)


def test_film_outside_measured_range_warns_once_with_a_note():
    # Finding 5: 6000 rpm at 40 °C extrapolates the film law to about 4 µm (> 2.5 µm measured)
    case = _case(environment={"sump_temperature": "40 degC"},
                 duty={"steps": [{"speed": "6000 rpm", "duration": "20 s"}]})
    with pytest.warns(FilmRangeWarning, match="above the measured range") as record:
        result = simulate(case)
    assert len([w for w in record if w.category is FilmRangeWarning]) == 1
    assert any("above the measured range" in note for note in result.notes)


def test_transient_approaches_steady_state():
    # independent check of the time integration: a long constant-speed run must end at the
    # steady state solved directly (K·T = F·T_fixed + s); 1 % of the temperature rise.
    case = _case(environment={"sump_temperature": "60 degC", "start_temperature": "60 degC"},
                 duty={"steps": [{"speed": "1500 rpm", "duration": "3 h"}]},
                 numerics={"max_time_step": "20 s"})
    transient = simulate(case).timeseries.iloc[-1]
    steady = steady_state(case, 1500 * RPM)
    assert transient["torque_Nm"] == pytest.approx(steady["torque_Nm"], rel=0.01)
    for column in ("T_contact_C", "T_groove_C"):
        assert transient[column] - 60 == pytest.approx(steady[column] - 60, rel=0.01)


def _step_values(result):
    return np.array([[s["torque_Nm"], s["T_contact_C"] - 23, s["T_groove_C"] - 23,
                      s["T_sump_C"] - 23] for s in result.steps])


@pytest.mark.parametrize("numerics", [{"mesh_refinement": 2.0},
                                      {"max_time_step": "1 s", "min_time_step": "0.05 s"}])
def test_mesh_and_time_step_refinement_change_results_below_1_percent(numerics):
    # torque and temperature rises (above the 23 °C start) of every step: < 1 % change when
    # the mesh is refined 2x or the time step 4-5x (issue requirement)
    duty = {"steps": [{"speed": "300 rpm", "duration": "10 min"},
                      {"speed": "1500 rpm", "duration": "10 min"},
                      {"speed": "100 rpm", "duration": "5 min"}]}
    env = {"sump_volume": "0.2 L", "ambient_temperature": "23 degC"}
    coarse = simulate(_case(environment=env, duty=duty))
    fine = simulate(_case(environment=env, duty=duty, numerics=numerics))
    assert np.max(np.abs(_step_values(fine) / _step_values(coarse) - 1)) < 0.01


def test_duty_cycle_from_csv_with_ramps_and_standstill(tmp_path):
    (tmp_path / "cycle.csv").write_text(
        "time_s,speed_rpm\n0,0\n60,0\n120,1500\n300,1500\n360,0\n420,0\n")
    case = _case(duty={"csv": "cycle.csv"})
    result = simulate(case, base_dir=tmp_path)
    frame = result.timeseries
    assert frame["time_s"].iloc[-1] == pytest.approx(420.0)
    assert np.all(np.isfinite(frame.select_dtypes("number").to_numpy()))
    standing = frame[frame["speed_rpm"] == 0]
    assert (standing["power_W"] == 0).all()  # no sliding, no heat
    # plateaus of constant speed are the summary steps: 0, 1500, 0 rpm
    assert [round(s["speed_rpm"]) for s in result.steps] == [0, 1500, 0]
    assert result.energy["rel_error"] < 1e-6


@pytest.mark.parametrize(("section", "values", "field"), [
    ("seal", {"shaft_diameter": "80 kg"}, "seal.shaft_diameter"),
    ("seal", {"shaft_diameter": "-80 mm"}, "seal.shaft_diameter"),
    ("seal", {"material": "NRB"}, "seal.material"),
    ("seal", {"lip_style": "wavy"}, "seal.lip_style"),
    ("oil", {"name": "VG86"}, "oil"),
    ("environment", {"sump_volume": "nan L"}, "environment.sump_volume"),
    ("environment", {"start_temperature": "-60 degC"}, "start_temperature"),
    ("duty", {"steps": [{"speed": "100 Hz", "duration": "1 min"}]}, "duty.steps.0.speed"),
])
def test_bad_input_names_the_field(section, values, field):
    with pytest.raises(InputError, match=field.replace(".", r"\.")):
        _case(**{section: values})


def test_an_oil_table_corrects_a_catalogue_oil_and_refuses_what_it_would_ignore():
    catalogue = get_oil("VG46")
    # the datasheet pour point of the oil in the gearbox corrects the catalogue's typical one
    oil = _case(oil={"name": "VG46", "min_temperature": "-39 degC"}).oil.build()
    assert oil.min_temperature == pytest.approx(234.15, abs=1e-9)
    assert (oil.walther_A, oil.walther_B) == (catalogue.walther_A, catalogue.walther_B)
    assert oil.source.endswith("min_temperature from the case")
    # a family with a catalogue name was dropped without a word (the oil stayed mineral)
    with pytest.raises(InputError, match=r"oil: family given: your own oil needs nu40"):
        _case(oil={"name": "VG46", "family": "PAO"})
    # an own oil without a name was called 'VG68-mineral', the default catalogue oil
    own = {"nu40": "46 mm^2/s", "nu100": "6.8 mm^2/s", "density15": "872 kg/m^3"}
    with pytest.raises(InputError, match=r"your own oil needs its name.*'VG68-mineral'"):
        _case(oil=own)
    # the ASTM D341 constants of an oil file serve as well as its two viscosities
    walther = _case(oil={"name": "mine", "walther_A": catalogue.walther_A,
                         "walther_B": catalogue.walther_B, "density15": "875 kg/m^3"})
    assert walther.oil.build().nu40 == pytest.approx(46e-6, rel=1e-12)


def test_free_convection_in_the_sump_takes_the_oils_expansion():
    # The free-convection floor of the oil-side coefficients took a constant 7e-4 1/K
    # (OIL_EXPANSION), whatever the oil's thermal_expansion, a second value for one property.
    def h_end(oil):
        case = _case(oil=oil, environment={"shaft_oil_convection": "open",
                                           "sump_temperature": "80 degC"})
        return RotaryModel(case).coefficients(0.0, 353.15)["shaft_end_oil"]  # at rest: free

    default = h_end({"name": "VG68"})
    assert default == h_end({"name": "VG68", "thermal_expansion": f"{0.34878 * 1.8 / 880} 1/K"})
    assert h_end({"name": "VG68", "thermal_expansion": "1.4e-3 1/K"}) > default * 1.05


def test_cli_run_writes_results_and_refuses_overwrite(tmp_path):
    case = tmp_path / "short.toml"
    case.write_text((EXAMPLES / "speed_cycle.toml").read_text().replace(
        'duration = "15 min"', 'duration = "1 min"').replace('duration = "60 min"',
                                                             'duration = "2 min"'))
    runner = CliRunner()
    out = tmp_path / "out"
    result = runner.invoke(app, ["rotary", "run", str(case), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    for name in ("timeseries.csv", "steps.csv", "summary.json", "case_resolved.toml",
                 "cycle_plain.png", "cycle_wave.png", "variants.png", "stribeck.png"):
        assert (out / name).is_file(), name
    summary = json.loads((out / "summary.json").read_text())
    step = summary["variants"]["wave"]["steps"][0]
    assert {"start_s", "end_s", "speed_rpm", "torque_Nm", "power_W", "T_contact_C",
            "T_groove_C", "T_sump_C"} <= set(step)
    assert summary["variants"]["plain"]["energy_balance_rel_error"] < 0.01
    header = (out / "timeseries.csv").read_text().splitlines()[0].split(",")
    assert header[:11] == ["variant", "time_s", "speed_rpm", "torque_Nm", "power_W",
                           "T_contact_C", "T_groove_C", "T_sump_C", "film_um", "F_lub_N",
                           "F_material_N"]
    # the resolved case reproduces the run
    rerun = load_rotary_case(out / "case_resolved.toml")
    assert set(rerun) == {"plain", "wave"} and rerun["wave"].seal.lip_style == "wave"
    assert rerun["plain"].environment.shaft_air_end == "insulated"  # the test-rig set-up
    assert rerun["plain"].seal.radial_force == pytest.approx(float(default_radial_force(0.08)))
    again = runner.invoke(app, ["rotary", "run", str(case), "--out", str(out), "-q"])
    assert again.exit_code == 2 and "--force" in again.output


def test_cli_bad_case_is_one_clear_message(tmp_path):
    case = tmp_path / "bad.toml"
    case.write_text('[seal]\nshaft_diameter = "80 kg"\n[duty]\nsteps = []\n')
    result = CliRunner().invoke(app, ["rotary", "run", str(case), "--out", str(tmp_path / "o")])
    assert result.exit_code == 2
    assert "seal.shaft_diameter" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "o").exists()


def test_duty_steps_with_ramp_interpolate_speed():
    # a step with ramp = 60 s rises linearly from the previous speed, then holds
    case = _case(duty={"steps": [{"speed": "500 rpm", "duration": "2 min"},
                                 {"speed": "1500 rpm", "duration": "3 min", "ramp": "60 s"}]})
    times, speeds, steps = case.duty.profile()
    assert steps == [(0.0, 120.0), (120.0, 300.0)]
    mid_ramp = np.interp(150.0, times, speeds) * 30 / math.pi
    assert mid_ramp == pytest.approx(1000.0)  # halfway between 500 and 1500 rpm
    frame = simulate(case).timeseries
    during = frame[(frame["time_s"] > 120) & (frame["time_s"] < 180)]
    assert len(during) >= 5 and np.all(np.diff(during["speed_rpm"]) > 0)


def test_steady_state_beyond_the_rubber_range_is_refused_in_degrees_celsius():
    # 120 mm at 5500 rpm over an 80 °C sump: the lip would pass 150 °C (157 °C), where the NBR
    # model ends.  The message gives that temperature, the range and a remedy in °C (formerly
    # the first iterate beyond the range stopped the solver with the range in kelvin).  At
    # 5000 rpm it now settles at 149.8 °C, since the oil in the annulus has its own wall
    # layers (test_annulus_correlation_is_across_the_gap_from_shaft_to_bore).
    case = _case(seal={"shaft_diameter": "120 mm"}, environment={"sump_temperature": "80 degC"})
    with pytest.raises(ModelError, match=r"5500 rpm: the contact would run at about 15\d degC "
                       r"\(sump 80 degC\), outside the -125 to 150 degC that the NBR model "
                       r"covers .* try a lower speed or another elastomer"):
        steady_state(case, 5500 * RPM)


@pytest.mark.parametrize(("rpm", "environment", "remedy"), [
    (10000, {}, "a held sump"),                                   # free sump (the app's)
    (1e6, {"sump_temperature": "60 degC"}, "another elastomer"),
])
def test_a_steady_state_that_runs_the_oil_beyond_its_range_is_refused_by_speed(
        rpm, environment, remedy):
    # 80 mm at 10000 rpm with a free sump: the iterates heat the bearing's oil past 700 K on
    # their way, and the oil's viscosity refused 'temperature = 721.841 K' -- no speed, no
    # field the user gave, and the hint 'add 273.15 to degC'.
    case = _case(environment=environment)
    with pytest.raises(ModelError, match=rf"steady state at {rpm:.0f} rpm: none found; .*"
                       r"427 degC, the end of the oil model's range .*NBR: 150 degC\); try "
                       rf"a lower speed.*{remedy}"):
        steady_state(case, rpm * RPM)


@pytest.mark.parametrize(("environment", "field"), [
    ({"sump_temperature": "-20 degC"}, "environment.sump_temperature -20.0 degC"),
    ({"ambient_temperature": "-30 degC"}, "environment.ambient_temperature (the start"),
    ({"start_temperature": "-30 degC"}, "environment.start_temperature -30.0 degC"),
])
def test_a_temperature_below_the_oils_range_names_the_field_it_was_given_in(environment,
                                                                            field):
    # VG 220 mineral is usable down to -15 degC.  The start temperature defaults to the held
    # sump temperature, else the ambient: the message named start_temperature even when the
    # case gave only one of those.
    with pytest.raises(InputError) as info:
        _case(oil={"name": "VG220-mineral"}, environment=environment)
    assert field in str(info.value) and "(-15.0 degC)" in str(info.value)


def test_a_steady_point_does_not_start_so_a_cold_ambient_is_no_start_temperature():
    # Without a duty cycle (lip_seal_torque, steady_state) nothing starts at the ambient: a
    # -30 degC room below VG 68's -24 degC is allowed, and at 1000 rpm the free sump settles
    # well above it.  Before, the case was refused for its "start temperature".
    r = sealsim.lip_seal_torque("80 mm", "1000 rpm", "ISO VG 68",
                                ambient_temperature="-30 degC")
    assert r["T_sump_C"] > -24.0 and r["T_contact_C"] > r["T_sump_C"]
    # at 10 rpm the free sump would settle at -27 degC, below the oil's range: refused with
    # that temperature (before: returned with the viscosity law extrapolated, no note)
    with pytest.raises(ModelError, match=r"free sump would settle at -2\d\.\d degC, below the "
                                         r"lowest usable temperature of VG68-mineral"):
        sealsim.lip_seal_torque("80 mm", "10 rpm", "ISO VG 68", ambient_temperature="-30 degC")
    # a transient run still starts at the ambient and is refused there
    with pytest.raises(InputError, match="ambient_temperature \\(the start"):
        _case(environment={"ambient_temperature": "-30 degC"})


def test_a_sweep_keeps_its_points_when_one_has_no_steady_state():
    # 120 mm in a held 80 degC sump: 5500 rpm would run the contact beyond NBR's 150 degC
    # (157 degC; 5000 rpm settles at 149.8 degC since the annulus's oil has its own wall layers).
    # A sweep returns the other points and a NaN row with the reason (before: the whole
    # sweep raised); a scalar call and a sweep in which no point has one still raise.
    frame = sealsim.lip_seal_torque("120 mm", ["1000 rpm", "5500 rpm"], "ISO VG 68",
                                    sump_temperature="80 degC")
    single = sealsim.lip_seal_torque("120 mm", "1000 rpm", "ISO VG 68",
                                     sump_temperature="80 degC")
    assert frame.loc[0, "torque_Nm"] == single["torque_Nm"]
    assert frame.loc[1, ["torque_Nm", "T_contact_C", "power_W"]].isna().all()
    assert any("1 of 2 points have no steady state" in n and "5500 rpm" in n
               for n in frame.attrs["notes"])
    for speed in ("5500 rpm", ["5500 rpm", "6000 rpm"]):
        with pytest.raises(ModelError, match="5500 rpm: the contact would run at about 15"):
            sealsim.lip_seal_torque("120 mm", speed, "ISO VG 68", sump_temperature="80 degC")


def test_a_sump_cooling_below_the_oils_range_is_noted():
    # Started warm in a -70 degC cold chamber, a 0.2 L sump in a light, fan-cooled housing at
    # 10 rpm cools below VG 68's -24 degC within 30 min; the run says so (before: no note, the
    # viscosity law extrapolated).
    case = _case(environment={"ambient_temperature": "-70 degC", "start_temperature": "20 degC",
                              "sump_volume": "0.2 L", "housing_mass": "0.5 kg",
                              "housing_heat_transfer": "50 W/(m^2*K)"},
                 duty={"steps": [{"speed": "10 rpm", "duration": "30 min"}]})
    result = simulate(case)
    coldest = result.timeseries["T_sump_C"].min()
    assert coldest < -24.0
    assert f"sump cooled to {coldest:.1f} degC, below the lowest usable temperature of " \
           "VG68-mineral (-24.0 degC)" in " ".join(result.notes)


def test_a_contact_beyond_the_fe_lip_table_is_noted():
    # The FE lip table holds its end values outside its temperature grid: a run whose contact
    # leaves the grid says so (speed_cycle_fe reached 148 degC on a table ending at 140 degC,
    # silently).  Checked on operating_notes, the function simulate and lip_seal_torque call,
    # with contacts inside, above and below a 20-100 degC grid; the analytic lip has no grid.
    from sealsim.rotary.simulation import operating_notes

    fe = _case(lip={"force": "fe", "temperatures": ["20 degC", "100 degC"]})
    nbr = get_elastomer("NBR")
    assert not [n for n in operating_notes(fe, nbr, [25.0, 99.9], []) if "FE lip" in n]
    for contact in ([25.0, 112.0], [5.0, 60.0]):
        notes = [n for n in operating_notes(fe, nbr, contact, []) if "FE lip" in n]
        assert len(notes) == 1 and f"{contact[0]:.0f} ... {contact[1]:.0f} degC left the FE " \
            "lip table's 20 ... 100 degC" in notes[0]
    width_only = _case(lip={"contact_width": "fe", "temperatures": ["20 degC", "100 degC"]})
    assert [n for n in operating_notes(width_only, nbr, [25.0, 112.0], []) if "FE lip" in n]
    assert not [n for n in operating_notes(_case(), nbr, [25.0, 112.0], []) if "FE lip" in n]


def test_cold_start_warms_the_contact_without_overshoot():
    # 80 mm NBR lip, VG 68, everything at -20 °C, 1500 rpm: the cold oil's 900 W fall as the
    # contact warms.  Taken at the start of each 0.25 s step the friction overshot (-20 → +70 →
    # -3 → +18 °C); the linearly implicit step warms the contact monotonically and, after 5 s,
    # within 1 K of a run with 100× shorter steps (measured 0.6 K; backward Euler's lag).
    def run(min_step, max_step):
        case = _case(oil={"name": "ISO VG 68"}, environment={"ambient_temperature": "-20 degC"},
                     duty={"steps": [{"speed": "1500 rpm", "duration": "6 s"}]},
                     numerics={"min_time_step": min_step, "max_time_step": max_step})
        return simulate(case).timeseries
    coarse, fine = run("0.25 s", "4 s"), run("0.0025 s", "0.04 s")
    assert np.all(np.diff(coarse["T_contact_C"]) > 0)
    at = np.interp(5.0, fine["time_s"], fine["T_contact_C"])
    assert abs(np.interp(5.0, coarse["time_s"], coarse["T_contact_C"]) - at) < 1.0
