"""Friction fits of the Θ law on the seal's own contact: parameters the friction table is built
with (roughness, film factor, ...) are fitted with the table of each value they take, and
parameters the chosen steady curve does not use are refused."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from rig_strokes import stroke_velocity

import sealsim
from sealsim.calibration.case import FrictionFitCase
from sealsim.calibration.friction_fit import offset_free, predict_run, with_law_table
from sealsim.calibration.study import friction_fit_study
from sealsim.cases import validate_case
from sealsim.errors import InputError, SealsimWarning
from sealsim.friction import make_law

#: the synthetic rig: analytic 3.5 mm O-ring at 10 % squeeze on a 25 mm rod, 3 bar, 20 °C
SEAL = {"cord_diameter": "3.5 mm", "squeeze": 0.1}
CONTACT = {"sliding_diameter": "25 mm", "temperature": "20 degC", "location": "rod",
           "map": {"analytic": SEAL}}
P_BAR = 3.0
#: the truth: seal_contact with a rougher counter surface than its default 0.3 µm
TRUE_ROUGHNESS = "0.6 um"


def contact_run(path: Path, speeds, law: dict, segment=2.0, ramp=0.2) -> Path:
    """Strokes back and forth at each speed [m/s], the friction the law gives in steady
    sliding at every sample (:func:`sealsim.seal_friction`); columns t [ms], v [mm/s],
    p [bar], F [N]."""
    t, v = stroke_velocity(speeds, segment, ramp)
    ureg = sealsim.units.unit_registry()
    with warnings.catch_warnings():     # the note on seal_contact's generic values
        warnings.simplefilter("ignore", SealsimWarning)
        frame = sealsim.seal_friction(SEAL, v * ureg("m/s"), f"{P_BAR} bar", "20 degC",
                                      law=law, diameter="25 mm")
    np.savetxt(path, np.column_stack([t * 1e3, v * 1e3, np.full(t.size, P_BAR),
                                      frame["friction_N"].to_numpy()]),
               delimiter=",", header="t,v,p,F", comments="")
    return path


def fit_case(file: str, parameters, friction=None) -> dict:
    columns = {"time": {"column": "t", "unit": "ms"},
               "velocity": {"column": "v", "unit": "mm/s"},
               "pressure": {"column": "p", "unit": "bar"},
               "friction": {"column": "F", "unit": "N"}}
    return {"friction": friction or {"law": "theta", "parameter_set": "seal_contact"},
            "contact": CONTACT,
            "signals": {"settle": 0.5, "sliding_threshold": "0.5 mm/s"},
            "fit": {"loss": "linear", "parameters": parameters},
            "measurements": [{"name": "sweep", "file": file, "role": "fit", "header": True,
                              "delimiter": ",", "columns": columns}]}


def test_fitted_roughness_gets_the_friction_table_of_each_value(tmp_path):
    # the data come from seal_contact with σ = 0.6 µm at four speeds of the mixed regime; the
    # fit starts from the set's 0.3 µm.  With the table built once at the start value the
    # model would not move with σ at all (the fit would stop at its start, unidentifiable);
    # with the table of each value it recovers 0.6 µm.  Tolerance 1 %: the data are the
    # model itself (no noise), the rest is the optimiser's and the phases' median.
    truth = {"law": "theta", "parameter_set": "seal_contact", "roughness": TRUE_ROUGHNESS}
    contact_run(tmp_path / "sweep.csv", [0.002, 0.01, 0.05, 0.2], truth)
    case = validate_case(FrictionFitCase, fit_case("sweep.csv", [
        {"name": "roughness", "bounds": ["0.1 um", "3 um"]}]), "test case")
    study = friction_fit_study(case, tmp_path)
    assert study.result.status == "ok", study.result.failure
    assert study.result.values[0] == pytest.approx(0.6e-6, rel=0.01)
    assert study.result.identifiable.all()
    # the predictions written after the fit (the law driven by the measured velocity, Θ from
    # rest; offset-free, as the measurement is) use the table of the fitted σ: equal to the
    # true law's within 1 % (σ within 1 %); the start table would give a visibly different
    # signal
    fitted_law = make_law(study.result.params)
    true_law = make_law(study.result.params.model_copy(update={"roughness": 0.6e-6}))
    run = study.runs[0]
    expected = offset_free(predict_run(true_law, with_law_table(true_law, [run])[0]),
                           run.phases)
    scale = np.abs(expected).max()
    assert np.abs(study.predictions["sweep"] - expected).max() < 0.01 * scale
    stale = offset_free(predict_run(fitted_law, run), run.phases)   # the start value's table
    assert np.abs(stale - expected).max() > 0.05 * scale


def test_fitting_a_field_the_steady_curve_does_not_use_is_refused():
    # seal_contact takes its steady curve from the contact: f_a, f_b and gamma do nothing
    with pytest.raises((InputError, ValidationError)) as err:
        validate_case(FrictionFitCase, fit_case("x.csv", [
            {"name": "f_a", "bounds": [0.01, 1.0]}]), "test case")
    text = str(err.value)
    assert "'f_a' is not used by the theta law with steady = 'contact'" in text
    assert "boundary_friction" in text and "roughness" in text
    # the lumped law has no friction table: roughness would do nothing there
    lumped = {"law": "theta", "parameter_set": "pneumatic_demo"}
    with pytest.raises((InputError, ValidationError)) as err:
        validate_case(FrictionFitCase, fit_case("x.csv", [
            {"name": "roughness", "bounds": ["0.1 um", "1 um"]}], lumped), "test case")
    text = str(err.value)
    assert "'roughness' is not used by the theta law with steady = 'lumped'" in text
    assert "f_a" in text and "boundary_friction" not in text.split("fit one of")[1]


def test_two_seals_at_one_speed_identify_what_one_cannot(tmp_path):
    # Synthetic truth: seal_contact with μ_b = 0.08 and a starved inlet fed by a 0.15 µm layer,
    # two O-rings of different section and squeeze (analytic maps: different contact widths
    # and inlet gradients), each run at one speed (10 mm/s both ways) and one pressure.  One
    # seal's run gives one friction level: μ_b and the layer trade off (the fit says so);
    # both seals in one fit (the second as [contacts.small], contact = "small") recover both
    # within 2 % (noise-free data; the rest is the optimiser's and the phases' median).
    truth = {"law": "theta", "parameter_set": "seal_contact", "boundary_friction": 0.08,
             "supply_layer": "0.15 um"}
    small = {"cord_diameter": "2 mm", "squeeze": 0.2}
    contact_run(tmp_path / "big.csv", [0.01], truth)
    t, v = stroke_velocity([0.01], 2.0, 0.2)
    ureg = sealsim.units.unit_registry()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SealsimWarning)
        frame = sealsim.seal_friction(small, v * ureg("m/s"), f"{P_BAR} bar", "20 degC",
                                      law=truth, diameter="25 mm")
    np.savetxt(tmp_path / "small.csv", np.column_stack([
        t * 1e3, v * 1e3, np.full(t.size, P_BAR), frame["friction_N"].to_numpy()]),
        delimiter=",", header="t,v,p,F", comments="")
    start = {"law": "theta", "parameter_set": "seal_contact", "supply_layer": "0.4 um"}
    parameters = [{"name": "boundary_friction", "bounds": [0.001, 2.0]},
                  {"name": "supply_layer", "bounds": ["0.02 um", "3 um"]}]
    one = validate_case(FrictionFitCase, fit_case("big.csv", parameters, start), "one seal")
    alone = friction_fit_study(one, tmp_path)
    assert not alone.result.identifiable.any()
    data = fit_case("big.csv", parameters, start)
    data["contacts"] = {"small": {**CONTACT, "map": {"analytic": small}}}
    data["measurements"].append({**data["measurements"][0], "name": "small",
                                 "file": "small.csv", "contact": "small"})
    both = friction_fit_study(validate_case(FrictionFitCase, data, "two seals"), tmp_path)
    assert both.result.status == "ok", both.result.failure
    assert both.result.identifiable.all()
    assert both.result.values == pytest.approx([0.08, 0.15e-6], rel=0.02)
    # a measurement naming a contact the case does not have is refused, with the names
    data["measurements"][1]["contact"] = "smal"
    with pytest.raises((InputError, ValidationError), match=r"'smal' names no "
                       r"\[contacts.NAME\] table \(given: \['small'\]\)"):
        validate_case(FrictionFitCase, data, "two seals")
