"""The run report, read by its real consumers: a browser for report.html, a terminal for
the table.

One short real run (two tool-use trials, then tool creation with no evaluation trial)
gives the folder. Its ``report.html`` is written through the command line and opened in
headless Chromium (Debian's ``chromium``): the DOM it builds must show the plot (a PNG
that exists), one table row per recorded trial with its reason, the created tool's
render and dimensions, and a ``<video controls>`` per clip whose MP4 exists and plays
(Chromium loads its first frame, imageio decodes it); its screenshot must not be blank. The terminal report is run with an
80-column ``COLUMNS`` and must show the longest reason in full.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlparse

import imageio.v2 as imageio
import numpy as np
import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case
from creative_py.records.trial import (TrialRecord, lengths_in_mm, measure_words,
                                       reason_text)
from creative_py.report.contents import read_run, readable_term
from creative_py.report.page import render_html

pytestmark = pytest.mark.sim

CHROMIUM = shutil.which("chromium")
needs_chromium = pytest.mark.skipif(
    CHROMIUM is None, reason="chromium is not installed (Debian's package chromium; "
    "make setup installs it)")


@pytest.fixture(scope="module")
def real_run(tmp_path_factory):
    """A real short run: the demonstration, two tool-use trials, tool creation."""
    out = tmp_path_factory.mktemp("runs")
    folder = run_case("rake", out, RunOptions(seed=0, phase="create", max_trials=2,
                                              eval_trials=0, create_eval_trials=0))
    return folder.path


def _creative(*args: str, columns: int = 80) -> subprocess.CompletedProcess:
    env = {**os.environ, "COLUMNS": str(columns)}
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", *args], env=env,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return proc


def _digests(folder: Path) -> dict[str, str]:
    return {p.relative_to(folder).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def _trials(folder: Path) -> list[dict]:
    return [json.loads(line) for line in (folder / "trials.jsonl").read_text().splitlines()
            if line.strip()]


class Dom(HTMLParser):
    """The elements of a page (tag and attributes, in order), and the cell texts of each
    trial row of its table."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.elements: list[tuple[str, dict[str, str]]] = []
        self.rows: list[list[str]] = []
        self.text: list[str] = []
        self._cell: list[str] | None = None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        attributes = {k: v or "" for k, v in attrs}
        self.elements.append((tag, attributes))
        if tag == "tr" and "trial" in attributes.get("class", "").split():
            self.rows.append([])
        elif tag == "td" and self._in_trial_row():
            self._cell = []

    def handle_endtag(self, tag):
        if tag == "td" and self._cell is not None:
            self.rows[-1].append("".join(self._cell).strip())
            self._cell = None

    def handle_data(self, data):
        self.text.append(data)
        if self._cell is not None:
            self._cell.append(data)

    def _in_trial_row(self) -> bool:
        for tag, attributes in reversed(self.elements[:-1]):
            if tag == "tr":
                return "trial" in attributes.get("class", "").split()
        return False

    def sources(self, tag: str) -> list[str]:
        return [a["src"] for t, a in self.elements if t == tag and "src" in a]


def _open_in_chromium(page: Path, tmp: Path) -> tuple[Dom, np.ndarray]:
    """Return the DOM Chromium builds from ``page`` and its 1280 x 2000 screenshot (one
    Chromium: the DOM on stdout, the screenshot in a file)."""
    shot = tmp / "screenshot.png"
    proc = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                           "--hide-scrollbars", f"--user-data-dir={tmp / 'chromium-profile'}",
                           "--dump-dom", f"--screenshot={shot}", "--window-size=1280,2000",
                           page.resolve().as_uri()],
                          capture_output=True, text=True, timeout=120, cwd=tmp)
    assert proc.returncode == 0 and "<html" in proc.stdout, proc.stderr[-2000:]
    assert shot.is_file(), proc.stderr[-2000:]
    return Dom(proc.stdout), imageio.imread(shot)


def _local_file(folder: Path, src: str) -> Path:
    """The file a relative link of the page names; fail on an absolute or outside one."""
    url = urlparse(src)
    assert not url.scheme and not url.netloc and not src.startswith("/"), src
    path = (folder / unquote(url.path)).resolve()
    assert path.is_relative_to(folder.resolve()), src
    return path


_PROBE = """<!DOCTYPE html><html><body>
{videos}
<script>
for (const v of document.querySelectorAll("video")) {{
  v.dataset.state = "waiting";
  v.addEventListener("loadeddata", () => {{
    v.dataset.state = "loaded " + v.videoWidth + "x" + v.videoHeight; }});
  v.addEventListener("error", () => {{
    v.dataset.state = "error " + (v.error && v.error.code); }});
}}
</script></body></html>
"""
"""A test page (not the report, which has no script) that says of each clip whether
Chromium's own decoder loads its first frame."""


def _assert_plays(mp4s: list[Path], tmp: Path) -> None:
    """Each clip plays: Chromium (one instance for them all) loads its first frame, and
    imageio's ffmpeg decodes frames of a picture, not all one colour."""
    probe = tmp / "probe.html"
    probe.write_text(_PROBE.format(videos="\n".join(
        f'<video muted preload="auto" src="{mp4.resolve().as_uri()}"></video>'
        for mp4 in mp4s)))
    proc = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                           f"--user-data-dir={tmp / 'chromium-profile'}",
                           "--virtual-time-budget=10000", "--dump-dom", probe.as_uri()],
                          capture_output=True, text=True, timeout=120, cwd=tmp)
    states = [a.get("data-state") for t, a in Dom(proc.stdout).elements if t == "video"]
    assert len(states) == len(mp4s), (states, proc.stderr[-1000:])
    for mp4, state in zip(mp4s, states):
        assert state and state.startswith("loaded "), (mp4, state, proc.stderr[-1000:])
        reader = imageio.get_reader(mp4)
        try:
            frames = [frame for _, frame in zip(range(5), reader)]
        finally:
            reader.close()
        assert frames, f"{mp4}: no frame decodes"
        assert frames[0].ndim == 3 and frames[0].shape[0] >= 64 and frames[0].shape[1] >= 64
        assert frames[0].std() > 1.0, f"{mp4}: the first frame is one colour"


def _assert_not_blank(screenshot: np.ndarray) -> None:
    """The screenshot is a drawn page: more than 20 % of it differs from the background
    colour (panels, pictures) and more than 0.5 % is dark (text)."""
    rgb = screenshot[..., :3].astype(int)
    drawn = (np.abs(rgb - rgb[0, 0]).max(axis=-1) > 6).mean()
    dark = (rgb.max(axis=-1) < 128).mean()
    assert drawn > 0.2 and dark > 0.005, f"{drawn:.1%} drawn, {dark:.2%} dark: blank page"


@pytest.fixture(scope="module")
def real_page(real_run, tmp_path_factory):
    """The real run's report.html written by ``creative report RUN --html``, opened in
    Chromium; and the run's files before and after."""
    if CHROMIUM is None:
        pytest.skip("chromium is not installed (Debian's package chromium; make setup "
                    "installs it)")
    before = _digests(real_run)
    (real_run / "report.html").unlink()  # the run wrote one; the command writes it anew
    proc = _creative("report", str(real_run), "--html")
    after = _digests(real_run)
    tmp = tmp_path_factory.mktemp("chromium")
    dom, screenshot = _open_in_chromium(real_run / "report.html", tmp)
    return proc, before, after, dom, screenshot


def test_the_run_writes_its_report_and_the_command_writes_only_report_html(real_run, real_page):
    proc, before, after, _, _ = real_page
    assert "report.html" in before                       # run_case wrote one at its end
    assert f"html: {real_run / 'report.html'}" in proc.stdout
    assert {k: v for k, v in after.items() if k != "report.html"} == \
        {k: v for k, v in before.items() if k != "report.html"}
    assert not any(name.startswith(".report.html") for name in after)   # no temp file


@needs_chromium
def test_the_page_shows_the_plot_every_trial_and_the_created_tool(real_run, real_page):
    _, _, _, dom, screenshot = real_page
    trials = _trials(real_run)
    # The plot: an <img> whose file is the run's trials.png.
    images = dom.sources("img")
    assert "trials.png" in images
    assert imageio.imread(_local_file(real_run, "trials.png")).shape[0] > 100
    # One table row per recorded trial, with its tool, outcome and whole reason, the
    # measured verdict folded under it.
    assert len(dom.rows) == len(trials) >= 3
    for row, t in zip(dom.rows, trials):
        assert row[0] == str(t["trial"]) and t["tool"] in row and t["outcome"] in row
        # the measured verdict folded under the reason (<details>: "measured")
        assert row[-1] == reason_text(TrialRecord.from_dict(t)).replace(" -- ", "measured", 1)
        # in words, every length in mm (issue 32)
        assert row[-1].startswith(lengths_in_mm(t["reason"]))
        assert measure_words(t["verdict"]) in row[-1]
    # The created tool: its render and its dimensions.
    summary = json.loads((real_run / "summary.json").read_text())
    created = summary["create"]["created_tools"]
    assert created
    text = " ".join(" ".join(dom.text).split())
    for tool in created:
        render = f"tools/{tool['name']}/{tool['name']}.png"
        assert render in images and _local_file(real_run, render).is_file()
        # in millimetres and degrees, as the print tables (issue 25: no metres beside
        # millimetres, no internal keys)
        for key, value in tool["dims"].items():
            name = key.removesuffix("_deg").replace("_", " ")
            if key.endswith("_deg"):
                assert f"{name} {value:g} deg" in text
            elif isinstance(value, (int, float)) and not isinstance(value, bool):
                assert f"{name} {value * 1000:.1f} mm" in text
            else:
                assert f"{name} {value}" in text
    # The learned hypotheses, literal by literal, and the plan's steps.
    for key in ("hs", "hg"):
        head, _, body = readable_term(summary["hypotheses"][key]).partition(" :- ")
        assert head in text and all(lit in text for lit in body.split(", "))
    steps = summary["plan"].removeprefix("plan([").removesuffix("])")
    assert steps.split(",", 1)[0] in text
    # Every link and source is relative and names a file of the run folder.
    for tag, attributes in dom.elements:
        for key in ("src", "href"):
            value = attributes.get(key)
            if value and not value.startswith("#"):
                assert _local_file(real_run, value).is_file(), (tag, value)
    _assert_not_blank(screenshot)


@needs_chromium
def test_the_runs_own_clips_are_on_the_page_and_play(real_run, real_page, tmp_path):
    """Every clip summary.json lists is a <video controls> whose MP4 decodes. Runs save
    clips since issue 9 item 5 (``summary.json``'s ``videos``)."""
    _, _, _, dom, _ = real_page
    summary = json.loads((real_run / "summary.json").read_text())
    videos = summary.get("videos")
    assert videos, "the run's summary.json lists no video clip (runs save clips: issue 9, " \
                   "item 5)"
    controls = [a for t, a in dom.elements if t == "video"]
    assert all("controls" in a for a in controls)
    sources = dom.sources("video")
    assert sorted(unquote(s) for s in sources) == sorted(v["file"] for v in videos)
    _assert_plays([_local_file(real_run, src) for src in sources], tmp_path)


@needs_chromium
def test_a_moved_folder_shows_its_clips_from_the_videos_folder(real_run, tmp_path):
    """A copy of the run (moved: every link relative), with summary.json listing no clip
    and one MP4 in videos/, made from the run's own camera frames: the page plays it."""
    moved = tmp_path / "moved" / real_run.name
    shutil.copytree(real_run, moved)
    summary = json.loads((moved / "summary.json").read_text())
    summary.pop("videos", None)
    (moved / "summary.json").write_text(json.dumps(summary))
    shutil.rmtree(moved / "videos", ignore_errors=True)
    page = render_html(read_run(moved))
    assert "<video" not in page and "This run saved no video clip." in page

    frames = [imageio.imread(p)[..., :3] for p in sorted(moved.glob("snapshots/*/*.png"))]
    frames = [f for f in frames if f.shape == frames[0].shape]
    assert len(frames) >= 3
    (moved / "videos").mkdir()
    imageio.mimwrite(moved / "videos" / "frames.mp4", frames * 3, fps=10)
    _creative("report", str(moved), "--html")
    dom, screenshot = _open_in_chromium(moved / "report.html", tmp_path)
    assert dom.sources("video") == ["videos/frames.mp4"]
    _assert_plays([_local_file(moved, "videos/frames.mp4")], tmp_path)
    assert "trials.png" in dom.sources("img")
    _assert_not_blank(screenshot)


_LAYOUT_PROBE = """<script>
(() => {
  const width = document.documentElement.clientWidth;
  const wide = [];
  for (const e of document.querySelectorAll("body *")) {
    const r = e.getBoundingClientRect();
    if (r.width > 0 && (r.right > width + 0.5 || r.left < -0.5))
      wide.push(e.tagName + "." + e.className + " " + Math.round(r.right));
  }
  const hidden = [];
  for (const v of document.querySelectorAll("video")) {
    const cap = v.closest("figure") && v.closest("figure").querySelector("figcaption");
    const rv = v.getBoundingClientRect(), rc = cap && cap.getBoundingClientRect();
    if (!rc || rc.height < 10 || rc.top < rv.bottom - 0.5 || rc.right > width + 0.5
        || getComputedStyle(cap).visibility !== "visible" || cap.innerText.trim() === "")
      hidden.push(v.getAttribute("src"));
  }
  const b = document.body.dataset;
  b.viewport = width;
  b.scrollWidth = document.documentElement.scrollWidth;
  b.wide = JSON.stringify(wide.slice(0, 20));
  b.hidden = JSON.stringify(hidden);
  b.text = document.body.innerText;
})();
</script>"""
"""Appended to a copy of the page (the report has no script of its own): measures, in
Chromium's layout at the window's width, every element's box and each clip's caption."""


def _summary_value(summary: dict, key: str):
    """The value at a headline figure's dotted key, ``created_tools[<name>]`` choosing a
    tool by name."""
    value = summary
    for part in key.split("."):
        name = None
        if part.endswith("]"):
            part, _, name = part[:-1].partition("[")
        value = value[part]
        if name is not None:
            value = next(v for v in value if v.get("name") == name)
    return value


@needs_chromium
def test_the_page_reads_at_1280_px(real_run, real_page, tmp_path):
    """Issue 16 item 3: in Chromium at 1280 px no element is wider than the window,
    every clip's caption is visible under its video, no Prolog variable or internal key
    shows, and the headline's figures are those of summary.json."""
    real_page  # the page as the command wrote it
    probe = real_run / ".layout-probe.html"
    probe.write_text((real_run / "report.html").read_text().replace(
        "</body>", _LAYOUT_PROBE + "</body>"))
    try:
        proc = subprocess.run(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
             f"--user-data-dir={tmp_path / 'chromium-profile'}", "--window-size=1280,2000",
             "--virtual-time-budget=3000", "--dump-dom", probe.resolve().as_uri()],
            capture_output=True, text=True, timeout=120, cwd=tmp_path)
    finally:
        probe.unlink()
    body = next(a for t, a in Dom(proc.stdout).elements if t == "body")
    assert body.get("data-viewport") == "1280", proc.stderr[-1000:]
    assert json.loads(body["data-wide"]) == [] and body["data-scroll-width"] == "1280"
    summary = json.loads((real_run / "summary.json").read_text())
    videos = summary["videos"]
    assert videos and json.loads(body["data-hidden"]) == []
    text = body["data-text"]
    for bad in (r"\b_G\d+", r"(?<![\w.])_\d+\b", r"'-'\(", r"failure:\w+:", r"\bfirst_success\b",
                r"\bsolved_by\b", r"\btrials_to_converge\b",
                # issue 32: Python's repr of terms, option and scene keys, m and cm
                # beside mm, the print figures' JSON keys
                r"Compound\(", r"\bmax_tracking_error\b", r"\b[a-z]+\d\.[a-z]+_[a-z]+\b",
                r"\d cm\b", r"\b\w+_pct\b", r"\b\w+_mm3?\b"):
        assert not re.search(bad, text), (bad, re.search(bad, text))
    # The headline: each card's figure is the summary's number at its key.
    cards = [a for t, a in Dom(proc.stdout).elements if t == "div" and "data-figure" in a]
    keys = {a["data-figure"] for a in cards}
    assert {"use.trials", "create.solved_by", "wall_time_s.total"} <= keys
    for a in cards:
        assert a["data-value"] == str(_summary_value(summary, a["data-figure"])), a
    use = summary["use"]
    assert f"Tool-use learning: {use['trials']} trials of a budget of 2" in text
    assert f"strategy {summary['options']['strategy']}" in text.lower()
    for clip in videos:                                   # the caption says the outcome
        assert lengths_in_mm(clip["reason"]) in text


def test_the_runs_model_file_loads_in_swipl_without_a_warning(real_run):
    """Issue 16 item 6: ``swipl <run>/model.pl`` (the learned and the created tool's
    models) consults without a warning."""
    text = (real_run / "model.pl").read_text()
    assert "learned_model(" in text and "needed a created tool" in text
    proc = subprocess.run(["swipl", "--on-warning=status", "-q", "-g", "halt",
                           str(real_run / "model.pl")], capture_output=True, text=True,
                          timeout=60)
    assert proc.returncode == 0 and "Warning" not in proc.stderr, proc.stderr


def test_summary_names_the_runs_files_relative_to_it(real_run):
    """Issue 16 item 6: the run folder is movable, so summary.json names its own files
    relative to it."""
    text = (real_run / "summary.json").read_text()
    assert str(real_run) not in text
    for tool in json.loads(text)["create"]["created_tools"]:
        for name in tool["files"].values():
            assert name is None or (not Path(name).is_absolute()
                                    and (real_run / name).is_file()), name


def test_the_terminal_report_starts_with_the_headline(real_run):
    out = _creative("report", str(real_run)).stdout
    summary = json.loads((real_run / "summary.json").read_text())
    first = out.splitlines()[0]
    robot = summary["options"]["robot"]     # the run records the arm it used
    assert first == f"Case {summary['case']}, strategy {summary['options']['strategy']}, " \
                    f"seed {summary['seed']}, robot {robot}."
    assert f"Tool-use learning: {summary['use']['trials']} trials" in out
    assert "design_volume_mm3=" not in out and "{'" not in out


def test_the_terminal_report_shows_the_longest_reason_whole_in_80_columns(real_run):
    trials = _trials(real_run)
    longest = max(trials, key=lambda t: len(t["reason"]))
    assert len(longest["reason"]) > 80
    # Into a pipe (not a terminal) with COLUMNS=80: one line per trial, cut nowhere.
    out = _creative("report", str(real_run)).stdout
    lines = [line for line in out.splitlines() if lengths_in_mm(longest["reason"]) in line]
    assert lines and all(t["tool"] in out for t in trials)
    for key in ("tested", "violated"):
        for literal in longest[key]:
            assert literal in lines[0]
    # At 80 columns: each trial a block whose reason, joined across its wrapped lines, is
    # whole.
    out = _creative("report", str(real_run), "--width", "80").stdout
    assert max(len(line) for line in out.splitlines()) <= 80
    reasons = _block_fields(out, "reason")
    assert reasons[: len(trials)] == [reason_text(TrialRecord.from_dict(t)) for t in trials]
    assert "…" not in out


def _block_fields(out: str, name: str) -> list[str]:
    """The value of field ``name`` of every trial block, its wrapped lines joined: a
    field's line starts with five spaces and its name, a wrapped line with ten or more."""
    values: list[list[str]] = []
    current: list[str] | None = None
    for line in out.splitlines():
        if line.startswith(f"     {name} "):
            current = [line.strip()[len(name):].strip()]
            values.append(current)
        elif current is not None and line.startswith(" " * 10) and line.strip():
            current.append(line.strip())
        else:
            current = None
    return [" ".join(v) for v in values]
