"""The FE model of a seal in its gland: FElupe region, field, solid body, rigid contacts,
fluid pressure -- set up once, then driven through load states by :mod:`.solver`.

Pipeline (FElupe style): geometry (:class:`~.geometry.SealAssembly`) → mesh
(:func:`~.profile_mesh.mesh_section`) → :class:`SealModel` (``RegionQuad`` → ``FieldAxisymmetric``
→ ``SolidBodyNearlyIncompressible`` + one ``ContactRigidPlane`` per rigid line (a
:class:`~.land_contact.ContactRigidLand` for a wall ending at a clearance gap) +
:class:`~.loads.FluidPressure`) → :func:`~.solver.solve` → :mod:`.results`.

Thermal expansion enters the mixed formulation through the reference volume of every cell:
FElupe's constant-pressure body evaluates :math:`\\bar J = v / V` and
:math:`U = K/2\\,(\\bar J - 1)^2`; the model sets :math:`V = J_{th} V_0`, which makes the
volumetric energy :math:`J_{th} V_0\\,U(v / (J_{th} V_0))` -- Eq. (7) of Heipl & Murrenhoff with the
stress-free volume of the heated (or cooled) rubber.
"""

from __future__ import annotations

from dataclasses import dataclass

import felupe as fem
import numpy as np

from sealsim.structure import material as material_module
from sealsim.structure.assembly import (
    HAVE_COMPILED_ASSEMBLY,
    CompiledSolidBody,
    ContactRigidPlaneOnce,
    SystemAssembly,
)
from sealsim.structure.constraints import (
    AxialPositionConstraint,
    GarterSpring,
    RollingConstraint,
    ring_samples,
)
from sealsim.structure.geometry import ORing, SealAssembly
from sealsim.structure.land_contact import ContactRigidLand
from sealsim.structure.loads import FluidPressure
from sealsim.structure.mesh import SealMesh

__all__ = ["DEFAULT_POSITIONING_PRESSURE", "GarterSpringSpec", "LoadState", "SealModel"]

DEFAULT_POSITIONING_PRESSURE = 1.0e3
"""Small pressure [Pa] (0.01 bar) that holds the seal against the downstream wall when the
fluid pressure is lower (frictionless contact leaves its axial position otherwise open)."""


@dataclass(frozen=True)
class GarterSpringSpec:
    """Garter spring of a radial lip seal (:class:`~.constraints.GarterSpring`).

    Parameters
    ----------
    rate : float
        Axial rate of the straight coil spring [N/m].
    tension : float
        Hoop pre-tension in the free seal [N].
    """

    rate: float
    tension: float


@dataclass(frozen=True)
class LoadState:
    """One load state: squeeze [-], fluid pressure [Pa], temperature [K], time [s]."""

    squeeze: float
    pressure: float
    temperature: float
    time: float = 0.0

    def interpolate(self, other: LoadState, fraction: float) -> LoadState:
        f = float(fraction)
        return LoadState(*(a + f * (b - a) for a, b in
                           zip((self.squeeze, self.pressure, self.temperature, self.time),
                               (other.squeeze, other.pressure, other.temperature, other.time))))


class SealModel:
    """Axisymmetric (or plane-strain) FE model of a seal in its gland.

    Parameters
    ----------
    assembly : SealAssembly
        Seal and gland.
    mesh : SealMesh
        Mesh of the seal section in its initial position (:attr:`SealAssembly.centre`).
    material : HyperelasticSealMaterial or ViscoelasticSealMaterial
        Seal material.
    installation_squeeze : float
        Squeeze at the end of the installation [-] (first squeeze of the load path).
    axisymmetric : bool
        Axisymmetric model (default) or plane strain (per unit length, for checks).
    walls : bool
        Include the groove walls (plane-strain checks between two flats use False and a
        symmetry condition instead); the assembly's own ``walls`` setting also counts.
    penalty : float
        Contact penalty as a multiple of the mean diagonal stiffness of the contact nodes.
    positioning_pressure : float
        Minimum pressure [Pa] on the upstream side (see :data:`DEFAULT_POSITIONING_PRESSURE`).
    rolling_stiffness : float
        Stiffness of the anti-rolling spring (:mod:`.constraints`) in units of
        G·A·2πR_c (shear modulus × section area × centre circumference); 0 disables it.
    friction : float or dict, optional
        Coulomb friction coefficient of the rigid lines (one value for all, or per line name:
        "sealing_surface", "groove_bottom", "wall_upstream", "wall_downstream"); FElupe's
        penalty friction with return mapping (stick / slip, state updated after each
        converged increment).
    elastic_slip : float, optional
        Elastic slip [m] a sticking contact node may take before it slides (FElupe's
        ``elastic_slip``: the tangential penalty is μ f_n / slip, so sticking does not depend
        on the contact pressure); default 1e-3 of the section's contact size. Without it the
        stick/slip state of nodes entering contact chatters between Newton iterations.
    spring : GarterSpringSpec, optional
        Garter spring on the mesh's ``"spring"`` node set (radial lip seals).
    compiled : bool, optional
        Assemble with the compiled solid body and the cached system pattern
        (:mod:`.assembly`) or with FElupe's own assembly, the reference (default
        :data:`sealsim.structure.material.USE_COMPILED`, i.e. compiled when numba is
        installed).
    """

    def __init__(self, assembly: SealAssembly, mesh: SealMesh, material, *,
                 installation_squeeze: float, axisymmetric: bool = True, walls: bool = True,
                 penalty: float = 1.0,
                 positioning_pressure: float = DEFAULT_POSITIONING_PRESSURE,
                 rolling_stiffness: float = 10.0, friction: float | dict | None = None,
                 elastic_slip: float | None = None, spring: GarterSpringSpec | None = None,
                 compiled: bool | None = None):
        self.assembly = assembly
        self.seal_mesh = mesh
        self.material = material
        self.installation_squeeze = float(installation_squeeze)
        self.axisymmetric = axisymmetric
        shaft = assembly.gland.arrangement == "shaft"
        walls = walls and assembly.walls and not shaft
        self.walls = walls
        self.positioning_pressure = float(positioning_pressure) if walls else 0.0
        t0 = assembly.reference_temperature
        material.set_state(t0, 0.0)
        lines = assembly.lines(0.0, t0, self.installation_squeeze)
        if not walls:
            lines = lines[:2]
        self.line_names = [line.name for line in lines]
        self.normals = {line.name: np.array(line.normal) for line in lines}
        npts = mesh.npoints
        self.centerpoints = {line.name: npts + k for k, line in enumerate(lines)}
        points = np.vstack([mesh.points] + [np.array(line.point)[None] for line in lines])
        self.mesh = fem.Mesh(points, mesh.cells, "quad")
        self.region = fem.RegionQuad(self.mesh)
        if axisymmetric:
            self.displacement = fem.FieldAxisymmetric(self.region, dim=2)
        else:
            self.displacement = fem.FieldPlaneStrain(self.region, dim=2)
        self.field = fem.FieldContainer([self.displacement])
        if compiled is None:
            compiled = material_module.USE_COMPILED
        self.compiled = bool(compiled) and HAVE_COMPILED_ASSEMBLY
        solid = CompiledSolidBody if self.compiled else fem.SolidBodyNearlyIncompressible
        self.solid = solid(material.umat, self.field, bulk=material.bulk(t0))
        self.V0 = self.solid.V.copy()
        self.loop = np.asarray(mesh.boundary)
        bonded = mesh.node_sets.get("bonded", np.array([], dtype=int))
        self.bonded = np.asarray(bonded, dtype=int)
        # in loop order (np.setdiff1d would sort them by node number, and gaps() maps the
        # contact's values back to the loop in this order)
        candidates = self.loop[~np.isin(self.loop, self.bonded)]
        mu = friction if isinstance(friction, dict) else \
            {name: float(friction or 0.0) for name in self.line_names}
        unknown = set(mu) - set(self.line_names) - {"sealing_surface", "groove_bottom",
                                                     "wall_upstream", "wall_downstream"}
        if unknown:
            raise ValueError(f"friction given for unknown rigid lines {sorted(unknown)}")
        self.friction = {name: float(mu.get(name, 0.0)) for name in self.line_names}
        if elastic_slip is None:
            seal = assembly.seal
            elastic_slip = 1e-3 * getattr(seal, "contact_scale", seal.radial_extent)
        plane = ContactRigidPlaneOnce if self.compiled else fem.ContactRigidPlane

        def contact(line):
            options = {"multiplier": penalty, "items": [self.solid],
                       "friction": self.friction[line.name],
                       "elastic_slip": elastic_slip if self.friction[line.name] > 0 else None}
            if line.edge_radius is not None:   # a wall ending at a land's edge (clearance)
                return ContactRigidLand(self.field, candidates, self.centerpoints[line.name],
                                        line.normal, line.edge_direction, line.edge_radius,
                                        **options)
            return plane(self.field, points=candidates,
                         centerpoint=self.centerpoints[line.name], normal=line.normal,
                         **options)

        self.contacts = {line.name: contact(line) for line in lines}
        self._candidates = candidates
        self.pressure = FluidPressure(self.field, self.loop, axisymmetric=axisymmetric)
        self.items = [self.solid, *self.contacts.values(), self.pressure]
        self.spring = None
        if spring is not None:
            seat = mesh.node_sets.get("spring")
            if seat is None or not axisymmetric:
                raise ValueError("a garter spring needs an axisymmetric model and a seal with "
                                 "a spring seat (segments tagged 'spring')")
            self.spring = GarterSpring(self.field, seat, spring.rate, spring.tension)
            self.items.append(self.spring)
        seal = assembly.seal
        g = material.shear_modulus(assembly.reference_temperature)
        self.rolling = None
        self.axial_hold = None
        if not shaft:
            samples = _core_samples(seal, mesh)
            if rolling_stiffness > 0:
                k = rolling_stiffness * g * seal.area * self.circumference(seal.centre_radius)
                self.rolling = RollingConstraint(self.field, samples, k)
                self.items.append(self.rolling)
            if not walls and len(mesh.symmetry_nodes) == 0:
                k = 10.0 * g * self.circumference(seal.centre_radius)
                self.axial_hold = AxialPositionConstraint(self.field, samples, k)
                self.items.append(self.axial_hold)
        # prescribed dofs: the rigid lines' reference points (+ symmetry line without walls,
        # + the edges bonded to the metal case)
        dof0 = [2 * p + c for p in self.centerpoints.values() for c in (0, 1)]
        self._symmetry = np.array([], dtype=int)
        if not walls and not shaft:
            self._symmetry = np.asarray(mesh.symmetry_nodes, dtype=int)
            dof0 += list(2 * self._symmetry)
        dof0 += [2 * p + c for p in self.bonded for c in (0, 1)]
        self.dof0 = np.array(sorted(dof0))
        self.dof1 = np.setdiff1d(np.arange(2 * self.mesh.npoints), self.dof0)
        self.system = (SystemAssembly(2 * self.mesh.npoints, self.dof1, self.dof0)
                       if self.compiled else None)
        self._line_origin = {line.name: np.array(line.point) for line in lines}
        self.state = LoadState(0.0, 0.0, t0, 0.0)
        self.force_scale = self._force_scale()
        self.newton_iterations: list[int] = []
        self.increment_log: list[dict] = []

    # -- sizes and scales -------------------------------------------------------------------------
    @property
    def ndofs(self) -> int:
        """Active degrees of freedom of the seal (two per mesh node)."""
        return 2 * self.seal_mesh.npoints

    def circumference(self, radius: float) -> float:
        """2π r for an axisymmetric model, 1 (per unit length) for plane strain."""
        return 2 * np.pi * radius if self.axisymmetric else 1.0

    def _force_scale(self) -> float:
        g = self.material.shear_modulus(self.assembly.reference_temperature)
        ring = self.assembly.seal
        return g * ring.radial_extent * self.circumference(ring.centre_radius)

    # -- loads -----------------------------------------------------------------------------------
    def applied_pressure(self, pressure: float) -> float:
        """Pressure on the wetted surface [Pa]: the fluid pressure, at least the positioning
        pressure (a smooth maximum would not matter: it is 0.01 bar)."""
        return max(float(pressure), self.positioning_pressure)

    def prescribed(self, state: LoadState) -> np.ndarray:
        """Values of the prescribed dofs (ext0) for a load state."""
        lines = self.assembly.lines(state.squeeze, state.temperature, self.installation_squeeze)
        values = np.zeros(2 * self.mesh.npoints)
        for line in lines:
            if line.name in self.centerpoints:
                p = self.centerpoints[line.name]
                values[2 * p:2 * p + 2] = np.array(line.point) - self._line_origin[line.name]
        if len(self.bonded):
            # the metal case moves with the housing: free thermal expansion about the origin
            strain = self.assembly.housing_expansion() * (
                state.temperature - self.assembly.reference_temperature)
            u = strain * self.seal_mesh.points[self.bonded]
            values[2 * self.bonded] = u[:, 0]
            values[2 * self.bonded + 1] = u[:, 1]
        return values[self.dof0]

    def set_load(self, state: LoadState, time_increment: float) -> np.ndarray:
        """Set material state, thermal volume, fluid pressure; return the prescribed values."""
        self.material.set_state(state.temperature, time_increment)
        self.solid.bulk = self.material.bulk(state.temperature)
        self.solid.V = self.V0 * self.material.volume_ratio
        self.pressure.update(self.applied_pressure(state.pressure))
        if self.spring is not None:
            self.spring.scale = self.assembly.spring_factor(state.squeeze,
                                                            self.installation_squeeze)
        return self.prescribed(state)

    # -- contact state ---------------------------------------------------------------------------
    def gaps(self, name: str) -> np.ndarray:
        """Gaps [m] of the loop nodes to a rigid line (negative = penetration; +inf for nodes
        that cannot touch it, such as bonded ones)."""
        contact = self.contacts[name]
        g = contact._kinematics(contact._gap_vectors())[0]
        if len(self._candidates) == len(self.loop):
            return g
        out = np.full(len(self.loop), np.inf)
        out[np.isin(self.loop, self._candidates)] = g
        return out

    def tangential_reaction(self, name: str) -> float:
        """Force [N] the seal exerts on a rigid line along it (friction; x for radial
        surfaces, y for walls), from the assembled contact forces on the line's reference
        point (full circumference for an axisymmetric model)."""
        contact = self.contacts[name]
        force = contact.results.force
        if force is None:
            return 0.0
        p = self.centerpoints[name]
        along = 0 if abs(self.normals[name][1]) > 0.5 else 1
        return -float(np.asarray(force[2 * p + along].toarray()).ravel()[0])

    def tributary_lengths(self) -> np.ndarray:
        """Half the lengths of the two deformed boundary segments at each loop node [m]."""
        x = self.pressure.positions()
        seg = np.linalg.norm(np.roll(x, -1, axis=0) - x, axis=1)
        return 0.5 * (seg + np.roll(seg, 1))

    def contact_forces(self, name: str) -> np.ndarray:
        """Normal contact force [N] at each loop node (full circumference or per unit length)."""
        contact = self.contacts[name]
        g = self.gaps(name)
        lam = contact.multipliers.normal if contact.multipliers is not None else 0.0
        return -lam * np.where(g < 0.0, g, 0.0)

    def contact_pressure(self, name: str | None = None) -> np.ndarray:
        """Nodal contact pressure [Pa] (one line, or the largest over all lines)."""
        names = self.line_names if name is None else [name]
        x = self.pressure.positions()
        area = self.tributary_lengths() * np.array([self.circumference(r) for r in x[:, 1]])
        pc = np.zeros(len(self.loop))
        for n in names:
            pc = np.maximum(pc, self.contact_forces(n) / area)
        return pc

    def update_wetting(self) -> float:
        """Update the wetted surface from the current contact pressures; change [m]."""
        entry = self.assembly.fluid_entry()
        pc = self.contact_pressure()
        if self.state.squeeze == 0.0:
            # unloaded start: nodes touching a rigid line bound the wetted surface
            tol = 1e-9 * self.assembly.seal.radial_extent
            touching = np.min([self.gaps(n) for n in self.line_names], axis=0) <= tol
            pc = np.where(touching, np.inf, pc)
        return self.pressure.update_wetting(pc, entry)

    # -- checkpoints ------------------------------------------------------------------------------
    def checkpoint(self) -> dict:
        return {
            "solid": self.solid.checkpoint(),
            "contacts": {k: c.checkpoint() for k, c in self.contacts.items()},
            "wet": (self.pressure.s0.copy(), self.pressure.s1.copy()),
            "state": self.state,
            "temperature": self.material.temperature,
            "spring": None if self.spring is None else self.spring.scale,
        }

    def restore(self, cp: dict) -> None:
        self.solid.restore(cp["solid"])
        for k, c in self.contacts.items():
            c.restore(cp["contacts"][k])
        self.pressure.s0, self.pressure.s1 = (a.copy() for a in cp["wet"])
        self.pressure.field = self.field
        self.state = cp["state"]
        self.material.temperature = cp["temperature"]
        if self.spring is not None:
            self.spring.scale = cp["spring"]
        for item in self.items:
            item.field.link(self.field)


def _core_samples(seal, mesh: SealMesh) -> np.ndarray:
    """Sample points of the rolling and axial constraints: two rings of eight points around
    the section's centre (O-ring: circle centre, radius 0.45 a; profile: area centroid, 60 %
    of its distance to the boundary)."""
    if isinstance(seal, ORing):
        return ring_samples(mesh.centre, 0.45 * seal.radius)
    from matplotlib.path import Path

    boundary = mesh.points[mesh.boundary]
    centre = np.asarray(mesh.centre)
    if not Path(boundary).contains_point(centre):
        # a section whose centroid lies outside (an L- or U-shape): the deepest inner point
        lo, hi = boundary.min(axis=0), boundary.max(axis=0)
        grid = np.stack(np.meshgrid(np.linspace(lo[0], hi[0], 41), np.linspace(lo[1], hi[1], 41)),
                        axis=-1).reshape(-1, 2)
        grid = grid[Path(boundary).contains_points(grid)]
        depth = np.min(np.linalg.norm(grid[:, None] - boundary[None], axis=2), axis=1)
        centre = grid[int(np.argmax(depth))]
    depth = float(np.min(np.linalg.norm(boundary - centre, axis=1)))
    return ring_samples(centre, 0.6 * depth)
