"""Tables embedded in an FMU: node values and derivatives of a C¹ bicubic Hermite interpolant.

The C side (``c/hermite.c``) evaluates the tensor-product cubic Hermite interpolant of
:class:`sealsim.structure.maps.HermiteGrid` from per-node data: the values, the first
derivatives along both axes and the mixed derivative.  Two ways to get the derivatives:

* :func:`pchip_table` -- from sampled data with the monotone PCHIP slopes of Fritsch & Carlson
  (1980), applied along each axis in turn (the slopes of ``HermiteGrid``: an FE map embedded
  this way is the same interpolant that sealsim evaluates);
* :func:`smooth_table` -- for a smooth function known everywhere (the analytic contact
  estimate): derivatives by second-order finite differences, so the table is fourth-order
  accurate in the node spacing.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import PchipInterpolator

from sealsim.errors import InputError

__all__ = ["HermiteTable", "pchip_table", "smooth_table"]


@dataclass(frozen=True)
class HermiteTable:
    """Node data of a 2-D Hermite table.

    Attributes
    ----------
    axes : (ndarray, ndarray)
        Strictly ascending node coordinates (n0,), (n1,).
    data : ndarray, shape (n0, n1, 4, nvars)
        Per node: values, d/dx0, d/dx1, d²/dx0dx1.
    """

    axes: tuple[np.ndarray, np.ndarray]
    data: np.ndarray

    @property
    def values(self) -> np.ndarray:
        """Node values, shape (n0, n1, nvars)."""
        return self.data[:, :, 0, :]

    def evaluate(self, a, b) -> np.ndarray:
        """The interpolant at points (a, b) inside the grid, shape (n, nvars): the formula of
        ``c/hermite.c`` in numpy (for error estimates of a table)."""
        x0, x1 = self.axes
        a = np.atleast_1d(np.asarray(a, dtype=float))
        b = np.atleast_1d(np.asarray(b, dtype=float))
        i = np.clip(np.searchsorted(x0, a, side="right") - 1, 0, x0.size - 2)
        j = np.clip(np.searchsorted(x1, b, side="right") - 1, 0, x1.size - 2)
        h0, h1 = x0[i + 1] - x0[i], x1[j + 1] - x1[j]

        def basis(t, h):
            t2, t3 = t * t, t * t * t
            return ((2 * t3 - 3 * t2 + 1, (t3 - 2 * t2 + t) * h),
                    (-2 * t3 + 3 * t2, (t3 - t2) * h))

        b0, b1 = basis((a - x0[i]) / h0, h0), basis((b - x1[j]) / h1, h1)
        out = 0.0
        for ci in (0, 1):
            for cj in (0, 1):
                node = self.data[i + ci, j + cj]              # (n, 4, nvars)
                v0, s0 = b0[ci]
                v1, s1 = b1[cj]
                out = out + ((v0 * v1)[:, None] * node[:, 0] + (s0 * v1)[:, None] * node[:, 1]
                             + (v0 * s1)[:, None] * node[:, 2]
                             + (s0 * s1)[:, None] * node[:, 3])
        return out

    def c_source(self, name: str) -> str:
        """C definitions of the arrays and the ``HermiteTable`` object ``name``."""
        x0, x1 = self.axes
        n0, n1, _, nvars = self.data.shape

        def array(label, values):
            body = ",\n    ".join(", ".join(repr(float(v)) for v in values[i:i + 4])
                                  for i in range(0, len(values), 4))
            return f"static const double {label}[{len(values)}] = {{\n    {body}\n}};"

        return "\n".join([
            array(f"{name}_X0", x0), array(f"{name}_X1", x1),
            array(f"{name}_DATA", self.data.ravel()),
            f"static const HermiteTable {name} = {{{n0}, {n1}, {nvars}, {name}_X0, {name}_X1, "
            f"{name}_DATA}};"])


def _check_axis(x, label: str) -> np.ndarray:
    x = np.asarray(x, dtype=float)
    if x.ndim != 1 or x.size < 2 or np.any(np.diff(x) <= 0) or not np.all(np.isfinite(x)):
        raise InputError(f"table axis {label}: needs at least two strictly ascending finite "
                         f"values, got {x.tolist()}")
    return x


def _slopes(x: np.ndarray, values: np.ndarray, axis: int) -> np.ndarray:
    """Nodal PCHIP slopes along ``axis`` (linear for two nodes)."""
    if x.size == 2:
        d = np.diff(values, axis=axis) / (x[1] - x[0])
        return np.concatenate([d, d], axis=axis)
    return PchipInterpolator(x, values, axis=axis).derivative()(x)


def pchip_table(x0, x1, values) -> HermiteTable:
    """Table from sampled values with PCHIP node slopes.

    Parameters
    ----------
    x0, x1 : array_like
        Node coordinates.
    values : array_like, shape (n0, n1, nvars)
        Sampled values.

    Examples
    --------
    >>> t = pchip_table([0.0, 1.0, 2.0], [0.0, 1.0], np.arange(6.0).reshape(3, 2, 1))
    >>> t.data[1, 0, :, 0].tolist()           # value, d/dx0, d/dx1, mixed
    [2.0, 2.0, 1.0, 0.0]
    """
    x0, x1 = _check_axis(x0, "0"), _check_axis(x1, "1")
    values = np.asarray(values, dtype=float)
    if values.shape[:2] != (x0.size, x1.size) or values.ndim != 3:
        raise InputError("table values do not match the grid")
    if not np.all(np.isfinite(values)):
        raise InputError("table values contain NaN or inf")
    d0 = _slopes(x0, values, 0)
    d1 = _slopes(x1, values, 1)
    d01 = _slopes(x1, d0, 1)
    return HermiteTable((x0, x1), np.stack([values, d0, d1, d01], axis=2))


def _partial(func: Callable, a, b, axis: int, bounds: tuple[float, float]):
    """d func/d (a, b)[axis] at the points (a, b): central differences, one-sided
    second-order differences on the ends of the axis range (func is never evaluated
    outside it)."""
    lo, hi = bounds
    step = 1e-5 * (hi - lo)

    def at(shift):
        point = [a, b]
        point[axis] = point[axis] + shift
        return np.asarray(func(*point), dtype=float)

    x = (a, b)[axis]
    tol = 1e-9 * (hi - lo)
    center = (at(step) - at(-step)) / (2 * step)
    forward = (-3 * at(0.0) + 4 * at(step) - at(2 * step)) / (2 * step)
    backward = (3 * at(0.0) - 4 * at(-step) + at(-2 * step)) / (2 * step)
    at_lo = (np.asarray(x) <= lo + tol)[..., None]
    at_hi = (np.asarray(x) >= hi - tol)[..., None]
    return np.where(at_lo, forward, np.where(at_hi, backward, center))


def smooth_table(func: Callable, x0, x1) -> HermiteTable:
    """Table of a smooth function with finite-difference node derivatives.

    Parameters
    ----------
    func : callable
        ``func(X0, X1) -> ndarray (..., nvars)`` for broadcast coordinate arrays.
    x0, x1 : array_like
        Node coordinates.

    Examples
    --------
    >>> t = smooth_table(lambda a, b: np.stack([a ** 3 * b], -1), [0.0, 1.0, 2.0], [1.0, 2.0])
    >>> [round(float(v), 6) for v in t.data[1, 1, :, 0]]
    [2.0, 6.0, 1.0, 3.0]
    """
    x0, x1 = _check_axis(x0, "0"), _check_axis(x1, "1")
    a, b = np.meshgrid(x0, x1, indexing="ij")
    bounds = [(x0[0], x0[-1]), (x1[0], x1[-1])]
    values = np.asarray(func(a, b), dtype=float)
    d0 = _partial(func, a, b, 0, bounds[0])
    d1 = _partial(func, a, b, 1, bounds[1])
    d01 = _partial(lambda p, q: _partial(func, p, q, 1, bounds[1]), a, b, 0, bounds[0])
    data = np.stack([values, d0, d1, d01], axis=2)
    if not np.all(np.isfinite(data)):
        raise InputError("table values contain NaN or inf")
    return HermiteTable((x0, x1), data)
