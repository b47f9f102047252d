"""Radial lip seals in gearboxes: friction torque and temperatures (Organisciak et al., SKF,
AGMA 14FTM14, 2014).

* :mod:`.case` -- the case file model (:class:`RotaryCase`: seal, oil, environment, friction,
  duty cycle, numerics);
* :mod:`.lip` -- DIN 3760 default dimensions and lip force, plain and wave lip styles;
* :mod:`.friction` -- the friction torque of the lip (:class:`LipSealFriction`): film,
  lubricant shear and viscoelastic losses on the real contact area;
* :mod:`.thermal_model` -- the axisymmetric thermal grid of shaft, seal and case;
* :mod:`.simulation` -- the coupled transient run (:func:`simulate`), the steady operating
  point (:func:`steady_state`), the friction map over speed and temperature
  (:func:`friction_map`) and case files with variants (:func:`load_rotary_case`).

The result folder of ``sealsim rotary run`` (tables, summary, figures) is written by
:mod:`sealsim.runs.rotary`.  The names below are imported on first use (so
``import sealsim.rotary.case`` stays light).  One call for a steady operating point:
:func:`sealsim.lip_seal_torque`.

>>> from sealsim.rotary import RotaryCase, steady_state
>>> case = RotaryCase(seal={"shaft_diameter": 0.06}, environment={"sump_temperature": 343.15})
>>> round(steady_state(case, 157.08)["torque_Nm"], 3)
0.2
"""

import importlib

_EXPORTS = {
    "DutyCycle": "case", "DutyStep": "case", "OilSpec": "case", "RotaryCase": "case",
    "LIP_STYLES": "lip", "LipStyle": "lip", "default_radial_force": "lip", "lip_force": "lip",
    "FrictionState": "friction", "LipSealFriction": "friction",
    "LipSealFrictionParameters": "friction",
    "RotaryModel": "simulation", "RotaryResult": "simulation", "friction_map": "simulation",
    "simulate": "simulation", "steady_state": "simulation",
    "load_rotary_case": "simulation",
}
__all__ = list(_EXPORTS)


def __getattr__(name):
    if name in _EXPORTS:
        return getattr(importlib.import_module(f"sealsim.rotary.{_EXPORTS[name]}"), name)
    raise AttributeError(f"module 'sealsim.rotary' has no attribute {name!r}")
