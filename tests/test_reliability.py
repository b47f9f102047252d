"""Reliability of every command that writes results (issue 9).

Each reproduction of the issue is a test: it asserts the exit code, one clear message and that
nothing outside ``--out`` changed.  Cases are tiny (a 0.2 s friction bench, validation errors
that stop before any simulation) so the whole file runs in a few seconds; the two tests with
real concurrent processes and a real SIGTERM start short Python subprocesses.
"""

from __future__ import annotations

import errno
import json
import os
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from sealsim.cases import check_variant_name, expand_variants, validate_case
from sealsim.cli import app
from sealsim.errors import InputError, ResultExistsError, SealsimError
from sealsim.output import RESULT_MARKER, ResultFolder, json_ready, run_variants

ROOT = Path(__file__).parents[1]
EXAMPLES = ROOT / "examples"
RUNNER = CliRunner()

TINY_FRICTION = """\
title = "tiny"
[friction]
law = "lugre"
parameter_set = "canudas1995"
[bench]
mode = "velocity"
duration = "0.2 s"
time_step = "1 ms"
velocity = { kind = "harmonic", mean = "1 mm/s", amplitude = "1 mm/s", angular_frequency = "10 rad/s" }
"""


def tree(path: Path) -> dict[str, bytes | None]:
    """Every entry below ``path`` (hidden ones too, but not the marker of result folders) with
    its content (None for folders)."""
    return {str(p.relative_to(path)): (None if p.is_dir() else p.read_bytes())
            for p in sorted(path.rglob("*")) if p.name != RESULT_MARKER}


def old_results(out: Path, text: str) -> None:
    """A result folder ``out`` an earlier run wrote: ``old.txt`` holding ``text``."""
    with ResultFolder(out) as folder:
        folder.write_text("old.txt", text)


def cli(*args, **kwargs):
    result = RUNNER.invoke(app, [str(a) for a in args], **kwargs)
    return result, " ".join(result.output.split())


def one_message(text: str, kind: str = "input error") -> None:
    assert text.count(f"{kind}:") == 1 and "Traceback" not in text, text


@pytest.fixture
def tiny_friction(tmp_path):
    case = tmp_path / "tiny.toml"
    case.write_text(TINY_FRICTION)
    return case


# -- 1. variant names never leave --out ---------------------------------------------------------
TRAVERSAL = {
    "rotary": (EXAMPLES / "rotary" / "sump_volume.toml", 'environment.sump_volume = "1 L"'),
    "pneumatic": (EXAMPLES / "pneumatic" / "cylinder_32.toml", 'title = "x"'),
    "structure": (EXAMPLES / "structure" / "oring_rod.toml", 'title = "x"'),
    "friction": (EXAMPLES / "friction" / "lugre_hysteresis.toml", 'title = "x"'),
}


@pytest.mark.parametrize("command", sorted(TRAVERSAL))
@pytest.mark.parametrize("name", ["a/../../../victim", "../../escaped", "/tmp/abs", ".hidden",
                                  "sp ace"])
def test_variant_names_that_would_leave_out_are_refused(command, name, tmp_path):
    example, override = TRAVERSAL[command]
    case = tmp_path / "case.toml"
    case.write_text(example.read_text() + f'\n[variants."{name}"]\n{override}\n')
    (tmp_path / "victim.png").write_text("precious")
    before = tree(tmp_path)
    result, text = cli(command, "run", case, "--out", tmp_path / "out" / "run")
    assert result.exit_code == 2, text
    one_message(text)
    assert f"variant name {name!r} is not allowed" in text
    assert tree(tmp_path) == before


def test_every_writer_refuses_names_that_leave_the_staging_folder(tmp_path):
    (tmp_path / "elsewhere").mkdir()
    with ResultFolder(tmp_path / "run") as folder:
        os.symlink(tmp_path / "elsewhere", folder.staging / "link")
        for bad in ["../x.txt", "/etc/x", "a/../../x", "", "link/x.txt", "a\\..\\x"]:
            with pytest.raises(InputError, match="would leave the result folder"):
                folder.write_text(bad, "x")
        folder.write_text("variant/ok.txt", "fine")
    assert tree(tmp_path / "elsewhere") == {}
    assert (tmp_path / "run" / "variant" / "ok.txt").read_text() == "fine"


@given(st.text(max_size=70))
def test_an_accepted_variant_name_is_one_plain_file_name(name):
    try:
        check_variant_name(name)
    except InputError:
        return
    assert Path(name).name == name and not name.startswith(".") and name not in ("", "..")
    assert not {"/", "\\", "\x00"} & set(name)


SEGMENTS = st.sampled_from(["a", "b", "..", ".", "x y", "run"])


@settings(max_examples=60, deadline=None, suppress_health_check=[
    HealthCheck.function_scoped_fixture])
@given(name=st.text(min_size=0, max_size=12) | st.sampled_from(["..", "a/../..", "/etc"]),
       out_parts=st.lists(SEGMENTS, min_size=1, max_size=4), check_name=st.booleans())
def test_nothing_is_ever_written_outside_the_target(tmp_path, monkeypatch, name, out_parts,
                                                    check_name):
    """Any variant name and any --out path: the run is refused, or it writes only inside --out.

    Half of the examples skip the variant-name check, so the writers' own guard
    (:meth:`ResultFolder.file`) is the one under test."""
    sandbox = Path(tempfile.mkdtemp(dir=tmp_path))  # a fresh one per example
    cwd = sandbox / "p" / "q" / "r" / "s"  # four levels: '..' never leaves the sandbox
    cwd.mkdir(parents=True)
    (cwd / "case.toml").write_text("x")
    monkeypatch.chdir(cwd)
    out = Path(*out_parts)
    before = tree(sandbox)
    try:
        if check_name:
            check_variant_name(name)
        run_variants({name: 1}, out, lambda n, case, report: case,
                     lambda folder, results: [folder.write_text(f"cycle_{n}.png", "png")
                                              for n in results],
                     inputs=[cwd / "case.toml"])
    except SealsimError:
        assert tree(sandbox) == before  # refused: nothing changed anywhere
        return
    target = out.resolve()
    after = tree(sandbox)
    changed = {p for p in set(before) | set(after) if before.get(p, 0) != after.get(p, 0)}
    for path in changed:
        full = (sandbox / path).resolve()
        assert full == target or target in full.parents or full in target.parents, path


# -- 2. concurrent runs and --force -------------------------------------------------------------
HELD_FRICTION = textwrap.dedent("""
    import sys, time
    from pathlib import Path
    import sealsim.runs.friction as study
    real = study.run_friction_case
    def slow(*args, **kwargs):     # hold the run until the test says go (at most 60 s)
        end = time.monotonic() + 60
        while sys.argv[1] != "-" and not Path(sys.argv[1]).exists() and time.monotonic() < end:
            time.sleep(0.02)
        return real(*args, **kwargs)
    study.run_friction_case = slow
    from sealsim.cli import app
    app(sys.argv[2:])
""")

SLOW_WRITER = textwrap.dedent("""
    import sys, time
    from pathlib import Path
    import sealsim.output as output
    real = output.ResultFolder.write_text
    def slow(self, name, text):
        path = real(self, name, text)
        Path(sys.argv[1]).touch()      # tell the test that writing has started
        time.sleep(30)
        return path
    output.ResultFolder.write_text = slow
    from sealsim.cli import app
    app(sys.argv[2:])
""")


def _spawn(script: str, *args) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-c", script, *map(str, args)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _wait_for(path: Path, proc: subprocess.Popen, timeout: float = 60.0) -> None:
    end = time.monotonic() + timeout
    while not path.exists():
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() < end, f"{path} did not appear"
        time.sleep(0.05)


def test_two_concurrent_runs_to_one_out_the_second_is_refused(tiny_friction, tmp_path):
    out = tmp_path / "out"
    go = tmp_path.parent / f"{tmp_path.name}.go"
    first = _spawn(HELD_FRICTION, go, "friction", "run", tiny_friction, "--out", out, "-q")
    _wait_for(tmp_path / ".out.lock", first)
    second = _spawn(HELD_FRICTION, "-", "friction", "run", tiny_friction, "--out", out, "-q",
                    "--force")
    _, err2 = second.communicate(timeout=60)
    go.touch()  # the first run may finish now
    _, err1 = first.communicate(timeout=60)
    assert second.returncode == 2, err2
    assert "being written by another sealsim run" in " ".join(err2.split())
    assert first.returncode == 0, err1
    summary = json.loads((out / "summary.json").read_text())
    assert summary["title"] == "tiny"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out", "tiny.toml"]  # no lock left


def test_force_replaces_only_results_that_existed_when_the_run_started(tmp_path):
    out = tmp_path / "run"
    late = ResultFolder(out, force=True)   # starts while out is empty
    with ResultFolder(out) as other:        # another run commits meanwhile
        other.write_text("theirs.txt", "theirs")
    with pytest.raises(ResultExistsError, match="written by another run"):
        with late as folder:
            folder.write_text("mine.txt", "mine")
    assert tree(out) == {"theirs.txt": b"theirs"}


# -- 3. signals ---------------------------------------------------------------------------------
@pytest.mark.parametrize("force", [False, True])
def test_sigterm_while_writing_leaves_out_unchanged(tiny_friction, tmp_path, force):
    out = tmp_path / "out"
    if force:
        old_results(out, "old results")
    before = tree(tmp_path)
    started = tmp_path.parent / f"{tmp_path.name}.started"
    proc = _spawn(SLOW_WRITER, started, "friction", "run", tiny_friction, "--out", out, "-q",
                  *(["--force"] if force else []))
    _wait_for(started, proc)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 143, err
    assert "terminated (SIGTERM): no results were written" in " ".join(err.split())
    assert "Traceback" not in err
    assert tree(tmp_path) == before  # no staging folder, no lock, old results intact


def test_interrupt_after_commit_says_the_new_results_were_written(tiny_friction, tmp_path,
                                                                  monkeypatch):
    out = tmp_path / "out"
    old_results(out, "old")
    import sealsim.output as output

    real = output.shutil.rmtree

    def rmtree_with_ctrl_c(path, *args, **kwargs):
        if str(path).endswith(".old"):  # deleting the replaced results: press Ctrl-C now
            # what Python does when SIGINT arrives: call the handler installed for it (here the
            # commit's deferring one).  Called directly, not through os.kill: a process-directed
            # signal may reach another thread and be handled after a sleep of any length, and
            # under pytest-xdist that made this test fail once in a loaded run
            signal.getsignal(signal.SIGINT)(signal.SIGINT, None)
        return real(path, *args, **kwargs)

    monkeypatch.setattr(output.shutil, "rmtree", rmtree_with_ctrl_c)
    # Ctrl-C as in a terminal: Python's own SIGINT handler, whatever an earlier test of this
    # worker left installed (the suspect when this test exited 0 in 2 of 5 full xdist runs;
    # not confirmed: a full run checking the handler around every test found it unchanged)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        result, text = cli("friction", "run", tiny_friction, "--out", out, "--force", "-q")
    finally:
        signal.signal(signal.SIGINT, previous)
    assert result.exit_code == 130, text
    assert "interrupted after the results were written" in text
    assert "no results were written" not in text
    assert (out / "summary.json").exists() and not (out / "old.txt").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out", "tiny.toml"]  # no .old left


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_stale_staging_of_dead_processes_is_cleaned_and_a_lost_backup_restored(tmp_path):
    pid = _dead_pid()
    stale = tmp_path / f".run.{pid}.abcd1234.partial"
    stale.mkdir()
    (stale / "half.csv").write_text("t\n")
    backup = tmp_path / f".run.{pid}.old"  # died between moving old results aside and commit
    backup.mkdir()
    (backup / "summary.json").write_text("old")
    alive = tmp_path / f".run.{os.getppid()}.abcd1234.partial"  # a live process: untouched
    alive.mkdir()
    with pytest.raises(ResultExistsError, match="restored"):  # old results back: refused
        with ResultFolder(tmp_path / "run"):
            pass
    assert not stale.exists() and not backup.exists() and alive.exists()
    assert (tmp_path / "run" / "summary.json").read_text() == "old"


# -- 4. failures while writing and bad locations --------------------------------------------------
@pytest.mark.parametrize("force", [False, True])
def test_full_disk_gives_one_message_and_removes_the_staging(tiny_friction, tmp_path,
                                                             monkeypatch, force):
    import sealsim.output as output

    out = tmp_path / "out"
    if force:
        old_results(out, "old results")
    before = tree(tmp_path)
    real = output.atomic_write_bytes

    def full(path, data):
        if Path(path).name == "summary.json":
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
        return real(path, data)

    monkeypatch.setattr(output, "atomic_write_bytes", full)
    result, text = cli("friction", "run", tiny_friction, "--out", out, "-q",
                       *(["--force"] if force else []))
    assert result.exit_code == 1, text
    one_message(text, "error")
    assert (f"cannot write result file '{out / 'summary.json'}': No space left on device"
            .replace(" ", "") in text.replace(" ", ""))  # long paths wrap anywhere
    assert tree(tmp_path) == before


@pytest.mark.parametrize("where", ["file", "under_file", "dot", "case_inside"])
def test_bad_output_location_is_refused_before_any_simulation(where, tiny_friction, tmp_path,
                                                               monkeypatch):
    import sealsim.runs.friction as study

    monkeypatch.setattr(study, "run_friction_case", lambda *a, **k: pytest.fail("simulated"))
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a_file").write_text("keep")
    case = tiny_friction
    out, message = {
        "file": ("a_file", "is a file"),
        "under_file": ("a_file/run", "is a file"),
        "dot": (".", "is the current folder"),
        "case_inside": ("inside", "lies inside the output folder"),
    }[where]
    if where == "case_inside":
        (tmp_path / "inside").mkdir()
        case = tmp_path / "inside" / "tiny.toml"
        case.write_text(TINY_FRICTION)
    before = tree(tmp_path)
    result, text = cli("friction", "run", case, "--out", out, "--force", "-q")
    assert result.exit_code == 2, text
    one_message(text)
    assert message in text
    assert tree(tmp_path) == before


def test_unwritable_location_is_refused_before_any_simulation(tmp_path, monkeypatch):
    real = os.access
    monkeypatch.setattr(os, "access", lambda path, mode: False if Path(path) == tmp_path
                        else real(path, mode))  # as root, chmod alone would not stop writing
    with pytest.raises(InputError, match="no write permission"):
        run_variants({"a": 1}, tmp_path / "run", lambda *a: pytest.fail("simulated"),
                     lambda folder, results: None)
    assert tree(tmp_path) == {}


def test_warnings_while_writing_plots_do_not_reach_the_user(tmp_path):
    import warnings

    def write(folder, results):
        warnings.warn("Attempting to set identical low and high xlims", UserWarning)
        folder.write_text("a.txt", "a")

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        run_variants({"a": 1}, tmp_path / "run", lambda *a: 1, write)
    assert caught == []
    assert tree(tmp_path / "run") == {"a.txt": b"a"}


# -- 5. inputs checked before anything is written --------------------------------------------------
ROTARY_CSV_CASE = """\
[seal]
shaft_diameter = "80 mm"
[duty]
csv = "duty.csv"
"""


@pytest.mark.parametrize("content, message", [
    ("time_s,speed_rpm\n0,100\n0,200\n", "every row is at time 0"),
    ("time_s,speed_rpm\n", "only 0 data rows; it needs at least 2"),
    ("\ufefftime_s,speed_rpm\n", "only 0 data rows; it needs at least 2"),  # BOM: header found
    # a header that states no unit: the numbers could be anything
    ("speed,rpm\n0,1\n60,1\n", "column 1 (time): no unit is given and its header 'speed' "
                                 "states none"),
    ("t [s],n\n0,1\n60,1\n", "column 2 (speed): no unit is given and its header 'n'"),
    ("t [s],n [Hz]\n0,1\n60,1\n", "'Hz' is ambiguous for a rotational speed"),
    ("t [s],T [degC]\n0,1\n60,1\n", "'degC' is not a unit of speed"),
    ("t [s],n [rpm]\n1,1\n60,1\n", "the time must start at 0 (the first row has 1 s)"),
    (b"\x7fELF\x02\x01\x00\x00\xff\xfe", "is not a text file"),
    ("time_s,speed_rpm\n0,100\n2000000,100\n", "raise duty.max_duration"),
    ("t [s],n [1/min]\n0,100\n60,50000\n", "within 0-47746 rpm"),
    (None, "is a folder"),
    # the row and column of a bad cell (the message gave neither, or Python's float() text)
    ("time_s,speed_rpm\n0,100\n60,abc\n", "row 3, column 2 (speed): 'abc' is not a number"),
    ("time_s,speed_rpm\n0,100\n60\n", "row 3: has 1 columns, column 2 (speed) is missing"),
    ("time_s,speed_rpm\n0,100\nnan,1\n", "row 3, column 1 (time): 'nan' is not a finite"),
    ("time_s,speed_rpm\n0,1\n60,2\n30,3\n", "row 4, column 1 (time): time 30 after 60"),
    ("time_s;speed_rpm\n0;1\n60;1\n", "set delimiter = ';'"),
])
def test_bad_duty_csv_is_one_message_and_writes_nothing(content, message, tmp_path):
    (tmp_path / "case.toml").write_text(ROTARY_CSV_CASE)
    csv = tmp_path / "duty.csv"
    if content is None:
        csv.mkdir()
    elif isinstance(content, bytes):
        csv.write_bytes(content)
    else:
        csv.write_text(content, encoding="utf-8")
    before = tree(tmp_path)
    result, text = cli("rotary", "run", tmp_path / "case.toml", "--out", tmp_path / "out")
    assert result.exit_code == 2, text
    one_message(text)
    assert "duty" in text and message in text
    assert tree(tmp_path) == before


def test_duty_steps_longer_than_the_limit_name_the_field_to_raise():
    from sealsim.rotary.case import RotaryCase

    steps = [{"speed": "100 rpm", "duration": "9e5 s"}] * 2
    data = {"seal": {"shaft_diameter": "80 mm"}, "duty": {"steps": steps}}
    with pytest.raises(InputError, match=r"duty: the steps last 1.8e\+06 s .*raise "
                                         r"duty.max_duration"):
        expand_variants(RotaryCase, data)
    data["duty"]["max_duration"] = "2e6 s"
    assert expand_variants(RotaryCase, data)["base"].duty.max_duration == 2e6


def test_duty_csv_with_bom_and_no_plateau_is_read():
    from sealsim.rotary.case import _read_duty_csv

    path = Path(os.environ.get("TMPDIR", "/tmp")) / f"bom_{os.getpid()}.csv"
    path.write_text("\ufefftime_s,speed_rpm\n0,0\n60,600\n120,1200\n", encoding="utf-8")
    try:
        times, speeds, steps = _read_duty_csv(path)
    finally:
        path.unlink()
    assert times.tolist() == [0.0, 60.0, 120.0]
    assert steps == [(0.0, 120.0)]  # a ramp only: summarised as one step, not none


def test_duty_csv_reads_the_units_its_header_states(tmp_path):
    # A rig's trace as German software writes it: semicolons, decimal commas, quoted names,
    # minutes and U/min (revolutions per minute, DIN 1301); the same cycle as time_s/speed_rpm.
    from sealsim.rotary.case import _read_duty_csv

    german = tmp_path / "zyklus.csv"
    german.write_text('"Zeit [min]";"Drehzahl [U/min]"\n0;0\n0,5;1000\n1,5;1000\n',
                      encoding="cp1252")
    plain = tmp_path / "cycle.csv"
    plain.write_text("time_s,speed_rpm\n0,0\n30,1000\n90,1000\n")
    times, speeds, steps = _read_duty_csv(german, delimiter=";", decimal=",")
    reference = _read_duty_csv(plain)
    np.testing.assert_allclose(times, reference[0], rtol=1e-12)
    np.testing.assert_allclose(speeds, reference[1], rtol=1e-12)
    assert speeds[-1] == pytest.approx(1000 * np.pi / 30, rel=1e-12)  # 1000 rpm in rad/s
    assert steps == reference[2] == [(30.0, 90.0)]
    # columns chosen by name, anywhere in the file
    logged = tmp_path / "log.csv"
    logged.write_text("T [degC],n [rpm],t [s]\n80,0,0\n80,500,60\n")
    times, speeds, _ = _read_duty_csv(logged, time_column="t [s]", speed_column="n [rpm]")
    assert times.tolist() == [0.0, 60.0] and speeds[-1] == pytest.approx(500 * np.pi / 30)


def test_duty_csv_options_of_a_case_reach_the_reader(tmp_path):
    # the [duty] fields delimiter/decimal/columns are read by a run, not only by the function
    (tmp_path / "zyklus.csv").write_text("Zeit [s];Drehzahl [1/min]\n0;100\n60,0;100\n")
    case = tmp_path / "case.toml"
    case.write_text(ROTARY_CSV_CASE.replace('csv = "duty.csv"', 'csv = "zyklus.csv"\n'
                                            'delimiter = ";"\ndecimal = ","'))
    from sealsim.rotary.simulation import load_rotary_case

    loaded = load_rotary_case(case)["base"]
    times, speeds, _ = loaded.duty_cycle().profile(tmp_path)
    assert times.tolist() == [0.0, 60.0] and speeds[0] == pytest.approx(100 * np.pi / 30)
    with pytest.raises(InputError, match="decimal = ',' needs another delimiter"):
        validate_case(type(loaded), {"seal": {"shaft_diameter": "80 mm"},
                                     "duty": {"csv": "x.csv", "decimal": ","}})


def _pneumatic(tmp_path, *edits):
    text = (EXAMPLES / "pneumatic" / "cylinder_32.toml").read_text()
    for old, new in edits:
        assert old in text
        text = text.replace(old, new, 1)
    case = tmp_path / "case.toml"
    case.write_text(text)
    return case


@pytest.mark.parametrize("edits, fields", [
    ([('sample_interval = "1 ms"', 'sample_interval = "1 ns"')],
     ["output.max_samples", "output.sample_interval"]),
    ([('duration = "4 s"', 'duration = "1e6 s"')], ["solver.max_duration"]),
    ([('temperature = "25 degC"          # ambient and supply air', 'temperature = "5000 K"\n'
       'supply_temperature = "-100 degC"'),
      ('temperature = "25 degC"          # barrel', 'temperature = "5000 K"')],
     # the bound in the unit the value was written in
     ["air.temperature", "air.supply_temperature", "cylinder.temperature", "<= 473.15 K",
      ">= -60 degC"]),
])
def test_pneumatic_limits_name_the_field_and_how_to_raise_them(edits, fields, tmp_path):
    case = _pneumatic(tmp_path, *edits)
    before = tree(tmp_path)
    result, text = cli("pneumatic", "run", case, "--out", tmp_path / "out")
    assert result.exit_code == 2, text
    one_message(text)
    for field in fields:
        assert field in text
    assert tree(tmp_path) == before


# -- 6. messages ----------------------------------------------------------------------------------
def test_a_base_case_error_is_reported_once_not_once_per_variant():
    from sealsim.rotary.case import RotaryCase

    data = {"seal": {"shaft_diameter": "80 m"}, "duty": {"steps": [
        {"speed": "100 rpm", "duration": "1 min"}]},
        "variants": {"a": {"seal": {"lip_style": "wave"}}, "b": {"seal": {"lip_style": "x"}},
                     "c": {}}}
    with pytest.raises(InputError) as err:
        expand_variants(RotaryCase, data, "case")
    msg = str(err.value)
    assert msg.count("seal.shaft_diameter") == 1, msg
    assert "variant 'b': seal.lip_style" in msg


def test_cross_field_errors_name_the_fields_not_the_whole_table(tmp_path):
    case = _pneumatic(tmp_path, ('title = ', 'initial_position = "500 mm"\ntitle = '))
    result, text = cli("pneumatic", "run", case, "--out", tmp_path / "out")
    assert result.exit_code == 2
    assert "initial_position" in text and "cylinder.stroke" in text
    assert "(top level)" not in text and "{'" not in text  # no dump of the case dict


def test_friction_summary_has_the_same_keys_as_the_other_models(tiny_friction, tmp_path):
    result, text = cli("friction", "run", tiny_friction, "--out", tmp_path / "out", "-q")
    assert result.exit_code == 0, text
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert {"title", "source", "sealsim_version", "variants"} <= set(summary)
    assert "case_file" not in summary


def test_json_results_have_no_float_noise(tmp_path):
    with ResultFolder(tmp_path / "run") as folder:
        folder.write_json("s.json", {"T": 67.99999999999949, "small": 1.234567890123456e-9})
    assert json.loads((tmp_path / "run" / "s.json").read_text()) == {
        "T": 68.0, "small": 1.23456789012e-09}
    assert json_ready(0.1 + 0.2, digits=12) == 0.3


def test_structure_map_help_shows_the_map_table():
    result, text = cli("structure", "map", "--help")
    assert "with a [map] table" in text
