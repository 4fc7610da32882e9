"""The report of a run folder that is not whole: a run still going or killed, with torn
and corrupt lines in ``trials.jsonl`` and no ``summary.json``."""

from __future__ import annotations

import json
import subprocess
import sys

from creative_py.report.contents import read_run
from creative_py.report.page import render_html


def _trial(n, **extra):
    return {"trial": n, "phase": "use", "phase_trial": n, "variant": "standard",
            "location": 1, "tool": "t", "outcome": "failure", **extra}


def test_a_partial_run_gets_a_page_of_its_readable_trials_and_nothing_else(tmp_path):
    lines = [json.dumps(_trial(1, reason="a <b>bold</b> & odd reason")),
             '{"trial": 2, "phase": "use", garbage', json.dumps(_trial(3)),
             '{"trial": 4, "pha']
    (tmp_path / "trials.jsonl").write_text("\n".join(lines) + "\n")
    before = sorted(p.name for p in tmp_path.iterdir())
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "report", str(tmp_path),
                           "--html"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr.count("warning: ") == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(before + ["report.html"])
    page = (tmp_path / "report.html").read_text()
    assert page.count('<tr class="trial ') == 2
    assert "a &lt;b&gt;bold&lt;/b&gt; &amp; odd reason" in page and "<b>bold</b>" not in page
    assert "Interrupted after 2 trials (no summary.json" in page
    assert "line 2 is not a JSON object" in page
    assert "No trials.png in this run folder." in page


def test_clips_outside_the_folder_are_not_linked(tmp_path):
    (tmp_path / "trials.jsonl").write_text(json.dumps(_trial(1)) + "\n")
    (tmp_path / "summary.json").write_text(json.dumps({"videos": [
        {"file": "../elsewhere.mp4", "phase": "use", "trial": 1},
        {"file": "videos/missing.mp4", "phase": "use", "trial": 1}]}))
    run = read_run(tmp_path)
    assert [c.file for c in run.clips] == ["videos/missing.mp4"]
    assert not run.clips[0].exists
    assert any("outside the run folder" in w for w in run.warnings)
    page = render_html(run)
    assert '="../elsewhere.mp4"' not in page and '="..%2Felsewhere.mp4"' not in page
    assert "missing: videos/missing.mp4" in page and "<video" not in page
