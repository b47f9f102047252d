"""Small reStructuredText writers: escaping free text, titles, tables, literal blocks."""

from __future__ import annotations

import re
import textwrap

# reST markup characters: escaped, free text is shown exactly as written (e.g. ``|v|`` would
# otherwise be a substitution reference and ``*`` an emphasis).
_SPECIAL = re.compile(r"([\\`*_|\[\]<>:])")
_LITERAL = re.compile(r"``(.+?)``")


def escape(text: str) -> str:
    """Free text as reST that shows every character as written; ````code```` stays literal.

    >>> print(escape("v* = |v| + 1, see ``sealsim oil list``"))
    v\\* = \\|v\\| + 1, see ``sealsim oil list``
    """
    parts = _LITERAL.split(text)
    # even indices: free text, odd: the inside of a double-backtick literal
    return "".join(_SPECIAL.sub(r"\\\1", part) if i % 2 == 0 else literal(part)
                   for i, part in enumerate(parts))


def literal(text: str) -> str:
    """Inline literal of any text (a backslash or double backtick cannot break it)."""
    text = text.replace("\n", " ").strip()
    if not text:
        return ""
    if "``" in text or text.endswith("\\"):
        return ":literal:`" + _SPECIAL.sub(r"\\\1", text) + "`"
    return f"``{text}``"


def paragraph(text: str) -> str:
    """A docstring-like block of free text as escaped paragraphs (blank lines kept)."""
    blocks = re.split(r"\n\s*\n", text.strip())
    return "\n\n".join(escape(" ".join(line.strip() for line in block.splitlines()))
                       for block in blocks if block.strip())


def title(text: str, char: str = "=", overline: bool = False) -> str:
    """A section title; the text is written as is (callers escape it when needed)."""
    line = char * max(len(text), 3)
    return (f"{line}\n" if overline else "") + f"{text}\n{line}\n"


def indent(text: str, spaces: int = 3) -> str:
    pad = " " * spaces
    return "\n".join(pad + line if line.strip() else "" for line in text.splitlines())


def literal_block(text: str, language: str = "text") -> str:
    """A code block showing ``text`` unchanged (trailing spaces removed)."""
    body = textwrap.dedent("\n".join(line.rstrip() for line in text.splitlines())).strip("\n")
    return f".. code-block:: {language}\n\n{indent(body)}\n"


def list_table(header: list[str], rows: list[list[str]], widths: list[int] | None = None,
               css_class: str | None = None) -> str:
    """A ``list-table``; cells are reST already (escape free text before)."""
    lines = [".. list-table::", "   :header-rows: 1"]
    if widths:
        lines.append("   :widths: " + " ".join(str(w) for w in widths))
    if css_class:
        lines.append(f"   :class: {css_class}")
    lines.append("")
    for row in [header, *rows]:
        for j, cell in enumerate(row):
            cell_lines = (cell or "").splitlines() or [""]
            lead = "   * - " if j == 0 else "     - "
            lines.append(lead + cell_lines[0])
            lines.extend("       " + extra if extra.strip() else "" for extra in cell_lines[1:])
    return "\n".join(lines) + "\n"


def markdown_table(text: str) -> tuple[list[str], list[list[str]]]:
    """Header and rows of the first pipe table (``| a | b |``) in Markdown text."""
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")]
            for line in text.splitlines() if line.strip().startswith("|")]
    rows = [r for r in rows if not all(re.fullmatch(r":?-{3,}:?", c) for c in r)]
    if not rows:
        raise ValueError("no Markdown table found")
    return rows[0], rows[1:]
