"""Material of the validation page: the README's measured results and the test catalogue.

* The README is where measured numbers are published, each with the command that produced
  it; its sections whose heading names validation, calibration or benchmarks are copied into
  the documentation unchanged (Markdown, rendered by MyST), so the two cannot disagree.
* The test catalogue lists every test module with its docstring (what it checks against) and
  the number of tests, read from the files without running them.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

from . import rst

#: README sections (``## ...`` headings) copied into the validation page
SECTION_PATTERN = re.compile(r"validation|calibration|benchmark|accuracy", re.IGNORECASE)


def readme_sections(readme: Path, pattern: re.Pattern = SECTION_PATTERN) -> list[tuple[str, str]]:
    """``(heading, body)`` of every level-2 section of the README whose heading matches."""
    text = readme.read_text(encoding="utf-8")
    parts = re.split(r"^## +(.+?)\s*$", text, flags=re.MULTILINE)
    # parts: [preamble, heading1, body1, heading2, body2, ...]
    return [(parts[i], parts[i + 1].strip("\n")) for i in range(1, len(parts) - 1, 2)
            if pattern.search(parts[i])]


def readme_markdown(readme: Path) -> str:
    """The matching README sections as one Markdown document (headings one level down)."""
    sections = readme_sections(readme)
    if not sections:
        raise ValueError(f"{readme} has no section whose heading matches "
                         f"{SECTION_PATTERN.pattern!r}; the validation page would be empty")
    out = ["# Measured results\n",
           "Copied from the repository's README, where each number is published with the "
           "command that measured it.\n"]
    for heading, body in sections:
        body = re.sub(r"^(#{3,}) ", r"#\1 ", body, flags=re.MULTILINE)  # keep nesting below
        out.append(f"## {heading}\n\n{body}\n")
    return "\n".join(out)


def test_modules(tests_dir: Path) -> list[tuple[str, str, int]]:
    """``(file name, docstring, number of test functions)`` of every ``test_*.py``."""
    found = []
    for path in sorted(tests_dir.glob("test_*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        count = sum(isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)
                    and node.name.startswith("test") for node in ast.walk(tree))
        if count:
            found.append((path.name, ast.get_docstring(tree) or "", count))
    return found


def test_catalogue(tests_dir: Path) -> str:
    """A table of the test modules: file, what it checks, number of test functions."""
    rows = [[rst.literal(name), rst.paragraph(doc.split("\n\n")[0]), str(count)]
            for name, doc, count in test_modules(tests_dir)]
    return rst.list_table(["Test module", "What it checks", "Tests"], rows, widths=[25, 65, 10])
