"""The drill session against the emulated plotter on a test clock (docs/protocols.md §3).

What goes on the wire (one command at a time, CR-terminated, host rounding),
what the model then shows, what the emulated machine really did (its drill
log), and how refusals, garbage and a lost link are handled.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness

X, Y = 0, 1


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    harness.connect()
    harness.run(0.02)
    yield harness
    harness.close()


@pytest.fixture
def messages(drill: StationHarness) -> list[str]:
    said: list[str] = []
    drill.station.model.message.connect(said.append)
    return said


def wait_idle(drill: StationHarness, timeout: float = 60.0) -> None:
    drill.run_until(lambda: not drill.drill_session.busy, timeout=timeout)


def test_profile_constants_are_the_reference_machines() -> None:
    profile = load_profile("pcb-drill")
    assert profile.dialect == "drill"
    assert profile.link.baud == 19200
    assert [a.name for a in profile.axes] == ["X", "Y"]
    # FIDELITY S2-27: the original drills boards up to A5 (148 x 210 mm).
    assert [a.travel for a in profile.axes] == [210.0, 150.0]
    caps = profile.capabilities
    assert (caps.home, caps.drill, caps.pen, caps.stop_command) == (True, True, True, False)


def test_microsteps_per_mm_and_half_away_from_zero(drill: StationHarness) -> None:
    session = drill.drill_session
    assert session.microsteps_per_mm(X) == pytest.approx(19.8)
    assert session.microsteps_per_mm(Y) == pytest.approx(19.7)
    # Exact halves (in decimal) go away from zero; banker's rounding would give 148 here.
    assert session.to_microsteps(X, 7.5) == 149  # 148.5
    assert session.to_microsteps(X, 12.5) == 248  # 247.5
    assert session.to_microsteps(X, 0.025) == 0  # 0.495
    assert session.to_microsteps(Y, 2.5) == 49  # 49.25
    assert session.to_microsteps(Y, 150) == 2955


def test_one_command_at_a_time(drill: StationHarness) -> None:
    session = drill.drill_session
    done: list[str] = []
    session.commandDone.connect(done.append)
    mark = len(drill.written)
    assert session.move_absolute(X, 100.0)  # 1980 microsteps at 1.3 ms: 2.6 s
    assert session.move_absolute(Y, 50.0)
    assert drill.written[mark:] == [b"X1980\r"]
    assert session.busy
    # Long after R, still before D: Y has not gone out.
    drill.run(2.0)
    assert drill.written[mark:] == [b"X1980\r"]
    assert done == []
    drill.run_until(lambda: done == ["X1980"], timeout=5.0)
    assert drill.written[mark:] == [b"X1980\r", b"Y985\r"]
    wait_idle(drill)
    assert done == ["X1980", "Y985"]
    assert drill.drill_emulator.positions[:2] == (1980, 985)


def test_move_x_rounds_on_the_host_and_the_model_follows_the_done(
    drill: StationHarness,
) -> None:
    session = drill.drill_session
    model = drill.station.model
    idle: list[bool] = []
    session.idle.connect(lambda: idle.append(True))
    mark = len(drill.written)
    assert session.move_absolute(X, 12.5)
    assert drill.written[mark:] == [b"X248\r"]
    assert model.axes[X].status_text == "moving"
    assert model.axes[X].moving
    wait_idle(drill)
    assert model.axes[X].position == pytest.approx(248 / 19.8)
    assert model.axes[X].status_text == "idle"
    assert not model.axes[X].moving
    assert idle == [True]
    assert drill.drill_emulator.positions[0] == 248


def test_moves_outside_the_travel_are_refused(drill: StationHarness, messages: list[str]) -> None:
    mark = len(drill.written)
    assert not drill.drill_session.move_absolute(X, 210.5)
    assert not drill.drill_session.move_absolute(Y, -0.1)
    assert drill.written[mark:] == []
    assert any("210.5" in m and "travel" in m for m in messages)
    assert drill.drill_session.move_absolute(Y, 150.0)
    assert drill.written[mark:] == [b"Y2955\r"]


def test_home_then_drill_makes_one_hole_where_it_was_sent(drill: StationHarness) -> None:
    session = drill.drill_session
    assert session.home(X)
    assert session.move_absolute(X, 12.5)
    assert session.move_absolute(Y, 10.0)
    assert session.drill()
    wait_idle(drill)
    emulator = drill.drill_emulator
    assert emulator.homed
    assert [hole.position for hole in emulator.drill_log] == [(248, 197)]
    assert b"".join(drill.written).endswith(b"N\rX248\rY197\rV\r")
    model = drill.station.model
    assert model.axes[Y].position == pytest.approx(197 / 19.7)


def test_home_sets_both_axes_to_zero_in_the_model(drill: StationHarness) -> None:
    model = drill.station.model
    assert drill.drill_session.home(Y)
    assert model.axes[X].status_text == "homing"
    wait_idle(drill)
    assert [a.position for a in model.axes] == [0.0, 0.0]
    assert [a.status_text for a in model.axes] == ["idle", "idle"]


def test_pen_and_park(drill: StationHarness) -> None:
    session = drill.drill_session
    assert session.pen(True)
    assert session.pen(False)
    assert session.park()
    wait_idle(drill)
    assert [event.down for event in drill.drill_emulator.pen_log] == [True, False]
    assert not drill.drill_emulator.motors_on
    assert drill.station.model.axes[X].status_text == "parked"


def test_terminal_lines_are_parsed_and_garbage_is_refused_locally(
    drill: StationHarness, messages: list[str]
) -> None:
    session = drill.drill_session
    mark = len(drill.written)
    for bad in ("E", "hello", "X-5", "X", "V1", "X1234567", "é", "N\rV"):
        assert not session.send_line(bad), bad
    assert session.refused_lines == 8
    assert drill.written[mark:] == []
    assert any("'E'" in m and "is not a drill command" in m for m in messages)
    assert session.send_line("  X100 ")
    assert drill.written[mark:] == [b"X100\r"]
    wait_idle(drill)
    assert drill.drill_emulator.rejected == 1  # only the probe sent at connect (answered E)


def test_an_error_from_the_device_clears_the_queue(
    drill: StationHarness, messages: list[str]
) -> None:
    session = drill.drill_session
    failed: list[str] = []
    session.commandFailed.connect(failed.append)
    idle: list[bool] = []
    session.idle.connect(lambda: idle.append(True))

    def spoil(direction: Direction, data: bytes) -> bytes:
        # The first X loses its digits on the way: the device answers EX.
        if direction is Direction.TO_DEVICE and data.startswith(b"X"):
            drill.loopback.set_manipulator(None)
            return b"X\r"
        return data

    drill.loopback.set_manipulator(spoil)
    mark = len(drill.written)
    assert session.move_absolute(X, 12.5)
    assert session.drill()
    assert session.pen(True)
    drill.run_until(lambda: bool(failed), timeout=5.0)
    assert failed == ["X248"]
    assert not session.busy
    assert idle == []
    drill.run(1.0)
    # Nothing after the refused command went out, and nothing was drilled.
    assert drill.written[mark:] == [b"X248\r"]
    assert drill.drill_emulator.drill_log == ()
    assert any("refused X248" in m and "2 queued" in m for m in messages)
    assert not drill.station.model.axes[X].moving
    # The session carries on with the next command.
    assert session.drill()
    wait_idle(drill)
    assert len(drill.drill_emulator.drill_log) == 1


def test_garbage_replies_are_counted_and_shown(drill: StationHarness, messages: list[str]) -> None:
    session = drill.drill_session
    done: list[str] = []
    session.commandDone.connect(done.append)

    def add_garbage(direction: Direction, data: bytes) -> bytes:
        return data + b"QQ\r\n" if direction is Direction.TO_HOST else data

    drill.loopback.set_manipulator(add_garbage)
    assert session.pen(True)
    wait_idle(drill)
    assert done == ["K"]
    assert session.rejected >= 1
    assert any("Garbage" in m and "QQ" in m for m in messages)


def test_stop_all_clears_the_queue_and_says_there_is_no_stop(
    drill: StationHarness, messages: list[str]
) -> None:
    session = drill.drill_session
    mark = len(drill.written)
    session.move_absolute(X, 50.0)
    session.move_absolute(Y, 50.0)
    session.drill()
    session.stop_all()
    assert session.queued == ()
    assert any("no stop command" in m and "2 queued" in m for m in messages)
    wait_idle(drill)
    assert drill.written[mark:] == [b"X990\r"]
    assert drill.drill_emulator.drill_log == ()


def test_a_lost_link_clears_the_queue(drill: StationHarness) -> None:
    session = drill.drill_session
    session.move_absolute(X, 50.0)
    session.drill()
    drill.loopback.sever("cable pulled")
    drill.step()
    assert not session.busy
    assert not session.drill()  # motion is refused while the link is lost
    assert drill.drill_emulator.drill_log == ()


def test_a_long_procedure_is_waited_for_and_a_missing_receipt_is_a_silent_link(
    drill: StationHarness,
) -> None:
    """The D of a slow procedure is not a silence; a command nobody acknowledges is."""
    session = drill.drill_session
    silences: list[None] = []
    session.linkLost.connect(lambda: silences.append(None))
    assert session.home(0)  # both axes across their travel: many seconds
    expected = session.expected_s(session.in_flight)  # type: ignore[arg-type]
    assert expected > 3.0
    drill.run_until(lambda: not session.busy, timeout=120)
    assert silences == []

    def to_device_only(direction: Direction, data: bytes) -> bytes:
        return b"" if direction is Direction.TO_DEVICE else data

    drill.loopback.set_manipulator(to_device_only)  # the command never arrives
    assert session.move_absolute(0, 5.0)
    drill.run(0.9)
    assert silences == []
    drill.run(0.3)
    assert silences == [None]


def test_the_session_gives_the_terminal_its_lines_decoded_garbage_included(
    drill: StationHarness,
) -> None:
    """Issue 35: the drill's text is read in the session; the page only shows the lines."""
    session = drill.drill_session
    lines: list[str] = []
    session.terminalLine.connect(lines.append)

    def add_garbage(direction: Direction, data: bytes) -> bytes:
        return data + b"\xff\xfeQ\r\n" if direction is Direction.TO_HOST else data

    assert session.send_line("X100")
    drill.loopback.set_manipulator(add_garbage)
    wait_idle(drill)
    drill.loopback.set_manipulator(None)
    assert lines[0] == "> X100"
    assert "< RX" in lines and "< DX" in lines
    assert "< \ufffd\ufffdQ" in lines  # undecodable bytes shown, never raised on


def test_a_typed_lines_expected_time_is_read_by_the_session(drill: StationHarness) -> None:
    session = drill.drill_session
    period = drill.station.profile.drill_timing.step_periods["X"]
    assert session.line_expected_s(" X1000 ") == pytest.approx(1000 * period)
    for not_a_move in ("N", "V", "hello", "X", "é", "X1000\rV"):
        assert session.line_expected_s(not_a_move) == 0.0
