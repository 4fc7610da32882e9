"""Fixtures for the bridge tests: the one Prolog engine of the test process."""

from __future__ import annotations

import pytest

from creative_py.bridge import Engine


@pytest.fixture(scope="session")
def engine() -> Engine:
    """Return the process's engine with the whole learning engine loaded.

    pyswip embeds one SWI-Prolog per process, so every test shares it.
    """
    return Engine.instance()
