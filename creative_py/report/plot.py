"""Figures and text reports of a run folder.

The trial plot follows the paper's Figures 5 and 6: trial number on the x axis (tool-use
learning trials "TUL", then tool-creation trials "TC"), the tool used on the y axis, and
each trial drawn as a filled marker (success) or a cross (failure), with blocked,
unreachable and invalid outcomes marked separately; each trial's label names the literal
it tested. Evaluation trials (no learning) are labelled "EV".
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any, Sequence, Union

from creative_py.records.folder import write_atomic
from creative_py.records.summary import RunSummary
from creative_py.records.trial import TrialRecord, as_record

Trials = Sequence[Union[TrialRecord, dict[str, Any]]]
"""Trial records, or the JSON objects of their ``trials.jsonl`` lines."""

MARKERS = {
    "success": dict(marker="o", color="tab:green", label="success"),
    "failure": dict(marker="x", color="tab:red", label="failure"),
    "blocked": dict(marker="s", color="tab:orange", label="blocked"),
    "unreachable": dict(marker="^", color="tab:gray", label="unreachable"),
    "invalid": dict(marker="D", color="black", label="invalid"),
}


def plot_trials(trials: Trials, path: Path, title: str = "") -> Path:
    """Draw the trial outcomes of a run and save them as a PNG.

    Parameters
    ----------
    trials : sequence of TrialRecord or dict
        Records of ``trials.jsonl``; fields used: ``phase``, ``phase_trial``, ``tool``,
        ``tested`` (written under each trial), ``outcome``.
    path : Path
        PNG file to write.
    title : str
        Figure title.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    trials = [as_record(t) for t in trials]
    tools: list[str] = []
    for t in trials:
        if t.tool not in tools:
            tools.append(t.tool)
    longest = max((len(", ".join(t.tested)) for t in trials), default=0)
    # Room under the axis for the slanted labels (about 0.045 inch per character).
    fig, ax = plt.subplots(figsize=(max(6.0, 0.45 * len(trials) + 2.5),
                                    1.6 + 0.38 * len(tools) + 0.045 * longest))
    seen = set()
    for i, t in enumerate(trials, start=1):
        style = dict(MARKERS.get(t.outcome, MARKERS["invalid"]))
        label = style.pop("label")
        y = tools.index(t.tool)
        ax.scatter([i], [y], s=70, label=None if label in seen else label, **style)
        seen.add(label)
    labels = trial_labels(trials)
    # Shade the tool-creation trials and mark the task variant changes.
    tc = [i for i, t in enumerate(trials, start=1) if t.phase == "create"]
    if tc:
        ax.axvspan(min(tc) - 0.5, max(tc) + 0.5, color="tab:blue", alpha=0.08, lw=0)
        ax.text(min(tc) - 0.4, len(tools) - 0.6, "tool creation", fontsize=8, color="tab:blue")
    ax.set_xticks(range(1, len(trials) + 1))
    # Each trial's tick names the literal it tested (the model's own trials test none).
    ax.set_xticklabels(labels, rotation=50, ha="right", rotation_mode="anchor", fontsize=7)
    ax.set_yticks(range(len(tools)))
    ax.set_yticklabels(tools, fontsize=8)
    ax.set_ylim(-0.6, len(tools) - 0.4)
    ax.set_xlim(0.4, len(trials) + 0.6)
    ax.grid(axis="x", alpha=0.25)
    ax.set_xlabel("trial")
    ax.set_ylabel("tool")
    if title:
        ax.set_title(title, fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.0, 1.0), fontsize=8, frameon=False)
    fig.tight_layout()
    image = io.BytesIO()  # drawn whole first: a full disk leaves the old file as it was
    fig.savefig(image, format=Path(path).suffix.lstrip(".") or "png", dpi=120)
    plt.close(fig)
    return write_atomic(Path(path), image.getvalue())


def trial_labels(trials: Trials) -> list[str]:
    """Return each trial's label in the plot: its number in the run, phase tag and the
    literal it tested (``#2 TUL  hook_down(hook_a2)``; the model's trials test none)."""
    out = []
    for i, t in enumerate((as_record(t) for t in trials), start=1):
        tag = {"use": "TUL", "create": "TC", "eval": "EV"}.get(t.phase, t.phase)
        tested = ", ".join(t.tested)
        out.append(f"#{t.trial or i} {tag}" + (f"  {tested}" if tested else ""))
    return out


def plot_title(summary: RunSummary) -> str:
    """Return the title of a run's plot: ``CREATIVE-py, hook case, seed 0``."""
    return f"CREATIVE-py, {summary.case} case, seed {summary.seed}"
