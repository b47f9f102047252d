"""A real seal on the friction test bench: the law inputs of a bench case's ``[seal]``.

A friction bench case (:mod:`sealsim.friction.case`) may name the seal it tests, as a pneumatic
seal names its ``map``: the analytic O-ring estimate, a ``map.nc`` or a structure case (FE map
built on demand and cached).  :func:`bench_inputs` builds that contact map, evaluates F_N and b
at the bench's constant pressure difference |p_A − p_B| and temperature, and for the Θ law with
``steady = "contact"`` (parameter set ``seal_contact``) gets the seal's friction table
(:func:`sealsim.pneumatic.case.seal_friction_table`, cached like a pneumatic seal's).  The
bench then runs the law exactly as a cylinder or :func:`sealsim.seal_friction` would at that
point: in steady sliding the bench force is the seal's steady friction.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
from pydantic import TypeAdapter, ValidationError

from sealsim.cases import validation_problems
from sealsim.errors import InputError
from sealsim.friction.base import ContactInputs
from sealsim.pneumatic.case import (
    MapModel,
    build_contact_map,
    map_elastomer,
    seal_friction_table,
)
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["bench_contact_map", "bench_inputs"]


def bench_contact_map(case, base_dir: str | Path = ".", progress=None):
    """The contact map of a friction bench case's ``[seal]`` (built on demand, cached), after
    checking that ``[inputs]`` gives the seal temperature and no normal force or width (the
    map gives them); see :func:`bench_inputs`."""
    seal, i = case.seal, case.inputs
    try:
        spec = TypeAdapter(MapModel).validate_python(seal.map, context={"require_units": True})
    except ValidationError as exc:
        raise InputError("seal.map: " + "; ".join(validation_problems(exc))) from None
    given = [k for k in ("normal_force", "contact_width") if getattr(i, k) is not None]
    if given:
        raise InputError(f"inputs.{given[0]}: the bench has a [seal], whose contact gives the "
                         "normal force and contact width; remove "
                         f"{' and '.join(given)} from [inputs] (or the [seal])")
    if i.temperature is None:
        raise InputError("inputs.temperature: the seal's contact map needs the seal "
                         "temperature; give temperature = '20 degC' in [inputs]")
    return build_contact_map(spec, seal.sliding_diameter, Path(base_dir), "seal.map",
                             progress, label="bench seal")


def bench_inputs(case, law, base_dir: str | Path = ".", progress=None
                 ) -> tuple[ContactInputs, dict[str, Any]]:
    """The law inputs of a friction bench case with a ``[seal]``, and what the seal gave.

    Parameters
    ----------
    case : sealsim.friction.case.FrictionCase
        A validated bench case with ``seal`` set.
    law : FrictionLaw
        The case's law (:func:`sealsim.friction.case.build_law`).
    base_dir : path
        Folder the map's relative paths start from (the case file's).
    progress : callable, optional
        ``progress(done, total)`` while an FE map is built on demand.

    Returns
    -------
    inputs : ContactInputs
        F_N [N] and b [m] of the contact at Δp = |p_A − p_B| and T, the pressures, T, and for
        the Θ law on its own contact the friction table, the sliding diameter and the stroke
        direction of positive bench velocities.
    seal : dict
        ``normal_force_N``, ``contact_width_mm``, ``pressure_difference_bar``,
        ``sliding_diameter_mm`` and ``contact_map`` (its description) for the summary.

    Raises
    ------
    InputError
        A map table that is not one of the three sources, ``[inputs]`` normal_force or
        contact_width given as well (the seal's contact gives them), no temperature, a pressure
        difference or temperature outside the map.
    """
    seal, i = case.seal, case.inputs
    contact_map = bench_contact_map(case, base_dir, progress)
    dp = abs(float(i.pressure_a) - float(i.pressure_b))
    lo, hi = contact_map.ranges["pressure"]
    if not lo - 1e-6 <= dp <= hi + 1e-6:
        raise InputError(f"inputs: the pressure difference |pressure_a - pressure_b| = "
                         f"{dp / 1e5:.4g} bar is outside the seal's contact map ({lo / 1e5:g} "
                         f"... {hi / 1e5:g} bar)")
    tlo, thi = contact_map.ranges["temperature"]
    if not tlo - 1e-6 <= i.temperature <= thi + 1e-6:
        c = ZERO_CELSIUS_K
        raise InputError(f"inputs.temperature: {i.temperature - c:.4g} degC is outside the "
                         f"seal's contact map ({tlo - c:g} ... {thi - c:g} degC)")
    normal_force, width = (float(np.asarray(x).reshape(-1)[0])
                           for x in contact_map.evaluate(dp, i.temperature))
    table = seal_friction_table(law, contact_map, "seal.map")
    inputs = ContactInputs(
        normal_force=normal_force, contact_width=width, pressure_a=i.pressure_a,
        pressure_b=i.pressure_b, temperature=i.temperature, contact_table=table,
        sliding_diameter=seal.sliding_diameter, pressure_difference=dp,
        table_orientation=1.0 if seal.positive_velocity == "away_from_pressure" else -1.0)
    description = {"normal_force_N": normal_force, "contact_width_mm": width * 1e3,
                   "pressure_difference_bar": dp / 1e5,
                   "sliding_diameter_mm": seal.sliding_diameter * 1e3,
                   "elastomer": map_elastomer(contact_map),
                   "contact_map": contact_map.describe()}
    return inputs, description
