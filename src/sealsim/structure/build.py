"""Building blocks of a structure case: section, assembly, material, mesh, model, load path.

:mod:`.run` (one load path, result folders) and :mod:`.mapping` (characteristic maps) both
compose these functions; neither imports the other.
"""

from __future__ import annotations

import math
import warnings

from sealsim.errors import InputError
from sealsim.structure.case import CUSTOM_THERMAL_EXPANSION, StructureCase
from sealsim.structure.geometry import Gland, ORing, SealAssembly
from sealsim.structure.material import (
    HyperelasticSealMaterial,
    material_from_elastomer,
    thermal_volume_ratio,
)
from sealsim.structure.profile_mesh import mesh_section
from sealsim.structure.model import GarterSpringSpec, SealModel
from sealsim.structure.solver import LoadStep
from sealsim.units import ZERO_CELSIUS_K

__all__ = [
    "RollingSpringWarning",
    "build_assembly",
    "build_material",
    "build_model",
    "build_section",
    "check_loads",
    "check_rubbery",
    "check_temperatures",
    "describe_seal",
    "garter_spring",
    "installation_squeeze",
    "load_steps",
]

#: Temperature range [K] of a custom material (no catalogue entry to take it from).
CUSTOM_TEMPERATURE_RANGE = (173.15, 573.15)


class RollingSpringWarning(UserWarning):
    """The anti-rolling spring is on: it replaces the gland's friction (moment reported)."""


def build_section(case: StructureCase):
    """The free seal section of a case: an :class:`ORing` or a
    :class:`~.profiles.SealProfile`."""
    from sealsim.structure import profiles as pf

    s, g = case.seal, case.gland
    if s.type == "oring":
        return ORing(s.cord_diameter, s.inner_diameter)
    if s.type == "xring":
        kw = {k: getattr(s, k) for k in ("lobe_radius", "valley_depth") if getattr(s, k)}
        return pf.xring_profile(s.cord_diameter, s.inner_diameter, **kw)
    if s.type == "rectangular":
        return pf.rectangular_profile(s.width, s.height, s.inner_diameter,
                                      corner_radius=s.corner_radius)
    if s.type in ("ucup", "wiper"):
        names = ("lip_thickness", "groove_depth", "flare", "edge_radius")
        kw = {k: getattr(s, k) for k in names if getattr(s, k, None) is not None}
        build = pf.ucup_profile if s.type == "ucup" else pf.wiper_profile
        return build(g.arrangement, s.lip_diameter, s.height, s.width, **kw)
    if s.type == "radial_lip":
        names = ("interference", "flex_thickness", "spring_coil_diameter", "spring_offset",
                 "oil_side_angle", "air_side_angle", "flex_angle", "edge_radius")
        kw = {k: getattr(s, k) for k in names if getattr(s, k) is not None}
        return pf.radial_lip_profile(g.sealing_diameter, s.outer_diameter, s.width, **kw)
    unit = s.unit_factor()
    points = [(z * unit, r * unit) for z, r in s.points]
    return pf.user_profile(points, bulges=s.bulges, tags=s.tags, name="seal")


def build_assembly(case: StructureCase) -> SealAssembly:
    """Seal and gland of a case (InputError for impossible geometry)."""
    section = build_section(case)
    g = case.gland
    width = g.groove_width if g.groove_width is not None else section.axial_extent
    edge = {} if g.land_edge_radius is None else {"land_edge_radius": g.land_edge_radius}
    gland = Gland(g.arrangement, g.sealing_diameter, width, clearance=g.clearance, **edge)
    assembly = SealAssembly(section, gland, g.inner_expansion, g.outer_expansion,
                            case.load.installation_temperature, walls=g.walls)
    _check_placement(assembly)
    return assembly


def _check_placement(a: SealAssembly) -> None:
    h = a.seal.radial_extent
    rs = a.gland.sealing_radius
    r_free = a.free_sealing_side_radius
    # the free section must sit roughly on the sealing surface (stretch/compression < 15 %)
    strain = (rs - r_free) / r_free
    if abs(strain) > 0.15:
        kind = "inner" if a.gland.side < 0 else "outer"
        raise InputError(
            f"seal: the free section's {kind} diameter {2 * r_free * 1e3:g} mm would be "
            f"{'stretched' if strain > 0 else 'compressed'} by {abs(strain) * 100:.0f} % onto "
            f"the sealing diameter {2 * rs * 1e3:g} mm; allowed is up to 15 %")
    if a.gland.side > 0 and rs - h <= 0:
        raise InputError("gland.sealing_diameter: the bore is too small for the seal section")
    g = a.gland
    if g.clearance is not None and g.clearance + g.land_edge_radius >= 0.5 * h:
        raise InputError(
            f"gland.clearance: {g.clearance * 1e3:g} mm (plus the land edge radius "
            f"{g.land_edge_radius * 1e3:g} mm) must be less than half the seal's radial height "
            f"{h * 1e3:g} mm: the groove walls would be too short to hold it")


def installation_squeeze(case: StructureCase, assembly: SealAssembly | None = None) -> float:
    """The squeeze at the end of the installation: the first ``load.squeeze``, or for a shaft
    seal its interference over its free radial height."""
    if case.gland.arrangement == "shaft":
        assembly = assembly or build_assembly(case)
        return assembly.shaft_squeeze
    return case.load.squeeze[0]


def build_material(case: StructureCase, *, equilibrium: bool = False):
    """Seal material of a case; ``equilibrium`` gives the relaxed hyperelastic variant."""
    from sealsim.properties.elastomers import get_elastomer

    spec = case.material
    t0 = case.load.installation_temperature
    if spec.custom:
        tc = spec.constants_temperature or t0
        alpha = spec.thermal_expansion
        alpha = CUSTOM_THERMAL_EXPANSION if alpha is None else alpha
        if spec.temperature_scaling == "entropic":
            c10, c01 = spec.c10, spec.c01

            def c10_t(T):
                return c10 * T / tc

            def c01_t(T):
                return c01 * T / tc
            return HyperelasticSealMaterial(c10_t, c01_t, spec.bulk_modulus, alpha, t0,
                                            name="custom Mooney-Rivlin")
        return HyperelasticSealMaterial(spec.c10, spec.c01, spec.bulk_modulus, alpha, t0,
                                        name="custom Mooney-Rivlin")
    elastomer = get_elastomer(spec.elastomer)
    overrides = {k: getattr(spec, k) for k in ("c10", "c01", "bulk_modulus", "thermal_expansion")
                 if getattr(spec, k) is not None}
    if spec.hardness_shore_a is not None:
        overrides.update(_hardness_scaled(elastomer, spec))
    if overrides:
        import dataclasses

        try:
            elastomer = dataclasses.replace(elastomer, **overrides)
        except InputError as exc:
            raise InputError(f"material: {exc}") from None
    material = material_from_elastomer(elastomer, spec.model, reference_temperature=t0,
                                       temperature_scaling=spec.temperature_scaling,
                                       frequency=spec.modulus_frequency)
    if equilibrium:
        material = material.equilibrium()
    return material


def _hardness_scaled(elastomer, spec) -> dict:
    """Constants of a compound of another Shore A hardness: the catalogue's C10, C01 (and
    Prony moduli) times E(S)/E(S_catalogue) of Gent's relation."""
    from sealsim.properties.elastomers import shore_a_young_modulus

    if spec.c10 is not None or spec.c01 is not None:
        raise InputError("material: give either hardness_shore_a or c10/c01, not both "
                         "(the hardness scales the catalogue constants)")
    if elastomer.hardness_shore_a is None:
        raise InputError(f"material.hardness_shore_a: {elastomer.name} has no catalogue "
                         "hardness to scale from; give c10 and c01 instead")
    scale = shore_a_young_modulus(spec.hardness_shore_a) / \
        shore_a_young_modulus(elastomer.hardness_shore_a)
    scaled = {"c10": elastomer.c10 * scale, "c01": elastomer.c01 * scale,
              "hardness_shore_a": spec.hardness_shore_a}
    if elastomer.prony is not None:
        e_inf, e_i, tau_i = elastomer.prony
        scaled["prony"] = (e_inf * scale, tuple(e * scale for e in e_i), tau_i)
    return scaled


def describe_seal(case: StructureCase) -> str:
    """A short title of the seal, e.g. '4 mm O-ring, rod seal, NBR'."""
    s = case.seal
    names = {"oring": "O-ring", "xring": "X-ring", "rectangular": "rectangular ring",
             "ucup": "U-cup", "wiper": "wiper", "radial_lip": "radial lip seal",
             "user": "seal profile"}
    size = s.cord_diameter or s.height or s.width
    material = case.material.elastomer or "custom rubber"
    if material.lower().endswith(".toml"):
        from sealsim.properties.elastomers import get_elastomer

        material = get_elastomer(material).name
    where = "shaft seal" if case.gland.arrangement == "shaft" else \
        f"{case.gland.arrangement} seal"
    lead = f"{size * 1e3:g} mm {names[s.type]}" if size else names[s.type]
    return f"{lead}, {where}, {material}"


def check_temperatures(case: StructureCase, temperatures) -> None:
    """InputError for temperatures the material cannot be evaluated at."""
    from sealsim.properties.elastomers import get_elastomer

    if case.material.custom:
        name, (lo, hi) = "the custom material", CUSTOM_TEMPERATURE_RANGE
    else:
        e = get_elastomer(case.material.elastomer)
        name, (lo, hi) = e.name, e.allowed_range
    for t in temperatures:
        if not lo <= t <= hi:
            raise InputError(
                f"temperature {t - ZERO_CELSIUS_K:g} degC is outside the range of {name}: "
                f"{lo - ZERO_CELSIUS_K:g} ... {hi - ZERO_CELSIUS_K:g} degC")


def check_rubbery(case: StructureCase, temperatures) -> None:
    """InputError for temperatures within GLASS_TRANSITION_MARGIN of the catalogue rubber's
    T_g, where a rubbery (hyperelastic or relaxed) material does not describe the seal."""
    from sealsim.properties.elastomers import (
        GLASS_TRANSITION_MARGIN,
        get_elastomer,
        rubbery_limit_message,
    )

    if case.material.custom:
        return
    e = get_elastomer(case.material.elastomer)
    cold = [t for t in temperatures if t < e.glass_transition + GLASS_TRANSITION_MARGIN - 1e-9]
    if cold:
        raise InputError("map.temperature: " + rubbery_limit_message(
            "a characteristic map (relaxed material)", min(cold), e))


def garter_spring(case: StructureCase, assembly: SealAssembly) -> GarterSpringSpec | None:
    """The garter spring of a radial lip seal (defaults from the coil size and the shaft
    diameter, :mod:`.profiles`); None for other seals."""
    from sealsim.structure import profiles as pf

    s = case.seal
    if s.type != "radial_lip" and s.spring_rate is None and s.spring_tension is None:
        return None
    seal = assembly.seal
    if seal.spring_radius is None and s.type != "user":
        return None
    if s.type == "user" and "spring" not in seal.contour.tags:
        raise InputError("seal.spring_rate/spring_tension need a spring seat: tag the seat "
                         "segments 'spring'")
    d = case.gland.sealing_diameter
    rate = s.spring_rate
    if rate is None:
        h = 0.5 * ((s.outer_diameter or d) - d)
        coil = s.spring_coil_diameter or 0.16 * h
        radius = seal.spring_radius or seal.inner_radius
        rate = pf.garter_spring_rate(coil, 0.25 * coil, 2 * math.pi * radius)
    tension = s.spring_tension
    if tension is None:
        tension = pf.SPRING_TENSION_PER_DIAMETER * d
    return GarterSpringSpec(rate, tension)


def check_loads(case: StructureCase, assembly: SealAssembly, material, squeezes,
                temperatures=(), field: str = "load.squeeze") -> None:
    """InputError unless every squeeze is in range and the seal, thermally expanded at every
    temperature [K] (default: the installation temperature), fits its gland at every squeeze."""
    temps = list(temperatures) or [case.load.installation_temperature]
    check_temperatures(case, temps)
    j = max(thermal_volume_ratio(t, case.load.installation_temperature,
                                 material.thermal_expansion) for t in temps)
    for s in squeezes:
        assembly.check_squeeze(s, field)
        assembly.check_fill(s, j)


def build_model(case: StructureCase, install_squeeze: float | None = None, *, material=None,
                squeezes=(), temperatures=()) -> SealModel:
    """Assembly, mesh and FE model for a case (geometry checks for the given loads)."""
    assembly = build_assembly(case)
    if install_squeeze is None:
        install_squeeze = installation_squeeze(case, assembly)
    assembly.check_squeeze(install_squeeze, "load.squeeze")
    if material is None:
        material = build_material(case)
    check_loads(case, assembly, material, [install_squeeze, *squeezes], temperatures)
    m = case.mesh
    if isinstance(assembly.seal, ORing):
        kwargs = {k: getattr(m, k) for k in ("n_arc", "n_wall", "n_radial") if getattr(m, k)}
    else:
        kwargs = {"size_contact": m.size_contact, "size_body": m.size_body,
                  "backend": m.backend}
    mesh = mesh_section(assembly.seal, assembly.centre, m.level, **kwargs)
    sv, g = case.solver, case.gland
    wall = g.friction if g.wall_friction is None else g.wall_friction
    friction = {"sealing_surface": g.sealing_friction, "groove_bottom": g.friction,
                "wall_upstream": wall, "wall_downstream": wall}
    if sv.rolling_stiffness > 0 and case.gland.arrangement != "shaft":
        warnings.warn(
            "the anti-rolling spring is on (solver.rolling_stiffness > 0): it holds the "
            "section instead of the gland friction; its moment is reported as "
            "rolling_moment_Nm", RollingSpringWarning, stacklevel=2)
    scale = getattr(assembly.seal, "contact_scale", assembly.seal.radial_extent)
    return SealModel(assembly, mesh, material, installation_squeeze=install_squeeze,
                     penalty=sv.penalty, positioning_pressure=sv.positioning_pressure,
                     rolling_stiffness=sv.rolling_stiffness, friction=friction,
                     elastic_slip=sv.elastic_slip * scale,
                     spring=garter_spring(case, assembly))


def load_steps(case: StructureCase) -> list[LoadStep]:
    """The load path of a case: installation, squeeze, pressure, temperature steps."""
    ld = case.load
    rec = "all" if ld.record_increments else "end"
    squeezes = ld.squeeze if ld.squeeze is not None else [installation_squeeze(case)]
    steps = [LoadStep("installation", squeeze=squeezes[0], increments=ld.squeeze_increments,
                      duration=ld.installation_time, record=rec)]
    if ld.hold_time > 0:
        steps.append(LoadStep("hold", duration=ld.hold_time, increments=2, record=rec))
    for s in squeezes[1:]:
        steps.append(LoadStep("squeeze", squeeze=s, increments=ld.squeeze_increments,
                              duration=ld.installation_time, record=rec))
    for p in ld.pressure:
        steps.append(LoadStep("pressure", pressure=p, increments=ld.pressure_increments,
                              duration=ld.pressure_time, record=rec))
    previous = ld.installation_temperature
    for t in ld.temperature:
        steps.append(LoadStep("temperature", temperature=t,
                              increments=ld.temperature_increments,
                              duration=abs(t - previous) / ld.temperature_rate,
                              record="all" if ld.record_increments else "end"))
        previous = t
    return steps
