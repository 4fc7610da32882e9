"""The trial plot (:func:`creative_py.report.plot.plot_trials`), exact: the figure it
saves is caught and read back (positions, markers, colours, labels, ticks, limits,
sizes) for six trials of every outcome and phase; and the per-phase counts."""

from __future__ import annotations

from pathlib import Path

import matplotlib.figure
import numpy as np
import pytest
from matplotlib.colors import to_rgba
from matplotlib.markers import MarkerStyle

from creative_py.records.summary import TrialCounts
from creative_py.report.plot import plot_trials, trial_labels


def _trial(i, phase, n, tool, outcome, tested=()):
    return {"trial": i, "phase": phase, "phase_trial": n, "variant": "standard",
            "location": 1, "tool": tool, "tested": list(tested), "outcome": outcome}


TRIALS = [_trial(1, "use", 1, "hook_a1", "failure", ["behind(hook_a1,cube1)"]),
          _trial(2, "use", 2, "hook_a2", "success"),
          _trial(3, "create", 1, "hook_new", "blocked", ["a", "b"]),
          _trial(4, "create", 2, "hook_new", "unreachable"),
          _trial(5, "eval", 1, "hook_a2", "invalid"),
          _trial(6, "create", 3, "hook_a1", "success")]


@pytest.fixture
def saved(monkeypatch):
    """The figures plot_trials saves, with savefig's keywords."""
    out = []
    real = matplotlib.figure.Figure.savefig

    def catch(self, path, **kw):
        out.append((self, kw))
        return real(self, path, **kw)

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", catch)
    return out


def _marker_path(marker: str) -> np.ndarray:
    style = MarkerStyle(marker)
    return style.get_path().transformed(style.get_transform()).vertices


def test_the_plot_of_six_trials_exact(tmp_path, saved):
    png = plot_trials(TRIALS, tmp_path / "t.png", title="a title")
    assert png == tmp_path / "t.png" and png.stat().st_size > 1000
    (fig, kw), = saved
    assert kw == {"format": "png", "dpi": 120}   # drawn in memory, then written whole
    # 6 wide at least; 1.6 + 0.38 per tool + 0.045 per character of the longest label
    assert fig.get_size_inches() == pytest.approx([6.0, 1.6 + 0.38 * 3 + 0.045 * 21])
    ax, = fig.axes
    dots = [(c.get_offsets().tolist(), c.get_sizes().tolist(),
             tuple(c.get_facecolors()[0]), c.get_label()) for c in ax.collections]
    assert dots == [
        ([[1, 0]], [70], to_rgba("tab:red"), "failure"),
        ([[2, 1]], [70], to_rgba("tab:green"), "success"),
        ([[3, 2]], [70], to_rgba("tab:orange"), "blocked"),
        ([[4, 2]], [70], to_rgba("tab:gray"), "unreachable"),
        ([[5, 1]], [70], to_rgba("black"), "invalid"),
        ([[6, 0]], [70], to_rgba("tab:green"), "_child5")]   # a label once only
    for c, marker in zip(ax.collections, "xos^Do"):
        assert np.allclose(c.get_paths()[0].vertices, _marker_path(marker)), marker
    span, = ax.patches   # the tool-creation trials 3..6, shaded
    assert (span.get_x(), span.get_width(), span.get_alpha(), span.get_linewidth()) == (
        2.5, 4.0, 0.08, 0.0)
    assert span.get_facecolor() == to_rgba("tab:blue", 0.08)
    text, = ax.texts
    assert (text.get_text(), text.get_position(), text.get_fontsize(), text.get_color()) == (
        "tool creation", (2.6, 2.4), 8.0, "tab:blue")
    assert [(t.get_text(), t.get_rotation(), t.get_ha(), t.get_rotation_mode(),
             t.get_fontsize()) for t in ax.get_xticklabels()] == [
        (label, 50.0, "right", "anchor", 7.0) for label in
        ["#1 TUL  behind(hook_a1,cube1)", "#2 TUL", "#3 TC  a, b", "#4 TC", "#5 EV",
         "#6 TC"]]
    assert list(ax.get_xticks()) == [1, 2, 3, 4, 5, 6]
    assert list(ax.get_yticks()) == [0, 1, 2]
    assert [(t.get_text(), t.get_fontsize()) for t in ax.get_yticklabels()] == [
        ("hook_a1", 8.0), ("hook_a2", 8.0), ("hook_new", 8.0)]
    assert (ax.get_xlim(), ax.get_ylim()) == ((0.4, 6.6), (-0.6, 2.6))
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_title(), ax.title.get_fontsize()) == (
        "trial", "tool", "a title", 10.0)
    assert [line.get_visible() for line in ax.get_xgridlines()] == [True] * 6
    assert ax.get_xgridlines()[0].get_alpha() == 0.25
    assert not any(line.get_visible() for line in ax.get_ygridlines())
    legend = ax.get_legend()
    assert [t.get_text() for t in legend.get_texts()] == [
        "failure", "success", "blocked", "unreachable", "invalid"]
    assert (legend._loc, legend.get_frame_on(), legend.get_texts()[0].get_fontsize()) == (
        2, False, 8.0)   # 2: upper left
    box = legend.get_bbox_to_anchor().transformed(ax.transAxes.inverted())
    assert (box.x0, box.y0) == pytest.approx((1.0, 1.0))


def test_a_long_run_without_creation_or_title(tmp_path, saved):
    trials = [_trial(i, "use", i, f"t{i % 2}", "success") for i in range(1, 13)]
    plot_trials(trials, tmp_path / "u.png")
    (fig, _), = saved
    assert fig.get_size_inches() == pytest.approx([0.45 * 12 + 2.5, 1.6 + 0.38 * 2])
    ax, = fig.axes
    assert len(ax.patches) == len(ax.texts) == 0 and ax.get_title() == ""
    assert (ax.get_xlim(), ax.get_ylim()) == ((0.4, 12.6), (-0.6, 1.6))


def test_labels_and_counts_exact():
    assert trial_labels([_trial(1, "eval", 0, "t", "success", ["x"]),
                         _trial(2, "use", 0, "t", "failure")]) == ["#1 EV  x", "#2 TUL"]
    assert TrialCounts.of(TRIALS).to_dict() == {
        "use": {"trials": 2, "successes": 1, "outcomes": ["failure", "success"]},
        "create": {"trials": 3, "successes": 1,
                   "outcomes": ["blocked", "unreachable", "success"]},
        "eval": {"trials": 1, "successes": 0, "outcomes": ["invalid"]}}


def test_a_run_without_trials_is_an_empty_plot(tmp_path, saved):
    plot_trials([], tmp_path / "e.png")
    (fig, _), = saved
    assert fig.get_size_inches() == pytest.approx([6.0, 1.6])
