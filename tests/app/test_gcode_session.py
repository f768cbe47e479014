"""The G-code session against the emulated plotter, on the manual clock.

What the operator relies on: lines reach the device without overrunning its
128-byte buffer, every reply is tied to its line, errors say which line,
positions follow the status reports, Esc stops without losing the position,
a held arrow reaches the wire at once, and a device that falls silent is
noticed.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace

import pytest
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.machines.gcode.session import SILENCE_S, SentLine
from app.profiles import load_profile
from protocol.gcode.codec import FEED_HOLD, SOFT_RESET, STATUS_QUERY
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("corexy-plotter"))
    harness.connect()
    harness.run(0.05)
    try:
        yield harness
    finally:
        harness.close()


def lines_written(harness: StationHarness) -> list[str]:
    """What went out as lines (real-time bytes left out)."""
    text = b"".join(harness.written).decode("ascii")
    for byte in (STATUS_QUERY, FEED_HOLD, SOFT_RESET):
        text = text.replace(byte.decode(), "")
    return [line for line in text.split("\n") if line]


def test_connecting_asks_for_the_status_and_shows_the_position(plotter: StationHarness) -> None:
    assert plotter.station.model.link_state is LinkState.CONNECTED
    assert STATUS_QUERY in b"".join(plotter.written)
    plotter.run(0.3)
    assert plotter.gcode_session.machine_state == "Idle"
    assert [axis.position for axis in plotter.station.model.axes] == [0.0, 0.0]


def test_a_console_line_is_answered_and_moves_the_machine(plotter: StationHarness) -> None:
    session = plotter.gcode_session
    acknowledged: list[SentLine] = []
    replies: list[str] = []
    session.lineAcknowledged.connect(acknowledged.append)
    session.replyText.connect(replies.append)
    assert session.send_line("G1 X20 Y10 F3000")
    plotter.run_until(lambda: bool(acknowledged), timeout=2)
    assert acknowledged[0].text == "G1 X20 Y10 F3000" and acknowledged[0].origin == "console"
    assert replies == ["ok  ← G1 X20 Y10 F3000"]
    plotter.run_until(lambda: session.settled, timeout=5)
    model = plotter.station.model
    assert (model.axes[0].position, model.axes[1].position) == pytest.approx((20.0, 10.0))
    assert plotter.gcode_emulator.position()["X"] == pytest.approx(20.0)


def test_an_error_reply_names_the_line_it_answers(plotter: StationHarness) -> None:
    session = plotter.gcode_session
    failed: list[tuple[SentLine, int, str]] = []
    session.lineFailed.connect(lambda sent, code, meaning: failed.append((sent, code, meaning)))
    session.send_line("G0 X1")
    session.send_line("G7 X1")  # no such command on the plotter
    session.send_line("G0 X2")
    plotter.run_until(lambda: session.streamer.idle, timeout=2)
    assert [(sent.text, code) for sent, code, _ in failed] == [("G7 X1", 20)]
    assert "unsupported" in failed[0][2].lower()
    assert session.errors == 1


def test_character_counting_keeps_at_most_127_bytes_unanswered(plotter: StationHarness) -> None:
    session = plotter.gcode_session
    lines = [f"G1 X{(i % 50) * 1.234:.3f} Y{(i % 37) * 0.5:.3f} F6000" for i in range(200)]
    for line in lines:
        assert session.send_line(line)
    longest = max(len(line) for line in lines) + 1  # its \n
    most = 0
    while not session.streamer.idle:
        most = max(most, session.streamer.in_flight_bytes)
        plotter.step()
    # The buffer was used (several lines out at once), never overrun, and room was kept for
    # a copy of a line in flight (no checksum: a line or an ok may arrive twice).
    assert 127 - 2 * longest < most <= 127 - longest
    assert plotter.gcode_emulator.max_unacknowledged <= 127
    assert plotter.gcode_emulator.overflows == 0


def test_ping_pong_profiles_send_one_line_at_a_time(qtbot: QtBot) -> None:
    profile = load_profile("corexy-plotter")
    assert profile.gcode is not None
    profile = replace(profile, gcode=replace(profile.gcode, streaming="ping-pong"))
    harness = StationHarness(profile)
    try:
        harness.connect()
        harness.run(0.05)  # the board's banner first: bytes sent while it boots are lost
        session = harness.gcode_session
        for i in range(10):
            session.send_line(f"G1 X{i} F6000")
        most = 0
        while not session.streamer.idle:
            most = max(most, session.streamer.in_flight)
            harness.step()
        assert most == 1
        assert len([line for line in lines_written(harness) if line.startswith("G1")]) == 10
    finally:
        harness.close()


def test_moves_from_the_panels_are_absolute_lines_within_the_travel(
    plotter: StationHarness,
) -> None:
    session = plotter.gcode_session
    assert session.move_absolute(1, 42.5)
    assert not session.move_absolute(0, 301.0)  # outside the 300 mm travel: refused here
    plotter.run_until(lambda: session.settled, timeout=5)
    assert plotter.station.model.axes[1].position == pytest.approx(42.5)
    assert session.move_relative(1, -2.5)
    plotter.run_until(lambda: session.settled, timeout=5)
    assert plotter.station.model.axes[1].position == pytest.approx(40.0)
    assert lines_written(plotter) == ["G90 G0 Y42.500", "G90 G0 Y40.000"]


def test_a_held_arrow_reaches_the_wire_at_once_and_stops_on_release(
    plotter: StationHarness,
) -> None:
    session = plotter.gcode_session
    before = len(plotter.written)
    session.set_jog((1, 0))
    # No step of the clock in between: the first jog line is already written.
    # The plotter's firmware has no $J=: absolute steps, so its distance mode stays G90.
    assert any(chunk.startswith(b"G90 G1 X") for chunk in plotter.written[before:])
    for _ in range(10):  # the key's auto-repeat: signs that it is still held
        plotter.run(0.1)
        session.keep_jogging()
    session.set_jog((0, 0))
    sent_at_release = len(lines_written(plotter))
    plotter.run_until(lambda: session.settled and not session.stopping, timeout=5)
    assert len(lines_written(plotter)) == sent_at_release  # nothing more after the release
    x = plotter.station.model.axes[0].position
    # The plotter ignores the jog's F (FIDELITY S1-01): it steps at its own interval, 25 µs.
    profile = plotter.station.profile
    assert profile.gcode is not None and profile.gcode.step_interval_us is not None
    axis = profile.axes[0]
    speed = (
        1e6 / profile.gcode.step_interval_us / (axis.steps_per_rev * axis.microsteps / axis.lead)
    )
    # Travelled about a second's worth; the release held the plotter and dropped what it
    # had queued, so it ran on only while braking.
    assert speed * 0.6 < x < speed * 1.2
    assert not any(b"G91" in chunk for chunk in plotter.written)


def test_stop_holds_then_resets_and_keeps_the_position(plotter: StationHarness) -> None:
    session = plotter.gcode_session
    for i in range(1, 30):
        session.send_line(f"G1 X{i * 5} F600")
    plotter.run(1.0)
    moving_x = plotter.gcode_emulator.position()["X"]
    assert 0 < moving_x < 145
    resets: list[bool] = []
    session.reset.connect(lambda: resets.append(True))
    session.stop_all()
    assert FEED_HOLD in b"".join(plotter.written)
    # The reset waits for the hold to complete: a reset in motion loses GRBL its position.
    assert session.stopping and SOFT_RESET not in b"".join(plotter.written)
    plotter.run_until(lambda: not session.stopping, timeout=2)
    assert plotter.gcode_emulator.state in ("Hold", "Idle")
    written = b"".join(plotter.written)
    assert written.index(FEED_HOLD) < written.index(SOFT_RESET)
    assert resets and session.streamer.idle
    plotter.run(1.0)
    stopped_x = plotter.gcode_emulator.position()["X"]
    plotter.run(1.0)
    assert plotter.gcode_emulator.position()["X"] == stopped_x  # standing still
    assert stopped_x >= moving_x  # it decelerated from where it was, not jumped back
    plotter.run(0.5)
    assert plotter.station.model.axes[0].position == pytest.approx(stopped_x, abs=1e-3)


def test_garbage_from_the_device_is_counted_not_fatal(plotter: StationHarness) -> None:
    session = plotter.gcode_session
    spoiled = [False]

    def add_garbage(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_HOST and not spoiled[0]:
            spoiled[0] = True
            return b"\xff\xfe garbage\n" + data
        return data

    plotter.loopback.set_manipulator(add_garbage)
    assert session.send_line("G0 X5")
    plotter.run_until(lambda: session.settled, timeout=5)
    assert session.rejected == 1
    assert plotter.station.model.axes[0].position == pytest.approx(5.0)
    assert plotter.station.model.link_state is LinkState.CONNECTED


def test_a_silent_device_is_given_up_and_asked_on_without_reopening_the_port(
    plotter: StationHarness,
) -> None:
    """Reopening an Arduino's port restarts the board: a silent one is asked on instead."""

    def swallow(direction: Direction, data: bytes) -> bytes:
        return b"" if direction is Direction.TO_HOST else data

    link = plotter.station.link
    assert link is not None
    closed: list[object] = []
    link.disconnected.connect(closed.append)
    plotter.loopback.set_manipulator(swallow)
    states: list[LinkState] = []
    plotter.station.model.linkStateChanged.connect(states.append)
    plotter.run(SILENCE_S + 0.5)
    assert LinkState.LOST in states
    assert plotter.gcode_session.silent_since is not None
    plotter.loopback.set_manipulator(None)
    plotter.run_until(lambda: plotter.station.model.link_state is LinkState.CONNECTED, timeout=10)
    assert plotter.station.link is link and closed == []  # nothing closed, nothing reopened
    assert plotter.gcode_session.silent_since is None


def grbl_board(status_mask: int) -> StationHarness:
    """The GRBL plotter with ``$10`` set: 1 as on a new board (no ``Bf:``), 3 with it."""
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.messages = []  # type: ignore[attr-defined]
    harness.station.model.message.connect(harness.messages.append)  # type: ignore[attr-defined]
    harness.connect()
    session = harness.gcode_session
    assert session.send_line(f"$10={status_mask}")
    harness.run_until(lambda: session.settled, timeout=5)
    harness.run(0.5)
    return harness


@pytest.fixture
def fresh_grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = grbl_board(1)
    status = harness.gcode_session.status
    assert status is not None and status.planner_free is None
    try:
        yield harness
    finally:
        harness.close()


def held_jog_distance(harness: StationHarness) -> float:
    """How far a right arrow held for a second (key repeats every 0.1 s) takes X."""
    session = harness.gcode_session
    session.set_jog((1, 0))
    for _ in range(10):
        harness.run(0.1)
        session.keep_jogging()
    session.set_jog((0, 0))
    harness.run_until(lambda: session.settled and session.machine_state == "Idle", timeout=5)
    return harness.station.model.axes[0].position


def test_a_held_jog_runs_as_far_on_a_board_without_bf_in_its_reports(
    qtbot: QtBot, fresh_grbl: StationHarness
) -> None:
    """G8-02: without ``Bf:`` the next jog step goes before the last is done, timed."""
    without = held_jog_distance(fresh_grbl)
    assert [m for m in fresh_grbl.messages if "refused" in m] == []  # type: ignore[attr-defined]
    with_bf = grbl_board(3)
    try:
        reference = held_jog_distance(with_bf)
    finally:
        with_bf.close()
    # Steps held back until an idle report would leave the machine standing between them.
    # The board joins jog steps at speed (GRBL's planner, G7-09): the timed feed must not
    # fall behind the Bf: one by more than a tenth (it now goes further: the Bf: feed waits
    # for a fresh report per step), nor run ahead of the key: 1 s held at 50 mm/s, plus
    # the one 5 mm step it sends ahead.
    assert reference > 20 and without >= 0.9 * reference
    assert without <= 1.0 * 50.0 + 5.0


def test_home_refused_for_disabled_homing_says_why_and_what_to_do(
    fresh_grbl: StationHarness,
) -> None:
    """G8-06: GRBL's default $22=0 answers $H with error:5; the station explains it."""
    session = fresh_grbl.gcode_session
    assert session.send_line("$22=0")
    fresh_grbl.run_until(lambda: session.settled, timeout=5)
    assert session.home(0)
    fresh_grbl.run_until(lambda: session.settled, timeout=5)
    told = [m for m in fresh_grbl.messages if "'$H' refused" in m]  # type: ignore[attr-defined]
    assert told and "Homing is switched off on the board ($22=0" in told[-1], told


def test_an_answer_after_a_soft_reset_belongs_to_no_line_and_new_lines_wait_for_the_banner(
    qtbot: QtBot,
) -> None:
    """G8-05: GRBL may answer the line it was parsing after the reset (a stray ok)."""
    harness = grbl_board(3)
    try:
        session = harness.gcode_session
        acknowledged: list[str] = []
        session.lineAcknowledged.connect(lambda sent: acknowledged.append(sent.text))
        session.soft_reset()
        assert session.send_line("G0 X2")
        session.receive_injected(b"ok\r\n")  # the stray ok, before the banner
        assert acknowledged == []
        assert b"G0 X2" not in b"".join(harness.written)  # held until the board is back
        harness.run_until(lambda: session.settled, timeout=5)
        assert acknowledged == ["G0 X2"]
        harness.run_until(lambda: harness.gcode_emulator.state == "Idle", timeout=5)
        assert harness.gcode_emulator.position()["X"] == 2.0
    finally:
        harness.close()
