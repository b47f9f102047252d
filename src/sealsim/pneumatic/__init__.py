"""Pneumatic cylinder simulation coupled with seal friction and contact maps (Heipl & Murrenhoff).

Heipl & Murrenhoff couple three models: a 1-D system simulation of a pneumatic
drive (valve, cylinder chambers, piston), a dynamic friction law per seal (the Θ rate-and-state
law) and characteristic diagrams F_N, b of each seal from FE.  This package is the system side:

* :mod:`.cylinder` -- geometry, piston dynamics, end stops, external load;
* :mod:`.chambers` -- mass and energy balance of the chamber air, wall heat transfer;
* :mod:`.valve` -- ISO 6358 flow, 5/2 and 5/3 spools with switching dynamics, meter-out and
  cushioning restrictions;
* :mod:`.controller` -- PLC command cycles and prescribed-position (test rig) mode;
* :mod:`.seals` -- a seal = a friction law of :mod:`sealsim.friction` + a contact map;
* :mod:`.contact_maps` -- F_N and b: FE maps of :mod:`sealsim.structure` (file or built on
  demand and cached) or an analytic O-ring estimate;
* :mod:`.seal_heating` -- frictional heating of the seals, the tube and the rod;
* :mod:`.simulation` -- the coupled stiff ODE (:func:`simulate`, every variant of a case file:
  :func:`~sealsim.pneumatic.simulation.run_cases`), built from :mod:`.system` (the model of a
  case), :mod:`.rhs` (the compiled right-hand side), :mod:`.integrate` (segments, events,
  the compiled BDF driver, LSODA) and :mod:`.results`;
* :mod:`.case`, :mod:`.summary` -- case files with variants, the summary numbers.

The result folder of ``sealsim pneumatic run`` (tables, summary, figures) is written by
:mod:`sealsim.runs.pneumatic`.  Python API (what that command computes)::

    from sealsim.pneumatic import load_pneumatic_case_file, simulate
    cases = load_pneumatic_case_file("examples/pneumatic/cylinder_32.toml")
    result = simulate(cases["T25C"])          # PneumaticResult
    result.timeseries                         # pandas DataFrame
    result.summary()["extend_time_s"]
"""

from sealsim.pneumatic.case import PneumaticCase, build_seals, load_pneumatic_case_file
from sealsim.pneumatic.contact_maps import AnalyticContactMap, ContactMap, FEContactMap
from sealsim.pneumatic.seals import Seal
from sealsim.pneumatic.results import PneumaticResult
from sealsim.pneumatic.simulation import simulate
from sealsim.pneumatic.system import PneumaticSystem

__all__ = [
    "AnalyticContactMap",
    "ContactMap",
    "FEContactMap",
    "PneumaticCase",
    "PneumaticResult",
    "PneumaticSystem",
    "Seal",
    "build_seals",
    "load_pneumatic_case_file",
    "simulate",
]
