"""Build the FMUs of a test module once per test session, also when pytest-xdist spreads the
module's tests over several workers (each worker would otherwise build its own copy: the
rotary maps alone take 15 s)."""

from __future__ import annotations

import contextlib
import json
from pathlib import Path

from sealsim.output import json_ready


@contextlib.contextmanager
def _locked(path: Path):
    try:
        import fcntl
    except ImportError:          # no POSIX locks (Windows): every worker builds its own
        yield
        return
    with open(path, "a") as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def build_once(tmp_path_factory, worker_id: str, name: str, build):
    """``build(folder)`` -> a JSON-able result (paths become strings), computed by the first
    worker that asks and read back by the others from the session's shared temporary root."""
    def text(result):
        return json.dumps(json_ready(result), default=str)

    if worker_id == "master":
        return json.loads(text(build(tmp_path_factory.mktemp(name))))
    root = tmp_path_factory.getbasetemp().parent
    folder, done = root / name, root / f"{name}.json"
    with _locked(root / f"{name}.lock"):
        if not done.exists():
            folder.mkdir(exist_ok=True)
            done.write_text(text(build(folder)))
    return json.loads(done.read_text())
