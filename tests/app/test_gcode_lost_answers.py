"""The lost-answer watch: a dwell among the lines unanswered bounds the wait, never ends it.

Relay string-art seed 34: a 3 s silence took lines whole, one of them a
``G4 S0.25``.  The board ran what it had and stood idle with its buffer
empty; since a dwell "may keep the board idle", the watch never judged the
answers lost, and the job waited for ever.  Plain Python, on made-up reports.
"""

from __future__ import annotations

from app.machines.gcode.lines import SentLine
from app.machines.gcode.lost_answers import (
    LOST_ANSWER_AFTER_S,
    AnswersLost,
    LostAnswerWatch,
    StreamWaits,
    Unaccounted,
    paused_s,
)
from app.machines.gcode.stuck_line import StuckLineWatch
from protocol.clock import ManualClock
from protocol.gcode.codec import StatusReport

RX = 128
PLANNER = 16


def idle(bf: bool = True) -> StatusReport:
    return StatusReport(
        "Idle", (1.0, 2.0, 0.0), 0.0, 0.0, PLANNER if bf else None, RX - 1 if bf else None
    )


def reports(
    watch: LostAnswerWatch, lines: list[SentLine], seconds: float, bf: bool = True
) -> list[object]:
    """A report every 0.2 s for ``seconds``: the verdicts."""
    found: list[object] = []
    for k in range(round(seconds / 0.2) + 1):
        verdict = watch.judge(idle(bf), lines, PLANNER, True, k * 0.2, 4.0)
        if verdict is not None:
            found.append(verdict)
    return found


DWELL = [SentLine(7, "G4 S0.25", "job", 6), SentLine(8, "G1 Z0.000 F900", "job", 7)]


def test_a_dwell_unanswered_is_waited_for_only_as_long_as_it_lasts() -> None:
    early = reports(LostAnswerWatch(RX), DWELL, LOST_ANSWER_AFTER_S + 0.2)
    assert not any(isinstance(v, AnswersLost) for v in early)  # the dwell may still run
    found = reports(LostAnswerWatch(RX), DWELL, 3.0)
    assert any(isinstance(v, AnswersLost) and v.lines == DWELL for v in found)


def test_a_program_stop_unanswered_is_waited_for_as_long_as_the_operator_takes() -> None:
    stop = [SentLine(7, "M0", "job", 6)]
    found = reports(LostAnswerWatch(RX), stop, 60.0)
    assert not any(isinstance(v, AnswersLost | Unaccounted) for v in found)
    assert any(isinstance(v, StreamWaits) for v in found)  # the operator is told


def test_without_bf_idle_lines_unanswered_end_in_a_reset_not_a_wait_for_ever() -> None:
    found = reports(LostAnswerWatch(RX), DWELL, 10.0, bf=False)
    assert isinstance(found[0], StreamWaits)
    assert any(isinstance(v, Unaccounted) for v in found)


def test_a_fragment_stuck_behind_a_dwell_is_found_once_the_dwell_is_over() -> None:
    """Seed 34 itself: 7 bytes of a cut line in the buffer, a ``G4 S0.25`` unanswered."""
    clock = ManualClock()
    watch = StuckLineWatch(clock, RX)
    fragment = StatusReport("Idle", (1.0, 2.0, 0.0), 0.0, 0.0, PLANNER, RX - 7)
    found = []
    for _ in range(30):
        found.append(watch.stuck(fragment, planner_empty=True, paused_s=paused_s(DWELL)))
        clock.advance(0.2)
    assert 7 in found
    stop = StuckLineWatch(clock, RX)
    for _ in range(300):
        assert (
            stop.stuck(
                fragment, planner_empty=True, paused_s=paused_s([SentLine(9, "M0", "job", 8)])
            )
            is None
        )
        clock.advance(0.2)
