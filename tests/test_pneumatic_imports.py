"""No import cycles in the friction and pneumatic packages (issue 16): every import -- at the top
of a module or inside a function -- read from the source with the standard library's ast."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGES = ("sealsim.friction", "sealsim.pneumatic")


def _module_name(path: Path) -> str:
    parts = path.relative_to(SRC).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def import_graph() -> dict[str, set[str]]:
    """Module -> the sealsim modules it imports (``from a.b import c`` counts a.b, and a.b.c
    when that is a module)."""
    modules = {_module_name(p): p for p in (SRC / "sealsim").rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        deps: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                deps.update(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                deps.add(node.module)
                deps.update(f"{node.module}.{a.name}" for a in node.names)
        graph[name] = {d for d in deps if d in modules and d != name}
    return graph


def cycles(graph: dict[str, set[str]], within) -> list[list[str]]:
    """Elementary cycles through modules of ``within`` (depth-first search)."""
    found, seen = [], set()

    def visit(node, stack):
        for dep in graph.get(node, ()):
            if not dep.startswith(within):
                continue
            if dep in stack:
                cycle = stack[stack.index(dep):] + [dep]
                key = frozenset(cycle)
                if key not in seen:
                    seen.add(key)
                    found.append(cycle)
            elif len(stack) < 12:
                visit(dep, stack + [dep])

    for start in graph:
        if start.startswith(within):
            visit(start, [start])
    return found


def test_no_import_cycles_in_friction_and_pneumatic():
    graph = import_graph()
    assert "sealsim.pneumatic.summary" in graph["sealsim.pneumatic.study"]   # the graph works
    # a package __init__ re-exporting its modules is not a cycle of those modules
    graph = {k: {d for d in v if not (k.startswith(d + ".") and d in PACKAGES)}
             for k, v in graph.items()}
    assert cycles(graph, PACKAGES) == []
