"""FMU export: sealsim's seal models as self-contained FMI 2.0 / 3.0 units.

A system engineer drops a calibrated sealsim seal into a model of another tool (Simulink,
Dymola, OpenModelica, Amesim, SimulationX, DSHplus, FMPy): the FMU is plain C generated from
templates (``sealsim/fmu/c``), compiled with the platform's C compiler, and carries its
sources so that it can be compiled for another platform.  No Python is needed to run it.

* **Seal friction** (:func:`build_friction_fmu`): the laws ``coulomb``, ``stribeck``,
  ``lugre`` and ``theta`` of :mod:`sealsim.friction` with their parameters, and the contact
  map F_N, b (Δp, T) of the seal as a table; states advance with the laws' exact updates in
  ``doStep`` (stable for any communication step).
* **Rotary lip seal** (:func:`build_rotary_fmu`): steady maps of the coupled friction–thermal
  model over speed × sump temperature plus a thermal lag identified from its transient.
* :func:`build_fmu` builds either from a case file (``sealsim fmu build``).

Running FMUs from Python: :class:`LoadedFMU`, and the co-simulation helpers of
:mod:`sealsim.fmu.cosim`.  Building and running needs FMPy (``pip install 'sealsim[fmu]'``).

Drive a friction FMU from a table or a measured signal through its **co-simulation**
interface: in model exchange, a host that does not restart its solver where the input changes
(FMPy's ``simulate_fmu`` with an input table, ``fmusim``) steps over a velocity reversal of the
stiff bristle state and gives wrong LuGre forces (2.5 N on a 1.1 N force, measured in the
documentation page "Working with other tools"); model exchange is right in a closed loop,
where the velocity is a state the host integrates.

>>> from sealsim.fmu import C_LAWS
>>> C_LAWS
('coulomb', 'stribeck', 'lugre', 'theta')
"""

from sealsim.fmu.build import build_fmu, build_friction_fmu, build_rotary_fmu
from sealsim.fmu.builder import BuildResult, FMUCompileError, FMUDependencyError
from sealsim.fmu.friction_export import C_LAWS

__all__ = ["C_LAWS", "BuildResult", "FMUCompileError", "FMUDependencyError", "LoadedFMU",
           "build_fmu", "build_friction_fmu", "build_rotary_fmu"]


def __getattr__(name):
    if name == "LoadedFMU":            # imports FMPy only when used
        from sealsim.fmu.instance import LoadedFMU

        return LoadedFMU
    raise AttributeError(name)
