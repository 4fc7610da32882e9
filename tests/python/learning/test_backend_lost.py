"""A backend lost mid-run (an arm gone silent over ROS 2, a simulator's process dead)
stops the run resumably: the trial it was running is recorded as not as planned in
``stopped.json`` (with the skill it was in), not as a failure in ``trials.jsonl`` (it
labels nothing); the folder keeps the trials before it and says how to go on, the
command line prints one line and exits 75, and a resume runs the lost trial again and
the rest, its report saying which trial was lost.

The backend here is the hook case's pybullet backend behind a scripted wrapper whose
episode raises :class:`creative_py.simulator.BackendLost` from ``run_skill`` in the
third trial, as the ROS 2 backend's episode raises its ``ArmUnavailable`` (a
``BackendLost``) when the arm went silent.
"""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

import creative_py.simulator.loader as loader
from creative_py.learning.options import RunOptions
from creative_py.learning.run import STOPPED, resume_run, run_case
from creative_py.simulator import BackendLost

pytestmark = pytest.mark.sim

_REAL_BACKEND_FOR = loader.backend_for
SILENT = "the clock on '/clock' stopped 3.01 s ago: the simulated arm died or froze"


class _LosingEpisode:
    """The real episode; the skills of the backend's ``lose_at``-th trial (the
    ``lose_at``-th episode that runs a skill) raise BackendLost: the arm is gone."""

    def __init__(self, backend, cm) -> None:
        self._backend, self._cm, self._ep, self._counted = backend, cm, cm.__enter__(), False

    def run_skill(self, name, pose=None):
        if not self._counted:
            self._counted = True
            self._backend.trials += 1
        if self._backend.trials == self._backend.lose_at:
            raise BackendLost(SILENT)
        return self._ep.run_skill(name, pose)

    def __getattr__(self, name):
        return getattr(self._ep, name)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return self._cm.__exit__(*exc)


class _LosingBackend:
    """The case's backend, scripted to lose its arm in trial ``lose_at``."""

    def __init__(self, real, lose_at: int) -> None:
        self.real, self.lose_at, self.trials = real, lose_at, 0

    def open_episode(self, *args, **kwargs):
        return _LosingEpisode(self, self.real.open_episode(*args, **kwargs))

    def __getattr__(self, name):
        return getattr(self.real, name)


@pytest.fixture
def losing(monkeypatch):
    made = {}

    def backend_for(manifest):
        if "b" not in made:
            made["b"] = _LosingBackend(_REAL_BACKEND_FOR(manifest), 3)
        return made["b"]

    monkeypatch.setattr(loader, "backend_for", backend_for)
    return made


def test_a_lost_backend_stops_the_run_resumably_and_a_resume_finishes_it(tmp_path, losing,
                                                                          monkeypatch):
    options = RunOptions(phase="use", video="none", world_seed=None, max_trials=4)
    said: list[str] = []
    with pytest.raises(BackendLost) as err:
        run_case("hook", tmp_path, options, progress=said.append, run_name="lost")
    folder = tmp_path / "lost"
    lines = (folder / "trials.jsonl").read_text().splitlines()
    assert losing["b"].trials == 3
    assert len(lines) >= 1  # the trials before it are kept, the lost one is not recorded
    assert all(json.loads(line)["outcome"] != "invalid" for line in lines)
    note = json.loads((folder / STOPPED).read_text())
    command = f"creative run hook --resume {folder}"
    lost = note.pop("lost_trial")
    assert note == {"stopped": "the backend was lost", "reason": SILENT,
                    "trials_recorded": len(lines), "resume": command}
    # the trial it was running: the next one, in the first skill of the case
    assert lost.pop("pose").keys() == {"dx", "dy", "roll"}
    assert lost == {"trial": len(lines) + 1, "phase": "use", "phase_trial": len(lines) + 1,
                    "tool": lost["tool"], "variant": "standard", "location": 1,
                    "skill": "pick_up", "outcome": "not as planned", "reason": SILENT,
                    "learned": False}
    assert err.value.resume_command == command
    assert said[-1] == (f"stopped after {len(lines)} recorded trial(s): the backend was lost "
                        f"in trial #{len(lines) + 1} ({lost['tool']} at location 1, skill "
                        f"pick_up), which did not go as planned and is run again on "
                        f"resuming ({SILENT}); to go on once it is back: {command}")
    assert not (folder / "summary.json").exists()
    # the arm is back: the resume replays the kept trials, runs the lost one again (as
    # planned then: the same tool) and the rest
    monkeypatch.setattr(loader, "backend_for", _REAL_BACKEND_FOR)
    resume_run(folder, progress=said.append)
    assert (folder / "summary.json").exists() and not (folder / STOPPED).exists()
    resumed = (folder / "trials.jsonl").read_text().splitlines()
    assert resumed[:len(lines)] == lines and len(resumed) > len(lines)
    again = json.loads(resumed[len(lines)])
    assert (again["trial"], again["tool"]) == (lost["trial"], lost["tool"])
    summary = json.loads((folder / "summary.json").read_text())
    assert summary["resumed"]["lost_trial"]["trial"] == lost["trial"]
    from creative_py.report.contents import read_run
    from creative_py.report.headline import headline

    text = "\n".join(headline(read_run(folder)).lines)
    assert (f"Trial #{lost['trial']} ({lost['tool']} at location 1) did not go as planned: "
            f"the backend was lost, in skill pick_up ({SILENT})") in text


def test_the_command_line_says_in_one_line_how_to_go_on_and_exits_75(monkeypatch, tmp_path):
    import creative_py.cli as cli
    import creative_py.learning.run as run

    def lost(*args, **kwargs):
        exc = BackendLost(SILENT + "\n(second line)")
        exc.resume_command = f"creative run hook --resume {tmp_path / 'r'}"
        raise exc

    monkeypatch.setattr(run, "run_case", lost)
    result = CliRunner().invoke(cli.app, ["run", "hook", "--out", str(tmp_path)])
    assert result.exit_code == 75, result.output
    err = result.stderr if hasattr(result, "stderr") else result.output
    assert err.strip().splitlines()[-1] == (
        f"error: the backend was lost: {SILENT} (second line); the run stopped, to go on: "
        f"creative run hook --resume {tmp_path / 'r'}")
