"""``sealsim schema KIND``: the JSON Schema of a kind of case file, for editors.

The schema is generated from the pydantic case model that reads the file
(:func:`sealsim.cases.case_json_schema`), so it cannot drift from what the commands accept.
"""

from __future__ import annotations

import importlib
import json

import typer

from sealsim.cases import CASE_KINDS, CaseKind, case_json_schema
from sealsim.cli._common import guarded
from sealsim.errors import InputError

__all__ = ["SCHEMA_KINDS", "kind_schema", "schema_command"]

#: the kinds of case file by their name on the command line (``friction-fit``)
SCHEMA_KINDS: dict[str, CaseKind] = {kind.name.replace(" ", "-"): kind for kind in CASE_KINDS}


def kind_schema(name: str) -> dict:
    """JSON Schema of the case kind ``name`` (``"rotary"``, ``"friction-fit"``, ...)."""
    kind = SCHEMA_KINDS.get(name.strip().replace(" ", "-").lower())
    if kind is None:
        raise InputError(f"KIND {name!r} is not a kind of case file; choose one of "
                         f"{', '.join(SCHEMA_KINDS)}")
    module, _, model = kind.model.rpartition(".")
    case_model = getattr(importlib.import_module(module), model)
    return case_json_schema(case_model, variants=kind.variants,
                            title=f"sealsim {kind.name} case ({kind.command})")


@guarded
def schema_command(
    kind: str = typer.Argument(..., help="Kind of case file: " + ", ".join(SCHEMA_KINDS)
                                         + "."),
) -> None:
    """Print the JSON Schema of a kind of case file (for editors that check TOML).

    Save it and point your editor at it, e.g. sealsim schema rotary > rotary.schema.json and a
    first line  #:schema ./rotary.schema.json  in the case file (taplo / Even Better TOML).
    """
    typer.echo(json.dumps(kind_schema(kind), indent=2, ensure_ascii=False))
