"""A feed hold the job did not ask for pauses the job, and Resume lets the board go on.

Relay grbl-plotter seed 8: bit 0 of a space flipped, and the space became
``!``, which GRBL takes as a feed hold wherever it comes, even mid-line.  The
board held with its planner full; the station waited for answers that never
came and the job stayed "running" (or paused "link lost") for good.  A
machine's own hold button does the same.
"""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from tests.app.test_gcode_resume_proof import EXPECTED, pen_down_moves, zigzag
from tests.helpers.harness import StationHarness
from tests.helpers.wire_as_written import as_written


def test_a_space_flipped_into_a_feed_hold_pauses_the_job_and_resume_goes_on(
    qtbot: QtBot, tmp_path: Path
) -> None:
    profile = as_written(load_profile("grbl-plotter"))
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    strokes_sent = [0]

    def flip_a_space_of_the_eighth_stroke(direction: Direction, data: bytes) -> bytes:
        if direction is not Direction.TO_DEVICE or strokes_sent[0] >= 8:
            return data
        strokes_sent[0] += data.count(b"G1 ")
        if strokes_sent[0] < 8:
            return data
        at = data.rfind(b"G1 ") + 2
        return data[:at] + bytes([data[at] ^ 1]) + data[at + 1 :]  # " " becomes "!"

    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        harness.loopback.set_manipulator(flip_a_space_of_the_eighth_stroke)
        assert runner.load(zigzag(profile, tmp_path)) == []
        runner.start()
        harness.run_until(lambda: runner.state is not JobState.RUNNING, timeout=60)
        assert harness.gcode_emulator.state == "Hold"
        assert runner.state is JobState.PAUSED, messages
        assert "holds" in messages[-1], messages
        assert harness.station.model.link_state is LinkState.CONNECTED
        assert not runner.needs_operator  # as after a lost link: the API resumes it
        runner.resume()
        harness.run_until(lambda: runner.state is not JobState.RUNNING, timeout=120)
        assert runner.state is JobState.DONE, messages
        assert pen_down_moves(harness) == EXPECTED  # each stroke once, in order
    finally:
        runner.deleteLater()
        harness.close()
