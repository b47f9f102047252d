r"""Quad meshes of any seal profile: gmsh (Python API), or a built-in fallback.

The element size is a field over the section (:class:`SizeField`):

.. math::

    h(\mathbf x) = \min\bigl(h_\mathrm{body},\;
        h_\mathrm{contact} + g\,d_\mathrm{contact}(\mathbf x),\;
        t(\mathbf x)/n_\mathrm{across} + g\,d_\mathrm{boundary}(\mathbf x)\bigr)

with :math:`h_\mathrm{contact}` a fraction of the profile's contact scale (its radial height,
or the lip head of a radial lip seal), :math:`d_\mathrm{contact}` the distance to the boundary where contact is expected
(segments tagged ``"contact"``; for a profile without tags the boundary within 15 % of the
radial height of its two radial extremes), :math:`t` the local wall thickness at the nearest
boundary point (distance to the opposite side) so that thin lips and flex sections get
``n_across`` elements across, and the grading :math:`g` = 0.3. Sizes are fractions of the
section's radial height (:data:`PROFILE_MESH_LEVELS`).

gmsh meshes the contour (lines and circular arcs of the built-in kernel) with
frontal-Delaunay triangles at twice the size and subdivides every triangle into three quads
(``Mesh.SubdivisionAlgorithm = 1``): an all-quad mesh with the requested size. gmsh's wheel
loads system OpenGL/X11 libraries (libGLU, libXrender, libXcursor, libXft, libXinerama,
libfontconfig); where they are missing (a minimal container), or with ``backend="builtin"``,
the built-in mesher does the same with numpy/scipy: a conforming Delaunay refinement
(Ruppert-style, circumcentres inserted in batches, encroached boundary segments split) at
twice the size, Laplacian smoothing, and the split of every triangle into three quads
(centroid and edge midpoints). Both give counter-clockwise quads, the boundary loop and the
node sets of tagged segments.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.spatial import Delaunay, cKDTree

from sealsim.errors import InputError
from sealsim.structure.contour import Contour, arc_geometry
from sealsim.structure.geometry import ORing
from sealsim.structure.mesh import SealMesh, mesh_oring
from sealsim.structure.profiles import SealProfile

__all__ = ["PROFILE_MESH_LEVELS", "SizeField", "gmsh_status", "mesh_profile", "mesh_section",
           "size_field"]

PROFILE_MESH_LEVELS = {
    # level: (contact size, body size) as fractions of the radial height, elements across a
    # thin wall
    "coarse": (1 / 40, 1 / 7, 3),
    "medium": (1 / 60, 1 / 9, 4),
    "fine": (1 / 90, 1 / 12, 5),
    "extra_fine": (1 / 135, 1 / 16, 7),
}
"""Named element sizes of profile meshes: size at the expected contact and in the body as
fractions of the section's radial height, and elements across the thinnest walls."""

GRADING = 0.3
"""Growth of the element size per unit distance from fine regions [-]."""

_GMSH_STATUS: tuple[bool, str] | None = None


def gmsh_status() -> tuple[bool, str]:
    """(True, version) if the gmsh module loads, else (False, the reason)."""
    global _GMSH_STATUS
    if _GMSH_STATUS is None:
        try:
            import gmsh

            _GMSH_STATUS = (True, str(gmsh.__version__))
        except (ImportError, OSError) as exc:  # OSError: a system library is missing
            _GMSH_STATUS = (False, f"{type(exc).__name__}: {exc}")
    return _GMSH_STATUS


@dataclass
class SizeField:
    """Element size h(x, y) [m] of a profile mesh (see the module docstring)."""

    h_contact: float
    h_body: float
    across: int
    _contact_tree: cKDTree | None
    _boundary_tree: cKDTree
    _limit: np.ndarray  # size limit at each boundary sample (wall thickness, arc radius)

    def __call__(self, x, y):
        p = np.stack([np.atleast_1d(np.asarray(x, float)), np.atleast_1d(np.asarray(y, float))],
                     axis=-1)
        h = np.full(len(p), self.h_body)
        if self._contact_tree is not None:
            d, _ = self._contact_tree.query(p)
            h = np.minimum(h, self.h_contact + GRADING * d)
        d, i = self._boundary_tree.query(p)
        h = np.minimum(h, self._limit[i] + GRADING * d)
        return h


def size_field(profile: SealProfile, level: str = "medium", *,
               size_contact: float | None = None, size_body: float | None = None) -> SizeField:
    """The element size field of a profile (see the module docstring).

    Parameters
    ----------
    profile : SealProfile
        The section.
    level : str
        One of :data:`PROFILE_MESH_LEVELS`.
    size_contact, size_body : float, optional
        Explicit sizes [m] (override the level).
    """
    if level not in PROFILE_MESH_LEVELS:
        raise InputError(f"mesh.level: {level!r} is not allowed; choose one of "
                         f"{', '.join(PROFILE_MESH_LEVELS)}")
    fc, fb, across = PROFILE_MESH_LEVELS[level]
    h0 = profile.radial_extent
    hc = fc * profile.contact_scale if size_contact is None else float(size_contact)
    hb = fb * h0 if size_body is None else float(size_body)
    if not (hc > 0 and hb > 0):
        raise InputError("mesh: element sizes must be positive")
    hb = max(hb, hc)
    contour = profile.contour
    s, seg = contour.sample(0.25 * hc)
    tags = np.array([contour.tags[k] for k in seg])
    contact = tags == "contact"
    if not np.any(contact) and "contact" not in contour.tags:
        y0, y1 = s[:, 1].min(), s[:, 1].max()
        contact = (s[:, 1] <= y0 + 0.15 * h0) | (s[:, 1] >= y1 - 0.15 * h0)
    contact &= tags != "bonded"
    limit = np.full(len(s), hb)
    # wall thickness at each sample: the nearest point that is far away along the contour
    # (on coarser samples: the thickness only matters where it is below n_across·h_body)
    w, _ = contour.sample(0.25 * min(hb, profile.min_feature))
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(w, axis=0), axis=1))])
    total = arc[-1] + float(np.linalg.norm(w[0] - w[-1]))
    pairs = cKDTree(w).query_pairs(across * hb, output_type="ndarray")
    thick = np.full(len(w), np.inf)
    if len(pairs):
        d = np.linalg.norm(w[pairs[:, 0]] - w[pairs[:, 1]], axis=1)
        along = np.abs(arc[pairs[:, 0]] - arc[pairs[:, 1]])
        along = np.minimum(along, total - along)
        far = along > 2.0 * d
        np.minimum.at(thick, pairs[far, 0], d[far])
        np.minimum.at(thick, pairs[far, 1], d[far])
    _, nearest = cKDTree(w).query(s)
    limit = np.minimum(limit, thick[nearest] / across)
    tree = cKDTree(s)
    # arcs: at least about 10 elements per quarter circle where that is coarser than h_contact
    for k in np.nonzero(contour.bulges)[0]:
        p0, p1, b, _ = contour.segment(k)
        _, radius, _, _ = arc_geometry(p0, p1, b)
        on = seg == k
        limit[on] = np.minimum(limit[on], max(0.16 * radius, hc))
    limit = np.maximum(limit, 0.2 * hc)  # guard against degenerate thin slivers
    ctree = cKDTree(s[contact]) if np.any(contact) else None
    return SizeField(hc, hb, across, ctree, tree, limit)


def mesh_profile(profile: SealProfile, level: str = "medium", *,
                 size_contact: float | None = None, size_body: float | None = None,
                 backend: str = "auto") -> SealMesh:
    """All-quad mesh of a seal profile.

    Parameters
    ----------
    profile : SealProfile
        The section (its contour in place).
    level : str
        One of :data:`PROFILE_MESH_LEVELS`.
    size_contact, size_body : float, optional
        Explicit element sizes [m].
    backend : {"auto", "gmsh", "builtin"}
        "auto" uses gmsh where it loads, the built-in mesher otherwise.

    Returns
    -------
    SealMesh
        Quads (counter-clockwise), the boundary loop (counter-clockwise), node sets
        ``"bonded"``, ``"spring"`` and ``"contact"`` of the tagged segments; no symmetry
        nodes.

    Examples
    --------
    >>> from sealsim.structure.profiles import rectangular_profile
    >>> m = mesh_profile(rectangular_profile(3e-3, 3e-3, 20e-3), "coarse", backend="builtin")
    >>> m.cells.shape[1], bool(np.all(np.isin(m.boundary, m.cells)))
    (4, True)
    """
    sizes = size_field(profile, level, size_contact=size_contact, size_body=size_body)
    if backend not in ("auto", "gmsh", "builtin"):
        raise InputError(f"mesh.backend: {backend!r} is not allowed; choose auto, gmsh or "
                         "builtin")
    ok, why = gmsh_status()
    if backend == "gmsh" and not ok:
        raise InputError(f"mesh.backend = 'gmsh' but gmsh cannot be loaded ({why}); install "
                         "the system libraries it needs (Debian/Ubuntu: apt install "
                         "libglu1-mesa libxrender1 libxcursor1 libxft2 libxinerama1) or use "
                         "backend = 'builtin'")
    use_gmsh = backend == "gmsh" or (backend == "auto" and ok)
    contour = profile.contour
    if use_gmsh:
        points, quads, loop, loop_seg = _mesh_gmsh(contour, sizes)
    else:
        points, quads, loop, loop_seg = _mesh_builtin(contour, sizes)
    return _seal_mesh(contour, points, quads, loop, loop_seg)


def _seal_mesh(contour: Contour, points, quads, loop, loop_seg) -> SealMesh:
    """Drop unused nodes, orient the quads, collect the node sets."""
    used = np.unique(quads)
    renumber = -np.ones(len(points), dtype=int)
    renumber[used] = np.arange(len(used))
    pts = points[used]
    cells = renumber[quads]
    loop = renumber[loop]
    if np.any(loop < 0):
        raise RuntimeError("profile mesh: boundary node outside the cells (internal error)")
    p = pts[cells]
    area2 = np.sum(p[..., 0] * np.roll(p[..., 1], -1, axis=1)
                   - np.roll(p[..., 0], -1, axis=1) * p[..., 1], axis=1)
    cells = np.where((area2 < 0)[:, None], cells[:, ::-1], cells)
    p = pts[cells]
    area2 = np.sum(p[..., 0] * np.roll(p[..., 1], -1, axis=1)
                   - np.roll(p[..., 0], -1, axis=1) * p[..., 1], axis=1)
    if np.any(area2 <= 0):
        raise InputError("the seal profile could not be meshed with valid elements; check the "
                         "contour for very thin slivers or use a finer mesh level")
    sets = {}
    for tag in ("bonded", "spring", "contact"):
        on = np.array([contour.tags[k] == tag for k in loop_seg])
        # a segment's nodes: its own loop nodes and the first node of the next segment
        nodes = set(loop[on].tolist()) | set(np.roll(loop, -1)[on].tolist())
        if nodes:
            sets[tag] = np.array(sorted(nodes))
    xc, yc = contour.centroid()
    return SealMesh(pts, cells, loop, (xc, yc), np.array([], dtype=int), sets)


# -- gmsh -----------------------------------------------------------------------------------------

def _mesh_gmsh(contour: Contour, sizes: SizeField):
    import gmsh

    gmsh.initialize(readConfigFiles=False, interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.Verbosity", 1)
        gmsh.model.add("seal")
        geo = gmsh.model.geo
        pts = [geo.addPoint(x, y, 0.0) for x, y in contour.points]
        curves, curve_seg = [], []  # gmsh curves and the contour segment of each
        n = contour.n
        for k in range(n):
            p0, p1, b, _ = contour.segment(k)
            a, e = pts[k], pts[(k + 1) % n]
            if b == 0.0:
                curves.append(geo.addLine(a, e))
                curve_seg.append(k)
                continue
            c, r, a0, th = arc_geometry(p0, p1, b)
            centre = geo.addPoint(c[0], c[1], 0.0)
            if abs(th) < 0.9 * math.pi:
                curves.append(geo.addCircleArc(a, centre, e))
                curve_seg.append(k)
            else:  # gmsh arcs must be shorter than a half circle
                am = a0 + 0.5 * th
                mid = geo.addPoint(c[0] + r * math.cos(am), c[1] + r * math.sin(am), 0.0)
                curves += [geo.addCircleArc(a, centre, mid), geo.addCircleArc(mid, centre, e)]
                curve_seg += [k, k]
        loop = geo.addCurveLoop(curves)
        geo.addPlaneSurface([loop])
        geo.synchronize()
        for name in ("MeshSizeExtendFromBoundary", "MeshSizeFromPoints",
                     "MeshSizeFromCurvature"):
            gmsh.option.setNumber(f"Mesh.{name}", 0)
        # the size field as a background view (linear on a triangulation of sample points):
        # a Python size callback would be called some 1e5 times
        bg, tri = _background_points(contour, sizes)
        h = 2.0 * sizes(*bg.T)
        xyz = bg[tri]  # (m, 3, 2)
        data = np.concatenate([xyz[:, :, 0], xyz[:, :, 1], np.zeros((len(tri), 3)), h[tri]],
                              axis=1)
        view = gmsh.view.add("size")
        gmsh.view.addListData(view, "ST", len(tri), data.ravel().tolist())
        field = gmsh.model.mesh.field.add("PostView")
        gmsh.model.mesh.field.setNumber(field, "ViewTag", view)
        gmsh.model.mesh.field.setAsBackgroundMesh(field)
        # frontal-Delaunay triangles, each split into three quads: recombining the triangles
        # first (Blossom) leaves quads with two edges on a smooth boundary, i.e. an angle
        # near 180°, where the contact is
        gmsh.option.setNumber("Mesh.Algorithm", 6)
        gmsh.option.setNumber("Mesh.RecombineAll", 0)
        gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1)  # all quads
        gmsh.option.setNumber("Mesh.Smoothing", 10)
        gmsh.model.mesh.generate(2)
        tags, xyz, _ = gmsh.model.mesh.getNodes()
        index = np.zeros(int(tags.max()) + 1, dtype=int)
        index[tags.astype(int)] = np.arange(len(tags))
        points = xyz.reshape(-1, 3)[:, :2].copy()
        etypes, _, enodes = gmsh.model.mesh.getElements(2)
        quads = None
        for et, en in zip(etypes, enodes):
            if et != 3:
                raise RuntimeError(f"gmsh returned elements of type {et}, not quads")
            quads = index[en.astype(int)].reshape(-1, 4)
        edges, edge_seg = [], []
        for ctag, k in zip(curves, curve_seg):
            _, _, cn = gmsh.model.mesh.getElements(1, abs(ctag))
            e = index[cn[0].astype(int)].reshape(-1, 2)
            edges.append(e)
            edge_seg += [k] * len(e)
    finally:
        gmsh.finalize()
    loop, loop_seg = _boundary_loop(points, np.concatenate(edges), np.array(edge_seg))
    return points, quads, loop, loop_seg


def _background_points(contour: Contour, sizes: SizeField):
    """Sample points of the size field (boundary, a grid, layers inside the boundary) and
    their Delaunay triangles."""
    s, _ = contour.sample(0.5 * sizes.h_contact)
    x0, x1, y0, y1 = contour.bounds
    pad = sizes.h_body
    step = 0.5 * sizes.h_body
    gx = np.arange(x0 - pad, x1 + pad + step, step)
    gy = np.arange(y0 - pad, y1 + pad + step, step)
    grid = np.stack(np.meshgrid(gx, gy, indexing="ij"), axis=-1).reshape(-1, 2)
    # layers parallel to the boundary, where the size grows fastest
    t = np.roll(s, -1, axis=0) - np.roll(s, 1, axis=0)
    nrm = np.stack([t[:, 1], -t[:, 0]], axis=1) / np.linalg.norm(t, axis=1)[:, None]
    h = sizes(*s.T)
    layers = [s + sign * f * h[:, None] * nrm for f in (1.0, 3.0) for sign in (1.0, -1.0)]
    pts = np.vstack([s, grid, *layers])
    return pts, Delaunay(pts).simplices


def _boundary_loop(points, edges, edge_seg):
    """Order boundary edges into one counter-clockwise loop of nodes; the segment of the
    edge that starts at each loop node."""
    nxt = {}
    for (a, b), k in zip(edges.tolist(), edge_seg.tolist()):
        nxt.setdefault(a, []).append((b, k))
        nxt.setdefault(b, []).append((a, k))
    if any(len(v) != 2 for v in nxt.values()):
        raise RuntimeError("profile mesh: the boundary is not one closed loop (internal error)")
    start = int(edges[0, 0])
    loop, segs, prev, cur = [], [], None, start
    for _ in range(len(edges)):
        (b0, k0), (b1, k1) = nxt[cur]
        b, k = (b0, k0) if b0 != prev else (b1, k1)
        loop.append(cur)
        segs.append(k)
        prev, cur = cur, b
    loop, segs = np.array(loop), np.array(segs)
    p = points[loop]
    area = np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
    if area < 0:  # reverse: the edge from loop[i] to loop[i-1] becomes the edge of loop[i]
        segs = np.roll(segs, 1)[::-1]
        loop = loop[::-1]
    return loop, segs


# -- built-in fallback ----------------------------------------------------------------------------

def _discretise_boundary(contour: Contour, size):
    """Boundary points spaced by ``size`` (a function of position) and their segment index."""
    out, seg = [], []
    for k in range(contour.n):
        p0, p1, b, _ = contour.segment(k)
        fine = 200
        t = np.linspace(0.0, 1.0, fine + 1)
        if b == 0.0:
            xy = p0[None] + t[:, None] * (p1 - p0)[None]
        else:
            c, r, a0, th = arc_geometry(p0, p1, b)
            a = a0 + th * t
            xy = c[None] + r * np.stack([np.cos(a), np.sin(a)], axis=1)
        ds = np.linalg.norm(np.diff(xy, axis=0), axis=1)
        h = size(*(0.5 * (xy[1:] + xy[:-1])).T)
        cum = np.concatenate([[0.0], np.cumsum(ds / h)])
        m = max(1, int(math.ceil(cum[-1] - 1e-9)))
        targets = np.arange(m) * cum[-1] / m
        tt = np.interp(targets, cum, t)
        if b == 0.0:
            pts = p0[None] + tt[:, None] * (p1 - p0)[None]
        else:
            a = a0 + th * tt
            pts = c[None] + r * np.stack([np.cos(a), np.sin(a)], axis=1)
        out.append(pts)
        seg.append(np.full(len(pts), k))
    return np.concatenate(out), np.concatenate(seg)


def _on_curve(contour: Contour, k: int, p, q):
    """Midpoint of boundary edge p-q of segment k, on the true curve."""
    m = 0.5 * (p + q)
    _, _, b, _ = contour.segment(k)
    if b == 0.0:
        return m
    p0, p1, _, _ = contour.segment(k)
    c, r, _, _ = arc_geometry(p0, p1, b)
    v = m - c
    return c + r * v / np.linalg.norm(v)


def _triangulate(boundary, interior, poly):
    """Delaunay triangles inside the contour and the boundary edges they miss."""
    B = np.asarray(boundary)
    pts = np.vstack([B, interior]) if len(interior) else B
    simp = Delaunay(pts).simplices
    u, v = pts[simp[:, 1]] - pts[simp[:, 0]], pts[simp[:, 2]] - pts[simp[:, 0]]
    area = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
    scale = np.max(np.ptp(pts, axis=0)) ** 2
    # slivers of three points on one straight boundary segment have no area: drop them
    simp = simp[(area > 1e-12 * scale) & poly.contains_points(pts[simp].mean(axis=1))]
    nb = len(B)
    edges = np.sort(np.concatenate([simp[:, [0, 1]], simp[:, [1, 2]], simp[:, [2, 0]]]), axis=1)
    have = set(map(tuple, edges.tolist()))
    missing = [i for i in range(nb) if tuple(sorted((i, (i + 1) % nb))) not in have]
    return pts, simp, missing


def _split_boundary(contour, boundary, bsegs, edges):
    """Insert the curve midpoint of the given boundary edges (in place)."""
    nb = len(boundary)
    for i in sorted(set(edges), reverse=True):
        m = _on_curve(contour, bsegs[i], np.asarray(boundary[i]),
                      np.asarray(boundary[(i + 1) % nb]))
        boundary.insert(i + 1, tuple(m))
        bsegs.insert(i + 1, bsegs[i])


def _mesh_builtin(contour: Contour, sizes: SizeField):
    from matplotlib.path import Path

    def target(x, y):
        return 2.0 * sizes(x, y)

    bpts, bseg = _discretise_boundary(contour, target)
    poly = Path(contour.sample(0.05 * sizes.h_contact)[0])
    boundary = [tuple(p) for p in bpts]  # ordered loop, grows when segments are split
    bsegs = list(bseg)
    interior = np.zeros((0, 2))
    for _ in range(80):
        pts, simp, missing = _triangulate(boundary, interior, poly)
        B = np.asarray(boundary)
        nb = len(B)
        mid = 0.5 * (B + np.roll(B, -1, axis=0))
        rad = 0.5 * np.linalg.norm(np.roll(B, -1, axis=0) - B, axis=1)
        if len(interior):
            # interior points inside the diametral circle of a boundary edge encroach it
            d, _ = cKDTree(interior).query(mid)
            missing = sorted(set(missing) | set(np.nonzero(d < rad)[0].tolist()))
        if missing:
            _split_boundary(contour, boundary, bsegs, missing)
            if len(interior):
                d, _ = cKDTree(np.asarray(boundary)).query(interior)
                interior = interior[d > 0.3 * target(*interior.T)]
            continue
        # refine triangles that are too big or badly shaped (Ruppert): circumcentres
        P = pts[simp]
        a, b, c = P[:, 0], P[:, 1], P[:, 2]
        la = np.linalg.norm(b - c, axis=1)
        lb = np.linalg.norm(c - a, axis=1)
        lc = np.linalg.norm(a - b, axis=1)
        area = 0.5 * np.abs((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
        R = la * lb * lc / (4.0 * np.maximum(area, 1e-300))
        h = target(*P.mean(axis=1).T)
        bad = (R > 0.62 * h) | (R / np.minimum(np.minimum(la, lb), lc) > 1.1)
        if not np.any(bad):
            break
        ax, ay, bx, by, cx, cy = a[bad, 0], a[bad, 1], b[bad, 0], b[bad, 1], c[bad, 0], c[bad, 1]
        dd = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
        with np.errstate(all="ignore"):
            ux = ((ax**2 + ay**2) * (by - cy) + (bx**2 + by**2) * (cy - ay)
                  + (cx**2 + cy**2) * (ay - by)) / dd
            uy = ((ax**2 + ay**2) * (cx - bx) + (bx**2 + by**2) * (ax - cx)
                  + (cx**2 + cy**2) * (bx - ax)) / dd
        cand = np.stack([ux, uy], axis=1)
        cand = cand[np.all(np.isfinite(cand), axis=1)]
        inside = poly.contains_points(cand)
        split = []
        if not np.all(inside):
            # a circumcentre outside: split the boundary edge nearest to it
            _, idx = cKDTree(mid).query(cand[~inside])
            split = [i for i in set(idx.tolist()) if 2 * rad[i] > 0.2 * target(*mid[i])[0]]
        cand = cand[inside]
        if len(cand):
            hc = target(*cand.T)
            d, _ = cKDTree(pts).query(cand)
            keep = d > 0.45 * hc
            cand, hc = cand[keep], hc[keep]
        chosen = []
        for i in np.argsort(hc) if len(cand) else []:
            if chosen and np.min(np.linalg.norm(cand[chosen] - cand[i], axis=1)) < 0.5 * hc[i]:
                continue
            chosen.append(i)
        new = cand[chosen] if chosen else np.zeros((0, 2))
        if len(new):
            # a new point that encroaches a boundary edge splits that edge instead
            d, idx = cKDTree(mid).query(new)
            enc = d < rad[idx]
            split += idx[enc].tolist()
            interior = np.vstack([interior, new[~enc]])
        if split:
            _split_boundary(contour, boundary, bsegs, split)
        if not len(new) and not split:
            break
    pts, simp, missing = _triangulate(boundary, interior, poly)
    if missing:
        raise InputError("the built-in mesher could not mesh the seal profile (boundary not "
                         "resolved); use a finer mesh level or gmsh")
    nb = len(boundary)
    # Laplacian smoothing of the interior points on the fixed (conforming) connectivity;
    # a step that would invert a triangle is not taken
    e = np.concatenate([simp[:, [0, 1]], simp[:, [1, 2]], simp[:, [2, 0]]])
    e = np.concatenate([e, e[:, ::-1]])
    cnt = np.bincount(e[:, 0], minlength=len(pts)).astype(float)

    def signed(p):
        u, v = p[simp[:, 1]] - p[simp[:, 0]], p[simp[:, 2]] - p[simp[:, 0]]
        return u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]

    sign = np.sign(signed(pts))
    for _ in range(4):
        acc = np.zeros_like(pts)
        np.add.at(acc, e[:, 0], pts[e[:, 1]])
        moved = pts.copy()
        moved[nb:] = acc[nb:] / np.maximum(cnt[nb:], 1)[:, None]
        if np.any(np.sign(signed(moved)) != sign):
            break
        pts = moved
    simp = np.where((sign < 0)[:, None], simp[:, [0, 2, 1]], simp)
    # split every triangle into three quads (centroid and edge midpoints)
    edge_id, new_pts, count = {}, [pts], len(pts)
    bedge = {tuple(sorted((i, (i + 1) % nb))): i for i in range(nb)}

    def midpoint(a, b):
        nonlocal count
        key = (a, b) if a < b else (b, a)
        if key not in edge_id:
            if key in bedge:
                i = bedge[key]
                m = _on_curve(contour, bsegs[i], pts[i], pts[(i + 1) % nb])
            else:
                m = 0.5 * (pts[a] + pts[b])
            edge_id[key] = count
            new_pts.append(m[None])
            count += 1
        return edge_id[key]

    quads = []
    for a, b, c in simp.tolist():
        g = count
        new_pts.append(pts[[a, b, c]].mean(axis=0)[None])
        count += 1
        mab, mbc, mca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        quads += [(a, mab, g, mca), (b, mbc, g, mab), (c, mca, g, mbc)]
    if not quads:
        raise InputError("the seal profile could not be meshed (no elements)")
    loop, loop_seg = [], []
    for i in range(nb):
        loop += [i, edge_id[tuple(sorted((i, (i + 1) % nb)))]]
        loop_seg += [bsegs[i], bsegs[i]]
    return np.vstack(new_pts), np.array(quads), np.array(loop), np.array(loop_seg)


def mesh_section(section, centre, level: str = "medium", **kwargs) -> SealMesh:
    """Mesh a seal cross-section with its centre at ``centre`` [m]: the O-grid for an
    :class:`~.geometry.ORing`, gmsh (or the built-in fallback) for a :class:`~.profiles.SealProfile`
    (moved axially so that its area centroid lies at ``centre[0]``; radii are kept)."""
    if isinstance(section, ORing):
        return mesh_oring(section, centre, level, **kwargs)
    from sealsim.structure.profiles import SealProfile

    if isinstance(section, SealProfile):
        shift = centre[0] - section.contour.centroid()[0]
        return mesh_profile(section.translated(shift), level, **kwargs)
    raise InputError(f"no mesh builder for seal sections of type {type(section).__name__}")
