"""Which trials become clips (``--video all|key|none``) and the options that choose it."""

import os

import pytest
from typer.testing import CliRunner

from creative_py.cli import app
from creative_py.learning.clips import ClipKeeper, failure_reason
from creative_py.learning.run import RunOptions

BLOCKED = "position_tool: gripper lagged its target by {} cm at (0.978, -0.250, -0.052) m"

# phase, outcome, reason of a run's trials, in order (a hook run's shape).
RUN = [("demo", "success", "goal reached"),
       ("use", "blocked", BLOCKED.format(3.1)),
       ("use", "failure", "goal not reached"),
       ("use", "failure", "goal not reached"),
       ("use", "success", "goal reached"),
       ("use", "blocked", BLOCKED.format(3.4)),
       ("use", "unreachable", "the camera does not see cube1"),
       ("eval", "success", "goal reached"),
       ("create", "blocked", BLOCKED.format(2.9)),
       ("create", "success", "goal reached")]


def _whys(mode):
    keeper = ClipKeeper(mode, "/nonexistent", spec=object(), new_recorder=lambda spec: None)
    return [keeper.why(*t) for t in RUN]


def test_key_keeps_the_demonstration_first_success_creation_and_first_of_each_failure():
    assert _whys("key") == [
        "demonstration",
        "failure:blocked: position_tool: gripper lagged its target by N cm at (N, N, N) m",
        "failure:failure: goal not reached",
        None,
        "first_success",
        None,                      # the same reason as trial 1, other numbers
        "failure:unreachable: the camera does not see cube1",
        None,
        "creation",
        "creation"]


def test_all_keeps_every_trial_and_none_none():
    whys = _whys("all")
    assert None not in whys and whys[3] == whys[5] == whys[7] == "trial"
    assert _whys("none") == [None] * len(RUN)
    assert ClipKeeper("none", "/nonexistent", spec=object()).recorder() is None


def test_a_world_without_a_camera_records_nothing():
    assert ClipKeeper("all", "/nonexistent", spec=None).why("use", "failure", "x") is None


def test_failure_reasons_ignore_numbers_only():
    assert failure_reason("blocked", "lag 3.1 cm") == failure_reason("blocked", "lag -2 cm")
    assert failure_reason("blocked", "lag 3.1 cm") != failure_reason("failure", "lag 3.1 cm")
    assert failure_reason("failure", "") == "failure"
    assert failure_reason("unreachable", "cube1 at 0.5 m") == "unreachable: cube1 at N m"


@pytest.mark.parametrize("kw, message", [
    ({"video": "some"}, "option video must be one of all, key, none, got 'some'"),
    ({"video": None}, "option video must be one of"),
    ({"gui": "yes"}, "option gui must be true or false"),
])
def test_run_options_check_video_and_gui(kw, message):
    with pytest.raises(ValueError, match=message):
        RunOptions(**kw)
    with pytest.raises(ValueError, match="option video"):
        ClipKeeper("loud", "/nonexistent", spec=object())


runner = CliRunner()


def test_video_option_errors_in_one_line():
    res = runner.invoke(app, ["run", "hook", "--video", "most"])
    assert res.exit_code == 2
    assert res.output.strip() == "error: --video must be all, key or none, got 'most'"


@pytest.mark.parametrize("args", [["run", "hook", "--gui"],
                                  ["trial", "hook", "--tool", "hook_a2", "--gui"]])
def test_gui_without_a_display_is_one_line_and_exit_2(args, monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    res = runner.invoke(app, args)
    assert res.exit_code == 2
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: --gui: no display"), res.output
    assert "Traceback" not in res.output
