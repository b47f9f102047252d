"""sphinx-gallery image scraper for the figures sealsim's plotting functions return.

``sealsim.plotting`` builds :class:`matplotlib.figure.Figure` objects without pyplot, so
sphinx-gallery's matplotlib scraper (which asks pyplot for its figures) does not see them.
This scraper shows every new figure an example binds to a global name (``fig = ...``) after
each code block, in the order the names were bound.
"""

from __future__ import annotations

from pathlib import PurePosixPath

def figure_scraper(block, block_vars, gallery_conf, **kwargs):
    from matplotlib.figure import Figure
    from sphinx_gallery.scrapers import figure_rst

    # block_vars lives as long as one example: the figures shown so far (kept, not their ids,
    # which a new figure could reuse)
    shown = block_vars.setdefault("sealsim_figures_shown", [])
    new = [v for v in list(block_vars["example_globals"].values())
           if isinstance(v, Figure) and v.canvas.manager is None  # pyplot's: matplotlib scraper
           and not any(v is f for f in shown)]
    paths = []
    for fig, path in zip(new, block_vars["image_path_iterator"]):
        fig.savefig(path, dpi=kwargs.get("dpi", 110))
        shown.append(fig)
        paths.append(PurePosixPath(path))
    return figure_rst(paths, gallery_conf["src_dir"]) if paths else ""
