"""Seal cross-sections and glands (rigid counter surfaces), independent of the FE solver.

Coordinates follow FElupe's axisymmetric convention: **x is the axial coordinate z, y is the
radius r** (both in m). The gland is centred at z = 0; the fluid pressure acts from the
upstream side z < 0, so at zero pressure the seal rests against the downstream groove wall
(with frictionless contact its axial position is otherwise undetermined).

A gland is four rigid lines: the *sealing surface* (rod for a rod seal, cylinder bore for a
piston seal; the friction contact), the *groove bottom* and the two *groove walls*. The squeeze
``s`` sets the radial gland depth ``h = d (1 − s)`` (d = cord diameter, or the free radial
height of any other profile). The first squeeze of a load path is the installation: both
radial surfaces start where they just touch the free section and move linearly in s to their
installed positions, so that ``h = d (1 − s)`` holds along the way; afterwards only the groove
bottom moves. Metal thermal expansion scales the radii (and the wall positions) about the axis
(about z = 0). A gland without side walls (``walls=False``) leaves the section free to bulge;
its axial position is then held by symmetry.

A radial shaft seal (``arrangement="shaft"``) has one rigid line, the shaft; the seal's metal
case is pressed into the housing, so the rubber edges bonded to it move with the housing. Its
squeeze is the radial interference over the free radial height, s = (R_shaft − r_lip)/h0. The
installation first puts the garter spring on the free seal (its tension ramps up over the
first :data:`SPRING_FRACTION` of the installation, pulling the lip inwards), while the shaft
rises from :data:`SHAFT_START` h0 below the free lip radius; the shaft then lifts the lip to
its own radius.

The section is an :class:`ORing` or any :class:`~sealsim.structure.profiles.SealProfile`; both
have the same small interface (:attr:`radial_extent`, :attr:`axial_extent`, :attr:`area`,
:attr:`inner_radius`, :attr:`outer_radius`, :attr:`centre_radius`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from sealsim.errors import InputError

__all__ = ["MAX_SQUEEZE", "Gland", "ORing", "RigidLine", "SealAssembly", "gland_fill"]

MAX_SQUEEZE = 0.40
"""Largest squeeze [-] the model accepts (standard static O-ring seals use 8–30 %)."""

SHAFT_START = 0.3
"""Start of a shaft seal's installation: the shaft this fraction of the free radial height
below the free lip radius (clear of the lip while the garter spring pulls it inwards)."""

SPRING_FRACTION = 0.3
"""Part of a shaft seal's installation over which the garter spring tension ramps up."""

INITIAL_WALL_CONTACT = 1e-3
"""Initial overlap of the O-ring with the downstream wall, as a fraction of the cord [-]:
makes the wall contact active from the first iteration (axial support)."""

DEFAULT_LAND_EDGE_RADIUS = 0.1e-3
"""Radius of a groove land's edge next to a clearance gap [m]: a machined edge broken by
about 0.1 mm (the usual "break sharp edges" of gland drawings).  The model needs a radius
(a sharp rigid corner has no unique normal); how much it matters is reported where a
clearance is used (docs/guide/calibration.md)."""


@dataclass(frozen=True)
class ORing:
    """Free (uninstalled) O-ring.

    Parameters
    ----------
    cord_diameter : float
        Cross-section diameter d [m].
    inner_diameter : float
        Inner diameter ID of the free ring [m].

    Examples
    --------
    >>> ring = ORing(4e-3, 20e-3)
    >>> round(ring.centre_radius * 1e3, 6), round(ring.area * 1e6, 4)
    (12.0, 12.5664)
    """

    cord_diameter: float
    inner_diameter: float

    def __post_init__(self):
        _positive("seal.cord_diameter", self.cord_diameter, "m")
        _positive("seal.inner_diameter", self.inner_diameter, "m")

    @property
    def radius(self) -> float:
        """Cross-section radius d/2 [m]."""
        return 0.5 * self.cord_diameter

    @property
    def centre_radius(self) -> float:
        """Radius of the cross-section centre [m]."""
        return 0.5 * self.inner_diameter + self.radius

    @property
    def inner_radius(self) -> float:
        return 0.5 * self.inner_diameter

    @property
    def outer_radius(self) -> float:
        return 0.5 * self.inner_diameter + self.cord_diameter

    @property
    def area(self) -> float:
        """Cross-section area π d²/4 [m²]."""
        return math.pi * self.radius**2

    @property
    def radial_extent(self) -> float:
        return self.cord_diameter

    @property
    def axial_extent(self) -> float:
        return self.cord_diameter


@dataclass(frozen=True)
class Gland:
    """Rigid gland: sealing surface, groove bottom, groove walls.

    Parameters
    ----------
    arrangement : {"rod", "piston", "shaft"}
        Rod seal: groove in the housing, the seal slides on the rod (sealing surface inside).
        Piston seal: groove in the piston, the seal slides in the bore (sealing surface
        outside). Shaft: a radial shaft seal held by its metal case in the housing, the lip
        runs on the shaft (sealing surface inside, no groove).
    sealing_diameter : float
        Rod, bore or shaft diameter [m].
    groove_width : float
        Axial groove width [m] (for a shaft seal: the seal width, not used by the model).
    clearance : float, optional
        Radial gap between the sealing surface and the groove's lands [m] (piston: half the
        bore minus the piston diameter; rod: half the housing bore next to the groove minus
        the rod diameter).  Then the groove walls end at the lands' edges, rounded with
        ``land_edge_radius``, and the seal can bulge into the gap; None: the walls reach the
        sealing surface (no gap).
    land_edge_radius : float
        Radius of the lands' edges [m] (used with a clearance).

    Examples
    --------
    >>> g = Gland("rod", 20e-3, 5.4e-3)
    >>> g.side, round(g.groove_bottom_radius(0.2, 4e-3) * 1e3, 6)
    (-1.0, 13.2)
    """

    arrangement: Literal["rod", "piston", "shaft"]
    sealing_diameter: float
    groove_width: float
    clearance: float | None = None
    land_edge_radius: float = DEFAULT_LAND_EDGE_RADIUS

    def __post_init__(self):
        if self.arrangement not in ("rod", "piston", "shaft"):
            raise InputError(f"gland.arrangement: {self.arrangement!r} is not allowed; "
                             "choose 'rod', 'piston' or 'shaft'")
        _positive("gland.sealing_diameter", self.sealing_diameter, "m")
        _positive("gland.groove_width", self.groove_width, "m")
        if self.clearance is not None:
            _positive("gland.clearance", self.clearance, "m")
            _positive("gland.land_edge_radius", self.land_edge_radius, "m")

    @property
    def side(self) -> float:
        """−1 if the sealing surface is inside the seal (rod, shaft), +1 if outside (piston)."""
        return 1.0 if self.arrangement == "piston" else -1.0

    @property
    def sealing_radius(self) -> float:
        return 0.5 * self.sealing_diameter

    def groove_bottom_radius(self, squeeze: float, cord: float) -> float:
        """Groove bottom radius [m] for squeeze s [-]: R_s ∓ d (1 − s)."""
        return self.sealing_radius - self.side * cord * (1.0 - squeeze)


@dataclass(frozen=True)
class RigidLine:
    """A rigid line of the gland: a point on it (x, y) [m] and the unit normal pointing into
    the seal.  A groove wall next to a clearance gap ends at its point: the land's edge,
    rounded with ``edge_radius`` [m], beyond which (along the unit vector ``edge_direction``,
    towards the sealing surface) the land's surface faces the gap (None: an infinite line)."""

    name: str
    point: tuple[float, float]
    normal: tuple[float, float]
    edge_radius: float | None = None
    edge_direction: tuple[float, float] | None = None


def gland_fill(ring, gland: Gland, squeeze: float, volume_ratio: float = 1.0) -> float:
    """Gland fill [-]: seal cross-section (times the thermal volume ratio) / groove area h·w.

    Examples
    --------
    >>> round(gland_fill(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3), 0.2), 3)
    0.727
    """
    depth = ring.radial_extent * (1.0 - squeeze)
    return ring.area * volume_ratio / (depth * gland.groove_width)


@dataclass(frozen=True)
class SealAssembly:
    """A seal section in its gland with the metal parts' thermal expansion.

    Parameters
    ----------
    seal : ORing or SealProfile
        The free seal section.
    gland : Gland
        The gland.
    inner_expansion : float
        Linear CTE [1/K] of the part inside the seal (rod, shaft, or piston with the groove).
    outer_expansion : float
        Linear CTE [1/K] of the part outside the seal (housing with the groove, or bore).
    reference_temperature : float
        Temperature [K] at which the dimensions are given.
    walls : bool
        Groove walls present (rod and piston glands); without them the section bulges freely
        and is held axially by symmetry.

    Examples
    --------
    >>> a = SealAssembly(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3))
    >>> lines = a.lines(0.1, 293.15, installation_squeeze=0.2)
    >>> [round(line.point[1] * 1e3, 4) for line in lines[:2]]
    [10.0, 13.6]
    """

    seal: object
    gland: Gland
    inner_expansion: float = 0.0
    outer_expansion: float = 0.0
    reference_temperature: float = 293.15
    walls: bool = True

    def __post_init__(self):
        d, w = self.seal.axial_extent, self.gland.groove_width
        shaft = self.gland.arrangement == "shaft"
        if self.walls and not shaft and w < d:
            raise InputError(
                f"gland.groove_width: {w * 1e3:g} mm is too narrow for the seal cross-section: "
                f"it must be at least its axial length {d * 1e3:g} mm (typically 1.3-1.5 d)")
        for name, value in (("inner_expansion", self.inner_expansion),
                            ("outer_expansion", self.outer_expansion)):
            if not (math.isfinite(value) and -1e-4 < value < 1e-3):
                raise InputError(f"gland.{name}: {value!r} 1/K is out of range (-1e-4 ... 1e-3)")
        if self.gland.arrangement == "piston" and self.seal.inner_radius <= 0:
            raise InputError("seal.inner_diameter must be > 0")
        bonded = getattr(self.seal, "has_bonded_edges", False)
        if shaft and not bonded:
            raise InputError("gland.arrangement = 'shaft' needs a seal with edges bonded to a "
                             "metal case (seal.type = 'radial_lip', or a user profile with "
                             "tags = 'bonded' on the case edges)")
        if bonded and not shaft:
            raise InputError("edges bonded to a metal case (tag 'bonded') are only allowed with "
                             "gland.arrangement = 'shaft'")
        if shaft and self.seal.inner_radius >= self.gland.sealing_radius:
            raise InputError(
                f"no contact candidate: the free lip's inner diameter "
                f"{2e3 * self.seal.inner_radius:.4g} mm is not smaller than the shaft diameter "
                f"{self.gland.sealing_diameter * 1e3:.4g} mm, so the lip would not touch the "
                "shaft; give the seal an interference")

    # -- placement ----------------------------------------------------------------------------
    @property
    def centre(self) -> tuple[float, float]:
        """Initial (x, y) of the free section's centre [m] (O-ring: circle centre; profile:
        area centroid): resting against the downstream wall (x = +w/2) with a small overlap,
        centred at x = 0 without walls, as drawn for a shaft seal; radii as given."""
        seal = self.seal
        h = seal.radial_extent
        if isinstance(seal, ORing):
            x_lo, x_hi, xc = -seal.radius, seal.radius, 0.0
        else:
            x_lo, x_hi = seal.axial_range
            xc = seal.contour.centroid()[0]
        if self.gland.arrangement == "shaft":
            shift = 0.0
        elif self.walls:
            shift = 0.5 * self.gland.groove_width - x_hi + INITIAL_WALL_CONTACT * h
        else:
            shift = -0.5 * (x_lo + x_hi)
        return (xc + shift, seal.centre_radius)

    @property
    def free_sealing_side_radius(self) -> float:
        """Radius of the free section's surface on the sealing side [m]."""
        return self.seal.inner_radius if self.gland.side < 0 else self.seal.outer_radius

    @property
    def shaft_squeeze(self) -> float:
        """Squeeze of a shaft seal, radial interference / free radial height [-]."""
        return (self.gland.sealing_radius - self.seal.inner_radius) / self.seal.radial_extent

    def check_squeeze(self, squeeze: float, field: str = "squeeze") -> None:
        """InputError unless 0 < s <= MAX_SQUEEZE."""
        if not (math.isfinite(squeeze) and 0.0 < squeeze <= MAX_SQUEEZE):
            raise InputError(f"{field}: {squeeze * 100:g} % is out of range; the squeeze must be "
                             f"> 0 % and <= {MAX_SQUEEZE * 100:g} % (a squeeze >= 100 % would "
                             "close the gland)")

    def check_fill(self, squeeze: float, volume_ratio: float = 1.0, limit: float = 0.97) -> None:
        """InputError if the (thermally expanded) seal overfills the gland (not for shaft
        seals or glands without walls)."""
        if self.gland.arrangement == "shaft" or not self.walls:
            return
        fill = gland_fill(self.seal, self.gland, squeeze, volume_ratio)
        if fill >= limit:
            raise InputError(
                f"gland too small: at squeeze {squeeze * 100:g} % the seal fills "
                f"{fill * 100:.0f} % of the groove cross-section (limit {limit * 100:.0f} %, "
                "thermal expansion included); widen the groove (gland.groove_width) or reduce "
                "the squeeze")

    # -- rigid lines for a load state ---------------------------------------------------------
    def lines(self, squeeze: float, temperature: float, installation_squeeze: float):
        """Rigid lines (sealing surface, groove bottom, upstream wall, downstream wall; without
        walls the first two; for a shaft seal the shaft only).

        Parameters
        ----------
        squeeze : float
            Current squeeze s [-] (0 ≤ s).
        temperature : float
            Current temperature T [K] (metal expansion).
        installation_squeeze : float
            Squeeze at the end of the installation [-] (the first squeeze of the load path).
        """
        g, d = self.gland, self.seal.radial_extent
        side = g.side
        rs = g.sealing_radius
        if squeeze < installation_squeeze:
            lam = squeeze / installation_squeeze
            r0 = self.free_sealing_side_radius
            if g.arrangement == "shaft":
                r0 -= SHAFT_START * d
            rs = r0 + (rs - r0) * lam
        dT = temperature - self.reference_temperature
        exp_seal = self.inner_expansion if side < 0 else self.outer_expansion
        exp_groove = self.outer_expansion if side < 0 else self.inner_expansion
        if g.arrangement == "shaft":
            return [RigidLine("sealing_surface", (0.0, rs * (1.0 + exp_seal * dT)), (0.0, 1.0))]
        rg = rs - side * d * (1.0 - squeeze)
        rs *= 1.0 + exp_seal * dT
        rg *= 1.0 + exp_groove * dT
        radial = [RigidLine("sealing_surface", (0.0, rs), (0.0, -side)),
                  RigidLine("groove_bottom", (0.0, rg), (0.0, side))]
        if not self.walls:
            return radial
        half = 0.5 * g.groove_width * (1.0 + exp_groove * dT)
        if g.clearance is None:
            return radial + [
                RigidLine("wall_upstream", (-half, 0.5 * (rs + rg)), (1.0, 0.0)),
                RigidLine("wall_downstream", (half, 0.5 * (rs + rg)), (-1.0, 0.0)),
            ]
        # the walls end at the lands' edges (part of the groove's metal part), the clearance
        # gap between them and the sealing surface
        r_land = (g.sealing_radius - side * g.clearance) * (1.0 + exp_groove * dT)
        edge = {"edge_radius": g.land_edge_radius, "edge_direction": (0.0, side)}
        return radial + [
            RigidLine("wall_upstream", (-half, r_land), (1.0, 0.0), **edge),
            RigidLine("wall_downstream", (half, r_land), (-1.0, 0.0), **edge),
        ]

    def spring_factor(self, squeeze: float, installation_squeeze: float) -> float:
        """Share of the garter spring's tension that acts at a point of the installation."""
        if installation_squeeze <= 0:
            return 1.0
        return min(1.0, squeeze / (SPRING_FRACTION * installation_squeeze))

    def housing_expansion(self) -> float:
        """CTE [1/K] of the metal part the bonded edges (metal case) move with: the housing."""
        return self.outer_expansion if self.gland.side < 0 else self.inner_expansion

    def fluid_entry(self, temperature: float | None = None) -> tuple[float, float]:
        """Where the fluid reaches the seal: the upstream corner at the sealing surface (for a
        shaft seal: the oil side, x < 0, at the shaft)."""
        if self.gland.arrangement == "shaft":
            x_lo = self.seal.axial_range[0] if hasattr(self.seal, "axial_range") else 0.0
            return (x_lo - self.seal.radial_extent, self.gland.sealing_radius)
        return (-0.5 * self.gland.groove_width, self.gland.sealing_radius)


def _positive(field: str, value: float, unit: str) -> None:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise InputError(f"{field}: {value!r} {unit} is not allowed; it must be a positive length")
