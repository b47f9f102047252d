"""Named parameter sets of the friction laws, stored as data in ``parameter_sets.toml``.

Each set records its source and how well it is verified: [V] verified in the named source,
[M] a literature value not re-checked against its source, [R] reconstructed or illustrative.
Use a set from a case file with ``parameter_set = "canudas1995"`` in the ``[law]`` table
(explicit fields override it), or from Python:

>>> from sealsim.friction import LuGre
>>> law = LuGre.from_parameter_set("canudas1995", warn=False)
>>> law.params.sigma0, law.params.static_force
(100000.0, 1.5)
>>> sorted(PARAMETER_SETS["lugre"])
['canudas1995']
"""

from __future__ import annotations

import tomllib
from importlib import resources
from typing import Any

__all__ = ["PARAMETER_SETS", "parameter_set_generic", "parameter_set_note",
           "parameter_set_source", "parameter_set_values"]

#: keys of a set that describe it instead of holding a law parameter
_META = ("source", "generic")


def _load() -> dict[str, dict[str, dict[str, Any]]]:
    text = resources.files("sealsim.friction").joinpath("parameter_sets.toml").read_text("utf-8")
    return tomllib.loads(text)


#: ``{law: {set name: {field: value, "source": text}}}`` as read from parameter_sets.toml
PARAMETER_SETS: dict[str, dict[str, dict[str, Any]]] = _load()


def parameter_set_values(law: str, name: str) -> dict[str, Any]:
    """Field values of a named set (without its ``source``).

    Raises
    ------
    ValueError
        Unknown set; the message lists the sets of that law.
    """
    sets = PARAMETER_SETS.get(law, {})
    if name not in sets:
        choices = ", ".join(repr(s) for s in sorted(sets)) or "none"
        raise ValueError(f"parameter_set {name!r} is not known for law {law!r}; "
                         f"choose one of {choices}")
    return {k: v for k, v in sets[name].items() if k not in _META}


def parameter_set_source(law: str, name: str) -> str:
    """Where the numbers of a named set come from (with its [V]/[M]/[R] tag)."""
    return PARAMETER_SETS[law][name]["source"]


def parameter_set_generic(law: str, name: str) -> list[str]:
    """Fields of a named set that are generic literature values, not fitted to any seal (the
    set's ``generic`` list; empty if it has none)."""
    return list(PARAMETER_SETS[law][name].get("generic", []))


def parameter_set_note(params) -> str:
    """A note when a law takes values from a set that is not measured ([R]: reconstructed or
    illustrative) or that are generic literature values not fitted to this seal (the set's
    ``generic`` fields, e.g. μ_b and the roughness of ``seal_contact``), else "" -- the note
    of ``sealsim friction run``, ``sealsim pneumatic run`` and :func:`sealsim.seal_friction`.

    Parameters
    ----------
    params : pydantic model
        Validated parameters of a law (``law``, ``parameter_set`` and the law's fields).

    Examples
    --------
    >>> from sealsim.friction.case import ThetaParameters
    >>> parameter_set_note(ThetaParameters(law="theta", parameter_set="pneumatic_demo"))[:60]
    "theta parameter set 'pneumatic_demo' holds illustrative or r"
    >>> parameter_set_note(ThetaParameters(law="theta", parameter_set="seal_contact"))[:82]
    "theta parameter set 'seal_contact': boundary_friction = 0.2 and roughness = 0.3 um"
    >>> parameter_set_note(ThetaParameters(law="theta", parameter_set="seal_contact",
    ...                                    boundary_friction=0.08, roughness=0.5e-6))
    ''
    """
    name = getattr(params, "parameter_set", None)
    if name is None:
        return ""
    published = type(params).model_validate({"law": params.law, "parameter_set": name})
    values = parameter_set_values(params.law, name)
    taken = [f for f in values if getattr(params, f, None) == getattr(published, f, None)]
    if not taken:
        return ""
    if parameter_set_source(params.law, name).startswith("[R]"):
        used = "" if len(taken) == len(values) else f" ({', '.join(taken)} from it)"
        return (f"{params.law} parameter set {name!r} holds illustrative or reconstructed "
                f"values, not fitted to measurements{used}: fit them to your seal with sealsim "
                "friction fit before trusting the friction force")
    generic = [f for f in parameter_set_generic(params.law, name) if f in taken]
    if not generic:
        return ""
    shown = " and ".join(f"{f} = {values[f]}" for f in generic)
    plural = len(generic) > 1
    return (f"{params.law} parameter set {name!r}: {shown} {'are' if plural else 'is'} "
            f"{'' if plural else 'a '}generic literature value{'s' if plural else ''} (see the set's source), not "
            f"fitted to this seal; fit {'them' if plural else 'it'} to a measured friction of "
            "your seal with sealsim friction fit (fit.parameters = [{name = "
            f"'{generic[0]}', ...}}]"
            + (f"; {' and '.join(repr(f) for f in generic[1:])} where the runs span several "
               "speeds, which identify it" if plural else "") + ")")
