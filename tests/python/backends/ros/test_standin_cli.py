"""The stand-in's command line: bad input is one line naming the option, exit 2, before
ROS or the physics start (so these run without the ros extra and send nothing)."""

from __future__ import annotations

import pytest

from creative_py.backends.ros.standin import main

PROG = "creative_py.backends.ros.standin: "


@pytest.mark.parametrize("argv,message", [
    (["--case", "nosuch"], "unknown case 'nosuch'"),
    (["--case", "hook", "--variant", "nope"], "option --variant: 'nope' is not a variant of hook"),
    (["--case", "hook", "--location", "9"], "option --location: 9 is not a location of hook"),
    (["--case", "hook", "--tool", "nope"], "unknown tool 'nope'"),
    (["--case", "hook", "--profile", "nosuch"], "no robot profile 'nosuch'"),
    (["--case", "hook", "--realtime", "0"], "option --realtime: must be in [0.01, 100.0]"),
    (["--case", "hook", "--seconds", "-1"], "option --seconds: must be > 0"),
    (["--case", "pull_cube_tool"], "the stand-in builds pybullet scenes"),
])
def test_bad_input_is_one_line_and_exit_2(argv, message, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith(PROG) and message in err and err.count("\n") == 1
