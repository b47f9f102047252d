r"""Radial lip force and contact width of a DIN 3760 lip seal from axisymmetric FE.

With ``[lip] force = "fe"`` a rotary case takes the lip force F_tip(T) and the contact width
b(T) (unless ``contact_width = "constant"``) from an FE model of its seal
(:func:`sealsim.structure.profiles.radial_lip_profile`, the garter spring as a ring spring,
the metal case rigid in the steel housing) instead of the
constant 0.15 N/mm and 0.25 mm with Eq. (1) of :mod:`sealsim.rotary.lip`. The FE load paths
install the lip at its mounting temperature T_m (``seal.mounting_temperature``), hold it for
:data:`~sealsim.properties.elastomers.HELD_SEAL_TIME` and then move through the temperature
grid at 1 K/min -- down from T_m through the grid temperatures below it, and (a second path)
up through those above:

* a rubber with a Prony series (the catalogue NBR) is the thermo-viscoelastic FE material
  (Prony + WLF/Arrhenius shift, glassy expansion through the fictive temperature,
  :class:`~sealsim.structure.material.ViscoelasticSealMaterial`): its stress relaxes at T_m,
  the contraction on cooling meets the stiffer cold rubber, the structure freezes near T_g --
  the lip mounted warm and cooled, by the FE itself;
* another rubber is hyperelastic with the held modulus of sealsim's convention
  (``temperature_scaling = "held"``), so its force at each temperature is that of a lip mounted
  there: below T_m an upper bound, and the run's notes say so;
* the rubber expands thermally (its free volume), the shaft and the housing with steel, and the
  garter spring's tension follows the lip radius (its steel rate does not change).

So the lip force falls where the rubber softens and the interference shrinks, and stays up
through the spring share -- the temperature dependence comes out of the FE instead of
Eq. (2).

**What the spring carries.** The garter spring pulls its seat inwards with its whole radial
force 2πT, but the seat lies on the air side of the contact edge (the R value; once the
shaft has swung the head onto it, about 1.2 mm on the 80 mm lip): the head is a lever on the
contact edge, and the flex takes part of the spring's pull to the metal case. Only a fraction
α of 2πT reaches the shaft; α depends on the geometry (R value, flex), not on the rubber's
modulus (the split of a load between the supports of an elastic body does not depend on its
modulus), so F_tip ≈ α·2πT + F_without, the force of the same lip without its spring, which
scales with the modulus. The FE tables therefore run the lip without its spring too, and the
spring share is 1 − F_without/F_tip, the share a split-shaft measurement with and without the
spring gives and the E-independent share of the rotary model's Eq. (2). F_tip − 2πT is not
the rubber's share: it also subtracts the spring's pull that the flex carries, and a soft
lip's would be negative (tests/test_structure_profiles_fe.py, the modulus sweep).

Between grid temperatures F_tip and b are interpolated monotonically (PCHIP), outside the grid
they are held at the end values. The table is cached under ``$SEALSIM_CACHE/lip_fe``
keyed by the resolved structure cases, like the FE maps of the pneumatic model.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import Field, field_validator, model_validator

from sealsim.cases import CaseModel, Q

__all__ = ["LipForceTable", "LipSpec", "lip_force_table", "lip_load_paths",
           "lip_structure_case"]

from sealsim.units import ZERO_CELSIUS_K as CELSIUS_0
Temperature = Q("temperature", gt=200.0, lt=500.0)

DEFAULT_TEMPERATURES = tuple(CELSIUS_0 + t for t in (-20.0, 0.0, 20.0, 40.0, 60.0, 80.0, 100.0,
                                                     120.0, 140.0))
"""Temperature grid of the FE lip force table [K]: the service range of NBR lip seals."""


class LipSpec(CaseModel):
    """Where the lip force and contact width come from (``[lip]`` of a rotary case)."""

    force: Literal["constant", "fe"] = Field("constant", description=(
        "'constant': seal.radial_force with the spring share and E(T) (lip.py Eq. 1) and "
        "seal.contact_width; 'fe': both from an FE model of the DIN 3760 lip"))
    contact_width: Literal["constant", "fe"] = Field("constant", description=(
        "'constant': seal.contact_width (a run-in lip, as Organisciak et al. validate with); "
        "'fe': the FE contact width of the new lip. Default: 'fe' with force = 'fe', else "
        "'constant'"))
    temperatures: list[Temperature] = Field(
        default_factory=lambda: list(DEFAULT_TEMPERATURES), min_length=2, description=(
            "temperature grid of the FE table"))
    mesh: Literal["coarse", "medium", "fine"] = "coarse"
    interference: Q("length", gt=0.0, le=3e-3) | None = Field(None, description=(
        "radial interference of the moulded lip (default: the profile's)"))
    flex_thickness: Q("length", gt=0.0, le=5e-3) | None = None
    spring_rate: Q("stiffness", ge=0.0) | None = None
    spring_tension: Q("force", ge=0.0) | None = None

    @model_validator(mode="before")
    @classmethod
    def _width_follows_force(cls, data):
        # the FE contact width of the new lip (0.27 mm at 20 degC on 80 mm, mesh-converged,
        # widening as the rubber expands: docs, "Seal profiles") goes with the FE force unless
        # the case asks for the constant one
        if isinstance(data, dict) and data.get("contact_width") is None:
            data = {**data, "contact_width": "fe" if data.get("force") == "fe" else "constant"}
        return data

    @field_validator("temperatures")
    @classmethod
    def _ascending(cls, v):
        if any(b <= a for a, b in zip(v, v[1:])):
            raise ValueError("lip.temperatures must be strictly ascending")
        return v


def lip_structure_case(seal, lip: LipSpec, installation_temperature: float = 293.15,
                       temperatures=None, viscoelastic: bool = False, spring: bool = True):
    """The structure case (:class:`~sealsim.structure.case.StructureCase`) of a rotary case's
    seal: DIN 3760 radial lip on its shaft, mounted at ``installation_temperature``, held for
    :data:`~sealsim.properties.elastomers.HELD_SEAL_TIME`, then ``temperatures`` (default the
    lip table's) in the order given at 1 K/min.

    Parameters
    ----------
    seal : sealsim.rotary.case.Seal
        The rotary case's seal (shaft diameter, outer diameter, width, material).
    lip : LipSpec
        FE settings.
    installation_temperature : float
        Temperature at which the seal is mounted and its geometry holds [K].
    temperatures : list of float, optional
        The load path's temperatures [K].
    viscoelastic : bool
        Thermo-viscoelastic material (Prony/WLF) instead of the hyperelastic held modulus.
    spring : bool
        With the garter spring; False: the same lip without it (its rubber's own force).
    """
    from sealsim.cases import validate_case
    from sealsim.properties.elastomers import HELD_SEAL_TIME
    from sealsim.structure.case import StructureCase

    temperatures = list(lip.temperatures if temperatures is None else temperatures)
    temps = [installation_temperature, *temperatures]
    # about 10 K per increment (the lip head slides on its face: larger ones need cutbacks)
    increments = max(2, math.ceil(max(abs(b - a) for a, b in zip(temps, temps[1:])) / 10.0))
    section = {"type": "radial_lip", "outer_diameter": seal.outer_diameter,
               "width": seal.width}
    for key in ("interference", "flex_thickness", "spring_rate", "spring_tension"):
        if getattr(lip, key) is not None:
            section[key] = getattr(lip, key)
    if not spring:
        section.update(spring_rate=0.0, spring_tension=0.0)
    material = ({"elastomer": seal.material, "model": "viscoelastic"} if viscoelastic else
                {"elastomer": seal.material, "temperature_scaling": "held"})
    installation_time = 60.0
    data = {
        "title": f"DIN 3760 lip seal {seal.shaft_diameter * 1e3:g} x "
                 f"{seal.outer_diameter * 1e3:g} x {seal.width * 1e3:g}, {seal.material}",
        "seal": section,
        "gland": {"arrangement": "shaft", "sealing_diameter": seal.shaft_diameter},
        "material": material,
        "mesh": {"level": lip.mesh},
        "load": {"installation_temperature": installation_temperature,
                 "squeeze_increments": 8, "installation_time": installation_time,
                 "hold_time": HELD_SEAL_TIME - installation_time if viscoelastic else 0.0,
                 "temperature": temperatures, "temperature_increments": increments,
                 "temperature_rate": 1.0 / 60.0},
    }
    return validate_case(StructureCase, data, "the FE lip model of the rotary case",
                         require_units=False)


def lip_load_paths(seal, lip: LipSpec, mounting_temperature: float, spring: bool = True):
    """The FE load paths of a lip table: (structure case, its temperatures) per path -- down
    from the mounting temperature through the grid temperatures below it, up through the
    others; thermo-viscoelastic when the rubber has a Prony series, else hyperelastic with the
    held modulus (one path in grid order: its forces do not depend on the path). ``spring =
    False``: the same paths for the lip without its garter spring."""
    from sealsim.properties.elastomers import get_elastomer

    grid = list(lip.temperatures)
    if get_elastomer(seal.material).prony is None:
        return [(lip_structure_case(seal, lip, mounting_temperature, grid, spring=spring),
                 grid)]
    down = sorted((t for t in grid if t < mounting_temperature), reverse=True)
    up = sorted(t for t in grid if t >= mounting_temperature)
    return [(lip_structure_case(seal, lip, mounting_temperature, temps, viscoelastic=True,
                                spring=spring), temps) for temps in (down, up) if temps]


@dataclass(frozen=True)
class LipForceTable:
    """F_tip(T), b(T) and the spring share from the FE of a lip seal (SI units).

    Parameters
    ----------
    temperature : numpy.ndarray
        Grid [K], ascending.
    force : numpy.ndarray
        Radial lip force (360°) [N].
    contact_width : numpy.ndarray
        Contact width [m].
    spring_force : numpy.ndarray
        The garter spring's own radial force 2πT on its seat [N] (not all of it reaches the
        shaft: module docstring).
    p_max : numpy.ndarray
        Peak contact pressure [Pa].
    force_without_spring : numpy.ndarray
        Radial lip force of the same lip on the same load path without its spring [N].

    Examples
    --------
    >>> t = LipForceTable(np.array([293.15, 373.15]), np.array([30.0, 25.0]),
    ...                   np.array([2e-4, 1.8e-4]), np.array([15.0, 15.2]), np.array([1e6, 8e5]),
    ...                   np.array([12.0, 8.0]))
    >>> round(float(t.force_at(333.15)), 3), round(float(t.force_at(400.0)), 3)
    (27.5, 25.0)
    >>> t.spring_share().round(3).tolist()
    [0.6, 0.68]
    """

    temperature: np.ndarray
    force: np.ndarray
    contact_width: np.ndarray
    spring_force: np.ndarray
    p_max: np.ndarray
    force_without_spring: np.ndarray

    def _interp(self, values, temperature):
        from scipy.interpolate import PchipInterpolator

        t = np.clip(np.asarray(temperature, dtype=float), self.temperature[0],
                    self.temperature[-1])
        return PchipInterpolator(self.temperature, values)(t)

    def force_at(self, temperature):
        """F_tip [N] at T [K] (held at the end values outside the grid)."""
        return self._interp(self.force, temperature)

    def contact_width_at(self, temperature):
        """b [m] at T [K] (held at the end values outside the grid)."""
        return self._interp(self.contact_width, temperature)

    def spring_share(self):
        """Spring share of the lip force at each grid temperature [-]: 1 − F_without/F, the
        share a split-shaft measurement with and without the spring gives (the rubber's share
        is F_without/F)."""
        return 1.0 - self.force_without_spring / self.force

    def frame(self):
        """pandas DataFrame in engineering units (``lip_fe.csv``)."""
        import pandas as pd

        return pd.DataFrame({
            "temperature_C": self.temperature - CELSIUS_0, "F_tip_N": self.force,
            "F_tip_per_length_N_per_mm": self.force / (np.pi * self._diameter) / 1e3
            if self._diameter else np.nan,
            "contact_width_mm": self.contact_width * 1e3,
            "F_without_spring_N": self.force_without_spring, "F_spring_N": self.spring_force,
            "spring_share": self.spring_share(), "p_max_MPa": self.p_max / 1e6})

    _diameter: float = 0.0


def _cache_dir() -> Path:
    root = os.environ.get("SEALSIM_CACHE")
    if root:
        return Path(root) / "lip_fe"
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "sealsim" / "lip_fe"


def lip_force_table(seal, lip: LipSpec, installation_temperature: float = 293.15, *,
                    cache: bool = True) -> LipForceTable:
    """Run (or read from the cache) the FE lip force table of a rotary case's seal.

    Parameters
    ----------
    seal : sealsim.rotary.case.Seal
        The seal (shaft diameter, outer diameter, width, material).
    lip : LipSpec
        FE settings (temperature grid, mesh, optional geometry and spring overrides).
    installation_temperature : float
        Mounting temperature T_m [K] (``seal.mounting_temperature``).
    cache : bool
        Read and write the cache (``$SEALSIM_CACHE/lip_fe``).

    Returns
    -------
    LipForceTable
    """
    import pandas as pd

    from sealsim.files import atomic_write_bytes
    from sealsim.structure.fingerprint import results_key

    # the lip with its spring, and without it for the rubber's share (module docstring)
    paths = {spring: lip_load_paths(seal, lip, installation_temperature, spring=spring)
             for spring in (True, False)}
    # the key of FE results: the resolved cases, the FE model's fingerprint (a changed FE
    # model must not read an old table) and the content of a compound file the seal is made
    # of (every load path is made of the seal's one material)
    cases = [case for spring in (True, False) for case, _ in paths[spring]]
    digest = results_key(cases[0], [case.model_dump(mode="json") for case in cases[1:]])[:16]
    target = _cache_dir() / f"lip-{digest}.csv"
    if cache and target.is_file():
        frame = pd.read_csv(target)
    else:
        from sealsim.structure.run import run_case

        def states(spring):
            # the last states are the grid temperatures in the path's order (installation
            # and hold come first)
            return [state for case, temps in paths[spring]
                    for state in run_case(case).states[-len(temps):]]

        frame = pd.DataFrame([
            {"temperature_K": state.temperature, "force_N": state.F_N,
             "contact_width_m": state.b, "spring_force_N": state.spring_force,
             "p_max_Pa": state.p_max, "force_without_spring_N": bare.F_N}
            for state, bare in zip(states(True), states(False))
        ]).sort_values("temperature_K", ignore_index=True)
        if cache:
            target.parent.mkdir(parents=True, exist_ok=True)
            atomic_write_bytes(target, frame.to_csv(index=False).encode("utf-8"))
    return LipForceTable(frame["temperature_K"].to_numpy(), frame["force_N"].to_numpy(),
                         frame["contact_width_m"].to_numpy(),
                         frame["spring_force_N"].to_numpy(), frame["p_max_Pa"].to_numpy(),
                         frame["force_without_spring_N"].to_numpy(),
                         _diameter=float(seal.shaft_diameter))
