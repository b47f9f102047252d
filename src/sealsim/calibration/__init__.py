"""Calibration and validation against measurements: identify friction-law parameters from rig
data and report how well the model predicts runs it was not fitted to.

* :mod:`.case` -- fit case files (law, contact source, parameters with bounds and stages,
  measurements with role fit/validate);
* :mod:`.friction_fit` -- the model of a measured run and the staged robust fit;
* :mod:`.statistics` -- standard errors, correlations, identifiability from the Jacobian;
* :mod:`.study` -- a case file to a result folder (``sealsim friction fit``);
* :mod:`.rotary_case`, :mod:`.rotary_fit`, :mod:`.rotary_study` -- the same for rotary lip
  seals: measured speed cycles (torque, spring-groove temperature) against the coupled
  transient model (``sealsim rotary fit``).
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
from sealsim.calibration.rotary_study import load_rotary_fit_case, run_rotary_fit_file
from sealsim.calibration.statistics import parameter_statistics
from sealsim.calibration.study import load_fit_case, run_friction_fit_file

__all__ = ["FitResult", "FrictionFitCase", "RotaryFitCase", "RotaryFitResult",
           "duty_from_speed", "fit_friction", "fit_rotary", "load_fit_case",
           "load_rotary_fit_case", "parameter_statistics", "predict_rotary_run", "predict_run",
           "prepare_rotary_run", "prepare_run", "run_friction_fit_file", "run_rotary_fit_file"]
