"""Parameter studies in this process: study files and their errors, designs, results against
independent references (the friction law's closed form, analytic Sobol' indices), hardness.

The Dask engine, the real cluster and the kill/resume behaviour are in test_studies_dask.py.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
import tomli_w
from scipy import special

from sealsim.errors import InputError, ResultExistsError
from sealsim.runs.study import run_study
from sealsim.studies import load_study
from sealsim.studies.design import ppf, unit_samples

ROOT = Path(__file__).resolve().parents[1]

#: a Coulomb + viscous law at a constant 0.1 m/s: F = F_C + c·v exactly (no states)
COULOMB_BASE = """
[base.friction]
law = "coulomb"
coulomb_force = "10 N"
viscous_coefficient = "50 N*s/m"
[base.bench]
mode = "velocity"
duration = "0.05 s"
time_step = "10 ms"
velocity = { kind = "constant", level = "0.1 m/s" }
"""


def _study(tmp_path, text: str, name: str = "study.toml"):
    path = tmp_path / name
    path.write_text(text)
    return load_study(path)


def _error(tmp_path, text: str) -> str:
    with pytest.raises(InputError) as info:
        _study(tmp_path, text)
    return str(info.value)


# -- study files: one clear error naming the factor ------------------------------------------
GRID_HEAD = ('[study]\nmodel = "friction"\n' + COULOMB_BASE
             + '[outputs]\nF = "max_friction_force_N"\n')


def test_unknown_field_path_names_the_factor_and_the_allowed_fields(tmp_path):
    msg = _error(tmp_path, GRID_HEAD + '[[factors]]\nname = "fn"\npath = "inputs.normal_forse"'
                                       '\nvalues = ["1 N"]\n')
    assert "factor 'fn' (inputs.normal_forse) = 1.0 N: inputs.normal_forse: unknown field" in msg
    assert "allowed fields: contact_width, normal_force" in msg
    assert "\n" not in msg                                      # one message, one line


def test_unknown_list_element_and_index_are_refused(tmp_path):
    text = ('[study]\nmodel = "pneumatic"\ncase = "{case}"\nvariant = "T25C"\n'
            '[outputs]\nF = "mean_friction_N"\n[[factors]]\nname = "T"\npath = "{path}"\n'
            'values = ["30 degC"]\n')
    case = ROOT / "examples" / "pneumatic" / "cylinder_32.toml"
    msg = _error(tmp_path, text.format(case=case, path="seals.plunger.temperature"))
    assert "factor 'T'" in msg and "no element named 'plunger'" in msg and "'rod'" in msg
    msg = _error(tmp_path, text.format(case=case, path="seals.7.temperature"))
    assert "factor 'T'" in msg and "no index 7" in msg


def test_a_factor_path_into_a_list_that_set_replaced_is_checked_against_it(tmp_path):
    # [set] replaces the duty cycle by one step: duty.steps.1 no longer exists.  The factor's
    # path was checked against the base case's three steps and the run documents then raised
    # a bare IndexError (traceback).
    case = ROOT / "examples" / "rotary" / "sump_volume.toml"
    text = ('[study]\nmodel = "rotary"\ncase = "{case}"\nvariant = "sump_3L"\n'
            '[set]\n"duty.steps" = [{{ speed = "1000 rpm", duration = "1 min" }}]\n'
            '[outputs]\nT = "last_step.torque_Nm"\n'
            '[[factors]]\nname = "speed"\npath = "duty.steps.{index}.speed"\n'
            'values = ["250 rpm", "500 rpm"]\n')
    msg = _error(tmp_path, text.format(case=case, index=1))
    assert "factor 'speed'" in msg and "'duty.steps' has 1 element, no index 1" in msg
    assert len(_study(tmp_path, text.format(case=case, index=0)).factors) == 1


def test_grid_values_with_and_without_a_unit_name_the_bare_one(tmp_path):
    # was "values: 500.0 rpm cannot be converted to a plain number", blaming the good value
    msg = _error(tmp_path, GRID_HEAD + '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"'
                                       '\nvalues = ["1", "2 N"]\n')
    assert "factor 'fc': values: '1' has no unit, '2 N' has one" in msg


def test_normal_distribution_of_a_positive_quantity_needs_bounds(tmp_path):
    msg = _error(tmp_path, '[study]\nmodel = "friction"\ndesign = "monte_carlo"\nsamples = 8\n'
                 + COULOMB_BASE + '[outputs]\nF = "max_friction_force_N"\n'
                 '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\n'
                 'distribution = "normal"\nmean = "10 N"\nstd = "1 N"\n')
    assert "factor 'fc' (friction.coulomb_force)" in msg
    assert "'normal' has no bounds" in msg and "truncnormal" in msg and ">= 0" in msg


@pytest.mark.parametrize("factor, design, expected", [
    ('values = []', 'design = "grid"', "values is empty, which gives zero runs"),
    ('range = { start = "1 N", stop = "2 N", num = 0 }', 'design = "grid"',
     "range.num = 0 gives no runs"),
    ('distribution = "uniform"\nlower = "1 N"\nupper = "2 N"',
     'design = "latin_hypercube"\nsamples = 0', "study.samples = 0 gives zero runs"),
])
def test_zero_runs_are_refused_naming_the_cause(tmp_path, factor, design, expected):
    msg = _error(tmp_path, f'[study]\nmodel = "friction"\n{design}\n' + COULOMB_BASE
                 + '[outputs]\nF = "max_friction_force_N"\n'
                 f'[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\n{factor}\n')
    assert expected in msg
    assert "fc" in msg or "samples" in msg


def test_out_of_range_grid_value_and_bad_expression_are_refused(tmp_path):
    msg = _error(tmp_path, GRID_HEAD + '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"'
                                       '\nvalues = ["1 N", "-2 N"]\n')
    assert "factor 'fc' (friction.coulomb_force) = -2.0 N" in msg and ">= 0" in msg
    msg = _error(tmp_path, GRID_HEAD + '[set]\n"friction.viscous_coefficient" = "= fc.real"\n'
                 '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\nvalues = ["1 N"]\n')
    assert "Attribute is not allowed" in msg
    msg = _error(tmp_path, GRID_HEAD + '[[factors]]\nname = "fc"\nvalues = ["1 N"]\n')
    assert "factor 'fc' has no path and no [set] expression uses it" in msg


# -- designs ----------------------------------------------------------------------------------
def test_truncated_normal_matches_its_closed_form_moments():
    # Mean of N(mu, s) truncated to [a, b]: mu + s (phi(al) - phi(be)) / (Phi(be) - Phi(al))
    # (Johnson, Kotz & Balakrishnan, Continuous Univariate Distributions 1, 1994, eq. 13.134).
    mu, s, a, b = 2.0, 0.03, 1.95, 2.08
    x = ppf(unit_samples("latin_hypercube", 20000, 1, seed=5)[:, 0], "truncnormal", mean=mu,
            std=s, lower=a, upper=b)
    al, be = (a - mu) / s, (b - mu) / s
    phi = lambda z: np.exp(-z * z / 2) / math.sqrt(2 * math.pi)  # noqa: E731
    big_phi = lambda z: 0.5 * (1 + special.erf(z / math.sqrt(2)))  # noqa: E731
    mean = mu + s * (phi(al) - phi(be)) / (big_phi(be) - big_phi(al))
    assert x.min() >= a and x.max() <= b
    # LHS of 20000 points: the sample mean is within 1e-4 of the exact one (stratified error
    # ~ s/n); 2e-5 mm here
    assert abs(x.mean() - mean) < 1e-4


def test_samples_are_reproducible_from_the_seed(tmp_path):
    text = ('[study]\nmodel = "friction"\ndesign = "monte_carlo"\nsamples = 5\nseed = 11\n'
            + COULOMB_BASE + '[outputs]\nF = "max_friction_force_N"\n[[factors]]\nname = "fc"\n'
            'path = "friction.coulomb_force"\ndistribution = "uniform"\nlower = "1 N"\n'
            'upper = "2 N"\n')
    a, b = _study(tmp_path, text, "a.toml"), _study(tmp_path, text, "b.toml")
    assert np.array_equal(a.sample_values, b.sample_values)
    assert a.fingerprint() == b.fingerprint()
    c = _study(tmp_path, text.replace("seed = 11", "seed = 12"), "c.toml")
    assert not np.array_equal(a.sample_values, c.sample_values)


# -- results against independent references ----------------------------------------------------
def test_grid_study_gives_the_closed_form_friction_and_a_complete_folder(tmp_path):
    study = _study(tmp_path, GRID_HEAD + '[[factors]]\nname = "fc"\npath = '
                   '"friction.coulomb_force"\nvalues = ["5 N", "15 N"]\n[[factors]]\nname = "c"\n'
                   'path = "friction.viscous_coefficient"\n'
                   'range = { start = "0 N*s/m", stop = "100 N*s/m", num = 3 }\n')
    result = run_study(study, tmp_path / "out", workers=0)
    ds = result.dataset
    assert ds["F"].dims == ("fc", "c") and ds["F"].attrs["units"] == "N"
    expected = ds["fc"].values[:, None] + ds["c"].values[None, :] * 0.1   # F = F_C + c v
    np.testing.assert_allclose(ds["F"].values, expected, rtol=1e-12)     # exact law, rounding
    files = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert files == [".sealsim-results", "case_resolved.toml", "heatmap_F.png", "response_F.png",
                     "runs.csv", "study.nc", "study.toml", "summary.json"]
    assert not any(p.name.startswith(".out") for p in tmp_path.iterdir())  # no work folder left
    header = (tmp_path / "out" / "runs.csv").read_text().splitlines()[0]
    assert header == "run,fc_N,c_Ns_m,F_N,status,error,wall_time_s,worker"
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["runs"] == {"total": 6, "finished": 6, "failed": 0, "computed": 6,
                               "reused": 0}
    with pytest.raises(ResultExistsError):          # issue 9: no silent overwrite
        run_study(study, tmp_path / "out", workers=0)


def test_failed_runs_are_recorded_and_do_not_stop_the_study(tmp_path):
    # a Stribeck law needs static_force >= coulomb_force: each value is valid with the other
    # factor nominal (checked up front), the combination 30 N / 20 N fails when it runs
    text = ('[study]\nmodel = "friction"\n[base.friction]\nlaw = "stribeck"\n'
            'coulomb_force = "10 N"\nstatic_force = "20 N"\nstribeck_velocity = "1 mm/s"\n'
            '[base.bench]\nmode = "velocity"\nduration = "0.05 s"\ntime_step = "10 ms"\n'
            'velocity = { kind = "constant", level = "0.1 m/s" }\n'
            '[outputs]\nF = "max_friction_force_N"\n'
            '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\n'
            'values = ["5 N", "30 N"]\n'
            '[[factors]]\nname = "fs"\npath = "friction.static_force"\n'
            'values = ["40 N", "20 N"]\n')
    result = run_study(_study(tmp_path, text), tmp_path / "out", workers=0)
    ds = result.dataset
    assert ds["status"].values.tolist() == [[1, 1], [1, 0]]
    assert np.isnan(ds["F"].values[1, 1]) and np.isfinite(ds["F"].values).sum() == 3
    assert "static_force (20 N) must be >= coulomb_force (30 N)" in str(ds["error"].values[1, 1])
    assert result.summary["failures"][0]["run"] == 3
    assert result.table["status"].tolist() == ["ok", "ok", "ok", "failed"]


def test_sobol_indices_of_an_additive_model_match_the_variance_shares(tmp_path):
    # F = F_C + c v with F_C ~ U(10, 30) N and c v ~ U(0, 10) N: for an additive model
    # S_i = ST_i = Var_i / Var = 400/500 and 100/500 (Sobol' 1993); a third factor that the
    # output does not depend on has zero indices.
    text = ('[study]\nmodel = "friction"\ndesign = "sobol"\nsamples = 64\nseed = 7\n'
            + COULOMB_BASE + '[outputs]\nF = "max_friction_force_N"\n'
            '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\ndistribution = '
            '"uniform"\nlower = "10 N"\nupper = "30 N"\n'
            '[[factors]]\nname = "c"\npath = "friction.viscous_coefficient"\ndistribution = '
            '"uniform"\nlower = "0 N*s/m"\nupper = "100 N*s/m"\n'
            # a gauge pressure is >= -1 atm (vacuum): its normal distribution needs bounds
            '[[factors]]\nname = "p"\npath = "inputs.pressure_a"\ndistribution = '
            '"truncnormal"\nmean = "1 bar"\nstd = "0.1 bar"\nlower = "0 bar"\n'
            'upper = "2 bar"\n')
    result = run_study(_study(tmp_path, text), tmp_path / "out", workers=0)
    table = result.sensitivity.set_index("factor")
    # N = 64 Saltelli base samples (320 runs): the estimators' Monte-Carlo error is about
    # 0.05-0.1 here (SALib's bootstrap intervals say the same), so 0.1 is the tolerance
    for name, share in (("fc", 0.8), ("c", 0.2), ("p", 0.0)):
        assert abs(table.loc[name, "S1"] - share) < 0.1
        assert abs(table.loc[name, "ST"] - share) < 0.1
    assert (tmp_path / "out" / "sensitivity.png").is_file()
    dist = result.distribution.iloc[0]
    # exact percentiles of U(10,30) + U(0,10): median 25 N (symmetric)
    assert abs(dist["P50"] - 25.0) < 0.5


def test_sobol_indices_from_too_few_samples_are_noted_and_the_cli_prints_the_notes(tmp_path):
    # N = 2 base samples (8 runs) of the additive model above: SALib's intervals span more
    # than the 0-1 an index can take; the indices were written and plotted without a word,
    # and the CLI printed none of summary.json's notes.  N = 64 (above): no such note.
    from typer.testing import CliRunner

    from sealsim.cli import app

    text = ('[study]\nmodel = "friction"\ndesign = "sobol"\nsamples = N\nseed = 7\n'
            + COULOMB_BASE + '[outputs]\nF = "max_friction_force_N"\n'
            '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\ndistribution = '
            '"uniform"\nlower = "10 N"\nupper = "30 N"\n'
            '[[factors]]\nname = "c"\npath = "friction.viscous_coefficient"\ndistribution = '
            '"uniform"\nlower = "0 N*s/m"\nupper = "100 N*s/m"\n')
    few = run_study(_study(tmp_path, text.replace("= N", "= 2")), tmp_path / "few", workers=0)
    assert any("sensitivity indices are uncertain" in n and "(F)" in n and "from 8 runs" in n
               for n in few.summary["notes"])
    many = run_study(_study(tmp_path, text.replace("= N", "= 64"), "many.toml"), tmp_path / "many",
                     workers=0)
    assert not any("uncertain" in n for n in many.summary["notes"])
    result = CliRunner().invoke(app, ["study", "run", str(tmp_path / "study.toml"), "--out",
                                      str(tmp_path / "cli"), "--workers", "0"])
    assert result.exit_code == 0, result.output
    assert "note: the sensitivity indices are uncertain" in " ".join(result.output.split())


def test_series_are_resampled_on_a_common_time_grid(tmp_path):
    text = GRID_HEAD + (
        '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\nvalues = ["5 N", "7 N"]\n'
        '[series]\nvariables = ["friction_force_N"]\ninterval = "20 ms"\n')
    ds = run_study(_study(tmp_path, text), tmp_path / "out", workers=0).dataset
    assert ds["time"].values.tolist() == pytest.approx([0.0, 0.02, 0.04])
    np.testing.assert_allclose(ds["friction_force_N"].values,
                               [[10.0] * 3, [12.0] * 3])     # F_C + 50 N s/m * 0.1 m/s


def test_wrong_output_path_stops_at_the_first_run_and_resume_after_the_fix(tmp_path):
    text = GRID_HEAD.replace('F = "max_friction_force_N"', 'F = "max_friction_N"') + (
        '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\nvalues = ["5 N", "7 N"]\n')
    with pytest.raises(InputError, match="output 'F' = 'max_friction_N' is not in the "
                                         "summary.*max_friction_force_N"):
        run_study(_study(tmp_path, text), tmp_path / "out", workers=0)
    assert not (tmp_path / "out").exists()
    fixed = _study(tmp_path, text.replace("max_friction_N", "max_friction_force_N"))
    result = run_study(fixed, tmp_path / "out", workers=0, resume=True)
    assert result.summary["runs"]["reused"] == 1 and result.summary["runs"]["computed"] == 1


# -- material hardness -----------------------------------------------------------------------------
def test_gent_hardness_modulus_agrees_with_fe_simulations_of_the_durometer():
    from sealsim.properties.elastomers import shore_a_young_modulus

    # Qi, Joyce & Boyce (2003), FE of the Shore A test on a neo-Hookean solid:
    # S = 100 erf(3.186e-4 sqrt(E[Pa])), i.e. E = (erfinv(S/100) / 3.186e-4)^2.
    for s, tol in ((60, 0.10), (70, 0.06), (80, 0.17)):
        qi = (special.erfinv(s / 100) / 3.186e-4) ** 2
        # two independent relations (indentation theory vs FE); their published spread
        # is 5-15 % in this range
        assert abs(shore_a_young_modulus(s) / qi - 1) < tol


def test_hardness_scales_the_structure_material(tmp_path):
    from sealsim.cases import apply_overrides, load_toml, validate_case
    from sealsim.properties.elastomers import shore_a_young_modulus
    from sealsim.structure.case import StructureCase
    from sealsim.structure.build import build_material

    data = load_toml(ROOT / "examples" / "pneumatic" / "rod_seal_12.toml")
    base = build_material(validate_case(StructureCase, data))
    soft = build_material(validate_case(StructureCase, apply_overrides(
        data, {"material": {"hardness_shore_a": 70}})))
    ratio = shore_a_young_modulus(70) / shore_a_young_modulus(75)   # catalogue NBR: 75 ShA
    assert soft.c10(293.15) / base.c10(293.15) == pytest.approx(ratio, rel=1e-12)
    with pytest.raises(InputError, match="either hardness_shore_a or c10"):
        build_material(validate_case(StructureCase, apply_overrides(
            data, {"material": {"hardness_shore_a": 70, "c10": "1 MPa"}})))


def test_cli_reports_a_bad_study_in_one_message(tmp_path):
    from typer.testing import CliRunner

    from sealsim.cli import app

    path = tmp_path / "bad.toml"
    path.write_text(GRID_HEAD + '[[factors]]\nname = "fc"\npath = "friction.coulomb_force"\n'
                                'values = []\n')
    result = CliRunner().invoke(app, ["study", "run", str(path), "--out",
                                      str(tmp_path / "out")])
    assert result.exit_code == 2
    text = " ".join(result.output.split())          # rich wraps long lines
    assert "factor 'fc': values is empty, which gives zero runs" in text
    assert "Traceback" not in result.output and not (tmp_path / "out").exists()


def test_structure_map_study_gives_the_maps_of_its_cases(tmp_path):
    # every run of a 'structure_map' study failed: "ImportError: cannot import name
    # 'compute_map' from 'sealsim.structure.maps'" (it lives in sealsim.structure.mapping)
    from sealsim.cases import apply_overrides, load_toml, validate_case
    from sealsim.structure.case import StructureCase
    from sealsim.structure.mapping import compute_map

    case = load_toml(ROOT / "examples" / "pneumatic" / "rod_seal_12.toml")
    small = {"mesh": {"level": "coarse"}, "map": {"temperature": ["20 degC"],
                                                  "pressure": ["0 bar", "6 bar"],
                                                  "workers": 1}}
    (tmp_path / "seal.toml").write_text(tomli_w.dumps(apply_overrides(case, small)))
    study = _study(tmp_path, '[study]\nmodel = "structure_map"\ncase = "seal.toml"\n'
                   '[[factors]]\nname = "squeeze"\npath = "load.squeeze"\n'
                   'values = [[0.10], [0.14]]\n[outputs]\nF_max = "F_N_N.max"\n')
    result = run_study(study, tmp_path / "out", workers=0)
    ds = result.dataset
    f_max = ds["F_max"].values                     # a failed run would be NaN
    assert np.all(np.isfinite(f_max)) and f_max[1] > f_max[0]   # more squeeze, more force
    # each run is the map of its case (the same FE, so equal to rounding)
    direct = compute_map(validate_case(StructureCase, apply_overrides(
        case, {**small, "load": {"squeeze": [0.14]}})), workers=1)
    assert f_max[1] == pytest.approx(float(direct["F_N"].max()), rel=1e-9)
