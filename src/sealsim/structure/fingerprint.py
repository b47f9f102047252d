"""Version and fingerprint of the FE seal model, for caches of its results.

A characteristic map cached under a hash of its structure case alone would survive a change
of the model that computed it (a new material law, a solver fix) and silently feed stale forces
to the pneumatic model. :func:`model_fingerprint` is therefore part of every cache key of FE
results (:func:`sealsim.pneumatic.contact_maps.build_or_load_fe_map`): it combines

* :data:`FE_MODEL_VERSION`, raised by hand whenever a change is *meant* to change FE results
  (physics or numerics), so the intent is recorded in the history;
* the FElupe version;
* the SHA-256 of the source of everything a map's values depend on: the modules of
  :mod:`sealsim.structure` and :mod:`sealsim.properties.elastomers`, the catalogue reader
  (``catalogue.py``, where present) and ``data/elastomers.toml`` -- so that even a change
  that forgot to raise the version gives a new key (a cosmetic edit costs one rebuild of the
  map, which is cheap compared with a wrong one).

:func:`results_key` is the one key of a structure case's FE results: the map cache's file name
and the kept load paths of an interrupted map build
(:class:`sealsim.structure.mapping._KeptPaths`) both come from it.
"""

from __future__ import annotations

import functools
import hashlib
import json
from importlib import resources
from typing import Any

__all__ = ["FE_MODEL_VERSION", "model_fingerprint", "results_key"]

#: Version of the FE model's results. History: 1 = hyperelastic/viscoelastic Mooney-Rivlin,
#: rubbery thermal expansion; 2 = glassy thermal expansion through the fictive temperature,
#: one modulus-temperature law for FE and analytic maps; 3 = seal profiles, Coulomb friction
#: on the groove walls by default; 4 = the radial lip's sharp edge with a refined contact band,
#: and contact results of bonded profiles mapped to the right loop nodes; 5 = the default
#: X-ring section has the Quad-Ring area 0.8215 W² (valley depth 0.098 W, was 0.08 W); 6 = a
#: cut-back increment grows back after easy increments (solver.GROWTH_FACTOR): cut-back paths
#: end on other increments.
FE_MODEL_VERSION = 6


@functools.lru_cache(maxsize=1)
def model_fingerprint() -> str:
    """Hex digest (16 characters) identifying the FE model that computes maps.

    Examples
    --------
    >>> len(model_fingerprint())
    16
    """
    import felupe

    digest = hashlib.sha256(f"sealsim FE model {FE_MODEL_VERSION}; felupe {felupe.__version__}"
                            .encode())
    structure = resources.files("sealsim.structure")
    properties = resources.files("sealsim.properties")
    # the elastomer module and its catalogue reader (where present) and data
    for folder, wanted in ((structure, None), (properties, {"elastomers.py", "catalogue.py"}),
                           (properties / "data", {"elastomers.toml"})):
        for entry in sorted(folder.iterdir(), key=lambda e: e.name):
            if entry.is_file() and (entry.name in wanted if wanted else
                                    entry.name.endswith(".py")):
                digest.update(entry.name.encode())
                digest.update(entry.read_bytes())
    return digest.hexdigest()[:16]


def results_key(case: Any, *extra: Any) -> str:
    """SHA-256 (hex) of everything FE results of a structure case depend on: the resolved case
    (every field, defaults filled in), the FE model's :func:`model_fingerprint`, the content of
    a compound file the case's material names (not only its path) and ``extra`` (JSON values,
    e.g. the stored profile positions).

    Examples
    --------
    >>> from sealsim.cases import validate_case
    >>> from sealsim.structure.case import StructureCase
    >>> case = validate_case(StructureCase, {
    ...     "seal": {"cord_diameter": "2 mm", "inner_diameter": "12 mm"},
    ...     "gland": {"arrangement": "rod", "sealing_diameter": "12 mm",
    ...               "groove_width": "2.7 mm"}, "load": {"squeeze": [0.1]}})
    >>> key = results_key(case)
    >>> len(key), key == results_key(case), key == results_key(case, [0.0])
    (64, True, False)
    """
    from sealsim.properties.elastomers import compound_file_digest

    text = json.dumps({"case": case.model_dump(mode="json"), "model": model_fingerprint(),
                       "material": compound_file_digest(case.material.elastomer),
                       "extra": list(extra)}, sort_keys=True)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()
