"""``sealsim app``: sealsim's answers in a local web page.

Four calculators on one page -- lip seal (:func:`sealsim.lip_seal_torque`), O-ring gland
(:func:`sealsim.oring_gland`), friction curves (:func:`sealsim.seal_friction`,
:func:`sealsim.friction_loop`) and case runs (``sealsim.runs``) -- served by Flask on
127.0.0.1.  The app holds no physics: every number on the page is the API's.

From Python::

    from sealsim.app import serve

    serve(port=0, open_browser=False)   # prints the address, runs until Ctrl-C
"""

from __future__ import annotations

import tempfile
import threading
import webbrowser
from collections.abc import Callable
from pathlib import Path

__all__ = ["serve", "start_server"]


def start_server(host: str = "127.0.0.1", port: int = 0, *, run_timeout: float = 600.0,
                 max_upload: int = 512 * 1024, max_running: int = 2,
                 work_dir: str | Path | None = None):
    """Start the app's server in a background thread; returns ``(server, url)``.

    ``server.shutdown()`` stops it; ``server.app.extensions["sealsim_jobs"].close()`` stops
    the runs and removes their folder.  Port 0 takes a free port.
    """
    import logging

    from werkzeug.serving import make_server

    from sealsim.app.server import AppConfig, create_app

    logging.getLogger("werkzeug").setLevel(logging.WARNING)  # no line per request

    folder = Path(work_dir) if work_dir is not None else Path(
        tempfile.mkdtemp(prefix="sealsim-app-"))
    app = create_app(AppConfig(folder, max_upload, run_timeout, max_running))
    server = make_server(host, port, app, threaded=True)
    server.app = app
    threading.Thread(target=server.serve_forever, daemon=True).start()
    threading.Thread(target=_warm_up, daemon=True).start()
    return server, f"http://{host}:{server.server_port}/"


def _warm_up() -> None:
    """Compile and load what the first answers need (numba kernels, matplotlib), while the
    page opens."""
    import warnings

    import sealsim
    from sealsim.plotting import new_figure
    from sealsim.plotting.calculators import figure_png

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sealsim.lip_seal_torque("80 mm", "1000 rpm", "VG68-mineral", "60 degC")
        figure_png(new_figure()[0])


def serve(host: str = "127.0.0.1", port: int = 0, *, open_browser: bool = True,
          run_timeout: float = 600.0, max_upload: int = 512 * 1024,
          announce: Callable[[str], None] = print) -> None:
    """Run the app until Ctrl-C: start the server, announce its address, open the browser."""
    server, url = start_server(host, port, run_timeout=run_timeout, max_upload=max_upload)
    announce(url)
    if open_browser:
        webbrowser.open(url)
    try:
        threading.Event().wait()
    except KeyboardInterrupt:
        pass
    finally:
        server.shutdown()
        server.app.extensions["sealsim_jobs"].close()
