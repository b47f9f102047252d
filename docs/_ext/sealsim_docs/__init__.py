"""Generated parts of the sealsim documentation, rebuilt from the repository on every build.

:func:`generate` writes everything below ``docs/_generated/`` (deleted first, so nothing from
an earlier build survives):

* ``cases/``: the field reference of every case file (:mod:`.case_reference`);
* ``cli.rst``: the command-line reference (:mod:`.cli_reference`);
* ``api/``: one autodoc page per module (:mod:`.api_reference`);
* ``gallery_src/``: the gallery's source tree (:mod:`.gallery`), which sphinx-gallery runs
  into ``gallery/``;
* ``live_tables.rst`` and ``tests.rst``: material of the validation page
  (:mod:`.validation`);
* ``one_call.rst``: the functions of the package's top level, for getting started.
"""

from __future__ import annotations

import shutil
import time
from pathlib import Path

from . import api_reference, case_reference, cli_reference, discover, gallery, validation

GENERATED = "_generated"


def generate(docs_dir: Path) -> dict[str, float]:
    """Write all generated sources for the docs in ``docs_dir``; returns seconds per part."""
    repo = docs_dir.parent
    out = docs_dir / GENERATED
    if out.exists():
        shutil.rmtree(out)
    out.mkdir()
    timings: dict[str, float] = {}
    start = time.perf_counter()

    def lap(name: str) -> None:
        nonlocal start
        now = time.perf_counter()
        timings[name] = round(now - start, 2)
        start = now

    modules = discover.sealsim_modules()
    lap("import sealsim")
    models = discover.case_models()
    classified = discover.classify_examples(repo / "examples", models)
    case_reference.write(out / "cases", repo, models, classified)
    lap("case reference")
    from sealsim.cli import app

    (out / "cli.rst").write_text(cli_reference.page(app), encoding="utf-8")
    lap("cli reference")
    api_reference.write(out / "api", modules)
    gallery.build(repo / "examples", docs_dir / "gallery", out / "gallery_src", classified)
    (out / "tests.rst").write_text(validation.tests_table(repo / "tests"), encoding="utf-8")
    lap("api, gallery sources, tests")
    (out / "live_tables.rst").write_text(validation.live_tables(repo), encoding="utf-8")
    lap("live validation tables")
    (out / "one_call.rst").write_text(api_reference.one_call_section(
        discover.one_call_functions()), encoding="utf-8")
    return timings
