"""Reports of a run folder: the trial plot, the terminal table and the HTML page.

``plot`` draws ``trials.png`` (the paper's Figures 5 and 6) and counts trials per phase;
``contents`` reads a run folder into one value (:class:`~creative_py.report.contents.RunContents`)
without writing anything; ``table`` prints it as rich tables in a terminal; ``page``
writes it as ``report.html`` beside the files it shows, with relative links only.
"""

from creative_py.report.plot import MARKERS, plot_trials, summarise_trials, trial_labels

__all__ = ["MARKERS", "plot_trials", "summarise_trials", "trial_labels"]
