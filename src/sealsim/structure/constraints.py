r"""A penalty constraint on the rolling (rigid rotation) of the seal cross-section.

With frictionless contact on all sides an O-ring section pressed into the groove corner by
the fluid pressure has an almost free rotation ("rolling") mode: all contact forces act
normal to the surfaces and nearly through the centre of the section. Its stiffness falls to
zero at a few bar (the follower fluid load and the geometric stiffness of the compressed
ring), and the frictionless model rolls away. In a real gland static friction holds the
section; here a stiff rotational spring on the *mean rotation of the section's core* does
(the section may still deform and translate freely):

.. math::

    \theta(u) = \frac{\sum_a (X_a - \bar X) \times (u_a - \bar u)}{\sum_a |X_a - \bar X|^2},
    \qquad \Pi = \tfrac12\,k\,\theta^2,

summed over the core nodes a. θ is linear in the displacements, so the item adds
:math:`k\,\theta\,\partial\theta/\partial u` to the residual and the rank-one matrix
:math:`k\,(\partial\theta/\partial u) \otimes (\partial\theta/\partial u)`. The constraint
moment k θ is reported with the results (it plays the part of the friction moment).
"""

from __future__ import annotations

import numpy as np
from felupe.mechanics import Assemble, Results
from scipy.sparse import coo_matrix

__all__ = ["RollingConstraint"]


class RollingConstraint:
    """Rotational penalty spring on the mean rotation of a set of nodes (an FElupe item).

    Parameters
    ----------
    field : felupe.FieldContainer
        Field container with the displacement field first.
    nodes : numpy.ndarray
        Node ids of the section's core.
    stiffness : float
        Rotational stiffness k [N·m/rad] (full circumference for an axisymmetric model).

    Examples
    --------
    >>> import felupe as fem
    >>> mesh = fem.Rectangle(n=3)
    >>> field = fem.FieldContainer([fem.FieldPlaneStrain(fem.RegionQuad(mesh), dim=2)])
    >>> rc = RollingConstraint(field, np.arange(mesh.npoints), 2.0)
    >>> field[0].values[:] = 0.01 * (mesh.points - 0.5) @ np.array([[0.0, 1.0], [-1.0, 0.0]])
    >>> round(rc.rotation(), 6)
    0.01
    """

    def __init__(self, field, nodes, stiffness):
        self.field = field
        self.nodes = np.asarray(nodes)
        self.stiffness = float(stiffness)
        X = field.region.mesh.points[self.nodes]
        d = X - X.mean(axis=0)
        # theta = sum_a (d_x u_y - d_y u_x)/S with u relative to the mean: the mean drops out
        # because sum_a d_a = 0
        S = np.sum(d**2)
        self._grad = np.stack([-d[:, 1], d[:, 0]], axis=1) / S  # dtheta/du_a
        self._dof = np.stack([2 * self.nodes, 2 * self.nodes + 1], axis=1).ravel()
        mesh = field.region.mesh
        self._size = mesh.npoints * mesh.dim
        self.assemble = Assemble(vector=self._vector, matrix=self._matrix)
        self.results = Results()

    def rotation(self) -> float:
        """Mean rotation θ [rad] of the nodes (counter-clockwise positive)."""
        u = self.field[0].values[self.nodes]
        return float(np.sum(self._grad * u))

    def moment(self) -> float:
        """Constraint moment k θ [N·m] (full circumference for an axisymmetric model)."""
        return self.stiffness * self.rotation()

    def _vector(self, field=None, **kwargs):
        if field is not None:
            self.field = field
        vals = (self.stiffness * self.rotation() * self._grad).ravel()
        vec = coo_matrix((vals, (self._dof, np.zeros_like(self._dof))),
                         shape=(self._size, 1)).tocsr()
        self.results.force = vec
        return vec

    def _matrix(self, field=None, **kwargs):
        g = self._grad.ravel()
        rows = np.repeat(self._dof, len(self._dof))
        cols = np.tile(self._dof, len(self._dof))
        vals = self.stiffness * np.outer(g, g).ravel()
        mat = coo_matrix((vals, (rows, cols)), shape=(self._size, self._size)).tocsr()
        self.results.stiffness = mat
        return mat
