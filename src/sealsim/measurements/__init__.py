"""Measured data: readers of rig files and the processing that turns them into comparable
numbers (velocity from position, sliding phases, friction levels, step averages).

* :mod:`.readers` -- text tables with a column mapping (quantity + pint unit per column) and
  named readers of known rigs (``format = "tudelft"``); bad files give an InputError naming the
  file, row and column.
* :mod:`.signals` -- pure functions on arrays: Savitzky–Golay derivative, sliding phases,
  offset-free friction level, last-30-s step averages (Organisciak et al. 2014).

>>> import numpy as np
>>> t = np.linspace(0.0, 8.0, 801)
>>> x = 0.01 * np.abs(((t + 2.0) % 4.0) - 2.0)          # triangular stroke, ±10 mm/s
>>> v = smooth_derivative(t, x, window=0.1)
>>> phases = sliding_phases(t, v)
>>> friction_level(0.004 * np.sign(v) + 1.0, phases)  # 4 mN level on a 1 N offset
(0.004, 1.0)
"""

from sealsim.measurements.readers import (
    FORMATS,
    QUANTITIES,
    ColumnSpec,
    Measurement,
    read_measurement,
    read_table,
    read_tudelft,
)
from sealsim.measurements.signals import (
    SlidingPhase,
    friction_level,
    level_drift,
    phase_mask,
    position_velocity_ratio,
    sliding_phases,
    smooth_derivative,
    step_averages,
    stroke_levels,
)

__all__ = [
    "FORMATS",
    "QUANTITIES",
    "ColumnSpec",
    "Measurement",
    "SlidingPhase",
    "friction_level",
    "level_drift",
    "phase_mask",
    "position_velocity_ratio",
    "read_measurement",
    "read_table",
    "read_tudelft",
    "sliding_phases",
    "smooth_derivative",
    "step_averages",
    "stroke_levels",
]
