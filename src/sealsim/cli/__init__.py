"""Command-line interface: ``sealsim COMMAND ...``.

The CLI holds no physics: each command parses options, calls the Python API and writes results
through :class:`sealsim.output.ResultFolder`.  Errors a user can fix (bad input, an existing
result folder) are printed as one message and exit with status 2; a model that fails for valid
input exits with status 1 and says where it failed.
"""

from __future__ import annotations

import typer

from sealsim import __version__
from sealsim.cli._common import console
from sealsim.cli.app import app_command
from sealsim.cli.cache import cache_app
from sealsim.cli.fmu import fmu_app
from sealsim.cli.friction import friction_app
from sealsim.cli.gland import gland_app
from sealsim.cli.pneumatic import pneumatic_app
from sealsim.cli.properties import material_app, oil_app
from sealsim.cli.rotary import rotary_app
from sealsim.cli.schema import schema_command
from sealsim.cli.structure import structure_app
from sealsim.cli.study import study_app

import sealsim.cli.calibration  # noqa: E402,F401  (registers the fit/compare commands)

app = typer.Typer(
    name="sealsim",
    help="sealsim -- friction, temperature and dynamics of elastomeric seals.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)
app.add_typer(oil_app, name="oil")
app.add_typer(material_app, name="material")
app.add_typer(rotary_app, name="rotary")
app.add_typer(friction_app, name="friction")
app.add_typer(structure_app, name="structure")
app.add_typer(pneumatic_app, name="pneumatic")
app.add_typer(cache_app, name="cache")
app.add_typer(fmu_app, name="fmu")
app.add_typer(study_app, name="study")
app.command("schema")(schema_command)
app.add_typer(gland_app, name="gland")
app.command("app")(app_command)


def _version(value: bool) -> None:
    if value:
        console.print(f"sealsim {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                 help="Print the sealsim version and exit."),
) -> None:
    """sealsim -- friction, temperature and dynamics of elastomeric seals."""


def main() -> None:  # pragma: no cover - thin entry point, exercised through CliRunner
    app()
