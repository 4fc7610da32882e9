"""What a run leaves behind, at the bottom of the layers: the run folder's reader and
writer (:mod:`creative_py.records.folder`).

It imports nothing else from :mod:`creative_py`, so the learning loop that writes a run
folder, the reports that read one and the sweep that collects them all depend on it
and on nothing of each other.
"""

from creative_py.records.folder import RunFolder, read_trials, write_atomic

__all__ = ["RunFolder", "read_trials", "write_atomic"]
