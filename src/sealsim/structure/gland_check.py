r"""O-ring gland design check: squeeze, stretch, gland fill and extrusion gap with the
worst-case tolerance stack, at the lowest and highest service temperature.

Pure functions (SI units, numpy arrays broadcast):

* :func:`installed_cord` -- the cross-section of a ring stretched onto a seat or compressed
  into a bore, at constant rubber volume and a round section (Apple Rubber, *Seal Design
  Guide*, "Seal compression (squeeze)": "the o-ring volume does not change and the
  cross-section remains round when stretched");
* :func:`squeeze`, :func:`stretch`, :func:`gland_fill` -- the definitions of the seal makers'
  handbooks (Parker, *O-Ring Handbook* ORD 5700): squeeze = (d2 - h)/d2 with h the gland depth
  from the groove bottom to the sealing surface, clearance included (US Seal, *General design
  and gland dimensions*: "squeeze is measured from the bottom of the groove to the mating
  surface and includes the clearance gap"; a face gland's is its flange separation);
  stretch = (D_hardware - d1)/d1 with the hardware diameter the ring sits on (piston: groove
  bottom; rod: rod; face: groove inner diameter); gland fill = ring section area /
  (h · groove width);
* :func:`extrusion_gap_limit` -- the largest diametral clearance against pressure and
  hardness (Parker ORD 5700, Figure 3-2 "Limits for extrusion", as tabulated by Seal & Design
  Inc., *Extrusion limits of O-rings*, sealanddesign.com: 70 and 90 Shore A);
* :func:`gland_state` -- all of them for one gland at a temperature, from the toleranced
  dimensions: the rubber (cord and inside diameter) grows with its linear expansion
  :math:`\alpha_r` and the fluid swell :math:`(1 + \Delta V/V)^{1/3}`, each metal part with its
  own expansion, all from the assembly temperature.

:func:`worst_case` finds the smallest and largest value of each quantity over the tolerance
band of every dimension (the classic worst-case stack: each dimension at the limit that
moves the quantity the wrong way, from the sign of its sensitivity), at each service
temperature with and without swell; :func:`corner_values` evaluates all 2^n tolerance corners
(a brute-force check of the stack).  :func:`design_checks` compares the results with the
published design ranges (:data:`DESIGN_LIMITS`, each with its source).  :func:`check_gland`
composes all of this for a :class:`~sealsim.structure.gland_case.GlandCase`.

>>> round(float(squeeze(3.53e-3, 3.10e-3)) * 100, 2)
12.18
>>> round(float(gland_fill(np.pi / 4 * 3.53e-3**2, 3.10e-3, 4.8e-3)) * 100, 1)
65.8
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from sealsim.errors import InputError

__all__ = ["CLEARANCE_MIN", "DESIGN_LIMITS", "GlandGeometry", "GlandReport",
           "PISTON_STRETCH_MIN", "QUANTITIES", "check_gland", "corner_values", "design_checks",
           "extrusion_gap_limit", "gland_fill", "gland_state", "installed_cord", "squeeze",
           "stretch", "worst_case"]

PSI = 6894.757293168361
"""Pascal per psi (NIST SP 811, B.8)."""
INCH = 0.0254
"""Metre per inch (exact)."""
ROUNDING = 1e-12
"""Relative rounding of a unit conversion, below which a value equals its limit."""

#: Quantities of the stack: report name -> key of :func:`gland_state`.
QUANTITIES = {"squeeze_percent": "squeeze", "stretch_percent": "stretch",
              "gland_fill_percent": "fill", "extrusion_gap_mm": "gap"}


def installed_cord(cord, inner_diameter, seat_inner=None, seat_outer=None):
    """Cross-section d2' [m] of a ring stretched onto ``seat_inner`` or compressed into
    ``seat_outer``, at constant volume and a round section.

    The torus volume π²/4 · C · d2² (C = d1 + d2, the centreline diameter) is kept: stretched
    onto a seat of diameter D_i > d1 the ring has C' = D_i + d2', compressed into a bore D_o <
    d1 + 2 d2 (a face-gland groove's outer wall) it has C' = D_o - d2'; otherwise it is
    unchanged.  Solved by fixed-point
    iteration (a contraction: dC'/dd2' << C'/d2').

    Parameters
    ----------
    cord, inner_diameter : array_like
        Free cross-section d2 and inside diameter d1 [m].
    seat_inner, seat_outer : array_like, optional
        Diameter [m] the ring's ID is pulled onto, and the diameter its OD is pushed into.

    Examples
    --------
    >>> round(float(installed_cord(3.53e-3, 20.22e-3, seat_inner=21.0e-3)) * 1e3, 4)
    3.4772
    """
    d2 = np.asarray(cord, dtype=float)
    d1 = np.asarray(inner_diameter, dtype=float)
    centre = d1 + d2
    out = np.broadcast_to(d2, np.broadcast_shapes(d2.shape, d1.shape)).copy()
    if seat_inner is not None:
        si = np.asarray(seat_inner, dtype=float)
        stretched = np.broadcast_to(si > d1, out.shape)
        x = out.copy()
        for _ in range(30):
            x = d2 * np.sqrt(centre / (si + x))
        out = np.where(stretched, x, out)
    if seat_outer is not None:
        so = np.asarray(seat_outer, dtype=float)
        squeezed = np.broadcast_to(so < d1 + 2.0 * d2, out.shape) & (out == d2)
        x = out.copy()
        for _ in range(30):
            x = d2 * np.sqrt(centre / np.maximum(so - x, 1e-12))
        out = np.where(squeezed, x, out)
    return out


def squeeze(cord, depth):
    """Squeeze (d2 - h)/d2 [-] of a cross-section d2 [m] in a gland of depth h [m]."""
    cord = np.asarray(cord, dtype=float)
    return (cord - np.asarray(depth, dtype=float)) / cord


def stretch(inner_diameter, hardware_diameter):
    """Stretch (D - d1)/d1 [-] of a ring of inside diameter d1 [m] on hardware of diameter D
    [m]; negative when the ring's ID is larger than the hardware."""
    d1 = np.asarray(inner_diameter, dtype=float)
    return (np.asarray(hardware_diameter, dtype=float) - d1) / d1


def gland_fill(section_area, depth, width):
    """Gland fill [-]: ring section area [m²] / (gland depth [m] · groove width [m])."""
    return np.asarray(section_area, dtype=float) / (np.asarray(depth, dtype=float)
                                                    * np.asarray(width, dtype=float))


#: Pressure steps of the extrusion table [Pa] (upper limits: below 500 psi, 500-1000, ...,
#: 2000-3000 psi) and the largest diametral clearance [m] for 70 and 90 Shore A.
EXTRUSION_TABLE = {
    "pressure": tuple(p * PSI for p in (500.0, 1000.0, 1500.0, 2000.0, 3000.0)),
    70.0: tuple(c * INCH for c in (0.016, 0.010, 0.006, 0.004, 0.002)),
    90.0: tuple(c * INCH for c in (0.028, 0.024, 0.020, 0.016, 0.010)),
}
EXTRUSION_SOURCE = ("Parker O-Ring Handbook ORD 5700, Fig. 3-2 'Limits for extrusion' (no "
                    "back-up ring), tabulated for 70 and 90 Shore A by Seal & Design Inc., "
                    "'Extrusion limits of O-rings' (sealanddesign.com); 80 Shore A "
                    "interpolated linearly; silicone: clearances halved (Parker ORD 5700, "
                    "Section IV)")


def extrusion_gap_limit(pressure, hardness_shore_a):
    """Largest diametral clearance [m] an O-ring without back-up ring bridges at a pressure
    [Pa] (Parker ORD 5700, Fig. 3-2; see :data:`EXTRUSION_SOURCE`).

    The table steps at 500, 1000, 1500, 2000 and 3000 psi (each upper limit included);
    between 70 and 90 Shore A the clearance is interpolated linearly, outside the hardness is
    clamped to 70 ... 90 (callers note it).  Above 3000 psi (206.8 bar) the table gives no
    clearance: 0 (back-up rings are needed).

    Examples
    --------
    >>> round(float(extrusion_gap_limit(100e5, 70.0)) * 1e3, 4)   # 1450 psi: 0.006 in
    0.1524
    >>> round(float(extrusion_gap_limit(100e5, 80.0)) * 1e3, 4)   # between 0.006 and 0.020
    0.3302
    >>> from sealsim.units import parse_quantity
    >>> round(float(extrusion_gap_limit(parse_quantity("1500 psi", "pressure"), 70.0)) / INCH, 4)
    0.006
    """
    p = np.asarray(pressure, dtype=float)
    steps = np.asarray(EXTRUSION_TABLE["pressure"])
    k = np.searchsorted(steps * (1 + ROUNDING), p, side="left")   # "1500 psi" is in its row
    inside = k < steps.size
    kk = np.minimum(k, steps.size - 1)
    soft, hard = (np.asarray(EXTRUSION_TABLE[h])[kk] for h in (70.0, 90.0))
    w = (np.clip(np.asarray(hardness_shore_a, dtype=float), 70.0, 90.0) - 70.0) / 20.0
    return np.where(inside, soft + w * (hard - soft), 0.0)


# -- one gland at one temperature -----------------------------------------------------------

#: Metal dimensions of each housing type and the part whose expansion they follow.
_METAL_PART = {
    "piston": {"bore": "outer", "groove_diameter": "inner", "groove_width": "inner",
               "piston_diameter": "inner"},
    "rod": {"rod": "inner", "groove_diameter": "outer", "groove_width": "outer",
            "bore": "outer"},
    "face": {"groove_depth": "inner", "groove_width": "inner",
             "groove_inner_diameter": "inner", "gap": "inner"},
}


def gland_state(housing: str, values: dict[str, Any], temperature, *,
                reference_temperature: float, rubber_expansion: float,
                inner_expansion: float, outer_expansion: float, volume_swell=0.0,
                area_factor: float = math.pi / 4.0) -> dict[str, np.ndarray]:
    """Squeeze, stretch, fill and extrusion gap of a gland at a temperature.

    Parameters
    ----------
    housing : {"piston", "rod", "face"}
        Piston gland (groove in the piston, the ring seals on the bore), rod gland (groove in
        the housing, the ring seals on the rod), face gland (axial squeeze).
    values : dict
        Sizes at the reference temperature [m]: ``cord``, ``inner_diameter`` of the ring and
        the housing's dimensions (:data:`sealsim.structure.gland_case.HOUSING_DIMENSIONS`);
        arrays broadcast.
    temperature : array_like
        Temperature T [K].
    reference_temperature : float
        T_ref [K] at which the sizes hold (assembly).
    rubber_expansion, inner_expansion, outer_expansion : float
        Linear expansion [1/K] of the rubber, the inner and the outer metal part.
    volume_swell : array_like
        Volume change ΔV/V of the ring in the fluid [-].
    area_factor : float
        Section area / d2² [-]: π/4 for an O-ring, 0.8215 for a Quad-Ring X-ring.

    Returns
    -------
    dict of numpy.ndarray
        ``squeeze``, ``stretch``, ``fill`` [-], ``gap`` (diametral extrusion gap; face: twice
        the flange gap) [m], ``cord`` (installed d2') and ``depth`` (gland depth h from the
        groove bottom to the sealing surface; face: groove depth + flange gap) [m].
    """
    dt = np.asarray(temperature, dtype=float) - reference_temperature
    grow = {"inner": 1.0 + inner_expansion * dt, "outer": 1.0 + outer_expansion * dt}
    try:
        metal = {k: np.asarray(values[k], dtype=float) * grow[part]
                 for k, part in _METAL_PART[housing].items()}
    except KeyError as exc:
        raise InputError(f"gland_state: {housing!r} gland needs {exc.args[0]!r}") from None
    rubber = (1.0 + rubber_expansion * dt) * np.cbrt(1.0 + np.asarray(volume_swell, float))
    d2 = np.asarray(values["cord"], dtype=float) * rubber
    d1 = np.asarray(values["inner_diameter"], dtype=float) * rubber
    if housing == "piston":
        hardware, outer_seat = metal["groove_diameter"], None
        depth = 0.5 * (metal["bore"] - metal["groove_diameter"])
        gap = metal["bore"] - metal["piston_diameter"]
    elif housing == "rod":
        # a rod-gland ring larger than the groove is squeezed radially (that is its squeeze),
        # not compressed around its circumference: only a stretch onto the rod thins it
        hardware, outer_seat = metal["rod"], None
        depth = 0.5 * (metal["groove_diameter"] - metal["rod"])
        gap = metal["bore"] - metal["rod"]
    else:
        hardware = metal["groove_inner_diameter"]
        outer_seat = hardware + 2.0 * metal["groove_width"]
        # from the groove bottom to the cover flange: a flange separation deepens the gland,
        # as the radial clearance does in a piston or rod gland
        depth = metal["groove_depth"] + metal["gap"]
        gap = 2.0 * metal["gap"]
    cord = installed_cord(d2, d1, seat_inner=hardware, seat_outer=outer_seat)
    return {"squeeze": squeeze(cord, depth), "stretch": stretch(d1, hardware),
            "fill": gland_fill(area_factor * cord**2, depth, metal["groove_width"]),
            "gap": gap * np.ones_like(cord), "cord": cord, "depth": depth * np.ones_like(cord)}


# -- the worst-case stack -----------------------------------------------------------------------

@dataclass(frozen=True)
class GlandGeometry:
    """A gland with its tolerance bands, everything :func:`gland_state` needs.

    ``limits`` maps each size (``cord``, ``inner_diameter`` and the housing's dimensions) to
    (smallest, nominal, largest) [m] at the reference temperature; nominal is the middle of
    the tolerance band (a fit such as f7 does not contain the basic size).
    """

    housing: str
    limits: dict[str, tuple[float, float, float]]
    reference_temperature: float
    rubber_expansion: float
    inner_expansion: float
    outer_expansion: float
    area_factor: float = math.pi / 4.0

    def state(self, values, temperature, volume_swell=0.0):
        return gland_state(self.housing, values, temperature,
                           reference_temperature=self.reference_temperature,
                           rubber_expansion=self.rubber_expansion,
                           inner_expansion=self.inner_expansion,
                           outer_expansion=self.outer_expansion, volume_swell=volume_swell,
                           area_factor=self.area_factor)

    def nominal(self) -> dict[str, float]:
        return {k: v[1] for k, v in self.limits.items()}


def worst_case(geometry: GlandGeometry, temperature: float, volume_swell: float = 0.0
               ) -> dict[str, dict[str, Any]]:
    """Smallest, nominal and largest value of each :func:`gland_state` quantity over the
    tolerance bands, at one temperature and swell.

    Each dimension is set to the limit that moves the quantity down (for the minimum) or up
    (for the maximum), by the sign of its sensitivity at nominal (a central difference over
    the band); the result is checked against all tolerance corners in the tests.

    Returns
    -------
    dict
        ``{quantity: {"min": .., "nominal": .., "max": .., "min_at": {size: value},
        "max_at": {...}}}`` for squeeze, stretch, fill, gap [-, m].
    """
    nominal = geometry.nominal()
    base = geometry.state(nominal, temperature, volume_swell)
    names = list(geometry.limits)
    # sensitivities of every quantity to every size, all in one vectorised call
    trial = {k: np.full(2 * len(names), nominal[k]) for k in names}
    for j, k in enumerate(names):
        trial[k][2 * j], trial[k][2 * j + 1] = geometry.limits[k][0], geometry.limits[k][2]
    moved = geometry.state(trial, temperature, volume_swell)
    out = {}
    for q in ("squeeze", "stretch", "fill", "gap"):
        rising = moved[q][1::2] > moved[q][0::2]
        ends = {}
        for sign, key in ((1.0, "max"), (-1.0, "min")):
            corner = np.where(rising == (sign > 0), 2, 0)
            corner, value = _improve_corner(geometry, q, sign, corner, temperature,
                                            volume_swell)
            ends[key] = value
            ends[f"{key}_at"] = {k: geometry.limits[k][c] for k, c in zip(names, corner)}
        out[q] = {"min": ends["min"], "nominal": float(base[q]), "max": ends["max"],
                  "min_at": ends["min_at"], "max_at": ends["max_at"]}
    return out


def _improve_corner(geometry: GlandGeometry, quantity: str, sign: float, corner: np.ndarray,
                    temperature: float, volume_swell: float) -> tuple[np.ndarray, float]:
    """Steepest ascent of sign·quantity over the tolerance corners, from ``corner`` (indices
    0/2 of the limits): a size whose sensitivity vanishes at nominal (a ring neither stretched
    nor compressed there) may still matter at the other limits."""
    names = list(geometry.limits)
    n = len(names)

    def values(corners):
        return {k: np.array([geometry.limits[k][c] for c in corners[:, j]])
                for j, k in enumerate(names)}

    current = float(geometry.state(values(corner[None, :]), temperature,
                                   volume_swell)[quantity][0])
    for _ in range(n):
        flips = np.repeat(corner[None, :], n, axis=0)
        flips[np.arange(n), np.arange(n)] = 2 - flips[np.arange(n), np.arange(n)]
        trial = geometry.state(values(flips), temperature, volume_swell)[quantity]
        best = int(np.argmax(sign * trial))
        if sign * trial[best] <= sign * current * (1.0 + 1e-12) + 1e-15:
            break
        corner, current = flips[best], float(trial[best])
    return corner, current


def corner_values(geometry: GlandGeometry, temperature: float, volume_swell: float = 0.0
                  ) -> dict[str, np.ndarray]:
    """:func:`gland_state` at every one of the 2^n tolerance corners (brute force)."""
    names = list(geometry.limits)
    corners = np.array(list(itertools.product((0, 2), repeat=len(names))))
    values = {k: np.array([geometry.limits[k][c] for c in corners[:, j]])
              for j, k in enumerate(names)}
    return geometry.state(values, temperature, volume_swell)


# -- design limits ------------------------------------------------------------------------------

@dataclass(frozen=True)
class DesignLimit:
    """A published design range: the quantity's worst-case value must stay on the right side
    of ``value``."""

    name: str
    quantity: str           # squeeze, stretch, fill, gap
    bound: str              # "min" (value >= limit) or "max" (value <= limit)
    value: float
    source: str
    maker: bool = True      # a seal maker's recommendation, not a standard

    def ok(self, value: float) -> bool:
        return value >= self.value if self.bound == "min" else value <= self.value


_APPLE = ("Apple Rubber, Seal Design Guide, 'O-ring installation' (applerubber.com): squeeze "
          "'~10-40% for static'")
_KUTZ = ("Mechanical Engineers' Handbook, Vol. 3 (Kutz, ed., Wiley), 'Seal technology', after "
         "the Parker O-Ring Handbook: 'maximum linear compression suggested by manufacturers "
         "is 30% for static applications and 16% for dynamic seals (up to 25% for small "
         "cross-sectional diameters)'")

#: The published design ranges, by motion: (static, reciprocating).  Each is a seal maker's
#: recommendation (ISO 3601-2 gives housing dimensions, not ranges).
DESIGN_LIMITS = {
    "static": (
        DesignLimit("squeeze_min", "squeeze", "min", 0.10, _APPLE),
        DesignLimit("squeeze_max", "squeeze", "max", 0.30, _KUTZ),
    ),
    "reciprocating": (
        DesignLimit("squeeze_min", "squeeze", "min", 0.10,
                    "O-Ring Supply Co., 'O-ring compression rate guide' (oringsupplyco.com): "
                    "dynamic reciprocating seals 10-15 %, 'under-compression below 10% risks "
                    "low-pressure leakage'"),
        DesignLimit("squeeze_max", "squeeze", "max", 0.16, _KUTZ),
    ),
    "any": (
        DesignLimit("stretch_max", "stretch", "max", 0.05,
                    "Parker Hannifin, 'How to design an O-ring gland: stretch' (Parker blog, "
                    "reposted at gallagherseals.com): 'up to 5% stretch is recommended'; "
                    "Apple Rubber Seal Design Guide: 1-5 %, 2 % ideal"),
        DesignLimit("gland_fill_max", "fill", "max", 0.90,
                    "Parker O-Ring eHandbook, Failure modes, 'Gland overfill' (parker.com): "
                    "'a maximum material condition gland fill of 90%'"),
    ),
}
#: A piston gland's ring must be stretched onto its groove when it is installed: a ring whose
#: inside diameter is larger than the groove bottom is not held by it (it twists and can be
#: pinched when the piston enters the bore; far larger, it does not fit the bore at all).
#: Checked on the worst-case stack at the assembly temperature, unswollen (a ring warmed in
#: service may loosen: rubber expands about ten times more than steel).
PISTON_STRETCH_MIN = DesignLimit(
    "stretch_min", "installed_stretch", "min", 0.0,
    "Apple Rubber, Seal Design Guide, 'Dimensional considerations' (applerubber.com): 'the "
    "O-ring's inside diameter (I.D.) must be smaller than the piston groove diameter, so that "
    "the O-ring is slightly stretched' (1-5 %, 2 % ideal; floating seals, which may leak, are "
    "the exception: set limits.stretch_min below 0)")
#: A piston or rod gland's metal parts must not interfere at any service temperature: their
#: expansion can close a clearance that the fit (checked at assembly when the case is read)
#: leaves, e.g. an aluminium piston in a steel bore when hot.  Geometry, not a recommendation.
CLEARANCE_MIN = DesignLimit(
    "clearance_min", "gap", "min", 0.0,
    "geometry: a diametral clearance below 0 is an interference, the piston or rod is larger "
    "than its bore and seizes (the metal parts' expansion from the assembly temperature "
    "closes the clearance of the fit)", maker=False)
#: Cross-sections below which the small-section squeeze limit of dynamic seals applies [m]
#: (AS568 -0xx series, 1.78 mm: the 'small cross-sectional diameters' of the Kutz quote).
SMALL_CORD = 2.0e-3
SMALL_CORD_DYNAMIC_SQUEEZE_MAX = 0.25


def design_checks(stack: dict[str, dict[str, float]], *, motion: str, cord: float,
                  pressure: float, hardness_shore_a: float, silicone: bool = False,
                  overrides: dict[str, float] | None = None,
                  housing: str | None = None) -> list[dict[str, Any]]:
    """The list of checks ``{"name", "value", "limit", "unit", "ok", "bound", "source",
    "maker"}``.

    Parameters
    ----------
    stack : dict
        ``{quantity: {"min": .., "max": ..}}`` over all temperatures (squeeze, stretch, fill
        [-], gap [m]); for a piston gland also ``installed_stretch`` (the stretch at the
        assembly temperature, unswollen, :data:`PISTON_STRETCH_MIN`).
    motion : {"static", "reciprocating"}
    cord : float
        Nominal cross-section [m].
    pressure : float
        Highest pressure difference [Pa].
    hardness_shore_a : float
        Ring hardness.
    silicone : bool
        A silicone (VMQ) ring: extrusion clearances halved.
    overrides : dict, optional
        The case's own limits (``squeeze_min`` ..., ``extrusion_gap_max`` [m]).
    housing : {"piston", "rod", "face"}, optional
        A piston gland adds the check ``stretch_min``, a piston or rod gland the check
        ``clearance_min`` (:data:`CLEARANCE_MIN`).

    Values and limits are percent for squeeze, stretch and fill, mm for the gap (``unit``).
    """
    overrides = {k: v for k, v in (overrides or {}).items() if v is not None}
    limits = list(DESIGN_LIMITS[motion]) + list(DESIGN_LIMITS["any"])
    if motion == "reciprocating" and cord < SMALL_CORD:
        limits[1] = DesignLimit("squeeze_max", "squeeze", "max",
                                SMALL_CORD_DYNAMIC_SQUEEZE_MAX, _KUTZ)
    gap_limit = float(extrusion_gap_limit(pressure, hardness_shore_a)) * (0.5 if silicone
                                                                          else 1.0)
    if housing == "piston":
        limits.insert(3, PISTON_STRETCH_MIN)             # after stretch_max
    limits.append(DesignLimit("extrusion_gap", "gap", "max", gap_limit, EXTRUSION_SOURCE))
    if housing in ("piston", "rod"):
        limits.append(CLEARANCE_MIN)
    checks = []
    for lim in limits:
        key = "extrusion_gap_max" if lim.name == "extrusion_gap" else lim.name
        if key in overrides:
            lim = DesignLimit(lim.name, lim.quantity, lim.bound, overrides[key],
                              "your limit (case file [limits])", maker=False)
        value = stack[lim.quantity][lim.bound]
        scale, unit = (1e3, "mm") if lim.quantity == "gap" else (100.0, "%")
        checks.append({"name": lim.name, "value": value * scale, "limit": lim.value * scale,
                       "unit": unit, "ok": bool(lim.ok(value)), "bound": lim.bound,
                       "source": lim.source, "maker": lim.maker})
    return checks


# -- orchestration ------------------------------------------------------------------------------

@dataclass
class GlandReport:
    """Result of :func:`check_gland` (``to_dict`` is the ``report.json`` of ``sealsim gland
    check``)."""

    case: Any
    geometry: GlandGeometry
    temperatures: list[float]
    swells: list[float]
    stacks: list[dict[str, Any]]
    overall: dict[str, dict[str, Any]]
    checks: list[dict[str, Any]]
    hardness: float
    notes: list[str] = field(default_factory=list)
    fe: dict[str, Any] | None = None

    @property
    def ok(self) -> bool:
        return all(c["ok"] for c in self.checks)

    @property
    def failed(self) -> list[str]:
        return [c["name"] for c in self.checks if not c["ok"]]

    def to_dict(self) -> dict[str, Any]:
        def scaled(stat, q):
            scale = 1e3 if q == "gap" else 100.0
            return {k: stat[k] * scale for k in ("min", "nominal", "max")}

        out: dict[str, Any] = {"title": self.case.title, "ok": self.ok, "failed": self.failed}
        out["housing"] = {"type": self.case.housing.type, "motion": self.case.housing.motion,
                          "ring": self.case.ring.type}
        for name, q in QUANTITIES.items():
            out[name] = scaled(self.overall[q], q)
        out["by_temperature"] = [
            {"temperature_C": s["temperature"] - 273.15, "fluid_swell": s["swell"],
             **{name: scaled(s[q], q) for name, q in QUANTITIES.items()}}
            for s in self.stacks]
        out["extrusion"] = {
            "pressure_bar": self.case.service.pressure / 1e5,
            "hardness_shore_a": self.hardness,
            "gap_max_mm": self.overall["gap"]["max"] * 1e3,
            "gap_limit_mm": next(c["limit"] for c in self.checks if c["name"] == "extrusion_gap"),
            "source": EXTRUSION_SOURCE}
        out["checks"] = self.checks
        out["dimensions_mm"] = {k: {"min": v[0] * 1e3, "nominal": v[1] * 1e3, "max": v[2] * 1e3}
                                for k, v in self.geometry.limits.items()}
        out["worst_case_corners"] = {
            f"{q}_{b}": {k: v * 1e3 for k, v in self.overall[q][f"{b}_at"].items()}
            | {"temperature_C": self.overall[q][f"{b}_temperature"] - 273.15,
               "fluid_swell": self.overall[q][f"{b}_swell"]}
            for q in ("squeeze", "fill", "gap", "stretch") for b in ("min", "max")}
        out["notes"] = self.notes
        if self.fe is not None:
            out["fe"] = self.fe
        return out


def geometry_of(case) -> tuple[GlandGeometry, Any, list[str]]:
    """The :class:`GlandGeometry` of a gland case, its elastomer and notes on the inputs."""
    from sealsim.properties.elastomers import get_elastomer
    from sealsim.structure.tolerances import (
        iso3601_cord_tolerance,
        iso3601_inner_diameter_tolerance,
    )

    ring, housing = case.ring, case.housing
    elastomer = get_elastomer(ring.material)
    notes = []
    tol_d2 = ring.cord_tolerance
    tol_d1 = ring.inner_diameter_tolerance
    if tol_d2 is None:
        tol_d2 = iso3601_cord_tolerance(ring.cord_diameter)
    if tol_d1 is None:
        tol_d1 = iso3601_inner_diameter_tolerance(ring.inner_diameter)
    notes.append(f"ring tolerances: d2 ±{tol_d2 * 1e3:.3g} mm "
                 f"({'ISO 3601-1' if ring.cord_tolerance is None else 'given'}), "
                 f"d1 ±{tol_d1 * 1e3:.3g} mm "
                 f"({'ISO 3601-1' if ring.inner_diameter_tolerance is None else 'given'})")
    limits = {"cord": (ring.cord_diameter - tol_d2, ring.cord_diameter,
                       ring.cord_diameter + tol_d2),
              "inner_diameter": (ring.inner_diameter - tol_d1, ring.inner_diameter,
                                 ring.inner_diameter + tol_d1)}
    limits.update(housing.dimension_limits())
    area = math.pi / 4.0
    if ring.type == "xring":
        from sealsim.structure.profiles import xring_profile

        area = xring_profile(1.0, 10.0).area  # the section scales with d2²
        notes.append("X-ring: section area 0.82 d2² (Quad-Ring); the design ranges are the "
                     "O-ring's (Quad-Ring dynamic glands run less squeeze, e.g. 7.9 % for "
                     "3.53 mm, Minnesota Rubber Quad-Ring design guide)")
    alpha = ring.thermal_expansion or elastomer.thermal_expansion
    geometry = GlandGeometry(housing.type, limits, case.service.assembly_temperature, alpha,
                             housing.inner_expansion, housing.outer_expansion, area)
    return geometry, elastomer, notes


def check_gland(case) -> GlandReport:
    """Worst-case stack and design checks of a :class:`~.gland_case.GlandCase`.

    The stack is taken at the lowest and the highest service temperature (and the assembly
    temperature), each with the ring unswollen and with the fluid swell; the overall minimum
    and maximum of each quantity are checked against :data:`DESIGN_LIMITS`.

    Examples
    --------
    >>> from sealsim.cases import validate_case
    >>> from sealsim.structure.gland_case import GlandCase
    >>> case = validate_case(GlandCase, {
    ...     "ring": {"cord_diameter": "3.53 mm", "inner_diameter": "18.77 mm",
    ...              "material": "NBR"},
    ...     "housing": {"type": "piston", "motion": "static",
    ...                 "bore": {"nominal": "25 mm", "fit": "H8"},
    ...                 "groove_diameter": {"nominal": "19.2 mm", "fit": "h9"},
    ...                 "groove_width": {"nominal": "4.8 mm", "upper": "0.2 mm", "lower": "0 mm"},
    ...                 "piston_diameter": {"nominal": "25 mm", "fit": "f7"}},
    ...     "service": {"pressure": "100 bar", "temperature": ["-20 degC", "100 degC"]}})
    >>> report = check_gland(case)
    >>> {k: round(v, 1) for k, v in report.to_dict()["squeeze_percent"].items()}
    {'min': 12.2, 'nominal': 16.6, 'max': 21.2}
    >>> report.ok
    True
    """
    geometry, elastomer, notes = geometry_of(case)
    service = case.service
    temps = sorted({service.assembly_temperature, *service.temperature})
    swells = sorted({0.0, service.fluid_swell})
    stacks = []
    for t in temps:
        for s in swells:
            stacks.append({"temperature": t, "swell": s, **worst_case(geometry, t, s)})
    overall: dict[str, dict[str, Any]] = {}
    nominal = worst_case(geometry, service.assembly_temperature, 0.0)
    for q in ("squeeze", "stretch", "fill", "gap"):
        lo = min(stacks, key=lambda st: st[q]["min"])
        hi = max(stacks, key=lambda st: st[q]["max"])
        overall[q] = {"min": lo[q]["min"], "nominal": nominal[q]["nominal"],
                      "max": hi[q]["max"], "min_at": lo[q]["min_at"], "max_at": hi[q]["max_at"],
                      "min_temperature": lo["temperature"], "max_temperature": hi["temperature"],
                      "min_swell": lo["swell"], "max_swell": hi["swell"]}
    ring = case.ring
    hardness = ring.hardness_shore_a or elastomer.hardness_shore_a
    if hardness is None:
        raise InputError(f"ring.hardness_shore_a: the catalogue has no hardness for "
                         f"{ring.material!r}; give it (e.g. 70)")
    if not 70.0 <= hardness <= 90.0:
        notes.append(f"hardness {hardness:g} Shore A is outside the extrusion table (70-90 "
                     "Shore A): the nearest row is used")
    checks = design_checks(
        {**overall, "installed_stretch": nominal["stretch"]}, motion=case.housing.motion,
        cord=ring.cord_diameter, pressure=service.pressure, hardness_shore_a=hardness,
        silicone=elastomer.name.upper() in ("VMQ", "FVMQ"),
        overrides=case.limits.model_dump(mode="python"), housing=case.housing.type)
    # the limits themselves are allowed: "1500 psi" or "212 degF" may come out of the unit
    # conversion a last bit above 1500 * PSI or 373.15 K
    if service.pressure > 1500 * PSI * (1 + ROUNDING):
        notes.append("pressure above 103.4 bar (1500 psi): Parker (ORD 5700, Section IV) "
                     "advises investigating back-up rings")
    lo_t, hi_t = elastomer.service_range
    if (min(service.temperature) < lo_t * (1 - ROUNDING)
            or max(service.temperature) > hi_t * (1 + ROUNDING)):
        notes.append(f"service temperatures outside the {elastomer.name} catalogue's service "
                     f"range {lo_t - 273.15:.0f} ... {hi_t - 273.15:.0f} degC")
    tg = elastomer.glass_transition
    if min(service.temperature) < tg:
        notes.append(f"lowest temperature {min(service.temperature) - 273.15:.0f} degC is "
                     f"below the glass transition of {elastomer.name} "
                     f"({tg - 273.15:.0f} degC): the ring is glassy there and the squeeze "
                     "shown (rubbery expansion) does not mean it seals")
    for check in checks:
        if not check["ok"]:
            notes.append(_failure_text(check))
    return GlandReport(case, geometry, temps, swells, stacks, overall, checks, hardness, notes)


def _failure_text(check: dict[str, Any]) -> str:
    unit = f" {check['unit']}"
    word = "below the minimum" if check["bound"] == "min" else "above the maximum"
    return (f"{check['name']} fails: worst case {check['value']:.3g}{unit} is {word} "
            f"{check['limit']:.3g}{unit} ({check['source']})")
