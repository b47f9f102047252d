"""sealsim -- friction, temperature and dynamics of elastomeric seals.

The package is layered: ``properties`` (oils, elastomers) feed the physical topic modules,
which feed the coupled simulations; ``cli`` and ``plotting`` sit on top and hold no physics.
"""

from importlib.metadata import PackageNotFoundError, version

from sealsim.errors import ConvergenceError, InputError, ModelError, ResultExistsError, SealsimError

try:
    __version__ = version("sealsim")
except PackageNotFoundError:  # pragma: no cover - only when run from an uninstalled tree
    __version__ = "0+unknown"

__all__ = [
    "ConvergenceError",
    "InputError",
    "ModelError",
    "ResultExistsError",
    "SealsimError",
    "__version__",
]
