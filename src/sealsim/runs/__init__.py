"""Case file → result folder: the runs behind ``sealsim ... run``, one module per model.

A run reads a case file with its variants, checks the output location before computing,
simulates every variant with the model packages, and writes tables, ``summary.json``, the
resolved case and the figures atomically into the result folder
(:func:`sealsim.output.run_variants`).  This layer sits above the models, next to
:mod:`sealsim.output` and :mod:`sealsim.plotting`: the model packages compute, they never
plot or write result folders.

* :mod:`~sealsim.runs.rotary` -- ``sealsim rotary run``;
* :mod:`~sealsim.runs.pneumatic` -- ``sealsim pneumatic run``;
* :mod:`~sealsim.runs.friction` -- ``sealsim friction run``;
* :mod:`~sealsim.runs.structure` -- ``sealsim structure run`` and ``sealsim structure map``;
* :mod:`~sealsim.runs.calibration` -- ``sealsim friction fit``, ``sealsim rotary fit`` and
  ``sealsim pneumatic compare``;
* :mod:`~sealsim.runs.study` -- ``sealsim study run``.

From Python::

    from sealsim.runs.rotary import run_case_file

    results = run_case_file("examples/rotary/speed_cycle.toml", "results/speed_cycle")
"""
