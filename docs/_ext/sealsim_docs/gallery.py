"""Source tree of the example gallery: ``examples/`` merged with ``docs/gallery/``.

Convention (nothing to register):

* every folder ``examples/TOPIC/`` and ``docs/gallery/TOPIC/`` is a section of the gallery;
* every ``*.py`` script in them is an entry; scripts named ``plot_*.py`` are run when the
  documentation is built and their figures and printed output shown (keep them to seconds),
  other scripts are shown with their code only;
* every ``*.toml`` case file of ``examples/TOPIC/`` is listed in its section with its title
  (or the first paragraph of its comment header) and a link to the field reference of its
  case type;
* ``docs/gallery/TOPIC/GALLERY_HEADER.rst`` (optional) is the section's introduction.

The scripts run next to the example files (the whole ``examples/`` tree is copied), so a
script reads ``"speed_cycle.toml"`` just as it would when started in ``examples/rotary/``.
"""

from __future__ import annotations

import ast
import shutil
from pathlib import Path

from pydantic import BaseModel

from . import rst
from .case_reference import page_name
from .discover import case_command, example_files

HEADER = "GALLERY_HEADER.rst"


def topics(examples_dir: Path, gallery_dir: Path) -> list[str]:
    """Topic folders that hold scripts or case files, sorted."""
    found = set()
    for root in (examples_dir, gallery_dir):
        for folder in root.iterdir() if root.is_dir() else []:
            if folder.is_dir() and not folder.name.startswith((".", "_")) and (
                    any(folder.glob("*.py")) or any(folder.glob("*.toml"))):
                found.add(folder.name)
    return sorted(found)


def add_title(script: Path) -> None:
    """Give a script's docstring a reST title (sphinx-gallery needs one) if it has none.

    A docstring whose first paragraph is one line (``\"\"\"ISO comparison -- an example.``)
    gets that line underlined, in the gallery's copy only.
    """
    source = script.read_text(encoding="utf-8")
    tree = ast.parse(source)
    doc = ast.get_docstring(tree, clean=False)
    if not doc:
        return
    paragraph = doc.strip("\n").split("\n\n")[0].splitlines()
    if len(paragraph) != 1:
        return  # already "Title\n=====" (or a multi-line paragraph sphinx-gallery reports)
    title = paragraph[0].strip()
    lines = source.splitlines(keepends=True)
    start = tree.body[0].lineno - 1  # line of the opening quotes
    for k in range(start, len(lines)):
        if title in lines[k]:
            lines.insert(k + 1, "=" * len(title) + "\n")
            script.write_text("".join(lines), encoding="utf-8")
            return


def describe_case_file(path: Path) -> str:
    """What a case file shows: its ``title``, else the first paragraph of its comment header."""
    from sealsim.cases import load_toml

    title = load_toml(path).get("title")
    if isinstance(title, str) and title.strip():
        return title.strip()
    paragraph = []
    for line in path.read_text(encoding="utf-8").splitlines():
        text = line.strip()
        if not text.startswith("#") or (not text.strip("# ") and paragraph):
            break
        if text.strip("# "):
            paragraph.append(text.lstrip("#").strip())
    return " ".join(paragraph).rstrip(":")


def section_header(topic: str, intro: str, case_files: list[Path],
                   classified: dict[Path, list[type[BaseModel]]], examples_dir: Path) -> str:
    """The header of one gallery section: its introduction and its case files."""
    out = [intro.rstrip() + "\n" if intro.strip() else rst.title(topic.replace("_", " ").title())]
    if case_files:
        rows = []
        for path in case_files:
            models = classified.get(path, [])
            kind = ", ".join(f":doc:`{m.__name__} </_generated/cases/{page_name(m)}>`"
                             + (f", run with {rst.literal(c)}" if (c := case_command(m)) else "")
                             for m in models) or "--"
            name = path.relative_to(examples_dir.parent).as_posix()
            rows.append([f":download:`{path.name} </../{name}>`", kind,
                         rst.escape(describe_case_file(path))])
        out.append(f"Case files in ``examples/{topic}/``; the page of each case type lists "
                   "its fields, :ref:`cli-reference` the commands:\n")
        out.append(rst.list_table(["File", "Case type", "What it shows"], rows,
                                  widths=[22, 18, 60]))
    return "\n".join(out) + "\n"


def build(examples_dir: Path, gallery_dir: Path, out_dir: Path,
          classified: dict[Path, list[type[BaseModel]]]) -> list[str]:
    """Assemble the gallery source tree in ``out_dir`` (replaced); returns the topics."""
    if out_dir.exists():
        shutil.rmtree(out_dir)
    shutil.copytree(examples_dir, out_dir, ignore=shutil.ignore_patterns(
        "__pycache__", ".*", "results"))
    (out_dir / HEADER).write_text((gallery_dir / HEADER).read_text(encoding="utf-8"),
                                  encoding="utf-8")
    found = topics(examples_dir, gallery_dir)
    for topic in found:
        target = out_dir / topic
        target.mkdir(exist_ok=True)
        own = gallery_dir / topic
        for script in sorted(own.glob("*.py")) if own.is_dir() else []:
            if (target / script.name).exists():
                raise FileExistsError(f"{script} has the name of examples/{topic}/"
                                      f"{script.name}; rename one of them")
            shutil.copy2(script, target / script.name)
        intro_file = own / HEADER
        intro = intro_file.read_text(encoding="utf-8") if intro_file.is_file() else ""
        case_files = [p for p in example_files(examples_dir, ".toml")
                      if p.parent == examples_dir / topic]
        for script in target.glob("*.py"):
            add_title(script)
        (target / HEADER).write_text(
            section_header(topic, intro, case_files, classified, examples_dir), encoding="utf-8")
    return found
