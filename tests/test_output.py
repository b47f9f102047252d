"""Result folders: all-or-nothing, never overwrite without force, no half-written files."""

from __future__ import annotations

import os

import pandas as pd
import pytest

from sealsim.errors import InputError, ResultExistsError
from sealsim.output import RESULT_MARKER, ResultFolder, atomic_write_bytes, atomic_write_text


def _tree(path):
    """Relative paths of everything below ``path`` (hidden entries included, but not the
    marker of a result folder: see test_force_replaces_only_folders_sealsim_wrote), sorted."""
    return sorted(str(p.relative_to(path)) for p in path.rglob("*") if p.name != RESULT_MARKER)


def _old_results(tmp_path):
    """A result folder an earlier run wrote."""
    out = tmp_path / "run"
    with ResultFolder(out) as folder:
        folder.write_text("summary.json", '{"torque_Nm": 0.5}')
    return out


def test_new_folder_gets_all_files_and_nothing_else(tmp_path):
    out = tmp_path / "new" / "run"  # parent does not exist yet
    with ResultFolder(out) as folder:
        folder.write_text("case.toml", "x = 1\n")
        folder.write_json("summary.json", {"a": 1.5})
        folder.write_csv("series.csv", pd.DataFrame({"t_s": [0.0, 1.0]}))
        assert not out.exists()  # nothing is visible before the run succeeded
    assert _tree(out) == ["case.toml", "series.csv", "summary.json"]
    assert (out / "series.csv").read_text().splitlines() == ["t_s", "0.0", "1.0"]
    assert _tree(out.parent) == ["run", "run/case.toml", "run/series.csv", "run/summary.json"]


def test_refuses_non_empty_folder_without_force_before_writing(tmp_path):
    out = _old_results(tmp_path)
    before = _tree(tmp_path)
    with pytest.raises(ResultExistsError, match="--force"):
        ResultFolder(out)  # refused at construction, i.e. before any computing
    assert _tree(tmp_path) == before  # no staging folder, no change
    assert (out / "summary.json").read_text() == '{"torque_Nm": 0.5}'


def test_force_replaces_old_results(tmp_path):
    out = _old_results(tmp_path)
    with ResultFolder(out, force=True) as folder:
        folder.write_text("new.txt", "new")
        assert (out / "summary.json").exists()  # old results stay until success
    assert _tree(out) == ["new.txt"]  # old file gone, not merged
    assert _tree(tmp_path) == ["run", "run/new.txt"]  # no backup or staging folder left


@pytest.mark.parametrize("force", [False, True])
def test_failure_inside_the_block_leaves_the_previous_folder_untouched(tmp_path, force):
    out = tmp_path / "run"
    if force:
        out = _old_results(tmp_path)
    before = {p: p.read_bytes() for p in out.rglob("*")} if out.exists() else None
    with pytest.raises(RuntimeError, match="solver blew up"):
        with ResultFolder(out, force=force) as folder:
            folder.write_text("partial.csv", "t,x\n0,1\n")
            raise RuntimeError("solver blew up")
    if force:
        assert {p: p.read_bytes() for p in out.rglob("*")} == before
        assert _tree(tmp_path) == ["run", "run/summary.json"]  # no staging folder behind
    else:
        assert _tree(tmp_path) == []  # no target, no staging folder


def test_interrupt_inside_the_block_leaves_nothing(tmp_path):
    out = tmp_path / "run"
    with pytest.raises(KeyboardInterrupt):
        with ResultFolder(out) as folder:
            folder.write_text("a.txt", "a")
            raise KeyboardInterrupt
    assert _tree(tmp_path) == []


def test_empty_existing_folder_is_fine_without_force(tmp_path):
    out = tmp_path / "run"
    out.mkdir()
    with ResultFolder(out) as folder:
        folder.write_text("a.txt", "a")
    assert _tree(out) == ["a.txt"]


def test_force_replaces_only_folders_sealsim_wrote(tmp_path):
    # `--out ~/Documents --force` (a typo, a wrong variable) moved the whole folder aside and
    # deleted it: only a folder with the marker every committed result folder gets is replaced
    out = _old_results(tmp_path)
    assert (out / RESULT_MARKER).is_file()
    with ResultFolder(out, force=True) as folder:
        folder.write_text("new.txt", "new")
    assert (out / RESULT_MARKER).is_file() and _tree(out) == ["new.txt"]
    documents = tmp_path / "Documents"
    (documents / "thesis").mkdir(parents=True)
    (documents / "thesis" / "draft.tex").write_text("precious")
    (documents / "notes.txt").write_text("precious")
    before = _tree(tmp_path)
    with pytest.raises(ResultExistsError, match=r"output folder '.*Documents' was not written by "
                                                r"sealsim \(it holds 'notes.txt', 'thesis' and no "
                                                r"\.sealsim-results file\); --force replaces only"):
        ResultFolder(documents, force=True)
    assert _tree(tmp_path) == before
    assert (documents / "thesis" / "draft.tex").read_text() == "precious"


def test_path_that_is_a_file_is_an_input_error(tmp_path):
    target = tmp_path / "results.txt"
    target.write_text("not a folder")
    with pytest.raises(InputError, match="is a file"):
        ResultFolder(target, force=True)  # even force must not delete a file
    assert target.read_text() == "not a folder"


def test_use_outside_with_block_is_a_programming_error(tmp_path):
    with pytest.raises(RuntimeError, match="with"):
        ResultFolder(tmp_path / "run").write_text("a.txt", "a")


def test_atomic_write_leaves_no_temporary_files(tmp_path):
    target = tmp_path / "data.txt"
    atomic_write_text(target, "first")
    atomic_write_text(target, "second")  # replacing an existing file
    assert target.read_text() == "second"
    assert _tree(tmp_path) == ["data.txt"]


def test_failed_atomic_write_keeps_the_old_file_and_no_temporary(tmp_path):
    target = tmp_path / "data.bin"
    atomic_write_bytes(target, b"old")
    with pytest.raises(TypeError):
        atomic_write_bytes(target, "not bytes")  # fails inside the write
    assert target.read_bytes() == b"old"
    assert _tree(tmp_path) == ["data.bin"]


def test_failed_figure_save_leaves_no_temporary(tmp_path):
    class BrokenFigure:
        def savefig(self, path, **kwargs):
            with open(path, "wb") as fh:
                fh.write(b"half a png")
            raise OSError("disk full")

    out = tmp_path / "run"
    with pytest.raises(OSError, match="disk full"):
        with ResultFolder(out) as folder:
            folder.savefig("plot.png", BrokenFigure())
    assert _tree(tmp_path) == []


def test_results_get_normal_permissions(tmp_path):
    # result files are for sharing (the PNG written by savefig already gets 0666 & ~umask)
    umask = os.umask(0)
    os.umask(umask)
    with ResultFolder(tmp_path / "run") as folder:
        folder.write_text("a.txt", "a")
    assert (tmp_path / "run" / "a.txt").stat().st_mode & 0o777 == 0o666 & ~umask
    assert (tmp_path / "run").stat().st_mode & 0o777 == 0o777 & ~umask


# -- one result file (an FMU): the same mechanism ------------------------------------------------
def test_result_file_is_checked_locked_staged_and_committed_only_on_success(tmp_path):
    from sealsim.errors import ResultBusyError
    from sealsim.output import ResultFile

    out = tmp_path / "new" / "seal.fmu"         # the parent does not exist yet
    with ResultFile(out, suffix=".fmu") as result:
        staged = result.write_bytes(b"first")
        assert not out.exists() and staged.parent == out.parent  # invisible until committed
        # a second run to the same file while this one writes it is refused, not raced
        with pytest.raises(ResultBusyError, match="being written by another sealsim run"):
            with ResultFile(out, suffix=".fmu"):
                pass
    assert out.read_bytes() == b"first" and _tree(out.parent) == ["seal.fmu"]
    with pytest.raises(ResultExistsError, match="already exists; use --force"):
        ResultFile(out)
    # a failed run leaves the file as it was, no temporary and no lock behind
    with pytest.raises(RuntimeError), ResultFile(out, force=True) as result:
        result.write_bytes(b"second")
        raise RuntimeError("the build failed")
    assert out.read_bytes() == b"first" and _tree(out.parent) == ["seal.fmu"]
    # nothing written (a build that wrote no file): nothing committed, the old file stays
    with ResultFile(out, force=True):
        pass
    assert out.read_bytes() == b"first"
    with ResultFile(out, force=True) as result:
        result.write_bytes(b"second")
    assert out.read_bytes() == b"second" and _tree(out.parent) == ["seal.fmu"]
    # a run that failed before any parent folder was needed removes the folders it created
    with pytest.raises(RuntimeError), ResultFile(tmp_path / "a" / "b" / "x.fmu"):
        raise RuntimeError
    assert not (tmp_path / "a").exists()


def test_result_file_refuses_bad_targets_before_any_work(tmp_path):
    from sealsim.output import ResultFile

    case = tmp_path / "case.toml"
    case.write_text("x = 1\n")
    with pytest.raises(InputError, match="must end in .fmu"):
        ResultFile(tmp_path / "seal.zip", suffix=".fmu")
    with pytest.raises(InputError, match="is a folder"):
        ResultFile(tmp_path, suffix="")
    # an input of the run is never the target, not even with force (nor through a link)
    link = tmp_path / "link.toml"
    link.symlink_to(case)
    for target in (case, link):
        with pytest.raises(InputError, match="is an input of the run"):
            ResultFile(target, force=True, inputs=[case])
    (tmp_path / "file").write_text("")
    with pytest.raises(InputError, match="is a file"):
        ResultFile(tmp_path / "file" / "seal.fmu")
    assert case.read_text() == "x = 1\n"


def test_result_file_never_overwrites_a_file_that_appeared_meanwhile(tmp_path):
    from sealsim.output import ResultFile

    out = tmp_path / "seal.fmu"
    with pytest.raises(ResultExistsError, match="already exists"), ResultFile(out) as result:
        result.write_bytes(b"mine")
        out.write_bytes(b"someone else's")      # written by another program meanwhile
    assert out.read_bytes() == b"someone else's" and _tree(tmp_path) == ["seal.fmu"]
    # with force: only the file that was there when the run started is replaced
    result = ResultFile(out, force=True)
    (tmp_path / "newer").write_bytes(b"newer")  # another file (inode: both exist now) ...
    os.replace(tmp_path / "newer", out)         # ... put in its place before the run locks it
    with pytest.raises(ResultExistsError, match="written by another run after this one"):
        with result:
            pass
    assert out.read_bytes() == b"newer"


def test_result_file_removes_temporaries_of_killed_runs(tmp_path):
    import subprocess
    import sys

    from sealsim.output import ResultFile

    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True).stdout.strip()
    out = tmp_path / "seal.fmu"
    left = tmp_path / f".seal.fmu.{dead}.abcd1234.tmp"   # a build killed while writing
    mine = tmp_path / f".seal.fmu.{os.getpid()}.abcd1234.tmp"
    other = tmp_path / ".other.fmu.1.abcd1234.tmp"
    for path in (left, mine, other):
        path.write_bytes(b"partial")
    with ResultFile(out) as result:
        result.write_bytes(b"fmu")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [mine.name, other.name, "seal.fmu"])
