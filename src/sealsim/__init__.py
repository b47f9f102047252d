"""sealsim -- friction, temperature and dynamics of elastomeric seals.

The package is layered: ``properties`` (oils, elastomers) feed the physical topic modules,
which feed the coupled simulations; ``cli`` and ``plotting`` sit on top and hold no physics.

One-call answers at the top level (:mod:`sealsim.api`, imported on first use so that
``import sealsim`` stays quick):

* :func:`lip_seal_torque` -- steady torque, power, contact temperature and film of a radial
  lip seal (``sealsim.lip_seal_torque("60 mm", "1500 rpm", "ISO VG 220", "70 degC")``);
* :func:`seal_friction` -- steady friction of a reciprocating seal over velocity, with F_N and
  b from an FE map or the analytic O-ring estimate;
* :func:`oring_gland` -- design check of an O-ring gland (squeeze, stretch, fill, extrusion
  gap from the worst-case tolerance stack), optionally with the FE force and friction;
* :func:`friction_loop` -- friction over a harmonic velocity (the hysteresis loop of a
  friction law with states).

The subpackages hold the long-form API: :mod:`sealsim.rotary`, :mod:`sealsim.pneumatic`,
:mod:`sealsim.friction`, :mod:`sealsim.structure`, :mod:`sealsim.properties`,
:mod:`sealsim.tribology`, :mod:`sealsim.thermal`, :mod:`sealsim.calibration`.
"""

from importlib.metadata import PackageNotFoundError, version

from sealsim.errors import ConvergenceError, InputError, ModelError, ResultExistsError, SealsimError

try:
    __version__ = version("sealsim")
except PackageNotFoundError:  # pragma: no cover - only when run from an uninstalled tree
    __version__ = "0+unknown"

#: top-level names imported on first use: name -> module
_LAZY = {"lip_seal_torque": "sealsim.api", "seal_friction": "sealsim.api",
         "oring_gland": "sealsim.api", "friction_loop": "sealsim.api"}


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'sealsim' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


__all__ = [
    "ConvergenceError",
    "InputError",
    "ModelError",
    "ResultExistsError",
    "SealsimError",
    "__version__",
    "friction_loop",
    "lip_seal_torque",
    "oring_gland",
    "seal_friction",
]
