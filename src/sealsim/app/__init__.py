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

__all__ = ["check_host", "serve", "server_url", "start_server"]

_HOSTS_ALLOWED = ("an IP address or host name of this computer, e.g. 127.0.0.1 (this computer "
                  "only) or 0.0.0.0 (every network interface)")


def check_host(host: str, option: str = "host") -> None:
    """Refuse an address the server cannot listen on, before it starts.

    werkzeug prints only the system's message ("Name or service not known") and exits the
    process; this names the option, the value and what is allowed instead.

    Raises
    ------
    InputError
        ``host`` resolves to no address, or to none of this computer's.

    Examples
    --------
    >>> check_host("127.0.0.1")
    >>> check_host("999.1.1.1", "--host")
    Traceback (most recent call last):
    ...
    sealsim.errors.InputError: --host '999.1.1.1' is not an IP address nor a host name ...
    """
    import socket

    from sealsim.errors import InputError

    # the address family werkzeug's server takes (werkzeug.serving.select_address_family)
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    try:
        found = socket.getaddrinfo(host, 0, family, socket.SOCK_STREAM)
    except (socket.gaierror, UnicodeError, ValueError):
        raise InputError(f"{option} {host!r} is not an IP address nor a host name that "
                         f"resolves; give {_HOSTS_ALLOWED}") from None
    problem = None
    for found_family, kind, proto, _, address in found:
        try:
            with socket.socket(found_family, kind, proto) as probe:
                probe.bind(address)            # port 0: tests the address only
            return
        except OSError as exc:
            problem = exc.strerror
    resolved = found[0][4][0]
    raise InputError(f"{option} {host!r}" + (f" ({resolved})" if resolved != host else "")
                     + f" is not an address of this computer ({problem}); give "
                     f"{_HOSTS_ALLOWED}")


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
    check_host(host)

    folder = Path(work_dir) if work_dir is not None else Path(
        tempfile.mkdtemp(prefix="sealsim-app-"))
    app = create_app(AppConfig(folder, max_upload, run_timeout, max_running))
    server = make_server(host, port, app, threaded=True)
    server.app = app
    threading.Thread(target=server.serve_forever, daemon=True).start()
    threading.Thread(target=_warm_up, daemon=True).start()
    return server, server_url(host, server.server_port)


def server_url(host: str, port: int) -> str:
    """The address a browser opens: an IPv6 literal in brackets (RFC 3986, 3.2.2).

    >>> server_url("127.0.0.1", 8050), server_url("::1", 8050)
    ('http://127.0.0.1:8050/', 'http://[::1]:8050/')
    """
    if ":" in host and not host.startswith("["):
        host = f"[{host}]"
    return f"http://{host}:{port}/"


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
