r"""Characteristic diagrams of the seal: reading F_N and b over pressure × temperature
(× squeeze). FE-free: the pneumatic model imports this module cheaply; the maps are computed
by :mod:`.mapping`.

Storing: an :class:`xarray.Dataset` with dimensions ``(squeeze, temperature, pressure)``, SI
coordinates with ``units`` attributes, the variables ``F_N`` [N] (full circumference),
``F_N_per_length`` [N/m], ``b`` [m] (sum of the contact zones), ``p_max``, ``p_mean`` [Pa],
``F_groove_bottom`` [N], ``contact_zones`` [-], ``b_span`` [m], the contact pressure profile
``contact_pressure`` [Pa] over an extra dimension ``position`` (axial position on the sealing
surface) and the resolved case as the string attribute ``case`` -- written to netCDF
(``map.nc``).

Reading: :func:`load_map` → :class:`SealMap`, a C¹ tensor-product cubic Hermite interpolant
whose node slopes are the monotone PCHIP slopes (Fritsch & Carlson 1980) along each axis
(mixed derivatives by applying them in turn). It has no kinks at grid lines -- an ODE solver
stepping across them does not chatter -- does not overshoot between monotone data, and
refuses to extrapolate (:class:`~sealsim.errors.InputError`) unless asked to clip. A scalar
call costs a few µs (pure Python on precomputed cell coefficients); arrays are vectorised.
"""

from __future__ import annotations

import bisect
import itertools
import math

import numpy as np
import xarray as xr
from scipy.interpolate import PchipInterpolator

from sealsim.errors import InputError
from sealsim.files import check_input_file
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["MAP_COORDS", "MAP_VARIABLES", "PROFILE_VARIABLES", "HermiteGrid", "SealMap",
           "load_map"]

MAP_VARIABLES = {
    "F_N": ("N", "normal force on the sealing surface (full circumference)"),
    "F_N_per_length": ("N/m", "normal force per unit circumferential length"),
    "b": ("m", "contact width on the sealing surface"),
    "p_max": ("Pa", "peak contact pressure on the sealing surface"),
    "p_mean": ("Pa", "mean contact pressure F_N / (2 pi R b)"),
    "F_groove_bottom": ("N", "normal force on the groove bottom (full circumference)"),
}
"""Scalar map variables (dimensions squeeze, temperature, pressure): unit, description."""

PROFILE_VARIABLES = {
    "contact_zones": ("1", "number of separate contact zones on the sealing surface"),
    "b_span": ("m", "distance from the first to the last contact edge on the sealing surface"),
}
"""Further scalar variables of a map (not interpolated by :class:`SealMap`)."""

MAP_COORDS = {
    "squeeze": ("1", "squeeze (1 - gland depth / cord diameter)"),
    "temperature": ("K", "temperature"),
    "pressure": ("Pa", "fluid (gauge) pressure on the upstream side"),
}


# -- interpolation --------------------------------------------------------------------------------

def _hermite_basis(t):
    """Cubic Hermite basis [h00, h10, h01, h11] at t in [0, 1] (h10, h11 multiply h·slope)."""
    t2 = t * t
    t3 = t2 * t
    return (2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + t, -2 * t3 + 3 * t2, t3 - t2)


def _slopes(x, values, axis):
    """Nodal PCHIP slopes along ``axis`` (linear for two nodes)."""
    if len(x) == 2:
        d = np.diff(values, axis=axis) / (x[1] - x[0])
        return np.concatenate([d, d], axis=axis)
    return PchipInterpolator(x, values, axis=axis).derivative()(x)


class HermiteGrid:
    """C¹ piecewise-cubic Hermite interpolation on a rectilinear grid (PCHIP slopes).

    Parameters
    ----------
    axes : list of array_like
        Strictly ascending grid coordinates, at least two per axis.
    values : numpy.ndarray
        Shape ``(len(axes[0]), ..., len(axes[-1]), nvars)``.

    Examples
    --------
    >>> x = np.linspace(0.0, 1.0, 5)
    >>> y = np.linspace(0.0, 2.0, 4)
    >>> f = (x[:, None] + 2 * y[None, :])[..., None]
    >>> g = HermiteGrid([x, y], f)
    >>> round(g.evaluate_scalar((0.3, 1.1))[0], 12)
    2.5
    """

    def __init__(self, axes, values):
        self.axes = [np.asarray(a, dtype=float) for a in axes]
        values = np.asarray(values, dtype=float)
        d = len(self.axes)
        self.ndim = d
        self.nvars = values.shape[-1]
        for k, a in enumerate(self.axes):
            if a.ndim != 1 or a.size < 2 or np.any(np.diff(a) <= 0):
                raise InputError(f"map axis {k} must be strictly ascending with >= 2 values")
            if values.shape[k] != a.size:
                raise InputError("map values do not match the grid")
        if not np.all(np.isfinite(values)):
            raise InputError("map values contain NaN or inf")
        # derivatives D_S for every subset S of axes (bitmask m)
        derivs = {}
        for mask in range(2**d):
            arr = values
            for k in range(d):
                if mask >> k & 1:
                    arr = _slopes(self.axes[k], arr, axis=k)
            derivs[mask] = arr
        # per-cell coefficients C[cell..., b_1, ..., b_d, var] with basis index b = 2 a + m
        cells = tuple(a.size - 1 for a in self.axes)
        coeff = np.zeros(cells + (4,) * d + (self.nvars,))
        h = [np.diff(a) for a in self.axes]
        for combo in itertools.product(range(4), repeat=d):
            corner = [(b >> 1) & 1 for b in combo]  # a: 0 left node, 1 right node
            order = [b & 1 for b in combo]  # m: value or slope
            mask = sum(m << k for k, m in enumerate(order))
            data = derivs[mask]
            sl = tuple(slice(c, c + n) for c, n in zip(corner, cells))
            block = data[sl]
            for k, m in enumerate(order):
                if m:
                    shape = [1] * d + [1]
                    shape[k] = -1
                    block = block * h[k].reshape(shape)
            idx = (Ellipsis,) + tuple(combo) + (slice(None),)
            coeff[idx] = block
        self.coeff = coeff
        #: node values and derivatives, shape (n_0, ..., n_{d-1}, 2**d, nvars): entry m holds
        #: the derivative along the axes k with bit k of m set (m = 0: the values); a cell's
        #: coefficient of basis (a, m) per axis is the corner node's entry m times the cell
        #: widths h_k of those axes, multiplied in axis order (what C code rebuilds from it)
        self.node_derivatives = np.stack([derivs[m] for m in range(2**d)], axis=d)
        # basis order in combo: b = 2 a + m -> [h00 (a0,m0), h10 (a0,m1), h01 (a1,m0), h11]
        self._axes_list = [a.tolist() for a in self.axes]
        self._flat = coeff.reshape(-1, 4**d, self.nvars)
        self._row_lists = None
        self._cells = cells

    @property
    def _rows(self):
        """The cell coefficients as nested lists (fast scalar evaluation), made on first use:
        for a friction table (T, Δp, u, two directions) that takes 0.5 s, and the compiled
        paths never need it."""
        if self._row_lists is None:
            self._row_lists = self._flat.tolist()
        return self._row_lists

    # scalar fast path ----------------------------------------------------------------------
    def evaluate_scalar(self, point):
        """Interpolated variables at one point (inside the grid), as a tuple of floats."""
        d = self.ndim
        cell = 0
        bases = []
        for k in range(d):
            ax = self._axes_list[k]
            x = point[k]
            i = bisect.bisect_right(ax, x) - 1
            n = len(ax) - 1
            if i < 0:
                i = 0
            elif i >= n:
                i = n - 1
            t = (x - ax[i]) / (ax[i + 1] - ax[i])
            t2 = t * t
            t3 = t2 * t
            bases.append((2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + t, -2 * t3 + 3 * t2, t3 - t2))
            cell = cell * self._cells[k] + i
        rows = self._rows[cell]
        if d == 1:
            w = bases[0]
        elif d == 2:
            b0, b1 = bases
            w = [u * v for u in b0 for v in b1]
        else:
            w = [1.0]
            for b in bases:
                w = [u * v for u in w for v in b]
        out = [0.0] * self.nvars
        for j, wj in enumerate(w):
            r = rows[j]
            for v in range(self.nvars):
                out[v] += wj * r[v]
        return tuple(out)

    # vectorised --------------------------------------------------------------------------------
    def evaluate(self, points):
        """Interpolated variables at points of shape (n, ndim) → (n, nvars)."""
        pts = np.atleast_2d(np.asarray(points, dtype=float))
        n = pts.shape[0]
        d = self.ndim
        cell = np.zeros(n, dtype=np.int64)
        w = np.ones((n, 1))
        for k in range(d):
            ax = self.axes[k]
            i = np.clip(np.searchsorted(ax, pts[:, k], side="right") - 1, 0, ax.size - 2)
            t = (pts[:, k] - ax[i]) / (ax[i + 1] - ax[i])
            b = np.stack(_hermite_basis(t), axis=-1)  # (n, 4)
            w = (w[:, :, None] * b[:, None, :]).reshape(n, -1)
            cell = cell * self._cells[k] + i
        return np.einsum("nj,njv->nv", w, self._flat[cell])


# -- the map object -------------------------------------------------------------------------------

class SealMap:
    """Characteristic diagram of a seal: F_N and b as smooth functions of the load.

    Parameters
    ----------
    dataset : xarray.Dataset
        A dataset as written by :func:`compute_map`.
    extrapolate : {"error", "clip"}
        Outside the grid: raise :class:`InputError` (default) or clamp to the grid edge.

    Notes
    -----
    Axes with a single value (e.g. one squeeze) are not interpolated; a value given for
    them must match it (within 1e-9 relative).
    """

    def __init__(self, dataset: xr.Dataset, extrapolate: str = "error"):
        if extrapolate not in ("error", "clip"):
            raise InputError(f"extrapolate: {extrapolate!r} is not allowed; use 'error' or 'clip'")
        self.dataset = dataset
        self.extrapolate = extrapolate
        self.dims = ["squeeze", "temperature", "pressure"]
        missing = [d for d in self.dims if d not in dataset.dims]
        if missing:
            raise InputError(f"map dataset lacks the dimension(s) {missing}")
        self.variables = [v for v in MAP_VARIABLES if v in dataset.data_vars]
        data = np.stack([dataset[v].transpose(*self.dims).values for v in self.variables],
                        axis=-1)
        self.coords = {d: np.asarray(dataset[d].values, dtype=float) for d in self.dims}
        self.active = [d for d in self.dims if self.coords[d].size > 1]
        index = tuple(slice(None) if d in self.active else 0 for d in self.dims)
        self._grid = HermiteGrid([self.coords[d] for d in self.active], data[index])
        self._lo = [float(self.coords[d][0]) for d in self.active]
        self._hi = [float(self.coords[d][-1]) for d in self.active]
        self._fn = self.variables.index("F_N")
        self._b = self.variables.index("b")

    @property
    def ranges(self) -> dict:
        """(min, max) of every axis in SI units."""
        return {d: (float(self.coords[d][0]), float(self.coords[d][-1])) for d in self.dims}

    def _check(self, name, value, lo, hi):
        if self.extrapolate == "clip":
            return min(max(value, lo), hi)
        tol = 1e-9 * max(abs(lo), abs(hi), 1.0)
        if not (lo - tol <= value <= hi + tol) or math.isnan(value):
            show = {"pressure": (1e-5, "bar"), "temperature": (None, "degC"),
                    "squeeze": (100.0, "%")}[name]
            f = (lambda v: v - ZERO_CELSIUS_K) if show[0] is None else (lambda v: v * show[0])
            raise InputError(
                f"{name} = {f(value):.6g} {show[1]} is outside the characteristic map "
                f"({f(lo):.6g} ... {f(hi):.6g} {show[1]}); extend the map grid or load it with "
                "extrapolate='clip'")
        return min(max(value, lo), hi)

    def _point(self, pressure, temperature, squeeze):
        given = {"pressure": pressure, "temperature": temperature, "squeeze": squeeze}
        for d in self.dims:
            if d not in self.active and given[d] is not None:
                ref = float(self.coords[d][0])
                if abs(float(given[d]) - ref) > 1e-9 * max(abs(ref), 1.0):
                    self._check(d, float(given[d]), ref, ref)
        point = []
        for k, d in enumerate(self.active):
            if given[d] is None:
                raise InputError(f"the map varies with {d}: give a value for it")
            point.append(self._check(d, float(given[d]), self._lo[k], self._hi[k]))
        return point

    def evaluate(self, pressure, temperature, squeeze=None):
        """F_N [N] and b [m] at pressure [Pa], temperature [K] (and squeeze [-]).

        Scalars give floats; arrays (broadcast together) give arrays.
        """
        if np.ndim(pressure) == 0 and np.ndim(temperature) == 0 and np.ndim(squeeze) == 0:
            out = self._grid.evaluate_scalar(self._point(pressure, temperature, squeeze))
            return out[self._fn], out[self._b]
        values = self.evaluate_all(pressure, temperature, squeeze)
        return values["F_N"], values["b"]

    __call__ = evaluate

    def evaluate_all(self, pressure, temperature, squeeze=None) -> dict:
        """All map variables (dict of arrays) at broadcast points."""
        arrays = np.broadcast_arrays(np.asarray(pressure, float), np.asarray(temperature, float),
                                     np.asarray(np.nan if squeeze is None else squeeze, float))
        shape = arrays[0].shape
        flat = [a.ravel() for a in arrays]
        given = dict(zip(["pressure", "temperature", "squeeze"], flat))
        cols = []
        for k, d in enumerate(self.active):
            col = given[d]
            if np.any(np.isnan(col)):
                raise InputError(f"the map varies with {d}: give a value for it")
            if self.extrapolate == "error":
                bad = (col < self._lo[k] - 1e-9 * abs(self._lo[k])) | \
                      (col > self._hi[k] + 1e-9 * abs(self._hi[k]))
                if np.any(bad):
                    self._check(d, float(col[np.argmax(bad)]), self._lo[k], self._hi[k])
            cols.append(np.clip(col, self._lo[k], self._hi[k]))
        for d in self.dims:
            if d not in self.active and not np.all(np.isnan(given[d])):
                ref = float(self.coords[d][0])
                dev = np.abs(given[d] - ref) > 1e-9 * max(abs(ref), 1.0)
                if np.any(dev):
                    self._check(d, float(given[d][np.argmax(dev)]), ref, ref)
        values = self._grid.evaluate(np.stack(cols, axis=-1))
        return {v: values[:, i].reshape(shape) for i, v in enumerate(self.variables)}


def load_map(path, extrapolate: str = "error") -> SealMap:
    """Read a ``map.nc`` written by ``sealsim structure map`` into a :class:`SealMap`."""
    p = check_input_file(path, "map file")
    try:
        with xr.open_dataset(p) as ds:
            ds = ds.load()
    except Exception as exc:  # netCDF errors come in many types
        raise InputError(f"map file {str(p)!r} is not a readable netCDF map: {exc}") from None
    return SealMap(ds, extrapolate=extrapolate)
