"""A line cut on the wire leaves its start in the board's buffer: the job must not stall.

Relay corexy-plotter seed 10: the cable fell silent for 3 s in the middle of
a line.  The board got the line's first bytes, never its end, and waited for
it, idle; the station waited for the answers of that line and the lines
behind it.  The job hung for good.  Judged from the emulator's own log.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Program
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import MachineProfile, load_profile
from protocol.transport.loopback import Direction
from tests.app.test_gcode_resume_proof import EXPECTED, pen_down_moves, run_as_the_api_does, zigzag
from tests.helpers.harness import StationHarness
from tests.helpers.wire_as_written import as_written


@pytest.mark.parametrize("seconds", [3.0, 6.0], ids=["3s", "6s-given-up"])
@pytest.mark.parametrize("name", ["corexy-plotter", "grbl-plotter"])
def test_a_silence_that_cuts_a_line_in_half_neither_hangs_nor_redraws(
    qtbot: QtBot, tmp_path: Path, name: str, seconds: float
) -> None:
    """3 s: the station still waits for the answers (the board, fast, ran what it had); 6 s:
    it gave the board up as silent, forgot its lines, and looks at it once it answers."""
    profile = as_written(load_profile(name))
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    strokes_sent = [0]
    cut_at: list[float] = []

    def cut_mid_line(direction: Direction, data: bytes) -> bytes:
        if cut_at:
            return b"" if harness.clock.now() - cut_at[0] < seconds else data
        if direction is Direction.TO_DEVICE:
            strokes_sent[0] += data.count(b"G1 ")
            if strokes_sent[0] >= 10 and b"G1 " in data:
                cut_at.append(harness.clock.now())
                return data[: data.rfind(b"G1 ") + 6]  # "G1 X1": the rest is lost
        return data

    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        harness.station.model.message.connect(messages.append)
        harness.loopback.set_manipulator(cut_mid_line)
        assert runner.load(zigzag(profile, tmp_path)) == []
        runner.start()
        run_as_the_api_does(harness, runner)
        assert cut_at
        drawn = pen_down_moves(harness)
        assert drawn == EXPECTED[: len(drawn)], messages  # none twice, none out of order
        if seconds < 4:
            # The board still had lines as the cable came back: the next line's bytes end
            # the fragment and the board refuses the glued line; the job stops there.
            assert runner.state in (JobState.DONE, JobState.FAILED), messages
        elif runner.state is not JobState.DONE:
            # GRBL may have moved the fragment into its line buffer, where Bf: cannot show
            # it (docs/link-faults.md): the resume's first line is glued to it and runs
            # ("G1 X60M5": the pen up, then off to X60), and the motion supervision stops it
            # (since the emulator's M3/M5 synchronise as GRBL's do, the timing that shows).
            assert runner.state is JobState.FAILED, messages
            assert "Machine stopped" in messages[-1], messages
        if runner.state is JobState.DONE:
            assert drawn == EXPECTED, messages
    finally:
        runner.deleteLater()
        harness.close()


def _short_strokes(
    profile: MachineProfile, tmp_path: Path, count: int = 20
) -> tuple[Program, list[tuple[float, float]]]:
    """The relay's job: pen-down strokes of 3 mm in a row (60 ms each), 60 to a row, and
    their ends."""
    settings = profile.gcode
    assert settings is not None
    ends = [
        (5.0 + 3 * (k % 60 + 1), (7.0 if k % 2 == 0 else 5.0) + 20 * (k // 60))
        for k in range(count)
    ]
    lines = ["G21 G90", settings.pen_up, "G0 X5 Y5", settings.pen_down]
    lines += [f"G1 X{x:g} Y{y:g} F3000" for x, y in ends]
    lines += [settings.pen_up, "G0 X0 Y0"]
    source = tmp_path / "short.gcode"
    source.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return load_job(source, ["X", "Y"], JobOptions(gcode=settings)), ends


@pytest.mark.parametrize("name", ["corexy-plotter", "grbl-plotter"])
def test_a_whole_line_lost_on_the_way_is_not_taken_for_a_lost_answer(
    qtbot: QtBot, tmp_path: Path, name: str
) -> None:
    """Relay corexy-plotter seed 28: a 3 s silence took a line on its way, whole, and the
    answers of the lines before it on theirs.  The board ran what it had and stood idle; the
    station took every missing answer for one lost on the way back, counted the lost line as
    run too, and went on after it: a stroke from the wrong place, the job "done".  The board
    standing short of where the lines sent end shows they did not all run."""
    profile = as_written(load_profile(name))
    program, ends = _short_strokes(profile, tmp_path)
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    strokes_sent = [0]
    silent_from: list[float] = []

    def lose_the_tenth_stroke(direction: Direction, data: bytes) -> bytes:
        """From the write holding the tenth stroke on, 3 s of silence both ways."""
        if silent_from:
            return b"" if harness.clock.now() - silent_from[0] < 3.0 else data
        if direction is Direction.TO_DEVICE:
            strokes_sent[0] += data.count(b"G1 ")
            if strokes_sent[0] >= 10:
                silent_from.append(harness.clock.now())
                return b""
        return data

    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        harness.station.model.message.connect(messages.append)
        harness.loopback.set_manipulator(lose_the_tenth_stroke)
        assert runner.load(program) == []
        runner.start()
        run_as_the_api_does(harness, runner)
        assert silent_from
        drawn = pen_down_moves(harness)
        assert drawn == ends[: len(drawn)], messages  # none twice, none skipped, in order
        assert runner.state is JobState.DONE, messages
        assert drawn == ends, messages
    finally:
        runner.deleteLater()
        harness.close()


def test_replies_held_then_read_in_a_burst_never_end_the_job_early(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """Relay grbl-plotter seed 21: the board's replies held 3.5 s, then read at once.  Their
    answers let the last lines go, and the board planned and answered them before the window
    had handled the burst; a status report in the burst, made while those lines still waited
    to go, then passed for the board standing after them: "done", six strokes undrawn."""
    profile = as_written(load_profile("grbl-plotter"))
    program, ends = _short_strokes(profile, tmp_path, 60)
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    held: list[bytes] = []

    def hold(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_HOST:
            held.append(data)
            return b""
        return data

    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        drawn_when_done: list[tuple[float, float]] = []
        runner.stateChanged.connect(
            lambda state: (
                drawn_when_done.extend(pen_down_moves(harness)) if state is JobState.DONE else None
            )
        )
        assert runner.load(program) == []
        runner.start()
        # Held when the last few lines still wait to go: their answers end the job.
        harness.run_until(lambda: runner.done >= len(program) - 10, timeout=20)
        harness.loopback.set_manipulator(hold)
        harness.run(3.5)  # the board runs what it has and stands, its replies held
        assert runner.done < len(program)
        # The reader thread reads the burst (answers counted, the last lines sent at once),
        # then the board's answers to those lines, all before the window handles the first.
        session = harness.gcode_session
        burst = session.feeder.receive(b"".join(held))
        held.clear()
        harness.clock.advance(0.05)
        harness.loopback.pump()  # the board plans and answers them (held by the cable here)
        harness.loopback.set_manipulator(None)
        after = session.feeder.receive(b"".join(held))
        assert after.replies, "the board did not answer the last lines"
        session.link.received.emit(burst)
        session.link.received.emit(after)
        run_as_the_api_does(harness, runner)
        assert runner.state is JobState.DONE, messages
        # Done only once the board has drawn it all (the station closes the link after).
        assert drawn_when_done == ends, messages
    finally:
        runner.deleteLater()
        harness.close()


def test_lines_lost_on_a_board_without_bf_neither_hang_nor_redraw(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """Relay string-art seed 34: a 3 s silence took lines whole on a board whose reports carry
    no ``Bf:`` ($10=1).  It ran what it had and stood idle; nothing it reports could show the
    lines missing, and the station waited for their answers for ever: the job hung."""
    profile = as_written(load_profile("grbl-plotter"))  # the wire it was found on
    program, ends = _short_strokes(profile, tmp_path)
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    # From here its reports carry no Bf:, as a fresh GRBL's ($10=1).
    emulator = harness.gcode_emulator
    emulator.config = replace(emulator.config, status_mask=1)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    strokes_sent = [0]
    silent_from: list[float] = []

    def lose_the_tenth_stroke(direction: Direction, data: bytes) -> bytes:
        if silent_from:
            return b"" if harness.clock.now() - silent_from[0] < 3.0 else data
        if direction is Direction.TO_DEVICE:
            strokes_sent[0] += data.count(b"G1 ")
            if strokes_sent[0] >= 10:
                silent_from.append(harness.clock.now())
                return b""
        return data

    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        harness.station.model.message.connect(messages.append)
        harness.loopback.set_manipulator(lose_the_tenth_stroke)
        assert runner.load(program) == []
        runner.start()
        run_as_the_api_does(harness, runner)
        assert silent_from
        drawn = pen_down_moves(harness)
        assert drawn == ends[: len(drawn)], messages  # none twice, none skipped, in order
        assert runner.state in (JobState.DONE, JobState.FAILED), messages
        if runner.state is JobState.DONE:
            assert drawn == ends, messages
    finally:
        runner.deleteLater()
        harness.close()
