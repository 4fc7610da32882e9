"""Record and compare the trial sequences of whole runs (the refactoring's fixtures).

A run's *sequence* is, per trial, the phase, the tool, the variant and location, the
tested literal and the outcome, plus the created tools' names and dimensions. The
fixtures in ``tests/fixtures/trial_sequences/`` were recorded from ``main`` before a
case became data; ``test_parity.py`` runs the same seeds and compares.

    python tests/integration/parity.py record RUN_DIR OUT.json
    python tests/integration/parity.py compare RUN_DIR FIXTURE.json
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures" / "trial_sequences"


def sequence(run_dir: Path) -> dict:
    """Return the comparable sequence of the run folder ``run_dir``."""
    run_dir = Path(run_dir)
    trials = [json.loads(line) for line in (run_dir / "trials.jsonl").read_text().splitlines()
              if line.strip()]
    summary = json.loads((run_dir / "summary.json").read_text())
    created = summary.get("create", {}).get("created_tools", [])
    return {
        "case": summary["case"],
        "seed": summary["seed"],
        "trials": [[t["phase"], t["phase_trial"], t["tool"], t["variant"], t["location"],
                    t["tested"], t["outcome"]] for t in trials],
        "created": [{"name": c["name"], "instance": c["instance"], "dims": c["dims"],
                     "trial_outcome": c["trial_outcome"]} for c in created],
        "hg": summary["hypotheses"]["hg"],
    }


def differences(got: dict, want: dict) -> list[str]:
    """Return the differences between two sequences, in words (empty when equal)."""
    out = []
    for key in ("case", "seed", "hg", "created"):
        if got[key] != want[key]:
            out.append(f"{key}: got {got[key]!r}, fixture {want[key]!r}")
    g, w = got["trials"], want["trials"]
    for i in range(max(len(g), len(w))):
        a = g[i] if i < len(g) else None
        b = w[i] if i < len(w) else None
        if a != b:
            out.append(f"trial {i + 1}: got {a}, fixture {b}")
    return out


def main(argv: list[str]) -> int:
    if len(argv) != 3 or argv[0] not in ("record", "compare"):
        print(__doc__)
        return 2
    seq = sequence(Path(argv[1]))
    if argv[0] == "record":
        Path(argv[2]).write_text(json.dumps(seq, indent=1) + "\n")
        return 0
    diff = differences(seq, json.loads(Path(argv[2]).read_text()))
    print("\n".join(diff) if diff else "identical")
    return 1 if diff else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
