"""The launcher of a run beside the stand-in (make run BACKEND=ros): which case and
profile it starts the stand-in with, what it runs, and the resume command the learner
prints under it. No ROS here: the launcher's plan and the hint's text."""

from __future__ import annotations

import json

import pytest

from creative_py.backends.ros.launch import PROG, LaunchError, main, plan
from creative_py.learning.options import RunOptions, run_json
from creative_py.records.folder import RESUME_ENV, resume_command


def _run_folder(tmp_path, name, case="hook", **options):
    folder = tmp_path / name
    folder.mkdir()
    meta = run_json(case, RunOptions(backend="ros", **options), None, None)
    (folder / "run.json").write_text(json.dumps(meta))
    return folder


def test_a_new_run_takes_the_case_from_its_command_and_records_its_profile():
    # no profile given: the case's robot (worlds/hook_tube/case.toml names baxter); the
    # learner's run.json records the profile, so that a resume keeps it
    args, case, profile, command = plan(["--", "run", "hook", "--backend", "ros"])
    assert (case, profile, command) == ("hook", "baxter", ["run", "hook", "--backend", "ros",
                                                           "--robot", "baxter"])
    _, case, profile, command = plan(["--profile", "mylab.toml", "--", "run", "hook"])
    assert (case, profile, command) == ("hook", "mylab.toml",
                                        ["run", "hook", "--robot", "mylab.toml"])
    _, _, profile, command = plan(["--", "run", "hook", "--robot", "lab.toml"])
    assert profile == "lab.toml" and command.count("--robot") == 1
    _, _, profile, command = plan(["--", "run", "hook", "--robot-profile", "lab.toml"])
    assert profile == "lab.toml" and command.count("--robot") == 0


def test_the_learner_gets_the_stand_ins_profile_on_its_command_line():
    # the profile travels as --robot (no environment variable): a trial too
    _, case, profile, command = plan(["--case", "hook", "--profile", "lab.toml", "--",
                                      "trial", "hook", "--backend", "ros"])
    assert command == ["trial", "hook", "--backend", "ros", "--robot", "lab.toml"]
    assert plan(["--case", "hook", "--", "cases"])[3] == ["cases"]


def test_a_resume_takes_case_and_profile_from_the_runs_run_json(tmp_path):
    folder = _run_folder(tmp_path, "hook-1", robot="mylab.toml")
    _, case, profile, command = plan(["--resume", str(folder)])
    assert (case, profile, command) == ("hook", "mylab.toml",
                                        ["run", "hook", "--resume", str(folder)])
    plain = _run_folder(tmp_path, "hook-2")
    assert plan(["--resume", str(plain), "--profile", "baxter"])[2] == "baxter"


@pytest.mark.parametrize("argv,message", [
    ([], "give the creative command after -- (or --resume DIR)"),
    (["--", "trial", "x"], "--case: the case the stand-in builds is needed"),
    (["--profile", "a.toml", "--", "run", "hook", "--robot", "b.toml"],
     "--profile a.toml: the command's --robot is 'b.toml'"),
])
def test_a_bad_command_line_is_one_line_and_exit_2(argv, message, capsys):
    with pytest.raises(LaunchError, match="^" + message.replace("(", r"\(").replace(")", r"\)")):
        plan(argv)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err == f"{PROG}: {message}\n"


def test_a_resume_refuses_another_profile_a_command_or_a_folder_without_run_json(
        tmp_path, capsys):
    folder = _run_folder(tmp_path, "hook-1", robot="mylab.toml")
    with pytest.raises(LaunchError, match="recorded with the robot profile 'mylab.toml'"):
        plan(["--resume", str(folder), "--profile", "baxter"])
    with pytest.raises(LaunchError, match="give no creative command"):
        plan(["--resume", str(folder), "--", "run", "hook"])
    with pytest.raises(LaunchError, match="is of case 'hook'"):
        plan(["--resume", str(folder), "--case", "wedge"])
    assert main(["--resume", str(tmp_path / "nothing")]) == 2
    assert capsys.readouterr().err == (f"{PROG}: --resume: {tmp_path / 'nothing'}: not a "
                                       "resumable run folder (no run.json)\n")
    broken = tmp_path / "broken"
    broken.mkdir()
    (broken / "run.json").write_text('{"case": "hook", "options": {"robot_profile": 3}}')
    with pytest.raises(LaunchError, match="field 'options.robot' is not text"):
        plan(["--resume", str(broken)])
    (broken / "run.json").write_text('{"case": "hook", "options": {"robot": "panda"}}')
    assert plan(["--resume", str(broken)])[2] == "panda"
    (broken / "run.json").write_text('{"case": 3, "options": {}}')
    with pytest.raises(LaunchError, match="field 'case' or 'options' is missing"):
        plan(["--resume", str(broken)])
    (broken / "run.json").write_text("[1, 2")
    with pytest.raises(LaunchError, match=r"run.json: not JSON \("):
        plan(["--resume", str(broken)])


def test_the_resume_hint_is_the_launchers_command_when_one_started_the_learner(
        monkeypatch):
    monkeypatch.delenv(RESUME_ENV, raising=False)
    assert resume_command("hook", "runs/hook-1") == "creative run hook --resume runs/hook-1"
    assert resume_command("hook", "my runs/h") == "creative run hook --resume 'my runs/h'"
    monkeypatch.setenv(RESUME_ENV, "make run BACKEND=ros RESUME={run}")
    assert resume_command("hook", "runs/hook-1") == "make run BACKEND=ros RESUME=runs/hook-1"
    monkeypatch.setenv(RESUME_ENV, f"{PROG} --resume")
    assert resume_command("hook", "runs/h") == f"{PROG} --resume runs/h"


def test_an_unknown_case_without_a_profile_is_one_line_naming_it(capsys):
    assert main(["--", "run", "nosuchcase"]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"{PROG}: --case nosuchcase: ") and err.count("\n") == 1
