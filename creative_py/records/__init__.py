"""What a run leaves behind, at the bottom of the layers: the trial record
(:mod:`creative_py.records.trial`, one line of ``trials.jsonl``) and the run folder's
reader and writer (:mod:`creative_py.records.folder`).

It imports nothing else from :mod:`creative_py`, so the learning loop that writes a run
folder, the simulator that gives a trial its outcome, the reports that read one and the
sweep that collects them all depend on it and on nothing of each other.
"""

from creative_py.records.folder import RunFolder, read_records, read_trials, write_atomic
from creative_py.records.trial import (PHASES, TRIAL_OUTCOMES, TrialRecord, cell_text,
                                       trial_columns)

__all__ = ["PHASES", "RunFolder", "TRIAL_OUTCOMES", "TrialRecord", "cell_text",
           "read_records", "read_trials", "trial_columns", "write_atomic"]
