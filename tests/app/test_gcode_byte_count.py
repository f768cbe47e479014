"""A line or an answer that arrives twice breaks character counting: stopped before it bites.

Relay corexy-plotter seeds 7, 31 (a line duplicated on the way to the board)
and 37 (an ``OK`` duplicated on the way back): the board's buffer overflowed,
bytes were dropped, a line glued from two halves was refused, and the board
went straight on to the lines behind it — 0.75 mm of a stroke not in the job
before the station's hold arrived.  The board's ``Bf:`` shows more bytes held
than the station counts unanswered well before that: the station stops then.
Judged from the emulator's log: the strokes drawn are a prefix of the job's.

A line duplicated on its way to the CoreXY plotter while its buffer was
nearly full (relay seeds 19, 61, 85), or an ``OK`` duplicated on its way back
(it answers once a move is done, so the line under way is out of its buffer
but still counted unanswered: one answer too many stays within the count),
overflowed it at once, before any report could show it.  The station now
keeps room for one more copy of the longest line in flight
(``LineStreamer(spare_line=True)``): nothing overflows, and the job either
stops on the excess or runs every stroke once.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from tests.app.test_gcode_resume_proof import EXPECTED, pen_down_moves, run_as_the_api_does, zigzag
from tests.helpers.harness import StationHarness
from tests.helpers.wire_as_written import as_written


def _strokes_drawn_are_the_jobs(harness: StationHarness) -> None:
    """Every pen-down move ends on the job's path: a whole stroke, in order, or the last one
    cut short on its own line."""
    drawn = pen_down_moves(harness)
    whole = [d for d in drawn if d in EXPECTED]
    assert whole == EXPECTED[: len(whole)], drawn
    for x, y in drawn[len(whole) :]:
        row = EXPECTED[len(whole)][1]
        assert y == row and 10.0 <= x <= 60.0, drawn  # cut short on its own stroke


@pytest.mark.parametrize(
    ("name", "way"),
    [
        ("corexy-plotter", Direction.TO_HOST),
        ("corexy-plotter", Direction.TO_DEVICE),
        ("grbl-plotter", Direction.TO_DEVICE),
        ("grbl-plotter", Direction.TO_HOST),
    ],
    ids=["corexy-answer", "corexy-line", "grbl-line", "grbl-answer"],
)
def test_a_line_or_answer_arriving_twice_stops_the_job_before_a_wrong_stroke(
    qtbot: QtBot, tmp_path: Path, name: str, way: Direction
) -> None:
    profile = as_written(load_profile(name))
    settings = profile.gcode
    assert settings is not None
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    count = [0]

    def twice(direction: Direction, data: bytes) -> bytes:
        if direction is not way or count[0] < 0:
            return data
        marker = b"g1 " if way is Direction.TO_DEVICE else b"ok"
        count[0] += data.lower().count(marker)
        if count[0] < 12:
            return data
        count[0] = -1  # once
        at = data.lower().rfind(marker)
        end = data.index(b"\n", at) + 1
        return data[:end] + data[at:end] + data[end:]

    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        harness.loopback.set_manipulator(twice)
        assert runner.load(zigzag(profile, tmp_path)) == []
        runner.start()
        run_as_the_api_does(harness, runner)
        assert count[0] == -1
        harness.run(2.0)  # the board settles
        _strokes_drawn_are_the_jobs(harness)
        refused = [
            e["line"]
            for e in harness.gcode_emulator.event_log
            if e["event"] == "reply" and "error" in str(e["text"]).lower()
        ]
        assert refused == [], messages  # no line glued from two halves reached its parser
        if runner.state is JobState.DONE:
            assert pen_down_moves(harness) == EXPECTED, messages
        else:
            assert runner.state is JobState.FAILED, messages
            # The excess in Bf:, or an answer counted for a pen line GRBL was still holding
            # (it answers one only once the moves before it ran: pen_watch.py), whichever
            # report shows it first.
            assert "arrived twice" in messages[-1] or "moves before it still ran" in messages[-1]
    finally:
        runner.deleteLater()
        harness.close()
