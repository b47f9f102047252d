"""The variables of an FMU and what is generated from them: modelDescription.xml (FMI 2.0 and
3.0) and the variable part of the C ``config.h``.

A model (:mod:`.friction_export`, :mod:`.rotary_export`) lists *all* variables its C code
knows (:class:`Variable`); those with ``exposed=False`` get a value reference and a slot in the
C array but do not appear in modelDescription.xml (the C code ignores them for the law at
hand, e.g. the LuGre parameters of a Θ-law FMU).  Units are SI; each unit is declared with its
SI base-unit exponents and a display unit where one helps (``degC``, ``bar``, ``rpm``).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from xml.sax.saxutils import quoteattr

from sealsim import __version__
from sealsim.units import ZERO_CELSIUS_K

__all__ = ["UNITS", "ModelSpec", "Variable", "c_variables", "model_description_xml",
           "xml_text_problem"]

#: characters XML 1.0 cannot hold: C0 controls other than tab, line feed and carriage return
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def xml_text_problem(text: str) -> str | None:
    """Why ``text`` cannot go into modelDescription.xml (a title, a description), or None.

    Examples
    --------
    >>> xml_text_problem("Piston seal, 32 mm") is None
    True
    >>> xml_text_problem("bad" + chr(1) + "title")
    "'bad\\\\x01title' contains the control character U+0001 at position 3, which an FMU's \
modelDescription.xml cannot hold; remove it"
    """
    found = _NOT_XML.search(text)
    if found is None:
        return None
    return (f"{text!r} contains the control character U+{ord(found.group()):04X} at position "
            f"{found.start()}, which an FMU's modelDescription.xml cannot hold; remove it")

#: unit name -> (SI base-unit exponents, display units (name, factor, offset))
UNITS: dict[str, tuple[dict[str, int], tuple[tuple[str, float, float], ...]]] = {
    "s": ({"s": 1}, ()),
    "m": ({"m": 1}, (("mm", 1e3, 0.0),)),
    "m/s": ({"m": 1, "s": -1}, (("mm/s", 1e3, 0.0),)),
    "m2": ({"m": 2}, (("mm2", 1e6, 0.0),)),
    "m2/s": ({"m": 2, "s": -1}, (("mm2/s", 1e6, 0.0),)),
    "N": ({"kg": 1, "m": 1, "s": -2}, ()),
    "N/m": ({"kg": 1, "s": -2}, ()),
    "N.s/m": ({"kg": 1, "s": -1}, ()),
    "Pa": ({"kg": 1, "m": -1, "s": -2}, (("bar", 1e-5, 0.0),)),
    "Pa.s": ({"kg": 1, "m": -1, "s": -1}, ()),
    "K": ({"K": 1}, (("degC", 1.0, -ZERO_CELSIUS_K),)),
    "K/s": ({"K": 1, "s": -1}, ()),
    "rad/s": ({"rad": 1, "s": -1}, (("rpm", 30.0 / math.pi, 0.0),)),
    "N.m": ({"kg": 1, "m": 2, "s": -2}, ()),
    "W": ({"kg": 1, "m": 2, "s": -3}, ()),
    "kg": ({"kg": 1}, (("g", 1e3, 0.0),)),
    "kg/s": ({"kg": 1, "s": -1}, (("g/s", 1e3, 0.0),)),
    "J": ({"kg": 1, "m": 2, "s": -2}, ()),
    "m/s2": ({"m": 1, "s": -2}, ()),
    "m3/(s.Pa)": ({"kg": -1, "m": 4, "s": 1}, (("dm3/(s.bar)", 1e8, 0.0),)),
    "W/(m2.K)": ({"kg": 1, "s": -3, "K": -1}, ()),
}

_BOUND = {">=": "BOUND_INCLUSIVE", "<=": "BOUND_INCLUSIVE", ">": "BOUND_EXCLUSIVE",
          "<": "BOUND_EXCLUSIVE"}


@dataclass(frozen=True)
class Variable:
    """One scalar variable of an FMU.

    Parameters
    ----------
    name : str
        FMI name (flat naming convention).
    macro : str
        Name of its value-reference macro in C (``VR_<macro>``).
    causality : {"parameter", "input", "output", "local", "independent"}
    description : str
        One line shown by simulation tools.
    unit : str, optional
        Key of :data:`UNITS`; None for dimensionless variables.
    start : float, optional
        Start value (parameters, inputs, states).
    boolean : bool
        A Boolean (stored as 0/1 in C).
    state : bool
        A continuous state (an output whose start value may be set before initialization).
    derivative_of : str, optional
        For ``der(x)``: the name of the state x.
    lower, upper : (str, float), optional
        Bounds checked by the FMU: a parameter's at the end of initialization, an input's
        whenever it is set (refused, not set), e.g. ``(">", 0.0)``; inclusive bounds also
        become the FMI ``min``/``max``.
    relative : bool
        A temperature difference (FMI ``relativeQuantity``: no offset in unit conversion).
    nominal : float, optional
        Typical magnitude (FMI ``nominal``): a solver scales the error tolerance of a
        continuous state with it, so a state of 1e-5 m is not integrated with an absolute
        tolerance meant for values near 1.
    exposed : bool
        Listed in modelDescription.xml.
    """

    name: str
    macro: str
    causality: str
    description: str
    unit: str | None = None
    start: float | None = None
    boolean: bool = False
    state: bool = False
    derivative_of: str | None = None
    lower: tuple[str, float] | None = None
    upper: tuple[str, float] | None = None
    relative: bool = False
    nominal: float | None = None
    exposed: bool = True

    @property
    def variability(self) -> str:
        if self.causality == "parameter":
            return "fixed"
        return "discrete" if self.boolean else "continuous"

    @property
    def initial(self) -> str | None:
        if self.causality == "parameter" or self.state:
            return "exact"
        if self.causality in ("output", "local"):
            return "calculated"
        return None


@dataclass
class ModelSpec:
    """Everything the builder needs to make an FMU of one model.

    Attributes
    ----------
    identifier : str
        FMI model identifier (a C identifier; names the binary).
    model_name, description : str
    model_source : str
        The C model file of the package (``friction_model.c`` or ``rotary_model.c``).
    variables : list of Variable
        All variables, value references in list order (``time`` first).
    defines : dict
        Model-specific C macros of config.h (name -> number or C text).
    tables : str
        C source of the model's tables (arrays and :c:type:`HermiteTable` objects).
    default_experiment : (start, stop, step) [s]
    documentation : dict
        File name -> bytes, written to ``documentation/`` of the FMU (``index.html`` first).
    report : dict
        JSON-friendly facts about the build (sources, table errors, validation).
    data : dict
        Larger results for the documentation only (arrays of a validation run).
    event_indicators : list of str
        Names of the (local, continuous) variables that are the model's event indicators
        (model exchange: the model switches a discrete state when one crosses zero).
    extra_sources : list of str
        Further files of ``sealsim/fmu/c`` the model needs (headers, and C files that
        ``all.c`` includes before the model).
    """

    identifier: str
    model_name: str
    description: str
    model_source: str
    variables: list[Variable]
    defines: dict[str, object] = field(default_factory=dict)
    tables: str = ""
    default_experiment: tuple[float, float, float] = (0.0, 1.0, 1e-3)
    documentation: dict[str, bytes] = field(default_factory=dict)
    report: dict = field(default_factory=dict)
    data: dict = field(default_factory=dict)
    event_indicators: list[str] = field(default_factory=list)
    extra_sources: list[str] = field(default_factory=list)

    def value_reference(self, name: str) -> int:
        """Value reference of a variable by FMI name."""
        for vr, v in enumerate(self.variables):
            if v.name == name:
                return vr
        raise KeyError(name)

    @property
    def states(self) -> list[tuple[int, Variable]]:
        """(value reference, variable) of the exposed continuous states, in state order."""
        return [(vr, v) for vr, v in enumerate(self.variables) if v.state and v.exposed]


def _number(x: float) -> str:
    """A float as XML/C text that reads back exactly."""
    return repr(float(x)) if math.isfinite(x) else "0.0"


def _unit_definitions(spec: ModelSpec) -> str:
    used = sorted({v.unit for v in spec.variables if v.exposed and v.unit})
    lines = ["  <UnitDefinitions>"]
    for name in used:
        base, displays = UNITS[name]
        attrs = " ".join(f'{k}="{e}"' for k, e in base.items())
        lines.append(f"    <Unit name={quoteattr(name)}>")
        lines.append(f"      <BaseUnit {attrs}/>")
        for dname, factor, offset in displays:
            extra = f' offset="{_number(offset)}"' if offset else ""
            lines.append(f"      <DisplayUnit name={quoteattr(dname)} "
                         f'factor="{_number(factor)}"{extra}/>')
        lines.append("    </Unit>")
    lines.append("  </UnitDefinitions>")
    return "\n".join(lines) if used else ""


def _type_attributes(v: Variable, spec: ModelSpec, fmi_version: int) -> str:
    attrs = []
    if v.unit:
        attrs.append(f"unit={quoteattr(v.unit)}")
        displays = UNITS[v.unit][1]
        if displays:
            attrs.append(f"displayUnit={quoteattr(displays[0][0])}")
    if v.relative:
        attrs.append('relativeQuantity="true"')
    if v.lower and v.lower[0] == ">=":
        attrs.append(f'min="{_number(v.lower[1])}"')
    if v.upper and v.upper[0] == "<=":
        attrs.append(f'max="{_number(v.upper[1])}"')
    if v.nominal is not None:
        attrs.append(f'nominal="{_number(v.nominal)}"')
    if v.derivative_of is not None:
        state_vr = spec.value_reference(v.derivative_of)
        if fmi_version == 2:
            exposed = [x for x in spec.variables if x.exposed]
            index = 1 + exposed.index(spec.variables[state_vr])
            attrs.append(f'derivative="{index}"')
        else:
            attrs.append(f'derivative="{state_vr}"')
    return " ".join(attrs)


def _start(v: Variable) -> str | None:
    if v.start is None or v.initial == "calculated":
        return None
    if v.boolean:
        return "true" if v.start else "false"
    return _number(v.start)


def model_description_xml(spec: ModelSpec, fmi_version: int, kinds: tuple[str, ...],
                          token: str, generated: str) -> str:
    """modelDescription.xml of an FMI 2.0 or 3.0 FMU.

    Parameters
    ----------
    spec : ModelSpec
    fmi_version : {2, 3}
    kinds : tuple of {"me", "cs"}
        Interfaces the FMU provides.
    token : str
        GUID (FMI 2) / instantiation token (FMI 3), also compiled into the binary.
    generated : str
        Generation date and time (ISO 8601, UTC).
    """
    exposed = [(vr, v) for vr, v in enumerate(spec.variables) if v.exposed]
    tool = f"sealsim {__version__}"
    head = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        "<fmiModelDescription",
        f'  fmiVersion="{"2.0" if fmi_version == 2 else "3.0"}"',
        f"  modelName={quoteattr(spec.model_name)}",
        f"  description={quoteattr(spec.description)}",
        f"  generationTool={quoteattr(tool)}",
        f'  generationDateAndTime="{generated}"',
        '  variableNamingConvention="flat"',
    ]
    if fmi_version == 2:
        head += [f'  guid="{token}"',
                 f'  numberOfEventIndicators="{len(spec.event_indicators)}">']
    else:
        head += [f'  instantiationToken="{token}">']
    body = []
    ident = quoteattr(spec.identifier)
    if fmi_version == 2:
        sources = '    <SourceFiles>\n      <File name="all.c"/>\n    </SourceFiles>'
        common = ('canNotUseMemoryManagementFunctions="true" canGetAndSetFMUstate="true" '
                  'canSerializeFMUstate="true"')
        if "me" in kinds:
            body.append(f"  <ModelExchange modelIdentifier={ident} {common}>\n{sources}\n"
                        "  </ModelExchange>")
        if "cs" in kinds:
            body.append(f"  <CoSimulation modelIdentifier={ident} "
                        f'canHandleVariableCommunicationStepSize="true" {common}>\n'
                        f"{sources}\n  </CoSimulation>")
    else:
        common = 'canGetAndSetFMUState="true" canSerializeFMUState="true"'
        if "me" in kinds:
            body.append(f"  <ModelExchange modelIdentifier={ident} {common}/>")
        if "cs" in kinds:
            body.append(f"  <CoSimulation modelIdentifier={ident} {common} "
                        'canHandleVariableCommunicationStepSize="true"/>')
    units = _unit_definitions(spec)
    if units:
        body.append(units)
    body.append("  <LogCategories>\n"
                '    <Category name="logEvents" description="table ranges entered again"/>\n'
                '    <Category name="logStatusWarning" description="inputs clipped to a '
                'table"/>\n'
                '    <Category name="logStatusError" description="invalid parameters or '
                'inputs"/>\n'
                "  </LogCategories>")
    start, stop, step = spec.default_experiment
    body.append(f'  <DefaultExperiment startTime="{_number(start)}" stopTime="{_number(stop)}" '
                f'stepSize="{_number(step)}"/>')

    body.append("  <ModelVariables>")
    for vr, v in exposed:
        common_attrs = (f"name={quoteattr(v.name)} valueReference=\"{vr}\" "
                        f"description={quoteattr(v.description)} "
                        f'causality="{v.causality}" variability="{v.variability}"')
        if v.initial is not None and v.causality != "input":
            common_attrs += f' initial="{v.initial}"'
        start_value = _start(v)
        type_attrs = "" if v.boolean else _type_attributes(v, spec, fmi_version)
        if fmi_version == 2:
            kind = "Boolean" if v.boolean else "Real"
            inner = " ".join(x for x in (type_attrs, f'start="{start_value}"'
                                         if start_value is not None else "") if x)
            body.append(f"    <ScalarVariable {common_attrs}>\n"
                        f"      <{kind}{' ' + inner if inner else ''}/>\n"
                        "    </ScalarVariable>")
        else:
            kind = "Boolean" if v.boolean else "Float64"
            attrs = " ".join(x for x in (common_attrs, type_attrs, f'start="{start_value}"'
                                         if start_value is not None else "") if x)
            body.append(f"    <{kind} {attrs}/>")
    body.append("  </ModelVariables>")

    outputs = [vr for vr, v in exposed if v.causality == "output"]
    derivatives = [vr for vr, v in exposed if v.derivative_of is not None]
    initial = [vr for vr, v in exposed
               if (v.causality == "output" and v.initial == "calculated")
               or v.derivative_of is not None]
    index = {vr: i + 1 for i, (vr, _) in enumerate(exposed)}
    body.append("  <ModelStructure>")
    if fmi_version == 2:
        for tag, vrs in (("Outputs", outputs), ("Derivatives", derivatives),
                         ("InitialUnknowns", initial)):
            if vrs:
                body.append(f"    <{tag}>")
                body += [f'      <Unknown index="{index[vr]}"/>' for vr in vrs]
                body.append(f"    </{tag}>")
    else:
        body += [f'    <Output valueReference="{vr}"/>' for vr in outputs]
        body += [f'    <ContinuousStateDerivative valueReference="{vr}"/>' for vr in derivatives]
        body += [f'    <InitialUnknown valueReference="{vr}"/>' for vr in initial]
        body += [f'    <EventIndicator valueReference="{spec.value_reference(name)}"/>'
                 for name in spec.event_indicators]
    body.append("  </ModelStructure>")
    return "\n".join(head + body + ["</fmiModelDescription>", ""])


def _c_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def c_variables(spec: ModelSpec) -> str:
    """The variable part of config.h: value references, states, variable table, starts."""
    variables = spec.variables
    lines = [f"#define NVARS {len(variables)}"]
    for vr, v in enumerate(variables):
        lines.append(f"#define VR_{v.macro} {vr}")
    states = spec.states
    lines.append(f"#define NSTATES {len(states)}")
    lines.append(f"#define NEVENT_INDICATORS {len(spec.event_indicators)}")
    state_vrs = [str(vr) for vr, _ in states] or ["0"]
    deriv_vrs = []
    for _, s in states:
        der = [vr for vr, v in enumerate(variables) if v.derivative_of == s.name]
        deriv_vrs.append(str(der[0]) if der else "-1")      # co-simulation only
    lines.append(f"static const int STATE_VR[] = {{{', '.join(state_vrs)}}};")
    lines.append(f"static const int DERIVATIVE_VR[] = {{{', '.join(deriv_vrs or ['0'])}}};")
    for i, (_, s) in enumerate(states):
        lines.append(f"#define STATE_{s.macro} {i}")
    causality = {"parameter": "CAUSALITY_PARAMETER", "input": "CAUSALITY_INPUT",
                 "output": "CAUSALITY_OUTPUT", "local": "CAUSALITY_LOCAL",
                 "independent": "CAUSALITY_INDEPENDENT"}
    lines.append("static const VariableInfo VARIABLES[NVARS] = {")
    for v in variables:
        if not v.exposed:
            lines.append("    {NULL, \"\", CAUSALITY_LOCAL, 0, SET_NEVER, BOUND_NONE, 0.0, "
                         "BOUND_NONE, 0.0},")
            continue
        settable = ("SET_ALWAYS" if v.causality == "input" else
                    "SET_BEFORE_INIT" if v.causality == "parameter" or v.state else "SET_NEVER")
        lower = (_BOUND[v.lower[0]], _number(v.lower[1])) if v.lower else ("BOUND_NONE", "0.0")
        upper = (_BOUND[v.upper[0]], _number(v.upper[1])) if v.upper else ("BOUND_NONE", "0.0")
        lines.append(f"    {{{_c_string(v.name)}, {_c_string(v.unit or '1')}, "
                     f"{causality[v.causality]}, {int(v.boolean)}, {settable}, {lower[0]}, "
                     f"{lower[1]}, {upper[0]}, {upper[1]}}},")
    lines.append("};")
    starts = ", ".join(_number(v.start if v.start is not None else 0.0) for v in variables)
    lines.append(f"static const double START_VALUES[NVARS] = {{{starts}}};")
    return "\n".join(lines)
