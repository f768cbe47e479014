"""Overrides and work zero in the G-code session, against the emulated GRBL board.

The override reaches what was asked even though GRBL counts each kind of byte once per
real-time pass (the emulator does too): the session looks at ``Ov:`` and sends what is
missing.  Work zero goes through the motion gate: refused while a job is under way, the
travel to the zero judged in machine coordinates.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from app.profiles import load_profile
from protocol.gcode.overrides import FEED_MINUS_10
from tests.helpers.harness import StationHarness


@pytest.fixture
def grbl(qapp: object) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.settled, timeout=5)
    try:
        yield harness
    finally:
        harness.close()


def said(harness: StationHarness) -> list[str]:
    heard: list[str] = []
    harness.station.model.message.connect(heard.append)
    return heard


def x_speed(harness: StationHarness, seconds: float) -> float:
    """mm/s along X from the emulator's log of positions (its own clock)."""
    emulator = harness.gcode_emulator
    t0, x0 = emulator.time, emulator.position()["X"]
    harness.run(seconds)
    return (emulator.position()["X"] - x0) / (emulator.time - t0)


def test_feed_50_reaches_ov_50_and_halves_the_speed_of_the_move_under_way(
    grbl: StationHarness,
) -> None:
    session, emulator = grbl.gcode_session, grbl.gcode_emulator
    assert session.send_line("G1 X250 F600", "intent")
    grbl.run(1.0)
    assert x_speed(grbl, 1.0) == pytest.approx(10.0, rel=0.01)
    mark = len(grbl.written)
    assert session.overrides.set(feed=50)
    # The five -10 % bytes go at once; the board may take them as one (flags): the session
    # completes what its Ov: shows missing.
    assert b"".join(grbl.written[mark:]).count(FEED_MINUS_10) == 5
    grbl.run_until(lambda: session.overrides.wanted is None, timeout=10)
    assert session.overrides.reported is not None and session.overrides.reported.feed == 50
    assert emulator.overrides == (50, 100)
    assert "Ov" in session.status.fields or session.overrides.reported.field() == "Ov:50,100,100"
    assert x_speed(grbl, 1.0) == pytest.approx(5.0, rel=0.01)


def test_grbl_merging_bytes_in_one_pass_is_completed_from_ov(grbl: StationHarness) -> None:
    session, emulator = grbl.gcode_session, grbl.gcode_emulator
    # Every byte of a write reaches the board within one control cycle: -10 counts once.
    assert session.overrides.set(feed=70, rapid=25)
    grbl.run_until(lambda: session.overrides.wanted is None, timeout=15)
    assert emulator.overrides == (70, 25)
    assert session.overrides.set(feed=100)
    grbl.run_until(lambda: session.overrides.wanted is None, timeout=15)
    assert emulator.overrides == (100, 25)


def test_overrides_outside_grbls_range_are_refused_with_the_reason(grbl: StationHarness) -> None:
    heard = said(grbl)
    mark = len(grbl.written)
    assert not grbl.gcode_session.overrides.set(feed=5)
    assert not grbl.gcode_session.overrides.set(rapid=75)
    assert grbl.written[mark:] == []
    assert "outside 10…200 %" in heard[0] and "none of 25, 50 and 100 %" in heard[1]


def test_the_corexy_plotter_has_no_overrides_and_no_work_systems(qapp: object) -> None:
    harness = StationHarness(load_profile("corexy-plotter"))
    harness.connect()
    try:
        harness.run(0.5)
        heard = said(harness)
        mark = len(harness.written)
        session = harness.gcode_session
        assert not session.overrides.set(feed=50)
        assert not session.work.zero(["X"])
        assert not session.work.go_to_zero()
        assert harness.written[mark:] == []
        assert "no feed or rapid override" in heard[0]
        assert "no work coordinate systems" in heard[1]
    finally:
        harness.close()


def test_zero_here_select_and_go_to_work_zero(grbl: StationHarness) -> None:
    session, emulator = grbl.gcode_session, grbl.gcode_emulator
    work = session.work
    assert work.system == "G54"  # the board's banner: a reset, G54
    assert session.move_absolute(0, 30.0) and session.move_absolute(1, 40.0)
    grbl.run_until(lambda: session.settled, timeout=10)
    mark = len(grbl.written)
    assert work.zero(["X", "Y"])
    assert grbl.written[mark:] == [b"G10 L20 P0 X0 Y0\n"]
    grbl.run_until(lambda: session.settled and work.offset == (30.0, 40.0, 0.0), timeout=5)
    assert grbl.station.model.axes[0].offset == pytest.approx(30.0)
    # Elsewhere, then back to the work zero with the pen up.
    assert session.move_absolute(0, 100.0)
    grbl.run_until(lambda: session.settled, timeout=10)
    assert session.pen(True)
    grbl.run_until(lambda: session.settled, timeout=5)
    mark = len(grbl.written)
    assert work.go_to_zero()
    assert grbl.written[mark:] == [b"M5\n", b"G90 G0 X0 Y0\n"]
    grbl.run_until(lambda: session.settled, timeout=10)
    assert emulator.position()["X"] == pytest.approx(30.0)
    assert emulator.position()["Y"] == pytest.approx(40.0)
    assert not emulator.pen_down
    # G55: another system, its own zero.
    assert work.select("G55")
    grbl.run_until(lambda: session.settled, timeout=5)
    assert work.system == "G55" and work.offset == (0.0, 0.0, 0.0)
    assert work.read()
    grbl.run_until(lambda: session.settled and "G59" in work.stored, timeout=5)
    assert work.stored["G54"] == (30.0, 40.0, 0.0) and work.system == "G55"


def test_go_to_work_zero_outside_the_travel_is_refused_before_a_byte(
    grbl: StationHarness,
) -> None:
    session = grbl.gcode_session
    assert session.send_line("G10 L2 P0 X350", "intent")  # beyond X's 300 mm
    grbl.run_until(lambda: session.settled and session.work.offset is not None, timeout=5)
    grbl.run_until(lambda: (session.work.offset or (0.0,))[0] == 350.0, timeout=5)
    heard = said(grbl)
    mark = len(grbl.written)
    assert not session.work.go_to_zero()
    assert grbl.written[mark:] == []
    assert "outside the travel" in heard[-1]


def test_zero_is_refused_while_the_machine_runs_or_a_job_holds_it(grbl: StationHarness) -> None:
    session = grbl.gcode_session
    assert session.send_line("G1 X100 F600", "intent")
    grbl.run(0.5)
    heard = said(grbl)
    mark = len(grbl.written)
    assert not session.work.zero(["X"])
    assert not session.work.select("G55")
    assert not session.work.go_to_zero()
    grbl.run_until(lambda: session.settled, timeout=20)
    grbl.station.model.set_jog_lock("a job is under way")
    assert not session.work.zero(["X"])
    assert grbl.written[mark:] == [] or all(w in (b"?",) for w in grbl.written[mark:])
    assert any("the work zero stays" in h for h in heard)
    assert any("a job is under way" in h for h in heard)


def test_a_second_click_before_the_board_showed_the_first_never_overshoots(
    grbl: StationHarness,
) -> None:
    session, emulator = grbl.gcode_session, grbl.gcode_emulator
    assert session.overrides.set(feed=90)
    assert session.overrides.set(feed=80)  # from 90, where the first bytes take the board
    grbl.run_until(lambda: session.overrides.wanted is None, timeout=15)
    assert emulator.overrides == (80, 100)
    feeds = [e["feed"] for e in emulator.event_log if e["event"] == "override"]
    assert min(feeds) == 80 and feeds[-1] == 80
