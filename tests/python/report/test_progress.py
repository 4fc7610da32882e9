"""The progress of ``creative run`` (issue 16 item 4): every line whole, a status line on
a terminal only, and ``run_case``'s lines through ``logging`` without a callback."""

import io
import logging

from rich.console import Console

from creative_py.report.progress import RunProgress, elapsed_text

LONG = ("TC predicted: hook_a2: behind(hook_a2,cube1) cannot hold within the reach of "
        "hook_a2 in the long_tube task: dx_reach = -0.011 m (deepest prong centre the "
        "held tool reaches, minus the cube centre); the trial would fail, so none is run")


def test_lines_into_a_log_are_never_folded_and_have_no_status_line():
    out = io.StringIO()
    console = Console(file=out, width=80)            # not a terminal: a log file
    with RunProgress(console, budget=12) as progress:
        progress("#3   TUL  hook_a2        loc 1  failure     tested behind(hook_a2,cube1)")
        progress(LONG)
    assert out.getvalue().splitlines() == [
        "#3   TUL  hook_a2        loc 1  failure     tested behind(hook_a2,cube1)", LONG]


def test_the_status_line_says_phase_trial_of_budget_elapsed_and_last_outcome():
    console = Console(file=io.StringIO(), width=120, force_terminal=True)
    progress = RunProgress(console, budget=12, live=False)
    progress.start -= 65
    progress("demonstration: the trainer shows the task with hook_a2 (loc 1)")
    assert progress.status().startswith("demonstration · 1:05 elapsed · demonstration:")
    progress("#3   TUL  hook_a2        loc 1  failure     tested behind(hook_a2,cube1)")
    assert progress.status() == "tool-use learning · trial 3 of 12 · 1:05 elapsed · " \
                                "last: hook_a2 failure"
    progress("#11  EVAL hook_a2        loc 2  success     tested -")
    assert progress.status() == "evaluation · trial 11 · 1:05 elapsed · last: hook_a2 success"
    progress("manufacturing tool 1: meshing, splitting to the build volume and slicing "
             "its pieces")
    assert progress.status().startswith("tool creation · 1:05 elapsed · manufacturing")
    assert elapsed_text(3725) == "1:02:05"


def test_a_terminal_shows_the_status_line_under_the_lines():
    out = io.StringIO()
    console = Console(file=out, width=100, force_terminal=True)
    with RunProgress(console, budget=12) as progress:
        progress("#1   TUL  hook_a1        loc 1  blocked     tested x")
        console.file.flush()
        text = out.getvalue()
    assert "#1   TUL  hook_a1" in text and "trial 1 of 12" in text


def test_run_case_without_a_callback_logs_its_lines(monkeypatch, caplog, tmp_path):
    """``run_case`` from Python, no callback: its first line (the run folder) is logged
    before any physics (the world is stopped there by a failing load)."""
    import creative_py.learning.run as run_module
    from creative_py.learning.options import RunOptions

    def stop(*_a, **_k):
        raise RuntimeError("stop here")

    monkeypatch.setattr(run_module.ClipKeeper, "__init__", stop)
    caplog.set_level(logging.INFO, logger="creative_py.learning.run")
    try:
        run_module.run_case("hook", tmp_path, RunOptions(phase="use"))
    except RuntimeError:
        pass
    assert any(r.getMessage().startswith("run folder ") for r in caplog.records)


def test_each_step_line_names_its_phase_and_the_status_line_is_cut_to_the_width():
    console = Console(file=io.StringIO(), width=30, force_terminal=True)
    progress = RunProgress(console, budget=None, live=False)
    assert progress.status() == "starting · 0:00 elapsed"
    assert (progress.phase, progress.trial, progress.last, progress.doing) == (
        "starting", None, "", "")
    steps = [("demonstration: x", "demonstration"), ("manufacturing y", "tool creation"),
             ("TC catalogue: z", "tool creation"), ("TC predicted: w", "tool creation"),
             ("encoding 3 clips", "video"), ("pddl check", "planning"),
             ("plan: [a]", "planning")]
    for line, phase in steps:
        progress("#14 TC  hook_a1  loc 2  success")
        assert (progress.phase, progress.trial, progress.last) == (
            "tool creation", 14, "hook_a1 success")
        progress(line)
        assert (progress.phase, progress.trial, progress.doing) == (phase, None, line)
        assert progress.status() == f"{phase} · 0:00 elapsed · {line}"
    progress("a line that starts no step")
    assert progress.status() == "planning · 0:00 elapsed · plan: [a]"
    progress("#0 DEMO  hook_a2  loc 1  success")
    assert progress.status() == "demonstration · trial 0 · 0:00 elapsed · last: hook_a2 success"
    progress("#4 TUL  hook_a3  loc 3  blocked")
    assert progress.status() == "tool-use learning · trial 4 · 0:00 elapsed · last: hook_a3 " \
                                "blocked"   # no budget: no "of N"
    rich = progress.__rich__()
    assert (rich.plain, str(rich.style)) == ("tool-use learning · trial 4 …", "bold")
    console.width = 10   # never narrower than 20 columns
    assert progress.__rich__().plain == "tool-use learning ·…"
    console.width = len(progress.status()) + 1   # a status exactly as wide: whole
    assert progress.__rich__().plain == progress.status()
    console.width -= 1
    assert progress.__rich__().plain == progress.status()[:-2] + "…"
    assert [elapsed_text(s) for s in (0, 59.9, 65, 120, 3599, 3600, 36000)] == [
        "0:00", "0:59", "1:05", "2:00", "59:59", "1:00:00", "10:00:00"]


def test_a_progress_line_is_printed_as_written():
    out = io.StringIO()
    progress = RunProgress(Console(file=out, width=80, force_terminal=True,
                                   color_system="standard"), live=False)
    progress("plan: [bold]pick_up(hook_a2)[/bold] in 42 s")
    assert out.getvalue() == "plan: [bold]pick_up(hook_a2)[/bold] in 42 s\n"


def test_a_run_progress_on_a_pipe_has_no_live_line_unless_asked():
    pipe = Console(file=io.StringIO(), force_terminal=False)
    assert RunProgress(pipe)._live is None
    live = RunProgress(pipe, live=True)._live
    assert live is not None and live.transient and live.refresh_per_second == 4
    assert RunProgress(Console(file=io.StringIO(), force_terminal=True), live=False)._live \
        is None
