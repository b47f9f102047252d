r"""Contact of the seal with a groove land that ends at a clearance gap.

A groove wall of a real gland does not reach the sealing surface: it ends at the edge of the
land (the piston's or the housing's collar next to the groove), a radial clearance below the
bore (piston) or above the rod (rod seal).  Pressed against that wall, the seal is unsupported
over the gap and can bulge (extrude) into it.  The rigid body of the land is a quarter plane
with a rounded edge: the wall (outward normal :math:`\mathbf n`, into the groove), the land's
top surface facing the gap (outward normal :math:`\mathbf t`, towards the sealing surface) and
between them a circular edge of radius ρ.  With the coordinates of a point relative to the
edge, :math:`a = \Delta\mathbf x\cdot\mathbf n` (in front of the wall) and
:math:`b = \Delta\mathbf x\cdot\mathbf t` (beyond the land's top), the signed distance to the
body (negative inside) is

.. math::

    g = \begin{cases}
        a & b \le -\rho \quad\text{(the wall)}\\
        b & a \le -\rho,\ b > -\rho \quad\text{(the land's top)}\\
        \lVert \mathbf v \rVert - \rho,\ \mathbf v = (a + \rho)\,\mathbf n + (b + \rho)\,
        \mathbf t & \text{else (the edge)}
    \end{cases}

continuous with a continuous normal :math:`\partial g / \partial \Delta\mathbf x`
(:math:`\mathbf n`, :math:`\mathbf t`, :math:`\mathbf v / \lVert\mathbf v\rVert`), the
curvature :math:`(\mathbf 1 - \hat{\mathbf v}\otimes\hat{\mathbf v}) / \lVert\mathbf v\rVert`
on the edge and zero on the flats: the distance function of a convex body (e.g. Wriggers,
*Computational Contact Mechanics*, 2nd ed., Springer 2006, ch. 4: normal gap and its
linearisation for a rigid obstacle).  :class:`ContactRigidLand` gives it to FElupe's
rigid-contact base class, which adds the penalty normal force and the Coulomb friction.
"""

from __future__ import annotations

import numpy as np
from felupe.mechanics import ContactRigidBase

from sealsim.structure.assembly import TrialOnce

__all__ = ["ContactRigidLand", "land_gap"]


def land_gap(dx, normal, along, radius):
    """Signed distance of points to a rigid land with a rounded edge, its gradient and
    curvature.

    Parameters
    ----------
    dx : array_like
        (n, 2) positions relative to the edge point [m] (the intersection of the wall line and
        the land's top line).
    normal : array_like
        Unit outward normal of the wall (into the groove) [-].
    along : array_like
        Unit outward normal of the land's top (along the wall towards the gap) [-].
    radius : float
        Edge radius ρ [m], > 0.

    Returns
    -------
    gap : numpy.ndarray
        (n,) signed distance [m] (negative: inside the land).
    gradient : numpy.ndarray
        (n, 2) outward unit normal ∂g/∂Δx [-].
    curvature : numpy.ndarray
        (n, 2, 2) ∂²g/∂Δx² [1/m] (zero on the flats).

    Examples
    --------
    A land whose wall faces −x and whose top faces +y, edge radius 0.1: a point in front of
    the wall, one above the top, one diagonally off the edge (√2·0.3 − 0.1 from it, normal
    at 45°) and one inside near the wall:

    >>> g, n, _ = land_gap([[-0.3, -1.0], [0.5, 0.2], [-0.2, 0.2], [0.02, -1.0]],
    ...                    [-1.0, 0.0], [0.0, 1.0], 0.1)
    >>> g.round(4).tolist(), n[2].round(4).tolist()
    ([0.3, 0.2, 0.3243, -0.02], [-0.7071, 0.7071])
    """
    dx = np.atleast_2d(np.asarray(dx, dtype=float))
    n = np.asarray(normal, dtype=float)
    t = np.asarray(along, dtype=float)
    a = dx @ n
    b = dx @ t
    v = (a + radius)[:, None] * n + (b + radius)[:, None] * t
    length = np.linalg.norm(v, axis=1)
    wall = b <= -radius
    top = ~wall & (a <= -radius)
    edge = ~wall & ~top
    gap = np.where(wall, a, np.where(top, b, length - radius))
    safe = np.where(edge, length, 1.0)
    unit = v / safe[:, None]
    gradient = np.where(wall[:, None], n, np.where(top[:, None], t, unit))
    eye = np.eye(dx.shape[1])
    curvature = np.where(edge[:, None, None],
                         (eye - np.einsum("ai,aj->aij", unit, unit)) / safe[:, None, None], 0.0)
    return gap, gradient, curvature


class ContactRigidLand(TrialOnce, ContactRigidBase):
    """Penalty contact (with Coulomb friction) of the seal's boundary nodes with a rigid
    groove land ending at a clearance gap, :func:`land_gap`; the centre point is the edge
    point (the intersection of the wall and the land's top).

    Parameters
    ----------
    field, points, centerpoint : see :class:`felupe.mechanics.ContactRigidBase`
    normal : array_like
        Unit outward normal of the wall (into the groove) [-].
    along : array_like
        Unit outward normal of the land's top (towards the gap) [-].
    radius : float
        Edge radius [m].
    **kwargs
        ``friction``, ``multiplier``, ``items``, ``elastic_slip`` ... of the base class.
    """

    def __init__(self, field, points, centerpoint, normal, along, radius, **kwargs):
        # _kinematics needs these before the base class evaluates the initial state
        self.normal = np.asarray(normal, dtype=float)
        self.along = np.asarray(along, dtype=float)
        self.radius = float(radius)
        super().__init__(field, points, centerpoint, **kwargs)

    def _kinematics(self, dx):
        return land_gap(dx, self.normal, self.along, self.radius)
