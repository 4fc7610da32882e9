"""The trial loop above the boundary (creative_py/simulator/trial.py), on a backend that
is no physics: a scripted episode with only the members of the Episode protocol.

What a third backend gets for free is checked here without any simulator: the skills
run in the manifest's order, the facts observed just before the tool action (or where a
blocked motion stopped), the oracle asked when the goal can have been reached, each
ending labelled by ``trial_outcome``, a non-finite true pose made ``invalid``, the load
measured once the tool acted, the verdict called back with the result taken, a
recorder rendered when no callback took it, and the simulator benchmark's ``by_hand``
and ``timings``. The physics' own trials are tested per backend
(tests/python/backends/).
"""

from __future__ import annotations

import math
import sys
import types
from contextlib import contextmanager

import pytest
from test_simulator_registry import signature_mismatches

from creative_py.backends import BACKENDS, BackendEntry
from creative_py.case import read_manifest
from creative_py.records.trial import verdict_lines, verdict_words
from creative_py.simulator import TRIAL_OUTCOMES, Episode, Observation, SkillOutcome, Verdict
from creative_py.simulator.trial import play_trial, run_trial, trial_outcome
from creative_py.simulator.types import NonFiniteState

MANIFEST = """\
id = "loopcase"
title = "A case for the trial loop"
ontology = "loopcase"
trial_budget = 2
goal = ["at(box1, shelf1)"]
backend = "fake_loop"

[roles]
tools = "tool"
target = "box1"
context = "shelf1"

[[skill]]
name = "pick_up"
primitive = "grasp"
args = ["tool"]

[[skill]]
name = "place"
primitive = "place_at_pose"
args = ["tool", "target"]
pose = true

[[skill]]
name = "push"
primitive = "push"
args = ["tool", "target", "context"]
tool_action = true

[pose]
term = "push_pose"

[[pose.param]]
name = "dx"
unit = "m"
min = -0.1
max = 0.2

[[variant]]
name = "easy"

[[variant]]
name = "hard"
harder = true

[demonstration]
tool = "stick1"
variant = "easy"
location = 1
steps = ["pick_up", "place", "push"]
[demonstration.pose]
dx = 0.05
"""

GUARD = Verdict("gripper lag", 0.04, 0.03, "m", "<", False, "max_lag",
                measures={"touching": ["robot against shelf1"]})


@pytest.fixture(autouse=True)
def _ontology_file(tmp_path_factory, monkeypatch):
    """The ontology file the manifest names (a manifest's ``ontology`` must be a file
    of ontology/cases/ that declares the case)."""
    import creative_py.case

    folder = tmp_path_factory.mktemp("ontology_cases")
    for shipped in creative_py.case.ONTOLOGY_CASES.glob("*.pl"):
        (folder / shipped.name).symlink_to(shipped)
    (folder / "loopcase.pl").write_text("case(loopcase).\n")
    monkeypatch.setattr(creative_py.case, "ONTOLOGY_CASES", folder)


class ScriptedEpisode:
    """An episode whose skills end as scripted (``ends``: skill -> SkillOutcome) and
    whose oracle says ``holds``; it logs every call."""

    render_time_s = 0.0

    def __init__(self, ends=None, holds=True, truth=None, measure_error=None):
        self.ends, self.holds = dict(ends or {}), holds
        self._truth = truth or {"box1": (0.5, 0.0, 0.8, 0.0), "stick1": (0.3, 0.1, 0.8, 0.0)}
        self.measure_error = measure_error
        self.log: list = []
        self.n_steps = 0
        self.render_time_s = 0.25

    def run_skill(self, name, pose=None, **options):
        self.log.append(("run_skill", name, pose, options))
        self.n_steps += 10
        return self.ends.get(name, SkillOutcome("ok"))

    def observe(self, cameras=True):
        self.log.append(("observe",))
        return Observation(facts=(("seen", len(self.log)),), truth=self.truth())

    def verdict(self):
        self.log.append(("verdict",))
        if self.measure_error is not None:
            raise self.measure_error
        return Verdict("box1 x", 0.7, 0.6, "m", ">", self.holds, "limit")

    def truth(self):
        return dict(self._truth)

    def sim_time(self):
        return self.n_steps * 0.01

    @property
    def steps(self):
        return self.n_steps

    def measured_load(self):
        self.log.append(("measured_load",))
        return 12.5, {"max_force_n": 12.5, "bodies": ["box1"]}


class Clip:
    """A recorder that counts its renderings."""

    snapshots: list = []

    def __init__(self):
        self.rendered = 0

    def render(self):
        self.rendered += 1
        return []

    def render_then(self, use, background=True, nice=0):
        use(self.render(), [])


@pytest.fixture
def backend(tmp_path, monkeypatch):
    """Register the scripted backend as ``fake_loop``; return its world and a holder
    whose ``episode`` the next ``open_episode`` yields (and whose ``opened`` logs the
    arguments)."""
    folder = tmp_path / "loopcase"
    folder.mkdir()
    (folder / "case.toml").write_text(MANIFEST)
    state = types.SimpleNamespace(episode=ScriptedEpisode(), opened=[])
    module = types.ModuleType("creative_test_loop_backend")

    @contextmanager
    def open_episode(world, variant, location, tool, seed=0, gui=False, images_dir=None,
                     pose_target=None, *, robot=True, record=None):
        state.opened.append((variant, location, tool, seed, gui, images_dir, pose_target,
                             robot, record))
        yield state.episode
        state.episode.log.append(("closed",))

    module.open_episode = open_episode
    monkeypatch.setitem(sys.modules, "creative_test_loop_backend", module)
    monkeypatch.setitem(BACKENDS, "fake_loop", BackendEntry("creative_test_loop_backend"))
    manifest = read_manifest(folder)
    state.world = types.SimpleNamespace(manifest=manifest)
    return state


def test_the_scripted_episode_is_all_a_backend_s_episode_must_be():
    assert signature_mismatches(Episode, ScriptedEpisode) == []


def test_a_trial_runs_the_skills_in_order_and_observes_before_the_tool_action(backend):
    seen = []
    clip = Clip()
    ep = backend.episode
    result = run_trial(backend.world, "stick1", "hard", 2, pose=(0.07,), seed=9,
                       images_dir="shots", pose_target=len, record=clip,
                       verdict=lambda *a: seen.append((a, list(ep.log))))
    assert backend.opened == [("hard", 2, "stick1", 9, False, "shots", len, True, clip)]
    assert ep.log == [("run_skill", "pick_up", None, {}), ("run_skill", "place", (0.07,), {}),
                      ("observe",), ("run_skill", "push", None, {}), ("verdict",),
                      ("observe",), ("measured_load",), ("closed",)]
    assert (result.outcome, result.reason) == ("success", "goal reached")
    assert result.facts_before == (("seen", 3),)          # just before the push
    assert (result.case, result.object, result.variant, result.location, result.pose,
            result.seed) == ("loopcase", "stick1", "hard", 2, (0.07,), 9)
    assert (result.steps, result.sim_time_s, result.render_time_s) == (30, 0.3, 0.25)
    assert (result.max_tool_force_n, result.tool_load) == (
        12.5, {"max_force_n": 12.5, "bodies": ["box1"]})
    assert result.verdict["asked"] is True and result.verdict["value"] == 0.7
    assert "stop" not in result.verdict
    assert result.perceived_final is None                 # no camera frame taken
    assert result.true_final == ep.truth() and result.wall_time_s >= 0
    # The callback comes once, with the result taken, inside the episode; it renders.
    assert seen == [(("success", "goal reached", result.verdict), ep.log[:-1])]
    assert clip.rendered == 0


def test_without_a_verdict_callback_the_recorder_is_rendered_and_the_pose_defaults(backend):
    clip = Clip()
    backend.episode = ScriptedEpisode(holds=False)
    result = run_trial(backend.world, "stick1", "easy", 1, record=clip)
    assert (result.outcome, result.reason, result.pose) == ("failure", "goal not reached",
                                                           (0.05,))
    assert clip.rendered == 1


def test_a_motion_blocked_before_the_tool_action_is_observed_where_it_stopped(backend):
    backend.episode = ScriptedEpisode(
        ends={"place": SkillOutcome("blocked", "place: gripper lagged", GUARD)})
    result = run_trial(backend.world, "stick1", "easy", 1)
    log = backend.episode.log
    assert [c[1] for c in log if c[0] == "run_skill"] == ["pick_up", "place"]
    assert (result.outcome, result.reason) == ("blocked", "place: gripper lagged")
    assert result.facts_before == (("seen", 4),)          # observed after the stop
    assert (result.max_tool_force_n, result.tool_load) == (0.0, None)
    assert ("measured_load",) not in log                  # the tool never acted
    assert result.verdict["asked"] is False
    assert result.verdict["stop"]["quantity"] == "gripper lag"


def test_a_tool_stopped_while_acting_is_judged_by_the_goal(backend):
    backend.episode = ScriptedEpisode(ends={"push": SkillOutcome("blocked", "push: slipped")})
    result = run_trial(backend.world, "stick1", "easy", 1)
    assert (result.outcome, result.reason) == ("success", "push: slipped")
    assert result.facts_before == (("seen", 3),)
    assert result.verdict["asked"] is True and result.max_tool_force_n == 12.5


def test_an_unreachable_skill_with_nothing_to_measure_is_its_status(backend):
    backend.episode = ScriptedEpisode(
        ends={"pick_up": SkillOutcome("unreachable", "pick_up: no posture")},
        measure_error=ValueError("nothing finite"))
    result = run_trial(backend.world, "stick1", "easy", 1)
    assert (result.outcome, result.reason) == ("unreachable", "pick_up: no posture")
    assert result.verdict is None and result.facts_before == ()
    # Asked (every skill ran), a measure that fails is an error, not an outcome.
    backend.episode = ScriptedEpisode(measure_error=ArithmeticError("nan"))
    with pytest.raises(ArithmeticError):
        run_trial(backend.world, "stick1", "easy", 1)


def test_an_oracle_that_meets_a_non_finite_state_makes_the_trial_invalid(backend):
    """A body only the oracle reads (nobody tracks it, no motion watches it) thrown to
    NaN: the oracle raises NonFiniteState and the trial is invalid, not a crash of the
    run or a failure the learner would label."""
    backend.episode = ScriptedEpisode(
        measure_error=NonFiniteState("non-finite pose of cubes3: (nan, 0.1, 0.015)"))
    result = run_trial(backend.world, "stick1", "easy", 1)
    assert (result.outcome, result.reason) == (
        "invalid", "non-finite pose of cubes3: (nan, 0.1, 0.015)")
    assert result.verdict is None


def test_a_non_finite_true_pose_makes_the_trial_invalid(backend):
    backend.episode = ScriptedEpisode(truth={"box1": (math.nan, 0.0, 0.8, 0.0)})
    result = run_trial(backend.world, "stick1", "easy", 1)
    assert (result.outcome, result.reason) == ("invalid", "non-finite pose of box1")


def test_by_hand_skips_the_carrying_and_timings_has_each_skill(backend):
    ep = ScriptedEpisode()
    timings: dict = {}
    played = play_trial(ep, backend.world.manifest, (0.02,), observe=False, by_hand=True,
                        timings=timings)
    assert [c[1:] for c in ep.log if c[0] == "run_skill"] == [
        ("place", (0.02,), {"by_hand": True}), ("push", None, {})]
    assert ("observe",) not in ep.log and played.facts_before == () and played.final is None
    assert set(timings) == {"place_s", "push_s"} and played.acted
    assert played.outcome == "success"


@pytest.mark.parametrize("status, acted, reached, want", [
    (SkillOutcome("ok"), True, True, ("success", "goal reached")),
    (SkillOutcome("ok"), True, False, ("failure", "goal not reached")),
    (SkillOutcome("blocked", "b"), False, True, ("blocked", "b")),
    (SkillOutcome("blocked", "b"), True, False, ("failure", "b")),
    (SkillOutcome("invalid", "nan"), True, True, ("invalid", "nan")),
    # Out of steps or time, wherever it ran out: blocked unless the tool acted and the
    # goal holds when the time is up (never a failure: the plan did not fit the budget).
    (SkillOutcome("out_of_time", "place: steps ran out"), False, False,
     ("blocked", "place: steps ran out")),
    (SkillOutcome("out_of_time", "place: steps ran out"), False, True,
     ("blocked", "place: steps ran out")),
    (SkillOutcome("out_of_time", "push: steps ran out"), True, False,
     ("blocked", "push: steps ran out")),
    (SkillOutcome("out_of_time", "push: steps ran out"), True, True,
     ("success", "push: steps ran out")),
])
def test_each_ending_has_one_outcome_for_every_backend(status, acted, reached, want):
    got = trial_outcome(status, acted, reached)
    assert got == want and got[0] in TRIAL_OUTCOMES


OUT_OF_STEPS = Verdict("control steps needed at least", 56, 50, "steps", "<=", False,
                       "[episode] max_steps")


@pytest.mark.parametrize("skill", ["place", "push"])
def test_a_run_out_of_steps_is_blocked_wherever_it_ran_out(backend, skill):
    # Before the tool action (place) or while the tool acts (push): one outcome, the
    # backend's reason, the budget's measure first on every short line, and the robot's
    # view where the motion stopped (what a planned example is labelled with).
    reason = f"{skill}: the episode's 50 control steps ran out"
    backend.episode = ScriptedEpisode(
        ends={skill: SkillOutcome("out_of_time", reason, OUT_OF_STEPS)}, holds=False)
    result = run_trial(backend.world, "stick1", "easy", 1)
    log = backend.episode.log
    assert (result.outcome, result.reason) == ("blocked", reason)
    seen = max(i for i, call in enumerate(log) if call == ("observe",))
    assert seen > max(i for i, call in enumerate(log) if call[0] == "run_skill")
    assert result.facts_before == (("seen", seen + 1),)  # seen where it stopped
    assert result.verdict["stop"]["quantity"] == "control steps needed at least"
    assert result.verdict["asked"] is (skill == "push")
    assert verdict_lines(result.verdict)[0] == (
        "stopped: control steps needed at least 56 steps, needs <= 50 steps")


def test_a_goal_reached_when_the_steps_ran_out_is_a_success(backend):
    backend.episode = ScriptedEpisode(
        ends={"push": SkillOutcome("out_of_time", "push: ran out", OUT_OF_STEPS)})
    result = run_trial(backend.world, "stick1", "easy", 1)
    assert (result.outcome, result.reason) == ("success", "push: ran out")
    assert result.verdict["asked"] is True and result.verdict["holds"] is True


def test_a_verdict_line_never_reads_as_a_pass_that_failed():
    # The main measure meets its threshold but the oracle judged otherwise (ManiSkill's
    # evaluate() also needs the robot static): the short lines say what judged it.
    placed = Verdict("cube1 distance", 0.0284, 0.05, "m", "<", False, "evaluate()")
    assert placed.to_dict()["note"] == "judged not met by evaluate()"
    assert verdict_lines(placed.to_dict()) == [
        "cube1 distance 0.0284 m, needs < 0.0500 m", "judged not met by evaluate()"]
    # a note of its own says why instead; a judgement that agrees needs none
    said = Verdict("cube1 distance", 0.0284, 0.05, "m", "<", False, "evaluate()",
                   note="robot moving")
    assert said.to_dict()["note"] == "robot moving"
    for holds, value in ((True, 0.0284), (False, 0.07)):
        agreed = Verdict("cube1 distance", value, 0.05, "m", "<", holds, "evaluate()")
        assert agreed.to_dict()["note"] == "" and len(verdict_lines(agreed.to_dict())) == 1
    # judged met though the measure misses its threshold
    assert Verdict("box1 x", 0.5, 0.6, "m", ">", True, "limit").short_note() == (
        "judged met by limit")


# ------------------------------------------------------------ the demonstration is a trial
def test_the_protocol_has_one_oracle():
    members = {n for n in vars(Episode) if not n.startswith("_")}
    assert "verdict" in members and "goal_reached" not in members


def test_the_demonstration_is_judged_by_the_trial_s_rule(backend):
    """The demonstration asks the episode's one oracle (``verdict``) and judges by
    ``trial_outcome``: a push stopped while the tool acted that leaves the goal
    reached is a success, as in any trial; the goal not reached is refused."""
    from creative_py.learning.tool_use import DemonstrationFailed, run_demonstration

    backend.world.variation = ""
    backend.episode = ScriptedEpisode(ends={"push": SkillOutcome("blocked", "push: slipped")})
    demo = run_demonstration(backend.world, pose_target=len)
    assert demo.goal_reached and [s.outcome for s in demo.steps] == ["ok", "ok", "blocked"]
    assert ("verdict",) in backend.episode.log
    backend.episode = ScriptedEpisode(holds=False)
    with pytest.raises(DemonstrationFailed, match="did not reach the goal in the physics"):
        run_demonstration(backend.world, pose_target=len)
    backend.episode = ScriptedEpisode(
        ends={"place": SkillOutcome("blocked", "place: gripper lagged", GUARD)})
    with pytest.raises(DemonstrationFailed, match="the trainer's skill place ended blocked "
                                                  "in the physics: place: gripper lagged"):
        run_demonstration(backend.world, pose_target=len)


def test_the_demonstration_is_played_by_the_trial_s_loop(backend):
    """The demonstration runs the trial's skill loop (``play_trial``): its steps in
    order with the robot observing before and after each, the oracle asked once, and a
    non-finite true pose making it ``invalid``, refused with the reason, as any trial."""
    from creative_py.learning.tool_use import DemonstrationFailed, run_demonstration

    backend.world.variation = ""
    backend.episode = ScriptedEpisode()
    demo = run_demonstration(backend.world, pose_target=len)
    assert [e[0] for e in backend.episode.log] == [
        "observe", "run_skill", "observe", "run_skill", "observe", "run_skill", "observe",
        "verdict", "closed"]
    assert [s.facts_before for s in demo.steps[1:]] == [s.facts_after for s in demo.steps[:-1]]
    backend.episode = ScriptedEpisode(truth={"box1": (float("nan"), 0.0, 0.8, 0.0)})
    with pytest.raises(DemonstrationFailed, match="did not reach the goal in the physics: "
                                                  "non-finite pose of box1"):
        run_demonstration(backend.world, pose_target=len)


STRUCK = Verdict("robot strike force", 463.1, 0.0, "N", "<=", False,
                 "robot links strike none of box2",
                 detail="the robot's hand_link struck box2 at (0.850, -0.250, -0.024) m",
                 measures={"struck": [{"link": "hand_link", "body": "box2", "force_n": 463.1,
                                       "point": [0.85, -0.25, -0.024]}],
                           "touching": ["hand_link against box2"]})


@pytest.mark.parametrize("status, reason, acted, reached, outcome", [
    # The robot itself struck a scene body: blocked, before or during the tool action,
    # unless the tool acted and the goal holds (the physics judges the state).
    ("ok", "place: struck", False, False, "blocked"),
    ("ok", "place: struck", True, False, "blocked"),
    ("ok", "place: struck", True, True, "success"),
    ("ok", "place: struck", False, True, "blocked"),
    # A guard that stopped the tool while acting: not a failure once the robot struck.
    ("blocked", "push: lagged", True, False, "blocked"),
    ("out_of_time", "push: ran out", True, False, "blocked"),
    ("unreachable", "push: no posture", True, False, "blocked"),
    # A physics blow-up stays what it is.
    ("invalid", "push: NaN", True, False, "invalid"),
])
def test_a_robot_that_struck_the_scene_is_blocked_unless_the_goal_holds(status, reason, acted,
                                                                       reached, outcome):
    # Whatever the outcome, the reason is the skill's (the strike's words or the guard's).
    got = trial_outcome(SkillOutcome(status, reason, struck=STRUCK), acted, reached)
    assert got == (outcome, reason) and outcome in TRIAL_OUTCOMES


def test_a_strike_before_the_tool_action_goes_on_and_the_first_strike_says_why(backend):
    # The hand strikes while placing; the skills go on (the goal may still be
    # reached); the goal not reached, the trial is blocked with the place's strike,
    # not the push's, and the record keeps which link struck which body.
    later = Verdict("robot strike force", 5.0, 0.0, "N", "<=", False)
    backend.episode = ScriptedEpisode(
        ends={"place": SkillOutcome("ok", "place: the robot's hand_link struck box2",
                                    struck=STRUCK),
              "push": SkillOutcome("ok", "push: struck again", struck=later)}, holds=False)
    result = run_trial(backend.world, "stick1", "easy", 1)
    assert [c[1] for c in backend.episode.log if c[0] == "run_skill"] == [
        "pick_up", "place", "push"]
    assert (result.outcome, result.reason) == (
        "blocked", "place: the robot's hand_link struck box2")
    assert result.verdict["struck"]["measures"]["touching"] == ["hand_link against box2"]
    assert "stop" not in result.verdict
    assert "struck: hand_link against box2 with 463 N" \
        in verdict_lines(result.verdict)
    assert "struck: robot strike force 463.1 N" in verdict_words(result.verdict)
    # The same trial whose goal holds is a success, still saying what struck.
    backend.episode = ScriptedEpisode(
        ends={"place": SkillOutcome("ok", "place: struck", struck=STRUCK)})
    result = run_trial(backend.world, "stick1", "easy", 1)
    assert (result.outcome, result.reason) == ("success", "place: struck")
