"""Supervision in each session, on the emulators and a test clock: no false stop, every true one.

The operator's own ways of moving a machine (jogs, zeroing, the usb3 unit's
joystick, homing, work offsets, arcs) never trip; a command changed on the
wire (the loopback's manipulator stands for the noisy cable) does, stops the
machine and says which move, what was seen and what was expected.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.machines.envelope import Fault
from app.machines.motion_gate import MotionGate
from app.machines.stage.supervision import StageSupervisor
from app.machines.supervision import MotionFault
from app.profiles import ProfileError, load_profile
from protocol.emulator.usb3_firmware import ADC_MAX
from protocol.stage.codec import AxisStatus, CommandId, CommandPacket, EchoFrame, EchoPacket
from protocol.transport.loopback import Direction
from protocol.usb3.codec import AxisId, StepSize, Thread, count_to_mm
from tests.helpers.harness import StationHarness

X, Y, Z = 0, 1, 2


class Watched:
    """A harness whose faults and messages are kept."""

    def __init__(self, profile: str) -> None:
        self.harness = StationHarness(load_profile(profile))
        self.faults: list[MotionFault] = []
        self.messages: list[str] = []
        self.harness.station.model.message.connect(self.messages.append)
        self.harness.connect()
        session = self.harness.station.session
        assert session is not None
        session.motionFault.connect(self.faults.append)

    def close(self) -> None:
        self.harness.close()


@pytest.fixture
def usb3(qtbot: QtBot) -> Iterator[Watched]:
    watched = Watched("usb3")
    watched.harness.run(0.5)
    yield watched
    watched.close()


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[Watched]:
    watched = Watched("grbl-plotter")
    watched.harness.run(0.5)
    yield watched
    watched.close()


# --- the profile ----------------------------------------------------------------------


def test_the_tolerance_comes_from_the_profile_and_nonsense_is_refused(tmp_path: Path) -> None:
    assert load_profile("xy-stage").supervision_tolerance_mm == 0.2
    assert load_profile("pcb-drill").supervision_tolerance_mm == 0.5  # the default
    source = (Path(__file__).resolve().parents[2] / "resources/machines/usb3.toml").read_text(
        "utf-8"
    )
    for bad in ("0", "-1", '"wide"', "inf"):
        path = tmp_path / "bad.toml"
        path.write_text(
            source.replace("tolerance_mm = 0.01", f"tolerance_mm = {bad}"), encoding="utf-8"
        )
        with pytest.raises(ProfileError, match="tolerance_mm"):
            load_profile(path)


# --- the usb3 unit ----------------------------------------------------------------------


def test_usb3_moves_jogs_zeroing_and_the_joystick_never_trip(usb3: Watched) -> None:
    unit = usb3.harness
    session, model, firmware = unit.usb3_session, unit.station.model, unit.usb3_emulator
    session.set_step_size(X, StepSize.FULL)
    unit.run(0.3)
    assert session.move_relative(X, 1.0)
    unit.run_until(lambda: model.axes[X].status_text == "idle" and not firmware.moving(AxisId.X))
    session.set_jog([1, 0, 1])
    unit.hold(1.0)
    session.set_jog([0, 0, -1])  # X released, Z turned round
    unit.hold(1.0)
    session.set_jog([0, 0, 0])
    unit.run(1.0)
    assert session.move_relative(X, 0.5)
    unit.run(0.2)
    session.zero_all()  # on the way: it goes on from its new zero
    unit.run(1.0)
    session.set_thread(Y, Thread.M10)
    unit.run(0.3)
    assert session.move_relative_axes([0.25, 0.3, 0.0])
    unit.run(3.0)
    firmware.set_joystick(AxisId.Y, ADC_MAX)  # the operator at the unit, at rest
    unit.run(1.0)
    firmware.set_joystick(AxisId.Y, 512)
    unit.run(1.0)
    assert session.move_relative(Y, -0.3)
    unit.run(3.0)
    assert usb3.faults == [], usb3.faults
    assert not any("Machine stopped" in m for m in usb3.messages)


def test_a_usb3_count_corrupted_on_the_wire_is_stopped_one_report_past_the_tolerance(
    usb3: Watched,
) -> None:
    unit = usb3.harness
    session, firmware = unit.usb3_session, unit.usb3_emulator
    session.set_step_size(X, StepSize.FULL)
    unit.run(0.3)

    def noisy_cable(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_DEVICE:
            return data.replace(b"X000000000003200;", b"X000001000003200;")
        return data

    unit.loopback.set_manipulator(noisy_cable)
    mark = len(unit.written)
    assert session.move_relative(X, 0.5)  # 3200 counts; 1 000 003 200 arrive
    unit.run_until(lambda: bool(usb3.faults), timeout=10.0)
    assert b"S;" in b"".join(unit.written[mark:])
    unit.run_until(lambda: not firmware.moving(AxisId.X), timeout=2.0)
    ran = count_to_mm(firmware.positions[X], Thread.M6)
    # 0.5 mm sent, 0.01 mm of tolerance, a report's travel (0.15 mm) and the braking from
    # full speed (75 pulses of 32 counts: 0.375 mm).
    assert 0.51 < ran < 0.51 + 0.15 + 0.4
    (fault,) = usb3.faults
    assert fault.text.startswith("Machine stopped: it reported X 0.")
    assert "past the target (X +0.500 mm, +3200 counts); expected X 0.500" in fault.text
    assert fault.text in usb3.messages
    unit.run(2.0)
    assert len(usb3.faults) == 1  # one stop, one message


def _stopped_within_one_report(
    usb3: Watched, axis: int, target: int, sign: int, mark: int
) -> tuple[MotionFault, float]:
    """The unit was stopped (``S;``) one report after the axis left the end ``target`` of its path.

    Returns the fault and how far past the target (mm) the axis came to rest.
    """
    unit = usb3.harness
    firmware = unit.usb3_emulator
    unit.run_until(lambda: bool(usb3.faults), timeout=10.0)
    assert b"S;" in b"".join(unit.written[mark:])
    unit.run_until(lambda: not firmware.moving(AxisId(axis)), timeout=2.0)
    past = count_to_mm((firmware.positions[axis] - target) * sign, Thread.M6)
    # Past the tolerance (0.01 mm), by at most a report's travel at full steps (0.15 mm)
    # and the braking from full speed (0.375 mm); a move run twice would be 0.5 mm past.
    assert 0.01 < past < 0.01 + 0.15 + 0.4, past
    (fault,) = usb3.faults
    assert fault.text in usb3.messages
    unit.run(2.0)
    assert len(usb3.faults) == 1  # one stop, one message
    return fault, past


def test_a_usb3_relative_move_arriving_twice_is_stopped_one_report_past_its_target(
    usb3: Watched,
) -> None:
    """The relay's seed 13: a repeated ``Y…;`` adds its count to the target again."""
    unit = usb3.harness
    session = unit.usb3_session
    session.set_step_size(Y, StepSize.FULL)
    unit.run(0.3)
    doubled = False

    def stuttering_cable(direction: Direction, data: bytes) -> bytes:
        nonlocal doubled
        move = b"Y000000000003200;"
        if direction is Direction.TO_DEVICE and move in data and not doubled:
            doubled = True
            return data.replace(move, move + move)
        return data

    unit.loopback.set_manipulator(stuttering_cable)
    mark = len(unit.written)
    start = unit.usb3_emulator.positions[Y]
    assert session.move_relative(Y, 0.5)  # 3200 counts, arriving twice
    fault, _ = _stopped_within_one_report(usb3, Y, start + 3200, 1, mark)
    assert doubled
    assert "past the target (Y +0.500 mm, +3200 counts); expected Y 0.500" in fault.text


def test_a_usb3_move_whose_direction_was_lost_is_stopped_one_report_off_its_path(
    usb3: Watched,
) -> None:
    """The relay's seed 180: the ``D`` before a move is lost, the move runs the other way."""
    unit = usb3.harness
    session, firmware = unit.usb3_session, unit.usb3_emulator
    session.set_step_size(Y, StepSize.FULL)
    unit.run(0.3)
    assert session.move_relative(Y, 1.0)
    unit.run_until(lambda: unit.station.model.axes[Y].position == 1.0, timeout=10.0)
    unit.run(0.5)  # at rest there
    assert usb3.faults == []
    start = firmware.positions[Y]

    def lossy_cable(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_DEVICE:
            return data.replace(b"D+-+;", b"")  # Y goes on in the last direction: up
        return data

    unit.loopback.set_manipulator(lossy_cable)
    mark = len(unit.written)
    assert session.move_relative(Y, -0.5), usb3.messages  # down 3200 counts; up 3200 runs
    fault, _ = _stopped_within_one_report(usb3, Y, start, 1, mark)  # off the start, upward
    assert "off the path" in fault.text or "past the target" in fault.text, fault.text
    assert "(Y -0.500 mm, -3200 counts)" in fault.text


def test_a_usb3_question_arriving_as_a_long_move_is_stopped_one_report_after_its_answer(
    usb3: Watched,
) -> None:
    """The relay's seed 134: "where does Y stand" (a move of nothing) arrived with one bit
    flipped as a move of 20 000 000 counts.  No move of the station's was in flight, so the
    reports looked like the joystick's and Y ran on for the whole travel."""
    unit = usb3.harness
    session, firmware = unit.usb3_session, unit.usb3_emulator
    start = firmware.positions[Y]

    def noisy_cable(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_DEVICE:
            return data.replace(b"Y000000000000000;", b"Y000000020000000;")
        return data

    unit.loopback.set_manipulator(noisy_cable)
    mark = len(unit.written)
    session.request_positions([Y])
    unit.run_until(lambda: bool(usb3.faults), timeout=10.0)
    assert b"S;" in b"".join(unit.written[mark:])
    unit.loopback.set_manipulator(None)
    unit.run_until(lambda: not firmware.moving(AxisId.Y), timeout=2.0)
    # Its answer, one report at top speed (100 ms), and the braking: well under a millimetre.
    assert 0 < count_to_mm(firmware.positions[Y] - start, Thread.M6) < 1.0
    (fault,) = usb3.faults
    assert "moved while nothing was sent (Y asked where it stands, a move of nothing)" in (
        fault.text
    ), fault.text
    assert fault.text in usb3.messages
    unit.run(2.0)
    assert len(usb3.faults) == 1  # one stop, one message


def test_a_usb3_question_answered_at_rest_never_trips_and_the_joystick_moves_after(
    usb3: Watched,
) -> None:
    """The hold ends once the axis has stood: the joystick moves it afterwards, unjudged."""
    unit = usb3.harness
    session, firmware = unit.usb3_session, unit.usb3_emulator
    session.request_positions([X, Y, Z])
    unit.run(1.0)
    firmware.set_joystick(AxisId.Y, ADC_MAX)
    unit.run(1.0)
    firmware.set_joystick(AxisId.Y, 512)
    unit.run(1.0)
    assert firmware.positions[Y] > 0
    assert usb3.faults == [], usb3.faults


def test_a_usb3_move_lost_in_a_silent_line_is_forgotten_once_the_unit_answers_unmoved(
    usb3: Watched,
) -> None:
    """The relay's seed 16: a move sent into a dead line never ran.  Counted anyway, it
    shifted the next targets by its length, and a healthy move was stopped as a runaway."""
    unit = usb3.harness
    session, firmware, model = unit.usb3_session, unit.usb3_emulator, unit.station.model
    session.set_step_size(Y, StepSize.FULL)
    unit.run(0.3)
    assert session.move_relative(Y, 0.5)
    unit.run_until(lambda: model.axes[Y].position == 0.5, timeout=10.0)
    unit.run(0.5)

    unit.loopback.set_manipulator(lambda direction, data: b"")  # the line goes dead
    assert session.move_relative(Y, -0.25)  # never arrives
    unit.run_until(lambda: model.link_state is LinkState.LOST, timeout=10.0)
    unit.loopback.set_manipulator(None)
    unit.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=10.0)
    assert firmware.positions[Y] == 3200  # it did not move

    for delta, there in ((-0.25, 1600), (0.75, 6400)):  # the job sends the move again, on
        assert session.move_relative(Y, delta)
        unit.run_until(lambda there=there: firmware.positions[Y] == there, timeout=10.0)
        unit.run(0.5)
    assert usb3.faults == [], usb3.faults
    assert model.axes[Y].position == 1.0
    assert not any("end switch" in m for m in usb3.messages), usb3.messages


# --- G-code -----------------------------------------------------------------------------


def test_gcode_jogs_offsets_arcs_and_homing_never_trip(grbl: Watched) -> None:
    unit = grbl.harness
    session = unit.gcode_session
    for line in (
        "G90 G0 X10 Y10",
        "G92 X0 Y0",  # a work offset: the machine stays
        "G1 X20 Y0 F3000",
        "G2 X40 Y0 I10 J0",  # up and over, in the offset's coordinates
        "G3 X20 Y0 R10",
        "G91 G1 X-5 Y5",
        "G90 G20 G1 X1 Y1",  # inches
        "G21 G92.1",
        "G0 X5 Y5",
    ):
        assert session.send_line(line, "console", confirmed=True), line
    unit.run_until(lambda: session.settled, timeout=60.0)
    session.set_jog([1, 1])
    unit.hold(0.6)
    session.set_jog([0, 0])
    unit.run(1.0)
    session.set_jog([-1, 0])
    unit.hold(0.4)
    session.set_jog([0, 0])
    unit.run(1.0)
    assert session.send_line("$H", "console")
    unit.run(3.0)
    assert session.send_line("G0 X3 Y4", "console")
    unit.run_until(lambda: session.settled, timeout=30.0)
    assert grbl.faults == [], grbl.faults
    assert not any("Machine stopped" in m for m in grbl.messages)


def test_a_gcode_line_that_lost_bytes_stops_the_board_and_names_the_line(grbl: Watched) -> None:
    unit = grbl.harness
    session, firmware = unit.gcode_session, unit.gcode_emulator
    assert session.send_line("G0 X5 Y5", "console")
    unit.run_until(lambda: session.settled, timeout=30.0)

    def noisy_cable(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_DEVICE:
            return data.replace(b"G1 X18.000 Y18.000 F3000\n", b"G1 X18.F3000\n")
        return data

    unit.loopback.set_manipulator(noisy_cable)
    assert session.send_line("G1 X18.000 Y18.000 F3000", "console")
    unit.run_until(lambda: bool(grbl.faults), timeout=10.0)
    (fault,) = grbl.faults
    assert "off the path of the moves sent (G1 X18.000 Y18.000 F3000)" in fault.text
    unit.run_until(lambda: firmware.state in ("Idle", "Hold"), timeout=5.0)
    where = firmware.position()
    x, y = where["X"], where["Y"]
    assert y == pytest.approx(5.0) and 5.0 < x < 18.0  # held on the wrong stroke


# --- the stage ----------------------------------------------------------------------------


def _echo(status: int, *positions_mm: float) -> EchoFrame:
    return EchoFrame(tuple(EchoPacket(0, status, round(p * 1000)) for p in positions_mm))


def test_stage_echoes_follow_moves_and_anything_else_is_judged_from_rest(qtbot: QtBot) -> None:
    harness = StationHarness(load_profile("xy-stage"))
    try:
        model = harness.station.model
        supervisor = StageSupervisor(model, MotionGate(model))
        assert supervisor.judge(_echo(AxisStatus.IDLE, 10.0, 5.0)) is None  # anchors at rest
        supervisor.sent((CommandPacket(CommandId.MOVE_ABS, 20_000), CommandPacket(CommandId.NOP)))
        moving = AxisStatus.CONSTANT_SPEED
        for x in (10.0, 14.0, 19.9, 20.0):
            assert supervisor.judge(_echo(moving, x, 5.0)) is None
        fault = supervisor.judge(_echo(moving, 21.0, 5.0))
        assert fault is not None
        assert "past the target (X MOVE_ABS 20.000 mm); expected X 20.000" in fault.text
        # Released after the stop: judged again once seen at rest.
        assert supervisor.judge(_echo(moving, 22.0, 5.0)) is None
        assert supervisor.judge(_echo(AxisStatus.STOPPED, 22.5, 5.0)) is None
        supervisor.sent((CommandPacket(CommandId.JOG, 1), CommandPacket(CommandId.HOME)))
        assert supervisor.judge(_echo(moving, 40.0, 0.0)) is None  # jog and homing: not followed
        assert supervisor.judge(_echo(AxisStatus.IDLE, 41.0, 0.0)) is None
        supervisor.sent((CommandPacket(CommandId.MOVE_REL, -1000), CommandPacket(CommandId.NOP)))
        assert supervisor.judge(_echo(moving, 40.5, 0.0)) is None
        off = supervisor.judge(_echo(moving, 39.0, 0.0))
        assert off is not None and Fault.PAST_TARGET.value in off.text
    finally:
        harness.close()


def test_stage_moves_and_jogs_on_the_emulator_never_trip(qtbot: QtBot) -> None:
    watched = Watched("xy-stage")
    try:
        unit = watched.harness
        session = unit.session
        unit.run(0.5)
        assert session.move_absolute(X, 10.0)
        assert session.move_absolute(Y, 5.0)
        unit.run(3.0)
        assert session.move_relative(X, -2.5)
        unit.run(2.0)
        session.set_jog([1, 0])
        unit.hold(0.5)
        session.set_jog([0, 0])
        unit.run(1.0)
        assert session.move_absolute(X, 1.0)
        unit.run(0.3)
        assert session.move_absolute(X, 30.0)  # turned round on the way
        unit.run(4.0)
        assert session.home(Y)
        unit.run(5.0)
        assert watched.faults == [], watched.faults
        assert math.isclose(unit.station.model.axes[X].position, 30.0, abs_tol=1e-3)
    finally:
        watched.close()
