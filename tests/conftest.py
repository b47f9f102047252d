"""Session-wide set-up of the test suite: the expensive builds of tests/session_builds.py."""

import pytest

from session_builds import prebuild


@pytest.fixture(scope="session", autouse=True)
def _session_builds(request, tmp_path_factory, worker_id):
    """Under pytest-xdist, make the expensive builds the selected tests need once, spread over
    the workers, before the first test (without xdist each fixture builds on first use)."""
    if worker_id != "master":
        prebuild(tmp_path_factory, worker_id, {item.path for item in request.session.items})


@pytest.fixture
def computed_map_paths(monkeypatch):
    """The temperatures [K] of the FE load paths a map build computes in this process, in
    order (sealsim.structure.mapping._map_task counted)."""
    import sealsim.structure.mapping as mapping

    computed: list[float] = []
    real = mapping._map_task
    monkeypatch.setattr(mapping, "_map_task",
                        lambda data, squeeze, temperature, *args: computed.append(temperature)
                        or real(data, squeeze, temperature, *args))
    return computed
