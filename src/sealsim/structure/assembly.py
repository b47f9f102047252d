r"""Compiled assembly of the seal's FE system: the nearly incompressible solid and the sum of
all items, with the sparsity pattern computed once.

:class:`CompiledSolidBody` is FElupe's :class:`~felupe.SolidBodyNearlyIncompressible` (the
three-field formulation with a constant pressure and volume ratio per cell, statically
condensed; Simo, Taylor & Pister 1985) with the deformation gradient, the volume terms and
the element integrals evaluated cell by cell in compiled loops (numba, ``cache=True``) and
the element values added straight into the data of a sparse matrix whose pattern (and the
position of every element entry in it) is computed once. For an axisymmetric field
(rotation axis x, radius y, FElupe's convention) the deformation gradient is

.. math::

    F = \begin{bmatrix} I + \partial u / \partial X & 0 \\ 0 & 1 + u_r / R \end{bmatrix},

the internal force of node *a* is :math:`\int_V (P_{iJ}\,\partial_J N_a + \delta_{ir}\,
P_{\theta\theta} N_a / R)\,dV` with :math:`dV = 2\pi R\,dA`, and the tangent is the
linearisation of that with the five non-zero components of :math:`\delta F` (FElupe's
``IntegralFormAxisymmetric``). The mixed formulation adds, per cell, the pressure
:math:`p\,\partial J / \partial F` to the stress, :math:`p\,\partial^2 J / \partial F^2` to the
tangent, and :math:`K/V\,\mathbf h \otimes \mathbf h` with :math:`\mathbf h = \int_V
\partial J/\partial F : \partial N\,dV` to the element matrix; the cell pressure follows
:math:`\bar J = (v + \mathbf h \cdot \Delta u) / V`, :math:`p = K(\bar J - 1)` exactly as
FElupe updates it. The isochoric stress and tangent come from the material's umat, as in
FElupe. Same equations as FElupe's implementation, which stays the reference the tests
compare against (F_N and b to 1e-9; measured ~1e-14).

:class:`SystemAssembly` sums the residuals and tangents of all items of a model into one
matrix whose pattern is the union of the items' patterns (extended only when an item brings a
new entry) and partitions it into the free/prescribed blocks with index maps computed once per
pattern, replacing the sparse additions and fancy indexing of every Newton iteration.
"""

from __future__ import annotations

import inspect

import felupe as fem
import numpy as np
from scipy.sparse import csr_matrix

__all__ = ["CompiledSolidBody", "ContactRigidPlaneOnce", "SystemAssembly", "TrialOnce",
           "csr_pattern"]

try:  # pragma: no cover - depends on the environment
    import numba
except ImportError:  # pragma: no cover
    numba = None

HAVE_COMPILED_ASSEMBLY = numba is not None


def _deformation_gradient(u, cells, h, dhdX, radius, axisymmetric, F):
    """F (3, 3, q, c) of the displacements u (points, 2) (written into F)."""
    ncells, nnodes = cells.shape
    nq = h.shape[1]
    for c in range(ncells):
        for q in range(nq):
            g00 = 0.0
            g01 = 0.0
            g10 = 0.0
            g11 = 0.0
            ur = 0.0
            for a in range(nnodes):
                p = cells[c, a]
                u0 = u[p, 0]
                u1 = u[p, 1]
                d0 = dhdX[a, 0, q, c]
                d1 = dhdX[a, 1, q, c]
                g00 += u0 * d0
                g01 += u0 * d1
                g10 += u1 * d0
                g11 += u1 * d1
                ur += u1 * h[a, q]
            F[0, 0, q, c] = g00 + 1.0
            F[0, 1, q, c] = g01
            F[1, 0, q, c] = g10
            F[1, 1, q, c] = g11 + 1.0
            F[0, 2, q, c] = 0.0
            F[1, 2, q, c] = 0.0
            F[2, 0, q, c] = 0.0
            F[2, 1, q, c] = 0.0
            F[2, 2, q, c] = ur / radius[q, c] + 1.0 if axisymmetric else 1.0
    return F


def _volume_terms(F, h, dhdX, radius, weight, axisymmetric, hv, v):
    """h = ∫ ∂J/∂F : ∂N dV (nodes, 2, c) and the deformed cell volumes v = ∫ J dV (c)."""
    nnodes, nq = h.shape
    ncells = F.shape[3]
    for c in range(ncells):
        vc = 0.0
        for a in range(nnodes):
            hv[a, 0, c] = 0.0
            hv[a, 1, c] = 0.0
        for q in range(nq):
            F00 = F[0, 0, q, c]
            F01 = F[0, 1, q, c]
            F10 = F[1, 0, q, c]
            F11 = F[1, 1, q, c]
            F22 = F[2, 2, q, c]
            J2 = F00 * F11 - F01 * F10
            w = weight[q, c]
            vc += J2 * F22 * w
            # cofactor J F^-T of the block-diagonal F
            c00 = F11 * F22
            c01 = -F10 * F22
            c10 = -F01 * F22
            c11 = F00 * F22
            for a in range(nnodes):
                d0 = dhdX[a, 0, q, c]
                d1 = dhdX[a, 1, q, c]
                hv[a, 0, c] += (c00 * d0 + c01 * d1) * w
                hr = c10 * d0 + c11 * d1
                if axisymmetric:
                    hr += J2 * h[a, q] / radius[q, c]
                hv[a, 1, c] += hr * w
        v[c] = vc
    return hv, v


def _force(F, P, p, h, dhdX, radius, weight, axisymmetric, hv, constraint, cells, stress, f):
    """Internal forces f (dofs) of the stress P + p ∂J/∂F (total stress written into
    ``stress``) and the volume constraint ``hv * constraint`` (per cell)."""
    nnodes, nq = h.shape
    ncells = F.shape[3]
    for c in range(ncells):
        pc = p[c]
        fe = np.zeros((nnodes, 2))
        for q in range(nq):
            F00 = F[0, 0, q, c]
            F01 = F[0, 1, q, c]
            F10 = F[1, 0, q, c]
            F11 = F[1, 1, q, c]
            F22 = F[2, 2, q, c]
            for i in range(3):
                for j in range(3):
                    stress[i, j, q, c] = P[i, j, q, c]
            stress[0, 0, q, c] += pc * F11 * F22
            stress[0, 1, q, c] += -pc * F10 * F22
            stress[1, 0, q, c] += -pc * F01 * F22
            stress[1, 1, q, c] += pc * F00 * F22
            stress[2, 2, q, c] += pc * (F00 * F11 - F01 * F10)
            P00 = stress[0, 0, q, c]
            P01 = stress[0, 1, q, c]
            P10 = stress[1, 0, q, c]
            P11 = stress[1, 1, q, c]
            w = weight[q, c]
            hoop = stress[2, 2, q, c] / radius[q, c] if axisymmetric else 0.0
            for a in range(nnodes):
                d0 = dhdX[a, 0, q, c]
                d1 = dhdX[a, 1, q, c]
                fe[a, 0] += (P00 * d0 + P01 * d1) * w
                fe[a, 1] += (P10 * d0 + P11 * d1 + hoop * h[a, q]) * w
        k = constraint[c]
        for a in range(nnodes):
            for i in range(2):
                f[2 * cells[c, a] + i] += fe[a, i] + hv[a, i, c] * k
    return f


def _stiffness(F, A, p, h, dhdX, radius, weight, axisymmetric, hv, bulk_per_volume, position,
               data):
    """Element tangents of A + p ∂²J/∂F² and K/V h⊗h, added into ``data`` at ``position``
    (cells, 2 nodes, 2 nodes... flattened to (c, 2n, 2n))."""
    nnodes, nq = h.shape
    ncells = F.shape[3]
    nd = 2 * nnodes
    # the five non-zero components of δF: (0,0), (0,1), (1,0), (1,1), (2,2)
    ci = (0, 0, 1, 1, 2)
    cj = (0, 1, 0, 1, 2)
    G = np.zeros((nd, 5))
    T = np.zeros((5, nd))
    Ar = np.zeros((5, 5))
    cof = np.zeros((3, 3))
    ke = np.zeros((nd, nd))
    for c in range(ncells):
        pc = p[c]
        ke[:, :] = 0.0
        for q in range(nq):
            F00 = F[0, 0, q, c]
            F01 = F[0, 1, q, c]
            F10 = F[1, 0, q, c]
            F11 = F[1, 1, q, c]
            F22 = F[2, 2, q, c]
            J2 = F00 * F11 - F01 * F10
            J = J2 * F22
            cof[0, 0] = F11 * F22
            cof[0, 1] = -F10 * F22
            cof[1, 0] = -F01 * F22
            cof[1, 1] = F00 * F22
            cof[2, 2] = J2
            pJ = pc / J
            for m in range(5):
                i = ci[m]
                j = cj[m]
                for n in range(5):
                    k = ci[n]
                    l = cj[n]  # noqa: E741 - index names of the formula
                    Ar[m, n] = A[i, j, k, l, q, c] + pJ * (cof[i, j] * cof[k, l]
                                                           - cof[i, l] * cof[k, j])
            w = weight[q, c]
            rinv = 1.0 / radius[q, c] if axisymmetric else 0.0
            for a in range(nnodes):
                d0 = dhdX[a, 0, q, c]
                d1 = dhdX[a, 1, q, c]
                G[2 * a, 0] = d0
                G[2 * a, 1] = d1
                G[2 * a + 1, 2] = d0
                G[2 * a + 1, 3] = d1
                G[2 * a + 1, 4] = h[a, q] * rinv
            for m in range(5):
                for b in range(nnodes):
                    T[m, 2 * b] = Ar[m, 0] * G[2 * b, 0] + Ar[m, 1] * G[2 * b, 1]
                    T[m, 2 * b + 1] = (Ar[m, 2] * G[2 * b + 1, 2] + Ar[m, 3] * G[2 * b + 1, 3]
                                       + Ar[m, 4] * G[2 * b + 1, 4])
            for a in range(nnodes):
                for s in range(nd):
                    ke[2 * a, s] += (G[2 * a, 0] * T[0, s] + G[2 * a, 1] * T[1, s]) * w
                    ke[2 * a + 1, s] += (G[2 * a + 1, 2] * T[2, s] + G[2 * a + 1, 3] * T[3, s]
                                         + G[2 * a + 1, 4] * T[4, s]) * w
        kv = bulk_per_volume[c]
        for r in range(nd):
            hr = hv[r // 2, r % 2, c] * kv
            for s in range(nd):
                data[position[c, r, s]] += ke[r, s] + hr * hv[s // 2, s % 2, c]
    return data


if HAVE_COMPILED_ASSEMBLY:  # pragma: no branch
    _deformation_gradient = numba.njit(cache=True)(_deformation_gradient)
    _volume_terms = numba.njit(cache=True)(_volume_terms)
    _force = numba.njit(cache=True)(_force)
    _stiffness = numba.njit(cache=True)(_stiffness)


def csr_pattern(rows, cols, size):
    """Sorted CSR pattern of the entries (rows, cols) and the position of each entry in it.

    Returns ``(indptr, indices, position)``: ``data[position[k]] += value[k]`` assembles.

    Examples
    --------
    >>> indptr, indices, pos = csr_pattern(np.array([1, 0, 1]), np.array([0, 1, 0]), 2)
    >>> indptr.tolist(), indices.tolist(), pos.tolist()
    ([0, 1, 2], [1, 0], [1, 0, 1])
    """
    keys = np.asarray(rows, dtype=np.int64) * size + np.asarray(cols, dtype=np.int64)
    unique, position = np.unique(keys, return_inverse=True)
    indptr = np.zeros(size + 1, dtype=np.int32)
    np.cumsum(np.bincount(unique // size, minlength=size), out=indptr[1:])
    return indptr, (unique % size).astype(np.int32), position.reshape(np.shape(rows))


class CompiledSolidBody(fem.SolidBodyNearlyIncompressible):
    """FElupe's nearly incompressible solid body with compiled assembly (see the module).

    Same constructor, state (``results.state``: u, p, J), checkpoints and results
    (``stress``, ``kinematics``, ``force``, ``stiffness``) as
    :class:`felupe.SolidBodyNearlyIncompressible`, for an axisymmetric or plane-strain field
    on a region of one cell type (the seal meshes are quads). :attr:`force_vector` is the
    dense residual of the last assembly; :attr:`results.stiffness` keeps one CSR matrix whose
    data is overwritten.
    """

    def __init__(self, umat, field, bulk, **kwargs):
        displacement = field[0]
        region = field.region
        self.axisymmetric = isinstance(displacement, fem.FieldAxisymmetric)
        if not (self.axisymmetric or isinstance(displacement, fem.FieldPlaneStrain)):
            raise TypeError("CompiledSolidBody needs an axisymmetric or plane-strain field")
        cells = np.ascontiguousarray(region.mesh.cells, dtype=np.int64)
        self._cells = cells
        h = np.asarray(region.h)
        self._h = np.ascontiguousarray(h[..., 0] if h.ndim == 3 else h)
        self._dhdX = np.ascontiguousarray(region.dhdX)
        if self._h.ndim != 2 or np.abs(h - h[..., :1]).max() > 0:
            raise TypeError("CompiledSolidBody needs the same shape functions in every cell")
        self._radius = np.ascontiguousarray(displacement.radius if self.axisymmetric
                                            else np.ones_like(region.dV))
        dA = region.dV
        self._weight = np.ascontiguousarray(2 * np.pi * self._radius * dA if self.axisymmetric
                                            else dA)
        ncells, nnodes = cells.shape
        self._size = region.mesh.npoints * 2
        edof = (2 * cells[:, :, None] + np.arange(2)).reshape(ncells, 2 * nnodes)
        rows = np.broadcast_to(edof[:, :, None], (ncells, 2 * nnodes, 2 * nnodes))
        cols = np.broadcast_to(edof[:, None, :], (ncells, 2 * nnodes, 2 * nnodes))
        indptr, indices, self._position = csr_pattern(rows, cols, self._size)
        self._stiffness = csr_matrix((np.zeros(len(indices)), indices, indptr),
                                     shape=(self._size, self._size))
        nq = self._h.shape[1]
        self._F = np.zeros((3, 3, nq, ncells))
        self._hv = np.zeros((nnodes, 2, ncells))
        self._v = np.zeros(ncells)
        self.force_vector = np.zeros(self._size)
        self._gradient_out = "out" in inspect.signature(umat.gradient).parameters
        hessian = inspect.signature(umat.hessian).parameters
        self._hessian_out = "out" in hessian
        # only the components the block-diagonal F of these fields needs, if the umat can
        self._hessian_reduced = "reduced" in hessian
        # F, h and v of the initial state (FElupe's state.F), then FElupe's constructor
        self._kinematics(displacement.values)
        super().__init__(umat, field, bulk, **kwargs)

    def _kinematics(self, u):
        """F, h and v of the displacements u (a new F: earlier results stay valid)."""
        F = np.zeros_like(self._F)
        _deformation_gradient(np.ascontiguousarray(u), self._cells, self._h, self._dhdX,
                              self._radius, self.axisymmetric, F)
        self._F = F
        _volume_terms(F, self._h, self._dhdX, self._radius, self._weight, self.axisymmetric,
                      self._hv, self._v)

    def _extract(self, field, parallel=False):
        state = self.results.state
        u = field[0].values
        du = (u - state.u)[self._cells]  # (c, a, i)
        # J̄ from h and v of the previous evaluation, linearised in the increment (FElupe)
        state.J[:] = (np.einsum("cai,aic->c", du, self._hv) + self._v) / self.V
        state.p[:] = self.bulk * (state.J - 1)
        state.u[:] = u
        self.field = field
        self._kinematics(u)
        self.results.kinematics = state.F = [self._F]
        return self.results.kinematics

    def restore(self, checkpoint, restore_statevars=True, restore_state=True):
        super().restore(checkpoint, restore_statevars, restore_state)
        # FElupe re-extracts F of the restored field: h and v must follow it
        self._kinematics(self.field[0].values)
        self.results.kinematics = self.results.state.F = [self._F]

    def _vector(self, field=None, parallel=False, items=None, args=(), kwargs=None, block=True):
        if field is not None:
            self._extract(field)
        F = self._F
        statevars = self.results.statevars
        kw = dict(kwargs or {})
        if self._gradient_out:
            kw["out"] = self.results.gradient
        self.results.gradient, self.results._statevars = self.umat.gradient(
            [F, statevars], *args, **kw)
        state = self.results.state
        constraint = self.bulk * (self._v / self.V - 1) - state.p
        stress = np.empty_like(F)
        f = self.force_vector
        f[:] = 0.0
        _force(F, np.ascontiguousarray(self.results.gradient), state.p, self._h, self._dhdX,
               self._radius, self._weight, self.axisymmetric, self._hv,
               np.ascontiguousarray(constraint, dtype=float), self._cells, stress, f)
        self.results.stress = [stress]
        self.results.force = csr_matrix(f.reshape(-1, 1))
        return self.results.force

    def _matrix(self, field=None, parallel=False, items=None, args=(), kwargs=None, block=True):
        if field is not None:
            self._extract(field)
        F = self._F
        kw = dict(kwargs or {})
        if self._hessian_out:
            kw["out"] = self.results.hessian
        if self._hessian_reduced:
            kw["reduced"] = True
        self.results.hessian = self.umat.hessian([F, self.results.statevars], *args, **kw)[0]
        K = self._stiffness
        K.data[:] = 0.0
        bulk_per_volume = np.broadcast_to(self.bulk / self.V, self._v.shape)
        _stiffness(F, np.ascontiguousarray(self.results.hessian), self.results.state.p,
                   self._h, self._dhdX, self._radius, self._weight, self.axisymmetric,
                   self._hv, np.ascontiguousarray(bulk_per_volume, dtype=float),
                   self._position, K.data)
        self.results.elasticity = None
        self.results.stiffness = K
        return K


class TrialOnce:
    """Mixin for FElupe's rigid contacts (:class:`felupe.mechanics.ContactRigidBase`): the
    trial state is evaluated once per configuration.

    FElupe evaluates the contact (gaps, penalty and friction return mapping) for the
    residual and again for the tangent; here the tangent reuses the trial of the residual
    when the gap vectors, the converged state variables and the multipliers are the same
    objects/values -- the same trial FElupe would compute again.
    """

    _trial = None

    def _evaluate(self, field=None):
        if field is not None:
            self.field = field
        dx = self._gap_vectors()
        cached = self._trial
        if cached is not None and cached[1] is self.results.statevars \
                and cached[2] is self._multipliers_statevars and cached[3] is self.multipliers \
                and np.array_equal(cached[0], dx):
            return cached[4]
        trial = super()._evaluate()
        self._trial = (dx, self.results.statevars, self._multipliers_statevars,
                       self.multipliers, trial)
        return trial

    def stiffness_entries(self):
        """(rows, cols, values) of the stiffness of the points in contact and the centre
        point (FElupe's contact matrix, global dofs) for the current configuration."""
        trial = self._evaluate()
        dof = self.field[0].indices.dof
        points = dof[self.points[trial.contact]]  # (m, dim)
        blocks = trial.stiffness  # (m, dim, dim)
        center = np.broadcast_to(dof[self.centerpoint].ravel(), points.shape)
        rows, cols, data = [], [], []
        for row, col, sign in ((points, points, 1.0), (points, center, -1.0),
                               (center, points, -1.0), (center, center, 1.0)):
            rows.append(np.broadcast_to(row[:, :, None], blocks.shape).ravel())
            cols.append(np.broadcast_to(col[:, None, :], blocks.shape).ravel())
            data.append(sign * blocks.ravel())
        return np.concatenate(rows), np.concatenate(cols), np.concatenate(data)


class ContactRigidPlaneOnce(TrialOnce, fem.ContactRigidPlane):
    """FElupe's rigid-plane contact, its trial state evaluated once per configuration
    (:class:`TrialOnce`)."""


class SystemAssembly:
    """Residual and free-dof tangent K11 of a model's items in one cached sparsity pattern.

    K11 (the free-free block, which the linear solver factorises) is assembled into the union
    of the items' patterns, extended only when an item brings a new entry (the contact items
    assemble the nodes in contact: their free-free entries lie in the solid's pattern); the
    position of every item entry in it is kept while the item's pattern repeats. The
    free-prescribed coupling K10 du0 is evaluated as a product with each item's matrix.

    Parameters
    ----------
    size : int
        Number of dofs of the field.
    dof1, dof0 : numpy.ndarray
        Free and prescribed dofs.

    Examples
    --------
    >>> import scipy.sparse as sp
    >>> system = SystemAssembly(3, np.array([0, 1]), np.array([2]))
    >>> f, K11 = system.sum([(np.ones(3), sp.eye(3, format="csr")),
    ...                      (np.zeros(3), sp.csr_matrix(np.ones((3, 3))))])
    >>> K11.toarray().tolist(), system.coupling(np.array([2.0])).tolist()
    ([[2.0, 1.0], [1.0, 2.0]], [2.0, 2.0])
    """

    def __init__(self, size, dof1, dof0):
        self.size = int(size)
        self.dof1 = np.asarray(dof1)
        self.dof0 = np.asarray(dof0)
        self._free = np.full(self.size, -1, dtype=np.int64)
        self._free[self.dof1] = np.arange(len(self.dof1))
        self.keys = np.zeros(0, dtype=np.int64)  # sorted row * n1 + col of K11's pattern
        self.patterns = 0  # patterns built (1 or 2 along a load path)
        self._where: dict = {}  # contribution number → (its pattern, where its entries go)
        self._matrices: list = []

    def _positions(self, slot, K):
        """(entries of K in K11, their positions in K11's pattern) for contribution number
        ``slot``, K a CSR matrix or (rows, cols, values); the pattern is extended by
        entries it lacks. Cached while K's pattern repeats."""
        if isinstance(K, tuple):
            pattern = (K[0], K[1])
        else:
            pattern = (K.indices, K.indptr)
        cached = self._where.get(slot)
        if cached is not None and cached[1] == self.patterns and \
                all(a is b or np.array_equal(a, b) for a, b in zip(cached[0], pattern)):
            return cached[2]
        if isinstance(K, tuple):
            rows, cols = self._free[K[0]], self._free[K[1]]
        else:
            rows = self._free[np.repeat(np.arange(self.size), np.diff(K.indptr))]
            cols = self._free[K.indices]
        entries = np.flatnonzero((rows >= 0) & (cols >= 0))
        n1 = len(self.dof1)
        keys = rows[entries] * n1 + cols[entries]
        pos = np.searchsorted(self.keys, keys)
        if len(keys) and (pos.max() >= len(self.keys)
                          or np.any(self.keys[np.minimum(pos, len(self.keys) - 1)] != keys)):
            self._rebuild(np.union1d(self.keys, keys))
            pos = np.searchsorted(self.keys, keys)
        # the solid's pattern arrays never change: identity suffices (others are compared)
        kept = pattern if slot == 0 else tuple(a.copy() for a in pattern)
        self._where[slot] = (kept, self.patterns, (entries, pos))
        return entries, pos

    def _rebuild(self, keys):
        self.keys = keys
        self.patterns += 1
        self._where.clear()
        n1 = len(self.dof1)
        indptr = np.zeros(n1 + 1, dtype=np.int32)
        np.cumsum(np.bincount(keys // n1, minlength=n1), out=indptr[1:])
        self._K11 = csr_matrix((np.zeros(len(keys)), (keys % n1).astype(np.int32), indptr),
                               shape=(n1, n1))

    def sum(self, contributions):
        """(f, K11) of a list of (dense residual, tangent) of all dofs -- a tangent is a CSR
        matrix or (rows, cols, values) --, the first one the solid's; K11 is overwritten by
        the next call."""
        while True:  # again if a contribution extended the pattern
            patterns = self.patterns
            where = [self._positions(k, K) for k, (_, K) in enumerate(contributions)]
            if self.patterns == patterns:
                break
        f = np.zeros(self.size)
        data = np.zeros(len(self.keys))
        for (r, K), (entries, pos) in zip(contributions, where):
            f += r
            if isinstance(K, tuple):  # entries may repeat
                np.add.at(data, pos, K[2][entries])
            else:  # the entries of a CSR matrix are unique: a plain indexed add is exact
                data[pos] += K.data[entries]
        self._K11.data = data
        self._matrices = [K for _, K in contributions]
        return f, self._K11

    def coupling(self, du0):
        """K10 du0 of the last assembly: the free-dof forces of prescribed dof changes."""
        x = np.zeros(self.size)
        x[self.dof0] = du0
        y = np.zeros(self.size)
        for K in self._matrices:
            if isinstance(K, tuple):
                np.add.at(y, K[0], K[2] * x[K[1]])
            else:
                y += K @ x
        return y[self.dof1]

    def assemble(self, items, field):
        """(f, K11) of FElupe items, the first a :class:`CompiledSolidBody` (its dense
        residual is used), the others with sparse residuals; an item with a method
        ``stiffness_entries()`` gives its tangent as (rows, cols, values)."""
        contributions = []
        for item in items:
            item.field.link(field)
            r = item.assemble.vector(field=item.field)
            entries = getattr(item, "stiffness_entries", None)
            if entries is not None:  # (rows, cols, values): no sparse matrix to build
                K = entries()
            else:
                K = item.assemble.matrix().tocsr()
            if isinstance(item, CompiledSolidBody):
                r = item.force_vector
            else:
                r = np.asarray(r.toarray()).ravel()
            contributions.append((r, K))
        return self.sum(contributions)
