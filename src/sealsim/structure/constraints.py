r"""Scalar penalty items: the anti-rolling spring, the axial symmetry hold, the garter spring.

Each item is a potential :math:`\Pi(c)` of one scalar :math:`c = \mathbf g \cdot \mathbf u`
that is linear in the displacements of a few nodes, so it adds :math:`\Pi'(c)\,\mathbf g` to the
residual and the rank-one matrix :math:`\Pi''(c)\,\mathbf g \otimes \mathbf g` (an FElupe item
with ``assemble.vector`` / ``assemble.matrix``).

**Anti-rolling spring** (:class:`RollingConstraint`). With frictionless contact on all sides
an O-ring section pressed into the groove corner by the fluid pressure has an almost free
rotation ("rolling") mode; static friction holds it in a real gland (model it with a friction
coefficient on the gland, :class:`~.model.SealModel`). The spring is the older alternative:
a stiff rotational spring on the mean rotation of the section's core,

.. math::

    \theta(u) = \frac{\sum_s (X_s - \bar X) \times u(X_s)}{\sum_s |X_s - \bar X|^2},
    \qquad \Pi = \tfrac12\,k\,\theta^2,

over sample points :math:`X_s` on two rings of eight points around the section centre,
symmetric about the radial and the axial line through it; :math:`u(X_s)` is interpolated
with the bilinear shape functions of the quad that holds the point. For a deformation that
is mirror-symmetric about the radial line through the centre (a pure squeeze between rod and
groove bottom) θ is zero -- exactly on a mirror-symmetric mesh -- so the spring reads no
rotation and carries no moment. The constraint moment k θ is reported with the results.

**Axial hold** (:class:`AxialPositionConstraint`): a gland without side walls leaves the
section's axial translation free; :math:`\Pi = \tfrac12 k\,\bar u_x^2` on the mean axial
displacement of the same sample points holds it (symmetry) and lets the section bulge.

**Garter spring** (:class:`GarterSpring`): the closed coil spring of a radial lip seal is a
ring of hoop tension :math:`T = T_0 + k_s\,2\pi\,(r - r_0)` (pre-tension :math:`T_0` at the
radius :math:`r_0` of the free seal, axial rate :math:`k_s` of the straight coil spring). A
ring under tension T presses with :math:`q = T/r` per unit length, :math:`2\pi T` in total,
on its seat (Timoshenko, Strength of Materials I, thin ring under radial load). With the mean
radial displacement c of the seat nodes, :math:`r = r_0 + c` and the potential

.. math:: \Pi(c) = 2\pi\,(T_0\,c + \pi k_s\,c^2),\qquad \Pi' = 2\pi T,\qquad \Pi'' = 4\pi^2 k_s.
"""

from __future__ import annotations

import numpy as np
from felupe.mechanics import Assemble, Results
from scipy.sparse import coo_matrix

__all__ = ["AxialPositionConstraint", "GarterSpring", "RollingConstraint", "ScalarPenalty",
           "interpolation_weights", "ring_samples"]


def ring_samples(centre, radius, rings=(0.5, 1.0), per_ring: int = 8) -> np.ndarray:
    """Sample points on rings around ``centre``, mirror-symmetric about both axes.

    Parameters
    ----------
    centre : tuple of float
        (x, y) [m].
    radius : float
        Radius of the outer ring [m].
    rings : tuple of float
        Ring radii as fractions of ``radius``.
    per_ring : int
        Points per ring (a multiple of 4), at (k + ½)·360°/per_ring.

    Examples
    --------
    >>> p = ring_samples((0.0, 1.0), 0.1)
    >>> p.shape, np.allclose(p[:, 0].sum(), 0.0)
    ((16, 2), True)
    """
    phi = (np.arange(per_ring) + 0.5) * 2 * np.pi / per_ring
    unit = np.stack([np.cos(phi), np.sin(phi)], axis=1)
    return np.concatenate([np.asarray(centre) + f * radius * unit for f in rings])


def interpolation_weights(points, cells, samples):
    """Bilinear shape-function weights of sample points in a quad mesh.

    Parameters
    ----------
    points : numpy.ndarray
        (n, 2) node coordinates [m].
    cells : numpy.ndarray
        (m, 4) quads, counter-clockwise.
    samples : numpy.ndarray
        (k, 2) points inside the mesh [m].

    Returns
    -------
    nodes : numpy.ndarray
        (k, 4) node ids of the quad holding each sample.
    weights : numpy.ndarray
        (k, 4) shape-function values N_a at each sample (sum 1).

    Examples
    --------
    >>> pts = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    >>> nodes, w = interpolation_weights(pts, np.array([[0, 1, 2, 3]]), np.array([[0.25, 0.5]]))
    >>> w.round(6).tolist()
    [[0.375, 0.125, 0.125, 0.375]]
    """
    xi0 = np.array([-1.0, 1.0, 1.0, -1.0])
    eta0 = np.array([-1.0, -1.0, 1.0, 1.0])
    P = points[cells]  # (m, 4, 2)
    lo, hi = P.min(axis=1), P.max(axis=1)
    nodes = np.zeros((len(samples), 4), dtype=int)
    weights = np.zeros((len(samples), 4))
    for s, x in enumerate(np.asarray(samples, dtype=float)):
        cand = np.nonzero(np.all((lo <= x + 1e-12) & (x - 1e-12 <= hi), axis=1))[0]
        best, best_err = None, np.inf
        for c in cand:
            X = P[c]
            xi = np.zeros(2)
            for _ in range(20):
                N = 0.25 * (1 + xi0 * xi[0]) * (1 + eta0 * xi[1])
                dN = 0.25 * np.stack([xi0 * (1 + eta0 * xi[1]), eta0 * (1 + xi0 * xi[0])])
                r = N @ X - x
                J = dN @ X  # (2 local, 2 global)
                step = np.linalg.solve(J.T, r)
                xi = xi - step
                if np.linalg.norm(step) < 1e-13:
                    break
            err = max(abs(xi[0]), abs(xi[1])) - 1.0
            if err < best_err:
                best, best_err = (c, xi.copy()), err
            if err <= 1e-9:
                break
        if best is None or best_err > 1e-6:
            raise ValueError(f"sample point {x} is not inside the mesh")
        c, xi = best
        nodes[s] = cells[c]
        weights[s] = 0.25 * (1 + xi0 * xi[0]) * (1 + eta0 * xi[1])
    return nodes, weights


class ScalarPenalty:
    """An FElupe item with the potential Π(c) of the scalar c = g·u + c0 (module docstring).

    Parameters
    ----------
    field : felupe.FieldContainer
        Field container with the displacement field first.
    dofs : numpy.ndarray
        Global dof numbers the scalar depends on.
    coefficients : numpy.ndarray
        g, one per dof.
    """

    def __init__(self, field, dofs, coefficients):
        self.field = field
        dofs = np.asarray(dofs)
        coefficients = np.asarray(coefficients, dtype=float)
        # merge repeated dofs (a node shared by several sample points)
        self._dof, inverse = np.unique(dofs, return_inverse=True)
        self._g = np.zeros(len(self._dof))
        np.add.at(self._g, inverse, coefficients)
        mesh = field.region.mesh
        self._size = mesh.npoints * mesh.dim
        self.assemble = Assemble(vector=self._vector, matrix=self._matrix)
        self.results = Results()

    def value(self) -> float:
        """The scalar c."""
        u = self.field[0].values.ravel()
        return float(self._g @ u[self._dof])

    def derivatives(self, c: float) -> tuple[float, float]:
        """(Π'(c), Π''(c)); a subclass defines them."""
        raise NotImplementedError

    def _vector(self, field=None, **kwargs):
        if field is not None:
            self.field = field
        d1, _ = self.derivatives(self.value())
        vec = coo_matrix((d1 * self._g, (self._dof, np.zeros_like(self._dof))),
                         shape=(self._size, 1)).tocsr()
        self.results.force = vec
        return vec

    def stiffness_entries(self):
        """(rows, cols, values) of the stiffness Π''(c) g gᵀ (global dofs)."""
        _, d2 = self.derivatives(self.value())
        rows = np.repeat(self._dof, len(self._dof))
        cols = np.tile(self._dof, len(self._dof))
        return rows, cols, d2 * np.outer(self._g, self._g).ravel()

    def _matrix(self, field=None, **kwargs):
        if field is not None:
            self.field = field
        rows, cols, vals = self.stiffness_entries()
        mat = coo_matrix((vals, (rows, cols)), shape=(self._size, self._size)).tocsr()
        self.results.stiffness = mat
        return mat


def _sample_dofs(nodes, weights, component):
    return (2 * nodes + component).ravel(), weights.ravel()


class RollingConstraint(ScalarPenalty):
    """Rotational penalty spring on the mean rotation of sample points around a centre.

    Parameters
    ----------
    field : felupe.FieldContainer
        Field container with the displacement field first.
    samples : numpy.ndarray
        (k, 2) sample points (:func:`ring_samples`) inside the mesh [m].
    stiffness : float
        Rotational stiffness k [N·m/rad] (full circumference for an axisymmetric model).

    Examples
    --------
    >>> import felupe as fem
    >>> mesh = fem.Rectangle(n=5)
    >>> field = fem.FieldContainer([fem.FieldPlaneStrain(fem.RegionQuad(mesh), dim=2)])
    >>> rc = RollingConstraint(field, ring_samples((0.5, 0.5), 0.3), 2.0)
    >>> field[0].values[:] = 0.01 * (mesh.points - 0.5) @ np.array([[0.0, 1.0], [-1.0, 0.0]])
    >>> round(rc.rotation(), 6), round(rc.moment(), 6)
    (0.01, 0.02)
    """

    def __init__(self, field, samples, stiffness):
        mesh = field.region.mesh
        nodes, w = interpolation_weights(mesh.points, mesh.cells, samples)
        d = samples - samples.mean(axis=0)
        S = np.sum(d**2)
        # theta = sum_s (d_x u_y - d_y u_x) / S with u_s = sum_a N_a u_a
        gx = -(d[:, 1:2] * w) / S
        gy = (d[:, 0:1] * w) / S
        dofs = np.concatenate([2 * nodes.ravel(), 2 * nodes.ravel() + 1])
        super().__init__(field, dofs, np.concatenate([gx.ravel(), gy.ravel()]))
        self.stiffness = float(stiffness)

    def rotation(self) -> float:
        """Mean rotation θ [rad] of the sample points (counter-clockwise positive)."""
        return self.value()

    def moment(self) -> float:
        """Constraint moment k θ [N·m] (full circumference for an axisymmetric model)."""
        return self.stiffness * self.rotation()

    def derivatives(self, c):
        return self.stiffness * c, self.stiffness


class AxialPositionConstraint(ScalarPenalty):
    """Penalty ½ k ū_x² on the mean axial displacement of sample points (symmetry hold).

    Parameters
    ----------
    field : felupe.FieldContainer
        Field container with the displacement field first.
    samples : numpy.ndarray
        (k, 2) sample points inside the mesh [m].
    stiffness : float
        k [N/m] (full circumference for an axisymmetric model).
    """

    def __init__(self, field, samples, stiffness):
        mesh = field.region.mesh
        nodes, w = interpolation_weights(mesh.points, mesh.cells, samples)
        super().__init__(field, 2 * nodes.ravel(), w.ravel() / len(samples))
        self.stiffness = float(stiffness)

    def derivatives(self, c):
        return self.stiffness * c, self.stiffness


class GarterSpring(ScalarPenalty):
    """Garter spring of a radial lip seal acting on its seat (module docstring).

    Parameters
    ----------
    field : felupe.FieldContainer
        Axisymmetric field container (y = radius) with the displacement field first.
    nodes : numpy.ndarray
        Node ids of the spring seat.
    rate : float
        Axial spring rate k_s of the straight coil spring [N/m].
    tension : float
        Pre-tension T_0 [N] in the free seal.

    Examples
    --------
    >>> import felupe as fem
    >>> mesh = fem.Rectangle(a=(0.0, 1.0), b=(1.0, 2.0), n=3)
    >>> field = fem.FieldContainer([fem.FieldAxisymmetric(fem.RegionQuad(mesh), dim=2)])
    >>> spring = GarterSpring(field, np.array([6, 7, 8]), rate=10.0, tension=2.0)
    >>> field[0].values[[6, 7, 8], 1] = 0.01     # the seat moves out by 0.01 m
    >>> round(spring.tension(), 6), round(spring.radial_force(), 6)
    (2.628319, 16.514212)
    """

    def __init__(self, field, nodes, rate, tension):
        nodes = np.asarray(nodes)
        super().__init__(field, 2 * nodes + 1, np.full(len(nodes), 1.0 / len(nodes)))
        self.rate = float(rate)
        self.pretension = float(tension)
        self.scale = 1.0  # the spring being put on: its force ramps from 0 to 1

    def tension(self) -> float:
        """Hoop tension T [N] at the current seat radius (times the put-on scale)."""
        return self.scale * (self.pretension + self.rate * 2 * np.pi * self.value())

    def radial_force(self) -> float:
        """Total radial force 2π T [N] of the spring on the seal (inwards)."""
        return 2 * np.pi * self.tension()

    def derivatives(self, c):
        return 2 * np.pi * self.scale * (self.pretension + self.rate * 2 * np.pi * c), \
            4 * np.pi**2 * self.rate * self.scale
