"""Frozen copies of the pre-issue-13 implementation (commit 9cdec80).

* :mod:`.friction_laws` -- the numpy friction laws (pure functions and law classes);
* :mod:`.pneumatic_simulation` -- the pneumatic right-hand side with numpy glue and law objects,
  :func:`~.pneumatic_simulation.simulate_reference`.

The tests compare the compiled kernels and the compiled right-hand side with them (< 1e-9
relative), and ``benchmarks/bench_pneumatic.py`` measures them as the baseline speed.
"""
