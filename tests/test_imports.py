"""The package's import structure, read from the source with the standard library's ast: no
import cycles between modules, and no module imports a higher layer.

Every import counts -- at the top of a module or inside a function -- because a deferred
import still makes the lower module depend on the higher one.  Layers, lowest first:

    base (errors, units, cases, files, tables, ode) -> properties -> tribology, friction, structure,
    thermal -> rotary, pneumatic -> measurements, calibration, fmu, studies, api ->
    output, plotting, runs, cli, app
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"

#: Layers, lowest first; a module belongs to the longest matching name.
LAYERS = (
    ("base", ("sealsim", "sealsim.errors", "sealsim.units", "sealsim.cases", "sealsim.files",
              "sealsim.tables", "sealsim.ode")),
    ("properties", ("sealsim.properties",)),
    ("physics", ("sealsim.tribology", "sealsim.friction", "sealsim.structure",
                 "sealsim.thermal")),
    ("systems", ("sealsim.rotary", "sealsim.pneumatic")),
    ("applications", ("sealsim.measurements", "sealsim.calibration", "sealsim.fmu",
                      "sealsim.studies", "sealsim.api")),
    ("front", ("sealsim.output", "sealsim.plotting", "sealsim.runs", "sealsim.cli",
               "sealsim.app")),
)

#: Known import cycles (module pairs): none.
KNOWN_CYCLES: set[frozenset] = set()

#: Known layer violations (importing module or package, imported package): none.
KNOWN_LAYER_VIOLATIONS: set[tuple[str, str]] = set()


def _module_name(path: Path) -> str:
    parts = path.relative_to(SRC).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


@functools.lru_cache(maxsize=1)
def import_graph() -> dict[str, frozenset[str]]:
    """Module -> the sealsim modules it imports (``from a.b import c`` counts a.b, and a.b.c
    when that is a module; relative imports are resolved)."""
    paths = {_module_name(p): p for p in (SRC / "sealsim").rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for name, path in paths.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        deps: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                deps.update(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    anchor = package.split(".")[:len(package.split(".")) - node.level + 1]
                    base = ".".join(anchor + ([base] if base else []))
                deps.add(base)
                deps.update(f"{base}.{a.name}" for a in node.names)
        graph[name] = frozenset(d for d in deps if d in paths and d != name)
    return graph


def without_parent_packages(graph: dict[str, set[str]]) -> dict[str, set[str]]:
    """The graph without the imports of a module's own packages: a package ``__init__`` that
    re-exports its modules is not a cycle of those modules."""
    return {k: {d for d in v if not k.startswith(d + ".")} for k, v in graph.items()}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """One cycle per strongly connected component with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for dep in sorted(graph.get(node, ())):
            if dep not in index:
                visit(dep)
                low[node] = min(low[node], low[dep])
            elif dep in on_stack:
                low[node] = min(low[node], index[dep])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def layer(module: str) -> int:
    """Index of the layer of ``module`` in :data:`LAYERS` (the longest matching name)."""
    best = (-1, -1)
    for k, (_, names) in enumerate(LAYERS):
        for name in names:
            if (module == name or module.startswith(name + ".")) and len(name) > best[1]:
                best = (k, len(name))
    return best[0]


def layer_violations(graph: dict[str, set[str]]) -> list[tuple[str, str]]:
    """(importer, imported) pairs where a module imports a module of a higher layer and the
    pair is not a :data:`KNOWN_LAYER_VIOLATIONS` entry."""
    def within(name, prefix):
        return name == prefix or name.startswith(prefix + ".")

    def known(importer, imported):
        return any(within(importer, a) and within(imported, b)
                   for a, b in KNOWN_LAYER_VIOLATIONS)

    return sorted((m, d) for m, deps in graph.items() for d in deps
                  if layer(d) > layer(m) and not known(m, d))


def test_the_graph_sees_imports_at_the_top_inside_functions_and_relative():
    graph = import_graph()
    assert "sealsim.plotting.rotary" in graph["sealsim.runs.rotary"]       # top of the module
    assert "sealsim.structure.maps" in graph["sealsim.pneumatic.contact_maps"]  # in a function
    assert layer("sealsim.properties.oils") < layer("sealsim.rotary.case") < layer("sealsim.cli")
    # the checks find what they look for
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert layer_violations({"sealsim.properties.oils": {"sealsim.plotting.properties"}}) == [
        ("sealsim.properties.oils", "sealsim.plotting.properties")]


def test_every_module_belongs_to_a_layer():
    assert [m for m in import_graph() if layer(m) < 0] == []


def test_no_import_cycles_between_modules():
    found = cycles(without_parent_packages(import_graph()))
    assert [c for c in found if frozenset(c) not in KNOWN_CYCLES] == []


def test_no_module_imports_a_higher_layer():
    assert layer_violations(import_graph()) == []


def test_model_packages_neither_plot_nor_write_result_folders():
    # the orchestration "case file -> result folder with plots" lives in sealsim.runs
    graph = import_graph()
    models = ("sealsim.rotary", "sealsim.pneumatic", "sealsim.friction", "sealsim.structure",
              "sealsim.calibration", "sealsim.fmu", "sealsim.studies")
    offending = sorted((m, d) for m, deps in graph.items() if m.startswith(models)
                       for d in deps if d.startswith(("sealsim.plotting", "sealsim.output")))
    assert offending == []
