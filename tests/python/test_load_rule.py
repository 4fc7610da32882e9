"""The rule every backend's tool load follows (creative_py/simulator/load.py): the force
averaged over 0.1 s windows, its 95th percentile over the windows with contact."""

from __future__ import annotations

import pytest

from creative_py.simulator.load import (LOAD_WINDOW_S, robust_force, samples_per_window,
                                        windowed)


def test_one_step_pulses_count_by_their_impulse():
    # a 1 N pulse one step in ten, at 240 Hz: 24 steps a window, 2.4 pulses each
    pulses = ([1.0] + [0.0] * 9) * 48
    per = samples_per_window(240.0)
    assert per == 24 and LOAD_WINDOW_S == 0.1
    means = windowed(pulses, per)
    assert len(means) == 20
    assert all(m in (2 / 24, 3 / 24) for m in means)
    assert robust_force(pulses, per) == pytest.approx(3 / 24)
    # a steady pull of the same impulse gives about the same robust force
    assert robust_force([0.1] * 480, per) == pytest.approx(0.1)


def test_windows_without_contact_are_left_out_and_none_gives_zero():
    assert windowed([0, 0, 0, 4, 0, 0, 0, 0, 2], 4) == [1.0, 2.0]
    assert robust_force([0.0] * 10, 4) == 0.0 and robust_force([], 4) == 0.0
    assert robust_force([3.0], 5) == 3.0  # a last, shorter window is its own mean
    assert samples_per_window(50.0) == 5 and samples_per_window(5.0) == 1
    assert samples_per_window(1.0) == 1   # never fewer than one sample a window
