"""Issue 25 ("Nothing lost, nothing silent"): the faults whose cause lies in the command
line, the case manifests, the run folder's records, the sweep and the packaging.

Each test fails on the code before the fix and checks the exact line a user sees
(exit code 2 and one ``error: ...`` line naming the option or file and the cause, as
``test_bad_input.py`` does), or that nothing is left behind or rewritten.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import pytest

from creative_py.case import broken_cases, case_index, get_case, read_manifest
from creative_py.records.folder import RunFolder, read_resume
from creative_py.learning.options import read_run_json
from creative_py.world_files import WORLDS_ROOT, WorldFileError

from test_bad_input import BANNER, _tree_copy

ROOT = Path(__file__).resolve().parents[2]


def creative(*args: str, cwd: Path | None = None, env: dict | None = None,
             timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "creative_py.cli", *args],
                          capture_output=True, text=True, timeout=timeout, cwd=cwd, env=env)


def error_lines(proc: subprocess.CompletedProcess) -> list[str]:
    """The lines on stderr besides pybullet's import banner."""
    return [ln for ln in proc.stderr.splitlines() if ln and BANNER not in ln]


def refused(proc: subprocess.CompletedProcess) -> str:
    """Return the one error line of a refused command (exit code 2, no traceback)."""
    lines = error_lines(proc)
    assert proc.returncode == 2, proc.stderr[-2000:]
    assert len(lines) == 1, proc.stderr[-2000:]
    assert "Traceback" not in proc.stderr + proc.stdout
    return lines[0]


# ------------------------------------------------------------------ the sweep

def test_a_huge_seed_range_is_refused_before_anything_is_allocated(tmp_path):
    """``--seeds 0-1000000000`` grew to 23 GB: the count is bounded before any list."""
    proc = creative("sweep", "hook", "--seeds", "0-1000000000", "--serial",
                    "--out", str(tmp_path / "s"))
    assert refused(proc) == ("error: --seeds 0-1000000000: 1000000001 numbers, at most "
                             "10000 in one sweep")
    assert not (tmp_path / "s").exists()


def test_the_product_of_a_sweep_s_options_is_bounded_too():
    from creative_py.sweep import parse_ints, plan_runs

    with pytest.raises(ValueError) as caught:
        plan_runs(["hook"], ["paper"], parse_ints("0-9999", "--seeds"),
                  parse_ints("0-1", "--world-seeds"))
    assert str(caught.value) == ("sweep: 1 case(s) x 1 strategy x 10000 seed(s) x 2 world "
                                 "seed(s) are 20000 runs, at most 10000 in one sweep")
    with pytest.raises(ValueError) as caught:
        parse_ints("9" * 5000, "--seeds")  # no int() of 5000 digits (Python refuses it)
    assert str(caught.value) == (f"--seeds: {'9' * 40}: a number is larger than "
                                 f"9223372036854775807")


def test_two_sweeps_started_in_the_same_second_get_their_own_folders(tmp_path):
    from creative_py.sweep import new_sweep_folder

    first, second, third = (new_sweep_folder(tmp_path) for _ in range(3))
    if first.name.count("-") == second.name.count("-") - 1:  # same second
        assert second.name == first.name + "-2" and third.name == first.name + "-3"
    assert len({first, second, third}) == 3 and all(p.is_dir() for p in (first, second, third))
    with pytest.raises(FileExistsError):
        new_sweep_folder(tmp_path, first.name)      # a given name is never renamed


def test_sigterm_ends_a_sweep_in_one_line_with_exit_code_143(tmp_path):
    """A SIGTERM printed Ray's C stack dump (rc 134); a --serial sweep died silently."""
    proc = subprocess.Popen([sys.executable, "-m", "creative_py.cli", "sweep", "rake",
                             "--serial", "--seeds", "0-1", "--phase", "use",
                             "--max-trials", "1", "--eval-trials", "0", "--out",
                             str(tmp_path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    deadline = time.monotonic() + 120
    while not list(tmp_path.glob("sweep-*/runs")) and time.monotonic() < deadline:
        time.sleep(0.1)
    time.sleep(1.0)
    proc.send_signal(signal.SIGTERM)
    out, err = proc.communicate(timeout=120)
    [folder] = tmp_path.glob("sweep-*")
    lines = [ln for ln in err.splitlines() if ln and BANNER not in ln
             and not ln.startswith(("INFO", "WARNING"))]
    assert proc.returncode == 143, err[-2000:]
    csv_lines = (folder / "sweep.csv").read_text().splitlines()
    assert csv_lines[0].startswith("case,strategy,seed")
    # the signal may land in an import the run swallows: the run ends, the sweep stops
    done = len(csv_lines) - 1
    assert done < 2
    assert lines[-1] == (f"sweep stopped by SIGTERM after {done} of 2 runs; the finished "
                         f"ones are in {folder / 'sweep.csv'}")
    assert "Traceback" not in err and "SIGTERM received" not in err


@pytest.mark.sim
@pytest.mark.slow  # Ray's start: 10-30 s
def test_sigterm_ends_a_ray_sweep_in_one_line_without_a_stack_dump(tmp_path):
    """Ray's C++ handler printed ``*** SIGTERM received ...`` and a stack dump."""
    proc = subprocess.Popen([sys.executable, "-m", "creative_py.cli", "sweep", "rake",
                             "--seeds", "0-1", "--num-cpus", "1", "--phase", "use",
                             "--max-trials", "1", "--eval-trials", "0", "--out",
                             str(tmp_path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline and not list(tmp_path.glob("sweep-*/runs/*")):
        time.sleep(0.2)                     # a run folder: Ray is up and running a task
    proc.send_signal(signal.SIGTERM)
    _out, err = proc.communicate(timeout=300)
    [folder] = tmp_path.glob("sweep-*")
    done = len((folder / "sweep.csv").read_text().splitlines()) - 1
    assert proc.returncode == 143, err[-2000:]
    assert err.splitlines()[-1] == (f"sweep stopped by SIGTERM after {done} of 2 runs; the "
                                    f"finished ones are in {folder / 'sweep.csv'}")
    assert "SIGTERM received" not in err and "Traceback" not in err


def test_a_local_ray_instance_that_times_out_at_startup_is_started_again(monkeypatch):
    """``make test`` under load: "The current node timed out during startup" (Ray's
    fixed 30 s) failed the sweep; a second start is tried, with no timed assertion."""
    import ray

    from creative_py.sweep import start_ray

    calls, said = [], []

    def init(**kw):
        calls.append(kw)
        if len(calls) == 1:
            raise Exception("The current node timed out during startup. This could happen "
                            "because some of the raylet failed to startup or the GCS has "
                            "become overloaded.")

    monkeypatch.setattr(ray, "init", init)
    monkeypatch.setattr(ray, "shutdown", lambda: calls.append("shutdown"))
    start_ray({"num_cpus": 2}, say=said.append)
    assert calls == [{"num_cpus": 2}, "shutdown", {"num_cpus": 2}]
    assert said == ["warning: the local Ray instance timed out during startup (attempt 1 "
                    "of 3); starting it again"]
    calls.clear()
    monkeypatch.setattr(ray, "init", lambda **kw: (_ for _ in ()).throw(
        ConnectionError("no cluster")))
    with pytest.raises(ConnectionError):        # any other error is raised at once
        start_ray({"address": "x:1"}, local=False, say=said.append)


# --------------------------------------------------------------- the cases

@pytest.fixture()
def worlds_with_a_copy(tmp_path) -> Path:
    root = tmp_path / "worlds"
    shutil.copytree(WORLDS_ROOT, root, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(root / "hook_tube", root / "hook_copy")   # still declares id "hook"
    return root


def test_a_duplicate_case_id_is_refused_naming_both_folders(worlds_with_a_copy):
    """The copy (sorted first) was used silently while the original was listed broken."""
    root = worlds_with_a_copy
    line = (f"case 'hook' is declared by 2 folders: {root / 'hook_copy' / 'case.toml'} and "
            f"{root / 'hook_tube' / 'case.toml'} (field 'id'; give each folder its own id)")
    with pytest.raises(WorldFileError) as caught:
        get_case("hook", root)
    assert str(caught.value) == line
    broken = broken_cases(root)
    assert broken[root / "hook_copy" / "case.toml"] == line
    assert broken[root / "hook_tube" / "case.toml"] == line
    assert "hook" not in case_index(root).folders
    assert get_case("wedge", root).id == "wedge"                # the others still load


def test_creative_run_and_creative_cases_say_the_same_of_a_duplicate_id(tmp_path):
    copy = _tree_copy(tmp_path)
    shutil.copytree(copy / "worlds" / "hook_tube", copy / "worlds" / "hook_copy")
    env = {**os.environ, "PYTHONPATH": str(copy)}
    line = (f"case 'hook' is declared by 2 folders: "
            f"{copy / 'worlds' / 'hook_copy' / 'case.toml'} and "
            f"{copy / 'worlds' / 'hook_tube' / 'case.toml'} (field 'id'; give each folder "
            f"its own id)")
    run = creative("run", "hook", "--out", str(tmp_path / "runs"), env=env, cwd=tmp_path)
    assert refused(run) == f"error: {line}"
    assert not (tmp_path / "runs").exists()
    listing = creative("cases", env=env, cwd=tmp_path)
    assert listing.returncode == 0, listing.stderr
    assert [ln for ln in listing.stdout.splitlines() if ln.startswith("broken")] == [
        f"broken         {line}"]                   # once, though two folders declare it


def test_creative_cases_aligns_every_id_on_the_longest():
    proc = creative("cases")
    assert proc.returncode == 0, proc.stderr
    width = max(len(i) for i in case_index().folders)
    lines = proc.stdout.splitlines()
    for head, world in zip(lines[::2], lines[1::2]):
        case_id = head.split(" ", 1)[0]
        assert head[width] == " " and head[width + 1] != " ", head
        assert world.startswith(" " * (width + 1) + "world "), world
        assert case_id in case_index().folders


def _manifest_copy(tmp_path, ontology: str) -> Path:
    world = tmp_path / "w"
    shutil.copytree(WORLDS_ROOT / "hook_tube", world)
    text = (world / "case.toml").read_text()
    assert 'ontology = "hook"' in text
    (world / "case.toml").write_text(text.replace('ontology = "hook"',
                                                  f'ontology = "{ontology}"', 1))
    return world


@pytest.mark.parametrize("ontology, cause", [
    ("nothere", "{cases}/nothere.pl: no such file"),
    ("wedge", "{cases}/wedge.pl does not declare case(hook). (the case's ontology file "
              "starts with it)"),
    ("../ranges", "must name a file of ontology/cases/ without its .pl (a lower-case "
                  "Prolog atom), got '../ranges'"),
])
def test_the_manifest_s_ontology_field_is_checked(tmp_path, ontology, cause):
    world = _manifest_copy(tmp_path, ontology)
    with pytest.raises(WorldFileError) as caught:
        read_manifest(world)
    cases = ROOT / "ontology" / "cases"
    assert str(caught.value) == (f"{world / 'case.toml'}: field 'ontology': "
                                 + cause.format(cases=cases))


def test_a_trial_of_a_case_whose_ontology_file_is_missing_names_case_toml(tmp_path):
    """It printed ``error: pose_target: error(existence_error(case,newc),_G0)``."""
    copy = _tree_copy(tmp_path)
    new = copy / "worlds" / "newc"
    shutil.copytree(copy / "worlds" / "rake_shelf", new)
    text = (new / "case.toml").read_text()
    (new / "case.toml").write_text(text.replace('id = "rake"', 'id = "newc"', 1)
                                   .replace('ontology = "rake"', 'ontology = "newc"', 1))
    proc = creative("trial", "newc", "--tool", "rake_a1", cwd=tmp_path,
                    env={**os.environ, "PYTHONPATH": str(copy)})
    assert refused(proc) == (f"error: {new / 'case.toml'}: field 'ontology': "
                             f"{copy / 'ontology' / 'cases' / 'newc.pl'}: no such file")


def test_a_bool_catalogue_number_is_refused_naming_the_file_and_field(tmp_path):
    """``handle_length = true`` passed as 1 m and ended in a raw Prolog error."""
    world = tmp_path / "w"
    shutil.copytree(WORLDS_ROOT / "hook_tube", world)
    text = (world / "objects.toml").read_text()
    (world / "objects.toml").write_text(text.replace("handle_length = 0.20",
                                                     "handle_length = true", 1))
    proc = creative("trial", "hook", "--world", str(world), "--tool", "hook_a2")
    assert refused(proc) == (f"error: {world / 'objects.toml'}: tool[0]: object 'hook_a1': "
                             f"field 'handle_length' must be a number, got True")


# ---------------------------------------------------------- the run folder

def test_options_given_with_resume_are_refused_not_ignored(tmp_path):
    folder = tmp_path / "run"
    folder.mkdir()
    proc = creative("run", "rake", "--resume", str(folder), "--seed", "7", "--strategy",
                    "paper", "--world", str(tmp_path))
    assert refused(proc) == (f"error: --seed, --strategy, --world: not allowed with "
                             f"--resume (a resumed run uses the options recorded in "
                             f"{folder / 'run.json'})")


def _record_line(trial: int, reason: str = "") -> str:
    return json.dumps({"trial": trial, "phase": "use", "phase_trial": trial,
                       "variant": "standard", "location": 1, "tool": "rake_a1",
                       "outcome": "failure", "reason": reason})


def test_a_trials_line_that_is_not_utf8_is_named_before_anything_is_rewritten(tmp_path):
    """The resume rewrote model.pl and the PDDL, then failed with a bare UTF-8 error."""
    path = tmp_path / "trials.jsonl"
    data = (_record_line(1).replace('"reason": ""', '"reason": "\xff"').encode("latin-1")
            + b"\n" + _record_line(2).encode() + b"\n")
    path.write_bytes(data)
    with pytest.raises(ValueError) as caught:
        read_resume(tmp_path)
    column = data.index(b"\xff") + 1
    assert str(caught.value) == (f"{path}: line 1: byte 0xff at column {column} is not "
                                 f"UTF-8 text; the run cannot be resumed")
    assert path.read_bytes() == data
    last = _record_line(1).encode() + b"\n" + _record_line(2).encode() + b"\n"
    path.write_bytes(last + data.splitlines()[0] + b"\n")   # the last line: not torn
    with pytest.raises(ValueError, match="line 3: byte 0xff"):
        read_resume(tmp_path)


def test_a_refused_resume_leaves_the_lock_file_as_it_was(tmp_path):
    (tmp_path / ".lock").write_text("12345\n")
    os.utime(tmp_path / ".lock", (1_000_000_000, 1_000_000_000))
    run = RunFolder.open(tmp_path)
    run.release()
    assert (tmp_path / ".lock").read_text() == "12345\n"
    assert (tmp_path / ".lock").stat().st_mtime == 1_000_000_000
    created = RunFolder.create(tmp_path, "rake", 0, "new")          # a new folder: its pid
    assert (created.path / ".lock").read_text() == f"{os.getpid()}\n"
    created.release()


# ------------------------------------------------------------------ report

def test_report_on_a_folder_that_does_not_exist_says_so(tmp_path):
    proc = creative("report", str(tmp_path / "nowhere"))
    assert refused(proc) == (f"error: {tmp_path / 'nowhere'}: no such folder (a run "
                             f"folder was expected)")


def test_report_on_a_trials_jsonl_that_is_a_folder_is_one_line(tmp_path):
    (tmp_path / "trials.jsonl").mkdir()
    proc = creative("report", str(tmp_path))
    assert refused(proc) == (f"error: {tmp_path / 'trials.jsonl'}: not a file (a run's "
                             f"trials.jsonl holds one JSON object per line)")


def test_report_skips_a_line_nested_too_deeply_with_a_warning(tmp_path):
    (tmp_path / "trials.jsonl").write_text("[" * 100000 + "\n" + _record_line(1) + "\n")
    proc = creative("report", str(tmp_path))
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert error_lines(proc) == [f"warning: {tmp_path / 'trials.jsonl'}: line 1 is not a "
                                 f"JSON object (nested too deeply); skipped"]
    assert "rake_a1" in proc.stdout


# ----------------------------------------------------------- command line

def test_a_path_component_longer_than_the_file_system_allows_is_one_line(tmp_path):
    long = tmp_path / ("x" * 300)
    text = str(long)
    shown = f"{text[:60]}...{text[-12:]}"
    for args, option in [(["run", "rake"], "--out"), (["sweep", "rake"], "--out"),
                         (["make-tool", "hook", "handle_length=long"], "--out")]:
        proc = creative(*args, option, str(long))
        assert refused(proc) == (f"error: {option} {shown}: File name too long (a name of "
                                 f"300 bytes, at most 255)")


@pytest.mark.parametrize("args, line", [
    (["run", "hook", "--seed", "1.5"],
     "error: Invalid value for '--seed': Input should be a valid integer, unable to parse "
     "string as an integer (see python -m creative_py.cli run --help)"),
    (["sweep", "hook", "--num-cpus", "two"],
     "error: Invalid value for '--num-cpus': Input should be a valid integer, unable to "
     "parse string as an integer (see python -m creative_py.cli sweep --help)"),
    (["run"], "error: Missing argument 'case' (see python -m creative_py.cli run --help)"),
])
def test_a_wrong_command_line_is_one_line_not_a_usage_box(args, line):
    assert refused(creative(*args)) == line


def test_help_shows_no_value_type_beside_a_plain_flag():
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "run", "--help"],
                          capture_output=True, text=True, timeout=60,
                          env={**os.environ, "COLUMNS": "160"})
    assert proc.returncode == 0
    assert "<bool>" not in proc.stdout
    assert "<int>" in proc.stdout                    # an option that takes a value keeps it
    [gui] = [ln for ln in proc.stdout.splitlines() if "--gui " in ln]
    assert gui.split("--gui", 1)[1].lstrip().startswith("Show the trials")


def test_help_at_80_columns_breaks_each_command_s_line_only_where_it_is_full():
    # The docstrings' own line breaks showed: "the URDF loads, the joints" then
    # "and links are found" on a line of its own.
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "--help"],
                          capture_output=True, text=True, timeout=60,
                          env={**os.environ, "COLUMNS": "80"})
    assert proc.returncode == 0
    lines = proc.stdout.splitlines()
    top = next(i for i, ln in enumerate(lines) if "Commands" in ln)
    rows = [ln for ln in lines[top + 1:] if ln.startswith("\u2502")]
    start = rows[0].index("List the robot profiles")
    width = len(rows[0]) - 2 - start            # the description column, less "│" and a space
    cells: list[list[str]] = []
    for ln in rows:
        text = ln[start:-1].rstrip()
        if ln[1:start].strip():                 # a command's name: a new cell
            cells.append([text])
        else:
            cells[-1].append(text)
    assert len(cells) == 8 and all(len(ln) <= width for c in cells for ln in c)
    for cell in cells:
        for line, after in zip(cell, cell[1:]):
            assert len(line) + 1 + len(after.split()[0]) > width, (line, after)
    assert cells[0] == ["List the robot profiles, each with a one-line check: the URDF",
                        "loads, the joints and links are found, the home posture is",
                        "reachable (docs/robots.md)."]


def test_a_refused_make_tool_leaves_no_empty_out_folder(tmp_path):
    out = tmp_path / "tools" / "sub"
    proc = creative("make-tool", "hook", "handle_length=long", "--build-volume", "10,10,10",
                    "--out", str(out))   # refused before slicing: no piece fits
    assert refused(proc).startswith("error: new_tool: the tool is ")
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- packaging

def test_the_licence_is_an_spdx_string_and_the_script_is_the_one_line_main():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert project["project"]["license"] == "MIT"
    assert project["project"]["scripts"]["creative"] == "creative_py.cli:main"
    assert "setuptools>=77" in project["build-system"]["requires"]


def test_building_the_metadata_prints_no_licence_warning(tmp_path):
    """About 60 lines of setuptools deprecation warnings on every fresh set-up."""
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copy(ROOT / name, tmp_path / name)
    shutil.copytree(ROOT / "creative_py", tmp_path / "creative_py",
                    ignore=shutil.ignore_patterns("__pycache__"))
    code = ("from setuptools.build_meta import prepare_metadata_for_build_wheel as p; "
            "import os; os.mkdir('m'); p('m')")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "Deprecat" not in proc.stdout + proc.stderr
    assert "licen" not in (proc.stdout + proc.stderr).lower().replace(
        "adding license file 'license'", "")


def test_a_run_json_edited_after_the_run_began_is_refused_on_resume(tmp_path):
    """A changed seed in run.json was accepted: the summary then named a seed the
    trials were not run with."""
    from creative_py.learning.options import RunOptions, run_json

    folder = tmp_path / "hook-edited-s0"
    folder.mkdir()
    recorded = ROOT / "tests" / "fixtures" / "runs" / "hook_s0"
    (folder / "trials.jsonl").write_bytes((recorded / "trials.jsonl").read_bytes())
    meta = run_json("hook", RunOptions(seed=0, strategy="paper", video="none"), None, None)
    (folder / "run.json").write_text(json.dumps(meta, indent=2))
    read_run_json(folder)                                      # as written: accepted
    meta["options"]["seed"] = 5
    (folder / "run.json").write_text(json.dumps(meta, indent=2))
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    proc = creative("run", "hook", "--resume", str(folder))
    assert refused(proc) == (f"error: {folder / 'run.json'}: field 'check' does not match "
                             "the case, options, world and drawn world: run.json was "
                             "changed after the run began; the run cannot be resumed (start "
                             "a new run for other options)")
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before
