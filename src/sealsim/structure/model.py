"""The FE model of a seal in its gland: FElupe region, field, solid body, rigid contacts,
fluid pressure -- set up once, then driven through load states by :mod:`.solver`.

Pipeline (FElupe style): geometry (:class:`~.geometry.SealAssembly`) → mesh
(:func:`~.mesh.mesh_section`) → :class:`SealModel` (``RegionQuad`` → ``FieldAxisymmetric``
→ ``SolidBodyNearlyIncompressible`` + one ``ContactRigidPlane`` per rigid line +
:class:`~.loads.FluidPressure`) → :func:`~.solver.solve` → :mod:`.results`.

Thermal expansion enters the mixed formulation through the reference volume of every cell:
FElupe's constant-pressure body evaluates :math:`\\bar J = v / V` and
:math:`U = K/2\\,(\\bar J - 1)^2`; the model sets :math:`V = J_{th} V_0`, which makes the
volumetric energy :math:`J_{th} V_0\\,U(v / (J_{th} V_0))` -- the seed's Eq. (7) with the
stress-free volume of the heated (or cooled) rubber.
"""

from __future__ import annotations

from dataclasses import dataclass

import felupe as fem
import numpy as np

from sealsim.structure.constraints import RollingConstraint
from sealsim.structure.geometry import SealAssembly
from sealsim.structure.loads import FluidPressure
from sealsim.structure.mesh import SealMesh

__all__ = ["DEFAULT_POSITIONING_PRESSURE", "LoadState", "SealModel"]

DEFAULT_POSITIONING_PRESSURE = 1.0e3
"""Small pressure [Pa] (0.01 bar) that holds the seal against the downstream wall when the
fluid pressure is lower (frictionless contact leaves its axial position otherwise open)."""


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
        symmetry condition instead).
    penalty : float
        Contact penalty as a multiple of the mean diagonal stiffness of the contact nodes.
    positioning_pressure : float
        Minimum pressure [Pa] on the upstream side (see :data:`DEFAULT_POSITIONING_PRESSURE`).
    rolling_stiffness : float
        Stiffness of the anti-rolling spring (:mod:`.constraints`) in units of
        G·A·2πR_c (shear modulus × section area × centre circumference); 0 disables it.
    """

    def __init__(self, assembly: SealAssembly, mesh: SealMesh, material, *,
                 installation_squeeze: float, axisymmetric: bool = True, walls: bool = True,
                 penalty: float = 1.0,
                 positioning_pressure: float = DEFAULT_POSITIONING_PRESSURE,
                 rolling_stiffness: float = 10.0):
        self.assembly = assembly
        self.seal_mesh = mesh
        self.material = material
        self.installation_squeeze = float(installation_squeeze)
        self.axisymmetric = axisymmetric
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
        self.solid = fem.SolidBodyNearlyIncompressible(
            material.umat, self.field, bulk=material.bulk(t0))
        self.V0 = self.solid.V.copy()
        self.loop = np.asarray(mesh.boundary)
        self.contacts = {
            line.name: fem.ContactRigidPlane(
                self.field, points=self.loop, centerpoint=self.centerpoints[line.name],
                normal=line.normal, multiplier=penalty, items=[self.solid])
            for line in lines
        }
        self.pressure = FluidPressure(self.field, self.loop, axisymmetric=axisymmetric)
        self.items = [self.solid, *self.contacts.values(), self.pressure]
        self.rolling = None
        if walls and rolling_stiffness > 0:
            rel = mesh.points - np.asarray(mesh.centre)
            dist = np.linalg.norm(rel, axis=1)
            core = np.where(dist <= 0.45 * assembly.seal.radius)[0]
            # a few dozen nodes describe the rotation of the core; more would only fill the
            # sparse matrix (the spring couples all its nodes)
            core = core[np.argsort(dist[core])][:: max(1, len(core) // 32)]
            g = material.shear_modulus(assembly.reference_temperature)
            ring = assembly.seal
            k = rolling_stiffness * g * ring.area * self.circumference(ring.centre_radius)
            self.rolling = RollingConstraint(self.field, core, k)
            self.items.append(self.rolling)
        # prescribed dofs: the rigid lines' reference points (+ symmetry line without walls)
        dof0 = [2 * p + c for p in self.centerpoints.values() for c in (0, 1)]
        self._symmetry = np.array([], dtype=int)
        if not walls:
            self._symmetry = np.asarray(mesh.symmetry_nodes)
            dof0 += list(2 * self._symmetry)
        self.dof0 = np.array(sorted(dof0))
        self.dof1 = np.setdiff1d(np.arange(2 * self.mesh.npoints), self.dof0)
        self._line_origin = {line.name: np.array(line.point) for line in lines}
        self.state = LoadState(0.0, 0.0, t0, 0.0)
        self.force_scale = self._force_scale()
        self.newton_iterations: list[int] = []

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
        return g * ring.cord_diameter * self.circumference(ring.centre_radius)

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
        return values[self.dof0]

    def set_load(self, state: LoadState, time_increment: float) -> np.ndarray:
        """Set material state, thermal volume, fluid pressure; return the prescribed values."""
        self.material.set_state(state.temperature, time_increment)
        self.solid.bulk = self.material.bulk(state.temperature)
        self.solid.V = self.V0 * self.material.volume_ratio
        self.pressure.update(self.applied_pressure(state.pressure))
        return self.prescribed(state)

    # -- contact state ---------------------------------------------------------------------------
    def gaps(self, name: str) -> np.ndarray:
        """Gaps [m] of the loop nodes to a rigid line (negative = penetration)."""
        contact = self.contacts[name]
        return contact._kinematics(contact._gap_vectors())[0]

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
        return np.where(g < 0.0, -lam * g, 0.0)

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
            tol = 1e-9 * self.assembly.seal.cord_diameter
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
        }

    def restore(self, cp: dict) -> None:
        self.solid.restore(cp["solid"])
        for k, c in self.contacts.items():
            c.restore(cp["contacts"][k])
        self.pressure.s0, self.pressure.s1 = (a.copy() for a in cp["wet"])
        self.pressure.field = self.field
        self.state = cp["state"]
        self.material.temperature = cp["temperature"]
        for item in self.items:
            item.field.link(self.field)
