"""Velocity of a synthetic friction-rig run, shared by the calibration tests."""

from __future__ import annotations

import numpy as np


def stroke_velocity(speeds, segment: float, ramp: float, dt: float = 0.01):
    """(t [s], v [m/s]) of back-and-forth strokes at each speed [m/s]: a ``ramp`` [s] to
    +speed, ``segment`` [s] at it, a ramp to −speed, ``segment`` at it, and a last ramp to
    rest, sampled every ``dt`` [s]."""
    knots_t, knots_v = [0.0], [0.0]
    for s in speeds:
        for sign in (1, -1):
            knots_t += [knots_t[-1] + ramp, knots_t[-1] + ramp + segment]
            knots_v += [sign * s, sign * s]
    knots_t.append(knots_t[-1] + ramp)
    knots_v.append(0.0)
    t = np.arange(0.0, knots_t[-1], dt)
    return t, np.interp(t, knots_t, knots_v)
