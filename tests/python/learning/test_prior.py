"""Transfer (``--prior``): the option, its records, its one-line errors and one real run.

The real run takes ~6 s (not marked slow). The Prolog side (what the ontology maps, the version space's start) is tested in
tests/prolog/transfer.plt.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from creative_py.cli import app
from creative_py.learning.options import RunOptions
from creative_py.records.summary import PriorDrop, RunSummary, UsePhase, UsePrior

runner = CliRunner()

WEDGE_MODEL = """\
learned_hypothesis(wedge, hs, (tool_pose(A, B, _) :- block(A), near(A, B))).
learned_hypothesis(wedge, hg, (tool_pose(A, B, _) :- near(A, B))).
"""

HOOK_MODEL = """\
learned_hypothesis(hook, hs, (tool_pose(A, B, C) :- hook(A), hook_down(A), behind(A, B), in_tube(A, C))).
learned_hypothesis(hook, hg, (tool_pose(A, B, _) :- hook_down(A), behind(A, B), hook(A))).
"""


def test_the_option_takes_a_path_or_none():
    assert RunOptions().prior is None
    assert RunOptions(prior="runs/hook-x").prior == "runs/hook-x"
    for bad in ("", 3):
        with pytest.raises(ValueError, match="option prior"):
            RunOptions(prior=bad)


def test_use_prior_is_one_typed_field_and_old_summaries_load():
    use = UsePhase(trials=2, prior=UsePrior(source="m.pl", case="hook", taken=["hook(t)"],
                                            dropped=[PriorDrop(literal="hook(t)", trial=1)]))
    s = RunSummary(case="rake", use=use)
    back = RunSummary.from_dict(json.loads(s.to_json()))
    assert back.use.prior.case == "hook"
    assert back.use.prior.dropped[0].trial == 1
    old = RunSummary.from_dict({"case": "hook", "use": {"trials": 6, "stop": "certified"}})
    assert old.use.prior is None
    with pytest.raises(ValueError, match="use.prior.taken"):
        RunSummary.from_dict({"use": {"prior": {"taken": "hook(t)"}}})


def _one_line(res, start):
    assert res.exit_code == 2, res.output
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(start), res.output
    assert "Traceback" not in res.output


def test_a_missing_prior_is_one_line_and_exit_2(tmp_path):
    res = runner.invoke(app, ["run", "hook", "--phase", "use", "--video", "none",
                              "--out", str(tmp_path / "runs"),
                              "--prior", str(tmp_path / "nothing")])
    _one_line(res, f"error: --prior {tmp_path / 'nothing'}: no such run folder")
    assert not (tmp_path / "runs").exists() or not any((tmp_path / "runs").iterdir())


def test_a_folder_without_a_model_and_a_file_that_is_no_model(tmp_path):
    res = runner.invoke(app, ["run", "hook", "--phase", "use", "--out", str(tmp_path),
                              "--prior", str(tmp_path)])
    _one_line(res, f"error: --prior {tmp_path}: the run folder has no model.pl")
    bad = tmp_path / "model.pl"
    bad.write_text("hello(world).\n")
    res = runner.invoke(app, ["run", "hook", "--phase", "use", "--out", str(tmp_path),
                              "--prior", str(bad)])
    _one_line(res, f"error: --prior {bad}: not a learned model file")


def test_a_prior_of_an_unrelated_case_is_one_line_and_exit_2(tmp_path):
    model = tmp_path / "model.pl"
    model.write_text(WEDGE_MODEL)
    res = runner.invoke(app, ["run", "hook", "--phase", "use", "--out", str(tmp_path),
                              "--prior", str(tmp_path)])
    _one_line(res, f"error: --prior {tmp_path}: the ontology maps no learned literal of "
                   "case 'wedge' to case 'hook'")


def test_a_real_rake_run_with_a_hook_prior(tmp_path):
    """rake after a hook model: h_g starts with the literals the ontology maps (the
    hook_like kind, behind/centred_on/hook_down), which no trial tests, and they are
    marked in model.pl and summary.json."""
    from creative_py.learning.run import run_case

    (tmp_path / "model.pl").write_text(HOOK_MODEL)
    folder = run_case("rake", tmp_path / "runs",
                      RunOptions(phase="use", video="none", eval_trials=1,
                                 prior=str(tmp_path / "model.pl")))
    summary = RunSummary.read(folder.path / "summary.json")
    prior = summary.use.prior
    assert prior.case == "hook"
    assert set(prior.taken) == {"hook_down(rake_a2)", "behind(rake_a2,box1)", "hook(rake_a2)"}
    assert summary.use.stop == "certified"
    tested = [t for line in (folder.path / "trials.jsonl").read_text().splitlines()
              for t in json.loads(line).get("tested") or []]
    assert tested and not any(t.startswith(("hook_down", "behind", "hook(")) for t in tested)
    assert "learned_hypothesis(rake, prior," in (folder.path / "model.pl").read_text()
    assert summary.eval.successes == 1


def test_run_json_records_the_prior_only_when_set():
    assert "prior" not in RunOptions().recorded()
    assert RunOptions(prior="m.pl").recorded()["prior"] == "m.pl"
