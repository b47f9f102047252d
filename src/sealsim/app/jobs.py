"""Long work of the app (case runs, FE gland checks) in child processes.

Each job gets an unguessable token (:func:`secrets.token_urlsafe`), its own folder inside the
app's work folder and a child process (``spawn``: nothing of the server is shared).  The
browser tab that started a job keeps its token; nothing lists the jobs, so another tab never
sees them.  A job that runs longer than the app's run-time limit is stopped (its process
killed); its folder is removed when the app stops.

The uploaded case is written as ``case.toml`` in the job folder: the name the browser sent is
never used as a path.  The child runs the same code as the command line
(``sealsim.runs.<kind>``) and reports errors with the command line's text
(:func:`sealsim.cli._common.error_parts`).
"""

from __future__ import annotations

import multiprocessing
import queue
import re
import secrets
import shutil
import threading
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from sealsim.output import RESULT_MARKER

__all__ = ["CASE_RUNNERS", "Job", "JobManager", "TOKEN"]

#: Kind of case -> (module of sealsim.runs, function, the command it stands for).
CASE_RUNNERS = {
    "rotary": ("sealsim.runs.rotary", "run_case_file", "sealsim rotary run"),
    "friction": ("sealsim.runs.friction", "run_case_file", "sealsim friction run"),
    "pneumatic": ("sealsim.runs.pneumatic", "run_case_file", "sealsim pneumatic run"),
    "structure": ("sealsim.runs.structure", "run_case_file", "sealsim structure run"),
    "gland": ("sealsim.runs.gland", "check_case_file", "sealsim gland check"),
}

#: A job token: 22 URL-safe characters (128 bits).
TOKEN = re.compile(r"[A-Za-z0-9_-]{22}")

CASE_FILE = "case.toml"
RESULT_FOLDER = "result"


@dataclass
class Job:
    """State of one job, as the browser polls it."""

    token: str
    kind: str
    folder: Path
    started: float = field(default_factory=time.monotonic)
    state: str = "running"          # running, done, failed, stopped
    label: str = ""
    done: float = 0.0
    total: float = 0.0
    error: str = ""
    result: Any = None
    process: Any = None

    def public(self) -> dict[str, Any]:
        return {"state": self.state, "kind": self.kind, "label": self.label,
                "done": self.done, "total": self.total, "error": self.error,
                "elapsed_s": round(time.monotonic() - self.started, 1),
                "result": self.result if self.state == "done" else None}


class JobManager:
    """Starts, watches and stops jobs; at most ``max_running`` at a time.

    Parameters
    ----------
    root : Path
        Work folder (one sub-folder per job).
    timeout : float
        Run-time limit of a job [s].
    max_running : int
        Jobs running at once (the machine's cores); more are refused with a message.
    """

    def __init__(self, root: Path, timeout: float, max_running: int = 2):
        self.root = Path(root)
        self.timeout = float(timeout)
        self.max_running = int(max_running)
        self._jobs: dict[str, Job] = {}
        self._lock = threading.Lock()
        self._context = multiprocessing.get_context("spawn")

    def get(self, token: str) -> Job | None:
        if not isinstance(token, str) or not TOKEN.fullmatch(token):
            return None
        with self._lock:
            return self._jobs.get(token)

    def start(self, kind: str, payload: dict[str, Any], case_text: str | None = None) -> Job:
        """Start a job: ``kind`` "case" (``case_text`` is the uploaded TOML) or "gland_fe"
        (``payload["gland"]`` the gland tables)."""
        from sealsim.errors import InputError

        with self._lock:
            running = sum(j.state == "running" for j in self._jobs.values())
            if running >= self.max_running:
                raise InputError(f"{running} runs are going on already (the app runs at most "
                                 f"{self.max_running} at a time on this machine); wait for "
                                 "one to finish")
            token = secrets.token_urlsafe(16)
            folder = self.root / token
            folder.mkdir(parents=True)
            job = Job(token, kind, folder)
            self._jobs[token] = job
        if case_text is not None:
            (folder / CASE_FILE).write_text(case_text, encoding="utf-8")
        messages = self._context.Queue()
        process = self._context.Process(target=_child, args=(kind, payload, str(folder),
                                                             messages), daemon=True)
        process.start()
        job.process = process
        threading.Thread(target=self._watch, args=(job, messages), daemon=True).start()
        return job

    def _watch(self, job: Job, messages) -> None:
        deadline = job.started + self.timeout
        while True:
            try:
                message = messages.get(timeout=0.2)
            except queue.Empty:
                message = None
            if message is not None:
                what = message[0]
                if what == "progress":
                    job.label, job.done, job.total = message[1], message[2], message[3]
                    continue
                if what == "done":
                    job.result, job.state = message[1], "done"
                else:
                    job.error, job.state = message[1], "failed"
                break
            if not job.process.is_alive():
                job.error = (f"error: the run stopped unexpectedly (exit code "
                             f"{job.process.exitcode})")
                job.state = "failed"
                break
            if time.monotonic() > deadline:
                job.process.kill()
                job.error = (f"stopped after {self.timeout:g} s: the app's run-time limit "
                             "(sealsim app --run-timeout); run the case with the command line "
                             "for longer runs")
                job.state = "stopped"
                break
        job.process.join(timeout=5)

    def files(self, job: Job) -> list[str]:
        """Result files of a finished job, relative to its result folder (posix names); not
        the folder's marker file (:data:`~sealsim.output.RESULT_MARKER`, bookkeeping of
        ``--force``, not a result)."""
        folder = job.folder / RESULT_FOLDER
        if job.state != "done" or not folder.is_dir():
            return []
        return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*")
                      if p.is_file() and not p.is_symlink() and p.name != RESULT_MARKER)

    def result_path(self, job: Job, name: str) -> Path | None:
        """The file ``name`` of a job's results if it is one of :meth:`files`, else None."""
        return job.folder / RESULT_FOLDER / name if name in self.files(job) else None

    def close(self) -> None:
        """Stop every running job and remove the work folder."""
        with self._lock:
            jobs = list(self._jobs.values())
        for job in jobs:
            if job.process is not None and job.process.is_alive():
                job.process.kill()
        shutil.rmtree(self.root, ignore_errors=True)


def _child(kind: str, payload: dict[str, Any], folder: str, messages) -> None:
    """The job's process: run it, report progress, then ``("done", result)`` or
    ``("error", text)``."""
    from sealsim.errors import SealsimError

    last = [0.0]

    def progress(label, done=None, total=None):
        if total is None:  # progress(done, total) of the FE map
            label, done, total = "FE", label, done
        now = time.monotonic()
        if now - last[0] > 0.2 or done >= total:
            last[0] = now
            messages.put(("progress", str(label), float(done), float(total)))

    try:
        if kind == "case":
            result = _run_case(Path(folder), progress)
        elif kind == "gland_fe":
            from sealsim.api import oring_gland

            result = oring_gland(payload["gland"], fe=True, progress=progress)
        else:
            raise ValueError(f"unknown job kind {kind!r}")
        messages.put(("done", _plain(result)))
    except SealsimError as exc:
        from sealsim.cli._common import error_parts

        kind_text, message = error_parts(exc)
        messages.put(("error", f"{kind_text}: {message}"))
    except Exception as exc:  # noqa: BLE001 - the page shows it instead of a dead job
        messages.put(("error", f"error: unexpected failure ({type(exc).__name__}: {exc}); "
                               f"{traceback.format_exc(limit=3)}"))


def _run_case(folder: Path, progress) -> dict[str, Any]:
    """Run the uploaded case like its command line command, into ``folder/result``."""
    import importlib
    import os

    from sealsim.cases import CASE_KINDS, detect_case_kind, load_toml
    from sealsim.errors import InputError

    os.chdir(folder)            # messages name the file as the command line would: case.toml
    data = load_toml(CASE_FILE)
    kind = detect_case_kind(data)
    if kind is None or kind.name not in CASE_RUNNERS:
        known = ", ".join(CASE_RUNNERS)
        what = (f"a {kind.name} case (run it with {kind.command})" if kind is not None else
                "not recognised as any kind of case (its tables: "
                f"{', '.join(sorted(data)) or 'none'}; kinds: "
                f"{', '.join(k.name for k in CASE_KINDS)})")
        raise InputError(f"{CASE_FILE}: this is {what}; the app runs {known} cases")
    module, function, command = CASE_RUNNERS[kind.name]
    run = getattr(importlib.import_module(module), function)
    try:
        run(CASE_FILE, RESULT_FOLDER, False, progress=progress)
    except InputError as exc:
        if "does not exist" not in str(exc):
            raise
        # the upload is the only file in its folder: any other file it names is missing
        raise InputError(f"{exc} (the app runs an uploaded case alone, in a folder of its "
                         "own: a case that refers to other files -- a duty-cycle CSV, a "
                         f"drawing, a structure case -- needs the command line: {command} "
                         f"{CASE_FILE} --out DIR)") from None
    return {"kind": kind.name, "command": command}


def _plain(value):
    """JSON-safe copy (numpy scalars to floats)."""
    from sealsim.output import json_ready

    return json_ready(value)
