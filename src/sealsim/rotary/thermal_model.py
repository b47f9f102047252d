"""Axisymmetric thermal model of a shaft and a radial lip seal in a housing (Organisciak et al.
2014, Eq. 6-7).

Geometry (z = 0 at the contact line, oil side at z < 0, r radial)::

      r = D/2  ┌──────────── seal body (rubber, L-shaped steel case) ──────┐ → housing
               │                                                        │
      r = R_b  └──┐ oil cavity (spring) ┌─ flex ─┐     air side         └─
                  │                     │        │
      r = R+h_l   ╲  lip head   (spring groove probe at z = R-value)
      r = R        ╲▁▁▁▁ contact band (heat source q = T·ω) ▁▁▁╱
      ════════════════════════ shaft (steel) ══════════════════════════════
       z_min (oil-side shaft end)                     z_max (air-side shaft end)

The seal proportions follow a DIN 3760 type A cross-section (lip head 0.2·section + 0.5 mm
high, up to the spring groove bottom; flex membrane at the air-side heel, oil-side lip angle 45°, air-side 25°,
steel case); they only shape the conduction paths, the friction does not depend on them.
Void cells connected to the oil-side end are oil, the others air.  Boundary faces are grouped:

* ``shaft_oil``, ``shaft_air``: shaft surface in oil (sump node) / in air (ambient);
* ``shaft_end_oil``, ``shaft_end_air``: where the modelled shaft ends; the environment's
  set-up decides what lies beyond (held at the sump or housing temperature, a semi-infinite
  fin with h_end = √(4·h·k/d), i.e. the fin conductance √(h·P·k·A) per end area, or nothing);
* ``lip_oil``, ``seal_oil``: seal surfaces wetted by oil (lip head / rest of the seal);
* ``seal_air``: seal surfaces in open air; ``seal_housing``: the seal's outer diameter pressed
  into the housing bore (housing node);
* ``shaft_pocket``, ``seal_pocket``: surfaces of the air pocket under the seal's air side
  (between lip, flex, body and shaft): a nearly closed cavity whose air is heated by the shaft,
  so it is its own lumped node, exchanging with ambient through its annular opening.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy import ndimage

from sealsim.thermal.conduction import AxisymmetricConduction, Solid, graded_edges

__all__ = ["FACE_GROUPS", "LipSealThermalGrid", "SealSection", "build_thermal_grid"]

FACE_GROUPS = ("shaft_oil", "shaft_air", "shaft_end_oil", "shaft_end_air", "lip_oil",
               "seal_oil", "seal_air", "seal_housing", "shaft_pocket", "seal_pocket")

STEEL, RUBBER, CASE = 0, 1, 2


@dataclass(frozen=True)
class SealSection:
    """Dimensions of the shaft + seal model [m].

    Parameters
    ----------
    shaft_diameter, outer_diameter, width : float
        d, D and the axial width of the seal.
    contact_band : float
        Axial width of the band that receives the frictional heat (contact width, plus twice
        the track amplitude of a wave lip).
    shaft_length_oil, shaft_length_air : float
        Modelled shaft length on each side of the contact [m].
    spring_offset : float
        Axial position of the garter spring plane ("R value", air side positive).
    bearing_span : tuple of float, optional
        Axial extent (z_far, z_near) of the bearing's inner ring on the oil-side shaft [m]
        (negative z); its cells receive the bearing's heat.
    """

    shaft_diameter: float
    outer_diameter: float
    width: float
    contact_band: float
    shaft_length_oil: float = 0.06
    shaft_length_air: float = 0.08
    spring_offset: float = 0.5e-3
    bearing_span: tuple[float, float] | None = None

    @property
    def radius(self) -> float:
        return self.shaft_diameter / 2

    @property
    def section(self) -> float:
        return (self.outer_diameter - self.shaft_diameter) / 2

    # cross-section proportions (DIN 3760 type A, see module docstring)
    @property
    def lip_height(self) -> float:
        """Contact edge to spring-groove bottom: about 2.5 mm on an 80 x 100 seal."""
        return 0.2 * self.section + 0.5e-3

    @property
    def body_inner_radius(self) -> float:
        return self.radius + 0.6 * self.section

    @property
    def oil_face(self) -> float:
        return -(0.15 * self.width + 0.5e-3)

    @property
    def air_face(self) -> float:
        return self.oil_face + self.width

    @property
    def lip_oil_limit(self) -> float:
        return -self.contact_band / 2 - 0.12 * self.width

    @property
    def lip_air_limit(self) -> float:
        return self.contact_band / 2 + 0.3 * self.width

    @property
    def flex_thickness(self) -> float:
        return 0.1 * self.width

    def groove_probe(self) -> tuple[float, float]:
        """(r, z) of the spring-groove thermocouple: rubber just under the groove bottom."""
        return self.radius + self.lip_height - 0.3e-3, self.spring_offset


@dataclass
class LipSealThermalGrid:
    """The conduction model and what the coupled simulation needs to know about it."""

    section: SealSection
    conduction: AxisymmetricConduction
    face_groups: dict[str, np.ndarray]
    contact_cells: np.ndarray
    contact_weights: np.ndarray
    groove_cell: int
    pocket_volume: float
    pocket_opening_area: float
    bearing_cells: np.ndarray
    bearing_weights: np.ndarray


def _tan(deg: float) -> float:
    return float(np.tan(np.radians(deg)))


@lru_cache(maxsize=16)
def build_thermal_grid(section: SealSection, shaft: Solid, rubber: Solid, case: Solid,
                       refinement: float = 1.0) -> LipSealThermalGrid:
    """Build the finite-volume grid of shaft and seal.

    Pure geometry, so a grid is built once per set of arguments and shared (read-only) by
    the models of every operating point and variant that use it.

    Parameters
    ----------
    section : SealSection
        Dimensions.
    shaft, rubber, case : Solid
        Materials of shaft, seal elastomer and seal case.
    refinement : float
        Mesh density factor (1 = default; 2 halves the cell sizes near features and makes
        the grading gentler).

    Returns
    -------
    LipSealThermalGrid
    """
    s = section
    r_ = s.radius
    h = s.section
    band = s.contact_band
    growth = 1.0 + 0.3 / refinement
    fine_contact = min(band / 8, 40e-6) / refinement
    skin = 5e-6 / refinement  # thin shaft skin under the contact: cell centre ≈ surface
    feature = 0.25e-3 / refinement
    coarse = max(s.shaft_diameter / 8, 2e-3) / refinement

    r_case_out = s.outer_diameter / 2 - 0.1 * h
    r_case_in = s.outer_diameter / 2 - 0.25 * h
    r_case_leg = s.body_inner_radius + 0.1 * h
    r_points = [(0.0, coarse), (r_, skin), (r_ + s.lip_height, feature),
                (s.body_inner_radius, feature), (r_case_leg, feature), (r_case_in, feature),
                (r_case_out, feature), (s.outer_diameter / 2, feature)]
    r_points.sort()
    r_edges = graded_edges([p for p, _ in r_points], [f for _, f in r_points], growth, coarse)

    z_case_leg = s.air_face - 0.12 * s.width
    z_points = {(-s.shaft_length_oil, coarse), (s.oil_face, feature),
                (s.lip_oil_limit, feature), (-band / 2, fine_contact),
                (band / 2, fine_contact), (s.lip_air_limit - s.flex_thickness, feature),
                (s.lip_air_limit, feature), (z_case_leg, feature), (s.air_face, feature),
                (s.shaft_length_air, coarse), (s.oil_face + 0.05 * s.width, feature)}
    if s.bearing_span is not None:
        z_points |= {(z, feature) for z in s.bearing_span}
    z_points = sorted(z_points)
    z_edges = graded_edges([p for p, _ in z_points], [f for _, f in z_points], growth, coarse)

    rc = 0.5 * (r_edges[:-1] + r_edges[1:])[:, None]
    zc = 0.5 * (z_edges[:-1] + z_edges[1:])[None, :]
    y = rc - r_  # height above the shaft
    in_seal_z = (zc >= s.oil_face) & (zc <= s.air_face)
    body = (rc >= s.body_inner_radius) & in_seal_z
    flex = (rc >= r_ + s.lip_height) & (rc < s.body_inner_radius) & (
        zc >= s.lip_air_limit - s.flex_thickness) & (zc <= s.lip_air_limit)
    oil_flank = np.maximum(-band / 2 - y / _tan(45.0), s.lip_oil_limit)
    air_flank = np.minimum(band / 2 + y / _tan(25.0), s.lip_air_limit)
    lip = (y > 0) & (y < s.lip_height) & (zc >= oil_flank) & (zc <= air_flank)
    steel_case = ((rc >= r_case_in) & (rc <= r_case_out) & (zc >= s.oil_face + 0.05 * s.width)
                  & (zc <= s.air_face)) | ((rc >= r_case_leg) & (rc <= r_case_out)
                                           & (zc >= z_case_leg) & (zc <= s.air_face))
    material = np.full((len(rc), zc.shape[1]), -1, dtype=int)
    material[np.broadcast_to(rc < r_, material.shape)] = STEEL
    material[body | flex | lip] = RUBBER
    material[steel_case] = CASE
    conduction = AxisymmetricConduction(r_edges, z_edges, material, [shaft, rubber, case])

    # oil or air: void regions connected to the oil-side end of the domain are oil
    void = material < 0
    labels, _ = ndimage.label(void)
    oil_labels = set(np.unique(labels[:, 0])) - {0}
    is_oil_void = np.isin(labels, list(oil_labels)).ravel()
    pocket_cells = (void & ~is_oil_void.reshape(void.shape)
                    & (rc < s.body_inner_radius) & (zc < s.air_face))
    is_pocket_void = pocket_cells.ravel()

    b = conduction.boundary
    cell_material = conduction.cell_material[b.cell]
    shaft_face = cell_material == STEEL
    seal_face = ~shaft_face
    at_edge = b.void < 0
    oil = np.zeros(len(b.cell), dtype=bool)
    oil[~at_edge] = is_oil_void[b.void[~at_edge]]
    pocket = np.zeros(len(b.cell), dtype=bool)
    pocket[~at_edge] = is_pocket_void[b.void[~at_edge]]
    air = ~at_edge & ~oil & ~pocket
    lip_zone = b.r < r_ + s.lip_height + 1e-9
    groups = {
        "shaft_oil": shaft_face & oil,
        "shaft_air": shaft_face & air,
        "shaft_end_oil": shaft_face & at_edge & (b.side == 2),
        "shaft_end_air": shaft_face & at_edge & (b.side == 3),
        "lip_oil": seal_face & oil & lip_zone,
        "seal_oil": seal_face & oil & ~lip_zone,
        "seal_air": seal_face & air,
        "seal_housing": seal_face & at_edge & (b.side == 1),
        "shaft_pocket": shaft_face & pocket,
        "seal_pocket": seal_face & pocket,
    }
    # faces in no group (none expected; e.g. a seal touching the domain end) are adiabatic
    assigned = np.sum([g.astype(int) for g in groups.values()], axis=0)
    if np.any(assigned > 1):  # pragma: no cover - a geometry bug, not user input
        raise RuntimeError("a boundary face belongs to two groups")
    face_groups = {name: np.nonzero(mask)[0] for name, mask in groups.items()}

    i_surface = int(np.argmin(np.abs(r_edges - r_))) - 1  # the shaft's outermost row
    zc1 = conduction.z_centres
    in_band = (zc1 > -band / 2) & (zc1 < band / 2)
    contact_cells = conduction.index[i_surface, in_band]
    weights = np.diff(z_edges)[in_band]
    bearing_cells, bearing_weights = np.zeros(0, dtype=int), np.zeros(0)
    if s.bearing_span is not None:
        under = (zc1 > s.bearing_span[0]) & (zc1 < s.bearing_span[1])
        bearing_cells = conduction.index[i_surface, under]
        bearing_weights = np.diff(z_edges)[under] / np.diff(z_edges)[under].sum()
    groove_cell = conduction.cell_at(*s.groove_probe())
    ring = np.pi * (r_edges[1:] ** 2 - r_edges[:-1] ** 2)
    pocket_volume = float(np.sum(ring[:, None] * np.diff(z_edges)[None, :] * pocket_cells))
    opening = np.pi * (s.body_inner_radius**2 - r_**2)
    return LipSealThermalGrid(s, conduction, face_groups, contact_cells,
                              weights / weights.sum(), groove_cell, pocket_volume, opening,
                              bearing_cells, bearing_weights)
