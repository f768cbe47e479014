"""A feed override of 50 % on real GRBL 1.1h (grbl-sim) and on the emulator: ``Ov:50``, and
the move takes twice as long, in simulated time on both (issue 33's "done when").

How the bytes reach each board: :mod:`tests.helpers.grbl_sim_overrides`.  Figures are
machine time (grbl-sim's step report, the emulator's ManualClock), never the wall clock.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from protocol.gcode.overrides import RAPID_50
from tests.helpers.grbl_sim_overrides import HALF, PAD, run_emulator, run_sim


def test_feed_50_shows_ov_50_and_doubles_the_time_on_grbl_sim_and_the_emulator(
    timing_sim: Path,
) -> None:
    full_sim, _ = run_sim(timing_sim, b"")
    half_sim, replies = run_sim(timing_sim, HALF)
    assert "Ov:50,100,100" in replies
    assert full_sim == pytest.approx(5.0, rel=0.02)
    assert half_sim / full_sim == pytest.approx(2.0, rel=0.02)
    full_emu, _ = run_emulator(b"")
    half_emu, reports = run_emulator(HALF)
    assert any("|Ov:50,100,100" in r for r in reports)
    assert half_emu / full_emu == pytest.approx(2.0, rel=0.02)
    assert half_emu == pytest.approx(half_sim, rel=0.02)


def test_rapid_50_scales_g0_on_grbl_sim_as_on_the_emulator(timing_sim: Path) -> None:
    """G0 X100 at 50 % of 100 mm/s: 50 mm/s after 0.05 s (1.25 mm) up, 2.05 s in all."""
    move = "G0 X100"
    half_sim, replies = run_sim(timing_sim, RAPID_50 + PAD, move)
    assert "Ov:100,50,100" in replies
    assert half_sim == pytest.approx(2.05, rel=0.02)
    half_emu, _ = run_emulator(RAPID_50 + PAD, move)
    assert half_emu == pytest.approx(half_sim, rel=0.02)
