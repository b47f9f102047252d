"""Assemble, compile and write an FMU: the model-independent part of the export.

An FMU is a ZIP archive::

    modelDescription.xml             variables, units, interfaces (FMI 2.0 or 3.0)
    binaries/<platform>/<id>.so      the compiled model (.dylib on macOS, .dll on Windows)
    sources/                         C sources, FMI headers and buildDescription.xml, so that
                                     the FMU can be compiled on another platform
    documentation/index.html         what the FMU is, where its numbers come from, its errors

The C sources are the runtime and FMI glue of this package (``sealsim/fmu/c``), the model's C
file and a generated ``config.h`` (value references, start values, parameter bounds,
tables); ``all.c`` includes them all, so one compiler call builds the binary.  The FMI
headers come from FMPy (BSD 2-clause, Modelica Association).

The ``.fmu`` is written through sealsim's one write mechanism, :class:`sealsim.files.ResultFile`:
the target is checked before anything is computed (an existing file is refused unless
``force``, an input file is never the target), it is locked while the FMU is built (a second
build to the same file is refused), the archive is assembled in a temporary folder that is
always removed, and the ``.fmu`` appears only when the build succeeded (a temporary file next
to it, then a link or a rename) -- nothing else is written outside the target.
"""

from __future__ import annotations

import datetime as _dt
import hashlib
import io
import json
import os
import platform
import shutil
import subprocess
import uuid
import zipfile
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

from sealsim.errors import InputError, ModelError, SealsimError
from sealsim.fmu.model_description import ModelSpec, c_variables, model_description_xml
from sealsim.files import ResultFile, json_ready, scratch_folder

__all__ = ["FMI_KINDS", "BuildResult", "FMUCompileError", "FMUDependencyError",
           "build_archive", "check_output", "find_compiler", "platform_folder"]

#: --kind option -> interfaces
FMI_KINDS = {"me": ("me",), "cs": ("cs",), "both": ("me", "cs")}

_C_FILES = ("sealsim_fmu.h", "fmu_runtime.c", "hermite.c", "contact_table.c")
_GLUE = {2: "fmi2_glue.c", 3: "fmi3_glue.c"}
_HEADERS = {2: ("fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h"),
            3: ("fmi3Functions.h", "fmi3FunctionTypes.h", "fmi3PlatformTypes.h")}


class FMUDependencyError(SealsimError):
    """A package the FMU export needs is missing (exit status 1)."""


class FMUCompileError(SealsimError):
    """No C compiler, or the compiler failed; the source FMU was still written.

    Attributes
    ----------
    path : Path
        The FMU that was written (sources, no binary).
    """

    exit_code = 1

    def __init__(self, message: str, path: Path):
        super().__init__(message)
        self.path = path


@dataclass
class BuildResult:
    """What :func:`build_archive` wrote.

    Attributes
    ----------
    path : Path
        The ``.fmu`` file.
    fmi_version : int
    kinds : tuple of str
        "me", "cs".
    binary : str or None
        Path of the binary inside the FMU (None for a source-only FMU).
    report : dict
        Facts about the build (also in ``documentation/build_report.json``).
    """

    path: Path
    fmi_version: int
    kinds: tuple[str, ...]
    binary: str | None
    report: dict = field(default_factory=dict)


def fmpy_module():
    """The fmpy package, or an error that says how to install it."""
    try:
        import fmpy
    except ImportError:
        raise FMUDependencyError(
            "the FMU export needs FMPy (the FMI headers and the FMU validation): install it "
            "with  pip install 'sealsim[fmu]'  (or  pip install fmpy)") from None
    return fmpy


def _fmi_header_folder() -> Path:
    folder = Path(fmpy_module().__file__).parent / "c-code"
    if not (folder / "fmi2Functions.h").is_file():
        raise FMUDependencyError(f"the FMPy installation has no FMI headers in {folder}; "
                                 "reinstall it with  pip install --force-reinstall fmpy")
    return folder


def check_output(out: str | Path, force: bool, inputs: Iterable[str | Path] = ()) -> Path:
    """Check the target of an FMU before anything is computed (:class:`~sealsim.files.ResultFile`).

    The name must end in ``.fmu``; an existing file is refused unless ``force``; a folder in
    its place, one of the input files, or a parent that is not a folder are refused.

    Returns
    -------
    Path
        The target.
    """
    return _result_file(out, force, inputs).requested


def _result_file(out: str | Path, force: bool, inputs: Iterable[str | Path] = ()) -> ResultFile:
    return ResultFile(out, force, inputs, suffix=".fmu")


def platform_folder(fmi_version: int) -> tuple[str, str]:
    """(binaries/ sub-folder, shared-library suffix) of this platform, as FMPy loads them."""
    fmpy = fmpy_module()
    return (fmpy.platform if fmi_version == 2 else fmpy.platform_tuple,
            fmpy.sharedLibraryExtension)


def find_compiler() -> str | None:
    """The C compiler: ``$CC`` if set, else the first of cc, gcc, clang on the PATH."""
    chosen = os.environ.get("CC")
    if chosen:
        return shutil.which(chosen)
    for name in ("cc", "gcc", "clang"):
        found = shutil.which(name)
        if found:
            return found
    return None


def _token(spec: ModelSpec, config: str, fmi_version: int, kinds) -> str:
    """A GUID derived from the generated model (the same model gives the same token)."""
    digest = hashlib.sha256(f"{fmi_version}|{kinds}|{config}".encode()).hexdigest()
    return "{" + str(uuid.UUID(digest[:32])) + "}"


def _config_h(spec: ModelSpec, kinds: tuple[str, ...]) -> str:
    lines = ["/* Generated by sealsim.fmu: the model's variables, parameters and tables. */",
             "#ifndef CONFIG_H", "#define CONFIG_H", "",
             f"#define MODEL_IDENTIFIER {spec.identifier}"]
    if "me" in kinds:
        lines.append("#define MODEL_EXCHANGE")
    if "cs" in kinds:
        lines.append("#define CO_SIMULATION")
    for name, value in spec.defines.items():
        lines.append(f"#define {name} {value if isinstance(value, str) else repr(value)}")
    lines += ["", c_variables(spec), "", spec.tables, "", "#endif", ""]
    return "\n".join(lines)


def _build_description(identifier: str) -> str:
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<fmiBuildDescription fmiVersion="3.0">\n'
            f'  <BuildConfiguration modelIdentifier="{identifier}">\n'
            '    <SourceFileSet language="C99">\n'
            '      <SourceFile name="all.c"/>\n'
            "    </SourceFileSet>\n"
            "  </BuildConfiguration>\n"
            "</fmiBuildDescription>\n")


def _write_sources(folder: Path, spec: ModelSpec, fmi_version: int, kinds) -> str:
    """sources/ of the FMU; returns the instantiation token."""
    sources = folder / "sources"
    sources.mkdir(parents=True)
    package = resources.files("sealsim.fmu").joinpath("c")
    for name in (*_C_FILES, _GLUE[fmi_version], *spec.extra_sources, spec.model_source):
        (sources / name).write_text(package.joinpath(name).read_text("utf-8"), "utf-8")
    headers = _fmi_header_folder()
    for name in _HEADERS[fmi_version]:
        shutil.copyfile(headers / name, sources / name)
    config = _config_h(spec, kinds)
    token = _token(spec, config, fmi_version, kinds)
    config = config.replace("#define MODEL_IDENTIFIER",
                            f'#define INSTANTIATION_TOKEN "{token}"\n#define MODEL_IDENTIFIER', 1)
    (sources / "config.h").write_text(config, "utf-8")
    (sources / "all.c").write_text(
        "/* Compile this one file into the FMU's shared library, e.g.\n"
        f" *   cc -shared -fPIC -O2 -std=c99 all.c -o {spec.identifier}.so -lm */\n"
        f"#define FMI_VERSION {fmi_version}\n"
        f'#include "fmu_runtime.c"\n#include "hermite.c"\n#include "contact_table.c"\n'
        + "".join(f'#include "{name}"\n' for name in spec.extra_sources
                  if name.endswith(".c"))
        + f'#include "{spec.model_source}"\n#include "{_GLUE[fmi_version]}"\n', "utf-8")
    (sources / "buildDescription.xml").write_text(_build_description(spec.identifier), "utf-8")
    return token


def _compile(folder: Path, spec: ModelSpec, fmi_version: int) -> tuple[str | None, str]:
    """Compile sources/all.c into binaries/; (binary path inside the FMU, or None, message)."""
    compiler = find_compiler()
    if compiler is None:
        wanted = os.environ.get("CC")
        return None, (f"the C compiler CC={wanted!r} was not found" if wanted else
                      "no C compiler was found (looked for $CC, cc, gcc, clang)")
    sub, suffix = platform_folder(fmi_version)
    target = folder / "binaries" / sub / f"{spec.identifier}{suffix}"
    target.parent.mkdir(parents=True)
    shared = ["-dynamiclib"] if platform.system() == "Darwin" else ["-shared"]
    command = [compiler, *shared, "-fPIC", "-O2", "-std=c99", "-ffp-contract=off",
               "-fvisibility=hidden", "-I", str(folder / "sources"),
               str(folder / "sources" / "all.c"), "-o", str(target), "-lm"]
    try:
        run = subprocess.run(command, capture_output=True, text=True, timeout=300)
    except (OSError, subprocess.TimeoutExpired) as exc:
        return None, f"the C compiler {compiler} could not be run: {exc}"
    if run.returncode != 0:
        shutil.rmtree(folder / "binaries", ignore_errors=True)
        output = (run.stderr or run.stdout).strip()
        return None, f"the C compiler {compiler} failed:\n{output[-4000:]}"
    return target.relative_to(folder).as_posix(), f"compiled with {compiler}"


def _zip(folder: Path) -> bytes:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(folder.rglob("*")):
            if path.is_file():
                zf.write(path, path.relative_to(folder).as_posix())
    return buffer.getvalue()


def build_archive(spec: ModelSpec, out: str | Path, *, fmi_version: int = 2,
                  kind: str = "both", force: bool = False, compile: bool = True,
                  check: Callable[[Path, str], None] | None = None,
                  document: Callable[[ModelSpec], None] | None = None,
                  inputs: Iterable[str | Path] = ()) -> BuildResult:
    """Generate, compile, validate and write the FMU of a model.

    Parameters
    ----------
    spec : ModelSpec
        The model (variables, C defines, tables, documentation).
    out : path
        The ``.fmu`` file (checked by :func:`check_output` first).
    fmi_version : {2, 3}
    kind : {"me", "cs", "both"}
        Model exchange, co-simulation or both in one FMU.
    force : bool
        Replace an existing file.
    compile : bool
        Compile the binary (False: a source-only FMU, e.g. for another platform).
    check : callable, optional
        ``check(folder, instantiation_token)`` runs on the unpacked FMU after compiling
        (it may add to ``spec.report`` and ``spec.data``, or raise).
    document : callable, optional
        ``document(spec)`` fills ``spec.documentation`` (after the check).
    inputs : iterable of path
        Files the FMU is built from (refused as ``out``).

    Returns
    -------
    BuildResult

    Raises
    ------
    FMUCompileError
        No compiler or a failed compile; the source FMU has been written.
    """
    if fmi_version not in (2, 3):
        raise InputError(f"--fmi {fmi_version!r} is not supported; choose 2 or 3")
    if kind not in FMI_KINDS:
        raise InputError(f"--kind {kind!r} is not allowed; choose me, cs or both")
    kinds = FMI_KINDS[kind]
    result_file = _result_file(out, force, inputs)
    target = result_file.requested
    generated = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    # locked until written; SIGTERM raises like Ctrl-C, so the scratch folder is removed
    with result_file, scratch_folder("sealsim-fmu-") as scratch:
        folder = Path(scratch) / "fmu"
        folder.mkdir()
        token = _write_sources(folder, spec, fmi_version, kinds)
        (folder / "modelDescription.xml").write_text(
            model_description_xml(spec, fmi_version, kinds, token, generated), "utf-8")
        binary, compile_message = (None, "not compiled (source FMU requested)")
        if compile:
            binary, compile_message = _compile(folder, spec, fmi_version)
        if binary is not None and check is not None:
            check(folder, token)
        if document is not None:
            document(spec)
        report = {"model": spec.model_name, "fmi_version": f"{fmi_version}.0",
                  "interfaces": list(kinds), "binary": binary, "compiler": compile_message,
                  "generated": generated, **spec.report}
        docs = folder / "documentation"
        docs.mkdir()
        for name, content in spec.documentation.items():
            (docs / name).write_bytes(content)
        (docs / "build_report.json").write_text(
            json.dumps(json_ready(report, digits=12), indent=2), "utf-8")
        fmpy_module()
        from fmpy.validation import validate_fmu

        problems = validate_fmu(str(folder))
        if problems:
            raise ModelError("the generated FMU is not valid (a sealsim bug, please report "
                             "it): " + "; ".join(problems))
        result_file.write_bytes(_zip(folder))
    result = BuildResult(target, fmi_version, kinds, binary, report)
    if compile and binary is None:
        raise FMUCompileError(
            f"{compile_message}\nThe source FMU was written to {str(target)!r} (C sources and "
            "sources/buildDescription.xml, no binary). Compile it on this machine with a C "
            "compiler, e.g.  python -m fmpy compile " + str(target) + "  (needs CMake), or "
            "set CC to your compiler and build again.", target)
    return result
