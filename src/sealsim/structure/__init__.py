"""Seal structural mechanics: axisymmetric hyperelastic FE of a seal in its gland (FElupe) and
characteristic diagrams of the normal force F_N and contact width b (seed 001).

Pipeline, one concept per module:

* :mod:`.geometry` -- seal sections (:class:`ORing`) and glands (:class:`Gland`,
  :class:`SealAssembly`: rod or piston arrangement, squeeze, metal expansion);
* :mod:`.mesh` -- quad meshes of sections (:func:`mesh_oring`, :func:`mesh_section`);
* :mod:`.material` -- nearly incompressible Mooney–Rivlin with thermal expansion and
  temperature-dependent constants, thermo-viscoelastic Prony/WLF variant;
* :mod:`.loads`, :mod:`.constraints` -- fluid pressure on the wetted surface, anti-rolling
  spring;
* :mod:`.model` -- :class:`SealModel` (FElupe region, field, solid body, rigid contacts);
* :mod:`.solver` -- load path with Newton iterations and automatic cutback (:func:`solve`);
* :mod:`.results` -- F_N, b, pressures, profiles, equilibrium checks (:func:`extract`);
* :mod:`.maps` -- characteristic maps (:func:`compute_map`, :func:`load_map`, :class:`SealMap`);
* :mod:`.case`, :mod:`.run` -- case files and the orchestration used by the CLI;
* :mod:`.analytic` -- Hertz line contact for checks;
* :mod:`.fingerprint` -- version and fingerprint of the FE model (part of map cache keys).
"""

import importlib

_EXPORTS = {
    "Gland": "geometry", "ORing": "geometry", "SealAssembly": "geometry",
    "mesh_oring": "mesh", "mesh_section": "mesh",
    "HyperelasticSealMaterial": "material", "ViscoelasticSealMaterial": "material",
    "material_from_elastomer": "material",
    "SealModel": "model", "LoadState": "model", "LoadStep": "solver", "solve": "solver",
    "extract": "results", "SealMap": "maps", "compute_map": "maps", "load_map": "maps",
}
__all__ = list(_EXPORTS)


def __getattr__(name):
    # lazy: reading a map (sealsim.structure.load_map) must not import FElupe
    if name in _EXPORTS:
        return getattr(importlib.import_module(f"sealsim.structure.{_EXPORTS[name]}"), name)
    raise AttributeError(f"module 'sealsim.structure' has no attribute {name!r}")
