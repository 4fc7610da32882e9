"""Every number of the world files and of the command line has finite bounds.

A value outside its bounds is refused when the world loads (before any physics), in
one line naming the file and the field, or the option: before these bounds
``settle_time = 1e6`` and a skill's ``settle_steps = 1e9`` ran the physics without end,
``solver_iterations = 100000000000`` gave a traceback, and a skill's ``speed = 0``,
``--out ''`` and ``--variant ''`` were taken silently (issue 19). The shipped worlds
lie well inside every bound.
"""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from creative_py.case import load_cases, manifest_of_folder
from creative_py.backends.pybullet import load_world
from creative_py.world_files import WORLDS_ROOT, WorldFileError

BANNER = "pybullet build time"


def _copy(tmp_path: Path, folder: str) -> Path:
    d = tmp_path / folder
    shutil.copytree(WORLDS_ROOT / folder, d)
    return d


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{old!r} not in {path.name}"
    path.write_text(text.replace(old, new, 1))


# (world folder, file, text, replacement, what the error says)
WORLD_CASES = [
    ("hook_tube", "physics.toml", "time_step = 0.004166666666666667", "time_step = 1.0",
     r"physics\.toml: field 'time_step': must be <= 0\.05"),
    ("hook_tube", "physics.toml", "solver_iterations = 50", "solver_iterations = 100000000000",
     r"physics\.toml: field 'solver_iterations': must be <= 1000"),
    ("hook_tube", "physics.toml", "gravity = [0.0, 0.0, -9.81]", "gravity = [0.0, 0.0, -1e9]",
     r"physics\.toml: field 'gravity': every number must be >= -100"),
    ("wedge_door", "physics.toml", "time_step = 0.004166666666666667", "time_step = 1e-9",
     r"physics\.toml: field 'arm\.time_step': must be >= 0\.0001"),
    ("hook_tube", "scene.toml", "settle_time = 0.25", "settle_time = 1e6",
     r"scene\.toml: field 'settle_time': must be <= 10"),
    ("hook_tube", "scene.toml", "turn_speed = 2.0", "turn_speed = 1e9",
     r"scene\.toml: field 'robot\.turn_speed': must be <= 10"),
    ("hook_tube", "scene.toml", "steps_per_waypoint = 8", "steps_per_waypoint = 1000000000",
     r"scene\.toml: field 'robot\.steps_per_waypoint': must be <= 1000"),
    ("hook_tube", "scene.toml", "keep = 1", "keep = 1000000",
     r"scene\.toml: field 'robot\.start\.keep': must be <= 100"),
    ("hook_tube", "scene.toml", 'position = ["0.58 - 0.1", -0.45, "travel_z"]',
     'position = ["0.58 - 0.1", -0.45, "travel_z * 1e9"]',
     r"scene\.toml: field 'robot\.start\.position': must lie within \[-10, 10\] m"),
    ("hook_tube", "scene.toml", "depth_sigma_m = 0.0005", "depth_sigma_m = 3.0",
     r"scene\.toml: field 'perception\.depth_sigma_m': must be <= 0\.1"),
    ("hook_tube", "scene.toml", "pedestal_width = 0.02", "pedestal_width = 1e6",
     r"scene\.toml: field 'tool_start\.pedestal_width': must lie within \[-10, 10\]"),
    ("hook_tube", "scene.toml", "inner_height = 0.07", "inner_height = 1e6",
     r"scene\.toml: body\[2\]: body tube1: inner_height must lie within \[0, 10\] m"),
    ("hook_tube", "scene.toml", "mass = 0.05", "mass = 1e9",
     r"body cube1: mass must lie within \[0, 1000\] kg"),
    ("wedge_door", "scene.toml", "swing_speed = 1.0", "swing_speed = 0.0",
     r"body door1: swing_speed must lie within \[0\.001, 100\] rad/s"),
    ("hook_tube", "objects.toml", 'hook_side = "right"', 'hook_side = "right"\nfriction = 1e9',
     r"objects\.toml: field 'tool\[0\]\.friction': must be <= 10"),
    ("hook_tube", "tasks.toml", 'limit = "tube1.mouth_x"', 'limit = "tube1.mouth_x * 1e12"',
     r"tasks\.toml: field 'oracle\.limit': must lie within \[-10, 10\] m"),
    ("wedge_door", "tasks.toml", "max_close_deg = 2.0", "max_close_deg = 1e9",
     r"tasks\.toml: field 'oracle\.max_close_deg': must lie within \[0, 180\] deg"),
    ("hook_tube", "tasks.toml", "set = {back_gap = 0.04, lateral = 0.0}",
     "set = {back_gap = -1e7, lateral = 0.0}",
     r"body cube1: position must lie within \[-10, 10\] m"),
    ("hook_tube", "case.toml", "settle_steps = 60", "settle_steps = 1e9",
     r"case\.toml: field 'skill\[2\]\.options\.settle_steps': must lie within \[0, 10000\] "
     r"steps"),
    ("hook_tube", "case.toml", "settle_steps = 60", "settle_steps = 60.5",
     r"case\.toml: field 'skill\[2\]\.options\.settle_steps': must be a whole number"),
    ("hook_tube", "case.toml", "until_x = \"tube1.mouth_x - 0.05\", speed = 0.20",
     "until_x = \"tube1.mouth_x - 0.05\", speed = 0",
     r"case\.toml: field 'skill\[2\]\.options\.speed': must lie within \[0\.001, 2\] m/s"),
    ("hook_tube", "case.toml", "approach = 0.10", "approach = \"travel_z * 1e6\"",
     r"case\.toml: field 'skill\[0\]\.options\.approach': must lie within \[0, 1\] m, got "
     r"[-0-9.e+]+ \(variant standard, location 1\)"),
    ("hook_tube", "case.toml", "posture_search = true", "posture_search = 1",
     r"case\.toml: field 'skill\[1\]\.options\.posture_search': must be true or false"),
    ("hook_tube", "case.toml", "posture_search = true", 'posture_search = "yes"',
     r"case\.toml: field 'skill\[1\]\.options\.posture_search': must be true or false, "
     r"got 'yes'"),
    ("wedge_door", "case.toml", "duration = 4.0", "duration = 1e9",
     r"case\.toml: field 'skill\[2\]\.options\.duration': must lie within \[0, 60\] s"),
    ("wedge_door", "case.toml", "settle_time = 0.25}", "settle_time = 1e6}",
     r"case\.toml: field 'skill\[1\]\.options\.settle_time': must lie within \[0, 10\] s"),
    ("hook_tube", "case.toml", "trial_budget = 12", "trial_budget = 1000000000",
     r"case\.toml: field 'trial_budget': must be <= 10000"),
    ("hook_tube", "case.toml", "max = 0.50", "max = 1e9",
     r"case\.toml: field 'pose\.param\[0\]\.max': must be <= 10"),
    ("hook_tube", "case.toml", "jitter = 0.005", "jitter = 1e12",
     r"case\.toml: field 'randomise\.location\.back_gap\.jitter': must be <= 1000"),
]


@pytest.mark.parametrize("folder, file, old, new, message", WORLD_CASES,
                         ids=[f"{c[1]}: {c[3][:40]}" for c in WORLD_CASES])
def test_a_number_outside_its_bounds_is_refused_naming_file_and_field(
        tmp_path, folder, file, old, new, message):
    d = _copy(tmp_path, folder)
    _edit(d / file, old, new)
    with pytest.raises(WorldFileError, match=message):
        load_world(manifest_of_folder(d), d)


def test_the_shipped_worlds_lie_inside_every_bound():
    for case, manifest in load_cases().items():
        if manifest.backend != "pybullet":
            continue  # these bounds are the pybullet world files' (scene.toml, physics.toml)
        world = load_world(manifest)
        assert world.locations, case


def test_every_option_of_every_primitive_and_oracle_has_bounds():
    """A new numeric option without bounds would let a number run the physics without
    end: each option is a flag, a word, or bounded; each default lies inside."""
    from creative_py.world.oracles import ORACLES
    from creative_py.world.oracles import OPTION_BOUNDS as ORACLE_BOUNDS
    from creative_py.world.skills import OPTION_BOUNDS, SKILLS, option_flags

    flags = option_flags()
    for p in SKILLS.values():
        for name, default in p.options.items():
            own = p.bounds.get(name) or OPTION_BOUNDS.get(name)   # its own bounds first
            assert name in flags or own, (p.name, name)
            if default is not None and own:
                lo, hi, _unit = own
                assert lo <= default <= hi, (p.name, name, default)
    for o in ORACLES.values():
        for name in o.options:
            assert name in ORACLE_BOUNDS or name in {o.subject, *o.words}, (o.name, name)
    own = [b for p in SKILLS.values() for b in p.bounds.values()]
    assert all(math.isfinite(lo) and math.isfinite(hi)
               for lo, hi, _ in [*OPTION_BOUNDS.values(), *ORACLE_BOUNDS.values(), *own])


# ------------------------------------------------------------------- the command line
def creative(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "creative_py.cli", *args],
                          capture_output=True, text=True, timeout=120)


def _one_line(proc: subprocess.CompletedProcess, message: str) -> None:
    lines = [line for line in proc.stderr.splitlines() if line and BANNER not in line]
    assert proc.returncode == 2, proc.stderr
    assert len(lines) == 1 and lines[0].startswith("error: "), proc.stderr
    assert message in lines[0], lines[0]


def test_a_world_whose_settle_time_would_hang_is_refused_in_one_line(tmp_path):
    d = _copy(tmp_path, "hook_tube")
    _edit(d / "scene.toml", "settle_time = 0.25", "settle_time = 1e6")
    _one_line(creative("trial", "hook", "--world", str(d), "--tool", "hook_a2"),
              "scene.toml: field 'settle_time': must be <= 10")


def test_a_run_whose_skill_option_would_hang_is_refused_in_one_line(tmp_path):
    d = _copy(tmp_path, "hook_tube")
    _edit(d / "case.toml", "settle_steps = 60", "settle_steps = 1e9")
    _one_line(creative("run", "hook", "--world", str(d), "--phase", "use", "--video", "none",
                       "--out", str(tmp_path / "runs")),
              "case.toml: field 'skill[2].options.settle_steps': must lie within")
    assert not (tmp_path / "runs").exists() or not any((tmp_path / "runs").iterdir())


def test_solver_iterations_too_many_for_pybullet_is_one_line(tmp_path):
    d = _copy(tmp_path, "hook_tube")
    _edit(d / "physics.toml", "solver_iterations = 50", "solver_iterations = 100000000000")
    _one_line(creative("trial", "hook", "--world", str(d), "--tool", "hook_a2"),
              "physics.toml: field 'solver_iterations': must be <= 1000")


CLI_CASES = [
    (["run", "hook", "--out", ""], "--out must name a folder, got an empty string"),
    (["sweep", "hook", "--serial", "--out", ""], "--out must name a folder"),
    (["make-tool", "hook", "handle_length=long", "--out", ""], "--out must name a folder"),
    (["trial", "hook", "--tool", "hook_a2", "--variant", ""], "--variant must not be empty"),
    (["trial", "hook", "--tool", "hook_a2", "--save-images", " "],
     "--save-images must name a folder"),
    (["make-tool", "hook", "handle_length=long", "--variant", "", "--out", "{tmp}/t"],
     "--variant must not be empty"),
    (["run", "hook", "--world", ""], "--world must name a folder"),
    (["run", "hook", "--max-trials", "1000000000"], "--max-trials must be at most 10000"),
    (["run", "hook", "--eval-trials", "1000000"], "--eval-trials must be at most 1000"),
    (["run", "hook", "--consecutive", "1000000"], "--consecutive must be at most 10000"),
    (["run", "hook", "--world-seed", str(2 ** 64)], "--world-seed must be at most"),
    (["trial", "hook", "--tool", "hook_a2", "--seed", str(2 ** 64)], "--seed must be at most"),
    (["sweep", "hook", "--max-trials", "1000000000"], "--max-trials must be at most 10000"),
    (["sweep", "hook", "--num-cpus", "1000000"], "--num-cpus must be at most 1024"),
    (["make-tool", "hook", "handle_length=long", "--build-volume", "1e12,210,210",
      "--out", "{tmp}/t"], "--build-volume '1e12,210,210'"),
]


@pytest.mark.parametrize("args, message", CLI_CASES,
                         ids=[" ".join(a) or "''" for a, _ in CLI_CASES])
def test_an_option_outside_its_bounds_is_one_line_with_exit_code_2(tmp_path, args, message):
    _one_line(creative(*[a.format(tmp=tmp_path) for a in args]), message)
