"""The usb3 question hold on its own: when an axis asked where it stands has moved on."""

from __future__ import annotations

from pytestqt.qtbot import QtBot

from app.machines.supervision import MotionFault
from app.machines.usb3.question_hold import BRAKING_COUNTS, HELD_FOR_S, QuestionHold
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from protocol.usb3.codec import AxisId, StepSize, Thread, count_to_mm
from tests.helpers.harness import StationHarness

Y = 1


def test_an_axis_creeping_to_its_stop_after_its_answer_is_not_a_question_run_as_a_move() -> None:
    """The relay's seed 4: on a loaded computer an axis still braking was taken for standing."""
    hold = QuestionHold()
    hold.asked(Y, 10.0)
    assert hold.report(Y, 4794, 10.01) is None  # the answer
    assert hold.report(Y, 4776, 10.1) is None  # 18 counts on, braking
    assert hold.report(Y, 4794 - BRAKING_COUNTS, 10.2) is None


def test_an_axis_running_on_past_the_braking_after_its_answer_is_reported_with_its_answer() -> None:
    hold = QuestionHold()
    hold.asked(Y, 10.0)
    assert hold.report(Y, 8, 10.01) is None  # the answer, already on its way
    assert hold.report(Y, 1208, 10.1) is None
    assert hold.report(Y, 2408, 10.2) is None
    assert hold.report(Y, 8 + BRAKING_COUNTS + 1, 10.3) == 8
    assert hold.report(Y, 9000, 10.4) is None  # said once: the stop releases it anyway


def test_the_hold_ends_once_the_axis_stood_or_the_station_moved_it() -> None:
    hold = QuestionHold()
    hold.asked(Y, 10.0)
    hold.report(Y, 0, 10.01)
    assert hold.report(Y, 50_000, 10.01 + HELD_FOR_S + 0.01) is None  # the joystick, later
    hold.asked(Y, 20.0)
    hold.report(Y, 0, 20.01)
    hold.release(Y)  # a move of the station's went out
    assert hold.report(Y, 50_000, 20.05) is None
    hold.asked(Y, 30.0)
    assert hold.report(Y, 0, 31.5) is None  # a late report is not the answer
    assert hold.report(Y, 50_000, 31.6) is None


def test_a_move_taken_for_lost_in_a_silence_may_still_run_to_its_target() -> None:
    """The relay's seed 3: the station's bytes held back 4.6 s; the axis answered unmoved, the
    move was taken for lost, and then arrived and ran while the job asked where Y stood."""
    hold = QuestionHold()
    hold.late(Y, 3200)
    hold.asked(Y, 10.0)
    assert hold.report(Y, 0, 10.01) is None
    assert hold.report(Y, 2860, 10.1) is None
    assert hold.report(Y, 3200, 10.2) is None
    assert hold.report(Y, 3200 + BRAKING_COUNTS + 1, 10.3) == 0  # past that move: stopped


def test_the_braking_allowed_after_an_answer_is_the_axis_step_sizes() -> None:
    """At 1/8 step a pulse is 4 counts: the braking from top speed is 300 counts, not 2400."""
    hold = QuestionHold()
    hold.asked(Y, 10.0, counts_per_pulse=4)
    assert hold.report(Y, 1000, 10.01) is None  # the answer
    assert hold.report(Y, 1000 + 300, 10.1) is None  # braking still
    assert hold.report(Y, 1000 + 400, 10.2) == 1000  # farther: the question ran as a move
    hold.asked(Y, 20.0)  # full steps unless told
    assert hold.report(Y, 0, 20.01) is None
    assert hold.report(Y, BRAKING_COUNTS, 20.1) is None


def test_a_question_run_as_a_long_move_at_eighth_step_is_stopped_within_a_fraction_of_it(
    qtbot: QtBot,
) -> None:
    """The relay's seed 134 (h-relay6): the connect's question ``Y…0;`` arrived as a move of
    20 000 000 counts at the unit's 1/8 step and was stopped 0.576 mm on, past the job's
    first target (0.5 mm), with 2400 counts allowed for a full step's braking."""
    unit = StationHarness(load_profile("usb3"))
    try:
        faults: list[MotionFault] = []
        unit.connect(wait_for_answer=False)
        session = unit.usb3_session
        session.motionFault.connect(faults.append)
        unit.loopback.set_manipulator(
            lambda direction, data: (
                data.replace(b"Y000000000000000;", b"Y000000020000000;", 1)
                if direction is Direction.TO_DEVICE
                else data
            )
        )
        unit.run_until(lambda: bool(faults), timeout=10.0)
        unit.loopback.set_manipulator(None)
        unit.run_until(lambda: not unit.usb3_emulator.moving(AxisId.Y), timeout=2.0)
        assert session.step_sizes[Y] is StepSize.EIGHTH
        # The braking allowed (77 pulses, 308 counts), a report's travel (120 counts) and the
        # braking after S; (300): under 0.12 mm, where 2400 allowed ran to 0.45 mm and more.
        assert 0 < count_to_mm(unit.usb3_emulator.positions[Y], Thread.M6) < 0.12
        assert "Y asked where it stands, a move of nothing" in faults[0].text
    finally:
        unit.close()


def test_a_move_held_back_on_the_way_and_taken_for_an_end_switch_may_still_run(
    qtbot: QtBot,
) -> None:
    """The relay's seeds 147 and 195 (h-relay6): the station's bytes held 2.3-2.8 s, the
    unit's answer to ``G;`` came before the late move's first report, the axis was taken
    for stopped at an end switch and asked where it stands; the move then ran to its
    target, which the hold (at 1/8 step's braking) took for a question run as a move."""
    unit = StationHarness(load_profile("usb3"))
    try:
        faults: list[MotionFault] = []
        switches: list[int] = []
        unit.connect()
        unit.run(0.5)
        session, firmware = unit.usb3_session, unit.usb3_emulator
        session.motionFault.connect(faults.append)
        session.endSwitchHit.connect(lambda axis, _end, _mm: switches.append(axis))
        move, held, release = b"X000000000003200;", bytearray(), [False]

        def slow_line(direction: Direction, data: bytes) -> bytes:
            if direction is not Direction.TO_DEVICE:
                return data
            if release[0]:
                data, release[0] = bytes(held) + data, False
                held.clear()
            elif move in data:
                held.extend(move)
                data = data.replace(move, b"")
            return data

        unit.loopback.set_manipulator(slow_line)
        start = firmware.positions[0]
        assert session.move_relative(0, 0.5)
        session.request_positions([0])  # answered where it stands: the move has not come
        unit.run_until(lambda: bool(switches), timeout=5.0)
        session.request_positions([0])  # as a paused job asks; the move arrives after it
        release[0] = True
        session.request_settings()
        unit.run_until(lambda: firmware.positions[0] == start + 3200, timeout=10.0)
        unit.run(1.0)
        assert faults == []
    finally:
        unit.close()
