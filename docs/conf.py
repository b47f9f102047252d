"""Sphinx configuration of the sealsim documentation (``make docs``).

Everything that describes code is generated from the code on every build (see
``_ext/sealsim_docs``): the field reference of the case files from the pydantic models, the
command-line reference from the typer application, the API reference from the docstrings, the
gallery from ``examples/`` and ``gallery/``, the measured results from the README.  Nothing is
downloaded while building (no intersphinx) and nothing is cached between builds.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS / "_ext"))
os.environ.setdefault("MPLBACKEND", "Agg")

import sealsim  # noqa: E402
import sealsim_docs  # noqa: E402

project = "sealsim"
author = "sealsim developers"
copyright = "sealsim developers, MIT licence"  # noqa: A001
release = version = sealsim.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx_gallery.gen_gallery",
    "myst_parser",
    "sealsim_docs.sphinx_ext",
]

# the generated sources (docs/_generated), written anew on every build
print("sealsim docs: generated sources, seconds per part:", sealsim_docs.generate(DOCS))

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
# gallery/ and _generated/gallery_src/ are sphinx-gallery's input, not pages
exclude_patterns = ["_build", "_generated/gallery_src", "gallery"]
templates_path: list[str] = []
# Footnotes of a numpydoc "References" section are listed without being cited in the text.
suppress_warnings = ["ref.footnote"]
html_static_path = ["_static"]
html_css_files = ["sealsim.css"]

# -- API reference ------------------------------------------------------------------------------
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
autodoc_preserve_defaults = True   # show ``DEFAULT_X`` rather than a long float
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
napoleon_use_ivar = True           # "Attributes" as a field list: no second target per field
python_use_unqualified_type_names = True

# -- Markdown (the README's result sections) -------------------------------------------------------
myst_heading_anchors = 3

# -- gallery ---------------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "_generated/gallery_src",
    "gallery_dirs": "_generated/gallery",
    # plot_*.py scripts run at build time (seconds each); any other script is shown with its
    # code only (iso_comparison.py runs for the validation page's table)
    "filename_pattern": r"/plot_[^/]*\.py$",
    "ignore_pattern": r"__init__\.py",
    # from the properties a model uses to the models built on them; new topics follow
    "subsection_order": [f"_generated/gallery_src/{topic}" for topic in (
        "properties", "rotary", "friction", "structure", "pneumatic", "calibration")] + ["*"],
    "within_subsection_order": "FileNameSortKey",
    "abort_on_example_error": True,
    "download_all_examples": False,
    "write_computation_times": False,
    "show_signature": False,
    "remove_config_comments": True,
    "capture_repr": (),
    # sealsim.plotting returns figures without pyplot: shown when bound to a name (fig = ...)
    "image_scrapers": ("matplotlib", "sealsim_docs.scraper.figure_scraper"),
    "doc_module": (),
    "backreferences_dir": None,
}

# -- HTML ------------------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"sealsim {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "header_links_before_dropdown": 7,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_sidebars = {"**": ["sidebar-nav-bs"], "index": []}
html_show_sourcelink = False
# quotes and ellipses only: "--force" in help texts and docstrings stays two hyphens
smartquotes_action = "qe"
