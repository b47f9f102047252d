"""Seal cross-sections and glands (rigid counter surfaces), independent of the FE solver.

Coordinates follow FElupe's axisymmetric convention: **x is the axial coordinate z, y is the
radius r** (both in m). The gland is centred at z = 0; the fluid pressure acts from the
upstream side z < 0, so at zero pressure the seal rests against the downstream groove wall
(with frictionless contact its axial position is otherwise undetermined).

A gland is four rigid lines: the *sealing surface* (rod for a rod seal, cylinder bore for a
piston seal; the friction contact), the *groove bottom* and the two *groove walls*. The squeeze
``s`` sets the radial gland depth ``h = d (1 − s)`` (d = cord diameter). The first squeeze
of a load path is the installation: both radial surfaces start where they just touch the free
O-ring and move linearly in s to their installed positions, so that ``h = d (1 − s)`` holds
along the way; afterwards only the groove bottom moves. Metal thermal expansion scales the
radii (and the wall positions) about the axis (about z = 0).

Other profiles (rectangular, lip) are new section classes with the same small interface
(:attr:`radial_extent`, :attr:`axial_extent`, :attr:`area`); the mesh builder dispatches on
the section type.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from sealsim.errors import InputError

__all__ = ["MAX_SQUEEZE", "Gland", "ORing", "RigidLine", "SealAssembly", "gland_fill"]

MAX_SQUEEZE = 0.40
"""Largest squeeze [-] the model accepts (standard static O-ring seals use 8–30 %)."""

INITIAL_WALL_CONTACT = 1e-3
"""Initial overlap of the O-ring with the downstream wall, as a fraction of the cord [-]:
makes the wall contact active from the first iteration (axial support)."""


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
    arrangement : {"rod", "piston"}
        Rod seal: groove in the housing, the seal slides on the rod (sealing surface inside).
        Piston seal: groove in the piston, the seal slides in the bore (sealing surface
        outside).
    sealing_diameter : float
        Rod diameter (rod seal) or bore diameter (piston seal) [m].
    groove_width : float
        Axial groove width [m].

    Examples
    --------
    >>> g = Gland("rod", 20e-3, 5.4e-3)
    >>> g.side, round(g.groove_bottom_radius(0.2, 4e-3) * 1e3, 6)
    (-1.0, 13.2)
    """

    arrangement: Literal["rod", "piston"]
    sealing_diameter: float
    groove_width: float

    def __post_init__(self):
        if self.arrangement not in ("rod", "piston"):
            raise InputError(f"gland.arrangement: {self.arrangement!r} is not allowed; "
                             "choose 'rod' or 'piston'")
        _positive("gland.sealing_diameter", self.sealing_diameter, "m")
        _positive("gland.groove_width", self.groove_width, "m")

    @property
    def side(self) -> float:
        """−1 if the sealing surface is inside the seal (rod), +1 if outside (piston)."""
        return -1.0 if self.arrangement == "rod" else 1.0

    @property
    def sealing_radius(self) -> float:
        return 0.5 * self.sealing_diameter

    def groove_bottom_radius(self, squeeze: float, cord: float) -> float:
        """Groove bottom radius [m] for squeeze s [-]: R_s ∓ d (1 − s)."""
        return self.sealing_radius - self.side * cord * (1.0 - squeeze)


@dataclass(frozen=True)
class RigidLine:
    """A rigid line of the gland: a point on it (x, y) [m] and the unit normal pointing into
    the seal."""

    name: str
    point: tuple[float, float]
    normal: tuple[float, float]


def gland_fill(ring: ORing, gland: Gland, squeeze: float, volume_ratio: float = 1.0) -> float:
    """Gland fill [-]: seal cross-section (times the thermal volume ratio) / groove area h·w.

    Examples
    --------
    >>> round(gland_fill(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3), 0.2), 3)
    0.727
    """
    depth = ring.cord_diameter * (1.0 - squeeze)
    return ring.area * volume_ratio / (depth * gland.groove_width)


@dataclass(frozen=True)
class SealAssembly:
    """An O-ring in its gland with the metal parts' thermal expansion.

    Parameters
    ----------
    seal : ORing
        The free O-ring.
    gland : Gland
        The gland.
    inner_expansion : float
        Linear CTE [1/K] of the part inside the seal (rod, or piston with the groove).
    outer_expansion : float
        Linear CTE [1/K] of the part outside the seal (housing with the groove, or bore).
    reference_temperature : float
        Temperature [K] at which the dimensions are given.

    Examples
    --------
    >>> a = SealAssembly(ORing(4e-3, 20e-3), Gland("rod", 20e-3, 5.4e-3))
    >>> lines = a.lines(0.1, 293.15, installation_squeeze=0.2)
    >>> [round(line.point[1] * 1e3, 4) for line in lines[:2]]
    [10.0, 13.6]
    """

    seal: ORing
    gland: Gland
    inner_expansion: float = 0.0
    outer_expansion: float = 0.0
    reference_temperature: float = 293.15

    def __post_init__(self):
        d, w = self.seal.cord_diameter, self.gland.groove_width
        if w < d:
            raise InputError(
                f"gland.groove_width: {w * 1e3:g} mm is too narrow for the seal cross-section: "
                f"it must be at least the cord diameter {d * 1e3:g} mm (typically 1.3-1.5 d)")
        for name, value in (("inner_expansion", self.inner_expansion),
                            ("outer_expansion", self.outer_expansion)):
            if not (math.isfinite(value) and -1e-4 < value < 1e-3):
                raise InputError(f"gland.{name}: {value!r} 1/K is out of range (-1e-4 ... 1e-3)")
        if self.gland.arrangement == "piston" and self.seal.inner_radius <= 0:
            raise InputError("seal.inner_diameter must be > 0")

    # -- placement ----------------------------------------------------------------------------
    @property
    def centre(self) -> tuple[float, float]:
        """Initial (x, y) of the free cross-section's centre [m]: resting against the
        downstream wall (x = +w/2), at the free ring's centre radius."""
        a = self.seal.radius
        x = 0.5 * self.gland.groove_width - a + INITIAL_WALL_CONTACT * self.seal.cord_diameter
        return (x, self.seal.centre_radius)

    @property
    def free_sealing_side_radius(self) -> float:
        """Radius of the free ring's surface on the sealing side [m]."""
        return self.seal.inner_radius if self.gland.side < 0 else self.seal.outer_radius

    def check_squeeze(self, squeeze: float, field: str = "squeeze") -> None:
        """InputError unless 0 < s <= MAX_SQUEEZE."""
        if not (math.isfinite(squeeze) and 0.0 < squeeze <= MAX_SQUEEZE):
            raise InputError(f"{field}: {squeeze * 100:g} % is out of range; the squeeze must be "
                             f"> 0 % and <= {MAX_SQUEEZE * 100:g} % (a squeeze >= 100 % would "
                             "close the gland)")

    def check_fill(self, squeeze: float, volume_ratio: float = 1.0, limit: float = 0.97) -> None:
        """InputError if the (thermally expanded) seal overfills the gland."""
        fill = gland_fill(self.seal, self.gland, squeeze, volume_ratio)
        if fill >= limit:
            raise InputError(
                f"gland too small: at squeeze {squeeze * 100:g} % the seal fills "
                f"{fill * 100:.0f} % of the groove cross-section (limit {limit * 100:.0f} %, "
                "thermal expansion included); widen the groove (gland.groove_width) or reduce "
                "the squeeze")

    # -- rigid lines for a load state ---------------------------------------------------------
    def lines(self, squeeze: float, temperature: float, installation_squeeze: float):
        """Rigid lines (sealing surface, groove bottom, upstream wall, downstream wall).

        Parameters
        ----------
        squeeze : float
            Current squeeze s [-] (0 ≤ s).
        temperature : float
            Current temperature T [K] (metal expansion).
        installation_squeeze : float
            Squeeze at the end of the installation [-] (the first squeeze of the load path).
        """
        g, d = self.gland, self.seal.cord_diameter
        side = g.side
        rs = g.sealing_radius
        if squeeze < installation_squeeze:
            lam = squeeze / installation_squeeze
            r0 = self.free_sealing_side_radius
            rs = r0 + (rs - r0) * lam
        rg = rs - side * d * (1.0 - squeeze)
        dT = temperature - self.reference_temperature
        exp_seal = self.inner_expansion if side < 0 else self.outer_expansion
        exp_groove = self.outer_expansion if side < 0 else self.inner_expansion
        rs *= 1.0 + exp_seal * dT
        rg *= 1.0 + exp_groove * dT
        half = 0.5 * g.groove_width * (1.0 + exp_groove * dT)
        return [
            RigidLine("sealing_surface", (0.0, rs), (0.0, -side)),
            RigidLine("groove_bottom", (0.0, rg), (0.0, side)),
            RigidLine("wall_upstream", (-half, 0.5 * (rs + rg)), (1.0, 0.0)),
            RigidLine("wall_downstream", (half, 0.5 * (rs + rg)), (-1.0, 0.0)),
        ]

    def fluid_entry(self, temperature: float | None = None) -> tuple[float, float]:
        """Where the fluid reaches the groove: the upstream corner at the sealing surface."""
        return (-0.5 * self.gland.groove_width, self.gland.sealing_radius)


def _positive(field: str, value: float, unit: str) -> None:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise InputError(f"{field}: {value!r} {unit} is not allowed; it must be a positive length")
