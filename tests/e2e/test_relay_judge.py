"""The fault relay's judge: what the machine did, against the job, decides the verdict.

Pure functions on made-up logs: each wrong machine behaviour (a stroke
twice, one skipped, two swapped, "done" with strokes missing, motion after
the stop, a station that never ends) must be told apart from an exact run
and from a clean stop.
"""

from __future__ import annotations

import json
from typing import Any

import pytest

from tests.helpers.relay_judge import (
    Cut,
    NailBoard,
    Span,
    Stroke,
    Track,
    Verdict,
    corexy_stroke_part_of,
    drill_holes,
    gcode_strokes,
    in_box,
    judge,
    merge_strokes,
    same_stroke,
    stage_targets,
    string_art_ops,
    stroke_part_of,
    usb3_joined,
    usb3_part_of,
    usb3_same,
    usb3_targets,
)

A, B, C, D = (0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)
SQUARE: list[Stroke] = [(A, B), (B, C), (C, D), (D, A)]


def strokes(seen: list[Stroke], at_exit: list[Stroke] | None = None) -> dict[str, Track[Any, Any]]:
    return {
        "strokes": Track(
            SQUARE,
            seen if at_exit is None else at_exit,
            seen,
            same=same_stroke,
            part_of=stroke_part_of,
        )
    }


def test_every_stroke_once_in_order_and_done_is_exact() -> None:
    verdict = judge(strokes(list(SQUARE)), 0, "done: square")
    assert verdict.verdict is Verdict.EXACT, verdict


def test_a_stroke_drawn_twice_is_wrong_even_when_the_job_says_done() -> None:
    verdict = judge(strokes([SQUARE[0], SQUARE[1], SQUARE[1], SQUARE[2], SQUARE[3]]), 0, "done")
    assert verdict.verdict is Verdict.WRONG
    assert "again" in verdict.reason


def test_a_redraw_from_the_start_after_a_stop_is_wrong() -> None:
    verdict = judge(strokes([SQUARE[0], SQUARE[1], SQUARE[0]]), 3, "stopped after 2 of 4")
    assert verdict.verdict is Verdict.WRONG


def test_a_skipped_stroke_is_wrong() -> None:
    verdict = judge(strokes([SQUARE[0], SQUARE[2], SQUARE[3]]), 0, "done")
    assert verdict.verdict is Verdict.WRONG
    assert "out of order" in verdict.reason


def test_two_strokes_swapped_are_wrong() -> None:
    verdict = judge(strokes([SQUARE[0], SQUARE[2], SQUARE[1], SQUARE[3]]), 0, "done")
    assert verdict.verdict is Verdict.WRONG


def test_a_stroke_not_in_the_job_is_wrong() -> None:
    verdict = judge(strokes([SQUARE[0], (B, (10.0, 4.0)), SQUARE[2]]), 3, "stopped")
    assert verdict.verdict is Verdict.WRONG


def test_done_with_strokes_missing_is_wrong() -> None:
    verdict = judge(strokes(SQUARE[:3]), 0, "done")
    assert verdict.verdict is Verdict.WRONG
    assert "said done" in verdict.reason


def test_a_prefix_with_a_message_is_a_clean_stop() -> None:
    verdict = judge(strokes(SQUARE[:2]), 3, "stepdeck run: stopped after 2 of 4: link lost")
    assert verdict.verdict is Verdict.STOPPED, verdict
    assert "link lost" in verdict.reason


def test_a_stop_may_cut_the_last_stroke_short_but_not_an_earlier_one() -> None:
    cut = (B, (10.0, 4.0))
    assert judge(strokes([SQUARE[0], cut]), 3, "stopped").verdict is Verdict.STOPPED
    again = judge(strokes([SQUARE[0], cut, SQUARE[1]]), 3, "stopped")
    assert again.verdict is Verdict.WRONG  # the cut stroke's start drawn twice


def test_a_stop_without_a_word_is_wrong() -> None:
    assert judge(strokes(SQUARE[:2]), 3, "  \n").verdict is Verdict.WRONG


def test_motion_after_the_stop_is_wrong() -> None:
    verdict = judge(strokes(SQUARE[:3], at_exit=SQUARE[:2]), 3, "stopped")
    assert verdict.verdict is Verdict.WRONG
    assert "went on" in verdict.reason


def test_a_station_that_never_ends_is_hung_and_a_wrong_one_still_wrong() -> None:
    assert judge(strokes(SQUARE[:2]), None, "Job paused: link lost").verdict is Verdict.HUNG
    assert judge(strokes([SQUARE[0], SQUARE[0]]), None, "").verdict is Verdict.WRONG


def test_a_crash_or_an_odd_status_is_wrong() -> None:
    said = "Traceback (most recent call last):\n  ...\nValueError"
    assert judge(strokes(SQUARE[:1]), 3, said).verdict is Verdict.WRONG
    assert judge(strokes(SQUARE[:1]), -9, "killed").verdict is Verdict.WRONG


def test_several_tracks_must_all_be_right() -> None:
    tracks: dict[str, Track[Any, Any]] = {
        "axis X": Track([1, 2, 3], [1, 2, 3], [1, 2, 3]),
        "axis Y": Track([5, 6, 7], [5, 7, 6], [5, 7, 6]),
    }
    verdict = judge(tracks, 0, "done")
    assert verdict.verdict is Verdict.WRONG
    assert verdict.reason.startswith("axis Y")


# --- reading the logs --------------------------------------------------------------------------


def _gcode_log(*events: dict[str, Any]) -> str:
    return "\n".join(json.dumps(e) for e in events) + "\n"


def _move(x: float, y: float, pen: bool) -> dict[str, Any]:
    return {"t": 0, "event": "move", "kind": "G1", "pos": {"X": x, "Y": y, "Z": 0.0}, "pen": pen}


def test_pen_down_moves_are_strokes_and_a_stroke_held_midway_is_one() -> None:
    log = _gcode_log(
        _move(0, 0, False),
        {"t": 0, "event": "pen", "down": True, "pos": {"X": 0, "Y": 0, "Z": 0}},
        {"t": 0, "event": "hold", "pos": {"X": 4.0, "Y": 0.0, "Z": 0.0}},
        _move(10, 0, True),
        _move(10, 10, True),
        {"t": 0, "event": "pen", "down": False, "pos": {"X": 10, "Y": 10, "Z": 0}},
        _move(0, 0, False),
        "not json",  # type: ignore[arg-type]
    )
    assert gcode_strokes(log) == [(A, B), (B, C)]


def test_a_stroke_stopped_by_a_reset_and_finished_from_there_is_one_stroke() -> None:
    log = _gcode_log(
        _move(0, 0, False),
        {"t": 0, "event": "pen", "down": True, "pos": {"X": 0, "Y": 0, "Z": 0}},
        {"t": 0, "event": "reset", "pos": {"X": 6.0, "Y": 0.0, "Z": 0.0}},
        {"t": 0, "event": "pen", "down": False, "pos": {"X": 6, "Y": 0, "Z": 0}},
        {"t": 0, "event": "pen", "down": True, "pos": {"X": 6, "Y": 0, "Z": 0}},
        _move(10, 0, True),
    )
    assert gcode_strokes(log) == [(A, B)]
    # ... but redrawn from its start, its first part is drawn twice.
    redrawn = _gcode_log(
        _move(0, 0, False),
        {"t": 0, "event": "pen", "down": True, "pos": {"X": 0, "Y": 0, "Z": 0}},
        {"t": 0, "event": "reset", "pos": {"X": 6.0, "Y": 0.0, "Z": 0.0}},
        {"t": 0, "event": "pen", "down": False, "pos": {"X": 6, "Y": 0, "Z": 0}},
        _move(0, 0, False),
        _move(10, 0, True),
    )
    seen = gcode_strokes(redrawn)
    assert seen == [(A, (6.0, 0.0)), (A, B)]
    track = {"s": Track([(A, B)], seen, seen, same=same_stroke, part_of=stroke_part_of)}
    assert judge(track, 0, "done").verdict is Verdict.WRONG


def test_only_a_piece_a_stop_cut_short_is_joined_to_the_next() -> None:
    half = (5.0, 0.0)
    assert merge_strokes([(s, False) for s in SQUARE]) == SQUARE
    assert merge_strokes([((A, half), True), ((half, B), False)]) == [(A, B)]
    # Two moves of the file that happen to continue in a line stay two strokes.
    assert merge_strokes([((A, half), False), ((half, B), False)]) == [(A, half), (half, B)]
    # Back along the same line is a second stroke over the first, not a longer one.
    assert merge_strokes([((A, B), True), ((B, half), False)]) == [(A, B), (B, half)]


def test_a_corexy_stroke_stopped_midway_may_be_off_the_line_but_not_out_of_its_box() -> None:
    whole = ((17.0, 15.0), (20.0, 17.0))
    caught = ((17.0, 15.0), (19.44, 15.54))  # both motors at one rate: not straight
    assert not stroke_part_of(caught, whole)
    assert corexy_stroke_part_of(caught, whole)
    assert not corexy_stroke_part_of(((17.0, 15.0), (20.5, 16.0)), whole)
    pieces = [(((17.0, 15.0), (19.44, 15.54)), True), (((19.44, 15.54), (20.0, 17.0)), False)]
    assert merge_strokes(pieces, in_box) == [whole]
    assert merge_strokes(pieces) == [p for p, _ in pieces]


def test_holes_are_read_from_the_drill_log() -> None:
    log = "1.0 received V\n2.0 hole X198 Y197\n3.0 done V\n4.5 hole X-3 Y0\n"
    assert drill_holes(log) == [(198, 197), (-3, 0)]


def test_stage_targets_sent_again_count_once() -> None:
    log = "\n".join(
        [
            "1.0 0 MOVE_ABS 10000 1",
            "1.0 1 MOVE_ABS 20000 1",
            "2.0 0 READ 2 1",
            "3.0 0 MOVE_ABS 10000 1",
            "4.0 1 MOVE_ABS 5000 0",
            "5.0 0 MOVE_ABS 30000 1",
        ]
    )
    assert stage_targets(log) == {0: [10000, 30000], 1: [20000]}


def _usb3(*lines: str) -> str:
    return "\n".join(f"{i}.0 {line}" for i, line in enumerate(lines)) + "\n"


def test_usb3_moves_are_places_and_a_move_twice_goes_too_far() -> None:
    log = _usb3(
        "SetDirection(signs=(1, 1, 1))",
        "Move(axis=<AxisId.X: 0>, count=1600)",
        "Move(axis=<AxisId.X: 0>, count=0)",
        "SetDirection(signs=(-1, 1, 1))",
        "Move(axis=<AxisId.X: 0>, count=600)",
        "Move(axis=<AxisId.X: 0>, count=600)",
    )
    seen = usb3_targets(log)["X"]
    assert [str(s) for s in seen] == ["1600", "1000", "400"]
    track = {"X": Track([1600, 1000], seen, seen, same=usb3_same)}
    assert judge(track, 0, "done").verdict is Verdict.WRONG


def test_a_usb3_move_stopped_and_finished_is_one_operation() -> None:
    log = _usb3(
        "SetDirection(signs=(1, 1, 1))",
        "Move(axis=<AxisId.X: 0>, count=3200)",
        "StopAll()",
        "Move(axis=<AxisId.X: 0>, count=1200)",  # it had stopped at 2000
        "Move(axis=<AxisId.X: 0>, count=800)",
    )
    seen = usb3_targets(log)["X"]
    assert seen == [Span(3200, 3200), Span(4000, 4000)]
    # A stopped move followed by one that cannot finish it is a new, unknown place.
    odd = usb3_targets(
        _usb3(
            "Move(axis=<AxisId.X: 0>, count=3200)",
            "StopAll()",
            "SetDirection(signs=(-1, 1, 1))",
            "Move(axis=<AxisId.X: 0>, count=9000)",
        )
    )["X"]
    assert odd == [Span(3200, 3200), Span(-9000, -5800)]
    assert not usb3_same(odd[1], 6400)


@pytest.mark.parametrize("status", [2, 3])
def test_a_refusal_before_anything_moved_is_a_clean_stop(status: int) -> None:
    verdict = judge(strokes([]), status, "stepdeck run: refused: no answer from the device")
    assert verdict.verdict is Verdict.STOPPED


def _winder(*places: tuple[float, float, float]) -> str:
    return _gcode_log(
        *(
            {"t": 0, "event": "move", "kind": "G1", "pos": {"A": a, "X": x, "Z": z}, "pen": False}
            for a, x, z in places
        )
    )


FOUR = NailBoard([0.0, 90.0, 180.0, 270.0], [50.0] * 4, 20.0)


def test_nails_are_drilled_and_wound_round_as_the_needle_went() -> None:
    log = _winder(
        (0, 50, 0),
        (0, 50, 10),
        (0, 50, 20),
        (0, 50, 0),  # nail 0, in two steps down
        (90, 50, 0),
        (90, 50, 20),
        (90, 50, 0),  # nail 1
        (45, 50, 0),
        (45, 40, 0),  # the winding starts: in beside a nail, winds nothing
        (45, 60, 0),
        (135, 60, 0),
        (135, 40, 0),  # out, across nail 1, in: nail 1 wound
        (135, 60, 0),
        (135, 40, 0),  # out and in at one angle (a resume): nothing
        (135, 60, 0),
        (-45, 60, 0),
        (-45, 40, 0),  # back across nails 1 and 0: no one nail
    )
    assert string_art_ops(log, FOUR) == [
        ("nail", 0),
        ("nail", 1),
        ("wrap", 1),
        ("at", "wrap A135.0→-45.0 across [0, 1]"),
    ]


def test_a_nail_drilled_twice_is_wrong() -> None:
    log = _winder((0, 50, 0), (0, 50, 20), (0, 50, 0), (0, 50, 20), (0, 50, 0))
    seen = string_art_ops(log, FOUR)
    track = {"nails": Track([("nail", 0), ("nail", 1)], seen, seen)}
    assert judge(track, 0, "done").verdict is Verdict.WRONG


def test_a_usb3_move_caught_and_stopped_is_judged_where_the_emulator_says_it_stopped() -> None:
    """A corrupted count sent X toward 1 000 019 200; the station stopped it (S;) one report
    later.  The commands alone say only "somewhere past 0": the stop line says where."""
    log = _usb3(
        "SetDirection(signs=(1, 1, 1))",
        "Move(axis=<AxisId.X: 0>, count=1600)",
        "Stopped(axis=<AxisId.X: 0>, count=1600)",
        "Move(axis=<AxisId.X: 0>, count=1000019200)",
        "StopAll()",
        "Stopped(axis=<AxisId.X: 0>, count=2300)",
    )
    seen = usb3_targets(log)["X"]
    assert seen == [Span(1600, 1600), Cut(2300, 2300, 1600, 1000020800)]
    # Short of the job's next target (3200): that move cut short, and the stop was clean.
    track = {"X": Track([1600, 3200], seen, seen, same=usb3_same, part_of=usb3_part_of)}
    assert judge(track, 3, "stepdeck run: stopped: X left its path").verdict is Verdict.STOPPED
    # Past it: a move the job never had, however soon it was stopped.
    past = usb3_targets(log.replace("count=2300", "count=3300"))["X"]
    track = {"X": Track([1600, 3200], past, past, same=usb3_same, part_of=usb3_part_of)}
    assert judge(track, 3, "stepdeck run: stopped: X left its path").verdict is Verdict.WRONG


def test_a_usb3_move_stopped_at_a_switch_and_finished_on_resume_is_one_operation() -> None:
    log = _usb3(
        "Move(axis=<AxisId.X: 0>, count=3200)",
        "Stopped(axis=<AxisId.X: 0>, count=2000)",  # a false end switch: the job pauses
        "Move(axis=<AxisId.X: 0>, count=1200)",  # the resume: on to the same target
        "Stopped(axis=<AxisId.X: 0>, count=3200)",
    )
    assert usb3_targets(log)["X"] == [Span(3200, 3200)]


def test_a_usb3_count_below_one_pulse_moves_nothing() -> None:
    """The relay's seed 164: the question ``X000000000000000;`` arrived as ``X…001;``.  The
    unit moves whole pulses, the count rounded down (4 counts a pulse at its power-on 1/8
    step): it did not move, and the run was exact (judged wrong before)."""
    log = _usb3(
        "SetDirection(signs=(1, 1, 1))",
        "Move(axis=<AxisId.X: 0>, count=1)",
        "Move(axis=<AxisId.X: 0>, count=1600)",
        "Move(axis=<AxisId.X: 0>, count=7)",  # one pulse of four counts, three dropped
    )
    assert usb3_targets(log)["X"] == [Span(1600, 1600), Span(1604, 1604)]
    full = _usb3(
        "StepSizes(sizes=(<StepSize.FULL: 0>, <StepSize.EIGHTH: 3>, <StepSize.EIGHTH: 3>))",
        "Move(axis=<AxisId.X: 0>, count=31)",
        "Move(axis=<AxisId.Y: 1>, count=31)",
    )
    assert "X" not in usb3_targets(full)
    assert usb3_targets(full)["Y"] == [Span(28, 28)]


def test_a_usb3_move_that_ended_short_and_was_finished_is_one_operation() -> None:
    """The relay's seed 152: ``Y…1600;`` arrived as ``Y…1400;``; Y stood 200 counts short
    (taken for an end switch), the job paused, and the resume moved it on to the target."""
    log = _usb3(
        "SetDirection(signs=(1, 1, 1))",
        "Move(axis=<AxisId.Y: 1>, count=3200)",
        "Stopped(axis=<AxisId.Y: 1>, count=3200)",
        "SetDirection(signs=(1, -1, 1))",
        "Move(axis=<AxisId.Y: 1>, count=1400)",
        "Stopped(axis=<AxisId.Y: 1>, count=1800)",
        "Move(axis=<AxisId.Y: 1>, count=200)",
        "Stopped(axis=<AxisId.Y: 1>, count=1600)",
    )
    seen = usb3_targets(log)["Y"]
    assert seen == [Span(3200, 3200), Span(1800, 1800), Span(1600, 1600)]
    joined = usb3_joined(seen, [3200, 1600])
    assert joined == [Span(3200, 3200), Span(1600, 1600)]
    track = {"Y": Track([3200, 1600], joined, joined, same=usb3_same, part_of=usb3_part_of)}
    assert judge(track, 0, "done").verdict is Verdict.EXACT
    # Past the target and back is no piece of it; nor a short place left unfinished.
    assert usb3_joined([Span(3200, 3200), Span(1400, 1400), Span(1600, 1600)], [3200, 1600]) == [
        Span(3200, 3200),
        Span(1400, 1400),
        Span(1600, 1600),
    ]
    unfinished = [Span(3200, 3200), Span(1800, 1800), Span(1000, 1000)]
    assert usb3_joined(unfinished, [3200, 1600, 1000]) == unfinished
