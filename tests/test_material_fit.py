"""Material fits (sealsim material fit): hyperelastic, viscoelastic, thermal; compound files.

References: FElupe's own evaluation of the strain energies, closed-form Drucker matrices,
synthetic data from known parameters (recovered within two standard errors), Treloar's 1944
data (Ogden 1972's result), pyvisco's own shift factors of its example data, the FE force of
the same constants entered by hand.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from sealsim.calibration.hyperelastic_fit import Curve, fit_hyperelastic
from sealsim.calibration.material_fit import fit_expansion, fit_material_file
from sealsim.calibration.viscoelastic_fit import (
    DMAData,
    fit_prony,
    fit_shift_law,
    isotherm_shifts,
    master_curve,
)
from sealsim.errors import InputError
from sealsim.properties.elastomers import CompoundConsistencyWarning, get_elastomer
from sealsim.properties.hyperelastic import MODES, nominal_stress
from sealsim.properties.viscoelasticity import prony_loss_modulus, prony_storage_modulus
from sealsim.structure.hyperelastic import drucker_stable, felupe_nominal_stress

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

PARAMS = {
    "neo_hooke": {"mu": 0.5e6},
    "mooney_rivlin": {"C10": 0.3e6, "C01": 0.08e6},
    "yeoh": {"C10": 0.25e6, "C20": -3e3, "C30": 80.0},
    "ogden": {"mu": [0.4e6, 2e4], "alpha": [1.5, 4.5]},
    "arruda_boyce": {"C1": 0.4e6, "limit": 4.0},
    "third_order_deformation": {"C10": 0.2e6, "C01": 0.02e6, "C11": -200.0, "C20": -2e3,
                                "C30": 60.0},
}


@pytest.mark.parametrize("model", sorted(PARAMS))
def test_closed_form_stresses_are_felupes(model):
    # the fit uses closed forms; the FE uses FElupe's energies: they must be the same law.
    # 1e-9 for invariant models; Ogden through FElupe's eigenvalues, whose automatic
    # derivative at equal stretches (the lateral pair of uniaxial, the equibiaxial pair) is
    # perturbed by tensortrax: 1e-3 there (1e-8 in planar, equal only at λ = 1)
    lam = np.linspace(0.4, 4.0, 25)
    for mode in MODES:
        l = lam if mode == "uniaxial" else lam[lam >= 1.0]
        a = nominal_stress(model, PARAMS[model], mode, l)
        b = felupe_nominal_stress(model, PARAMS[model], mode, l)
        tol = 1e-9 if model != "ogden" else 1e-8 if mode == "planar" else 1e-3
        assert np.max(np.abs(a - b)) <= tol * np.max(np.abs(b)), (model, mode)


def test_drucker_check_against_closed_form_ogden():
    # for Ogden the Drucker matrix in log strains is diagonal, D_ii = sum_k 2 mu_k lam_i^a_k
    # (Ogden 1972): stable where its projection on sum(d eps) = 0 is positive definite
    mu, alpha = [0.5e6, -0.2e6], [2.0, 4.0]
    params = {"mu": mu, "alpha": alpha}
    basis = np.array([[1, -1, 0], [1, 1, -2]]) / np.array([[2 ** 0.5], [6 ** 0.5]])
    from sealsim.properties.hyperelastic import principal_stretches
    for mode in MODES:
        lam = np.linspace(1.0, 2.5, 40)
        got = drucker_stable("ogden", params, mode, lam)
        p = principal_stretches(mode, lam)
        want = []
        for k in range(lam.size):
            d = np.diag([sum(2 * m * p[i, k] ** a for m, a in zip(mu, alpha)) for i in range(3)])
            want.append(np.linalg.eigvalsh(basis @ d @ basis.T).min() > 0)
        assert got.tolist() == want, mode
    assert not all(drucker_stable("ogden", params, "equibiaxial", [2.5]))


def _synthetic(model, params, modes, rng, noise=0.01, points=14):
    curves = []
    for mode in modes:
        lam = np.linspace(1.1, 3.5 if mode == "uniaxial" else 2.5, points)
        p = nominal_stress(model, params, mode, lam)
        curves.append(Curve(mode, mode, lam, p * (1 + noise * rng.standard_normal(lam.size))))
    return curves


@pytest.mark.parametrize("model", ["neo_hooke", "mooney_rivlin", "yeoh", "ogden",
                                   "arruda_boyce"])
def test_synthetic_truth_is_recovered_within_two_standard_errors(model):
    # 1 % relative noise, 12 seeds: a correct standard error puts 95 % of the estimates within
    # 2 s.e.; at least 80 % required (binomial: fewer than 1e-3 false alarms), none beyond 5
    # (Gauss-Newton errors of the nonlinear, correlated Ogden exponents reach 4.2 s.e.)
    rng = np.random.default_rng(20250)
    truth = PARAMS[model]
    flat = np.concatenate([np.ravel(truth[k]) for k in truth])
    inside, total = 0, 0
    for _ in range(12):
        fit = fit_hyperelastic(_synthetic(model, truth, MODES, rng), model,
                               terms=2 if model == "ogden" else None)
        assert fit.identifiable.all(), fit.reasons
        z = np.abs(fit.values - flat) / fit.standard_errors
        assert np.all(z < 5.0), (model, fit.values, fit.standard_errors)
        inside += int(np.sum(z <= 2.0))
        total += z.size
    assert inside / total >= 0.8, (model, inside, total)


def test_a_second_ogden_term_from_uniaxial_data_alone_is_reported_unidentifiable():
    rng = np.random.default_rng(7)
    curves = _synthetic("ogden", {"mu": [0.4e6], "alpha": [2.0]}, ["uniaxial"], rng,
                        noise=0.005)
    fit = fit_hyperelastic(curves, "ogden2")
    assert not fit.identifiable.all()
    assert any("not identifiable" in n for n in fit.notes)
    report = fit.report()["parameters"]
    assert any(not p["identifiable"] for p in report.values())
    # while one term on the same data is determined
    assert fit_hyperelastic(curves, "ogden1").identifiable.all()


def test_a_modulus_on_its_bound_is_reported():
    # uniaxial curves whose best Mooney-Rivlin has C10 < 0 (P = 2(λ − λ⁻²)(C10 + C01/λ) with
    # C10 = −0.05 MPa, C01 = 0.5 MPa): the fit stops on the bound C10 >= 0 (least_squares'
    # trf stops within its tolerance inside the bounds: 1e-20 Pa with one scipy, 1.1e-6 Pa
    # with scipy 1.17; the fit calls a value within 1e-6 MPa = 1 Pa of a bound "on" it).  It
    # was reported as a value with a standard error of 0.014 MPa, "not identifiable" because
    # that error exceeds the value -- as if more data would determine it
    lam = np.linspace(1.05, 2.5, 15)
    curve = Curve("ut", "uniaxial", lam, 2 * (lam - lam ** -2) * (-0.05e6 + 0.5e6 / lam))
    fit = fit_hyperelastic([curve], "mooney_rivlin")
    report = fit.report()["parameters"]
    assert abs(report["C10"]["value"]) <= 1.0            # Pa, of a 0.5 MPa modulus
    assert report["C10"]["at_limit"] == "lower bound 0 MPa"
    assert report["C10"]["stderr"] is None and not report["C10"]["identifiable"]
    assert report["C01"]["at_limit"] is None           # unbounded: never "on its bound"
    assert any(n.startswith("C10 sits on its lower bound 0 MPa: the best mooney_rivlin lies "
                            "beyond what the model allows") for n in fit.notes)
    # a curve the model can follow has no limit
    ok = Curve("ut", "uniaxial", lam, 2 * (lam - lam ** -2) * (0.15e6 + 0.2e6 / lam))
    assert fit_hyperelastic([ok], "mooney_rivlin").limits == [None, None]


def test_bad_curves_are_refused():
    with pytest.raises(InputError, match=r"stretch 101 is beyond 20.*unit '%'"):
        Curve("u", "uniaxial", np.array([1.0, 11.0, 51.0, 101.0]),   # strains in % as '1'
              np.array([0.0, 0.5e6, 1.5e6, 2.2e6]))
    with pytest.raises(InputError, match="tension test"):
        Curve("x", "equibiaxial", np.array([0.9, 1.1]), np.array([-1.0, 1.0]))
    with pytest.raises(InputError, match="mode"):
        Curve("x", "shear", np.array([1.1, 1.2]), np.array([1.0, 2.0]))


@pytest.fixture(scope="module")
def treloar():
    return fit_material_file(EXAMPLES / "materials" / "treloar_ogden.toml")


def test_treloar_ogden3_follows_all_three_modes(treloar):
    # Ogden (1972): three terms follow Treloar's three modes. Target 5 % RMS relative error:
    # met beyond 5 % strain on all three; with the first point of each curve (λ <= 1.03,
    # where a stretch reading error of 0.005 is 17 % of λ − 1) equibiaxial and planar give
    # 7.0 % and 9.0 % (the three modes' smallest-strain points imply initial moduli 30 %
    # apart; no smooth energy meets them all) -- pinned here so a worse fit fails
    modes = treloar.report["modes"]
    for mode in MODES:
        assert modes[mode]["role"] == "fit"
        assert modes[mode]["rel_rmse_beyond_small_strain"] <= 0.05, mode
    assert modes["uniaxial"]["rel_rmse"] <= 0.051
    assert modes["equibiaxial"]["rel_rmse"] <= 0.071
    assert modes["planar"]["rel_rmse"] <= 0.091
    assert treloar.hyperelastic.label == "ogden3"
    # Ogden's classic exponents: one near 1.3, one near 5, one negative near -2
    alpha = sorted(treloar.hyperelastic.parameters["alpha"])
    assert alpha[0] < -1.0 and 1.0 < alpha[1] < 1.6 and 4.0 < alpha[2] < 6.0


def test_treloar_ogden3_is_as_close_as_ogdens_own_1972_constants(treloar):
    # the published fit (Ogden 1972, Proc. R. Soc. A 326, 565: mu = 0.63, 0.0012, -0.01 MPa,
    # alpha = 1.3, 5.0, -2.0 in W = sum mu_p/alpha_p (l1^a + l2^a + l3^a - 3)) evaluated here
    # in closed form, independent of FElupe: on all points it gives 7.2 / 7.5 / 8.9 % RMS
    # relative error, so the 5 % on every point of every mode is not met by Ogden's own
    # constants either; sealsim's fit must be at least as close in every mode (+0.2 points:
    # the optimiser's tolerance)
    mu = np.array([0.63e6, 0.0012e6, -0.01e6])
    alpha = np.array([1.3, 5.0, -2.0])
    lateral = {"uniaxial": -alpha / 2, "equibiaxial": -2 * alpha, "planar": -alpha}
    files = {"uniaxial": "uniaxial.csv", "equibiaxial": "equibiaxial.csv",
             "planar": "pure_shear.csv"}
    kgf_cm2 = 98066.5
    for mode in MODES:
        data = np.loadtxt(EXAMPLES / "materials" / "data" / "treloar_1944" / files[mode],
                          delimiter=",", skiprows=2)
        lam, measured = data[data[:, 0] > 1.0].T
        ogden = (mu * (lam[:, None] ** (alpha - 1)
                       - lam[:, None] ** (lateral[mode] - 1))).sum(axis=1)
        rel = ogden / (measured * kgf_cm2) - 1.0
        published = float(np.sqrt(np.mean(rel ** 2)))
        assert 0.07 < published < 0.09, (mode, published)     # the reference reproduced
        assert treloar.report["modes"][mode]["rel_rmse"] <= published + 0.002, mode


def test_treloar_mooney_rivlin_from_uniaxial_misses_equibiaxial(treloar):
    cmp = treloar.report["comparisons"]["mooney_rivlin (uniaxial)"]
    assert cmp["modes"]["uniaxial"]["role"] == "fit"
    assert cmp["modes"]["equibiaxial"]["role"] == "validate"
    assert cmp["modes"]["equibiaxial"]["rel_rmse"] > 1.0   # predicted, off by > 100 %
    # and the report says where it is unstable (C01 < 0 from uniaxial data)
    unstable = treloar.report["unstable_models"]["mooney_rivlin (uniaxial)"]
    assert unstable["equibiaxial"]["stable_to"] < 1.5
    assert "ogden3" not in treloar.report["unstable_models"]


def test_report_has_the_shape_of_the_issue(treloar):
    r = treloar.report
    assert set(r) >= {"model", "parameters", "modes"}
    for p in r["parameters"].values():
        assert {"value", "stderr"} <= set(p)
    for m in r["modes"].values():
        assert {"rel_rmse", "r2"} <= set(m)


def test_compound_file_round_trips_and_names_its_sources(treloar, tmp_path):
    path = tmp_path / "treloar_nr.toml"
    path.write_text(treloar.compound_text)
    e = get_elastomer(str(path))
    assert e.hyperelastic[0] == "ogden"
    mu = dict(e.hyperelastic[1])["mu"]
    assert mu == pytest.approx(treloar.hyperelastic.parameters["mu"], rel=1e-7)
    assert 2 * (e.c10 + e.c01) == pytest.approx(sum(mu), rel=1e-7)
    assert "catalogue NBR [L]" in treloar.compound_text
    assert "fitted by sealsim material fit" in treloar.compound_text


# -- viscoelastic ------------------------------------------------------------------------------

def _dma_truth(rng, noise=0.005):
    t_ref, c1, c2 = 296.15, 8.86, 101.6
    tau = 10.0 ** np.arange(-9.0, 4.01, 0.5)
    e_i = 40e6 * np.exp(-0.5 * ((np.log10(tau) + 3.0) / 2.0) ** 2)
    e_inf = 3e6
    temps = np.arange(253.15, 354.0, 10.0)
    f = np.logspace(-1, 2, 10)
    T, F = np.repeat(temps, f.size), np.tile(f, temps.size)
    log_a = -c1 * (T - t_ref) / (c2 + T - t_ref)
    w = 2 * np.pi * F * 10 ** log_a
    e1 = prony_storage_modulus(w, e_inf, e_i, tau) * (1 + noise * rng.standard_normal(T.size))
    e2 = prony_loss_modulus(w, e_inf, e_i, tau) * (1 + noise * rng.standard_normal(T.size))
    return DMAData(T, F, e1, e2), (c1, c2, t_ref)


def test_wlf_fit_recovers_c1_c2_within_two_standard_errors():
    # shift factors with stated standard errors (0.05 decades) around the true WLF law
    t_ref, c1, c2 = 296.15, 8.86, 101.6
    temps = np.arange(253.15, 354.0, 10.0)
    hits, total = 0, 0
    for seed in range(20):
        rng = np.random.default_rng(seed)
        log_a = -c1 * (temps - t_ref) / (c2 + temps - t_ref) + 0.05 * rng.standard_normal(
            temps.size) + 0.7
        fit = fit_shift_law(temps, log_a, np.full(temps.size, 0.05), t_ref, "wlf")
        for name, true in (("c1", c1), ("c2", c2)):
            z = abs(fit.parameters[name] - true) / fit.standard_errors[name]
            assert z < 4.0, (seed, name)
            hits += z <= 2.0
            total += 1
    assert hits / total >= 0.8


def test_superposition_of_synthetic_dma_finds_the_wlf_law():
    # the whole path (shift factors found from the data, then WLF) recovers C1 and C2 within
    # two standard errors: 20 noisy data sets, at least 80 % of the estimates within 2 s.e.
    # (measured 100 %; 98 % over 30 seeds), none beyond 3, and within 3 % of the truth.  The
    # law is fitted to the pairwise increments (independent); fitted to the cumulative shifts
    # as if they were independent, the same data gave 22 % within 2 s.e., |z| up to 11 and a
    # bias of -1 to -2 s.e. (the random-walk correlation of sums of pairwise shifts)
    hits, total = 0, 0
    for seed in range(20):
        data, (c1, c2, t_ref) = _dma_truth(np.random.default_rng(seed))
        temps, log_a, se = isotherm_shifts(data)
        fit = fit_shift_law(temps, log_a, se, t_ref, "wlf", cumulative=True)
        for name, true in (("c1", c1), ("c2", c2)):
            assert fit.parameters[name] == pytest.approx(true, rel=0.03), (seed, name)
            z = abs(fit.parameters[name] - true) / fit.standard_errors[name]
            assert z < 3.0, (seed, name, z)
            hits += z <= 2.0
            total += 1
    assert hits / total >= 0.8, (hits, total)


def test_wlf_with_an_arrhenius_branch_below_tg_is_recovered_where_plain_wlf_misses():
    # Shift factors that follow WLF above T_g and, below it, the Arrhenius continuation with
    # the WLF's value and slope at T_g (Ferry 1980, ch. 11; the law a compound evaluates),
    # written out here: log a = y_g + B (1/T - 1/T_g), B = C1 C2 T_g^2 / (C2 + T_g - T_r)^2.
    t_ref, c1, c2, tg = 373.15, 8.0, 120.0, 330.0
    temps = np.arange(223.15, 374.0, 7.5)
    d_g = tg - t_ref
    b = c1 * c2 * tg ** 2 / (c2 + d_g) ** 2
    d = np.where(temps >= tg, temps - t_ref, d_g)        # the WLF branch only above T_g
    log_a = np.where(temps >= tg, -c1 * d / (c2 + d),
                     -c1 * d_g / (c2 + d_g) + b * (1 / temps - 1 / tg))
    se = 0.01 * np.sqrt(np.arange(temps.size) + 1.0)
    fit = fit_shift_law(temps, log_a, se, t_ref, "wlf", cumulative=True, arrhenius_below=tg)
    assert fit.parameters["c1"] == pytest.approx(c1, rel=1e-4)
    assert fit.parameters["c2"] == pytest.approx(c2, rel=1e-4)
    assert np.max(np.abs(fit.log10_shift(temps) - log_a)) < 1e-3        # decades
    # a WLF at every temperature cannot follow the kink of the slope's curvature at T_g:
    # 1.0 decade off just below it
    plain = fit_shift_law(temps, log_a, se, t_ref, "wlf", cumulative=True)
    assert np.max(np.abs(plain.log10_shift(temps) - log_a)) > 0.5
    with pytest.raises(InputError, match="arrhenius_below"):
        fit_shift_law(temps, log_a, se, t_ref, "arrhenius", cumulative=True,
                      arrhenius_below=tg)


def test_prony_from_synthetic_master_curve():
    # the Prony series of the superposed synthetic data: E_inf within 2 s.e., E' within 2 %
    # and E'' within 4 % (noise 0.5 %; the rest is the shift factors' systematic error),
    # smooth, no ripple
    data, (c1, c2, t_ref) = _dma_truth(np.random.default_rng(3))
    temps, log_a, se = isotherm_shifts(data)
    shift = fit_shift_law(temps, log_a, se, t_ref, "wlf")
    f_r, e1, e2 = master_curve(data, shift)
    prony = fit_prony(f_r, e1, e2, terms_per_decade=2)
    assert prony.smooth and prony.ripple <= 0.01
    assert prony.rel_rmse["storage"] < 0.02 and prony.rel_rmse["loss"] < 0.04
    assert abs(prony.equilibrium_modulus - 3e6) <= 2 * prony.standard_errors[0]


def test_bilinear_dilatometry_is_recovered_within_two_standard_errors():
    rng = np.random.default_rng(11)
    T = np.linspace(180.0, 300.0, 49)
    eps = np.where(T < 228.0, 7e-5 * (T - 228.0), 2.1e-4 * (T - 228.0))
    fit = fit_expansion(T, eps + 2e-5 * rng.standard_normal(T.size))
    for name, true in (("glass_transition", 228.0), ("rubbery", 2.1e-4), ("glassy", 7e-5)):
        assert abs(getattr(fit, name) - true) <= 2.5 * fit.standard_errors[name], name


# pyvisco 2.1.3, pyvisco.master.get_aT on examples/freq_user_raw.csv with RefT = -5 degC
# (run once outside CI with pyvisco installed; its power-law pairwise shifts)
PYVISCO_LOG_AT = {-50: 10.236, -42: 9.363, -35: 7.840, -27: 6.095, -20: 4.264, -12: 1.990,
                  -5: 0.0, 3: -1.911, 10: -3.409, 18: -5.033, 25: -6.689, 32: -8.445,
                  40: -10.305, 47: -12.101, 55: -13.425, 62: -14.511, 70: -15.457,
                  77: -16.306, 85: -17.067, 92: -17.750, 100: -18.345}


@pytest.fixture(scope="module")
def pyvisco_fit():
    return fit_material_file(EXAMPLES / "materials" / "pyvisco_dma.toml")


def test_pyvisco_dma_shift_factors_match_pyvisco(pyvisco_fit):
    # an independent implementation of the same pairwise shifting: within 0.25 decades from
    # -5 degC up (measured: 0.12 at most); in the glass below -5 degC the storage modulus is
    # nearly flat and each shift is an extrapolation (measured difference up to 1.6 decades
    # at -50 degC, within the combined standard errors there)
    data = pyvisco_fit.dma
    temps, log_a, se = isotherm_shifts(data)
    ref = np.interp(273.15 - 5.0, temps, log_a)
    for (t_c, theirs), ours, s in zip(PYVISCO_LOG_AT.items(), log_a - ref, se):
        if t_c >= -5:
            assert abs(ours - theirs) <= 0.25, (t_c, ours, theirs)
        else:
            assert abs(ours - theirs) <= 2.0, (t_c, ours, theirs)


def test_pyvisco_dma_fit_report(pyvisco_fit):
    r = pyvisco_fit.report
    assert r["modes"]["dma"]["rel_rmse"] < 0.08      # E' (measured 6.8 %)
    assert r["viscoelastic"]["prony_smooth"]
    # tan delta peak at 1 Hz from the isotherms: the raw data peak lies between the 70 and
    # 77.5 degC isotherms (0.335 and 0.342)
    assert 70.0 < r["viscoelastic"]["tan_delta_peak_temperature_K"] - 273.15 < 80.0
    assert "wlf_c1" in r["parameters"] and "prony_E_inf" in r["parameters"]


def test_pyvisco_dma_master_curve_is_at_its_reference_temperature(pyvisco_fit):
    # The measured shifts are referred to their own value at T_r = 100 degC (an isotherm at
    # 99.99 degC): the master curve at T_r holds that isotherm unshifted and the WLF law, 0 at
    # T_r by definition, meets it.  They were pinned near the coldest isotherm instead, 0.82
    # decades off at T_r, so the compound (Prony series + WLF) missed its own data by 27 % RMS
    # in E' (35 % at 100 degC) while the report gave the 6.9 % of the series on the master
    # curve.
    shift = pyvisco_fit.shift
    assert abs(np.interp(shift.reference_temperature, shift.temperatures,
                         shift.log_shift)) < 0.01
    # their errors too: the sums of the pairwise increments to T_r (the random walk from the
    # coldest isotherm, reversed): 0 at 100 degC, largest at -50 degC
    assert shift.log_shift_stderr[-1] == 0.0
    assert shift.log_shift_stderr[0] == pytest.approx(np.max(shift.log_shift_stderr))
    dma = pyvisco_fit.report["modes"]["dma"]
    # the series moved by the fitted law on every measured point: 8.3 %, against 6.9 % of the
    # series on the master curve (the law misses the glassy shifts, where E' is nearly flat)
    assert dma["rel_rmse"] <= dma["rel_rmse_law"] < 0.10
    assert dma["rel_rmse_loss_law"] > dma["rel_rmse_loss"]   # E'' does not superpose


def test_pyvisco_compound_evaluates_the_fitted_shift_law(pyvisco_fit, tmp_path):
    # The compound evaluates WLF above its T_g (here the tan delta peak, 74.7 degC) and the
    # slope-continuous Arrhenius branch below.  The law was fitted as a WLF at every
    # temperature: the compound's shift at -50 degC was 24.0 decades against the fitted
    # law's 30.3 and the measured 27.2 (5.2 decades low at -20 degC), and the report's errors
    # were those of a law the compound does not use.  Now the fit is the compound's law.
    shift = pyvisco_fit.shift
    compound = _written_compound(pyvisco_fit, tmp_path)
    assert shift.arrhenius_below == pytest.approx(compound.glass_transition)
    t = shift.temperatures
    ours = np.asarray(compound._log10_shift(t)) - float(compound._log10_shift(
        np.asarray(shift.reference_temperature)))
    # (to 1e-3 decades: the file gives T_g to 6 digits, 74.6911 degC)
    assert np.max(np.abs(ours - shift.log10_shift(t))) < 1e-3
    # the remaining miss (measured: 1.9 decades at -20 degC, 1.75 at -50 degC, 0.05 above
    # T_g): below ~0 degC E' is nearly flat and the pairwise shifts are extrapolations
    # (pyvisco's own differ from ours by up to 1.6 decades there, see above)
    miss = np.abs(shift.log10_shift(t) - shift.log_shift)
    assert np.max(miss) < 2.0
    assert np.max(miss[t >= shift.arrhenius_below]) < 0.1


def test_pyvisco_compound_follows_its_own_dma_data(pyvisco_fit, tmp_path):
    # The compound's E'(T, f) -- its master-curve sigmoid moved by its shift law, what the
    # lip force, the O-ring maps and the heat model use -- against every measured point,
    # evaluated here through the written file.  The sigmoid was fitted to the Prony series
    # over its relaxation times (32 decades, most beyond the data) and the law was a WLF the
    # compound does not evaluate below T_g: 12.0 % RMS, 23.7 % on the 40 degC isotherm, the
    # 100 degC isotherm 9.5 % high (10.1 % RMS).  Now 6.4 %; at 100 degC 1 % high on
    # average but still 10.5 % RMS, from -19 % at 0.1 Hz to +12 % at 22 Hz: the Richards
    # sigmoid sits at its asymmetry bound (nu = 0.05) and cannot follow both the 30-decade
    # transition and the steep rubbery end of this polymer (the Prony series: 3.1 % there);
    # a model-form limit, reported, not hidden.
    compound = _written_compound(pyvisco_fit, tmp_path)
    data = pyvisco_fit.dma
    rel = np.asarray(compound._modulus(data.temperature, data.frequency)) / data.storage - 1
    assert np.sqrt(np.mean(rel ** 2)) < 0.07
    per = [np.sqrt(np.mean(rel[g] ** 2)) for g in data.isotherms()]
    assert max(per) < 0.12
    hot = data.isotherms()[-1]                                   # 100 degC = T_r
    assert abs(np.mean(rel[hot])) < 0.03
    dma = pyvisco_fit.report["modes"]["dma"]
    assert dma["rel_rmse_compound"] == pytest.approx(np.sqrt(np.mean(rel ** 2)), rel=1e-9)
    factors = pyvisco_fit.report["viscoelastic"]["shift_factors"]
    assert [f["storage_rel_rmse_compound"] for f in factors] == pytest.approx(per)


def test_a_rubbers_dma_in_its_service_range_gives_back_its_modulus_curve(tmp_path):
    # Synthetic DMA of the catalogue NBR (its Prony series moved by its own shift law, the
    # plateau times T/T_p, as the catalogue defines it): isotherms -20 ... 100 degC, 0.1-100
    # Hz, the glass not reached -- a seal rubber measured in its service range.  The compound
    # follows these points within 3.1 % RMS, 3.7 % on every isotherm.  Its sigmoid was fitted
    # to the Prony series, whose E_inf takes up the warm isotherms' entropic rise (the master
    # curve is shifted along log f only) and was then multiplied by T/T_ref once more: 14.7 %
    # RMS, 27 % high at 100 degC.  Fitted to the measured points alone the glassy modulus is
    # free (250 GPa): it comes from the series.
    nbr = get_elastomer("NBR")
    e_inf, e_i, tau = nbr.prony
    t_p = nbr.prony_reference_temperature
    temps = np.repeat(np.arange(-20.0, 101.0, 10.0) + 273.15, 10)
    f = np.tile(np.logspace(-1, 2, 10), 13)
    w = 2 * np.pi * f * 10.0 ** (np.asarray(nbr.log10_shift_factor(temps))
                                 - nbr.log10_shift_factor(t_p))
    e1 = prony_storage_modulus(w, 0.0, e_i, tau) + e_inf * temps / t_p
    e2 = prony_loss_modulus(w, e_inf, e_i, tau)
    (tmp_path / "dma.csv").write_text("f,T,E1,E2\n" + "".join(
        f"{a:.10g},{b:.10g},{c:.10g},{d:.10g}\n" for a, b, c, d in zip(f, temps, e1, e2)))
    (tmp_path / "fit.toml").write_text(
        '[compound]\nname = "syn"\nbase = "NBR"\nreference_temperature = "23 degC"\n'
        '[[viscoelastic.files]]\nfile = "dma.csv"\ndelimiter = ","\nheader = true\n'
        'columns = { frequency = { column = "f", unit = "Hz" }, temperature = { column = "T", '
        'unit = "K" }, storage_modulus = { column = "E1", unit = "Pa" }, loss_modulus = { '
        'column = "E2", unit = "Pa" } }\n')
    fit = fit_material_file(tmp_path / "fit.toml")
    compound = _written_compound(fit, tmp_path)
    rel = np.asarray(compound._modulus(temps, f)) / e1 - 1
    assert np.sqrt(np.mean(rel ** 2)) < 0.04
    assert max(np.sqrt(np.mean(rel[g] ** 2)) for g in fit.dma.isotherms()) < 0.05
    assert compound.glassy_modulus < 1e10                       # 2.9 GPa (NBR: 2 GPa)
    assert fit.report["modes"]["dma"]["rel_rmse_compound"] == pytest.approx(
        np.sqrt(np.mean(rel ** 2)), rel=1e-9)
    # what the seal models take from it: the 1 Hz modulus within 6 % of NBR's and the held
    # seal's modulus (lip force, O-ring maps) within 11 % at 20, 60, 100 degC (measured -3 to
    # -6 % and -9 to -10 %; with the old fit +18, +34, +40 %: the speed cycle's torque of
    # examples/rotary/speed_cycle.toml came out 0.437 N m against NBR's 0.345, now 0.336)
    t = np.array([20.0, 60.0, 100.0]) + 273.15
    assert compound.modulus(t) == pytest.approx(nbr.modulus(t), rel=0.06)
    assert compound.held_modulus(t) == pytest.approx(nbr.held_modulus(t), rel=0.11)


def _written_compound(fit, tmp_path):
    path = tmp_path / "compound.toml"
    path.write_text(fit.compound_text)
    with warnings.catch_warnings():
        warnings.simplefilter("error", CompoundConsistencyWarning)   # loads without the note
        return get_elastomer(str(path))


def test_written_compounds_constants_and_curve_agree(treloar, pyvisco_fit, tmp_path):
    # A held seal's stiffness is the constants times E_h(T)/E(T_ref, f_test) of the curve.
    # DMA only: the constants are the fitted curve at (T_ref, f_test), 288 MPa for pyvisco's
    # polymer at 100 degC and 1 Hz (measured 296 MPa; they were E_inf = 212 MPa, counting the
    # relaxation twice, 408 MPa while the master curve was not at T_r and 327 MPa while the
    # curve was fitted to the Prony series instead of the measured points).
    # Tensile curves on a catalogue base: the base's curve moved with T_g gets the rubbery
    # plateau that passes through the constants' modulus (the plateau ratio alone left the
    # Treloar compound's curve 33 % off).  Both to the root finder's precision.
    dma_only = _written_compound(pyvisco_fit, tmp_path)
    assert abs(dma_only.constants_modulus_mismatch()) < 1e-6
    assert 6 * (dma_only.c10 + dma_only.c01) == pytest.approx(288e6, rel=0.01)
    tensile = _written_compound(treloar, tmp_path)
    assert abs(tensile.constants_modulus_mismatch()) < 1e-6
    assert tensile.glassy_modulus == pytest.approx(2e9)       # the base's glass, unchanged


def test_hardness_alone_is_the_gent_fallback_and_says_so(tmp_path):
    (tmp_path / "h.toml").write_text(
        'title = "hardness only"\n[compound]\nname = "h70"\nbase = "NBR"\n'
        'reference_temperature = "23 degC"\nhardness_shore_a = 70\n')
    r = fit_material_file(tmp_path / "h.toml")
    assert "FALLBACK: Gent's Shore A relation" in r.compound_text
    assert any("weakest" in n for n in r.notes)
    from sealsim.properties.rubber_modulus import shore_a_young_modulus
    e = r.compound_table
    assert e["c10"].endswith("MPa")
    c10 = float(e["c10"].split()[0]) * 1e6
    assert 6 * c10 * 1.25 == pytest.approx(float(shore_a_young_modulus(70)), rel=1e-6)


# -- end to end: FE of a fitted compound ------------------------------------------------------

# 12 squeeze increments, not 4: a 2.5 % squeeze step fails Newton on this coarse ring and the
# solver goes on at the halved size until it lands on the nominal grid again (4 nominal
# increments became 60, 222 Newton iterations; 12 take 23 increments, 96 iterations).  The
# Ogden run (tensortrax's energy, ~6x the neo-Hookean's cost per iteration) took 19.7 s of
# CPU instead of 8.3 s; the 10 % squeeze end state is the same within 0.02 % (F_N 19.286 ->
# 19.282 N Ogden, 19.428 -> 19.423 N neo-Hookean, their ratio 0.99272 both ways).
STRUCTURE = """
[seal]
cord_diameter = "4 mm"
inner_diameter = "20 mm"
[gland]
arrangement = "rod"
sealing_diameter = "20 mm"
groove_width = "5.4 mm"
[mesh]
level = "coarse"
[load]
installation_temperature = "23 degC"
squeeze = [0.10]
squeeze_increments = 12
"""


def test_fitted_compound_gives_the_fe_force_of_the_same_constants_by_hand(tmp_path):
    from sealsim.structure.case import load_structure_cases
    from sealsim.structure.run import run_case

    rng = np.random.default_rng(5)
    curves = _synthetic("mooney_rivlin", {"C10": 0.9e6, "C01": 0.2e6}, ["uniaxial"], rng)
    rows = "\n".join(f"{l:.17g},{p:.17g}" for l, p in zip(curves[0].stretch, curves[0].stress))
    (tmp_path / "ut.csv").write_text("stretch,stress_Pa\n" + rows + "\n")
    (tmp_path / "fit.toml").write_text(
        '[compound]\nname = "my_nbr"\nbase = "NBR"\nreference_temperature = "23 degC"\n'
        'bulk_modulus = "2000 MPa"\nthermal_expansion = "2e-4 1/K"\n'
        '[hyperelastic]\nmodel = "mooney_rivlin"\n[[hyperelastic.curves]]\nname = "ut"\n'
        'mode = "uniaxial"\nfile = "ut.csv"\ndelimiter = ","\nheader = true\n'
        'columns = { stretch = { column = "stretch", unit = "1" }, '
        'stress = { column = "stress_Pa", unit = "Pa" } }\n')
    result = fit_material_file(tmp_path / "fit.toml")
    (tmp_path / "my_nbr.toml").write_text(result.compound_text)
    c10, c01 = (result.hyperelastic.parameters[k] for k in ("C10", "C01"))
    # the same temperature law on both sides: a named compound defaults to the held-seal
    # modulus (its master curve's relaxation after an hour, about half the test-frequency
    # constants), which a rubber given only by its constants cannot have
    (tmp_path / "fitted.toml").write_text(STRUCTURE + '[material]\nelastomer = "my_nbr.toml"\n'
                                          'temperature_scaling = "entropic"\n')
    (tmp_path / "by_hand.toml").write_text(
        STRUCTURE + f'[material]\nc10 = "{c10!r} Pa"\nc01 = "{c01!r} Pa"\n'
        'bulk_modulus = "2000 MPa"\nthermal_expansion = "2e-4 1/K"\n'
        'temperature_scaling = "entropic"\n')
    forces = []
    for name in ("fitted.toml", "by_hand.toml"):
        case = next(iter(load_structure_cases(tmp_path / name).values()))
        forces.append(np.array([s.F_N for s in run_case(case).states]))
    assert forces[0] == pytest.approx(forces[1], rel=1e-9, abs=0.0)


def _uniaxial_fit_file(folder, rows: str, deformation: tuple[str, str], stress_unit: str):
    """A Mooney-Rivlin fit file on one uniaxial curve ``rows`` (CSV below the header
    ``<deformation column>,stress``) on the catalogue NBR."""
    column, unit = deformation
    (folder / "u.csv").write_text(f"{column},stress\n{rows}")
    (folder / "fit.toml").write_text(
        '[compound]\nname = "my_nbr"\nbase = "NBR"\nreference_temperature = "23 degC"\n'
        '[hyperelastic]\nmodel = "mooney_rivlin"\n[[hyperelastic.curves]]\nname = "u"\n'
        'mode = "uniaxial"\nfile = "u.csv"\ndelimiter = ","\nheader = true\n'
        f'columns = {{ {column} = {{ column = "{column}", unit = "{unit}" }}, '
        f'stress = {{ column = "stress", unit = "{stress_unit}" }} }}\n')
    return folder / "fit.toml"


def test_a_decimal_comma_table_fits_as_its_decimal_point_original(tmp_path):
    # the reader's hint for '1,5' ("set decimal = ','") led to "decimal: unknown field" in a
    # material fit file: a German lab's DMA or tensile export could not be read at all
    rows = "1.0,0\n1.2,0.31\n1.5,0.62\n2.0,0.98\n2.5,1.29\n"
    original = fit_material_file(_uniaxial_fit_file(tmp_path, rows, ("stretch", "1"), "MPa"))
    german = tmp_path / "de"
    german.mkdir()
    path = _uniaxial_fit_file(german, rows, ("stretch", "1"), "MPa")
    table = german / "u.csv"
    table.write_text(table.read_text().replace(",", ";").replace(".", ","))
    path.write_text(path.read_text().replace('delimiter = ","', 'delimiter = ";"\ndecimal = ","'))
    fitted = fit_material_file(path)
    # the same numbers in another notation: the same fit to the last bit
    assert fitted.hyperelastic.parameters == original.hyperelastic.parameters


def test_a_curve_that_fits_no_rubber_is_an_input_error_naming_the_wrong_point(tmp_path):
    # a negative stress in tension (a sign slip in one row) gave Mooney-Rivlin a negative
    # initial shear modulus and the compound writer a traceback ('math domain error')
    path = _uniaxial_fit_file(tmp_path, "1.0,0\n1.5,-0.5\n2.0,0.8\n2.5,1.2\n", ("stretch", "1"),
                              "MPa")
    with pytest.raises(InputError, match=r"initial shear modulus of -[\d.]+ MPa \(<= 0\).*"
                                         r"curve 'u' at stretch 1.5: -0.5 MPa"):
        fit_material_file(path)


def test_dma_temperatures_in_celsius_read_as_kelvin_are_refused_naming_the_unit():
    # pyvisco's -50 ... 100 degC isotherms with the column's unit given as K: the fit ran and
    # failed only at the written compound ('glass_transition = 74.691 K is not allowed')
    f = np.full(3, 1.0)
    with pytest.raises(InputError, match=r"temperature of point 1 is -50 K .* outside 100-800 K"
                                         r".*check the temperature column's unit"):
        DMAData(np.array([-50.0, 20.0, 100.0]), f, f * 1e6, f * 1e5)


def test_dma_moduli_in_mpa_read_as_pa_are_refused_naming_the_unit():
    # a rubber's 4.5 ... 1000 MPa with the column's unit given as Pa: the fit ended in a
    # scipy traceback ('Each lower bound must be strictly less than each upper bound')
    t, f = np.array([250.0, 260.0, 270.0]), np.full(3, 1.0)
    with pytest.raises(InputError, match=r"storage modulus of point 2 is 4.5 Pa, outside "
                                         r"10000-1e\+11 Pa .* check the modulus column's unit"):
        DMAData(t, f, np.array([1e7, 4.5, 1e6]), f * 1e5)


def test_a_curve_too_soft_for_the_base_rubber_names_the_stress_unit(tmp_path):
    # stresses of a rubber written in kPa instead of MPa: E = 6 kPa, below any plateau the
    # base's master curve can be moved to; was a traceback of brentq ('f(a) and f(b) must
    # have different signs')
    path = _uniaxial_fit_file(tmp_path, "0,0\n10,0.5\n50,1.5\n100,2.2\n", ("strain", "%"),
                              "kPa")
    with pytest.raises(InputError, match=r"Young's modulus 0.0057\d* MPa at 23 degC is beyond "
                                         r"what the master curve of compound.base NBR .*"
                                         r"stress unit"):
        fit_material_file(path)


def test_ogden_compound_runs_in_the_fe(treloar, tmp_path):
    # FElupe's Ogden energy in the seal FE; at 10 % squeeze the force is that of a
    # neo-Hookean ring of the same initial shear modulus within 15 % (Ogden-3 of Treloar is
    # nearly neo-Hookean at these strains)
    from sealsim.structure.case import load_structure_cases
    from sealsim.structure.run import run_case

    (tmp_path / "nr.toml").write_text(treloar.compound_text)
    mu0 = treloar.hyperelastic.initial_shear_modulus
    # (the same temperature law on both sides, as above)
    (tmp_path / "ogden.toml").write_text(
        STRUCTURE.replace("23 degC", "20 degC") + '[material]\nelastomer = "nr.toml"\n'
        'temperature_scaling = "entropic"\n')
    (tmp_path / "neo.toml").write_text(
        STRUCTURE.replace("23 degC", "20 degC")
        + f'[material]\nc10 = "{mu0 / 2!r} Pa"\nc01 = "0 Pa"\nbulk_modulus = "2000 MPa"\n'
        'thermal_expansion = "1.9e-4 1/K"\n')
    f = [run_case(next(iter(load_structure_cases(tmp_path / n).values()))).states[-1].F_N
         for n in ("ogden.toml", "neo.toml")]
    assert f[0] == pytest.approx(f[1], rel=0.15)


# -- command line -----------------------------------------------------------------------------

def test_cli_material_fit_writes_the_folder_and_show_reads_the_compound(tmp_path):
    from typer.testing import CliRunner

    from sealsim.cli import app

    out = tmp_path / "treloar"
    runner = CliRunner()
    res = runner.invoke(app, ["material", "fit",
                              str(EXAMPLES / "materials" / "treloar_ogden.toml"),
                              "--out", str(out)])
    assert res.exit_code == 0, res.output
    names = {p.name for p in out.iterdir()}
    assert {"treloar_nr.toml", "report.json", "curves.csv", "hyperelastic_uniaxial.png",
            "hyperelastic_equibiaxial.png", "hyperelastic_planar.png"} <= names
    report = json.loads((out / "report.json").read_text())
    assert report["model"] == "ogden3"
    again = runner.invoke(app, ["material", "fit",
                                str(EXAMPLES / "materials" / "treloar_ogden.toml"),
                                "--out", str(out)])
    assert again.exit_code == 2 and "--force" in again.output
    show = runner.invoke(app, ["material", "show", str(out / "treloar_nr.toml"), "--json"])
    assert show.exit_code == 0, show.output
    assert json.loads(show.output)["name"] == "treloar_nr"
    assert not math.isnan(json.loads(show.output)["c10_Pa"])


def test_a_dma_compound_on_a_base_gets_the_bases_service_minimum_moved_with_tg(
        pyvisco_fit, tmp_path):
    # pyvisco's polymer (T_g 74.7 degC, tan delta peak) on base NBR (T_g -25 degC) got NBR's
    # service minimum of -40 degC, below T_g - 100 K = -25.3 degC where the compound refuses
    # every temperature: 'sealsim material show' of the written file failed with its own
    # default temperatures.  The minimum now follows T_g (as the base's WLF reference does).
    from typer.testing import CliRunner

    from sealsim.cli import app

    compound = _written_compound(pyvisco_fit, tmp_path)
    nbr = get_elastomer("NBR")
    moved = compound.glass_transition - nbr.glass_transition
    assert compound.service_range[0] == pytest.approx(nbr.service_range[0] + moved, abs=1e-3)
    show = CliRunner().invoke(app, ["material", "show", str(tmp_path / "compound.toml")])
    assert show.exit_code == 0, show.output
    assert "outside the service range" not in show.output     # its first row, rounded inwards


def test_fit_file_inside_the_result_folder_is_refused(tmp_path):
    from typer.testing import CliRunner

    from sealsim.cli import app

    (tmp_path / "h.toml").write_text(
        '[compound]\nname = "h70"\nbase = "NBR"\nreference_temperature = "23 degC"\n'
        'hardness_shore_a = 70\n')
    res = CliRunner().invoke(app, ["material", "fit", str(tmp_path / "h.toml"), "--out",
                                   str(tmp_path), "--force"])
    assert res.exit_code == 2
    assert (tmp_path / "h.toml").exists()
