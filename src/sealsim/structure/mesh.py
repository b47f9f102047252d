"""Quad meshes of seal cross-sections (x = axial, y = radius, in m).

The O-ring section is an O-grid: a square core and four curved patches, one around each
point where the section meets a rigid surface (sealing surface, groove bottom, the two walls),
so that the contact zones get the finest, nearly uniform elements along the arc while the
±45° corners are coarser. Element layers are graded towards the surface.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from sealsim.errors import InputError
from sealsim.structure.geometry import ORing

__all__ = ["MESH_LEVELS", "SealMesh", "mesh_oring"]

MESH_LEVELS = {
    # level: (elements per 90° of arc at the radial surfaces, ... at the walls, radial layers)
    "coarse": (20, 8, 4),
    "medium": (40, 16, 6),
    "fine": (60, 24, 9),
    "extra_fine": (80, 32, 12),
}
"""Named mesh densities: elements per 90° of arc around the sealing surface and groove bottom
contacts, per 90° around the wall contacts, and element layers in the outer patches."""


@dataclass
class SealMesh:
    """A seal cross-section mesh.

    Attributes
    ----------
    points : numpy.ndarray
        (n, 2) node coordinates [m], column 0 axial (x = z), column 1 radial (y = r).
    cells : numpy.ndarray
        (m, 4) quad connectivity, counter-clockwise.
    boundary : numpy.ndarray
        Node ids of the outer boundary as a closed counter-clockwise loop (first node not
        repeated).
    centre : tuple of float
        Section centre [m].
    symmetry_nodes : numpy.ndarray
        Nodes on the vertical line through the centre (used by plane-strain checks); empty
        for unstructured meshes.
    node_sets : dict
        Named boundary node sets of profile meshes: ``"bonded"`` (moves with the housing),
        ``"spring"`` (garter spring seat).
    """

    points: np.ndarray
    cells: np.ndarray
    boundary: np.ndarray
    centre: tuple[float, float]
    symmetry_nodes: np.ndarray
    node_sets: dict = field(default_factory=dict)

    @property
    def npoints(self) -> int:
        return len(self.points)

    def min_boundary_spacing(self) -> float:
        """Smallest distance between neighbouring boundary nodes [m]."""
        p = self.points[self.boundary]
        return float(np.min(np.linalg.norm(np.roll(p, -1, axis=0) - p, axis=1)))


def _graded(n: int, ratio: float) -> np.ndarray:
    """n+1 values on [-1, 1], finest near 0; ends / centre spacing = ``ratio``."""
    u = np.linspace(-1.0, 1.0, n + 1)
    w = 5.0 / (ratio + 4.0)  # g'(0) = w, g'(1) = w + 5 (1 - w)  -> ratio
    return u * (w + (1.0 - w) * u**4)


def _layers(n: int, ratio: float) -> np.ndarray:
    """n+1 values on [0, 1]; first / last layer thickness = ``ratio`` (fine near 1)."""
    if n == 1:
        return np.array([0.0, 1.0])
    q = ratio ** (-1.0 / (n - 1))
    h = q ** np.arange(n)
    return np.concatenate([[0.0], np.cumsum(h) / np.sum(h)])


def mesh_oring(ring: ORing, centre: tuple[float, float], level: str = "medium", *,
               n_arc: int | None = None, n_wall: int | None = None,
               n_radial: int | None = None,
               arc_grading: float = 1.0, radial_grading: float = 4.0,
               core: float = 0.5) -> SealMesh:
    """O-grid quad mesh of an O-ring cross-section.

    Parameters
    ----------
    ring : ORing
        The O-ring (its cord diameter sets the radius).
    centre : tuple of float
        (x, y) of the section centre [m].
    level : str
        One of :data:`MESH_LEVELS` (ignored where ``n_arc``/``n_radial`` are given).
    n_arc : int, optional
        Elements per quarter of the circumference around the sealing-surface and
        groove-bottom contacts (even, >= 4).
    n_wall : int, optional
        Elements per quarter of the circumference around the wall contacts (even, >= 4).
    n_radial : int, optional
        Element layers between the core and the surface (>= 1).
    arc_grading : float
        Ratio of the largest to the smallest element along the arc (>= 1).
    radial_grading : float
        Ratio of the innermost to the outermost layer thickness (>= 1).
    core : float
        Half-width of the square core as a fraction of the radius (0.3–0.65).

    Returns
    -------
    SealMesh

    Examples
    --------
    >>> m = mesh_oring(ORing(4e-3, 20e-3), (0.0, 12e-3), "coarse")
    >>> m.npoints, len(m.cells), len(m.boundary)
    (413, 384, 56)
    """
    if level not in MESH_LEVELS and (n_arc is None or n_wall is None or n_radial is None):
        raise InputError(f"mesh.level: {level!r} is not allowed; choose one of "
                         f"{', '.join(MESH_LEVELS)}")
    defaults = MESH_LEVELS.get(level, (None, None, None))
    n = int(n_arc if n_arc is not None else defaults[0])
    nw = int(n_wall if n_wall is not None else defaults[1])
    nr = int(n_radial if n_radial is not None else defaults[2])
    if n < 4 or n % 2 or nw < 4 or nw % 2 or nr < 1:
        raise InputError(f"mesh: n_arc = {n} and n_wall = {nw} must be even and >= 4, "
                         f"n_radial = {nr} >= 1")
    if not (0.3 <= core <= 0.65) or arc_grading < 1 or radial_grading < 1:
        raise InputError("mesh: core must be 0.3-0.65, gradings >= 1")
    a = ring.radius
    c = core * a
    gx = _graded(n, arc_grading)  # along x: patches at the radial surfaces (top, bottom)
    gy = _graded(nw, arc_grading)  # along y: patches at the walls (right, left)
    t = _layers(nr, radial_grading)
    blocks = []
    # core rectangle of n x nw cells
    X, Y = np.meshgrid(c * gx, c * gy, indexing="ij")  # [i, j]
    blocks.append((np.stack([X, Y], axis=-1), "core"))
    for k in range(4):
        g = gy if k % 2 == 0 else gx
        phi = 0.5 * np.pi * k
        rot = np.array([[np.cos(phi), -np.sin(phi)], [np.sin(phi), np.cos(phi)]])
        inner = np.stack([np.full_like(g, c), c * g], axis=-1)
        theta = 0.25 * np.pi * g
        outer = a * np.stack([np.cos(theta), np.sin(theta)], axis=-1)
        local = (1.0 - t)[:, None, None] * inner[None] + t[:, None, None] * outer[None]  # [k, j]
        blocks.append((local @ rot.T, "patch"))
    points, cells, grids = [], [], []
    offset = 0
    for coords, _kind in blocks:
        ni, nj = coords.shape[:2]
        ids = offset + np.arange(ni * nj).reshape(ni, nj)
        points.append(coords.reshape(-1, 2))
        cells.append(np.stack([ids[:-1, :-1], ids[1:, :-1], ids[1:, 1:], ids[:-1, 1:]],
                              axis=-1).reshape(-1, 4))
        grids.append(ids)
        offset += ni * nj
    points = np.concatenate(points)
    cells = np.concatenate(cells)
    # merge duplicate nodes on the block interfaces
    key = np.round(points / a, 9)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    order = np.argsort(first)
    renumber = np.empty_like(order)
    renumber[order] = np.arange(order.size)
    new_points = points[first[order]]
    new_cells = renumber[inverse[cells]]
    loop = []
    for ids in grids[1:]:
        loop.extend(renumber[inverse[ids[-1, :-1]]])
    loop = np.asarray(loop)
    new_points = new_points + np.asarray(centre, dtype=float)
    sym = np.where(np.isclose(new_points[:, 0], centre[0], atol=1e-12 * a + 1e-15))[0]
    _check_cells(new_points, new_cells)
    return SealMesh(new_points, new_cells, loop, (float(centre[0]), float(centre[1])), sym)


def _check_cells(points, cells):
    p = points[cells]
    x, y = p[..., 0], p[..., 1]
    area2 = np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
    if np.any(area2 <= 0):
        raise RuntimeError("mesh has cells with non-positive area (internal error)")
