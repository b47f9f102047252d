"""Transient axisymmetric heat conduction on a structured (r, z) finite-volume grid.

The energy equation of Organisciak et al. (2014, Eq. 7), ρ·c_p·∂T/∂t = ∇·(k∇T) + q, is
integrated over ring-shaped cells of a tensor grid (r_edges × z_edges).  Each cell holds one
solid (index into a list of :class:`Solid`) or is void (-1, fluid: oil or air).  Conductances between cell
centres use the exact cylindrical-shell resistance ln(r_face/r_centre)/(2π·k·Δz) radially and
Δz/(2·k·A) axially, in series across a face (Patankar, *Numerical Heat Transfer and Fluid
Flow*, 1980, §4.2).  Faces between a solid cell and a void cell or the domain edge are
*boundary faces*; the caller groups them and links every group to a node: a lumped node with
a heat capacity (oil sump, housing) or a node of fixed temperature (ambient air).

Time integration is backward Euler on the whole network (cells + lumped nodes):

    (C/Δt + K)·T¹ = C/Δt·T⁰ + F·T_fixed + s,

which is unconditionally stable and conserves energy exactly: heat in = heat stored + heat
to the fixed nodes, step by step, up to the linear-solver round-off.
"""

from __future__ import annotations

from collections.abc import Hashable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

__all__ = [
    "AxisymmetricConduction",
    "BoundaryFaces",
    "Link",
    "PatternFactoriser",
    "Solid",
    "ThermalNetwork",
    "factorise",
    "graded_edges",
]


@dataclass(frozen=True)
class Solid:
    """A heat-conducting solid.

    Parameters
    ----------
    name : str
        Label.
    conductivity : float
        k [W/(m·K)].
    density : float
        ρ [kg/m³].
    specific_heat : float
        c_p [J/(kg·K)].
    """

    name: str
    conductivity: float
    density: float
    specific_heat: float


def graded_edges(breakpoints: Sequence[float], fine: Sequence[float],
                 growth: float = 1.2, coarse: float = np.inf) -> np.ndarray:
    """Cell edges through all breakpoints with sizes graded from each breakpoint's fine size.

    Between consecutive breakpoints a and b with target sizes h_a and h_b the cell size grows
    geometrically (factor ``growth``) away from both ends, capped at ``coarse``; the sizes are
    then scaled to fit the segment exactly.

    Parameters
    ----------
    breakpoints : sequence of float
        Increasing positions that must be edges [m].
    fine : sequence of float
        Target cell size at each breakpoint [m].
    growth : float
        Size ratio of neighbouring cells (> 1).
    coarse : float
        Largest cell size [m].

    Returns
    -------
    numpy.ndarray
        Increasing edge positions, starting and ending at the first and last breakpoint.

    Examples
    --------
    >>> e = graded_edges([0.0, 1.0], [0.1, 0.1])
    >>> round(float(e[0]), 6), round(float(e[-1]), 6), len(e) > 5
    (0.0, 1.0, True)
    """
    bps = np.asarray(breakpoints, dtype=float)
    sizes_at = np.asarray(fine, dtype=float)
    if bps.ndim != 1 or len(bps) < 2 or np.any(np.diff(bps) <= 0):
        raise ValueError("breakpoints must be at least two strictly increasing values")
    edges = [bps[0]]
    for a, b, ha, hb in zip(bps[:-1], bps[1:], sizes_at[:-1], sizes_at[1:], strict=True):
        length = b - a
        left, right = [], []
        total = 0.0
        sa, sb = ha, hb
        while total < length:
            # grow from the side with the smaller current size
            if sa <= sb:
                left.append(min(sa, coarse))
                total += left[-1]
                sa *= growth
            else:
                right.append(min(sb, coarse))
                total += right[-1]
                sb *= growth
        sizes = np.array(left + right[::-1])
        sizes *= length / sizes.sum()
        segment = a + np.cumsum(sizes)
        segment[-1] = b  # exactly: callers locate features by their breakpoints
        edges.extend(segment)
    return np.array(edges)


@dataclass(frozen=True)
class BoundaryFaces:
    """Faces between a solid cell and a void cell or the domain edge.

    Attributes
    ----------
    cell : ndarray of int
        Unknown index of the solid cell.
    side : ndarray of int
        0: −r (inner), 1: +r (outer), 2: −z, 3: +z.
    area : ndarray
        Face area [m²] (full 360°).
    resistance : ndarray
        Conduction resistance from the cell centre to the face [K/W].
    r, z : ndarray
        Face centre [m].
    void : ndarray of int
        Flat index (i·n_z + j) of the neighbouring void cell, −1 at the domain edge.
    """

    cell: np.ndarray
    side: np.ndarray
    area: np.ndarray
    resistance: np.ndarray
    r: np.ndarray
    z: np.ndarray
    void: np.ndarray


class AxisymmetricConduction:
    """Finite-volume conduction model of solids on an axisymmetric (r, z) grid.

    Parameters
    ----------
    r_edges : array_like
        Radial cell edges [m], starting at ≥ 0 (0 = axis).
    z_edges : array_like
        Axial cell edges [m].
    material : array_like of int, shape (n_r, n_z)
        Index into ``solids`` per cell, −1 for void.
    solids : sequence of Solid
        Materials.

    Examples
    --------
    >>> steel = Solid("steel", 45.0, 7850.0, 460.0)
    >>> m = AxisymmetricConduction([0, 0.01, 0.02], [0, 0.01], [[0], [0]], [steel])
    >>> m.n_cells, round(float(m.capacity.sum()), 3)  # π·0.02²·0.01 m³ · ρ·c
    (2, 45.377)
    """

    def __init__(self, r_edges, z_edges, material, solids: Sequence[Solid]):
        self.r_edges = np.asarray(r_edges, dtype=float)
        self.z_edges = np.asarray(z_edges, dtype=float)
        self.material = np.asarray(material, dtype=int)
        self.solids = tuple(solids)
        nr, nz = len(self.r_edges) - 1, len(self.z_edges) - 1
        if self.material.shape != (nr, nz):
            raise ValueError(f"material must have shape {(nr, nz)}, got {self.material.shape}")
        if self.r_edges[0] < 0 or np.any(np.diff(self.r_edges) <= 0) or np.any(
                np.diff(self.z_edges) <= 0):
            raise ValueError("edges must be increasing and radii non-negative")
        self.shape = (nr, nz)
        active = self.material >= 0
        self.index = np.full((nr, nz), -1, dtype=int)
        self.index[active] = np.arange(int(active.sum()))
        self.n_cells = int(active.sum())

        r0, r1 = self.r_edges[:-1], self.r_edges[1:]
        dz = np.diff(self.z_edges)
        self.r_centres = 0.5 * (r0 + r1)
        self.z_centres = 0.5 * (self.z_edges[:-1] + self.z_edges[1:])
        k = np.array([s.conductivity for s in self.solids])
        rho_c = np.array([s.density * s.specific_heat for s in self.solids])
        mat = np.where(active, self.material, 0)
        kc = k[mat]  # (nr, nz), meaningless on void cells
        ring = np.pi * (r1**2 - r0**2)  # (nr,)
        volume = ring[:, None] * dz[None, :]
        self.volume = volume[active]
        self.capacity = (rho_c[mat] * volume)[active]
        self.cell_r = np.broadcast_to(self.r_centres[:, None], self.shape)[active]
        self.cell_z = np.broadcast_to(self.z_centres[None, :], self.shape)[active]
        self.cell_material = self.material[active]

        rc = self.r_centres[:, None]
        with np.errstate(divide="ignore"):
            r_half_out = np.log(r1[:, None] / rc) / (2 * np.pi * kc * dz[None, :])
            r_half_in = np.where(r0[:, None] > 0, np.log(rc / np.maximum(r0[:, None], 1e-300))
                                 / (2 * np.pi * kc * dz[None, :]), np.inf)
        z_half = dz[None, :] / (2 * kc * ring[:, None])

        rows, cols, vals = [], [], []
        # radial faces between (i, j) and (i+1, j)
        a, b = active[:-1, :], active[1:, :]
        both = a & b
        g = 1.0 / (r_half_out[:-1, :] + r_half_in[1:, :])
        rows.append(self.index[:-1, :][both])
        cols.append(self.index[1:, :][both])
        vals.append(g[both])
        # axial faces between (i, j) and (i, j+1)
        a, b = active[:, :-1], active[:, 1:]
        both = a & b
        g = 1.0 / (z_half[:, :-1] + z_half[:, 1:])
        rows.append(self.index[:, :-1][both])
        cols.append(self.index[:, 1:][both])
        vals.append(g[both])
        self._pairs = (np.concatenate(rows), np.concatenate(cols), np.concatenate(vals))

        # boundary faces
        faces = {k_: [] for k_ in ("cell", "side", "area", "resistance", "r", "z", "void")}
        ii, jj = np.nonzero(active)
        for side, (di, dj) in enumerate(((-1, 0), (1, 0), (0, -1), (0, 1))):
            ni, nj = ii + di, jj + dj
            inside = (ni >= 0) & (ni < nr) & (nj >= 0) & (nj < nz)
            neighbour_void = np.ones_like(ii, dtype=bool)
            neighbour_void[inside] = ~active[ni[inside], nj[inside]]
            sel = neighbour_void.copy()
            if side == 0:  # no face on the axis
                sel &= r0[ii] > 0
            i_s, j_s = ii[sel], jj[sel]
            if side in (0, 1):
                r_face = r0[i_s] if side == 0 else r1[i_s]
                area = 2 * np.pi * r_face * dz[j_s]
                res = r_half_in[i_s, j_s] if side == 0 else r_half_out[i_s, j_s]
                z_face = self.z_centres[j_s]
            else:
                z_face = self.z_edges[j_s] if side == 2 else self.z_edges[j_s + 1]
                area = ring[i_s]
                res = z_half[i_s, j_s]
                r_face = self.r_centres[i_s]
            void = np.where(inside[sel], ni[sel] * nz + nj[sel], -1)
            faces["cell"].append(self.index[i_s, j_s])
            faces["side"].append(np.full(len(i_s), side))
            faces["area"].append(area)
            faces["resistance"].append(res)
            faces["r"].append(r_face)
            faces["z"].append(z_face)
            faces["void"].append(void)
        self.boundary = BoundaryFaces(**{k_: np.concatenate(v) for k_, v in faces.items()})

    def conduction_matrix(self) -> sp.csr_matrix:
        """Symmetric conductance matrix K [W/K] of the internal faces (row sums zero)."""
        i, j, g = self._pairs
        n = self.n_cells
        off = sp.coo_matrix((np.concatenate([-g, -g]), (np.concatenate([i, j]),
                                                       np.concatenate([j, i]))), shape=(n, n))
        diag = np.bincount(i, weights=g, minlength=n) + np.bincount(j, weights=g, minlength=n)
        return (off + sp.diags(diag)).tocsr()

    def cell_at(self, r: float, z: float) -> int:
        """Unknown index of the solid cell containing the point (r, z)."""
        i = int(np.searchsorted(self.r_edges, r, side="right") - 1)
        j = int(np.searchsorted(self.z_edges, z, side="right") - 1)
        i = min(max(i, 0), self.shape[0] - 1)
        j = min(max(j, 0), self.shape[1] - 1)
        idx = int(self.index[i, j])
        if idx < 0:
            raise ValueError(f"point r={r:.6g} m, z={z:.6g} m is not inside a solid cell")
        return idx


@dataclass(frozen=True)
class Link:
    """A conductance between two nodes of a :class:`ThermalNetwork` (node names)."""

    a: str
    b: str
    conductance: float


class ThermalNetwork:
    """Conduction cells plus lumped nodes, solved together.

    Parameters
    ----------
    conduction : AxisymmetricConduction
        The conduction model (its cells are unknowns).
    lumped : mapping of str to float
        Lumped nodes with their heat capacity [J/K] (unknowns).
    fixed : sequence of str
        Nodes of prescribed temperature (ambient air; a sump held at constant temperature).
    face_groups : mapping of str to (face indices, node name)
        Boundary faces of ``conduction.boundary`` grouped by surface; each group exchanges heat
        by convection with one node.
    """

    def __init__(self, conduction: AxisymmetricConduction, lumped: Mapping[str, float],
                 fixed: Sequence[str], face_groups: Mapping[str, tuple[np.ndarray, str]]):
        self.conduction = conduction
        self.lumped_names = list(lumped)
        self.fixed_names = list(fixed)
        if set(self.lumped_names) & set(self.fixed_names):
            raise ValueError("a node cannot be both lumped and fixed")
        self.n_cells = conduction.n_cells
        self.n = self.n_cells + len(self.lumped_names)
        self.node_index = {name: self.n_cells + k for k, name in enumerate(self.lumped_names)}
        self.capacity = np.concatenate([conduction.capacity,
                                        np.array([lumped[n] for n in self.lumped_names], float)])
        self.face_groups = {g: (np.asarray(f, dtype=int), node) for g, (f, node) in
                            face_groups.items()}
        for g, (_, node) in self.face_groups.items():
            if node not in self.node_index and node not in self.fixed_names:
                raise ValueError(f"face group {g!r} links to unknown node {node!r}")
        self._k_cond = conduction.conduction_matrix()
        # the cell behind each face of a group (group_heat, every output row of a transient)
        self._group_cells = {g: conduction.boundary.cell[f] for g, (f, _) in
                             self.face_groups.items()}
        self._plans: dict[tuple, dict] = {}  # assembly plans per set of link end nodes

    def group_area(self, group: str) -> float:
        """Total area of a face group [m²]."""
        faces, _ = self.face_groups[group]
        return float(self.conduction.boundary.area[faces].sum())

    def assemble(self, coefficients: Mapping[str, float | np.ndarray],
                 links: Sequence[Link] = ()) -> tuple[sp.csc_matrix, sp.csr_matrix]:
        """Network matrices for the given convection coefficients: :meth:`assemble_faces` of
        their :meth:`face_conductances`."""
        return self.assemble_faces(self.face_conductances(coefficients), links)

    def assemble_faces(self, conductances: Mapping[str, np.ndarray],
                       links: Sequence[Link] = ()) -> tuple[sp.csc_matrix, sp.csr_matrix]:
        """Network matrices for the given face conductances.

        The sparsity pattern depends only on the face groups and on which nodes the links
        join; it is built once per set of links and reused, so a call only computes the
        conductances and scatters them into the matrix entries.

        Parameters
        ----------
        conductances : mapping
            :meth:`face_conductances` [W/K] per face group.
        links : sequence of Link
            Extra conductances between lumped/fixed nodes [W/K].

        Returns
        -------
        K : scipy.sparse.csc_matrix, shape (n, n)
            Conductance matrix of the unknowns [W/K].
        F : scipy.sparse.csr_matrix, shape (n, n_fixed)
            Coupling to the fixed nodes: the heat flow into the unknowns is F·T_fixed − K·T.
        """
        g_all = np.concatenate([*(conductances[group] for group in self.face_groups),
                                np.array([link.conductance for link in links], dtype=float)])
        plan = self._plan(tuple((link.a, link.b) for link in links))
        k = sp.csc_matrix((plan["k_base"] + plan["k_scatter"] @ g_all, plan["k_indices"],
                           plan["k_indptr"]), shape=(self.n, self.n))
        f = sp.csr_matrix((plan["f_scatter"] @ g_all, plan["f_indices"], plan["f_indptr"]),
                          shape=(self.n, len(self.fixed_names)))
        return k, f

    def face_conductances(self, coefficients: Mapping[str, float | np.ndarray]
                          ) -> dict[str, np.ndarray]:
        """Conductance [W/K] of each boundary face, cell centre to its node: the half-cell
        resistance in series with the convection 1/(h·A), per face group.

        Parameters
        ----------
        coefficients : mapping
            Heat transfer coefficient [W/(m²·K)] per face group (scalar or one per face).
        """
        b = self.conduction.boundary
        out = {}
        for group, (faces, _) in self.face_groups.items():
            h = np.asarray(coefficients[group], dtype=float)
            if np.any(h < 0) or not np.all(np.isfinite(h)):
                raise ValueError(f"heat transfer coefficient of {group!r} must be finite, >= 0")
            with np.errstate(divide="ignore"):
                g = 1.0 / (b.resistance[faces] + 1.0 / (h * b.area[faces]))
            out[group] = np.broadcast_to(g, faces.shape)
        return out

    def group_heat(self, temperatures: np.ndarray, fixed_temperatures: Sequence[float],
                   conductances: Mapping[str, np.ndarray]) -> dict[str, float]:
        """Heat [W] that leaves the conduction cells through each face group into its node,
        Σ g·(T_cell − T_node).

        Parameters
        ----------
        temperatures : numpy.ndarray
            Temperatures of the unknowns [K] (cells, then lumped nodes).
        fixed_temperatures : sequence of float
            Temperatures of the fixed nodes [K], in the order of ``fixed_names``.
        conductances : mapping
            :meth:`face_conductances` of the coefficients the temperatures were solved with.

        Returns
        -------
        dict
            ``{group: heat [W]}``, positive out of the solid.  In a steady state the groups
            together carry away what the sources put into the cells (energy conservation).
        """
        if len(fixed_temperatures) != len(self.fixed_names):
            raise ValueError(f"{len(fixed_temperatures)} fixed temperatures for the "
                             f"{len(self.fixed_names)} fixed nodes {self.fixed_names}")
        fixed = dict(zip(self.fixed_names, fixed_temperatures))
        out = {}
        for group, (_, node) in self.face_groups.items():
            t_node = fixed[node] if node in fixed else temperatures[self.node_index[node]]
            out[group] = float(conductances[group] @ (temperatures[self._group_cells[group]]
                                                      - t_node))
        return out

    def _plan(self, link_nodes: tuple[tuple[str, str], ...]) -> dict:
        """Sparsity pattern of (K, F) and the maps from conductances to matrix entries."""
        if link_nodes in self._plans:
            return self._plans[link_nodes]
        b = self.conduction.boundary
        k_rows, k_cols, k_sign, k_source = [], [], [], []
        f_rows, f_cols, f_source = [], [], []
        offset = 0

        def connect(cells: np.ndarray, node: str, sources: np.ndarray):
            # a conductance g between unknown i and node j: K_ii += g and, for a lumped j,
            # K_jj += g, K_ij = K_ji -= g; for a fixed j, F_ij += g
            k_rows.append(cells)
            k_cols.append(cells)
            k_sign.append(np.ones(len(cells)))
            k_source.append(sources)
            if node in self.node_index:
                j = np.full(len(cells), self.node_index[node])
                k_rows.extend([j, cells, j])
                k_cols.extend([j, j, cells])
                k_sign.extend([np.ones(len(cells)), -np.ones(len(cells)), -np.ones(len(cells))])
                k_source.extend([sources] * 3)
            else:
                f_rows.append(cells)
                f_cols.append(np.full(len(cells), self.fixed_names.index(node)))
                f_source.append(sources)

        for faces, node in self.face_groups.values():
            connect(b.cell[faces], node, offset + np.arange(len(faces)))
            offset += len(faces)
        for a, c in link_nodes:
            for lumped, other in ((a, c), (c, a)):
                if lumped in self.node_index:
                    connect(np.array([self.node_index[lumped]]), other, np.array([offset]))
                    break
            offset += 1
        n_sources = offset
        cond = self._k_cond.tocoo()
        rows = np.concatenate([cond.row, *k_rows])
        cols = np.concatenate([cond.col, *k_cols])
        # column-major keys order the entries as CSC stores them
        keys, slot = np.unique(cols.astype(np.int64) * self.n + rows, return_inverse=True)
        n_cond = len(cond.data)
        k_base = np.bincount(slot[:n_cond], weights=cond.data, minlength=len(keys))
        k_scatter = sp.csr_matrix(
            (np.concatenate(k_sign), (slot[n_cond:], np.concatenate(k_source))),
            shape=(len(keys), n_sources)) if k_rows else sp.csr_matrix((len(keys), n_sources))
        k_indptr = np.searchsorted(keys // self.n, np.arange(self.n + 1)).astype(np.int32)
        n_fixed = len(self.fixed_names)
        if f_rows:
            f_keys, f_slot = np.unique(np.concatenate(f_rows).astype(np.int64) * max(n_fixed, 1)
                                       + np.concatenate(f_cols), return_inverse=True)
            f_scatter = sp.csr_matrix((np.ones(len(f_slot)), (f_slot, np.concatenate(f_source))),
                                      shape=(len(f_keys), n_sources))
        else:
            f_keys, f_scatter = np.zeros(0, np.int64), sp.csr_matrix((0, n_sources))
        plan = {"k_base": k_base, "k_scatter": k_scatter,
                "k_indices": (keys % self.n).astype(np.int32), "k_indptr": k_indptr,
                "f_scatter": f_scatter, "f_indices": (f_keys % max(n_fixed, 1)).astype(np.int32),
                "f_indptr": np.searchsorted(f_keys // max(n_fixed, 1),
                                            np.arange(self.n + 1)).astype(np.int32)}
        self._plans[link_nodes] = plan
        return plan


def factorise(matrix: sp.csc_matrix):
    """Sparse LU of a symmetric network matrix.

    The conduction matrices are symmetric; a minimum-degree ordering of A + Aᵀ with symmetric
    pivoting gives about half the fill of SuperLU's default column ordering (COLAMD), and so
    faster factorisations and solves.
    """
    return spla.splu(matrix, permc_spec="MMD_AT_PLUS_A", options={"SymmetricMode": True})


class _PermutedLU:
    """Solves A·x = b with the LU of B = A[order][:, order]: B·x[order] = b[order]."""

    def __init__(self, lu, order: np.ndarray):
        self._lu, self._order = lu, order

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        x = np.empty_like(rhs, dtype=float)
        x[self._order] = self._lu.solve(np.ascontiguousarray(rhs[self._order]))
        return x


class PatternFactoriser:
    """:func:`factorise` for a sequence of matrices of one sparsity pattern, which orders only
    the first.

    A transient's system matrices C/Δt + K differ in their values (Δt, the convection
    coefficients of a speed and sump temperature), not in their pattern, yet SuperLU
    computes the minimum-degree ordering of A + Aᵀ anew for each: a fifth of the time of
    the 37 factorisations of the rotary fit example's first run (3570 unknowns; 245 → 194 ms,
    CPU).  The ordering P of the first matrix serves the later ones: B = P·A·Pᵀ is
    factorised in its natural order, which is the same elimination (SuperLU's symmetric mode
    pivots on the diagonal), so the solutions agree with those of :func:`factorise` to
    round-off.  A matrix of another pattern is ordered anew.

    >>> a = sp.csc_matrix(np.array([[4.0, -1.0, 0.0], [-1.0, 4.0, -1.0], [0.0, -1.0, 4.0]]))
    >>> lu = PatternFactoriser()
    >>> first, second = lu(a), lu((a + sp.eye(3)).tocsc())
    >>> second.solve(np.array([4.0, 3.0, 4.0])).round(12).tolist(), lu.orderings
    ([1.0, 1.0, 1.0], 1)
    """

    def __init__(self):
        self.orderings = 0        # fill-reducing orderings computed
        self._pattern = None      # (indptr, indices, order, gather, B's indptr, B's indices)

    def __call__(self, matrix: sp.csc_matrix):
        """LU of ``matrix`` (CSC); ``.solve(b)`` solves ``matrix @ x = b``."""
        known = self._pattern
        if known is None or not (np.array_equal(known[0], matrix.indptr)
                                 and np.array_equal(known[1], matrix.indices)):
            lu = factorise(matrix)
            self.orderings += 1
            order = np.argsort(lu.perm_c)
            # where each entry of B = A[order][:, order] is in A.data (entries numbered 1..nnz
            # so that none is an explicit zero the indexing could drop)
            numbered = sp.csc_matrix((np.arange(1.0, matrix.nnz + 1), matrix.indices,
                                      matrix.indptr), shape=matrix.shape)[order][:, order]
            numbered = numbered.tocsc()
            numbered.sort_indices()
            self._pattern = (matrix.indptr.copy(), matrix.indices.copy(), order,
                             numbered.data.astype(np.int64) - 1, numbered.indptr,
                             numbered.indices)
            return lu
        _, _, order, gather, indptr, indices = known
        permuted = sp.csc_matrix((matrix.data[gather], indices, indptr), shape=matrix.shape)
        lu = spla.splu(permuted, permc_spec="NATURAL", options={"SymmetricMode": True})
        return _PermutedLU(lu, order)


class BackwardEulerStepper:
    """Backward-Euler time stepping of a :class:`ThermalNetwork` with cached factorisations.

    A factorisation of (C/Δt + K) is kept per ``key`` (the caller's label of the convection
    state, e.g. a speed bin) and Δt, so piecewise-constant duty cycles factorise only a few
    times; the fill-reducing ordering of the first matrix serves every later one
    (:class:`PatternFactoriser`, :attr:`orderings`).  ``build()`` may return a third item
    with (K, F), e.g. the face conductances the matrices were assembled from; it is kept with
    the factorisation and is :attr:`payload` after each :meth:`step` (what that step was
    solved with).

    **Heat sources that follow the temperatures** (``feedback_sources`` E, n × m, and
    ``feedback_probes`` P, n × m): source j is E[:, j]·Q_j(θ_j) with θ_j = P[:, j]ᵀ·T a linear
    functional of the temperatures, e.g. a friction heat that falls as the contact warms.  Taken
    at the start of the step, such a heat can overshoot on a stiff node (a cold start: a lip
    contact of little heat capacity would warm by its whole step's heat before the friction
    sees it, and oscillate).  With the slopes s_j = dQ_j/dθ_j given to :meth:`step`, the step
    is linearly implicit in them (the Rosenbrock–Euler linearisation of the source; Hairer &
    Wanner, *Solving Ordinary Differential Equations II*, 2nd ed., Springer 1996, IV.7):
    Q_j ≈ Q_j(θⁿ) + s_j·(θ_jⁿ⁺¹ − θ_jⁿ), solved with the cached factorisation by the Woodbury
    formula: with x the step without feedback and U = (C/Δt + K)⁻¹E,
    (I − PᵀU·S)·a = Pᵀ(x − Tⁿ), Tⁿ⁺¹ = x + U·S·a, S = diag(s).  :attr:`feedback_heat` holds
    the heats S·a [W] the step added to the sources given.
    """

    def __init__(self, network: ThermalNetwork, max_cache: int = 64,
                 feedback_sources: np.ndarray | None = None,
                 feedback_probes: np.ndarray | None = None):
        self.network = network
        self._cache: dict[Hashable, tuple] = {}
        self._responses: dict[Hashable, np.ndarray] = {}
        # what a step needs of a cached system besides its LU, computed once per system
        self._step_data: dict[Hashable, dict] = {}
        self.max_cache = max_cache
        self.factorisations = 0
        self._factorise = PatternFactoriser()   # one ordering for the network's pattern
        self.payload = None
        self.feedback_sources = feedback_sources
        self.feedback_probes = feedback_probes
        self.feedback_heat = np.zeros(0 if feedback_sources is None
                                      else feedback_sources.shape[1])

    @property
    def orderings(self) -> int:
        """Fill-reducing orderings computed for the :attr:`factorisations` (one per sparsity
        pattern)."""
        return self._factorise.orderings

    def system(self, key: Hashable, dt: float, build) -> tuple:
        """Factorised system (LU, K, F, payload) for ``key`` and ``dt``; ``build()`` returns
        (K, F) or (K, F, payload) when needed."""
        full_key = (key, dt)
        entry = self._cache.get(full_key)
        if entry is None:
            k, f, *payload = build()
            lu = self._factorise((sp.diags(self.network.capacity / dt) + k).tocsc())
            entry = (lu, k, f, payload[0] if payload else None)
            if len(self._cache) >= self.max_cache:
                oldest = next(iter(self._cache))
                self._cache.pop(oldest)
                self._responses.pop(oldest, None)
                self._step_data.pop(oldest, None)
            self._cache[full_key] = entry
            self.factorisations += 1
        return entry

    def step(self, temperatures: np.ndarray, dt: float, source: np.ndarray,
             fixed_temperatures: np.ndarray, key: Hashable, build,
             slopes: np.ndarray | None = None) -> tuple[np.ndarray, float]:
        """Advance one step; ``slopes`` [W/K] of the feedback sources make it linearly
        implicit in them (see the class docstring), ``None`` takes ``source`` as given.

        Returns
        -------
        T1 : numpy.ndarray
            Temperatures after the step [K].
        heat_out : float
            Heat that left to the fixed nodes during the step [J]: Δt·Σ_ij F_ij·(T¹_i −
            T_fixed,j), through the conductances F that link the unknowns to them.
        """
        lu, k, f, self.payload = self.system(key, dt, build)
        data = self._step_data.get((key, dt))
        if data is None:
            # each unknown's conductance to the fixed nodes, F·1: the heat to them is
            # Σ_ij F_ij·(T_i − T_fixed,j) (= Σ(K·T) − Σ(F·T_fixed) for a network's K, whose
            # other couplings conserve heat), a dense product instead of a sparse one
            data = {"capacity_dt": self.network.capacity / dt,
                    "fixed_conductance": np.asarray(f.sum(axis=1)).ravel(), "fixed": None}
            self._step_data[(key, dt)] = data
        fixed = np.asarray(fixed_temperatures, dtype=float)
        if data["fixed"] is None or data["fixed"][0] != fixed.tobytes():
            flux = f @ fixed
            data["fixed"] = (fixed.tobytes(), flux, float(np.sum(flux)))
        _, fixed_flux, fixed_flux_sum = data["fixed"]
        rhs = data["capacity_dt"] * temperatures + fixed_flux + source
        t1 = lu.solve(rhs)
        self.feedback_heat = np.zeros(self.feedback_heat.shape)
        if slopes is not None and (slopes != 0.0).any():
            probes = self.feedback_probes
            cached = self._responses.get((key, dt))
            if cached is None:
                responses = np.stack([lu.solve(column) for column in self.feedback_sources.T],
                                     axis=1)
                cached = self._responses[(key, dt)] = (responses, probes.T @ responses)
            responses, coupling = cached
            system = np.eye(slopes.size) - coupling * slopes[None, :]
            if np.linalg.det(system) > 0.1:  # else a source outruns the network within the step
                self.feedback_heat = slopes * np.linalg.solve(system,
                                                              probes.T @ (t1 - temperatures))
                t1 = t1 + responses @ self.feedback_heat
        heat_out = dt * (float(data["fixed_conductance"] @ t1) - fixed_flux_sum)
        return t1, heat_out
