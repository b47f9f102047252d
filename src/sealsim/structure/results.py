r"""Results of a seal load state: normal force, contact width and pressure, groove reactions,
equilibrium and penetration checks, and the deformed section for plots.

Conventions
-----------
* Forces of an axisymmetric model are for the **full circumference** (360°) [N]; per unit
  circumferential length they are divided by 2π R of the surface [N/m]. Plane-strain forces
  are per unit length [N/m].
* Contact pressure at a node is its contact force divided by its tributary area
  (2π r × half the two adjacent deformed boundary segments).
* The contact width b of one contact zone is the distance between its two edges along the
  surface (:func:`contact_width`): where the contact pressure falls to zero, with p² linear
  in position next to the last node in contact (the square-root edge of a smooth, Hertz
  contact); the wetted surface of the fluid pressure ends at the same edges. A profile with
  several lobes (an X-ring) touches in several zones: b is the sum of their widths (the
  surface that carries load and shears the film), the span from the first to the last edge
  is reported as well.
* Friction (tangential) forces of the rigid lines come from the assembled contact forces on
  their reference points and enter the equilibrium check.
* Global equilibrium: the reactions of the rigid parts (minus the fluid load) balance the
  seal; axially they sum to zero, radially to the hoop force :math:`2\pi\int P_{\theta\theta}\,dA`
  (the axisymmetric section is not a free body in r: the ring's hoop stress takes part of the
  radial load, which is why the rod force differs from the groove-bottom force).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from sealsim.units import ZERO_CELSIUS_K

__all__ = [
    "StateResult",
    "SurfaceResult",
    "contact_width",
    "contact_zones",
    "extract",
    "pressure_profile",
    "profiles_frame",
    "results_frame",
]


@dataclass
class SurfaceResult:
    """Contact with one rigid line.

    Attributes
    ----------
    name : str
        Rigid line ("sealing_surface", "groove_bottom", "wall_upstream", "wall_downstream").
    force : float
        Total normal force [N] (full circumference; per unit length for plane strain).
    width : float
        Contact width [m] along the line (0 if no contact).
    p_max, p_mean : float
        Peak and mean (force / (2π R b)) contact pressure [Pa].
    position : numpy.ndarray
        Coordinate along the line of the nodes in contact [m] (z for radial surfaces, r for
        walls), sorted.
    pressure : numpy.ndarray
        Contact pressure at those nodes [Pa].
    radius : float
        Radius of the line (or mean radius of the contact on a wall) [m].
    edge_low, edge_high : float
        Outermost contact edges along the line [m] (nan without contact).
    zones : int
        Number of separate contact zones.
    zone_edges : list of tuple
        (low edge, high edge) of every contact zone [m].
    tangential : float
        Force of the seal on the line along it [N] (friction; z for radial lines, r for
        walls).
    """

    name: str
    force: float
    width: float
    p_max: float
    p_mean: float
    position: np.ndarray
    pressure: np.ndarray
    radius: float
    edge_low: float = float("nan")
    edge_high: float = float("nan")
    zones: int = 0
    tangential: float = 0.0
    zone_edges: list = field(default_factory=list)

    @property
    def span(self) -> float:
        """Distance from the first to the last contact edge [m] (0 without contact)."""
        return float(self.edge_high - self.edge_low) if self.zones else 0.0


@dataclass
class StateResult:
    """Everything computed for one load state (SI units)."""

    squeeze: float
    pressure: float
    temperature: float
    time: float
    F_N: float
    F_N_per_length: float
    b: float
    p_max: float
    p_mean: float
    surfaces: dict[str, SurfaceResult]
    axial_imbalance: float
    radial_imbalance: float
    hoop_force: float
    fluid_force: tuple[float, float]
    max_penetration: float
    wetted_length: float
    rolling_moment: float
    spring_force: float = 0.0
    deformed_points: np.ndarray = field(repr=False, default=None)
    cells: np.ndarray = field(repr=False, default=None)
    von_mises: np.ndarray = field(repr=False, default=None)
    lines: list = field(repr=False, default_factory=list)
    bonded_points: np.ndarray = field(repr=False, default=None)
    spring_points: np.ndarray = field(repr=False, default=None)

    def row(self) -> dict:
        """One row of ``result.csv`` (engineering units; the squeeze in percent, as the gland
        check gives it)."""
        s = self.surfaces
        return {
            "squeeze_percent": round(self.squeeze * 100.0, 8),
            "pressure_bar": self.pressure / 1e5,
            "temperature_C": self.temperature - ZERO_CELSIUS_K,
            "time_s": self.time,
            "F_N_N": self.F_N,
            "F_N_per_length_N_per_mm": self.F_N_per_length / 1e3,
            "b_mm": self.b * 1e3,
            "p_max_MPa": self.p_max / 1e6,
            "p_mean_MPa": self.p_mean / 1e6,
            "contact_zones": s["sealing_surface"].zones,
            "b_span_mm": s["sealing_surface"].span * 1e3,
            "F_friction_sealing_N": s["sealing_surface"].tangential,
            "F_groove_bottom_N": s["groove_bottom"].force if "groove_bottom" in s else 0.0,
            "p_max_groove_bottom_MPa": s["groove_bottom"].p_max / 1e6
            if "groove_bottom" in s else 0.0,
            "F_wall_upstream_N": s["wall_upstream"].force if "wall_upstream" in s else 0.0,
            "F_wall_downstream_N": s["wall_downstream"].force if "wall_downstream" in s else 0.0,
            "hoop_force_N": self.hoop_force,
            "max_penetration_um": self.max_penetration * 1e6,
            "rolling_moment_Nm": self.rolling_moment,
            "spring_force_N": self.spring_force,
        }


def _edge(x, p, inner, direction, threshold):
    """Position where the pressure profile falls to ``threshold`` beyond node ``inner`` in
    ``direction`` (±1), with p² linear in x (the square-root edge of a smooth contact, exact
    for Hertz)."""
    outer = inner + direction
    outer = outer if 0 <= outer < len(x) else None
    pt2 = threshold**2
    pi2 = p[inner] ** 2
    if outer is not None and p[outer] > 0.0:
        # both in contact: interpolate p² between them
        return x[inner] + (x[outer] - x[inner]) * (pi2 - pt2) / (pi2 - p[outer] ** 2)
    # beyond the last node in contact: extrapolate p² from the next inner node
    k = inner - direction
    if 0 <= k < len(x) and p[k] ** 2 > pi2:
        e = x[inner] + (x[inner] - x[k]) * (pi2 - pt2) / (p[k] ** 2 - pi2)
    else:
        e = x[inner] if outer is None else 0.5 * (x[inner] + x[outer])
    if outer is not None:  # not past the first free node
        e = min(e, x[outer]) if direction > 0 else max(e, x[outer])
    return e


def _skip_grazing(x, p, edge, other, direction, threshold):
    """(edge node, pressures) with a grazing outermost node dropped: one with less pressure
    than its inner neighbour whose presence contradicts the p²-linear edge extrapolated from
    the two nodes inside it (that edge lies inside the node)."""
    inner = edge - direction
    if threshold != 0.0 or abs(other - edge) < 2 or not p[edge] < p[inner]:
        return edge, p
    q = p.copy()
    q[edge] = 0.0
    e = _edge(x, q, inner, direction, 0.0)
    if (e - x[edge]) * direction < -1e-12 * max(abs(x[inner] - x[edge]), 1e-300):
        return inner, q
    return edge, p


def contact_width(position, pressure, threshold_low=0.0, threshold_high=0.0):
    """Contact width [m] and the two edges from a nodal contact pressure profile.

    Parameters
    ----------
    position : array_like
        Node positions along the surface [m], ascending, including the free nodes next to
        the contact (pressure 0).
    pressure : array_like
        Nodal contact pressure [Pa].
    threshold_low, threshold_high : float
        Pressure [Pa] that defines the edge on the low/high side: 0 for the geometric edge,
        the fluid pressure for the edge of the sealing (dry) contact on the pressurised side.

    Returns
    -------
    (width, low_edge, high_edge) : tuple of float

    Notes
    -----
    The contact zone is the run of nodes around the peak whose pressure exceeds the
    thresholds. Each edge is where p falls to the threshold, with p² linear in position
    between the nodes -- or, beyond the last node in contact, extrapolated from the last two
    nodes but not past the first free node. Near a smooth contact edge p ∝ √(e − x) (Hertz),
    so the geometric edge is found well inside an element. An outermost node with less
    pressure than its neighbour, where the p² line through the two nodes inside it reaches
    zero before the node, only grazes the surface (node-to-surface contact: its nodal force
    does not stand for its tributary length); the edge then comes from the nodes inside it.

    Examples
    --------
    An elliptic (Hertz) profile of width 1.5 sampled every 0.1:

    >>> x = np.linspace(-1.0, 1.0, 21)
    >>> p = np.sqrt(np.clip(0.75**2 - x**2, 0.0, None))
    >>> [round(v, 4) for v in contact_width(x, p)]
    [1.5115, -0.7558, 0.7558]
    """
    x = np.asarray(position, dtype=float)
    p = np.asarray(pressure, dtype=float)
    if x.size == 0 or not np.any(p > 0):
        return 0.0, float("nan"), float("nan")
    peak = int(np.argmax(p))
    if p[peak] <= max(threshold_low, threshold_high):
        return 0.0, float(x[peak]), float(x[peak])
    lo = peak
    while lo - 1 >= 0 and p[lo - 1] > threshold_low:
        lo -= 1
    hi = peak
    while hi + 1 < len(p) and p[hi + 1] > threshold_high:
        hi += 1
    # a grazing edge node: its nodal contact force does not stand for its tributary length
    # (a node just touching the surface); then the edge comes from the nodes inside it
    lo, p = _skip_grazing(x, p, lo, hi, -1, threshold_low)
    hi, p = _skip_grazing(x, p, hi, lo, +1, threshold_high)
    e_lo = _edge(x, p, lo, -1, threshold_low)
    e_hi = _edge(x, p, hi, +1, threshold_high)
    return float(e_hi - e_lo), float(e_lo), float(e_hi)


def contact_zones(in_contact) -> list[np.ndarray]:
    """Runs of consecutive loop positions in contact (the loop is closed).

    Examples
    --------
    >>> [z.tolist() for z in contact_zones(np.array([1, 1, 0, 0, 1, 0, 1], bool))]
    [[4], [6, 0, 1]]
    """
    inc = np.asarray(in_contact, dtype=bool)
    n = len(inc)
    if not inc.any():
        return []
    if inc.all():
        return [np.arange(n)]
    start = int(np.nonzero(~inc)[0][0])  # a free node: runs do not wrap around it
    order = (start + 1 + np.arange(n)) % n
    zones, run = [], []
    for k in order:
        if inc[k]:
            run.append(k)
        elif run:
            zones.append(np.array(run))
            run = []
    if run:
        zones.append(np.array(run))
    return zones


def _surface(model, name) -> SurfaceResult:
    x = model.pressure.positions()
    normal = model.normals[name]
    along = 0 if abs(normal[1]) > 0.5 else 1  # radial surface: along z; wall: along r
    f = model.contact_forces(name)
    total = float(np.sum(f))
    inc = f > 0
    pc = model.contact_pressure(name)
    n = len(inc)
    widths, edges, positions, pressures = [], [], [], []
    for zone in contact_zones(inc):
        nodes = np.concatenate([[(zone[0] - 1) % n], zone, [(zone[-1] + 1) % n]])
        nodes = np.unique(nodes)
        order = np.argsort(x[nodes, along])
        pos, p = x[nodes, along][order], pc[nodes][order]
        w, lo, hi = contact_width(pos, p)
        widths.append(w)
        edges += [lo, hi]
        keep = p > 0
        positions.append(pos[keep])
        pressures.append(p[keep])
    if widths:
        pos_all = np.concatenate(positions)
        p_all = np.concatenate(pressures)
        order = np.argsort(pos_all)
        pos_all, p_all = pos_all[order], p_all[order]
        width, lo, hi = float(np.sum(widths)), float(np.min(edges)), float(np.max(edges))
    else:
        pos_all = p_all = np.zeros(0)
        width, lo, hi = 0.0, float("nan"), float("nan")
    if along == 0:
        cp = model.centerpoints[name]
        radius = float(model.mesh.points[cp, 1] + model.field[0].values[cp, 1])
    else:
        radius = float(np.average(x[inc, 1], weights=f[inc])) if np.any(inc) else float("nan")
    circ = model.circumference(radius) if np.isfinite(radius) else 1.0
    p_mean = total / (circ * width) if width > 0 else 0.0
    return SurfaceResult(name, total, width, float(p_all.max()) if len(p_all) else 0.0, p_mean,
                         pos_all, p_all, radius, lo, hi, len(widths),
                         model.tangential_reaction(name),
                         sorted(zip(edges[0::2], edges[1::2])))


def pressure_profile(surface: SurfaceResult, positions) -> np.ndarray:
    """Contact pressure [Pa] of a surface at given positions along it [m]: linear between the
    contact nodes of a zone, falling linearly to zero at the zone's edges, zero outside the
    contact zones.

    Examples
    --------
    >>> s = SurfaceResult("sealing_surface", 1.0, 0.2, 2.0, 1.0, np.array([0.0, 0.1]),
    ...                   np.array([2.0, 1.0]), 0.01, -0.05, 0.15, 1,
    ...                   zone_edges=[(-0.05, 0.15)])
    >>> pressure_profile(s, [-0.1, -0.025, 0.05, 0.2]).tolist()
    [0.0, 1.0, 1.5, 0.0]
    """
    grid = np.asarray(positions, dtype=float)
    out = np.zeros_like(grid)
    for lo, hi in surface.zone_edges:
        inside = (surface.position >= lo) & (surface.position <= hi)
        z = np.concatenate([[lo], surface.position[inside], [hi]])
        p = np.concatenate([[0.0], surface.pressure[inside], [0.0]])
        on = (grid >= lo) & (grid <= hi)
        out[on] = np.interp(grid[on], z, p)
    return out


def _reaction(model, name) -> np.ndarray:
    """Force (axial, radial) [N] of a rigid line on the seal: minus the contact item's
    residual on the seal nodes = its residual on the line's reference point."""
    force = model.contacts[name].results.force
    if force is None:
        return np.zeros(2)
    cp = model.centerpoints[name]
    return np.asarray(force[2 * cp:2 * cp + 2].toarray()).ravel()


def _hoop_force(model) -> float:
    """2π ∫ P_θθ dA (axisymmetric) [N]; 0 for plane strain."""
    if not model.axisymmetric:
        return 0.0
    P = model.solid.results.stress[0]
    dA = model.region.dV
    return float(2 * np.pi * np.sum(P[2, 2] * dA))


def _von_mises(model) -> np.ndarray:
    P = model.solid.results.stress[0]
    F = model.solid.results.kinematics[0]
    J = np.linalg.det(np.moveaxis(F, (0, 1), (-2, -1)))
    sigma = np.einsum("iK...,jK...->ij...", P, F) / J
    dev = sigma - np.einsum("ii...->...", sigma) / 3 * np.eye(3)[..., None, None]
    vm = np.sqrt(1.5 * np.einsum("ij...,ij...->...", dev, dev))
    return vm.mean(axis=0)


def extract(model) -> StateResult:
    """Evaluate the current (converged) state of a :class:`~.model.SealModel`."""
    # the solid's stresses are those of the last (converged) Newton evaluation; evaluating
    # them again would apply the viscoelastic history update twice
    surfaces = {name: _surface(model, name) for name in model.line_names}
    seal = surfaces["sealing_surface"]
    fp = model.pressure.force()  # (seg, node, comp)
    fluid = (float(fp[..., 0].sum()), float(fp[..., 1].sum()))
    # resultant of the contact forces on the seal (normal and friction): the reactions on
    # the rigid lines' reference points; the garter spring pulls the seal inwards
    reactions = [_reaction(model, n) for n in surfaces]
    axial = fluid[0] + sum(r[0] for r in reactions)
    radial = fluid[1] + sum(r[1] for r in reactions)
    spring = model.spring.radial_force() if model.spring is not None else 0.0
    radial -= spring
    if model.axial_hold is not None:
        # the symmetry hold of a gland without walls is a support too
        hold = np.asarray(model.axial_hold.results.force.toarray()).ravel()
        axial -= float(hold[0::2].sum())
    if len(model.bonded):
        # the metal case holds the bonded edges: its reaction is the residual of all items
        # there (internal minus the other external forces; the case is not an item)
        total = sum(np.asarray(item.results.force.toarray()).ravel() for item in model.items
                    if getattr(item.results, "force", None) is not None)
        axial += float(total[2 * model.bonded].sum())
        radial += float(total[2 * model.bonded + 1].sum())
    hoop = _hoop_force(model)
    scale = max(seal.force, 1e-30)
    pen = 0.0
    for name in model.line_names:
        g = model.gaps(name)
        if np.any(g < 0):
            pen = max(pen, float(-g.min()))
    state = model.state
    u = model.field[0].values[: model.seal_mesh.npoints]
    lines = model.assembly.lines(state.squeeze, state.temperature, model.installation_squeeze)
    circ = model.circumference(seal.radius)
    return StateResult(
        squeeze=state.squeeze, pressure=state.pressure, temperature=state.temperature,
        time=state.time, F_N=seal.force, F_N_per_length=seal.force / circ, b=seal.width,
        p_max=seal.p_max, p_mean=seal.p_mean, surfaces=surfaces,
        axial_imbalance=axial / scale, radial_imbalance=(radial - hoop) / scale,
        hoop_force=hoop, fluid_force=fluid, max_penetration=pen,
        wetted_length=model.pressure.wetted_length(),
        rolling_moment=model.rolling.moment() if model.rolling is not None else 0.0,
        spring_force=spring,
        deformed_points=model.seal_mesh.points + u, cells=model.seal_mesh.cells,
        von_mises=_von_mises(model), lines=[ln for ln in lines if ln.name in surfaces],
        bonded_points=(model.seal_mesh.points + u)[model.bonded],
        spring_points=None if model.spring is None else
        (model.seal_mesh.points + u)[model.seal_mesh.node_sets["spring"]],
    )


def results_frame(results):
    """pandas DataFrame with one row per state (the columns of ``result.csv``)."""
    import pandas as pd

    return pd.DataFrame([r.row() for r in results])


def profiles_frame(results):
    """Long-format contact pressure profiles: one row per state, surface and contact node."""
    import pandas as pd

    rows = []
    for k, r in enumerate(results):
        for name, s in r.surfaces.items():
            for pos, p in zip(s.position, s.pressure):
                rows.append({"state": k, "squeeze_percent": round(r.squeeze * 100.0, 8),
                             "pressure_bar": r.pressure / 1e5,
                             "temperature_C": r.temperature - ZERO_CELSIUS_K, "time_s": r.time,
                             "surface": name, "position_mm": pos * 1e3,
                             "contact_pressure_MPa": p / 1e6})
    return pd.DataFrame(rows, columns=["state", "squeeze_percent", "pressure_bar", "temperature_C",
                                       "time_s", "surface", "position_mm",
                                       "contact_pressure_MPa"])
