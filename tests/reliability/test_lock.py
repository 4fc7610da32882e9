"""Issue 19 item 1: a run folder is locked for the life of its run; a second run or
resume of the same folder is refused in one line, exit 2."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap

import pytest

from _runs import creative, one_error_line, run_cli, trials, wait_for
from creative_py.learning.options import run_json_check
from creative_py.records.folder import FolderInUse, RunFolder

HOLD = textwrap.dedent("""
    import sys, time
    from creative_py.records.folder import RunFolder
    run = RunFolder.open(sys.argv[1])
    print("locked", flush=True)
    time.sleep(600)
""")


def _holder(folder) -> subprocess.Popen:
    """Return a child process holding ``folder``'s lock (as a run going on does)."""
    proc = subprocess.Popen([sys.executable, "-c", HOLD, str(folder)],
                            stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "locked"
    return proc


def test_a_created_folder_is_locked_until_released(tmp_path):
    run = RunFolder.create(tmp_path, "rake", 0)
    with pytest.raises(FolderInUse, match=rf"another run is using this folder \(pid {os.getpid()}\)"):
        RunFolder.open(run.path)
    run.release()
    again = RunFolder.open(run.path)
    again.release()


def test_a_lock_dies_with_its_process(tmp_path):
    run = RunFolder.create(tmp_path, "rake", 0)
    run.release()
    holder = _holder(run.path)
    with pytest.raises(FolderInUse, match=f"pid {holder.pid}"):
        RunFolder.open(run.path)
    holder.kill()
    holder.wait()
    RunFolder.open(run.path).release()  # SIGKILL leaves no stale lock


def test_resuming_a_folder_in_use_is_refused_in_one_line(tmp_path):
    folder = tmp_path / "run"
    (folder / "snapshots").mkdir(parents=True)
    meta = {"case": "rake", "options": {"phase": "use"}, "world": None, "drawn_world": None}
    (folder / "run.json").write_text(json.dumps({**meta, "check": run_json_check(meta)}))
    (folder / "trials.jsonl").write_text("")
    holder = _holder(folder)
    try:
        line = one_error_line(run_cli("run", "rake", "--resume", str(folder), timeout=120))
    finally:
        holder.kill()
        holder.wait()
    assert line == f"error: {folder}: another run is using this folder (pid {holder.pid})"
    assert (folder / "trials.jsonl").read_text() == ""
    assert not any((folder / "snapshots").iterdir())


@pytest.mark.sim
def test_resumed_twice_at_once_one_is_refused(tmp_path):
    """Two resumes of the same folder at once: one runs it, the other is refused at
    once; the trials are written once."""
    # two tool-use trials and no evaluation: the resume that runs has one trial to do
    first = creative("run", "rake", "--out", str(tmp_path), "--phase", "use",
                     "--max-trials", "2", "--eval-trials", "0", "--video", "none")
    wait_for(lambda: list(tmp_path.glob("*/trials.jsonl")))
    first.kill()  # killed after its first trial
    first.communicate()
    folder = next(tmp_path.glob("*/trials.jsonl")).parent
    a = creative("run", "rake", "--resume", str(folder))
    b = creative("run", "rake", "--resume", str(folder))
    (out_a, err_a), (out_b, err_b) = a.communicate(timeout=600), b.communicate(timeout=600)
    codes = sorted([a.returncode, b.returncode])
    assert codes == [0, 2], (err_a[-1500:], err_b[-1500:])
    refused = err_a if a.returncode == 2 else err_b
    assert "another run is using this folder (pid" in refused
    numbers = [t["trial"] for t in trials(folder)]
    assert numbers == list(range(1, len(numbers) + 1)), numbers
    summary = json.loads((folder / "summary.json").read_text())
    assert summary["use"]["trials"] == len([t for t in trials(folder) if t["phase"] == "use"])


def test_a_forked_child_does_not_keep_the_lock(tmp_path):
    """A clip is rendered in a forked child that may outlive a killed run: the lock
    must die with the run's process, not with the child."""
    code = textwrap.dedent("""
        import os, sys, time
        from creative_py.records.folder import RunFolder
        run = RunFolder.create(sys.argv[1], "rake", 0, "run")
        child = os.fork()
        if child == 0:  # the fork hooks have run: say so (the parent may be killed now)
            print(os.getpid(), flush=True)
            time.sleep(600)
            os._exit(0)
        time.sleep(600)
    """)
    proc = subprocess.Popen([sys.executable, "-c", code, str(tmp_path)],
                            stdout=subprocess.PIPE, text=True)
    child = int(proc.stdout.readline())
    try:
        with pytest.raises(FolderInUse):
            RunFolder.open(tmp_path / "run")
        os.kill(proc.pid, signal.SIGKILL)  # the child sleeps on, as a clip process would
        proc.wait()
        RunFolder.open(tmp_path / "run").release()
    finally:
        os.kill(child, signal.SIGKILL)
