"""The usb3 question hold on its own: when an axis asked where it stands has moved on."""

from __future__ import annotations

from app.machines.usb3.question_hold import BRAKING_COUNTS, HELD_FOR_S, QuestionHold

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
