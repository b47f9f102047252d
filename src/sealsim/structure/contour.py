r"""Closed contours of axisymmetric seal cross-sections: lines and circular arcs, checks,
fillets, user polylines and DXF files.

Coordinates follow FElupe's axisymmetric convention (see :mod:`.geometry`): **x is the axial
coordinate z, y is the radius r**, both in m. A contour is a closed chain of segments; segment
``k`` runs from point ``k`` to point ``k + 1`` (the last one back to point 0) and is a straight
line (bulge 0) or a circular arc. The arc is given by its *bulge* :math:`b = \tan(\theta/4)`,
θ the signed included angle (positive counter-clockwise) -- the convention of DXF polylines, so
a DXF ``LWPOLYLINE`` maps one to one. Each segment carries a tag:

* ``""`` -- free surface (may touch a rigid surface of the gland, may be wetted by the fluid);
* ``"bonded"`` -- bonded to a rigid insert (the metal case of a radial lip seal): its nodes
  move with the housing;
* ``"spring"`` -- the seat of a garter spring;
* ``"contact"`` -- free surface where contact is expected (the mesher refines it).

Checks (:func:`check_contour`) name the problem and where it is: fewer than three points,
zero-length segments, a radius <= 0 (the section must lie off the axis), self-intersection,
zero area. Open contours are caught where a contour is assembled from pieces (a DXF drawing
or a polyline whose first and last point differ by more than the closing tolerance).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from sealsim.errors import InputError
from sealsim.files import check_input_file

__all__ = [
    "TAGS",
    "Contour",
    "arc_geometry",
    "check_contour",
    "contour_from_dxf",
    "contour_from_polyline",
    "filleted_contour",
]

TAGS = ("", "bonded", "spring", "contact")
"""Allowed segment tags (see the module docstring)."""

_MAX_ARC_STEP = math.radians(6.0)  # sampling of arcs for checks and plots


def arc_geometry(p0, p1, bulge):
    """Centre, radius, start angle and signed sweep of the arc from ``p0`` to ``p1``.

    Parameters
    ----------
    p0, p1 : array_like
        End points (x, y) [m].
    bulge : float
        tan(θ/4) of the signed included angle θ (counter-clockwise positive), ≠ 0.

    Returns
    -------
    centre : numpy.ndarray
        (x, y) [m].
    radius : float
        [m].
    start : float
        Angle of ``p0`` seen from the centre [rad].
    sweep : float
        Signed included angle θ [rad].

    Examples
    --------
    A quarter circle of radius 1 from (1, 0) to (0, 1), counter-clockwise:

    >>> c, r, a0, th = arc_geometry((1.0, 0.0), (0.0, 1.0), math.tan(math.pi / 8))
    >>> np.round(c, 12).tolist(), round(r, 12), round(math.degrees(th), 9)
    ([0.0, 0.0], 1.0, 90.0)
    """
    p0 = np.asarray(p0, dtype=float)
    p1 = np.asarray(p1, dtype=float)
    theta = 4.0 * math.atan(bulge)
    chord = p1 - p0
    c = float(np.hypot(*chord))
    radius = c / (2.0 * abs(math.sin(theta / 2.0)))
    mid = 0.5 * (p0 + p1)
    # distance of the centre from the chord midpoint, on the left of p0 -> p1 for a
    # counter-clockwise arc shorter than a half circle
    h = c / 2.0 / math.tan(theta / 2.0)
    left = np.array([-chord[1], chord[0]]) / c
    centre = mid + h * left
    start = math.atan2(p0[1] - centre[1], p0[0] - centre[0])
    return centre, radius, start, theta


@dataclass(frozen=True)
class Contour:
    """A closed contour of lines and arcs (see the module docstring).

    Parameters
    ----------
    points : numpy.ndarray
        (n, 2) corner points [m], x axial, y radial; the first point is not repeated.
    bulges : numpy.ndarray
        (n,) bulge of segment k (point k to k+1); 0 for a line.
    tags : tuple of str
        (n,) tag of segment k, one of :data:`TAGS`.

    Examples
    --------
    >>> sq = Contour(np.array([[0.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]]))
    >>> sq.area, sq.bounds
    (1.0, (0.0, 1.0, 1.0, 2.0))
    """

    points: np.ndarray
    bulges: np.ndarray = None
    tags: tuple = None
    _samples: dict = field(default_factory=dict, repr=False, compare=False)

    def __post_init__(self):
        pts = np.asarray(self.points, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2:
            raise InputError("a seal contour needs points as (x, y) pairs")
        n = len(pts)
        bul = np.zeros(n) if self.bulges is None else np.asarray(self.bulges, dtype=float)
        tags = ("",) * n if self.tags is None else tuple(self.tags)
        if bul.shape != (n,) or len(tags) != n:
            raise InputError(f"a seal contour of {n} points needs {n} bulges and {n} tags")
        bad = [t for t in tags if t not in TAGS]
        if bad:
            raise InputError(f"segment tag {bad[0]!r} is not allowed; use one of "
                             f"{', '.join(repr(t) for t in TAGS)}")
        object.__setattr__(self, "points", pts)
        object.__setattr__(self, "bulges", bul)
        object.__setattr__(self, "tags", tags)

    @property
    def n(self) -> int:
        return len(self.points)

    def segment(self, k: int):
        """(start point, end point, bulge, tag) of segment k."""
        return self.points[k], self.points[(k + 1) % self.n], float(self.bulges[k]), self.tags[k]

    def sample(self, max_step: float | None = None):
        """Points along the contour and the segment each comes from.

        Arcs get a point at least every 6°; with ``max_step`` [m] every segment gets points
        at most that far apart. The result starts at point 0 and does not repeat it.

        Returns
        -------
        points : numpy.ndarray
            (m, 2) [m].
        segment : numpy.ndarray
            (m,) index of the segment that starts at (or contains) each point.
        """
        key = max_step
        if key in self._samples:
            return self._samples[key]
        out, seg = [], []
        for k in range(self.n):
            p0, p1, b, _ = self.segment(k)
            if b == 0.0:
                length = float(np.hypot(*(p1 - p0)))
                m = 1 if max_step is None else max(1, math.ceil(length / max_step))
                t = np.arange(m) / m
                out.append(p0[None] + t[:, None] * (p1 - p0)[None])
            else:
                c, r, a0, th = arc_geometry(p0, p1, b)
                m = max(2, math.ceil(abs(th) / _MAX_ARC_STEP))
                if max_step is not None:
                    m = max(m, math.ceil(abs(th) * r / max_step))
                a = a0 + th * np.arange(m) / m
                out.append(c[None] + r * np.stack([np.cos(a), np.sin(a)], axis=1))
            seg.append(np.full(len(out[-1]), k))
        result = (np.concatenate(out), np.concatenate(seg))
        self._samples[key] = result
        return result

    @property
    def area(self) -> float:
        """Signed area [m²] (positive for a counter-clockwise contour), arcs included."""
        x, y = self.points[:, 0], self.points[:, 1]
        xn, yn = np.roll(x, -1), np.roll(y, -1)
        a = 0.5 * float(np.sum(x * yn - xn * y))
        for k in np.nonzero(self.bulges)[0]:
            p0, p1, b, _ = self.segment(k)
            _, r, _, th = arc_geometry(p0, p1, b)
            a += 0.5 * r * r * (th - math.sin(th))  # circular segment, signed with θ
        return a

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """(x_min, x_max, y_min, y_max) [m], exact for the arcs (their extreme points)."""
        pts = [self.points]
        for k in np.nonzero(self.bulges)[0]:
            p0, p1, b, _ = self.segment(k)
            c, r, a0, th = arc_geometry(p0, p1, b)
            for a in (0.0, 0.5 * math.pi, math.pi, 1.5 * math.pi):
                rel = (a - a0) % (2 * math.pi) if th > 0 else (a0 - a) % (2 * math.pi)
                if rel <= abs(th):
                    pts.append((c + r * np.array([math.cos(a), math.sin(a)]))[None])
        p = np.concatenate(pts)
        return (float(p[:, 0].min()), float(p[:, 0].max()), float(p[:, 1].min()),
                float(p[:, 1].max()))

    def centroid(self) -> tuple[float, float]:
        """Area centroid (x, y) [m] of the sampled polygon."""
        s, _ = self.sample()
        x, y = s[:, 0], s[:, 1]
        xn, yn = np.roll(x, -1), np.roll(y, -1)
        cross = x * yn - xn * y
        a = 0.5 * np.sum(cross)
        return (float(np.sum((x + xn) * cross) / (6 * a)),
                float(np.sum((y + yn) * cross) / (6 * a)))

    def counter_clockwise(self) -> Contour:
        """The same contour oriented counter-clockwise (reversed if needed)."""
        if self.area > 0:
            return self
        n = self.n
        order = [0, *range(n - 1, 0, -1)]
        # reversed segment k' runs from point order[k'] to order[k'+1]: the old segment
        # order[k'+1] -> order[k'] (i.e. old index order[k'+1]) with the opposite bulge
        seg = [(order[(k + 1) % n]) for k in range(n)]
        return Contour(self.points[order], -self.bulges[seg], tuple(self.tags[s] for s in seg))

    def translated(self, dx: float, dy: float = 0.0) -> Contour:
        """The contour moved by (dx, dy) [m]."""
        return Contour(self.points + np.array([dx, dy]), self.bulges, self.tags)


def _segments_intersect(a0, a1, b0, b1):
    """Proper intersections of segment sets a (m, 2, 2) against b (k, 2, 2) → (m, k) bool."""
    def orient(p, q, r):
        return ((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1])
                - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))

    A0, A1 = a0[:, None, :], a1[:, None, :]
    B0, B1 = b0[None, :, :], b1[None, :, :]
    d1 = orient(B0, B1, A0)
    d2 = orient(B0, B1, A1)
    d3 = orient(A0, A1, B0)
    d4 = orient(A0, A1, B1)
    return (d1 * d2 < 0) & (d3 * d4 < 0)


def check_contour(contour: Contour, name: str = "seal contour") -> Contour:
    """Check a contour and return it counter-clockwise; :class:`InputError` naming the problem.

    Parameters
    ----------
    contour : Contour
        The contour.
    name : str
        How the contour is called in messages (e.g. ``"seal.points"`` or a DXF file name).

    Examples
    --------
    A bow tie crosses itself:

    >>> bow = Contour(np.array([[0, 1.0], [1, 2.0], [1, 1.0], [0, 2.0]]) * 1e-3)
    >>> try:
    ...     check_contour(bow, "bow")
    ... except InputError as e:
    ...     print(str(e)[:60])
    bow: the contour crosses itself (segment 1 from (0, 1) mm ...
    """
    pts = contour.points
    if contour.n < 3 and not np.any(contour.bulges):
        raise InputError(f"{name}: a closed contour needs at least 3 points, got {contour.n}")
    scale = float(np.max(np.ptp(pts, axis=0))) if contour.n > 1 else 0.0
    if not np.all(np.isfinite(pts)) or scale <= 0:
        raise InputError(f"{name}: the points must be finite and not all equal")
    seg_len = np.linalg.norm(np.roll(pts, -1, axis=0) - pts, axis=1)
    short = np.nonzero(seg_len <= 1e-9 * scale)[0]
    if short.size:
        k = int(short[0])
        raise InputError(f"{name}: segment {k + 1} has zero length (point {k + 1} "
                         f"{_mm(pts[k])} repeats; remove the duplicate point)")
    if np.any(np.abs(contour.bulges) >= 1e3):
        raise InputError(f"{name}: an arc bulge of more than 1e3 is not allowed")
    s, seg = contour.sample()
    if np.any(s[:, 1] <= 0.0):
        k = int(np.argmin(s[:, 1]))
        raise InputError(f"{name}: the section reaches the axis or beyond (radius "
                         f"{s[k, 1] * 1e3:.4g} mm at z = {s[k, 0] * 1e3:.4g} mm); every point "
                         "needs a radius > 0 (y is the radius, x the axial coordinate)")
    a0, a1 = s, np.roll(s, -1, axis=0)
    m = len(s)
    cross = _segments_intersect(a0, a1, a0, a1)
    idx = np.arange(m)
    near = np.abs(idx[:, None] - idx[None, :])
    cross &= (near > 1) & (near < m - 1)
    if np.any(cross):
        i, j = (int(v) for v in np.argwhere(cross)[0])
        ki, kj = int(seg[i]), int(seg[j])
        raise InputError(
            f"{name}: the contour crosses itself (segment {ki + 1} from "
            f"{_mm(pts[ki])} mm and segment {kj + 1} from {_mm(pts[kj])} mm intersect); "
            "a seal section must be one simple closed loop")
    if abs(contour.area) <= 1e-9 * scale * scale:
        raise InputError(f"{name}: the contour encloses no area")
    return contour.counter_clockwise()


def _mm(p) -> str:
    return f"({p[0] * 1e3:.4g}, {p[1] * 1e3:.4g})"


def contour_from_polyline(points, bulges=None, tags=None, *, name: str = "seal.points",
                          close_tolerance: float = 1e-6) -> Contour:
    """A checked contour from a polyline [m]; the last point may repeat the first.

    Parameters
    ----------
    points : array_like
        (n, 2) points [m] (x axial, y radius).
    bulges, tags : sequence, optional
        Per segment (see :class:`Contour`).
    name : str
        Name in messages.
    close_tolerance : float
        A last point within this distance [m] of the first closes the contour.

    Examples
    --------
    >>> c = contour_from_polyline([[0, 1e-3], [2e-3, 1e-3], [2e-3, 2e-3], [0, 2e-3], [0, 1e-3]])
    >>> c.n, round(c.area * 1e6, 9)
    (4, 2.0)
    """
    pts = np.asarray(points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise InputError(f"{name}: give the points as a list of [z, r] pairs")
    n = len(pts)
    bul = None if bulges is None else list(bulges)
    tg = None if tags is None else list(tags)
    if n >= 2 and np.hypot(*(pts[-1] - pts[0])) <= close_tolerance:
        pts = pts[:-1]
        bul = bul[: n - 1] if bul is not None and len(bul) == n else bul
        tg = tg[: n - 1] if tg is not None and len(tg) == n else tg
    for label, values in (("bulges", bul), ("tags", tg)):
        if values is not None and len(values) != len(pts):
            raise InputError(f"{name}: {len(pts)} points need {len(pts)} {label} (one per "
                             f"segment, the last one closing the contour), got {len(values)}")
    return check_contour(Contour(pts, bul, tg), name)


def filleted_contour(points, radii, tags=None, *, corner_tags=None,
                     name: str = "profile") -> Contour:
    """A polygon whose corners are rounded with tangent arcs.

    Parameters
    ----------
    points : array_like
        (n, 2) polygon corners [m], counter-clockwise.
    radii : array_like or float
        Fillet radius [m] of each corner (0 keeps the sharp corner).
    tags : sequence of str, optional
        Tag of each polygon side (side k from corner k to k+1).
    corner_tags : sequence of str or None, optional
        Tag of each corner's fillet arc (None: the tag of the side before it).

    Examples
    --------
    A 2 x 2 square with corner radius 0.5 has the area 4 − (4 − π)·0.25:

    >>> sq = filleted_contour([[0, 1.0], [2, 1.0], [2, 3.0], [0, 3.0]], 0.5)
    >>> round(sq.area, 9) == round(4 - (4 - math.pi) * 0.25, 9), sq.n
    (True, 8)
    """
    P = np.asarray(points, dtype=float)
    n = len(P)
    r = np.broadcast_to(np.asarray(radii, dtype=float), (n,))
    sides = [""] * n if tags is None else list(tags)
    out_pts, out_bul, out_tag = [], [], []
    trims = np.zeros((n, 2))  # trim length at start / end of each side
    geo = []
    for k in range(n):
        a, p, b = P[k - 1], P[k], P[(k + 1) % n]
        u1 = (a - p) / np.linalg.norm(a - p)
        u2 = (b - p) / np.linalg.norm(b - p)
        cosang = float(np.clip(np.dot(u1, u2), -1.0, 1.0))
        half = 0.5 * math.acos(cosang)
        u, v = p - a, b - p
        turn = float(u[0] * v[1] - u[1] * v[0])  # > 0: left turn (convex corner, CCW loop)
        if r[k] <= 0 or half <= 1e-9 or abs(math.pi / 2 - half) < 1e-12:
            geo.append(None)
            continue
        t = r[k] / math.tan(half)
        trims[k - 1, 1] = t
        trims[k, 0] = t
        sweep = (math.pi - 2.0 * half) * (1.0 if turn > 0 else -1.0)
        geo.append((p + u1 * t, p + u2 * t, math.tan(sweep / 4.0)))
    lengths = np.linalg.norm(np.roll(P, -1, axis=0) - P, axis=1)
    over = np.nonzero(trims.sum(axis=1) > lengths * (1 + 1e-9))[0]
    if over.size:
        k = int(over[0])
        raise InputError(f"{name}: the corner radii at both ends of side {k + 1} "
                         f"({lengths[k] * 1e3:.4g} mm long) do not fit on it; reduce them")
    for k in range(n):
        g = geo[k]
        if g is None:
            out_pts.append(P[k])
            out_bul.append(0.0)
            out_tag.append(sides[k])
        else:
            t1, t2, bulge = g
            out_pts.append(t1)
            out_bul.append(bulge)
            own = None if corner_tags is None else corner_tags[k]
            out_tag.append(sides[k - 1] if own is None else own)
            if np.linalg.norm(t2 - P[(k + 1) % n]) > 1e-12 and \
                    trims[k].sum() < lengths[k] * (1 - 1e-9):
                out_pts.append(t2)
                out_bul.append(0.0)
                out_tag.append(sides[k])
    return Contour(np.array(out_pts), np.array(out_bul), tuple(out_tag))


#: Drawing units of a DXF header ($INSUNITS code) as pint unit texts.
DXF_UNITS = {1: "in", 2: "ft", 4: "mm", 5: "cm", 6: "m", 13: "um", 14: "dm"}


def dxf_declared_unit(path, name: str | None = None) -> str | None:
    """The length unit a DXF drawing declares in its header ($INSUNITS): ``"mm"``, ``"in"``,
    ...; None when it declares none (0, unitless) or cannot be parsed (the contour reader
    reports that); the name of any other declared unit as ezdxf gives it.  A path that is no
    regular file (missing, a folder, a FIFO) is an InputError named ``name``."""
    import ezdxf
    from ezdxf.units import unit_name

    check_input_file(Path(path), "DXF file", label=name)
    try:
        code = int(ezdxf.readfile(str(path)).header.get("$INSUNITS", 0))
    except (OSError, ValueError, ezdxf.DXFError):
        return None
    if code == 0:
        return None
    return DXF_UNITS.get(code, unit_name(code))


def contour_from_dxf(path, *, layer: str | None = None, unit: float = 1e-3,
                     close_tolerance: float = 1e-6, name: str | None = None) -> Contour:
    """Read a seal section from a DXF drawing (ezdxf).

    The section is either one closed ``LWPOLYLINE``/``POLYLINE`` (bulges become arcs) or a
    chain of ``LINE`` and ``ARC`` entities that closes; x of the drawing is the axial
    coordinate, y the radius. Only entities on ``layer`` (if given) are read.

    Parameters
    ----------
    path : path-like
        The DXF file.
    layer : str, optional
        Layer to read (default: all layers).
    unit : float
        Length of one drawing unit [m] (default 1e-3: millimetres).
    close_tolerance : float
        End points closer than this [m] are joined.
    name : str, optional
        Name in messages (default the file name).

    Raises
    ------
    InputError
        Unreadable file, no entities, several closed polylines, an open chain of lines and
        arcs (names the loose end), or any problem of :func:`check_contour`.
    """
    import ezdxf

    p = Path(path)
    label = name or f"DXF file {str(p)!r}"
    check_input_file(p, "DXF file", label=label)
    try:
        doc = ezdxf.readfile(str(p))
    except (OSError, ezdxf.DXFError) as exc:
        raise InputError(f"{label} is not a readable DXF file: {exc}") from None
    msp = doc.modelspace()

    def on_layer(e):
        return layer is None or e.dxf.layer == layer

    polys = [e for e in msp.query("LWPOLYLINE POLYLINE") if on_layer(e)]
    pieces = [e for e in msp.query("LINE ARC") if on_layer(e)]
    where = f" on layer {layer!r}" if layer else ""
    if polys and pieces:
        raise InputError(f"{label}: found both polylines and LINE/ARC entities{where}; draw the "
                         "section as one closed polyline or as one chain of lines and arcs")
    tol = close_tolerance / unit
    if polys:
        if len(polys) > 1:
            raise InputError(f"{label}: {len(polys)} polylines{where}; the section must be one "
                             "closed polyline (put other geometry on another layer and give "
                             "the layer)")
        e = polys[0]
        if e.dxftype() == "LWPOLYLINE":
            data = [(x, y, b) for x, y, _s, _e, b in e.get_points("xyseb")]
            closed = e.closed
        else:
            data = [(v.dxf.location[0], v.dxf.location[1], v.dxf.bulge) for v in e.vertices]
            closed = e.is_closed
        pts = np.array([(x, y) for x, y, _ in data], dtype=float)
        bul = [b for _, _, b in data]
        if not closed and np.hypot(*(pts[-1] - pts[0])) > tol:
            raise InputError(
                f"{label}: the polyline is open (it ends at {_mm(pts[-1] * unit)} mm, "
                f"{np.hypot(*(pts[-1] - pts[0])) * unit * 1e3:.4g} mm from its start "
                f"{_mm(pts[0] * unit)} mm); close it")
        if not closed:
            pts, bul = pts[:-1], bul[:-1]
        return check_contour(Contour(pts * unit, np.array(bul)), label)
    if not pieces:
        raise InputError(f"{label}: no LWPOLYLINE, POLYLINE, LINE or ARC entity{where}")
    segs = []
    for e in pieces:
        if e.dxftype() == "LINE":
            segs.append((np.array([e.dxf.start.x, e.dxf.start.y]),
                         np.array([e.dxf.end.x, e.dxf.end.y]), 0.0))
        else:
            c = np.array([e.dxf.center.x, e.dxf.center.y])
            r = e.dxf.radius
            a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
            sweep = (a1 - a0) % (2 * math.pi) or 2 * math.pi
            segs.append((c + r * np.array([math.cos(a0), math.sin(a0)]),
                         c + r * np.array([math.cos(a1), math.sin(a1)]),
                         math.tan(sweep / 4.0)))
    return check_contour(_chain(segs, tol, label, unit), label)


def _chain(segs, tol, label, unit) -> Contour:
    """Join segments (start, end, bulge) end to end into one closed contour."""
    remaining = list(segs)
    start, end, b = remaining.pop(0)
    pts, bul = [start], [b]
    current = end
    while remaining:
        for i, (s, e, bb) in enumerate(remaining):
            if np.hypot(*(s - current)) <= tol:
                pts.append(s)
                bul.append(bb)
                current = e
                break
            if np.hypot(*(e - current)) <= tol:  # reversed piece
                pts.append(e)
                bul.append(-bb)
                current = s
                break
        else:
            raise InputError(f"{label}: the lines and arcs do not form a closed contour: "
                             f"nothing continues at {_mm(current * unit)} mm "
                             f"({len(remaining)} piece(s) left over)")
        remaining.pop(i)
    if np.hypot(*(current - pts[0])) > tol:
        raise InputError(f"{label}: the contour is open: it ends at {_mm(current * unit)} mm, "
                         f"not at its start {_mm(pts[0] * unit)} mm")
    return Contour(np.array(pts) * unit, np.array(bul))
