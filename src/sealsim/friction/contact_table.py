r"""The steady friction of a seal from its own contact, tabulated: the plain-array table the
friction laws take their steady curve from.

A seal's steady friction per unit circumference comes from its contact pressure profile
p_c(z) by inverse hydrodynamics and mixed lubrication
(:func:`sealsim.tribology.mixed_lubrication.reciprocating_friction`) at every temperature,
pressure difference and speed; :mod:`sealsim.pneumatic.friction_tables` builds the table from
a seal's contact map and caches it.  The table stores, per stroke direction (+: the counter
surface slides towards +z of the seal's profile, −: back):

==================  ======  ==========================================================
variable            unit    meaning
==================  ======  ==========================================================
asperity_load_pos   N/m     load carried by the asperities, α·F'_N (boundary friction
                            μ_b·α·F'_N: μ_b is applied when the table is read, so a
                            calibration can fit it without rebuilding the table)
viscous_pos         N/m     viscous friction ∫ η·u/h + h/2·(1 − α)·dp/dz dz
asperity_load_neg   N/m     the same for the other direction
viscous_neg         N/m
film_pos, film_neg  m       film at the pressure maximum h*
film_decay_rate     1/s     decay rate κ of the speed φ the film stands for when the seal
                            stops, dφ/dt = −κ·φ: the film squeezed out by the load it
                            carries (:func:`sealsim.tribology.squeeze_film.film_speed_decay_rate`),
                            the mean of both stroke directions' films (one rate whatever the
                            direction: the film's state evolves continuously through v = 0)
==================  ======  ==========================================================

over the axes temperature [K], pressure difference [Pa] and log10 of the speed [m/s].  The
friction of a seal of sliding diameter D at speed v > 0 is

    F(v) = π·D·[μ_b·asperity_load_pos + viscous_pos](T, Δp, log10 v)

(and with the ``_neg`` columns for v < 0, with the sign of v).  Between the nodes the table is
the C¹ tensor-product cubic Hermite interpolant with monotone PCHIP node slopes (Fritsch &
Carlson 1980), the interpolant of the FE maps (:class:`sealsim.structure.maps.HermiteGrid`);
outside its axes it is clamped (below the slowest speed the contact is boundary lubricated and
its values hardly change).  The table is plain arrays -- an int64 layout row and one float64
array (:meth:`SteadyFrictionTable.tables`) -- read by the compiled kernel
:func:`contact_table_point` in numba code; the FMUs' C code reads the same interpolant from
its node values and derivatives (:meth:`SteadyFrictionTable.node_tables`, 8× smaller).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from sealsim.errors import InputError

__all__ = ["TABLE_VARIABLES", "SteadyFrictionTable", "cell_sum", "cell_sum_pair",
           "contact_table_point", "film_decay_rate",
           "hermite_basis", "locate_on_axis", "speed_cell", "table_cell"]

#: variables of the table, in the order of its last axis (see the module docstring)
TABLE_VARIABLES = ("asperity_load_pos", "viscous_pos", "asperity_load_neg", "viscous_neg",
                   "film_pos", "film_neg", "film_decay_rate")
#: index of the film's decay-rate column
FILM_DECAY = 6
#: layout row: n_T, n_p, n_u, n_vars (the data array holds the three axes, then the cell
#: coefficients, shape (n_T - 1, n_p - 1, n_u - 1, 4, 4, 4, n_vars), C order)
_ROW = 4


@njit(cache=True)
def hermite_basis(t):
    """The cubic Hermite basis functions (h00, h10, h01, h11) at t in [0, 1]."""
    t2 = t * t
    t3 = t2 * t
    return (2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + t, -2 * t3 + 3 * t2, t3 - t2)


@njit(cache=True)
def locate_on_axis(data, pos, n, x):
    """(cell index, local coordinate in [0, 1]) of x on the axis data[pos:pos + n], clamped:
    the last node <= x (numpy.searchsorted side="right", minus 1), at most the last cell."""
    lo, hi = data[pos], data[pos + n - 1]
    x = min(max(x, lo), hi)
    a, b = 0, n
    while a < b:
        mid = (a + b) >> 1
        if x < data[pos + mid]:
            b = mid
        else:
            a = mid + 1
    i = min(max(a - 1, 0), n - 2)
    return i, (x - data[pos + i]) / (data[pos + i + 1] - data[pos + i])


#: basis weights of a coordinate on the cell's first node (t = 0)
_ON_NODE = (1.0, 0.0, 0.0, 0.0)


@njit(cache=True)
def table_cell(row, data, temperature, pressure):
    """(i, weights, j, weights) of the temperature and pressure cell of (T [K], Δp [Pa]), the
    table clamped to its axes: the part of a lookup that :func:`contact_steady
    <sealsim.friction.compiled.contact_steady>` shares between its speeds."""
    nt = row[0]
    i, a = locate_on_axis(data, 0, nt, temperature)
    j, b = locate_on_axis(data, nt, row[1], pressure)
    return i, hermite_basis(a), j, hermite_basis(b)


@njit(cache=True)
def cell_sum(row, data, i, wa, j, wb, k, wc, var):
    """Σ w·coefficient of one variable ``var`` (its index in :data:`TABLE_VARIABLES`) over the
    64 basis terms of cell (i, j, k) with the axis weights wa, wb, wc.  Terms of weight 0 (a
    coordinate on a node, e.g. clamped below the slowest speed) add exactly 0 and are
    skipped."""
    npr, nu, nv = row[1], row[2], row[3]
    base = row[0] + npr + nu + (((i * (npr - 1) + j) * (nu - 1) + k) * 64) * nv + var
    total = 0.0
    for q0 in range(4):
        w0 = wa[q0]
        if w0 == 0.0:
            continue
        for q1 in range(4):
            w01 = w0 * wb[q1]
            if w01 == 0.0:
                continue
            for q2 in range(4):
                w = w01 * wc[q2]
                if w == 0.0:
                    continue
                total += w * data[base + ((q0 * 4 + q1) * 4 + q2) * nv]
    return total


@njit(cache=True)
def cell_sum_pair(row, data, i, wa, j, wb, k, wc, var_a, var_b):
    """:func:`cell_sum` of two variables in one pass over the cell's basis terms (each sum in
    the same order, so each the same number as its own :func:`cell_sum`)."""
    npr, nu, nv = row[1], row[2], row[3]
    base = row[0] + npr + nu + (((i * (npr - 1) + j) * (nu - 1) + k) * 64) * nv
    total_a = 0.0
    total_b = 0.0
    for q0 in range(4):
        w0 = wa[q0]
        if w0 == 0.0:
            continue
        for q1 in range(4):
            w01 = w0 * wb[q1]
            if w01 == 0.0:
                continue
            for q2 in range(4):
                w = w01 * wc[q2]
                if w == 0.0:
                    continue
                term = base + ((q0 * 4 + q1) * 4 + q2) * nv
                total_a += w * data[term + var_a]
                total_b += w * data[term + var_b]
    return total_a, total_b


@njit(cache=True)
def speed_cell(row, data, speed):
    """(k, weights) of the speed cell of |speed| [m/s] (log10 axis, clamped)."""
    k, c = locate_on_axis(data, row[0] + row[1], row[2], math.log10(abs(speed)))
    return k, hermite_basis(c)


@njit(cache=True)
def contact_table_point(row, data, temperature, pressure, speed):
    """(asperity load [N/m], viscous friction [N/m], film [m]) of the stroke direction of
    ``speed`` at (T [K], Δp [Pa], |speed| [m/s]), the table clamped to its axes; all zero at
    speed = 0.  ``row``/``data``: :meth:`SteadyFrictionTable.tables`."""
    if speed == 0.0:
        return 0.0, 0.0, 0.0
    i, wa, j, wb = table_cell(row, data, temperature, pressure)
    k, wc = speed_cell(row, data, speed)
    off = 0 if speed > 0.0 else 2                       # the stroke direction's columns
    return (cell_sum(row, data, i, wa, j, wb, k, wc, off),
            cell_sum(row, data, i, wa, j, wb, k, wc, off + 1),
            cell_sum(row, data, i, wa, j, wb, k, wc, 4 + off // 2))


@njit(cache=True)
def _table_many(row, data, temperature, pressure, speed, load, visc, film):
    for n in range(speed.shape[0]):
        load[n], visc[n], film[n] = contact_table_point(row, data, temperature[n], pressure[n],
                                                        speed[n])


@njit(cache=True)
def _film_cell(row, data, film):
    """Speed cell of the film's speed φ [m/s] in a contact table; no film (φ ≤ 0 or not a
    number): the table's slowest speed, its first node."""
    if film > 0.0:
        return speed_cell(row, data, film)
    return 0, _ON_NODE


@njit(cache=True)
def film_decay_rate(row, data, temperature, pressure, film):
    """The film's decay rate κ [1/s] at rest of the film formed for the speed ``film`` = φ
    [m/s] at (T [K], Δp [Pa]), the table clamped to its axes (no film, φ ≤ 0: the slowest
    speed).  The C port is ``film_decay_rate`` of ``sealsim/fmu/c/contact_table.c``."""
    i, wa, j, wb = table_cell(row, data, temperature, pressure)
    k, wc = _film_cell(row, data, film)
    return cell_sum(row, data, i, wa, j, wb, k, wc, FILM_DECAY)


@njit(cache=True)
def _decay_many(row, data, temperature, pressure, film, out):
    for n in range(film.shape[0]):
        out[n] = film_decay_rate(row, data, temperature[n], pressure[n], film[n])


def _flat_conditions(speed, pressure, temperature):
    """Speed [m/s], pressure difference [Pa] and temperature [K] broadcast, as float copies."""
    return (np.array(a, dtype=float) for a in np.broadcast_arrays(
        np.asarray(speed, dtype=float), np.asarray(pressure, dtype=float),
        np.asarray(temperature, dtype=float)))


@dataclass
class SteadyFrictionTable:
    """A seal's steady friction per unit circumference over (T, Δp, log10 u) and direction.

    Parameters
    ----------
    temperature : array_like
        Temperature axis [K], ascending (>= 2 values).
    pressure : array_like
        Pressure-difference axis [Pa], ascending (>= 2 values).
    speed : array_like
        Speed axis [m/s], > 0, ascending (>= 2 values; interpolated in log10 u).
    values : numpy.ndarray
        Shape (n_T, n_p, n_u, 7): :data:`TABLE_VARIABLES` per unit circumference.
    attrs : dict
        Where the table came from (JSON-friendly), stored with it.

    Examples
    --------
    >>> t, p, u = [290.0, 300.0], [0.0, 1e5], [1e-3, 1e-2, 1e-1]
    >>> values = np.zeros((2, 2, 3, 7))
    >>> values[..., 0] = values[..., 2] = 100.0        # asperities carry 100 N/m
    >>> values[..., 1] = values[..., 3] = np.array(u) * 50.0
    >>> table = SteadyFrictionTable(t, p, u, values)
    >>> load, viscous, film = table.evaluate([0.01, -0.1], 1e5, 295.0)
    >>> load.tolist(), viscous.round(3).tolist()
    ([100.0, 100.0], [0.5, 5.0])
    """

    temperature: np.ndarray
    pressure: np.ndarray
    speed: np.ndarray
    values: np.ndarray
    attrs: dict = field(default_factory=dict)

    def __post_init__(self):
        self.temperature = np.asarray(self.temperature, dtype=float)
        self.pressure = np.asarray(self.pressure, dtype=float)
        self.speed = np.asarray(self.speed, dtype=float)
        self.values = np.asarray(self.values, dtype=float)
        shape = (self.temperature.size, self.pressure.size, self.speed.size,
                 len(TABLE_VARIABLES))
        if self.values.shape != shape:
            raise InputError(f"friction table values have shape {self.values.shape}, "
                             f"expected {shape}")
        if np.any(self.speed <= 0):
            raise InputError("friction table speeds must be > 0")
        if not np.all(np.isfinite(self.values)):
            raise InputError("friction table values contain NaN or inf")

    @property
    def ranges(self) -> dict[str, tuple[float, float]]:
        """(min, max) of each axis in SI units."""
        return {"temperature": (float(self.temperature[0]), float(self.temperature[-1])),
                "pressure": (float(self.pressure[0]), float(self.pressure[-1])),
                "speed": (float(self.speed[0]), float(self.speed[-1]))}

    def _hermite(self):
        """The interpolant (:class:`sealsim.structure.maps.HermiteGrid`, built once)."""
        grid = self.__dict__.get("_grid")
        if grid is None:
            from sealsim.structure.maps import HermiteGrid

            axes = [self.temperature, self.pressure, np.log10(self.speed)]
            grid = self.__dict__["_grid"] = HermiteGrid(axes, self.values)
        return grid

    def tables(self):
        """(int64 row, float64 data) of :func:`contact_table_point` (built once)."""
        cached = self.__dict__.get("_tables")
        if cached is None:
            grid = self._hermite()
            row = np.array([a.size for a in grid.axes] + [len(TABLE_VARIABLES)],
                           dtype=np.int64)
            data = np.concatenate(grid.axes + [np.ascontiguousarray(grid.coeff).reshape(-1)])
            cached = self.__dict__["_tables"] = (row, data)
        return cached

    def node_tables(self):
        """(int64 row, float64 data) of the same interpolant with node values and derivatives
        instead of cell coefficients -- the three axes, then shape (n_T, n_p, n_u, 8, n_vars)
        (:attr:`~sealsim.structure.maps.HermiteGrid.node_derivatives`), 8× smaller: the layout
        of the FMUs' C code (``sealsim/fmu/c/contact_table.c``), which forms each cell's
        coefficients from it exactly as :class:`~sealsim.structure.maps.HermiteGrid` does."""
        grid = self._hermite()
        row = np.array([a.size for a in grid.axes] + [len(TABLE_VARIABLES)], dtype=np.int64)
        return row, np.concatenate(grid.axes + [grid.node_derivatives.reshape(-1)])

    def evaluate(self, speed, pressure, temperature):
        """(asperity load [N/m], viscous friction [N/m], film [m]) at signed speeds [m/s],
        pressure differences [Pa] and temperatures [K] (broadcast; clamped to the axes)."""
        u, p, t = _flat_conditions(speed, pressure, temperature)
        out = [np.empty(u.shape) for _ in range(3)]
        _table_many(*self.tables(), t.reshape(-1), p.reshape(-1), u.reshape(-1),
                    *(o.reshape(-1) for o in out))
        return tuple(out)

    def film_decay(self, speed, pressure, temperature):
        """Decay rate κ [1/s] at rest of the film formed for the speed ``speed`` [m/s] at
        pressure differences [Pa] and temperatures [K] (broadcast; clamped to the axes; no
        film, speed ≤ 0: the slowest speed) -- :func:`film_decay_rate`."""
        u, p, t = _flat_conditions(speed, pressure, temperature)
        out = np.empty(u.shape)
        _decay_many(*self.tables(), t.reshape(-1), p.reshape(-1), u.reshape(-1),
                    out.reshape(-1))
        return out

    def steady_force(self, speed, pressure, temperature, diameter, boundary_friction):
        """Steady friction force F = π·D·(μ_b·load + viscous)·sgn(v) [N]."""
        load, viscous, _ = self.evaluate(speed, pressure, temperature)
        return np.pi * diameter * (boundary_friction * load + viscous) * np.sign(speed)

    # -- storage ---------------------------------------------------------------------------
    def to_dataset(self):
        """The table as an :class:`xarray.Dataset` (netCDF-ready)."""
        import json

        import xarray as xr

        dims = ("temperature", "pressure", "speed")
        units = {"asperity_load": "N/m", "viscous": "N/m", "film": "m", "film_decay": "1/s"}
        variables = {name: (dims, self.values[..., k],
                            {"units": units[name.rsplit("_", 1)[0]]})
                     for k, name in enumerate(TABLE_VARIABLES)}
        coords = {"temperature": ("temperature", self.temperature, {"units": "K"}),
                  "pressure": ("pressure", self.pressure, {"units": "Pa"}),
                  "speed": ("speed", self.speed, {"units": "m/s"})}
        return xr.Dataset(variables, coords=coords,
                          attrs={"title": "sealsim steady friction table of a seal (per unit "
                                          "circumference, from its contact pressure profile)",
                                 "parameters": json.dumps(self.attrs, sort_keys=True)})

    @classmethod
    def from_dataset(cls, dataset) -> SteadyFrictionTable:
        """Read a table written by :meth:`to_dataset`."""
        import json

        missing = [v for v in TABLE_VARIABLES if v not in dataset.data_vars]
        if missing:
            raise InputError(f"friction table lacks the variable(s) {missing}")
        values = np.stack([dataset[v].transpose("temperature", "pressure", "speed").values
                           for v in TABLE_VARIABLES], axis=-1)
        return cls(dataset["temperature"].values, dataset["pressure"].values,
                   dataset["speed"].values, values,
                   json.loads(dataset.attrs.get("parameters", "{}")))
