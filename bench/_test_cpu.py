"""A pytest plugin of ``bench/test_time.py``: the CPU seconds of every test.

Loaded with ``-p _test_cpu`` (``bench/`` on ``PYTHONPATH``). For each test it adds the
CPU seconds (user + system) of the worker process and of the child processes it waited
for during the test's setup, call and teardown, and appends one JSON line (node id, CPU
seconds, wall seconds) to the file named by ``CREATIVE_TEST_CPU``. A module-scoped
fixture's cost falls on the first test that uses it, as in ``--durations``.
"""

from __future__ import annotations

import json
import os
import resource
import time

import pytest


def _cpu() -> float:
    """Return the CPU seconds of this process and of its waited-for children."""
    total = 0.0
    for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN):
        usage = resource.getrusage(who)
        total += usage.ru_utime + usage.ru_stime
    return total


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    """Measure one test's setup, call and teardown and append its line."""
    cpu, wall = _cpu(), time.perf_counter()
    yield
    path = os.environ.get("CREATIVE_TEST_CPU")
    if path:
        line = {"test": item.nodeid, "cpu_s": round(_cpu() - cpu, 3),
                "wall_s": round(time.perf_counter() - wall, 3)}
        with open(path, "a", encoding="utf-8") as out:
            out.write(json.dumps(line) + "\n")
