"""Seal structural mechanics: axisymmetric hyperelastic FE of a seal in its gland (FElupe) and
characteristic diagrams of the normal force F_N and contact width b (Heipl & Murrenhoff,
IFAS RWTH Aachen).

Pipeline, one concept per module:

* :mod:`.geometry` -- the O-ring section (:class:`ORing`) and glands (:class:`Gland`,
  :class:`SealAssembly`: rod, piston or shaft arrangement, squeeze, walls, metal expansion);
* :mod:`.contour`, :mod:`.profiles` -- any section as a closed contour of lines and arcs
  (checks, fillets, polylines, DXF) and the parametric families (X-ring, rectangular ring,
  U-cup, wiper, DIN 3760 radial lip seal);
* :mod:`.mesh`, :mod:`.profile_mesh` -- quad meshes: the O-ring's O-grid, gmsh (or a
  built-in fallback) for profiles (:func:`mesh_section`);
* :mod:`.material` -- nearly incompressible Mooney–Rivlin with thermal expansion and
  temperature-dependent constants, thermo-viscoelastic Prony/WLF variant;
* :mod:`.loads`, :mod:`.constraints` -- fluid pressure on the wetted surface, anti-rolling
  spring, axial symmetry hold, garter spring;
* :mod:`.model` -- :class:`SealModel` (FElupe region, field, solid body, rigid contacts with
  Coulomb friction, bonded edges);
* :mod:`.solver` -- load path with Newton iterations and automatic cutback (:func:`solve`);
* :mod:`.results` -- F_N, b, pressures, profiles, equilibrium checks (:func:`extract`);
* :mod:`.maps` -- reading characteristic maps (:func:`load_map`, :class:`SealMap`; no FE);
* :mod:`.mapping` -- computing them (:func:`compute_map`);
* :mod:`.case`, :mod:`.build`, :mod:`.run` -- case files, building a model from a case, and
  the orchestration used by the CLI;
* :mod:`.analytic` -- Hertz line contact for checks;
* :mod:`.fingerprint` -- version and fingerprint of the FE model (part of map cache keys).
"""

import importlib

_EXPORTS = {
    "Gland": "geometry", "ORing": "geometry", "SealAssembly": "geometry",
    "Contour": "contour", "SealProfile": "profiles", "xring_profile": "profiles",
    "rectangular_profile": "profiles", "ucup_profile": "profiles",
    "wiper_profile": "profiles", "radial_lip_profile": "profiles", "user_profile": "profiles",
    "mesh_oring": "mesh", "mesh_section": "profile_mesh", "mesh_profile": "profile_mesh",
    "HyperelasticSealMaterial": "material", "ViscoelasticSealMaterial": "material",
    "material_from_elastomer": "material",
    "SealModel": "model", "LoadState": "model", "LoadStep": "solver", "solve": "solver",
    "extract": "results", "SealMap": "maps", "compute_map": "mapping", "load_map": "maps",
}
__all__ = list(_EXPORTS)


def __getattr__(name):
    # lazy: reading a map (sealsim.structure.load_map) must not import FElupe
    if name in _EXPORTS:
        return getattr(importlib.import_module(f"sealsim.structure.{_EXPORTS[name]}"), name)
    raise AttributeError(f"module 'sealsim.structure' has no attribute {name!r}")
