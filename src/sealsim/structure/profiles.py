r"""Seal cross-section profiles: parametric families and user contours.

A :class:`SealProfile` is a free (uninstalled) axisymmetric seal section given by a closed
:class:`~.contour.Contour` (x axial, y radius, m). It has the small interface the gland and
the FE model need -- :attr:`~SealProfile.radial_extent`, :attr:`~SealProfile.axial_extent`,
:attr:`~SealProfile.area`, :attr:`~SealProfile.inner_radius`,
:attr:`~SealProfile.outer_radius`, :attr:`~SealProfile.centre_radius` -- the same as
:class:`~.geometry.ORing`, so :class:`~.geometry.SealAssembly` places any profile in its
gland.

Families (each a function returning a :class:`SealProfile`):

* :func:`xring_profile` -- X-ring / quad ring: an ISO 3601 / AS568 sized square envelope
  with four lobes and concave valleys between them (two lobes touch each counter surface);
* :func:`rectangular_profile` -- rectangular or square ring with rounded corners;
* :func:`ucup_profile` -- pneumatic U-cup (lip seal) for a rod or a piston: a heel and two
  flared lips (dynamic and static) around a groove open to the pressure side;
* :func:`wiper_profile` -- a rod wiper: a heel in the groove and one lip towards the air side;
* :func:`radial_lip_profile` -- a DIN 3760 / ISO 6194-1 radial shaft seal (type A): lip head
  with oil- and air-side faces, spring groove, flex section and a body bonded to the metal case
  (the case itself is rigid: the bonded edges move with the housing);
* :func:`user_profile` -- any closed polyline (case file) or DXF drawing.

The proportions of the families are typical catalogue shapes, each documented where it is
set; they are parameters, so a user can match a drawing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sealsim.errors import InputError
from sealsim.structure.contour import (
    Contour,
    arc_geometry,
    check_contour,
    contour_from_dxf,
    contour_from_polyline,
    filleted_contour,
)

__all__ = [
    "SealProfile",
    "radial_lip_profile",
    "rectangular_profile",
    "ucup_profile",
    "user_profile",
    "wiper_profile",
    "xring_profile",
]


@dataclass(frozen=True)
class SealProfile:
    """A free seal cross-section of any shape.

    Parameters
    ----------
    family : str
        "xring", "rectangular", "ucup", "wiper", "radial_lip" or "user".
    contour : Contour
        Closed, checked, counter-clockwise contour [m] (x axial, y radius).
    min_feature : float
        Thinnest wall of the section [m] (lip, flex): the mesher puts several elements
        across it.
    spring_radius : float, optional
        Radius of the garter spring's coil axis in the free seal [m] (radial lip seals).
    contact_size : float, optional
        Size of the region that touches the counter surface [m] (default: the radial
        height); the contact elements are a fraction of it.

    Examples
    --------
    >>> p = rectangular_profile(3e-3, 4e-3, 20e-3, corner_radius=0.3e-3)
    >>> round(p.radial_extent * 1e3, 6), round(p.inner_radius * 1e3, 6)
    (4.0, 10.0)
    """

    family: str
    contour: Contour
    min_feature: float
    spring_radius: float | None = None
    contact_size: float | None = None

    @property
    def _bounds(self):
        return self.contour.bounds

    @property
    def radial_extent(self) -> float:
        """Free radial height of the section [m] (the 'cord' of the squeeze definition)."""
        b = self._bounds
        return b[3] - b[2]

    @property
    def axial_extent(self) -> float:
        """Free axial length of the section [m]."""
        b = self._bounds
        return b[1] - b[0]

    @property
    def contact_scale(self) -> float:
        """Length the contact element size refers to [m]."""
        return self.radial_extent if self.contact_size is None else self.contact_size

    @property
    def cord_diameter(self) -> float:
        """Alias of :attr:`radial_extent` (the size that the squeeze refers to) [m]."""
        return self.radial_extent

    @property
    def inner_radius(self) -> float:
        return self._bounds[2]

    @property
    def outer_radius(self) -> float:
        return self._bounds[3]

    @property
    def axial_range(self) -> tuple[float, float]:
        b = self._bounds
        return b[0], b[1]

    @property
    def centre_radius(self) -> float:
        """Radius of the area centroid [m]."""
        return self.contour.centroid()[1]

    @property
    def area(self) -> float:
        """Cross-section area [m²]."""
        return abs(self.contour.area)

    @property
    def has_bonded_edges(self) -> bool:
        return "bonded" in self.contour.tags

    def translated(self, dx: float) -> SealProfile:
        """The profile moved axially by dx [m]."""
        return SealProfile(self.family, self.contour.translated(dx), self.min_feature,
                           self.spring_radius, self.contact_size)


def _radial(points, base: float, side: float):
    """Local (z, t) with t measured from the sealing side → (x, y): y = base + side·t."""
    p = np.asarray(points, dtype=float)
    return np.stack([p[:, 0], base + side * p[:, 1]], axis=1)


def _sealing_side(arrangement: str) -> float:
    if arrangement not in ("rod", "piston"):
        raise InputError(f"gland.arrangement: {arrangement!r} is not allowed for this seal; "
                         "choose 'rod' or 'piston'")
    return 1.0 if arrangement == "rod" else -1.0


def _signed_angle(u, v) -> float:
    """Signed angle from vector u to vector v [rad], in (−π, π]."""
    return math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])


def _positive(name, value):
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{name}: {value!r} is not allowed; it must be a positive length")


# -- X-ring ---------------------------------------------------------------------------------------

XRING_LOBE_RADIUS = 0.16
"""Lobe radius of an X-ring as a fraction of the cord [-]: an engineering estimate of the
shape of ISO 3601 / AS568 sized quad rings in catalogue drawings (round corner lobes, the
section close to its square envelope)."""

XRING_VALLEY_DEPTH = 0.098
"""Depth of the valley between two lobes below the envelope, fraction of the cord [-]: with
the default lobe radius it gives the section area of Minnesota Rubber's Quad-Ring seals,
"Seal Volume = (Max Quad-Ring Brand Cross-section)² × 0.8215" per unit length (Quad-Ring
Brand Design Guide, face-seal gland example): 0.8212 W², 4.6 % more than an O-ring's
π/4·W².  No dimensioned drawing of the lobes could be read, so how the area splits between
lobes and valleys stays an estimate."""


def xring_profile(cord_diameter: float, inner_diameter: float, *,
                  lobe_radius: float = XRING_LOBE_RADIUS,
                  valley_depth: float = XRING_VALLEY_DEPTH) -> SealProfile:
    """X-ring (quad ring): square envelope cord × cord with four lobes and four valleys.

    Parameters
    ----------
    cord_diameter : float
        Cross-section size W [m] (the envelope is W × W, like the O-ring of the same size).
    inner_diameter : float
        Inner diameter of the free ring [m].
    lobe_radius : float
        Lobe radius as a fraction of W [-] (0.1 ... 0.35).
    valley_depth : float
        Valley depth below the envelope as a fraction of W [-] (0.02 ... 0.2).

    Returns
    -------
    SealProfile
        Centred at x = 0; y from ID/2 to ID/2 + W.

    Examples
    --------
    >>> x = xring_profile(3.53e-3, 18.64e-3)
    >>> round(x.radial_extent * 1e3, 6), round(x.axial_extent * 1e3, 6)
    (3.53, 3.53)
    >>> round(x.area / 3.53e-3**2, 3)     # Quad-Ring 0.8215; O-ring 0.785, square 1
    0.821
    """
    _positive("seal.cord_diameter", cord_diameter)
    _positive("seal.inner_diameter", inner_diameter)
    if not (0.1 <= lobe_radius <= 0.35 and 0.02 <= valley_depth <= 0.2):
        raise InputError("seal.lobe_radius must be 0.1-0.35 and seal.valley_depth 0.02-0.2 "
                         "(fractions of the cord)")

    # lobes: circles of radius rho in the four corners of the W x W envelope; valleys:
    # concave arcs centred outside the section, tangent to the two lobes of their side, with
    # the deepest point at `depth` below the envelope. Tangency of the valley circle (radius
    # R_v, centre at W/2 - depth + R_v from the middle) with a lobe (centre a = W/2 - rho
    # from the middle along both axes): a^2 + (R_v + rho - depth)^2 = (R_v + rho)^2.
    W = cord_diameter
    rho, depth = lobe_radius * W, valley_depth * W
    a = 0.5 * W - rho
    r_valley = (a * a + depth * depth) / (2.0 * depth) - rho
    if r_valley <= 0.05 * W:
        raise InputError("seal: the X-ring valley is too deep for its lobes; reduce "
                         "valley_depth or lobe_radius")
    normals = [np.array(v, dtype=float) for v in ((0, -1), (1, 0), (0, 1), (-1, 0))]
    lobes = [np.array(v, dtype=float) * a for v in ((1, -1), (1, 1), (-1, 1), (-1, -1))]
    pts, bul = [], []
    for k in range(4):  # valley k (bottom, right, top, left), then the lobe after it
        v = normals[k] * (0.5 * W - depth + r_valley)
        before, after = lobes[k - 1], lobes[k]
        t0 = before + rho * (v - before) / np.linalg.norm(v - before)
        t1 = after + rho * (v - after) / np.linalg.norm(v - after)
        pts.append(t0)
        bul.append(math.tan(_signed_angle(t0 - v, t1 - v) / 4.0))
        nxt = normals[(k + 1) % 4] * (0.5 * W - depth + r_valley)
        t2 = after + rho * (nxt - after) / np.linalg.norm(nxt - after)
        pts.append(t1)
        bul.append(math.tan(_signed_angle(t1 - after, t2 - after) / 4.0))
    pts = np.array(pts) + np.array([0.0, inner_diameter / 2 + W / 2])
    con = Contour(pts, np.array(bul))
    contour = check_contour(Contour(pts, con.bulges, ("contact",) * con.n), "X-ring")
    return SealProfile("xring", contour, min_feature=cord_diameter)


# -- rectangular ring ------------------------------------------------------------------------------

def rectangular_profile(width: float, height: float, inner_diameter: float, *,
                        corner_radius: float | None = None) -> SealProfile:
    """Rectangular (or square) ring with rounded corners.

    Parameters
    ----------
    width : float
        Axial width [m].
    height : float
        Radial height [m].
    inner_diameter : float
        Inner diameter of the free ring [m].
    corner_radius : float, optional
        Corner radius [m] (default 10 % of the smaller side: moulded rings have rounded
        corners; a sharp corner gives a singular contact pressure at the contact edge).

    Examples
    --------
    >>> p = rectangular_profile(4e-3, 4e-3, 20e-3)
    >>> round(p.area * 1e6, 4)
    15.8627
    """
    for name, v in (("seal.width", width), ("seal.height", height),
                    ("seal.inner_diameter", inner_diameter)):
        _positive(name, v)
    r = 0.1 * min(width, height) if corner_radius is None else corner_radius
    if not 0 <= r < 0.5 * min(width, height):
        raise InputError(f"seal.corner_radius: {r * 1e3:g} mm must be >= 0 and less than half "
                         f"the smaller side ({0.5e3 * min(width, height):g} mm)")
    y0 = inner_diameter / 2
    pts = [[-width / 2, y0], [width / 2, y0], [width / 2, y0 + height], [-width / 2, y0 + height]]
    con = filleted_contour(pts, r, tags=["contact", "", "contact", ""], name="rectangular ring")
    return SealProfile("rectangular", check_contour(con, "rectangular ring"),
                       min_feature=min(width, height))


# -- U-cup ----------------------------------------------------------------------------------------

def ucup_profile(arrangement: str, sealing_diameter: float, height: float, width: float, *,
                 lip_thickness: float | None = None, groove_depth: float | None = None,
                 flare: float | None = None, edge_radius: float | None = None) -> SealProfile:
    """Pneumatic U-cup lip seal (symmetric two-lip profile) for a rod or a piston.

    The heel lies on the downstream side (x > 0), the two lips point to the pressure side
    (x < 0) around a groove that the fluid fills and that presses the lips apart (pressure
    activation). Each lip is flared by ``flare`` beyond the heel: the lips alone carry the
    installation squeeze.

    Parameters
    ----------
    arrangement : {"rod", "piston"}
        Rod seal (dynamic lip inside, on the rod) or piston seal (dynamic lip outside).
    sealing_diameter : float
        Diameter of the dynamic lip's edge in the free seal [m] (rod seal: smaller than the
        rod by the lip interference; piston seal: larger than the bore).
    height : float
        Free radial height from lip edge to lip edge [m].
    width : float
        Axial length [m].
    lip_thickness : float, optional
        Lip thickness at the pressure-side face [m] (default 0.28·height).
    groove_depth : float, optional
        Axial depth of the groove between the lips [m] (default 0.45·width).
    flare : float, optional
        Radial flare of each lip beyond the heel [m] (default 0.08·height).
    edge_radius : float, optional
        Radius of the lip edges [m] (default 0.04·height).

    Examples
    --------
    >>> u = ucup_profile("rod", 19.6e-3, 4.4e-3, 5e-3)
    >>> round(u.inner_radius * 1e3, 6), round(u.radial_extent * 1e3, 6)
    (9.8, 4.4)
    """
    side = _sealing_side(arrangement)
    for name, v in (("seal.sealing_diameter", sealing_diameter), ("seal.height", height),
                    ("seal.width", width)):
        _positive(name, v)
    H, L = height, width
    w = 0.28 * H if lip_thickness is None else lip_thickness
    g = 0.45 * L if groove_depth is None else groove_depth
    e = 0.08 * H if flare is None else flare
    r = 0.04 * H if edge_radius is None else edge_radius
    if not (0 < w < 0.45 * H and 0 < g < 0.8 * L and 0 <= e < 0.25 * H and 0 <= r < 0.5 * w):
        raise InputError("seal: U-cup proportions out of range (lip_thickness < 0.45 height, "
                         "groove_depth < 0.8 width, flare < 0.25 height, edge_radius < half "
                         "the lip thickness)")
    a = 0.06 * L  # axial chamfer from the pressure face to the lip edge
    c = 0.5 * w  # radial size of that chamfer
    lip_len = 0.55 * L  # where the flared lip meets the heel surface
    groove_r = 0.3 * (H - 2 * w)  # radius at the bottom of the groove
    # local (z, t): t from the dynamic lip edge (t = 0) to the static lip edge (t = H)
    local = [[0.0, c], [a, 0.0], [lip_len, e], [L, e], [L, H - e], [lip_len, H - e],
             [a, H], [0.0, H - c], [0.0, H - w], [g, 0.5 * H], [0.0, w]]
    radii = [0.0, r, 0.0, 0.1 * H, 0.1 * H, 0.0, r, 0.0, 0.3 * r, groove_r, 0.3 * r]
    tags = ["contact", "contact", "", "", "", "contact", "contact", "", "", "", ""]
    # the dynamic lip is on the sealing side: y = R_edge + t (rod) or R_edge − t (piston)
    pts = _radial(local, sealing_diameter / 2, side)
    con = filleted_contour(pts, radii, tags, name="U-cup")
    return SealProfile("ucup", check_contour(con, "U-cup"), min_feature=min(w, H - 2 * e) * 0.8)


# -- wiper ----------------------------------------------------------------------------------------

def wiper_profile(arrangement: str, sealing_diameter: float, height: float, width: float, *,
                  lip_thickness: float | None = None, flare: float | None = None,
                  edge_radius: float | None = None) -> SealProfile:
    """Wiper (scraper): a heel in the groove and one lip that points to the air side.

    The air (dirt) side is x < 0, the same side the fluid pressure of a pressure seal acts
    from; a wiper normally sees no pressure. The lip is a wedge from the heel to its edge at
    x = 0, flared by ``flare`` below the heel.

    Parameters
    ----------
    arrangement : {"rod", "piston"}
        Usually "rod".
    sealing_diameter : float
        Diameter of the lip edge in the free wiper [m].
    height, width : float
        Free radial height and axial length [m].
    lip_thickness : float, optional
        Lip thickness at its root [m] (default 0.35·height).
    flare : float, optional
        Radial flare of the lip edge below the heel [m] (default 0.1·height).
    edge_radius : float, optional
        Radius of the wiping edge [m] (default 0.03·height).

    Examples
    --------
    >>> p = wiper_profile("rod", 19.5e-3, 3.5e-3, 5e-3)
    >>> round(p.inner_radius * 1e3, 3)     # the edge radius rounds the lip edge off
    9.77
    """
    side = _sealing_side(arrangement)
    for name, v in (("seal.sealing_diameter", sealing_diameter), ("seal.height", height),
                    ("seal.width", width)):
        _positive(name, v)
    H, L = height, width
    w = 0.35 * H if lip_thickness is None else lip_thickness
    e = 0.1 * H if flare is None else flare
    r = 0.03 * H if edge_radius is None else edge_radius
    if not (0 < w < 0.7 * H and 0 <= e < 0.4 * H and 0 <= r < 0.3 * w):
        raise InputError("seal: wiper proportions out of range")
    heel = 0.4 * L
    local = [[0.0, 0.0], [heel, e], [L, e], [L, H], [heel, H], [heel, e + w],
             [0.0, 0.45 * w]]
    radii = [r, 0.15 * w, 0.05 * H, 0.05 * H, 0.05 * H, 0.3 * w, 0.1 * w]
    tags = ["contact", "", "", "contact", "", "", "contact"]
    pts = _radial(local, sealing_diameter / 2, side)
    con = filleted_contour(pts, radii, tags, name="wiper")
    return SealProfile("wiper", check_contour(con, "wiper"), min_feature=0.45 * w)


# -- DIN 3760 radial lip seal ----------------------------------------------------------------------

LIP_OIL_SIDE_ANGLE = 45.0
"""Oil-side angle of the lip head to the shaft axis [deg]; DIN 3760 lips have 40–60° (range
from catalogue section drawings, an engineering estimate: no dimensioned source was found)."""

LIP_AIR_SIDE_ANGLE = 25.0
"""Air-side angle of the lip head to the shaft axis [deg]; typically 20–35° (as above). The
liquid-side angle is the larger one so that the contact pressure is asymmetric, peak towards
the oil side, which pumps back (Science Progress 104(2), 2021, doi 10.1177/00368504211017010;
Salant, Proc. IMechE J 213 (1999) 189)."""

FLEX_ANGLE = 75.0
"""Angle of the flex section to the shaft axis [deg]: catalogue sections show a short, mostly
radial flex from the case flange down to the lip head."""

SPRING_OFFSET = 0.5e-3
"""Axial offset of the garter spring's axis from the lip edge towards the air side (the
'R value') [m]; catalogue designs use 0.3–0.8 mm so that the pressure peak is on the oil side."""


CONTACT_BAND = 0.4e-3
"""Width of the contact band the contact elements refer to, at a 10 mm section (scaled with
the section height) [m]: new lips touch over 0.1-0.2 mm, so the contact elements are a
fraction of that (:data:`~.profile_mesh.PROFILE_MESH_LEVELS`)."""

REFINED_FACES = (0.4e-3, 1.2e-3)
"""Lengths of the oil-side and the air-side face next to the lip edge that are meshed with the
contact element size, at a 10 mm section (scaled with the section height) [m]: the band grows
towards the air side as the head heels over (warm, soft rubber), so that side is longer."""

EDGE_RADIUS = 0.03e-3
"""Radius of the moulded lip edge at a 10 mm section (scaled with the section height) [m]: a
sharp, trimmed or moulded edge; the contact width of a new lip (0.1-0.3 mm) is several times
this radius, so its exact value hardly matters once it is meshed finely."""


def radial_lip_profile(shaft_diameter: float, outer_diameter: float, width: float, *,
                       interference: float | None = None, flex_thickness: float | None = None,
                       spring_coil_diameter: float | None = None,
                       spring_offset: float = SPRING_OFFSET,
                       flex_angle: float = FLEX_ANGLE,
                       oil_side_angle: float = LIP_OIL_SIDE_ANGLE,
                       air_side_angle: float = LIP_AIR_SIDE_ANGLE,
                       edge_radius: float | None = None) -> SealProfile:
    """DIN 3760 / ISO 6194-1 type A radial shaft seal: the rubber part around the lip.

    The section (oil side x < 0, air side x > 0, lip edge at x = 0) is the lip head with the
    oil- and air-side faces, the spring groove on its back, the flex section and the part of
    the body that is bonded to the metal case. The case is rigid: the edges tagged
    ``"bonded"`` move with the housing. The rubber outer cover of the case (press fit) does
    not take part in the lip mechanics and is left out.

    The proportions are engineering estimates of an 80 × 100 × 10 seal from catalogue section
    drawings (section height H = 10 mm: head 2.6 mm high, flex 1.2 mm thick at 75° to the
    axis, spring coil Ø 1.6 mm), scaled with the section height H = (D − d)/2 for other sizes.
    The lip edge is where the oil-side and the air-side cones meet, rounded only by
    :data:`EDGE_RADIUS`; the first :data:`REFINED_FACES` of both faces are meshed with the contact
    element size, so the contact band of the installed lip (0.1-0.2 mm) is resolved.
    The drawn lip is the moulded one, without the spring: the garter spring is put on in the
    FE model and pulls the lip inwards before the shaft is installed.

    Parameters
    ----------
    shaft_diameter : float
        Nominal shaft diameter d [m].
    outer_diameter : float
        Outer diameter D [m].
    width : float
        Seal width [m].
    interference : float, optional
        Radial interference of the moulded lip (without spring) on the shaft [m] (default
        0.5 mm + 0.006·d, 1 mm for d = 80 mm, before the edge radius: an engineering estimate
        that keeps the lip pressed on the shaft without its spring; catalogues do not publish
        the moulded lip diameter).
    flex_thickness : float, optional
        Thickness of the flex section [m] (default 0.12·H).
    spring_coil_diameter : float, optional
        Outer diameter of the garter spring's coil [m] (default 0.16·H).
    spring_offset : float
        Axial offset of the spring axis from the lip edge to the air side [m].
    flex_angle : float
        Angle of the flex section to the shaft axis [deg].
    oil_side_angle, air_side_angle : float
        Angles of the lip faces to the shaft axis [deg].
    edge_radius : float, optional
        Radius of the lip edge [m] (default :data:`EDGE_RADIUS` scaled with H).

    Examples
    --------
    >>> p = radial_lip_profile(0.08, 0.1, 0.01)
    >>> round(p.inner_radius * 1e3, 4), p.has_bonded_edges
    (39.0261, True)
    """
    for name, v in (("seal.shaft_diameter", shaft_diameter),
                    ("seal.outer_diameter", outer_diameter), ("seal.width", width)):
        _positive(name, v)
    H = 0.5 * (outer_diameter - shaft_diameter)
    if H < 3e-3 or H > 0.5 * shaft_diameter + 5e-3:
        raise InputError(f"seal.outer_diameter: a radial section of {H * 1e3:g} mm is out of "
                         "range for a radial lip seal (3 mm ... d/2 + 5 mm)")
    s = H / 10e-3
    i = 0.5e-3 + 0.006 * shaft_diameter if interference is None else interference
    tf = 1.2e-3 * s if flex_thickness is None else flex_thickness
    coil = 1.6e-3 * s if spring_coil_diameter is None else spring_coil_diameter
    edge_r = EDGE_RADIUS * s if edge_radius is None else edge_radius
    if not 0 <= edge_r <= 0.5 * CONTACT_BAND * s:
        raise InputError(f"seal.edge_radius: {edge_r * 1e3:g} mm is out of range for this lip "
                         f"(0 ... {0.5e3 * CONTACT_BAND * s:g} mm)")
    if not (0 < i < 0.3 * H and 0.25 * H > tf > 0 and 0 < coil < 0.3 * H):
        raise InputError("seal: radial lip proportions out of range (interference < 0.3 H, "
                         "flex_thickness < 0.25 H, spring_coil_diameter < 0.3 H)")
    if width < 0.5 * H or width > 2 * H + 10e-3:
        raise InputError(f"seal.width: {width * 1e3:g} mm does not fit a section of "
                         f"{H * 1e3:g} mm (0.5 H ... 2 H + 10 mm)")
    head = 2.6e-3 * s  # lip edge to the spring seat level
    oil = math.radians(oil_side_angle)
    air = math.radians(air_side_angle)
    rho = 0.5 * coil
    # local (z, t): t radially outwards from the free lip edge
    b_oil = 0.6 * head  # height of the inclined oil-side face
    oil_face = (-b_oil / math.tan(oil), b_oil)
    oil_top = (oil_face[0] - 0.15 * head, head)
    # spring groove: a circular seat, the coil axis 0.3 rho above the head's back
    zs, ts = spring_offset, head + 0.3 * rho
    half = math.sqrt(rho**2 - (ts - head) ** 2)
    # flex: from the head's back (air side of the spring seat) up to the body, at flex_angle
    # to the axis, 0.3 H long; the body is bonded to the case above and behind it
    phi = math.radians(flex_angle)
    u = np.array([math.cos(phi), math.sin(phi)])
    nrm = np.array([-u[1], u[0]])
    top0 = np.array([zs + half + 0.05 * H, head])
    top1 = top0 + 0.3 * H * u
    body_z0 = top1[0]  # oil-side face of the bonded body
    body_t0 = top1[1] - tf  # underside of the body
    body_t1 = 0.85 * H + i  # top of the body (below the case's cylindrical part)
    body_z1 = body_z0 + 0.3 * H  # the case flange (air side)
    # underside of the flex: parallel at distance tf, from the air-side face to the body
    bot_ref = top0 - tf * nrm
    # intersection with the air-side face t = z·tan(air)
    d_air = np.array([math.cos(air), math.sin(air)])
    A = np.array([u, -d_air]).T
    v, w_face = np.linalg.solve(A, -bot_ref)
    bot0 = w_face * d_air
    s_bot = (body_t0 - bot_ref[1]) / u[1]
    bot1 = bot_ref + s_bot * u
    if not (bot0[1] > 0.2 * head and top1[1] < body_t1 and bot1[0] < body_z1):
        raise InputError("seal: the radial lip proportions do not form a valid section "
                         "(check width, flex_thickness and spring_offset)")
    # the contact band: the first REFINED_FACES of each face next to the edge are meshed with
    # the contact element size (split points on the straight faces, no fillet there)
    # (at most 60 % of a face, so the split point stays clear of the face's far fillet)
    len_air = min(REFINED_FACES[1] * s, 0.6 * float(np.hypot(*bot0)))
    len_oil = min(REFINED_FACES[0] * s, 0.6 * b_oil / math.sin(oil))
    band_air = len_air * d_air
    band_oil = len_oil * np.array([-math.cos(oil), math.sin(oil)])
    pts = [(0.0, 0.0), tuple(band_air), tuple(bot0), tuple(bot1), (body_z1, body_t0),
           (body_z1, body_t1), (body_z0, body_t1), tuple(top1), tuple(top0), (zs + half, head),
           (zs - half, head), oil_top, (oil_face[0], oil_face[1] + 0.15 * head), oil_face,
           tuple(band_oil)]
    radii = [edge_r, 0.0, 0.4 * tf, 0.3 * tf, 0.0, 0.0, 0.0, 0.3 * tf, 0.4 * tf, 0.0, 0.0,
             0.1 * head, 0.1 * head, 0.1 * head, 0.0]
    tags = ["contact", "", "", "", "bonded", "bonded", "", "", "", "spring", "", "", "", "",
            "contact"]
    corner = ["contact"] + [None] * (len(pts) - 1)  # the lip edge's rounding
    y0 = 0.5 * shaft_diameter - i
    xy = _radial(pts, y0, 1.0)
    con = check_contour(filleted_contour(xy, radii, tags, corner_tags=corner,
                                         name="radial lip seal"), "radial lip seal")
    # the spring seat: the straight seat segment becomes the concave arc of the coil (a
    # right turn of the counter-clockwise contour)
    k = con.tags.index("spring")
    p0, p1, _, _ = con.segment(k)
    sweep = -2.0 * math.asin(min(1.0, 0.5 * float(np.hypot(*(p1 - p0))) / rho))
    bul = con.bulges.copy()
    bul[k] = math.tan(sweep / 4.0)
    centre, _, _, _ = arc_geometry(p0, p1, bul[k])
    contour = check_contour(Contour(con.points, bul, con.tags), "radial lip seal")
    # the contact elements are a fraction of the contact band
    return SealProfile("radial_lip", contour, min_feature=tf, spring_radius=float(centre[1]),
                       contact_size=CONTACT_BAND * s)


STEEL_SHEAR_MODULUS = 79e9
"""Shear modulus of spring steel [Pa] (EN 10270-1 wire; Wahl, Mechanical Springs, 1963)."""

SPRING_TENSION_PER_DIAMETER = 34.0
"""Default hoop pre-tension of the garter spring per shaft diameter [N/m] (2.7 N at
d = 80 mm): its radial force 2πT is 0.45 of a radial load of 0.15 N/mm, the defaults of
:mod:`sealsim.rotary.lip` (an estimate; on the installed FE lip, stretched by the shaft, the
spring's 2πT is 23 N, of which about 0.64 reaches the shaft: :mod:`sealsim.rotary.lip_fe`);
the same order as the 3.34 N 'circumferential load' of the helicopter-gearbox seal springs of
Coatings 2021, 11(2), 156."""


def garter_spring_rate(coil_diameter: float, wire_diameter: float, length: float,
                       shear_modulus: float = STEEL_SHEAR_MODULUS) -> float:
    """Axial rate of a close-wound garter spring, k = G d⁴ / (8 D³ n), n = L / d.

    Parameters
    ----------
    coil_diameter : float
        Outer coil diameter [m].
    wire_diameter : float
        Wire diameter d [m] (mean coil diameter D = coil − wire).
    length : float
        Spring length L [m] (its circumference in the seal).
    shear_modulus : float
        G of the wire [Pa].

    Returns
    -------
    float
        k [N/m] (Wahl, Mechanical Springs, 2nd ed., 1963, ch. 2).

    Examples
    --------
    >>> round(garter_spring_rate(1.6e-3, 0.4e-3, 2 * math.pi * 41.5e-3), 1)
    224.4
    """
    mean = coil_diameter - wire_diameter
    turns = length / wire_diameter
    return shear_modulus * wire_diameter**4 / (8.0 * mean**3 * turns)


# -- user profiles ---------------------------------------------------------------------------------

def user_profile(points=None, *, bulges=None, tags=None, dxf=None, layer=None,
                 dxf_unit: float = 1e-3, name: str = "seal") -> SealProfile:
    """A profile from a closed polyline [m] or a DXF drawing.

    Parameters
    ----------
    points : array_like, optional
        (n, 2) polyline [m], x axial, y radius (the last point may repeat the first).
    bulges, tags : sequence, optional
        Per segment (see :class:`~.contour.Contour`).
    dxf : path-like, optional
        DXF file instead of ``points``.
    layer : str, optional
        DXF layer.
    dxf_unit : float
        Length of one DXF drawing unit [m].
    name : str
        Prefix of the field names in messages.

    Examples
    --------
    >>> p = user_profile([[0, 10e-3], [3e-3, 10e-3], [3e-3, 13e-3], [0, 13e-3]])
    >>> round(p.area * 1e6, 6), p.family
    (9.0, 'user')
    """
    if (points is None) == (dxf is None):
        raise InputError(f"{name}: give either points (a closed polyline) or a dxf file")
    if dxf is not None:
        contour = contour_from_dxf(dxf, layer=layer, unit=dxf_unit)
    else:
        contour = contour_from_polyline(points, bulges, tags, name=f"{name}.points")
    return SealProfile("user", contour, min_feature=_thinnest_wall(contour))


def _thinnest_wall(contour: Contour) -> float:
    """Smallest distance between two boundary points that are far apart along the contour
    (an estimate of the thinnest wall) [m]."""
    from scipy.spatial import cKDTree

    b = contour.bounds
    size = max(b[1] - b[0], b[3] - b[2])
    s, _ = contour.sample(size / 60)
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(s, axis=0), axis=1))])
    total = arc[-1] + np.linalg.norm(s[0] - s[-1])
    tree = cKDTree(s)
    pairs = tree.query_pairs(size / 2, output_type="ndarray")
    if len(pairs) == 0:
        return size
    d = np.linalg.norm(s[pairs[:, 0]] - s[pairs[:, 1]], axis=1)
    along = np.abs(arc[pairs[:, 0]] - arc[pairs[:, 1]])
    along = np.minimum(along, total - along)
    far = along > 2.0 * d  # not neighbours on the same side
    return float(d[far].min()) if np.any(far) else size
