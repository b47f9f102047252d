"""Session-wide set-up of the test suite: the expensive builds of tests/session_builds.py."""

import pytest

from session_builds import await_builds, prebuild


def pytest_itemcollected(item):
    """A test that uses a module-scoped fixture runs on the xdist worker of its module's other
    such tests (``--dist loadgroup``): dealt to both, each worker built its own copy of the
    fixture (an FE map, a fit, a rotary run: 5-40 s each).  xdist starts the largest groups
    first.  (Marked as collected: xdist reads the groups in its modifyitems hook.)"""
    info = getattr(item, "_fixtureinfo", None)
    if info is not None and any(defs[-1].scope == "module" and defs[-1].baseid.endswith(".py")
                                for name in info.names_closure
                                if (defs := info.name2fixturedefs.get(name))):
        item.add_marker(pytest.mark.xdist_group(item.module.__name__))


def pytest_configure(config):
    """Refuse ``--dist loadgroup`` where xdist silently ignores the groups: it marks a grouped
    test by a suffix of its node id, which pytest 9.2 no longer keeps (pytest-xdist#1386,
    open for xdist 3.8); each worker would then build the groups' FE maps, fits and browser."""
    from importlib.metadata import version

    def release(name):
        return tuple(int(part) for part in version(name).split(".")[:2] if part.isdigit())

    if (getattr(config.option, "dist", "no") == "loadgroup" and release("pytest") >= (9, 2)
            and release("pytest-xdist") <= (3, 8)):
        raise pytest.UsageError(
            f"pytest {version('pytest')} with pytest-xdist {version('pytest-xdist')} ignores "
            "--dist loadgroup's groups (pytest-xdist#1386): install the test extra's versions "
            "(pip install -e '.[test]')")


@pytest.fixture(scope="session", autouse=True)
def _session_builds(request, tmp_path_factory, worker_id):
    """Under pytest-xdist, start the expensive builds the selected tests need, once, spread
    over the workers (without xdist each fixture builds on first use)."""
    if worker_id != "master":
        prebuild(tmp_path_factory, worker_id, {item.path for item in request.session.items})


@pytest.fixture(scope="module", autouse=True)
def _builds_of_this_module(request, tmp_path_factory, worker_id):
    """Under pytest-xdist, hold a test module (before its module fixtures) until the builds of
    its file are complete: a worker runs other tests while the other worker still builds."""
    if worker_id != "master":
        await_builds(tmp_path_factory, worker_id, request.path)


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
