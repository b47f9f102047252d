"""The documentation's case-file field reference covers every case model and example file.

The generator (``docs/_ext/sealsim_docs``) finds the kinds of case file by walking the package;
these checks fail if a case model or an example would be missing from the documentation.
"""

import sys
from pathlib import Path

import pytest

from sealsim.cases import CaseModel

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "docs" / "_ext"))

from sealsim_docs import case_reference, discover  # noqa: E402


def _public_case_models() -> set[type]:
    found, todo = set(), [CaseModel]
    while todo:
        for sub in todo.pop().__subclasses__():
            todo.append(sub)
            # public models bound in a sealsim module (not the ones doctests define)
            module = sys.modules.get(sub.__module__)
            if (not sub.__name__.startswith("_") and sub.__module__.startswith("sealsim.")
                    and getattr(module, sub.__qualname__, None) is sub):
                found.add(sub)
    return found


@pytest.fixture(scope="module")
def roots():
    return discover.case_models()


def test_every_case_model_is_on_a_reference_page(roots):
    documented = {table.model for root in roots for table in case_reference.tables(root)}
    # a base whose subclasses are the forms of a table (the parameters base of the friction
    # laws) appears through them, which must all be documented
    missing = {m for m in _public_case_models() - documented
               if not (m.__subclasses__() and set(m.__subclasses__()) <= documented)}
    assert not missing, f"case models on no reference page: {sorted(m.__name__ for m in missing)}"


def test_every_field_is_a_row(roots):
    for root in roots:
        page = case_reference.model_page(root, [], REPO)
        for table in case_reference.tables(root):
            for name in table.model.model_fields:
                assert f"``{name}``" in page, f"{root.__name__}: {table.header}.{name} missing"


def _compound(path) -> bool:
    """An elastomer (compound) file, e.g. examples/materials/compounds/: not a case."""
    from sealsim.properties.elastomers import load_elastomer_file

    try:
        load_elastomer_file(path)
    except Exception:  # noqa: BLE001 - not a compound file
        return False
    return True


def test_every_example_file_belongs_to_exactly_one_case_model(roots):
    classified = discover.classify_examples(REPO / "examples", roots)
    assert classified, "no example case files found"
    wrong = {str(p.relative_to(REPO)): [m.__name__ for m in kinds]
             for p, kinds in classified.items() if len(kinds) != 1 and not _compound(p)}
    assert not wrong, f"example files accepted by no or several case models: {wrong}"


def test_registry_of_case_kinds_agrees_with_the_walk(roots):
    import sealsim.cases

    kinds = getattr(sealsim.cases, "CASE_KINDS", None)
    if kinds is None:
        pytest.skip("sealsim.cases has no CASE_KINDS registry")
    registered = {kind.model for kind in kinds}
    walked = {f"{m.__module__}.{m.__qualname__}" for m in roots}
    # every registered kind has its page; the walk may find more documents (e.g. catalogues)
    assert registered <= walked, f"registered but not found: {sorted(registered - walked)}"


def test_command_line_page_lists_every_command():
    import re

    from sealsim.cli import app
    from sealsim_docs import cli_reference

    page = (REPO / "docs" / "guide" / "python_and_cli.md").read_text(encoding="utf-8")
    section = page.split("## Command line", 1)[1].split("\n## ", 1)[0]
    leaves = [" ".join(path) for path, command in cli_reference.commands(app)
              if path and not hasattr(command, "list_commands")]
    # a line "sealsim GROUP a | b" lists a, b; "sealsim GROUP CMD ..." lists CMD;
    # "sealsim CMD ARG" lists a command without a group
    listed = set()
    for group, rest in re.findall(r"^sealsim (\w+) (.*)$", section, flags=re.MULTILINE):
        listed.add(group)
        listed.update(f"{group} {word}" for word in re.findall(r"(?:^|\| )(\w+)", rest))
    listed.update(re.findall(r"^sealsim (\w+)", section, flags=re.MULTILINE))  # top-level
    assert leaves and sorted(set(leaves) - listed) == []
