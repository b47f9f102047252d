"""Calibration and validation against measurements: identify friction-law parameters from rig
data and report how well the model predicts runs it was not fitted to.

* :mod:`.case` -- fit case files (law, contact source, parameters with bounds and stages,
  measurements with role fit/validate);
* :mod:`.friction_fit` -- the model of a measured run and the staged robust fit;
* :mod:`.statistics` -- standard errors, correlations, identifiability from the Jacobian;
* :mod:`.study` -- a fit case to fitted parameters, report and predictions
  (``sealsim friction fit``);
* :mod:`.rotary_case`, :mod:`.rotary_fit`, :mod:`.rotary_study` -- the same for rotary lip
  seals: measured speed cycles (torque, spring-groove temperature) against the coupled
  transient model (``sealsim rotary fit``);
* :mod:`.pneumatic_compare` -- a measured cylinder run against its simulation
  (``sealsim pneumatic compare``).

The result folders of these commands are written by :mod:`sealsim.runs.calibration`.
"""

from sealsim.calibration.case import FrictionFitCase
from sealsim.calibration.friction_fit import FitResult, fit_friction, predict_run, prepare_run
from sealsim.calibration.rotary_case import RotaryFitCase
from sealsim.calibration.rotary_fit import (
    RotaryFitResult,
    duty_from_speed,
    fit_rotary,
    predict_rotary_run,
    prepare_rotary_run,
)
from sealsim.calibration.rotary_study import (
    RotaryFitStudy,
    load_rotary_fit_case,
    rotary_fit_study,
)
from sealsim.calibration.statistics import parameter_statistics
from sealsim.calibration.study import FrictionFitStudy, friction_fit_study, load_fit_case

__all__ = ["FitResult", "FrictionFitCase", "FrictionFitStudy", "RotaryFitCase",
           "RotaryFitResult", "RotaryFitStudy", "duty_from_speed", "fit_friction", "fit_rotary",
           "friction_fit_study", "load_fit_case", "load_rotary_fit_case", "parameter_statistics",
           "predict_rotary_run", "predict_run", "prepare_rotary_run", "prepare_run",
           "rotary_fit_study"]
