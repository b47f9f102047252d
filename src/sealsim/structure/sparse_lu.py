r"""Sparse LU factorisation of matrices of one sparsity pattern, with the ordering and the
symbolic analysis kept between factorisations (the Newton systems of the FE solver).

scipy's SuperLU orders and analyses the matrix again in every call (a lip seal's 4552 dofs:
7 MFlop in 16 ms per factorisation; this LU is about 2.5× faster there, 1.1-1.3× on the
medium O-ring's 14.6 MFlop, where SuperLU's supernodes pay off).
:class:`PatternLU` does the analysis once per pattern:

1. the fill-reducing column ordering is SuperLU's own (minimum degree on the pattern of
   :math:`A + A^T`, the ``superlu`` backend's settings), taken from one SuperLU factorisation;
2. the symbolic factorisation of the symmetrised pattern of :math:`B = P A P^T`: elimination
   tree (Liu's algorithm) and the row patterns of :math:`L` as reaches in it (Davis 2006,
   §4.1-4.4); without pivoting :math:`U` has the transposed pattern of :math:`L`;

and every factorisation is then the numerical left-looking LU :math:`B = L D U` in those
patterns (Davis 2006, §6.2, with diagonal pivots), in compiled loops. The diagonal pivot of
each column must pass the threshold test of partial pivoting, :math:`|d_j| \ge 0.1\,
\max_i |b_{ij}|` over the reduced column (SuperLU's ``diag_pivot_thresh`` of the ``superlu``
backend: growth stays bounded as with threshold pivoting); a matrix whose pivot fails it is
factorised by SuperLU instead, as before. The matrices of the seal models (stiffness, penalty
contact, follower pressure) pass it: it is a fallback, not a path.

References
----------
- T. A. Davis, *Direct Methods for Sparse Linear Systems*, SIAM 2006, ch. 4 (elimination
  tree, symbolic factorisation) and ch. 6 (LU).
- J. W. H. Liu, "A compact row storage scheme for Cholesky factors using elimination trees",
  ACM Trans. Math. Softw. 12 (1986) 127-148.
"""

from __future__ import annotations

import numpy as np
from scipy.sparse.linalg import splu

__all__ = ["DENSE_FLOPS_PER_DOF", "HAVE_COMPILED_LU", "PIVOT_THRESHOLD", "PatternLU",
           "superlu_factor"]

try:  # pragma: no cover - depends on the environment
    import numba
except ImportError:  # pragma: no cover
    numba = None

HAVE_COMPILED_LU = numba is not None

#: Relative size a diagonal pivot must have in its reduced column (SuperLU's
#: ``diag_pivot_thresh`` of the ``superlu`` backend).
PIVOT_THRESHOLD = 0.1

#: Factorisation work per unknown (2 Σ_j c_j², c_j the entries of column j of L, divided by
#: n) above which SuperLU's supernodal (BLAS) factorisation is faster than this scalar one,
#: whose loops win on sparser factors. Measured, same-run medians: a lip seal's 1540 flops
#: per dof 2.5× faster here; a medium O-ring's 5330 1.1-1.3× faster here; the same O-ring
#: with the anti-rolling spring's dense block, 8370, 1.2× slower here.
DENSE_FLOPS_PER_DOF = 6500.0


def superlu_factor(A):
    """SuperLU factors of A with the ``superlu`` backend's settings: minimum-degree ordering
    of A + Aᵀ, symmetric mode, diagonal pivots above 0.1 of their column."""
    return splu(A.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=PIVOT_THRESHOLD,
                options={"SymmetricMode": True})


def _symbolic(n, Sp, Si):
    """Elimination tree of the symmetric pattern (CSC Sp, Si, both triangles) and the
    strictly lower pattern of L by columns (Lp, Li; rows ascending)."""
    parent = np.full(n, -1, np.int64)
    ancestor = np.full(n, -1, np.int64)
    for k in range(n):  # Liu's algorithm with path compression
        for p in range(Sp[k], Sp[k + 1]):
            i = Si[p]
            while i != -1 and i < k:
                inext = ancestor[i]
                ancestor[i] = k
                if inext == -1:
                    parent[i] = k
                i = inext
    # row k of L: the reach of the entries of A[k, :k] in the tree (first count, then fill)
    mark = np.full(n, -1, np.int64)
    counts = np.zeros(n, np.int64)
    for k in range(n):
        mark[k] = k
        for p in range(Sp[k], Sp[k + 1]):
            i = Si[p]
            while i < k and mark[i] != k:
                counts[i] += 1
                mark[i] = k
                i = parent[i]
    Lp = np.zeros(n + 1, np.int64)
    for j in range(n):
        Lp[j + 1] = Lp[j] + counts[j]
    Li = np.empty(Lp[n], np.int64)
    fill = Lp[:n].copy()
    mark[:] = -1
    for k in range(n):  # rows in ascending order: every column's rows come out sorted
        mark[k] = k
        for p in range(Sp[k], Sp[k + 1]):
            i = Si[p]
            while i < k and mark[i] != k:
                Li[fill[i]] = k
                fill[i] += 1
                mark[i] = k
                i = parent[i]
    # U by columns = L by rows (columns ascending)
    Up = np.zeros(n + 1, np.int64)
    for p in range(Lp[n]):
        Up[Li[p] + 1] += 1
    for i in range(n):
        Up[i + 1] += Up[i]
    Ui = np.empty(Lp[n], np.int64)
    fill = Up[:n].copy()
    for j in range(n):
        for p in range(Lp[j], Lp[j + 1]):
            i = Li[p]
            Ui[fill[i]] = j
            fill[i] += 1
    return Lp, Li, Up, Ui


def _numeric(Bp, Bi, Bx, Lp, Li, Up, Ui, Lx, Ux, D, x, threshold):
    """Left-looking B = L D U in the given patterns (L unit lower by columns, U strictly
    upper by columns, D the pivots); ``x`` a zero work vector (left zero). Returns -1, or
    the first column whose diagonal pivot fails the threshold test (or is zero/NaN)."""
    n = D.shape[0]
    for j in range(n):
        for p in range(Bp[j], Bp[j + 1]):
            x[Bi[p]] = Bx[p]
        for p in range(Up[j], Up[j + 1]):  # U[:j, j]: rows ascending = topological order
            k = Ui[p]
            xk = x[k]
            Ux[p] = xk
            x[k] = 0.0
            if xk != 0.0:
                for q in range(Lp[k], Lp[k + 1]):
                    x[Li[q]] -= Lx[q] * xk
        d = x[j]
        x[j] = 0.0
        largest = 0.0
        for q in range(Lp[j], Lp[j + 1]):
            v = abs(x[Li[q]])
            if v > largest:
                largest = v
        if not abs(d) >= threshold * largest or d == 0.0:
            for q in range(Lp[j], Lp[j + 1]):
                x[Li[q]] = 0.0
            return j
        D[j] = d
        for q in range(Lp[j], Lp[j + 1]):
            i = Li[q]
            Lx[q] = x[i] / d
            x[i] = 0.0
    return -1


def _solve(Lp, Li, Lx, Up, Ui, Ux, D, x):
    """Solve L D U y = x in place (x permuted)."""
    n = D.shape[0]
    for j in range(n):
        xj = x[j]
        if xj != 0.0:
            for q in range(Lp[j], Lp[j + 1]):
                x[Li[q]] -= Lx[q] * xj
    for j in range(n - 1, -1, -1):
        x[j] /= D[j]
        xj = x[j]
        if xj != 0.0:
            for p in range(Up[j], Up[j + 1]):
                x[Ui[p]] -= Ux[p] * xj
    return x


if HAVE_COMPILED_LU:  # pragma: no branch
    _symbolic = numba.njit(cache=True)(_symbolic)
    _numeric = numba.njit(cache=True)(_numeric)
    _solve = numba.njit(cache=True)(_solve)


class PatternLU:
    """LU factors of square CSR matrices of one sparsity pattern (see the module).

    Parameters
    ----------
    A : scipy.sparse.csr_matrix
        The first matrix: SuperLU's ordering of it and the symbolic analysis of its pattern
        serve every later matrix of the same ``indptr`` and ``indices``.

    Examples
    --------
    >>> import scipy.sparse as sp
    >>> A = sp.csr_matrix(np.array([[4.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 2.0]]))
    >>> lu = PatternLU(A)
    >>> lu.factorize(A)
    True
    >>> lu.solve(np.array([1.0, 2.0, 3.0])).round(6).tolist()
    [0.222222, 0.111111, 1.444444]
    """

    def __init__(self, A):
        n = A.shape[0]
        self.n = n
        order = superlu_factor(A).perm_c  # column j of A is column order[j] of B
        inverse = np.asarray(order, dtype=np.int64)
        rows = inverse[np.repeat(np.arange(n), np.diff(A.indptr))]
        cols = inverse[np.asarray(A.indices, dtype=np.int64)]
        self._gather = np.lexsort((rows, cols))  # A.data → B's CSC data
        self._Bi = np.ascontiguousarray(rows[self._gather])
        self._Bp = np.zeros(n + 1, dtype=np.int64)
        np.cumsum(np.bincount(cols, minlength=n), out=self._Bp[1:])
        self._perm = inverse  # b permuted: y[inverse[i]] = b[i]
        # symmetrised pattern of B (both triangles) for the symbolic analysis
        keys = np.sort(np.concatenate([cols * n + rows, rows * n + cols]))
        keys = keys[np.concatenate(([True], keys[1:] != keys[:-1]))]  # np.unique: 20x slower
        Sp = np.zeros(n + 1, dtype=np.int64)
        np.cumsum(np.bincount(keys // n, minlength=n), out=Sp[1:])
        self._Lp, self._Li, self._Up, self._Ui = _symbolic(n, Sp, keys % n)
        counts = np.diff(self._Lp).astype(float)
        self.flops = 2.0 * float(np.dot(counts, counts))  # of one factorisation
        #: better left to SuperLU (see :data:`DENSE_FLOPS_PER_DOF`)
        self.dense = self.flops > DENSE_FLOPS_PER_DOF * max(n, 1)
        self._Lx = np.empty(len(self._Li))
        self._Ux = np.empty(len(self._Ui))
        self._D = np.empty(n)
        self._x = np.zeros(n)
        self.factorized = False

    @property
    def fill(self) -> int:
        """Entries of L and U (diagonal once)."""
        return len(self._Li) + len(self._Ui) + self.n

    def factorize(self, A) -> bool:
        """Factorise A (the pattern of the first matrix); False if a diagonal pivot fails the
        threshold test (A is then left to another solver)."""
        Bx = np.ascontiguousarray(A.data[self._gather], dtype=float)
        failed = _numeric(self._Bp, self._Bi, Bx, self._Lp, self._Li, self._Up, self._Ui,
                          self._Lx, self._Ux, self._D, self._x, PIVOT_THRESHOLD)
        self.factorized = failed < 0
        return self.factorized

    def solve(self, b):
        """x with A x = b of the last factorised A."""
        if not self.factorized:
            raise RuntimeError("PatternLU.solve needs a successful factorize first")
        y = np.empty(self.n)
        y[self._perm] = b
        _solve(self._Lp, self._Li, self._Lx, self._Up, self._Ui, self._Ux, self._D, y)
        return y[self._perm]
