"""Bad input is refused in one line, with exit code 2, quickly, and nothing is lost.

Each row of :data:`CORPUS` is a command a user might type; the test runs the real
``creative`` command line in its own process and checks what the user sees: exit code
2, one line ``error: ...`` on stderr naming the option or file and the cause, no
traceback. (pybullet's import banner, which it prints itself, is the one other line a
command may show.) How long each refusal takes (aim: under 10 s) is measured by
``bench/bad_input_bench.py``, not asserted here.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from creative_py.learning.strategies import STRATEGIES

BANNER = "pybullet build time"


def creative(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "creative_py.cli", *args],
                          capture_output=True, text=True, timeout=60, cwd=cwd)


@pytest.fixture()
def a_file(tmp_path) -> Path:
    path = tmp_path / "a_file"
    path.write_text("not a folder\n")
    return path


CORPUS = [
    (["run", "hok"], "unknown case 'hok'; known cases:"),
    (["run", "hook", "--max-trials", "0"], "--max-trials must be at least 1, got 0"),
    (["run", "hook", "--consecutive", "-1"], "--consecutive must be at least 1"),
    (["run", "hook", "--eval-trials", "-2"], "--eval-trials must be at least 0"),
    (["run", "hook", "--seed", "-1"], "--seed must be at least 0"),
    (["run", "hook", "--phase", "sometimes"], "--phase: option phase must be one of"),
    (["run", "hook", "--strategy", "clever"],
     "--strategy: unknown strategy 'clever'; strategies: " + ", ".join(STRATEGIES)),
    (["sweep", "hook", "--strategies", "paper,clever"],
     "--strategies: unknown strategy 'clever'; strategies: " + ", ".join(STRATEGIES)),
    (["run", "hook", "--out", "{a_file}"], "not a folder"),
    (["run", "hook", "--world", "{tmp}/nowhere"], "nowhere/case.toml: file not found"),
    # a folder nothing can be created in (root ignores permission bits; /proc refuses)
    (["run", "hook", "--out", "/proc/creative_runs"], "/proc/creative_runs: "),
    (["make-tool", "hook", "handle_length=long", "--out", "/proc/creative_tools"],
     "/proc/creative_tools"),
    # The trial command's unknown tool, unknown variant, bad location and unreadable
    # pose are each one fail line of cli.trial, checked with their messages and exit
    # code 2 in this process by test_cli_trial.py (test_bad_arguments_give_a_clear_error);
    # the rows below keep a real process of the command for fail's one line.
    (["trial", "hook", "--tool", "hook_a2", "--pose", "0.03,0,1e9"],
     "--pose: roll must be within"),
    (["trial", "hook", "--tool", "hook_a2", "--seed", "-1"], "--seed must be at least 0"),
    (["trial", "hook", "--tool", "hook_a2", "--save-images", "{a_file}"], "not a folder"),
    (["make-tool", "wedge", "shape=box,hook_side=left", "--out", "{tmp}/t"],
     "unknown property 'hook_side'"),
    (["make-tool", "hook", "handle_length=long", "--context", "max_tool_length((0.3",
      "--out", "{tmp}/t"], "not Prolog facts"),
    (["make-tool", "hook", "handle_length=long", "--context", "max_tool_length(foo)",
      "--out", "{tmp}/t"], "--context 'max_tool_length(foo)': the size model cannot use it"),
    # (with --html too: the command reads the folder, and fails, before it writes)
    (["report", "{tmp}"], "no trials.jsonl in this run folder"),
    (["make-tool", "hook", "handle_length=long", "--build-volume", "250,210",
      "--out", "{tmp}/t"], "--build-volume '250,210': expected three positive numbers"),
    (["make-tool", "hook", "handle_length=long", "--build-volume", "250,0,210",
      "--out", "{tmp}/t"], "--build-volume '250,0,210'"),
    (["report", "{tmp}", "--width", "10"], "--width 10: under 40 columns"),
]


@pytest.mark.parametrize("args, message", CORPUS, ids=[" ".join(a) for a, _ in CORPUS])
def test_bad_input_is_one_line_with_exit_code_2(tmp_path, a_file, args, message):
    args = [a.format(tmp=tmp_path, a_file=a_file) for a in args]
    proc = creative(*args)
    lines = [line for line in proc.stderr.splitlines() if line and BANNER not in line]
    assert proc.returncode == 2, proc.stderr
    assert len(lines) == 1 and lines[0].startswith("error: "), proc.stderr
    assert message in lines[0]
    assert "Traceback" not in proc.stderr + proc.stdout
    assert not (tmp_path / "t").exists()          # nothing written for a refused tool


def test_make_tool_refuses_an_existing_tool_folder_unless_told_to_overwrite(tmp_path):
    first = creative("make-tool", "hook", "handle_length=long", "--variant", "long_tube",
                     "--out", str(tmp_path), "--name", "h1", "--no-slice")
    assert first.returncode == 0, first.stderr
    # Issue 16 item 5: the tool's size and mass first, then its files.
    head = first.stdout.splitlines()[0]
    assert head.startswith("tool h1: ") and " x " in head and head.endswith(" g"), head
    assert "print: " in first.stdout and " pieces" in first.stdout
    # --no-slice: the pieces are written, not sliced, and stderr says that no slicer
    # checked them (test_unsliced_tool.py has the tool that no bed takes)
    assert [line for line in first.stderr.splitlines() if line and BANNER not in line] == [
        "warning: h1: 3 printed piece(s) written but not sliced (--no-slice): no slicer "
        "has checked them"]
    assert not list(tmp_path.rglob("*.gcode"))
    stl = tmp_path / "h1" / "h1.stl"
    before = stl.read_bytes()
    again = creative("make-tool", "hook", "handle_length=long", "--variant", "long_tube",
                     "--out", str(tmp_path), "--name", "h1", "--no-slice")
    assert again.returncode == 2
    assert "the tool's folder exists (--overwrite replaces it)" in again.stderr
    assert stl.read_bytes() == before                 # nothing already written is lost
    forced = creative("make-tool", "hook", "handle_length=long", "--variant", "long_tube",
                      "--out", str(tmp_path), "--name", "h1", "--overwrite", "--no-slice")
    assert forced.returncode == 0, forced.stderr
    assert list((tmp_path / "h1").glob("*.gcode")) == []     # --no-slice: STL pieces only
    assert len(list((tmp_path / "h1").glob("h1_part*.stl"))) >= 2


@pytest.mark.parametrize("command", [["make-tool", "hook", "handle_length=long"],
                                     ["run", "hook"]])
def test_without_the_slicer_printing_commands_stop_in_one_line_before_work(tmp_path,
                                                                          command):
    import os
    import shutil

    bin_dir = tmp_path / "bin"                 # a PATH with SWI-Prolog but no slicer
    bin_dir.mkdir()
    (bin_dir / "swipl").symlink_to(shutil.which("swipl"))
    out = tmp_path / "out"
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", *command, "--out",
                           str(out)], capture_output=True, text=True, timeout=60,
                          env={**os.environ, "PATH": str(bin_dir)})
    lines = [line for line in proc.stderr.splitlines() if line and BANNER not in line]
    assert proc.returncode == 2, proc.stderr
    assert lines == ["error: the slicer 'prusa-slicer' is not installed, and every printed "
                     "piece is sliced (make setup installs it: apt-get install prusa-slicer)"]
    assert not out.exists()


def test_a_run_whose_demonstration_fails_is_one_line_and_leaves_no_folder(tmp_path):
    import shutil

    from creative_py.world_files import WORLDS_ROOT

    world = tmp_path / "hook_tube"
    shutil.copytree(WORLDS_ROOT / "hook_tube", world)
    manifest = world / "case.toml"
    manifest.write_text(manifest.read_text().replace('tool = "hook_a2"', 'tool = "stick_a5"'))
    out = tmp_path / "runs"
    proc = creative("run", "hook", "--world", str(world), "--out", str(out))
    lines = [line for line in proc.stderr.splitlines()
             if line.startswith(("error", "Traceback"))]
    assert proc.returncode == 2, proc.stderr
    assert len(lines) == 1
    assert "case.toml: field 'demonstration': stick_a5 at location 1 did not reach the " \
           "goal in the physics" in lines[0]
    assert not out.exists() or list(out.iterdir()) == []


def _world_copy(tmp_path, old: str, new: str, file: str = "objects.toml") -> Path:
    import shutil

    from creative_py.world_files import WORLDS_ROOT

    world = tmp_path / "hook_tube"
    shutil.copytree(WORLDS_ROOT / "hook_tube", world)
    text = (world / file).read_text()
    assert old in text
    (world / file).write_text(text.replace(old, new, 1))
    return world


def test_a_catalogued_tool_named_like_a_scene_object_is_refused(tmp_path):
    world = _world_copy(tmp_path, 'name = "hook_a1"', 'name = "cube1"')
    proc = creative("trial", "hook", "--world", str(world), "--tool", "hook_a2")
    assert proc.returncode == 2, proc.stderr
    assert "objects.toml: object 'cube1': the name is already a [[body]] of scene.toml" \
        in proc.stderr
    assert "Traceback" not in proc.stderr


def test_a_dimension_outside_the_ontology_s_ranges_is_refused_before_any_trial(tmp_path):
    world = _world_copy(tmp_path, "handle_length = 0.20", "handle_length = 5.0")
    out = tmp_path / "runs"
    proc = creative("run", "hook", "--world", str(world), "--out", str(out))
    assert proc.returncode == 2, proc.stderr
    assert "objects.toml: hook_a1: handle_length outside every qualitative range" \
        in proc.stderr
    assert "outside_ranges = true" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert not out.exists()


def test_a_dimension_outside_the_ranges_is_accepted_when_the_world_says_so(tmp_path):
    from creative_py.bridge import Engine
    from creative_py.case import read_manifest
    from creative_py.learning.checks import check_catalogue
    from creative_py.backends.pybullet import load_world

    world = _world_copy(tmp_path, 'handle_length = 0.20',
                        'handle_length = 0.90\noutside_ranges = true')
    check_catalogue(Engine.instance(), load_world(read_manifest(world)))


def _tree_copy(tmp_path) -> Path:
    import shutil

    root = Path(__file__).resolve().parents[2]
    copy = tmp_path / "tree"
    for folder in ("creative_py", "prolog", "ontology", "worlds", "robots"):
        shutil.copytree(root / folder, copy / folder,
                        ignore=shutil.ignore_patterns("__pycache__"))
    return copy


def _run_in_tree(copy: Path, tmp_path: Path, *args: str) -> tuple[subprocess.CompletedProcess,
                                                                 list[str]]:
    """Run ``creative`` from the copy of the tree; return the process and its error lines."""
    import os

    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", *args],
                          capture_output=True, text=True, timeout=60,
                          env={**os.environ, "PYTHONPATH": str(copy)}, cwd=tmp_path)
    return proc, [line for line in proc.stderr.splitlines() if line and BANNER not in line]


def test_an_ontology_missing_a_property_s_ranges_is_named(tmp_path):
    copy = _tree_copy(tmp_path)
    ranges = copy / "ontology" / "ranges.pl"
    ranges.write_text("\n".join(line for line in ranges.read_text().splitlines()
                                if not line.startswith("qualitative_range(handle_length")))
    proc, lines = _run_in_tree(copy, tmp_path, "run", "hook", "--out", str(tmp_path / "runs"))
    assert proc.returncode == 2, proc.stderr
    assert lines == ["error: ontology: the property handle_length of a hook has no values "
                     "(no qualitative_range/5 in ontology/ranges.pl, nor a size_choice/4 in "
                     "ontology/kinds/)"]
    assert not (tmp_path / "runs").exists()


@pytest.mark.parametrize("bad, message, debug", [
    ("broken(:- .", "rake.pl:", True),
    # the engine's consult raises PrologLoadError here, PrologSyntaxError above: both
    # BridgeErrors, re-raised under --debug by the same line of cli.errors.one_line_errors,
    # so the first case's --debug run checks this one's
    ("p(X) :- undefined_thing(X).", "Unknown procedure: undefined_thing/1", False),
])
def test_a_broken_ontology_file_is_one_line_and_debug_shows_the_traceback(tmp_path, bad,
                                                                           message, debug):
    import os

    copy = _tree_copy(tmp_path)
    with open(copy / "ontology" / "cases" / "rake.pl", "a") as fh:
        fh.write("\n" + bad + "\n")
    env = {**os.environ, "PYTHONPATH": str(copy)}
    out = tmp_path / "runs"
    cmd = [sys.executable, "-m", "creative_py.cli", "run", "rake", "--out", str(out)]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=60, env=env,
                          cwd=tmp_path)
    lines = [line for line in proc.stderr.splitlines() if line and BANNER not in line]
    assert proc.returncode == 2, proc.stderr
    assert len(lines) == 1 and lines[0].startswith("error: ") and message in lines[0]
    assert str(copy / "ontology" / "cases" / "rake.pl") in lines[0]
    assert not out.exists()
    if debug:
        traced = subprocess.run(cmd[:3] + ["--debug"] + cmd[3:], capture_output=True,
                                text=True, timeout=60, env=env, cwd=tmp_path)
        assert traced.returncode != 0 and "Traceback" in traced.stderr


@pytest.mark.parametrize("command", [
    ["report", "{tmp}/no_such_run"],
    ["make-tool", "hook", "handle_length=huge", "--out", "{tmp}/t"],
    ["run", "hook", "--world", "{tmp}", "--out", "{tmp}/runs"],
    ["trial", "hook", "--world", "{tmp}"],
])
def test_debug_shows_the_traceback_of_every_commands_error(tmp_path, command):
    """Issue 16 item 6: an error a command catches and words in one line shows its
    traceback under ``--debug`` (and the same line last)."""
    command = [c.format(tmp=tmp_path) for c in command]
    plain = creative(*command)
    lines = [line for line in plain.stderr.splitlines() if line and BANNER not in line]
    assert plain.returncode == 2 and len(lines) == 1 and lines[0].startswith("error: ")
    debug = creative("--debug", *command)
    assert debug.returncode == 2 and "Traceback (most recent call last)" in debug.stderr
    assert debug.stderr.rstrip().splitlines()[-1] == lines[0]


def test_a_case_file_lacking_a_hook_predicate_is_named_before_the_run(tmp_path):
    copy = _tree_copy(tmp_path)
    rake = copy / "ontology" / "cases" / "rake.pl"
    rake.write_text(rake.read_text().replace("relative_pose(rake,", "relative_pose_x(rake,"))
    proc, lines = _run_in_tree(copy, tmp_path, "run", "rake", "--out", str(tmp_path / "runs"))
    assert proc.returncode == 2, proc.stderr
    assert lines == ["error: ontology/cases/rake.pl: case rake does not answer the engine's "
                     "hook predicate(s) relative_pose/5 (ontology/README.md lists them)"]
    assert not (tmp_path / "runs").exists()


def test_a_case_naming_no_kind_s_class_says_what_to_rename_in_one_line(tmp_path):
    """A kind's root class need not be named like its file (the paddle kind's file
    renamed paddles.pl still runs the paddle case's ontology); a case's tool class that
    no kind has is named at once, with the root classes to rename it to."""
    copy = _tree_copy(tmp_path)
    kinds = copy / "ontology" / "kinds"
    (kinds / "paddle.pl").rename(kinds / "paddles.pl")
    text = (kinds / "paddles.pl").read_text()
    (kinds / "paddles.pl").write_text(text.replace("kind(paddle).", "kind(paddles)."))
    (copy / "creative_py" / "kinds" / "paddle.py").rename(copy / "creative_py" / "kinds" /
                                                          "paddles.py")
    proc, lines = _run_in_tree(copy, tmp_path, "make-tool", "paddle_tube",
                               "shaft_length=long", "--name", "p1", "--no-slice",
                               "--out", str(tmp_path / "tools"))
    assert proc.returncode == 0, proc.stderr
    assert not [line for line in lines if line.startswith("error")], proc.stderr
    assert (tmp_path / "tools" / "p1").is_dir()
    case = copy / "ontology" / "cases" / "paddle_tube.pl"
    case.write_text(case.read_text().replace("case_tool_class(paddle_tube, paddle).",
                                             "case_tool_class(paddle_tube, paddles)."))
    line = next(n for n, t in enumerate(case.read_text().splitlines(), 1)
                if t.startswith("case_tool_class("))
    proc, lines = _run_in_tree(copy, tmp_path, "run", "paddle_tube", "--out",
                               str(tmp_path / "runs"))
    assert proc.returncode == 2, proc.stderr
    assert len(lines) == 1 and lines[0].startswith("error: ")
    roots = ", ".join(
        f"{m.group(1)} of kinds/{p.name}" for p in sorted(kinds.glob("*.pl"))
        for m in [re.search(r"^subclass_of\((\w+), (?:tool|object)\)\.", p.read_text(), re.M)])
    assert "paddle of kinds/paddles.pl" in roots and "hook_like of kinds/hook_like.pl" in roots
    assert lines[0].endswith(
        f"{case}:{line}: case_tool_class/2 names the tool class paddles, which no kind of "
        f"ontology/kinds/ has: rename it to a kind's root class ({roots}), or add "
        f"subclass_of(paddles, tool) to its kind's file")
    assert not (tmp_path / "runs").exists()
