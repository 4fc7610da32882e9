"""Issue 32 item 6: the probe's last silent inputs, each refused at its cause in one line
(exit 2, no traceback, nothing already written lost), and ``make-tool``'s own inputs,
its ``--context`` Prolog text above all, probed as hard as the run's.

Each test runs the real ``creative`` command in a child process (or, where a signal or
a full disk must come at one moment, the function in this process) and checks what the
user sees.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from creative_py.learning.options import RunOptions, run_json
from creative_py.records.folder import RunFolder, write_atomic
from creative_py.world_files import WORLDS_ROOT

from test_bad_input import BANNER

ROOT = Path(__file__).resolve().parents[2]
RECORDED = ROOT / "tests" / "fixtures" / "runs"


def creative(*args: str, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "creative_py.cli", *args],
                          capture_output=True, text=True, timeout=timeout)


def refused(proc: subprocess.CompletedProcess) -> str:
    """Return the one error line of a refused command: exit code 2, no traceback, no
    other line on stderr (no SWI-Prolog warning either), nothing on stdout."""
    lines = [ln for ln in proc.stderr.splitlines() if ln and BANNER not in ln]
    assert proc.returncode == 2, proc.stderr[-2000:]
    assert len(lines) == 1 and lines[0].startswith("error: "), proc.stderr[-2000:]
    assert "Traceback" not in proc.stderr + proc.stdout
    assert proc.stdout == ""
    return lines[0]


def _prior(tmp_path: Path, text: bytes) -> Path:
    folder = tmp_path / "prior"
    folder.mkdir()
    (folder / "model.pl").write_bytes(text)
    return folder


# ---------------------------------------------------------------- --prior model.pl

@pytest.mark.parametrize("name, text, why", [
    # 100,000 brackets deep: SIGSEGV in libswipl (the C stack; pyswip starts
    # SWI-Prolog with --nosignals, so its own overflow check cannot catch it)
    ("brackets", b"learned_hypothesis(hook, hs, " + b"f(" * 100000 + b"a"
     + b")" * 100000 + b").\n", "brackets nested deeper than 1000 levels"),
    # operators nest without brackets; the reader takes it, the writer would not
    ("operators", b"learned_hypothesis(hook, hs, " + b"- " * 100000 + b"a).\n",
     "a term nested deeper than 200 levels"),
    # two SWI-Prolog warnings were printed before the error
    ("not UTF-8", b"learned_hypothesis(hook, hs, a(\xff)).\n",
     "not UTF-8 text (byte 0xff at line 1, byte 32)"),
    ("syntax", b"learned_hypothesis(hook, hs, (a :- b)).\nlearned_hypothesis(hook, hg, "
     b"(a :- b c)).\n", "syntax error: operator expected at line 2, column 37"),
])
def test_a_hostile_prior_is_one_line_naming_the_file(tmp_path, name, text, why):
    prior = _prior(tmp_path, text)
    out = tmp_path / "runs"
    proc = creative("run", "rake", "--prior", str(prior), "--out", str(out))
    assert refused(proc) == f"error: --prior {prior}: {prior / 'model.pl'}: {why}"
    assert not out.exists()


def test_a_prior_is_read_as_data_and_its_directives_never_run(tmp_path):
    flag = tmp_path / "ran"
    prior = _prior(tmp_path, f":- initialization(shell('touch {flag}')).\n"
                             f":- shell('touch {flag}').\n".encode())
    proc = creative("run", "rake", "--prior", str(prior), "--out", str(tmp_path / "runs"))
    assert "not a learned model file" in refused(proc)
    assert not flag.exists()


# ---------------------------------------------------------------- run.json

def test_a_run_json_whose_check_was_deleted_is_not_resumed(tmp_path):
    """An edited seed with the check taken out resumed with exit 0 and mixed two seeds'
    trials."""
    folder = tmp_path / "hook-edited-s0"
    folder.mkdir()
    (folder / "trials.jsonl").write_bytes((RECORDED / "hook_s0" / "trials.jsonl").read_bytes())
    meta = run_json("hook", RunOptions(seed=0, strategy="paper", video="none"), None, None)
    meta["options"]["seed"] = 5
    del meta["check"]
    (folder / "run.json").write_text(json.dumps(meta, indent=2))
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    proc = creative("run", "hook", "--resume", str(folder))
    assert refused(proc) == (f"error: {folder / 'run.json'}: field 'check' is missing, so "
                             "an edit of run.json after the run began cannot be told; the "
                             "run cannot be resumed (start a new run)")
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before


# ---------------------------------------------------------------- summary.json

def test_a_summary_whose_counts_contradict_each_other_is_not_believed(tmp_path):
    """An edited summary.json made the report say "9 of 4 trials succeeded"."""
    folder = tmp_path / "run"
    shutil.copytree(RECORDED / "hook_s0", folder)
    data = json.loads((folder / "summary.json").read_text())
    assert data["eval"]["trials"] == 4
    data["eval"]["successes"] = 9
    (folder / "summary.json").write_text(json.dumps(data, indent=2))
    proc = creative("report", str(folder), "--width", "200")
    assert proc.returncode == 0, proc.stderr
    assert "9 of 4" not in proc.stdout
    warnings = [ln for ln in proc.stderr.splitlines() if ln.startswith("warning: ")]
    assert warnings == [f"warning: {folder / 'summary.json'}: field 'eval': 9 successes of "
                        "4 trials: the counts contradict each other; not shown"]


# ---------------------------------------------------------------- case.toml

def test_a_goal_that_does_not_parse_names_the_file_and_the_field(tmp_path):
    world = tmp_path / "rake_shelf"
    shutil.copytree(WORLDS_ROOT / "rake_shelf", world)
    manifest = world / "case.toml"
    text = manifest.read_text()
    assert 'goal = ["out_from_under(box1, shelf1)"]' in text
    manifest.write_text(text.replace('goal = ["out_from_under(box1, shelf1)"]',
                                     'goal = ["out_from_under(box1, shelf1"]'))
    out = tmp_path / "runs"
    proc = creative("run", "rake", "--world", str(world), "--out", str(out))
    assert refused(proc) == (f"error: {manifest}: field 'goal', item 1 "
                             "'out_from_under(box1, shelf1': not a Prolog literal (syntax "
                             "error: operator expected at line 1, column 28)")
    assert not out.exists()


# ---------------------------------------------------------------- long paths

def _deep(root: Path, length: int) -> Path:
    """A path below ``root`` of exactly ``length`` bytes, in components of at most 199."""
    parts, n = [], len(str(root))
    while length - n > 200:
        parts.append("d" * 199)
        n += 200
    parts.append("d" * (length - n - 1))
    path = root.joinpath(*parts)
    assert len(str(path)) == length
    return path


def test_a_4000_byte_out_is_refused_before_anything_is_made(tmp_path):
    """It left 20 empty folders (or ran the whole run to fail at its first tool)."""
    out = _deep(tmp_path / "o", 4000)
    proc = creative("run", "rake", "--out", str(out))
    line = refused(proc)
    assert line.startswith("error: --out ") and "leaves no room for the 256 bytes" in line
    assert list(tmp_path.iterdir()) == []


def test_a_run_folder_that_cannot_be_made_leaves_no_folder_above_it(tmp_path):
    parent = _deep(tmp_path / "o", 4080)      # the parents fit; the run folder does not
    with pytest.raises(OSError):
        RunFolder.create(parent, "rake", 0)
    assert list(tmp_path.iterdir()) == []


def test_a_5000_character_tool_name_is_refused_before_anything_is_made(tmp_path):
    out = tmp_path / "tools"
    proc = creative("make-tool", "hook", "handle_length=long", "--name", "a" * 5000,
                    "--out", str(out), "--no-slice")
    assert refused(proc) == ("error: --name: at most 200 characters (the tool's file names "
                             "add to it), got 5000")
    assert not out.exists()


def test_a_tool_folder_the_file_system_refuses_leaves_no_out_folder(tmp_path):
    """The writer's own clean-up, below the command line's checks."""
    from creative_py.kinds import spec_from_dict
    from creative_py.mesh.export import write_tool_files

    spec = spec_from_dict({"kind": "hook", "name": "h" * 250, "handle_length": 0.3,
                           "handle_width": 0.02, "hook_length": 0.05, "hook_width": 0.02,
                           "hook_angle_deg": 90.0, "hook_side": "right", "mass": None})
    out = tmp_path / "a" / "b"
    with pytest.raises(OSError):
        write_tool_files(spec, out, picture=False)
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- a full disk

def test_a_full_disk_leaves_the_old_file_and_names_the_file(tmp_path, monkeypatch):
    """``report --html --plot`` on a full disk rewrote trials.png, then failed naming no
    file. (test_the_report_on_a_real_full_disk does it on a small tmpfs.)"""
    import creative_py.records.folder as folder

    path = tmp_path / "trials.png"
    path.write_bytes(b"the old plot")
    fdopen = os.fdopen

    class Full:
        def __init__(self, fd, mode):
            self.fh = fdopen(fd, mode)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.fh.close()

        def write(self, data):
            raise OSError(28, "No space left on device")

    monkeypatch.setattr(folder.os, "fdopen", Full)
    with pytest.raises(OSError) as info:
        write_atomic(path, b"the new plot")
    assert (info.value.errno, info.value.filename) == (28, str(path))
    assert path.read_bytes() == b"the old plot"
    assert [p.name for p in tmp_path.iterdir()] == ["trials.png"]


def _mount_tmpfs(where: Path, size: str) -> bool:
    where.mkdir()
    if os.geteuid() != 0 or not shutil.which("mount"):
        return False
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs",
                           str(where)], capture_output=True)
    return done.returncode == 0


def test_the_report_on_a_real_full_disk(tmp_path):
    disk = tmp_path / "disk"
    if not _mount_tmpfs(disk, "256k"):
        pytest.skip("no tmpfs can be mounted here (root and mount(8) needed)")
    try:
        run = disk / "run"
        shutil.copytree(RECORDED / "hook_s0", run)
        proc = creative("report", str(run), "--plot")      # a trials.png to keep
        assert proc.returncode == 0, proc.stderr
        before = {p.name: p.read_bytes() for p in run.iterdir()}
        with open(disk / "filler", "wb") as fh:             # fill the disk
            try:
                while True:
                    fh.write(b"\0" * 65536)
                    fh.flush()
            except OSError:
                pass
        proc = creative("report", str(run), "--html", "--plot")
        assert proc.returncode == 2, proc.stderr
        lines = [ln for ln in proc.stderr.splitlines() if ln.startswith("error: ")]
        assert lines == [f"error: {run / 'trials.png'}: No space left on device"]
        assert {p.name: p.read_bytes() for p in run.iterdir()} == before
    finally:
        subprocess.run(["umount", str(disk)], check=True)


# ---------------------------------------------------------------- the sweep

def test_a_case_given_twice_to_a_sweep_is_refused(tmp_path):
    """``sweep hook hook`` ran every run twice."""
    proc = creative("sweep", "hook", "hook", "--serial", "--out", str(tmp_path / "s"))
    assert refused(proc) == "error: sweep: case 'hook' is given twice"
    assert not (tmp_path / "s").exists()


# ---------------------------------------------------------------- Ctrl-C

def test_a_trial_line_and_the_count_of_kept_trials_agree_under_ctrl_c(tmp_path,
                                                                         monkeypatch):
    """Ctrl-C during a trial's fsync kept its line but not its count: "8 trials kept"
    where 9 were. The signal comes here in the middle of the fsync."""
    import creative_py.records.folder as folder

    run = RunFolder.create(tmp_path, "rake", 0)
    real_fsync = os.fsync

    def fsync_then_ctrl_c(fd):
        real_fsync(fd)
        os.kill(os.getpid(), signal.SIGINT)
        sum(range(1000))                          # bytecode on which Python handles it

    monkeypatch.setattr(folder.os, "fsync", fsync_then_ctrl_c)
    # Python's own SIGINT handler, not blocked, whatever an earlier test in this worker
    # left (in one fresh clone's CI the signal never reached the test).
    handler = signal.signal(signal.SIGINT, signal.default_int_handler)
    mask = signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    # Another thread, as a run has (the progress line's): a signal sent to the process
    # may be taken by any thread that does not block it, so blocking it in this one
    # would not hold it back.
    done = threading.Event()
    other = threading.Thread(target=done.wait)
    other.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            run.append_trial({"trial": 1, "phase": "eval", "phase_trial": 1,
                              "variant": "standard", "location": 1, "tool": "rake_a2",
                              "outcome": "success"})
    finally:
        done.set()
        other.join()
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)
        signal.signal(signal.SIGINT, handler)
    run.release()
    lines = (run.path / "trials.jsonl").read_text().splitlines()
    assert len(lines) == len(run.trials) == 1


# ---------------------------------------------------------------- make-tool

MAKE_TOOL = [
    # --context is Prolog text read as data: one conjunction of facts, never called
    (["--context", "a] , [b"], "error: --context 'a] , [b': not Prolog facts (syntax error: "
     "cannot start term at line 1, column 1)"),                   # was a traceback
    (["--context", "max_tool_length(0.3)|b"], "error: --context 'max_tool_length(0.3)|b': "
     "unknown task fact '|'(max_tool_length(0.3),b); the size model understands "),  # idem
    (["--context", "max_tool_length(" + "(" * 60000 + "0.3" + ")" * 60000 + ")"],
     "not Prolog facts (brackets nested deeper than 1000 levels)"),    # was SIGSEGV
    (["--context", "max_tool_length(" + "- " * 60000 + "0.3)"],
     "not Prolog facts (a term nested deeper than 200 levels)"),       # was a traceback
    (["--context", "max_tool_length(0.5). max_tool_length(0.01)"],
     "error: --context 'max_tool_length(0.5). max_tool_length(0.01)': not Prolog facts "
     "(syntax error: one term expected)"),                # the second fact was ignored
    (["--context", "max_tool_length(0.3)]. :- initialization(halt). x([1"],
     "not Prolog facts (syntax error: cannot start term at line 1, column 20)"),
    (["--context", "max_tool_length(1.0Inf)"], "error: --context 'max_tool_length(1.0Inf)': "
     "max_tool_length(1.0Inf): a number is not finite"),
    (["--context", "tube_length_m(tube2, 0.45)"], "error: --context: "
     "tube_length_m(tube2,0.45) is about tube2, which the task does not have (its objects: "
     "tube1)"),                                           # a tool was made, the fact ignored
    (["--context", os.fsdecode(b"max_tool_length(\xff)")],
     "error: --context: not UTF-8 text (byte 0xff at character 17)"),  # "cannot start SWI"
    # the other options
    (["--name", os.fsdecode(b"h\xff")], "error: --name: not UTF-8 text (byte 0xff at "
     "character 2)"),
    (["--variant", os.fsdecode(b"\xfe")], "error: --variant: not UTF-8 text (byte 0xfe at "
     "character 1)"),
    (["--out", "{a_file}"], "error: --out {a_file}: not a folder"),   # "the tool's folder
]                                                            # exists (--overwrite ...)"


@pytest.mark.parametrize("extra, message", MAKE_TOOL,
                         ids=[" ".join(a)[:40] for a, _ in MAKE_TOOL])
def test_make_tool_refuses_hostile_input_in_one_line(tmp_path, extra, message):
    a_file = tmp_path / "a_file"
    a_file.write_text("not a folder\n")
    flag = tmp_path / "ran"
    extra = [a.format(a_file=a_file) for a in extra]
    proc = creative("make-tool", "hook", "handle_length=long", "--out", str(tmp_path / "t"),
                    "--no-slice", *extra)
    line = refused(proc)
    message = message.format(a_file=a_file)
    assert line.startswith(message) if message.startswith("error: ") else message in line
    assert not (tmp_path / "t").exists() and not flag.exists()
    assert a_file.read_text() == "not a folder\n"


def test_make_tool_context_directives_are_never_run(tmp_path):
    flag = tmp_path / "ran"
    for text in (f":- shell('touch {flag}')", f"shell('touch {flag}')",
                 f"initialization(shell('touch {flag}'))", ":- halt", "halt"):
        proc = creative("make-tool", "hook", "handle_length=long", "--context", text,
                        "--out", str(tmp_path / "t"), "--no-slice")
        assert "unknown task fact" in refused(proc)
    assert not flag.exists() and not (tmp_path / "t").exists()


def test_a_long_spec_is_shown_by_its_start_and_end(tmp_path):
    """The whole 5,000-character spec was printed back in the error line."""
    spec = "handle_length=" + "(" * 5000
    proc = creative("make-tool", "hook", spec, "--out", str(tmp_path / "t"), "--no-slice")
    line = refused(proc)
    assert line.startswith("error: hook spec 'handle_length=((((") and len(line) < 400, line
    assert "handle_length cannot be '((((" in line
    assert not (tmp_path / "t").exists()


# ---------------------------------------------------------------- options beyond bounds

# (world folder, file, text, replacement, the error after "<file>: ") : each loaded
# without complaint (its numbers within bounds) and failed mid-run, with a traceback
# (KeyError, ValueError, ZeroDivisionError) or a line naming no file; or was taken
# silently (a box whose corners are swapped).
WORLD_OPTIONS = [
    ("bring_cube", "tasks.toml", "goal = [0.6, 0.0, 0.035]", "goal = [0.6, 0.0]",
     "field 'oracle.start': must be a list of 2 numbers (m), as many as 'goal', got "
     "[1, 0, 0.035]"),
    ("bring_cube", "tasks.toml", "goal = [0.6, 0.0, 0.035]", "goal = [1.0, 0.0, 0.035]",
     "field 'oracle.start': equals 'goal', so the reward's scale |start - goal|_1 is 0 "
     "(move them apart or set 'scale')"),
    ("clean_table", "tasks.toml", '"cubes8"]', '"cubes8", "cubes9"]',
     "field 'oracle.objects': 'cubes9' is no object of the scene (did you mean 'cubes'?); "
     "objects: cubes, cubes1, cubes2, cubes3, cubes4, cubes5, cubes6, cubes7, cubes8, "
     "goal1, rake_c1, table1"),
    ("clean_table", "tasks.toml", '"cubes8"]', '"cubes8", "goal1"]',
     "field 'oracle.objects': 'goal1': the episode records no start of it (it is neither "
     "perceived nor a movable body)"),
    ("clean_table", "tasks.toml", "centre = [1.1, 0.0]", "centre = [1.1, 0.0, 0.0, 0.0]",
     "field 'oracle.centre': must be a list of 1 or 2 or 3 numbers (m), got "
     "[1.1, 0, 0, 0]"),
    ("one_book", "tasks.toml", '["book1",', '["bok1",',
     "field 'oracle.neighbours': 'bok1' is no object of the scene (did you mean "
     "'book1'?); objects: book1, book2, book3, book4, book5, bookends1, hook_a1, table1"),
    ("one_book", "tasks.toml", '["book1",', '["book3",',
     "field 'oracle.neighbours': names the object itself ('book3')"),
    ("high_object", "tasks.toml", 'box_min = ["box_x - 0.175", -0.585, 0.0225]',
     'box_min = ["box_x + 0.3", -0.585, 0.0225]',
     "field 'oracle.box_min': along x (0.85) must lie below 'box_max' (0.725) (variant "
     "standard, location 1)"),
    ("high_object", "tasks.toml", 'start = ["shelf_front + 0.10", 0.0, 0.925]',
     'start = ["box_x", 0.0, 0.08625]',
     "field 'oracle.start': lies at the box's centre, so the reward's scale "
     "|start - centre|_1 is 0 (variant standard, location 1)"),
    ("dislodge_cube", "tasks.toml", 'axes = ["x", "y"]', 'axes = ["x", "w"]',
     "field 'oracle.axes': must be x, y or z, got 'w'"),
    ("dislodge_cube", "tasks.toml", 'near = ["pipe_x - 0.2", 0.01]', 'near = ["pipe_x - 0.2"]',
     "field 'oracle.near': must be a list of 2 numbers (m), one per axis of 'axes', got "
     "[0.9] (variant standard, location 1)"),
    ("hook_tube", "tasks.toml", 'axis = "x"', 'axis = "X"',
     "field 'oracle.axis': must be x, y or z, got 'X'"),
    ("hook_tube", "tasks.toml", 'limit = "tube1.mouth_x"', "limit = [0.5, 0.6]",
     "field 'oracle.limit': must be a number, got a list [0.5, 0.6]"),
    ("wedge_door", "tasks.toml", 'body = "target"', 'body = "door2"',
     "field 'oracle.body': 'door2' is no object of the scene (did you mean 'door1'?); "
     "objects: door1, floor1, ground1, wedge_a2"),
    ("clean_table", "case.toml", "direction = [1.0, 0.0]", "direction = [1.0]",
     "field 'skill[2].options.direction': must be a list of 2 numbers, got [1]"),
    ("clean_table", "case.toml", "direction = [1.0, 0.0]", "direction = [0.0, 0.0]",
     "field 'skill[2].options.direction': must not be zero, got [0, 0]"),
    ("clean_table", "case.toml", "via = [0.16, 0.0]", "via = [0.16, 0.0, 0.3]",
     "field 'skill[1].options.via': must be a list of 2 numbers, got [0.16, 0, 0.3]"),
    ("clean_table", "case.toml", "via = [0.16, 0.0]", "via = [0.16, 0.0], slide_from = [0.1]",
     "field 'skill[1].options.slide_from': must be a list of 2 numbers, got [0.1]"),
    ("clean_table", "case.toml", "ramp = 0.10,", "ramp = [0.10, 0.2],",
     "field 'skill[2].options.ramp': must be a number, got a list [0.1, 0.2]"),
    ("wedge_door", "case.toml", "retreat = [0.45, -0.75, 0.10]", "retreat = [0.45, -0.75]",
     "field 'skill[1].options.retreat': must be a list of 3 numbers, got [0.45, -0.75]"),
    # documented as +-pi/2 or 0, bounded by +-2 pi: 0.3 carried the prong neither flat
    # nor down
    ("high_object", "case.toml", "flat_roll = 1.5707963267948966", "flat_roll = 0.3",
     "field 'skill[1].options.flat_roll': must be -pi/2, 0 (chosen by the room) or pi/2 "
     "(the prong carried flat), got 0.3 rad"),
    ("high_object", "case.toml", "flat_roll = 1.5707963267948966", "flat_roll = 4.71238898",
     "field 'skill[1].options.flat_roll': must be -pi/2, 0 (chosen by the room) or pi/2 "
     "(the prong carried flat), got 4.71239 rad"),
    # the bodies whose strike by the robot decides a trial: a typo would watch nothing
    ("hook_tube", "scene.toml", 'keep_clear = ["tube1", "riser1"]',
     'keep_clear = ["tube1", "riser"]',
     "field 'robot.keep_clear': 'riser' is no [[body]] of the scene (table1, riser1, "
     "tube1, cube1) (did you mean 'riser1'?)"),
    # in the table of an arm that is not the one running (the case's Baxter)
    ("hook_tube", "scene.toml", "steps_per_waypoint = 1\n",
     'steps_per_waypoint = 1\nkeep_clear = ["tube"]\n',
     "field 'robot.panda.keep_clear': 'tube' is no [[body]] of the scene (table1, riser1, "
     "tube1, cube1) (did you mean 'tube1'?)"),
    ("paddle_tube", "scene.toml", 'keep_clear = ["tube1", "riser1"]', 'keep_clear = "tube1"',
     "field 'robot.keep_clear': must be a list of [[body]] names, got 'tube1'"),
]


@pytest.mark.parametrize("folder, file, old, new, message", WORLD_OPTIONS,
                         ids=[f"{c[0]} {c[3][:40]}" for c in WORLD_OPTIONS])
def test_an_option_that_cannot_work_is_refused_when_the_world_loads(
        tmp_path, folder, file, old, new, message):
    from creative_py.backends.pybullet import load_world
    from creative_py.case import manifest_of_folder
    from creative_py.world_files import WorldFileError

    world = tmp_path / folder
    shutil.copytree(WORLDS_ROOT / folder, world)
    text = (world / file).read_text()
    assert old in text, old
    (world / file).write_text(text.replace(old, new, 1))
    with pytest.raises(WorldFileError) as info:
        load_world(manifest_of_folder(world), world)
    assert str(info.value) == f"{world / file}: {message}"


@pytest.mark.parametrize("row", [WORLD_OPTIONS[2], WORLD_OPTIONS[16]],
                         ids=["an oracle's object", "a skill's list"])
def test_an_option_that_cannot_work_stops_the_trial_command_in_one_line(tmp_path, row):
    """Before: a KeyError traceback (the oracle's) and a ValueError traceback (the
    skill's), after the physics had run."""
    folder, file, old, new, message = row
    world = tmp_path / folder
    shutil.copytree(WORLDS_ROOT / folder, world)
    (world / file).write_text((world / file).read_text().replace(old, new, 1))
    proc = creative("trial", "clean_table", "--world", str(world), "--tool", "rake_c1")
    assert refused(proc) == f"error: {world / file}: {message}"
