"""Material of the validation page: live comparison tables and the test catalogue.

* The measured numbers are published in ``docs/guide/`` (Markdown pages of the validation
  section), each with the command that produced it.
* Fast scripts of the repository that print a Markdown table of model against reference
  (:data:`LIVE_TABLES`) are run, and their table shown as computed by today's code.
* The test catalogue lists every test module with its docstring (what it checks against) and
  the number of tests, read from the files without running them.
"""

from __future__ import annotations

import ast
import contextlib
import io
import runpy
from pathlib import Path

from . import rst

#: scripts run at build time: (path in the repository, what the table compares); each prints a
#: Markdown table and takes seconds
LIVE_TABLES = [("examples/rotary/iso_comparison.py",
                "Lip seal power loss: sealsim against ISO/TR 14179-2")]

def test_files(tests_dir: Path) -> list[tuple[str, str, int]]:
    """``(file name, docstring, number of test functions)`` of every ``test_*.py``."""
    found = []
    for path in sorted(tests_dir.glob("test_*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        count = sum(isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)
                    and node.name.startswith("test") for node in ast.walk(tree))
        if count:
            found.append((path.name, ast.get_docstring(tree) or "", count))
    return found


def tests_table(tests_dir: Path) -> str:
    """A table of the test modules: file, what it checks, number of test functions."""
    rows = [[rst.literal(name), rst.paragraph(doc.split("\n\n")[0]), str(count)]
            for name, doc, count in test_files(tests_dir)]
    return rst.list_table(["Test module", "What it checks", "Tests"], rows, widths=[25, 65, 10])


def live_table(repo: Path, script: str, caption: str) -> str:
    """Run ``script`` (as ``python script`` would) and return its Markdown table as reST."""
    output = io.StringIO()
    with contextlib.redirect_stdout(output):
        runpy.run_path(str(repo / script), run_name="__main__")
    header, rows = rst.markdown_table(output.getvalue())
    return (f"{rst.escape(caption)}, computed when this page was built by "
            f"``python {script}``:\n\n" +
            rst.list_table([rst.escape(h) for h in header],
                           [[rst.escape(c) for c in row] for row in rows]))


def live_tables(repo: Path) -> str:
    return "\n".join(live_table(repo, script, caption) for script, caption in LIVE_TABLES)
