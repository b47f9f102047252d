"""Run an FMU from Python through FMPy: a small uniform layer over FMI 2.0 and 3.0.

Used by the build-time checks, the co-simulation helpers of :mod:`sealsim.fmu.cosim`, the
tests and the benchmark.  Variables are addressed by name; log messages of the FMU are
collected in :attr:`LoadedFMU.messages` (status, category, text), and an FMI call that fails
raises :class:`~sealsim.errors.ModelError` with the FMU's last error message.

Examples
--------
::

    with LoadedFMU("seal.fmu") as fmu:              # co-simulation
        fmu.set(v=0.01, p_A=3e5)
        fmu.initialize()
        fmu.do_step(0.0, 1e-3)
        force, = fmu.get("F")
"""

from __future__ import annotations

import ctypes
import shutil
import tempfile
import zipfile
from pathlib import Path

from sealsim.errors import InputError, ModelError
from sealsim.fmu.builder import fmpy_module

__all__ = ["LoadedFMU"]

_LABELS = ["OK", "WARNING", "DISCARD", "ERROR", "FATAL", "PENDING"]


class LoadedFMU:
    """One instance of an FMU (a ``.fmu`` file or an unpacked folder).

    Parameters
    ----------
    path : path
        The FMU.
    kind : {"cs", "me"}
        Interface to instantiate.
    name : str
        Instance name (shown in the FMU's log messages).
    """

    def __init__(self, path: str | Path, kind: str = "cs", name: str = "sealsim"):
        fmpy_module()                      # a clear message when FMPy is missing
        from fmpy import read_model_description

        path = Path(path)
        self._scratch = None
        if path.is_dir():
            folder = path
        else:
            if not zipfile.is_zipfile(path):
                raise InputError(f"{str(path)!r} is not an FMU (a ZIP archive)")
            self._scratch = tempfile.mkdtemp(prefix="sealsim-fmu-run-")
            with zipfile.ZipFile(path) as zf:
                zf.extractall(self._scratch)
            folder = Path(self._scratch)
        self.messages: list[tuple[str, str, str]] = []
        try:
            md = read_model_description(str(folder))
            self.model_description = md
            self.fmi_version = int(md.fmiVersion[0])
            self.vr = {v.name: v.valueReference for v in md.modelVariables}
            self.boolean = {v.name for v in md.modelVariables if v.type == "Boolean"}
            interface = md.coSimulation if kind == "cs" else md.modelExchange
            if interface is None:
                raise InputError(f"{str(path)!r} has no "
                                 f"{'co-simulation' if kind == 'cs' else 'model exchange'} "
                                 "interface")
            self.kind = kind
            token = md.guid if self.fmi_version == 2 else md.instantiationToken
            args = dict(guid=token, unzipDirectory=str(folder),
                        modelIdentifier=interface.modelIdentifier, instanceName=name)
            if self.fmi_version == 2:
                from fmpy import fmi2
                cls = fmi2.FMU2Slave if kind == "cs" else fmi2.FMU2Model
                self._fmu = cls(**args)
                self._callbacks = fmi2.fmi2CallbackFunctions()
                self._callbacks.logger = fmi2.fmi2CallbackLoggerTYPE(self._log2)
                self._callbacks.allocateMemory = fmi2.fmi2CallbackAllocateMemoryTYPE(
                    fmi2.calloc)
                self._callbacks.freeMemory = fmi2.fmi2CallbackFreeMemoryTYPE(fmi2.free)
                self._fmu.instantiate(callbacks=self._callbacks)
            else:
                from fmpy import fmi3
                cls = fmi3.FMU3Slave if kind == "cs" else fmi3.FMU3Model
                self._fmu = cls(**args)
                self._fmu.instantiate(logMessage=self._log3)
        except Exception as exc:
            self._cleanup()
            if isinstance(exc, InputError | ModelError):
                raise
            raise ModelError(f"cannot load the FMU {str(path)!r}: {exc}"
                             + self._last_error()) from None

    # -- logging ----------------------------------------------------------------------------
    def _log2(self, env, instance, status, category, message):
        self._record(status, category, message)

    def _log3(self, env, status, category, message):
        self._record(status, category, message)

    def _record(self, status, category, message):
        decode = (lambda b: b.decode("utf-8", "replace") if isinstance(b, bytes) else str(b))
        self.messages.append((_LABELS[status] if 0 <= status < len(_LABELS) else str(status),
                              decode(category), decode(message)))

    def _last_error(self) -> str:
        errors = [m for s, _, m in self.messages if s in ("ERROR", "FATAL")]
        return f" ({errors[-1]})" if errors else ""

    def _call(self, what: str, func, *args):
        try:
            return func(*args)
        except ModelError:
            raise
        except Exception as exc:
            raise ModelError(f"FMU call {what} failed{self._last_error()}: {exc}") from None

    # -- life cycle ---------------------------------------------------------------------------
    def initialize(self, start_time: float = 0.0) -> None:
        """Enter and leave initialization mode (parameters and start values are fixed)."""
        f = self._fmu
        if self.fmi_version == 2:
            self._call("setupExperiment", f.setupExperiment, None, start_time)
            self._call("enterInitializationMode", f.enterInitializationMode)
            self._call("exitInitializationMode", f.exitInitializationMode)
            if self.kind == "me":
                self._call("enterContinuousTimeMode", f.enterContinuousTimeMode)
        else:
            self._call("enterInitializationMode", f.enterInitializationMode, None, start_time)
            self._call("exitInitializationMode", f.exitInitializationMode)
            if self.kind == "me":
                self._call("enterContinuousTimeMode", f.enterContinuousTimeMode)

    def reset(self) -> None:
        """Back to the instantiated state with the start values."""
        self._call("reset", self._fmu.reset)

    def close(self) -> None:
        """Free the instance and remove the unpacked files."""
        fmu = getattr(self, "_fmu", None)
        if fmu is not None:
            try:
                fmu.terminate()
            except Exception:       # already in an error state: freeing is what matters
                pass
            fmu.freeInstance()
            self._fmu = None
        self._cleanup()

    def _cleanup(self):
        if self._scratch is not None:
            shutil.rmtree(self._scratch, ignore_errors=True)
            self._scratch = None

    def __enter__(self) -> LoadedFMU:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # -- values -------------------------------------------------------------------------------
    def _refs(self, names):
        try:
            return [self.vr[n] for n in names]
        except KeyError as exc:
            raise InputError(f"the FMU has no variable {exc.args[0]!r}; it has "
                             f"{', '.join(sorted(self.vr))}") from None

    def set(self, **values: float) -> None:
        """Set variables by name (Booleans accept True/False)."""
        reals = {k: v for k, v in values.items() if k not in self.boolean}
        bools = {k: v for k, v in values.items() if k in self.boolean}
        f = self._fmu
        if reals:
            refs = self._refs(reals)
            setter = f.setReal if self.fmi_version == 2 else f.setFloat64
            self._call(f"set {', '.join(reals)}", setter, refs, [float(v) for v in
                                                                  reals.values()])
        if bools:
            self._call(f"set {', '.join(bools)}", f.setBoolean, self._refs(bools),
                       [bool(v) for v in bools.values()])

    def get(self, *names: str) -> list[float]:
        """Values of variables by name (Booleans as 0.0/1.0)."""
        f = self._fmu
        out = []
        for name in names:
            ref = self._refs([name])
            if name in self.boolean:
                out.append(float(self._call(f"get {name}", f.getBoolean, ref)[0]))
            else:
                getter = f.getReal if self.fmi_version == 2 else f.getFloat64
                out.append(self._call(f"get {name}", getter, ref)[0])
        return out

    # -- co-simulation ------------------------------------------------------------------------
    def do_step(self, t: float, h: float) -> None:
        """One communication step from t to t + h (inputs held)."""
        self._call("doStep", self._fmu.doStep, t, h)

    def get_state(self):
        """A copy of the whole FMU state (free it with :meth:`free_state`)."""
        f = self._fmu
        return self._call("getFMUstate", f.getFMUstate if self.fmi_version == 2
                          else f.getFMUState)

    def set_state(self, state) -> None:
        f = self._fmu
        self._call("setFMUstate", f.setFMUstate if self.fmi_version == 2 else f.setFMUState,
                   state)

    def free_state(self, state) -> None:
        f = self._fmu
        self._call("freeFMUstate", f.freeFMUstate if self.fmi_version == 2
                   else f.freeFMUState, state)

    @property
    def raw(self):
        """The FMPy object (low-level API: ``fmi2DoStep``, ``doStep``, ...)."""
        return self._fmu

    # -- model exchange -------------------------------------------------------------------------
    @property
    def n_states(self) -> int:
        return self.model_description.numberOfContinuousStates

    def set_continuous_states(self, x) -> None:
        n = self.n_states
        array = (ctypes.c_double * n)(*[float(v) for v in x])
        self._call("setContinuousStates", self._fmu.setContinuousStates, array, n)

    def derivatives(self) -> list[float]:
        n = self.n_states
        array = (ctypes.c_double * n)()
        f = self._fmu
        if self.fmi_version == 2:
            self._call("getDerivatives", f.getDerivatives, array, n)
        else:
            self._call("getContinuousStateDerivatives", f.getContinuousStateDerivatives,
                       array, n)
        return list(array)
