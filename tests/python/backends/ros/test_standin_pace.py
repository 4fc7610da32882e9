"""The stand-in's pacing (standin.Pace), on a fake clock: no ROS, no physics."""

from __future__ import annotations

import pytest

from creative_py.backends.ros.standin import Pace


class FakeClock:
    def __init__(self) -> None:
        self.t = 100.0
        self.slept: list[float] = []

    def __call__(self) -> float:
        return self.t

    def sleep(self, s: float) -> None:
        self.slept.append(s)
        self.t += s


class Log:
    def __init__(self) -> None:
        self.lines: list[str] = []

    def warning(self, line: str) -> None:
        self.lines.append(line)


def test_it_sleeps_until_the_wall_clock_reaches_the_physics_time():
    clock, log = FakeClock(), Log()
    pace = Pace(1.0, 0.0, log, clock, clock.sleep)
    for k in range(1, 301):  # 6 s of physics, one publication period (20 ms) at a time
        clock.t += 0.001      # the work of the period
        pace.wait(0.02 * k)
    assert clock.slept[0] == pytest.approx(0.019)
    assert clock.t == pytest.approx(106.0)
    assert pace.factor == pytest.approx(1.0, abs=0.01) and log.lines == []


def test_a_short_lag_is_caught_up_and_a_long_one_dropped_and_reported():
    clock, log = FakeClock(), Log()
    pace = Pace(1.0, 0.0, log, clock, clock.sleep)
    clock.t += 0.2  # a stall of 0.2 s: caught up (no sleep until the physics is ahead)
    pace.wait(0.02)
    assert clock.slept == [] and pace.dropped == 0.0
    pace.wait(0.2)
    assert clock.slept == [] and clock.t == pytest.approx(100.2)
    pace.wait(0.22)
    assert clock.slept == [pytest.approx(0.02)]
    for k in range(13, 260):  # now every period takes 0.08 s of wall time: 4x too slow
        clock.t += 0.08
        pace.wait(0.02 * k)
    assert pace.dropped > 0
    assert pace.factor == pytest.approx(0.25, abs=0.02)
    assert log.lines and log.lines[0].startswith("physics ran at 0.2")
    assert "this machine cannot keep up" in log.lines[0]
