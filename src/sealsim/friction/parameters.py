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

__all__ = ["PARAMETER_SETS", "parameter_set_note", "parameter_set_source",
           "parameter_set_values"]


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
    return {k: v for k, v in sets[name].items() if k != "source"}


def parameter_set_source(law: str, name: str) -> str:
    """Where the numbers of a named set come from (with its [V]/[M]/[R] tag)."""
    return PARAMETER_SETS[law][name]["source"]


def parameter_set_note(params) -> str:
    """A note when a law takes values from a set that is not measured ([R]: reconstructed or
    illustrative), else "" -- the note of ``sealsim friction run``, ``sealsim pneumatic run``
    and :func:`sealsim.seal_friction`.

    Parameters
    ----------
    params : pydantic model
        Validated parameters of a law (``law``, ``parameter_set`` and the law's fields).

    Examples
    --------
    >>> from sealsim.friction.case import ThetaParameters
    >>> parameter_set_note(ThetaParameters(law="theta", parameter_set="pneumatic_demo"))[:60]
    "theta parameter set 'pneumatic_demo' holds illustrative or r"
    """
    name = getattr(params, "parameter_set", None)
    if name is None or not parameter_set_source(params.law, name).startswith("[R]"):
        return ""
    published = type(params).model_validate({"law": params.law, "parameter_set": name})
    values = parameter_set_values(params.law, name)
    taken = [f for f in values if getattr(params, f, None) == getattr(published, f, None)]
    if not taken:
        return ""
    used = "" if len(taken) == len(values) else f" ({', '.join(taken)} from it)"
    return (f"{params.law} parameter set {name!r} holds illustrative or reconstructed values, "
            f"not fitted to measurements{used}: fit them to your seal with sealsim friction "
            "fit before trusting the friction force")
