r"""Fluid pressure on the wetted part of the seal surface (a follower load), as an FElupe item.

The fluid reaches the seal at the upstream groove corner and wets the free surface up to the
*contact edges*; inside the edge element the edge is interpolated from the contact pressure
profile (square-root edge), so that the load -- and with it F_N(p) -- changes smoothly with
the pressure and the deformation. (Letting the fluid penetrate the contact where the contact
pressure is below the fluid pressure, as commercial codes optionally do, was tried: with
frictionless contact it destabilises the rolling mode of the O-ring section at a few bar.)

The load is the consistent nodal force of a pressure p acting against the outward normal of
the deformed boundary segments (2-node lines). For an axisymmetric model the segment force is
integrated over the full circumference, :math:`f_a = p \int N_a\,\hat n\,2\pi r\,ds`; for a
plane-strain model per unit thickness. The wetted fractions are updated by the solver before
every Newton iteration and held fixed within it (their change is not linearised).
"""

from __future__ import annotations

import numpy as np
from felupe.mechanics import Assemble, Results
from scipy.sparse import coo_matrix

__all__ = ["FluidPressure", "segment_moments", "wetted_fractions"]

_ROT = np.array([[0.0, 1.0], [-1.0, 0.0]])  # (t_x, t_y) -> (t_y, -t_x): outward for CCW loops


def segment_moments(s0, s1):
    r"""Integrals of the linear shape functions over the wetted part [s0, s1] of a segment.

    Returns the first moments :math:`m_a = \int N_a\,d\xi` (shape (2, n)) and the second
    moments :math:`M_{ab} = \int N_a N_b\,d\xi` (shape (2, 2, n)) with
    :math:`N_0 = 1 - \xi`, :math:`N_1 = \xi`.

    Examples
    --------
    >>> m, M = segment_moments(np.array([0.0]), np.array([1.0]))
    >>> m[:, 0].tolist(), (M[:, :, 0] * 6).round(12).tolist()
    ([0.5, 0.5], [[2.0, 1.0], [1.0, 2.0]])
    """
    s0 = np.asarray(s0, dtype=float)
    s1 = np.asarray(s1, dtype=float)

    def prim(s):
        return (s - s**2 / 2, s**2 / 2, s - s**2 + s**3 / 3, s**2 / 2 - s**3 / 3, s**3 / 3)

    p0, p1 = prim(s0), prim(s1)
    d = [b - a for a, b in zip(p0, p1)]
    m = np.stack([d[0], d[1]])
    M = np.stack([np.stack([d[2], d[3]]), np.stack([d[3], d[4]])])
    return m, M


def wetted_fractions(contact_pressure, lengths, start):
    """Wetted interval [s0, s1] of every segment of a closed loop of boundary nodes.

    The fluid wets the free surface from the loop node ``start`` in both directions up to
    the contact edges. In the segment between the last free node and the first node in
    contact the edge is placed where the contact pressure, extrapolated with p² linear in
    arc length from the first two nodes in contact, falls to zero (the square-root edge of a
    smooth contact) -- so the wetted surface, and the load, move continuously with the
    contact edge instead of jumping node by node.

    Parameters
    ----------
    contact_pressure : numpy.ndarray
        Contact pressure [Pa] at the loop nodes (0 where free).
    lengths : numpy.ndarray
        Length [m] of segment k (loop node k to k+1).
    start : int
        Loop position where the fluid arrives (a free node).

    Returns
    -------
    (s0, s1) : numpy.ndarray
        Wetted interval of segment k, as fractions of its length from node k.

    Examples
    --------
    >>> pc = np.array([0.0, 0.0, 1.0, 2.0, 2.0, 0.0])
    >>> s0, s1 = wetted_fractions(pc, np.ones(6), 0)
    >>> s0.tolist(), s1.tolist()
    ([0.0, 0.0, 0.0, 0.0, 0.5, 0.0], [1.0, 0.6666666666666667, 0.0, 0.0, 1.0, 1.0])
    """
    n = len(contact_pressure)
    dry = contact_pressure > 0.0
    s0 = np.zeros(n)
    s1 = np.zeros(n)
    if dry[start]:
        return s0, s1
    if not np.any(dry):
        s1[:] = 1.0
        return s0, s1

    def edge_distance(j, j2, seg_in, seg_out):
        """Distance from dry node j back into the free segment where p reaches zero."""
        pj2, pk2 = contact_pressure[j] ** 2, contact_pressure[j2] ** 2
        length = lengths[seg_out]
        if pk2 > pj2:
            d = lengths[seg_in] * pj2 / (pk2 - pj2)
        else:
            d = 0.5 * length
        return min(d, length)

    k = start
    while not dry[(k + 1) % n]:
        s1[k] = 1.0
        k = (k + 1) % n
    j = (k + 1) % n
    d = edge_distance(j, (j + 1) % n, j, k)
    s1[k] = 1.0 - d / lengths[k]
    k = start
    while not dry[(k - 1) % n]:
        seg = (k - 1) % n
        s0[seg], s1[seg] = 0.0, 1.0
        k = (k - 1) % n
    i = (k - 1) % n  # dry; segment i runs from i (dry) to k (free)
    d = edge_distance(i, (i - 1) % n, (i - 1) % n, i)
    if s1[i] == 0.0:
        s0[i], s1[i] = d / lengths[i], 1.0
    return s0, s1


class FluidPressure:
    """Pressure on the wetted boundary segments of a 2d (axisymmetric or plane) seal mesh.

    Parameters
    ----------
    field : felupe.FieldContainer
        Field container with the displacement field first.
    loop : numpy.ndarray
        Closed counter-clockwise loop of boundary node ids.
    axisymmetric : bool
        Integrate over 2π r (y = radius) if True, per unit thickness otherwise.
    """

    def __init__(self, field, loop, axisymmetric=True):
        self.field = field
        self.loop = np.asarray(loop)
        self.axisymmetric = axisymmetric
        self.pressure = 0.0
        n = len(self.loop)
        self.s0 = np.zeros(n)
        self.s1 = np.zeros(n)
        self.assemble = Assemble(vector=self._vector, matrix=self._matrix)
        self.results = Results()
        mesh = field.region.mesh
        self._size = mesh.npoints * mesh.dim
        a = self.loop
        b = np.roll(self.loop, -1)
        dof = np.stack([2 * a, 2 * a + 1, 2 * b, 2 * b + 1], axis=1)  # (n, 4)
        self._rows = np.repeat(dof, 4, axis=1).ravel()
        self._cols = np.tile(dof, (1, 4)).ravel()
        self._dof = dof

    def update(self, pressure):
        self.pressure = float(pressure)

    def positions(self):
        """Current coordinates of the loop nodes (n, 2) [m]."""
        u = self.field[0].values
        X = self.field.region.mesh.points
        return X[self.loop] + u[self.loop]

    def segments(self):
        x = self.positions()
        return x, np.roll(x, -1, axis=0)

    def wetted_length(self):
        xa, xb = self.segments()
        return float(np.sum((self.s1 - self.s0) * np.linalg.norm(xb - xa, axis=1)))

    def update_wetting(self, contact_pressure, entry):
        """Recompute the wetted intervals; returns the change of the wetted length [m].

        Parameters
        ----------
        contact_pressure : numpy.ndarray
            Contact pressure [Pa] at the loop nodes.
        entry : tuple of float
            (x, y) where the fluid reaches the groove: the wetting starts at the nearest free
            node.
        """
        old = self.wetted_length()
        x = self.positions()
        lengths = np.linalg.norm(np.roll(x, -1, axis=0) - x, axis=1)
        dist = np.linalg.norm(x - np.asarray(entry), axis=1)
        dist[contact_pressure > 0.0] = np.inf
        if not np.isfinite(dist).any() or self.pressure <= 0.0:
            self.s0[:] = 0.0
            self.s1[:] = 0.0
        else:
            self.s0, self.s1 = wetted_fractions(contact_pressure, lengths, int(np.argmin(dist)))
        return abs(self.wetted_length() - old)

    def _terms(self):
        xa, xb = self.segments()
        t = xb - xa
        nvec = t @ _ROT.T  # outward normal times segment length (CCW loop)
        m, M = segment_moments(self.s0, self.s1)
        if self.axisymmetric:
            ya, yb = xa[:, 1], xb[:, 1]
            c = 2 * np.pi * np.stack([M[0, 0] * ya + M[0, 1] * yb, M[1, 0] * ya + M[1, 1] * yb])
            dc = 2 * np.pi * M  # dc_a / dy_b
        else:
            c = m
            dc = np.zeros_like(M)
        return nvec, c, dc

    def force(self):
        """Nodal forces (n, 2, 2): [segment, node a/b, component] of the fluid on the seal."""
        nvec, c, _ = self._terms()
        return -self.pressure * np.stack([c[0][:, None] * nvec, c[1][:, None] * nvec], axis=1)

    def _vector(self, field=None, **kwargs):
        if field is not None:
            self.field = field
        f = -self.force()  # residual = internal - external
        vals = f.reshape(len(self.loop), 4).ravel()
        rows = self._dof.ravel()
        vec = coo_matrix((vals, (rows, np.zeros_like(rows))), shape=(self._size, 1)).tocsr()
        self.results.force = vec
        return vec

    def _matrix(self, field=None, **kwargs):
        if field is not None:
            self.field = field
        rows, cols, vals = self.stiffness_entries()
        mat = coo_matrix((vals, (rows, cols)), shape=(self._size, self._size)).tocsr()
        self.results.stiffness = mat
        return mat

    def stiffness_entries(self):
        """(rows, cols, values) of the follower-load stiffness (global dofs)."""
        nvec, c, dc = self._terms()
        p = self.pressure
        n = len(self.loop)
        K = np.zeros((n, 2, 2, 2, 2))  # [seg, node_i, comp_i, node_j, comp_j]
        ey = np.array([0.0, 1.0])
        for a in range(2):
            for b in range(2):
                sign = 1.0 if b == 1 else -1.0  # d(nvec)/dx_b = ±R
                follower = sign * c[a][:, None, None] * _ROT[None]
                area = np.einsum("si,j->sij", nvec, ey) * dc[a, b][:, None, None]
                K[:, a, :, b, :] = p * (follower + area)
        return self._rows, self._cols, K.reshape(n, 16).ravel()
