"""The trial record owns the line of ``trials.jsonl``: written and read back byte for
byte, checked field by field, and a new field reaches the JSON and the reports
without a change anywhere else."""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from typing import Union

import pytest
from rich.console import Console

from creative_py.records import RunFolder, TrialRecord, read_records, read_trials
from creative_py.records.trial import trial_columns
from creative_py.report.contents import RunContents
from creative_py.report.page import render_html
from creative_py.report.table import print_report

# Two lines of a hook run (seed 0, --strategy paper), shortened: a tool-use trial (with
# the version space's count) and an evaluation trial (without it).
USE_LINE = (
    '{"trial": 2, "phase": "use", "phase_trial": 2, "variant": "standard", "location": 1, '
    '"tool": "hook_a2", "kind": "experiment", "tested": ["hook_down(hook_a2)"], '
    '"violated": ["hook_down(hook_a2)"], "pose": {"dx": 0.0375, "dy": 0.0, "roll": 0.9604}, '
    '"outcome": "failure", "reason": "goal not reached", '
    '"hs": "tool_pose(_G3,_G4,_G5) :- hook(_G3)", '
    '"hg": "tool_pose(_G3,_G4,_G5) :- handle_length(_G3,medium)", "wall_time_s": 1.473, '
    '"sim_time_s": 8.267, "decision_time_s": 0.0198, "vs_count": 7168, '
    '"vs_count_exact": true, "facts": [["pose", "cube1", 1.131971275328603, '
    '-0.26002960492287597, -0.0796848854355147, 0.32288591161895086], ["size", "cube1", '
    '0.03040792442657536, 0.023583940648564172, 0.03]], "max_tool_force_n": 0.0, '
    '"tool_load": {"max_force_n": 0.0, "point": null, "force": null, "grasp_point": null, '
    '"contacts": 0, "bodies": [], "step": 0, "steps": 476}}')
EVAL_LINE = (
    '{"trial": 12, "phase": "eval", "phase_trial": 3, "variant": "standard", "location": 3, '
    '"tool": "hook_a2", "kind": "exploit", "tested": [], "violated": [], '
    '"pose": {"dx": 0.0391, "dy": 0.0, "roll": 0.0}, "outcome": "success", '
    '"reason": "goal reached", "hs": "h", "hg": "g", "wall_time_s": 1.55, '
    '"sim_time_s": 7.833, "decision_time_s": 0.0023, "facts": [], "max_tool_force_n": 2.46174, '
    '"tool_load": {"max_force_n": 2.46174, "point": [0.338733, -0.030723, -0.002053], '
    '"force": [2.46126, -0.583746, -0.184305], "grasp_point": [0.04, 0.0, 0.0], '
    '"contacts": 4, "bodies": ["cube1"], "step": 1433, "steps": 476}}')


@pytest.mark.parametrize("line", [USE_LINE, EVAL_LINE])
def test_a_line_of_a_run_is_read_and_written_back_byte_for_byte(line):
    record = TrialRecord.from_json(line)
    assert record.to_json() == line
    assert isinstance(record.location, int) and isinstance(record.pose["roll"], float)


def test_an_unlabelled_trial_has_no_count_keys():
    record = TrialRecord.from_json(EVAL_LINE)
    assert record.vs_count is None and "vs_count" not in record.to_dict()
    assert record.tool_load["bodies"] == ["cube1"]
    assert record.get("max_tool_force_n") == pytest.approx(2.46174)


def test_the_fields_are_typed_and_the_outcome_checked():
    record = TrialRecord.from_json(USE_LINE)
    assert record.facts[1] == ["size", "cube1", 0.03040792442657536, 0.023583940648564172,
                               0.03]
    assert record.vs_count_exact is True


@pytest.mark.parametrize("change, field_name", [
    ({"outcome": "won"}, "outcome"),
    ({"phase": "learn"}, "phase"),
    ({"location": "1"}, "location"),
    ({"location": True}, "location"),
    ({"trial": 2.5}, "trial"),
    ({"tested": "hook_down(hook_a2)"}, "tested"),
    ({"tested": [3]}, "tested[0]"),
    ({"pose": [0.0375, 0.0, 0.9604]}, "pose"),
    ({"facts": [["pose", "cube1"], "size"]}, "facts[1]"),
    ({"tool_load": [1, 2]}, "tool_load"),
    ({"vs_count_exact": "yes"}, "vs_count_exact"),
    ({"wall_time_s": "slow"}, "wall_time_s"),
])
def test_a_wrong_value_is_refused_naming_its_field(change, field_name):
    data = {**json.loads(USE_LINE), **change}
    with pytest.raises(ValueError, match=re.escape(f"field '{field_name}'")):
        TrialRecord.from_json(json.dumps(data))


def test_a_missing_key_and_a_non_object_are_refused():
    data = json.loads(USE_LINE)
    del data["tool"]
    with pytest.raises(ValueError, match="'tool'"):
        TrialRecord.from_dict(data)
    with pytest.raises(ValueError, match="JSON object"):
        TrialRecord.from_json("[1, 2]")
    with pytest.raises(ValueError, match="not a JSON object"):
        TrialRecord.from_json('{"trial": 1, "pha')


def test_a_record_built_in_code_is_checked_too():
    with pytest.raises(ValueError, match="'outcome'"):
        TrialRecord(trial=1, phase="use", variant="v", location=1, tool="t",
                    outcome="half")


def test_non_finite_times_are_written_as_text_and_read_back_as_numbers():
    record = TrialRecord(trial=1, phase="use", variant="v", location=1, tool="t",
                         outcome="success", wall_time_s=math.nan)
    assert record.to_dict()["wall_time_s"] == "nan"
    assert math.isnan(TrialRecord.from_json(record.to_json()).wall_time_s)


def test_keys_of_a_later_version_are_kept_after_the_known_ones():
    data = {**json.loads(EVAL_LINE), "grip_force_n": 12.5}
    record = TrialRecord.from_dict(data)
    assert record.extra == {"grip_force_n": 12.5}
    assert record.to_json() == json.dumps(data)


def test_the_run_folder_writes_records_and_reads_them_back(tmp_path):
    run = RunFolder.create(tmp_path, "hook", 0)
    for line in (USE_LINE, EVAL_LINE):
        run.append_trial(TrialRecord.from_json(line))
    with open(run.trials_path, "a") as fh:
        fh.write(json.dumps({**json.loads(EVAL_LINE), "outcome": "won"}) + "\n")
    assert run.trials_path.read_text().splitlines()[:2] == [USE_LINE, EVAL_LINE]
    warnings: list[str] = []
    records = read_records(run.path, warn=warnings.append)
    assert [r.trial for r in records] == [2, 12]
    assert len(warnings) == 1 and "line 3" in warnings[0] and "'outcome'" in warnings[0]
    assert read_trials(run.path) == [json.loads(USE_LINE), json.loads(EVAL_LINE)]


@dataclass(kw_only=True)
class _WithGrip(TrialRecord):
    """A trial record with one more field, as a later version might add it: one line
    (with its report column), nothing else."""

    grip_force_n: Union[float, None] = field(default=None, metadata={"column": "grip"})


def test_a_new_optional_field_round_trips_and_shows_in_the_reports(tmp_path):
    base = json.loads(EVAL_LINE)
    record = _WithGrip.from_dict({**base, "grip_force_n": 12.5})
    assert record.grip_force_n == 12.5 and record.extra == {}
    line = record.to_json()
    assert json.loads(line) == {**base, "grip_force_n": 12.5}
    assert _WithGrip.from_json(line) == record
    # Left out while None: the lines of older runs read as they were.
    assert _WithGrip.from_json(EVAL_LINE).to_json() == EVAL_LINE
    with pytest.raises(ValueError, match="'grip_force_n'"):
        _WithGrip.from_dict({**base, "grip_force_n": "strong"})
    # The reports: the column follows the record's own ones.
    headers = [h for h, _ in trial_columns(_WithGrip)]
    assert headers == [h for h, _ in trial_columns()] + ["grip"]
    run = RunContents(path=tmp_path, trials=[record], summary={}, model_text=None,
                      plot=None, clips=[], tools=[], pddl_files=[], warnings=[])
    console = Console(record=True, width=400)
    print_report(run, console, width=400)
    table = console.export_text()
    assert "grip" in table and "12.5" in table
    narrow = Console(record=True, width=60)
    print_report(run, narrow, width=60)
    blocks = narrow.export_text()
    assert "grip" in blocks and "12.5" in blocks
    page = render_html(run)
    assert "<th>grip</th>" in page and "12.5" in page


def test_the_reason_cell_and_the_short_lines_carry_the_measured_verdict():
    from creative_py.records.trial import reason_text, verdict_lines
    from creative_py.simulator.types import Verdict

    stop = Verdict("gripper lag", 0.032, 0.03, "m", "<=", False,
                   threshold_name="max_tracking_error",
                   measures={"touching": ["robot against base1"]},
                   detail="touching: robot against base1")
    oracle = Verdict("box1 centre x", 1.07, 0.85, "m", "<", False,
                     threshold_name="shelf1.mouth_x", note="moved 0.0 cm")
    verdict = {**oracle.to_dict(), "asked": False, "stop": stop.to_dict()}
    rec = TrialRecord(trial=1, phase="use", variant="standard", location=1, tool="rake_a1",
                      outcome="blocked", reason="position_tool: gripper lagged",
                      verdict=verdict)
    assert TrialRecord.from_json(rec.to_json()) == rec
    # Words with one unit a quantity (issue 32: the page showed max_tracking_error,
    # tube1.mouth_x, and m and cm in one cell).
    assert reason_text(rec) == (
        "position_tool: gripper lagged -- stopped: gripper lag 32.0 mm (needs <= 30.0 mm; "
        "the limit: max tracking error); touching: robot against base1 | box1 centre x "
        "1070.0 mm (needs < 850.0 mm; the limit: shelf1's mouth x)")
    assert verdict_lines(rec.verdict) == [
        "stopped: gripper lag 0.0320 m, needs <= 0.0300 m", "touching robot against base1",
        "box1 centre x 1.0700 m, needs < 0.8500 m", "moved 0.0 cm"]
    # A record written before verdicts: the reason alone.
    old = TrialRecord(trial=2, phase="use", variant="standard", location=1, tool="t",
                      outcome="failure", reason="goal not reached")
    assert reason_text(old) == "goal not reached" and verdict_lines(old.verdict) == []
    assert "verdict" not in old.to_dict()


def test_a_strike_says_how_many_link_body_contacts_besides_the_strongest():
    # One writer of these words: the strike's line here and the pybullet episode's
    # detail of a strike (its reason) both take them from more_strikes.
    from creative_py.records.trial import more_strikes, struck_line

    strike = {"link": "hand", "body": "tube1", "force_n": 331.2, "point": [0.85, -0.24, 0.0]}
    assert [more_strikes([strike] * n) for n in (0, 1, 2, 4)] == [
        "", "", " (1 more link-body contact)", " (3 more link-body contacts)"]
    assert struck_line({"measures": {"struck": [strike] * 4}}) == (
        "struck: hand against tube1 with 331 N (3 more link-body contacts)")
    assert struck_line({"measures": {"struck": [strike]}}) == (
        "struck: hand against tube1 with 331 N")


def test_lengths_and_limits_read_as_words_with_one_unit():
    from creative_py.records.trial import lengths_in_mm, limit_words, measure_words

    assert lengths_in_mm("gripper lagged its target by 3.0 cm at (0.978, -0.250, -0.052) m: "
                         "24.9 cm short; moved 1.1 cm; 0.8500 m; 2 mm; 3 min") == (
        "gripper lagged its target by 30 mm at (978, -250, -52) mm: 249 mm short; moved "
        "11 mm; 850.0 mm; 2 mm; 3 min")
    assert [limit_words(n) for n in ("tube1.mouth_x - 0.05", "grasp_slip_max_rad",
                                     "max_tracking_error", "", None)] == [
        "tube1's mouth x - 0.05", "grasp slip max", "max tracking error", "", ""]
    door = {"quantity": "door1 angle", "value": 12.46, "threshold": 20.0, "unit": "deg",
            "relation": ">=", "threshold_name": "door1.min_open_deg",
            "text": "door1 angle 12.5 deg (needs >= 20 deg, door1.min_open_deg); closed "
                    "0.3 deg after touching the tool (needs < 2 deg)"}
    assert measure_words(door) == ("door1 angle 12.46 deg (needs >= 20 deg; the limit: "
                                   "door1's min open); closed 0.3 deg after touching the "
                                   "tool (needs < 2 deg)")
    slip = {"quantity": "grasp slip", "value": 0.2, "threshold": 0.1, "unit": "rad",
            "relation": "<=", "threshold_name": "grasp_slip_max_rad",
            "text": "grasp slip 0.2000 rad (needs <= 0.1000 rad, grasp_slip_max_rad)"}
    assert measure_words(slip) == "grasp slip 11.5 deg (needs <= 5.7 deg; the limit: grasp slip max)"
    # An older record without the numbers: its text, lengths in mm.
    assert measure_words({"text": "moved 1.1 cm"}) == "moved 11 mm"


# -------------------------------------------------- what every field of the record must do
# A new field (one typed line of records/trial.py) is checked by these; no line changes.
_FIELDS = [f for f in __import__("dataclasses").fields(TrialRecord) if f.name != "extra"]


def _wrong_value(f) -> object:
    """A JSON value the field's type does not admit (a dict, or text for a dict field)."""
    text = str(f.type)
    return "not a mapping" if text.startswith(("dict", "Union[dict")) else {"not": 1}


@pytest.mark.parametrize("f", _FIELDS, ids=lambda f: f.name)
def test_every_field_is_checked_and_round_trips(f):
    """The line of a field's own value reads back equal and writes back the same; a
    value of the wrong type is refused naming the field."""
    base = json.loads(EVAL_LINE)
    record = TrialRecord.from_dict(base)
    value = getattr(record, f.name)
    assert TrialRecord.from_json(record.to_json()) == record
    if value is not None:
        assert json.loads(record.to_json())[f.name] == base[f.name]
    with pytest.raises(ValueError, match=f"field '{f.name}'"):
        TrialRecord.from_dict({**base, f.name: _wrong_value(f)})
    if f.metadata.get("column"):
        assert f.metadata["column"] in [h for h, _ in trial_columns()]


def test_a_key_json_cannot_keep_is_refused_before_it_is_written():
    """``pose={0: 0.03}`` was written as ``{"0": 0.03}`` and read back as another record;
    the keys are checked as the values are (as the trial record's first checker did)."""
    with pytest.raises(ValueError, match=re.escape("field 'pose': key 0 is not of type str")):
        TrialRecord(trial=1, phase="use", variant="v", location=1, tool="t",
                    outcome="success", pose={0: 0.03})
    record = TrialRecord(trial=1, phase="use", variant="v", location=1, tool="t",
                         outcome="success", pose={"dx": 0.03})
    assert TrialRecord.from_json(record.to_json()) == record
