"""Fixtures the end-to-end tests share."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.helpers import grbl_sim, grbl_sim_timing


@pytest.fixture(scope="session")
def timing_sim() -> Path:
    """grbl-sim built with its machine clock reported (built once, skipped without a compiler)."""
    if grbl_sim.compiler() is None:
        pytest.skip("no C compiler and make: grbl-sim cannot be built (.ci/run installs them)")
    source = Path(__file__).resolve().parents[1] / "third_party" / "grbl"
    return grbl_sim_timing.build(source)
