"""Time profiles of the benches and test rigs: constant, harmonic, piecewise linear.

A profile is a case-file model with units (:func:`profile_type`) offering ``value(t)``,
``integral(t)``, ``derivative(t)``, ``breakpoints()`` and ``period()``; the friction benches
drive a law with them (velocity, displacement, applied force) and the pneumatic test rig
prescribes the piston position with them.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field, create_model, model_validator

from numba import njit

from sealsim.cases import CaseModel, Q

__all__ = ["profile_integral", "profile_type", "profile_value"]

#: profile kinds of :meth:`table` (:func:`profile_value`, :func:`profile_integral`)
CONSTANT, HARMONIC, PIECEWISE = 1, 2, 3


class _ConstantBase(CaseModel):
    """A constant value."""

    def value(self, t):
        return np.full(np.shape(t), self.value_, dtype=float)

    def integral(self, t):
        return self.value_ * np.asarray(t, dtype=float)

    def derivative(self, t):
        return np.zeros(np.shape(t))

    @property
    def value_(self) -> float:
        return self.level  # type: ignore[attr-defined]

    def breakpoints(self):
        return np.array([])

    def period(self):
        return None

    def table(self):
        """(kind, parameters) for the compiled :func:`profile_value` and
        :func:`profile_integral`."""
        return CONSTANT, np.array([self.value_], dtype=float)


class _HarmonicBase(CaseModel):
    """mean + amplitude·cos(ω·t + phase)."""

    def value(self, t):
        t = np.asarray(t, dtype=float)
        return self.mean + self.amplitude * np.cos(self.angular_frequency * t + self.phase)

    def integral(self, t):
        t = np.asarray(t, dtype=float)
        w = self.angular_frequency
        return self.mean * t + self.amplitude / w * (np.sin(w * t + self.phase)
                                                      - np.sin(self.phase))

    def derivative(self, t):
        t = np.asarray(t, dtype=float)
        w = self.angular_frequency
        return -self.amplitude * w * np.sin(w * t + self.phase)

    def breakpoints(self):
        return np.array([])

    def period(self):
        return 2.0 * np.pi / self.angular_frequency

    def table(self):
        """(kind, parameters) for the compiled :func:`profile_value` and
        :func:`profile_integral`."""
        return HARMONIC, np.array([self.mean, self.amplitude, self.angular_frequency,
                                   self.phase], dtype=float)


class _PiecewiseBase(CaseModel):
    """Linear interpolation between (times, values); constant outside."""

    @model_validator(mode="after")
    def _check(self):
        t = np.asarray(self.times, dtype=float)
        if len(self.times) != len(self.values):
            raise ValueError(f"times and values must have the same length "
                             f"(got {len(self.times)} and {len(self.values)})")
        if len(t) < 1 or np.any(np.diff(t) <= 0):
            raise ValueError("times must be increasing, e.g. ['0 s', '1 s', '3 s']")
        return self

    def value(self, t):
        return np.interp(np.asarray(t, dtype=float), self.times, self.values)

    def integral(self, t):
        t = np.asarray(t, dtype=float)
        tp = np.asarray(self.times, dtype=float)
        vp = np.asarray(self.values, dtype=float)
        # extend with the held values before the first and after the last point
        cum = np.concatenate([[0.0], np.cumsum(0.5 * (vp[1:] + vp[:-1]) * np.diff(tp))])
        before = vp[0] * np.minimum(t, tp[0])          # constant vp[0] from 0 to tp[0]
        inside_t = np.clip(t, tp[0], tp[-1])
        idx = np.clip(np.searchsorted(tp, inside_t, side="right") - 1, 0, len(tp) - 1)
        seg_t0 = tp[idx]
        v0 = vp[idx]
        v_at = np.interp(inside_t, tp, vp)
        inside = cum[idx] + 0.5 * (v0 + v_at) * (inside_t - seg_t0)
        after = vp[-1] * np.maximum(t - tp[-1], 0.0)
        return before + inside + after

    def derivative(self, t):
        t = np.asarray(t, dtype=float)
        tp = np.asarray(self.times, dtype=float)
        vp = np.asarray(self.values, dtype=float)
        if len(tp) < 2:
            return np.zeros(t.shape)
        slopes = np.diff(vp) / np.diff(tp)
        idx = np.searchsorted(tp, t, side="right") - 1
        inside = (idx >= 0) & (idx < len(slopes))
        return np.where(inside, slopes[np.clip(idx, 0, len(slopes) - 1)], 0.0)

    def breakpoints(self):
        return np.asarray(self.times, dtype=float)

    def period(self):
        return None

    def table(self):
        """(kind, parameters) for the compiled :func:`profile_value` and
        :func:`profile_integral`: n, times, values, the integral at the times."""
        tp = np.asarray(self.times, dtype=float)
        vp = np.asarray(self.values, dtype=float)
        cum = np.concatenate([[0.0], np.cumsum(0.5 * (vp[1:] + vp[:-1]) * np.diff(tp))])
        return PIECEWISE, np.concatenate([[tp.size], tp, vp, cum])


@njit(cache=True)
def profile_value(kind, table, t):
    """The value of a profile at time t [s] from its :meth:`table` (compiled ``value``)."""
    if kind == CONSTANT:
        return table[0]
    if kind == HARMONIC:
        return table[0] + table[1] * math.cos(table[2] * t + table[3])
    n = int(table[0])
    return np.interp(t, table[1:1 + n], table[1 + n:1 + 2 * n])


@njit(cache=True)
def profile_integral(kind, table, t):
    """The integral of a profile from 0 to t [s] from its :meth:`table` (compiled
    ``integral``: the same formulas)."""
    if kind == CONSTANT:
        return table[0] * t
    if kind == HARMONIC:
        mean, amp, w, phase = table[0], table[1], table[2], table[3]
        return mean * t + amp / w * (math.sin(w * t + phase) - math.sin(phase))
    n = int(table[0])
    tp = table[1:1 + n]
    vp = table[1 + n:1 + 2 * n]
    cum = table[1 + 2 * n:1 + 3 * n]
    before = vp[0] * min(t, tp[0])
    inside_t = min(max(t, tp[0]), tp[n - 1])
    idx = min(max(np.searchsorted(tp, inside_t, side="right") - 1, 0), n - 1)
    v_at = np.interp(inside_t, tp, vp)
    inside = cum[idx] + 0.5 * (vp[idx] + v_at) * (inside_t - tp[idx])
    after = vp[n - 1] * max(t - tp[n - 1], 0.0)
    return before + inside + after


_PROFILE_CACHE: dict[str, Any] = {}


def profile_type(dimension: str):
    """Case-file type of a time profile whose values have ``dimension``.

    A discriminated union on ``kind``:

    * ``kind = "constant"``: ``level``;
    * ``kind = "harmonic"``: ``mean + amplitude·cos(angular_frequency·t + phase)``
      (``phase`` in degrees or radians, e.g. ``"-90 deg"``);
    * ``kind = "piecewise"``: ``times`` and ``values`` lists, linear in between, held constant
      outside.

    Examples
    --------
    >>> from pydantic import TypeAdapter
    >>> p = TypeAdapter(profile_type("velocity")).validate_python(
    ...     {"kind": "piecewise", "times": ["0 s", "1 s"], "values": ["0 m/s", "2 m/s"]})
    >>> p.value([0.5, 3.0]), p.integral([1.0])
    (array([1., 2.]), array([1.]))
    """
    if dimension in _PROFILE_CACHE:
        return _PROFILE_CACHE[dimension]
    tag = dimension.title().replace("_", "")
    constant = create_model(
        f"Constant{tag}Profile", __base__=_ConstantBase,
        kind=(Literal["constant"], ...), level=(Q(dimension), ...))
    harmonic = create_model(
        f"Harmonic{tag}Profile", __base__=_HarmonicBase,
        kind=(Literal["harmonic"], ...), mean=(Q(dimension), 0.0),
        amplitude=(Q(dimension), ...),
        angular_frequency=(Q("angular_speed", gt=0), ...),
        phase=(Q("angle"), 0.0))
    piecewise = create_model(
        f"Piecewise{tag}Profile", __base__=_PiecewiseBase,
        kind=(Literal["piecewise"], ...), times=(list[Q("time", ge=0)], ...),
        values=(list[Q(dimension)], ...))
    union = Annotated[constant | harmonic | piecewise, Field(discriminator="kind")]
    _PROFILE_CACHE[dimension] = union
    return union


def _constant(level: float):
    from pydantic import TypeAdapter

    return TypeAdapter(profile_type("velocity")).validate_python(
        {"kind": "constant", "level": level})
