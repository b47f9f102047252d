"""Build sealsim FMUs from Python or from case files (what ``sealsim fmu build`` calls).

* :func:`build_friction_fmu` -- a friction law object (any of :data:`C_LAWS`) with a contact
  map or a constant contact;
* :func:`build_cylinder_fmu` -- a whole pneumatic cylinder (chambers, valve, seals, end
  stops) from its case;
* :func:`build_rotary_fmu` -- a rotary lip-seal case;
* :func:`build_fmu` -- a case file: a friction case, a pneumatic case (the whole cylinder, or
  one seal with ``seal``), a rotary case, or an FMU case (:mod:`sealsim.fmu.case`).

Each checks the output file first, builds in a temporary folder, checks the compiled FMU
against sealsim's own model, writes the ``.fmu`` atomically and returns a
:class:`~sealsim.fmu.builder.BuildResult`.  Default: FMI 2.0 with model exchange and
co-simulation in one FMU.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np

from sealsim.cases import (
    DEFAULT_VARIANT,
    detect_case_kind,
    expand_variants,
    load_toml,
    one_variant_used,
    validate_case,
)
from sealsim.errors import InputError
from sealsim.fmu.builder import FMI_KINDS, BuildResult, build_archive, check_output
from sealsim.fmu.case import (
    ContactSettings,
    FMUCase,
    FrictionTable,
    RotarySettings,
    TableSettings,
)
from sealsim.fmu.friction_export import (
    c_parameters,
    contact_table,
    friction_check,
    friction_spec,
    model_identifier,
    steady_table,
)
from sealsim.fmu.model_description import xml_text_problem
from sealsim.units import format_quantity

__all__ = ["build_cylinder_fmu", "build_fmu", "build_friction_fmu", "build_rotary_fmu"]

RPM = math.pi / 30.0


def _identifier(name: str | None, out) -> str:
    return name or model_identifier(str(out))


def build_friction_fmu(law, out, *, contact_map=None, normal_force: float | None = None,
                       contact_width: float | None = None,
                       seal_temperature: float | None = None,
                       sliding_diameter: float | None = None, velocity_direction: float = 1.0,
                       name: str | None = None, fmi_version: int = 2, kind: str = "both",
                       force: bool = False, compile: bool = True,
                       table: TableSettings | None = None, title: str = "", source: str = "",
                       inputs=()) -> BuildResult:
    """Build the FMU of a seal friction law.

    Parameters
    ----------
    law : FrictionLaw
        A law of :data:`~sealsim.fmu.friction_export.C_LAWS` (e.g.
        ``Theta.from_parameter_set("pneumatic_demo")``).
    out : path
        The ``.fmu`` file.
    contact_map : ContactMap, optional
        F_N, b (Δp, T) of the seal (FE or analytic, :mod:`sealsim.pneumatic.contact_maps`),
        embedded as a table.
    normal_force, contact_width : float, optional
        A constant contact [N], [m] instead of a map.
    seal_temperature : float, optional
        Start value of the input T_seal [K] (default: the law's reference temperature, where
        the Θ law's γ is γ_ref; else 293.15 K).
    sliding_diameter : float, optional
        Diameter of the sliding surface [m] of a Θ law with ``steady = "contact"`` (its
        friction table is per unit circumference); default the contact map's.
    velocity_direction : {1, -1}
        Θ law with ``steady = "contact"``: +1 if a positive v slides the counter surface from
        side A to side B of the seal (a rod seal, A the chamber), −1 the other way (a piston
        seal, A the cap-end chamber); the FMU's start value of ``velocity_direction``.
    name : str, optional
        Model identifier (default: from the file name).
    fmi_version : {2, 3}
    kind : {"me", "cs", "both"}
    force : bool
        Replace an existing file.
    compile : bool
        False: write a source-only FMU.
    table : TableSettings, optional
        Grid of a tabulated analytic map.
    title, source : str
        Shown in the FMU's description and documentation.
    inputs : iterable of path
        Files the FMU is built from (the output must not be one of them).
    """
    from sealsim.fmu.report import friction_documentation

    _check_request(out, force, inputs, title, source, kind)
    table_settings = table or TableSettings()
    c_parameters(law)                         # a law without C code: refused before work
    steady = steady_table(law, contact_map, sliding_diameter, velocity_direction)
    tab = None
    if contact_map is not None:
        tab = contact_table(contact_map, table_settings.temperature_points,
                            table_settings.pressure_points)
    spec = friction_spec(law, _identifier(name, out), table=tab, normal_force=normal_force,
                         contact_width=contact_width, seal_temperature=seal_temperature,
                         steady=steady, title=title, source=source)
    return build_archive(spec, out, fmi_version=fmi_version, kind=kind, force=force,
                         compile=compile,
                         check=friction_check(law, spec, contact_map, tab, FMI_KINDS[kind],
                                              steady),
                         document=lambda s: friction_documentation(s, law, tab, steady))


def build_cylinder_fmu(case, out, *, name: str | None = None, fmi_version: int = 2,
                       kind: str = "both", force: bool = False, compile: bool = True,
                       base_dir: str | Path = ".", title: str = "", source: str = "",
                       inputs=()) -> BuildResult:
    """Build the FMU of a whole pneumatic cylinder (:mod:`sealsim.fmu.cylinder_export`).

    Parameters
    ----------
    case : PneumaticCase
        The case (one variant); its seals' contact maps are built or read first.
    out : path
        The ``.fmu`` file.
    base_dir : path
        Folder that relative map paths of the case refer to.
    name, fmi_version, kind, force, compile, title, source, inputs
        As for :func:`build_friction_fmu`.
    """
    from sealsim.fmu.cylinder_export import cylinder_check, cylinder_spec, cylinder_system
    from sealsim.fmu.report import cylinder_documentation

    _check_request(out, force, inputs, title or case.title, source, kind)
    system = cylinder_system(case, base_dir)
    spec = cylinder_spec(system, _identifier(name, out), title=title or case.title,
                         source=source)
    return build_archive(spec, out, fmi_version=fmi_version, kind=kind, force=force,
                         compile=compile, check=cylinder_check(system, spec, FMI_KINDS[kind]),
                         document=cylinder_documentation)


def _check_request(out, force, inputs, title: str, source: str, kind: str) -> None:
    """Before any computing: the target may be written, the title fits the FMU's
    modelDescription.xml and ``kind`` is one of FMI_KINDS; else an InputError naming the field."""
    check_output(out, force, inputs)
    problem = xml_text_problem(title)
    if problem:
        raise InputError(f"title{f' ({source})' if source else ''}: {problem}")
    if kind not in FMI_KINDS:
        raise InputError(f"--kind {kind!r} is not allowed; choose me, cs or both")


def _default_speed_max(case, base_dir) -> float:
    top = 3000.0 * RPM
    if case.duty is not None:
        _, speeds, _ = case.duty.profile(base_dir)
        top = max(top, 1.2 * float(np.max(speeds)))
    return top


def _default_sumps(case) -> np.ndarray:
    env = case.environment
    sump0 = env.sump_temperature if env.sump_temperature is not None else (
        env.start_temperature if env.start_temperature is not None else env.ambient_temperature)
    lo, hi = min(293.15, sump0 - 5.0), max(393.15, sump0 + 40.0)
    oil_min = case.oil.build().min_temperature
    if oil_min is not None:
        lo = max(lo, oil_min)
    return np.linspace(lo, hi, 6)


def build_rotary_fmu(case, out, *, settings: RotarySettings | None = None,
                     name: str | None = None, fmi_version: int = 2, kind: str = "both",
                     force: bool = False, compile: bool = True, base_dir: Path | None = None,
                     title: str = "", source: str = "", inputs=(),
                     progress=None) -> BuildResult:
    """Build the FMU of a rotary lip seal from its case (maps computed now, seconds).

    Parameters
    ----------
    case : RotaryCase
        Seal, oil, environment; its duty cycle sets the default speed range and is the
        transient the FMU is checked against.
    out : path
        The ``.fmu`` file.
    settings : RotarySettings, optional
        Grids, lag order and checks (defaults: see :class:`~sealsim.fmu.case.RotarySettings`).
    base_dir : Path, optional
        Folder of a duty-cycle CSV given by a relative path.
    progress : callable, optional
        ``progress(task, done, total)``.
    name, fmi_version, kind, force, compile, title, source, inputs
        As for :func:`build_friction_fmu`.
    """
    from sealsim.fmu.report import rotary_documentation
    from sealsim.fmu.rotary_export import rotary_check, rotary_maps, rotary_spec

    _check_request(out, force, inputs, title or case.title, source, kind)
    s = settings or RotarySettings()
    speed_max = s.max_speed if s.max_speed is not None else _default_speed_max(case, base_dir)
    sumps = (np.asarray(s.sump_temperatures, float) if s.sump_temperatures is not None
             else _default_sumps(case))
    maps = rotary_maps(case, speed_max=speed_max, speed_points=s.speed_points,
                       sump_temperatures=np.sort(sumps), torque_speed_min=s.torque_speed_min,
                       lag_order=s.lag_order, lag_points=s.lag_points,
                       lag_sump_temperatures=s.lag_sump_temperatures,
                       lag_duration=s.lag_duration,
                       ambient_step=s.ambient_step if s.ambient_input else None,
                       ambient_range=s.ambient_range, torque_points=tuple(s.torque_points),
                       progress=progress)
    spec = rotary_spec(case, maps, _identifier(name, out), title=title or case.title,
                       source=source)
    if not s.ambient_input:
        spec.variables = [v if v.name != "T_ambient" else _hide(v) for v in spec.variables]
    check = rotary_check(case, maps, spec, between=s.check_between,
                         duty_cycle=s.check_duty_cycle, base_dir=base_dir)
    return build_archive(spec, out, fmi_version=fmi_version, kind=kind, force=force,
                         compile=compile, check=check,
                         document=lambda sp: rotary_documentation(sp, maps))


def _hide(variable):
    from dataclasses import replace

    return replace(variable, exposed=False)


# -- case files ---------------------------------------------------------------------------------
def _case_kind(data: dict, source: str) -> str:
    """"friction", "pneumatic", "rotary" or "fmu": the kind of a case file
    (:func:`sealsim.cases.detect_case_kind`) that an FMU is built from."""
    kind = detect_case_kind(data)
    if kind is not None and kind.name in ("friction", "pneumatic", "rotary", "fmu"):
        return kind.name
    found = f" (it looks like a {kind.name} case)" if kind is not None else ""
    raise InputError(f"{source} is neither a friction case ([bench], [inputs]), a pneumatic case "
                     "([cylinder], [[seals]]), a rotary case ([seal] with [environment], [oil] "
                     f"or [duty]) nor an FMU case ([fmu]){found}; see examples/fmu/")


def _model_name(title: str, path: Path, variant: str, chosen: bool) -> str:
    """The FMU's model name: the case's title (else its file name) with the variant exported
    when the case has named variants and one was chosen -- a case's title usually describes
    all its variants ("seals at 25 vs 55 degC") while the FMU holds one."""
    if not chosen:
        return title
    return f"{title or path.stem} (variant {variant})"


def _one_variant(cases: dict, variant: str | None, source: str, same=None,
                 notes: list | None = None, but: str = ""):
    """The variant to export: the one asked for, the only one, or the first when all agree
    (which ``notes`` then says, with ``but``: what differs all the same)."""
    if variant is not None:
        if variant not in cases:
            raise InputError(f"{source}: variant {variant!r} does not exist; choose one of "
                             f"{', '.join(cases)}")
        return variant, cases[variant]
    name = next(iter(cases))
    if len(cases) == 1:
        return name, cases[name]
    if same is not None and len({same(c) for c in cases.values()}) == 1:
        if notes is not None:
            notes.append(f"{source} has the variants {', '.join(cases)}; they give the same "
                         f"FMU{but}: built from the first, {name!r} (--variant chooses "
                         "another)")
        return name, cases[name]
    raise InputError(f"{source} has the variants {', '.join(cases)}; choose one with "
                     "--variant (or fmu.variant)")


def _named(seals, name: str):
    return next((s for s in seals if s.name == name), None)


def _seal_identity(case, seal: str) -> str:
    """What a seal FMU of ``seal`` takes from a pneumatic case (its start temperature aside):
    the seal's table and the diameter its map is evaluated at."""
    spec = _named(case.seals, seal)
    diameter = case.cylinder.bore if spec is not None and spec.location == "piston" \
        else case.cylinder.rod_diameter
    return repr((spec, diameter))


def _seal_temperature(case, spec) -> float:
    """Start value of a seal FMU's input T_seal [K]: the seal's, the cylinder's seal
    temperature or the body's."""
    from sealsim.pneumatic.case import body_temperature

    for temperature in (spec and spec.temperature, case.cylinder.seal_temperature):
        if temperature is not None:
            return temperature
    return body_temperature(case)


def _law(params):
    from sealsim.friction import make_law

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # LuGre passivity: documented in the law
        return make_law(params)


def build_fmu(path, out, *, fmi_version: int = 2, kind: str = "both", force: bool = False,
              variant: str | None = None, seal: str | None = None, compile: bool = True,
              progress=None) -> BuildResult:
    """Build the FMU of a case file.

    Parameters
    ----------
    path : path
        A friction case (``[friction]`` + ``[bench]``: the law with the constant contact of
        its ``[inputs]``), a pneumatic case (the whole cylinder, or with ``seal`` the law and
        contact map of that seal), a rotary
        case (the lip-seal FMU), or an FMU case (``[fmu]``, see :mod:`sealsim.fmu.case`).
    out : path
        The ``.fmu`` file; refused if it exists, unless ``force``.
    fmi_version : {2, 3}
    kind : {"me", "cs", "both"}
    variant, seal : str, optional
        Which variant of the case, which seal of a pneumatic case (also ``fmu.variant``,
        ``fmu.seal`` of an FMU case; without a seal: the whole cylinder).
    compile : bool
        False: a source-only FMU.
    progress : callable, optional
        ``progress(task, done, total)``.

    Returns
    -------
    BuildResult
        Its ``report["source"]`` names the case file and the variant built from; when no
        variant was chosen and all variants give the same FMU, ``report["notes"]`` says so.
    """
    notes: list[str] = []
    with one_variant_used():          # one variant is exported, not all of them run
        result = _build_case_fmu(Path(path), out, fmi_version, kind, force, variant, seal,
                                 compile, progress, notes)
    result.report.setdefault("notes", []).extend(notes)
    return result


def _build_case_fmu(path: Path, out, fmi_version, kind, force, variant, seal, compile,
                    progress, notes: list) -> BuildResult:
    """:func:`build_fmu`; ``notes`` receives what the caller should be told."""
    check_output(out, force, [path])
    source = f"case file {str(path)!r}"
    data = load_toml(path)
    kind_of = _case_kind(data, source)
    fmu_case = None
    inputs = [path]
    law_override = None
    if kind_of == "fmu":
        fmu_case = validate_case(FMUCase, data, source)
        settings = fmu_case.fmu
        variant = variant or settings.variant
        seal = seal or settings.seal
        if settings.friction_file is not None:
            fitted = path.parent / settings.friction_file
            law_override = validate_case(FrictionTable, load_toml(fitted, "friction file"),
                                         f"friction file {str(fitted)!r}").friction
            inputs.append(fitted)
        elif fmu_case.friction is not None:
            law_override = fmu_case.friction
        if settings.source is None:
            return _inline_friction(fmu_case, law_override, path, out, fmi_version, kind,
                                    force, compile, inputs)
        source_path = path.parent / settings.source
        inputs.append(source_path)
        source = f"case file {str(source_path)!r}"
        data = load_toml(source_path, "fmu.source case file")
        kind_of = _case_kind(data, source)
        if kind_of == "fmu":
            raise InputError(f"fmu.source: {str(source_path)!r} is an FMU case itself; give a "
                             "friction, pneumatic or rotary case")
        base = source_path.parent
    else:
        base = path.parent
    case_path = source_path if fmu_case is not None else path

    def chosen(cases) -> bool:
        """A variant of several (asked for, or the only named one) goes into the name; not
        when no variant was asked for because all variants give the same FMU."""
        return (variant is not None and len(cases) > 1) or (
            len(cases) == 1 and DEFAULT_VARIANT not in cases)

    common = dict(name=fmu_case.fmu.name if fmu_case else None, fmi_version=fmi_version,
                  kind=kind, force=force, compile=compile, inputs=inputs)
    title = fmu_case.title if fmu_case and fmu_case.title else ""
    if kind_of == "rotary":
        from sealsim.rotary.case import RotaryCase

        if law_override is not None:
            raise InputError("[friction] and fmu.friction_file apply to seal friction FMUs, "
                             "not to a rotary case")
        cases = expand_variants(RotaryCase, data, source)
        name, case = _one_variant(cases, variant, source)
        return build_rotary_fmu(case, out, settings=fmu_case.rotary if fmu_case else None,
                                base_dir=base,
                                title=title or _model_name(case.title, case_path, name,
                                                           chosen(cases)),
                                source=f"{source}, variant {name!r}", progress=progress,
                                **common)
    table = fmu_case.table if fmu_case else None
    if kind_of == "friction":
        from sealsim.friction.case import load_friction_cases

        cases = load_friction_cases(data, source)
        name, case = _one_variant(cases, variant, source,
                                  same=lambda c: repr((c.friction, c.inputs, c.seal)), notes=notes)
        title = title or _model_name(case.title, case_path, name, chosen(cases))
        params = law_override or case.friction
        i = case.inputs
        if case.seal is not None:                      # a real seal: its contact map
            from sealsim.pneumatic.bench import bench_contact_map

            side = 1.0 if i.pressure_a >= i.pressure_b else -1.0
            away = case.seal.positive_velocity == "away_from_pressure"
            return build_friction_fmu(
                _law(params), out, contact_map=bench_contact_map(case, base, progress),
                seal_temperature=i.temperature, sliding_diameter=case.seal.sliding_diameter,
                velocity_direction=side if away else -side, table=table,
                title=title, source=f"{source}, variant {name!r}", **common)
        return build_friction_fmu(
            _law(params), out, normal_force=i.normal_force, contact_width=i.contact_width,
            seal_temperature=i.temperature,
            table=table, title=title,
            source=f"{source}, variant {name!r}", **common)
    from sealsim.pneumatic.case import build_contact_map, load_pneumatic_cases

    cases = load_pneumatic_cases(data, source)
    if seal is None:                                   # the whole cylinder
        if law_override is not None:
            raise InputError("[friction] and fmu.friction_file replace the law of one seal: "
                             "give fmu.seal (or --seal) to export that seal")
        name, case = _one_variant(cases, variant, source, same=lambda c: repr(c), notes=notes)
        return build_cylinder_fmu(case, out, base_dir=base,
                                  title=title or _model_name(case.title, case_path, name,
                                                             chosen(cases)),
                                  source=f"{source}, variant {name!r}", **common)
    starts = [_seal_temperature(c, _named(c.seals, seal)) for c in cases.values()]
    start = f"{format_quantity(starts[0], 'temperature')} in {next(iter(cases))!r}"
    name, case = _one_variant(
        cases, variant, source, notes=notes, same=lambda c: _seal_identity(c, seal),
        but="" if len(set(starts)) == 1 else
        f" but for the start value of the input T_seal ({start})")
    seals = {s.name: s for s in case.seals}
    if seal not in seals:
        raise InputError(f"{source}: there is no seal {seal!r}; choose one of "
                         f"{', '.join(seals)}")
    spec = seals[seal]
    where = f"seals[{case.seals.index(spec)}] ({seal!r}).map"
    law = _law(law_override or spec.friction)
    contact_map = None
    if spec.map is not None:
        diameter = (case.cylinder.bore if spec.location == "piston"
                    else case.cylinder.rod_diameter)
        contact_map = build_contact_map(spec.map, diameter, base, where,
                                        None if progress is None else
                                        (lambda d, n: progress("FE map", d, n)))
    temperature = _seal_temperature(case, spec)
    if contact_map is None and law.name == "theta":
        raise InputError(f"{where}: the theta law needs the seal's normal force and contact "
                         "width; give the seal a map")
    cylinder = _model_name(case.title, case_path, name, chosen(cases))
    # the friction FMU's v is the piston velocity: it slides the rod from the rod-end chamber
    # (side A) out, the bore past a piston seal from the rod-end chamber (side B) to the cap end
    return build_friction_fmu(law, out, contact_map=contact_map, seal_temperature=temperature,
                              sliding_diameter=diameter if contact_map is not None else None,
                              velocity_direction=-1.0 if spec.location == "piston" else 1.0,
                              table=table, title=title or f"{cylinder}: {seal} seal",
                              source=f"{source}, variant {name!r}, seal {seal!r}", **common)


def _inline_friction(fmu_case: FMUCase, params, path: Path, out, fmi_version, kind, force,
                     compile, inputs) -> BuildResult:
    """An FMU case with its own [friction] and [seal_contact] tables."""
    from sealsim.pneumatic.case import build_contact_map

    contact = fmu_case.seal_contact or ContactSettings()
    contact_map = None
    if contact.map is not None:
        contact_map = build_contact_map(contact.map, contact.sliding_diameter or 0.0,
                                        path.parent, "seal_contact.map")
    return build_friction_fmu(
        _law(params), out, contact_map=contact_map, normal_force=contact.normal_force,
        contact_width=contact.contact_width, seal_temperature=contact.temperature,
        sliding_diameter=contact.sliding_diameter,
        name=fmu_case.fmu.name, fmi_version=fmi_version, kind=kind, force=force,
        compile=compile, table=fmu_case.table, title=fmu_case.title,
        source=f"FMU case {str(path)!r}", inputs=inputs)
