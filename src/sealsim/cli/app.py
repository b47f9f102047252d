"""``sealsim app``: the local web page (sealsim.app); no physics here."""

from __future__ import annotations

import typer

from sealsim.cli._common import console, guarded


@guarded
def app_command(
    port: int = typer.Option(0, "--port", "-p", min=0, max=65535,
                             help="Port (0: a free one)"),
    host: str = typer.Option("127.0.0.1", "--host",
                             help="Address to listen on (127.0.0.1: this computer only)"),
    no_browser: bool = typer.Option(False, "--no-browser", help="Do not open the browser"),
    run_timeout: float = typer.Option(600.0, "--run-timeout", min=1.0,
                                      help="Longest case run or FE check [s]"),
    max_upload: int = typer.Option(512, "--max-upload", min=1, max=65536,
                                   help="Largest case upload [kB]"),
) -> None:
    """Start sealsim's web page: lip seal, O-ring gland, friction curves, case runs.

    Runs until Ctrl-C.  Every number on the page comes from sealsim's Python API.
    """
    from sealsim.app import check_host, serve

    check_host(host, "--host")
    serve(host, port, open_browser=not no_browser, run_timeout=run_timeout,
          max_upload=max_upload * 1024,
          announce=lambda url: console.print(f"sealsim app running at {url} (Ctrl-C stops it)"))
