"""G-code resume from proof, never from line 1: faults on the station's side of the cable.

The station runs on the harness's manual clock; the emulator's own event log
(its pen-down moves) judges the drawing, never what the station says.  After
each fault the job is resumed as the scripting API does it (Resume whenever
the link is back and nobody is asked anything), so a redraw could not hide
behind an operator's decision.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Program
from app.jobs.run.gcode_stream import GcodeStream
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.machines.gcode.session import SentLine
from app.profiles import MachineProfile, load_profile
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness

STROKES = 24


def zigzag(profile: MachineProfile, tmp_path: Path) -> Program:
    """24 strokes, each its own pen-down line from X10 to X60, a row apart (the issue's file)."""
    settings = profile.gcode
    assert settings is not None
    lines = ["G21 G90"]
    for k in range(STROKES):
        y = 5 + 3 * k
        lines += [settings.pen_up, f"G0 X10 Y{y}", settings.pen_down, f"G1 X60 Y{y} F3000"]
    lines.append(settings.pen_up)
    source = tmp_path / "plot.gcode"
    source.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return load_job(source, [a.name for a in profile.axes], JobOptions(gcode=settings))


def pen_down_moves(harness: StationHarness) -> list[tuple[float, float]]:
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
        for e in harness.gcode_emulator.event_log
        if e["event"] == "move" and e["pen"]
    ]


EXPECTED = [(60.0, 5.0 + 3 * k) for k in range(STROKES)]


def run_as_the_api_does(harness: StationHarness, runner: JobRunner, timeout: float = 120) -> None:
    """Resume whenever the link is back and the job is not held for the operator."""
    start = harness.clock.now()
    while runner.state not in (JobState.DONE, JobState.FAILED, JobState.ABORTED):
        if harness.clock.now() - start > timeout:
            raise AssertionError(f"the job hung in {runner.state}")
        harness.step()
        if (
            runner.state is JobState.PAUSED
            and not runner.needs_operator
            and harness.station.model.link_state is LinkState.CONNECTED
        ):
            runner.resume()


Fault = Callable[[StationHarness], None]


def silent_line(seconds: float) -> Fault:
    """Nothing passes either way for ``seconds``, the port open (a pulled RS232 cable)."""

    def fault(harness: StationHarness) -> None:
        harness.loopback.set_manipulator(lambda _d, _b: b"")
        harness.run(seconds)
        harness.loopback.set_manipulator(None)

    return fault


def replies_held(seconds: float) -> Fault:
    """The device's replies are held back ``seconds``, then delivered."""

    def fault(harness: StationHarness) -> None:
        held: list[bytes] = []

        def hold(direction: Direction, data: bytes) -> bytes:
            if direction is Direction.TO_HOST:
                held.append(data)
                return b""
            return data

        harness.loopback.set_manipulator(hold)
        harness.run(seconds)
        harness.loopback.set_manipulator(None)
        if harness.loopback.is_open:
            for data in held:
                harness.loopback.listener.data_received(data)

    return fault


def pulled(seconds: float) -> Fault:
    def fault(harness: StationHarness) -> None:
        harness.loopback.sever("cable pulled")
        harness.run(seconds)

    return fault


@pytest.mark.parametrize(
    ("name", "fault"),
    [
        ("grbl-plotter", replies_held(4.0)),
        ("grbl-plotter", silent_line(5.4)),
        ("corexy-plotter", pulled(3.9)),
        ("corexy-plotter", silent_line(5.4)),
    ],
    ids=["grbl-held-4s", "grbl-silent-5.4s", "corexy-pulled-3.9s", "corexy-silent-5.4s"],
)
@pytest.mark.parametrize("strokes_before", [0, 1, 5, 12])
def test_a_link_fault_mid_job_draws_every_stroke_once_and_resumes_by_itself(
    qtbot: QtBot, tmp_path: Path, name: str, fault: Fault, strokes_before: int
) -> None:
    """The issue's runs: 48 pen-down strokes for a file of 24.  The machine ran what it had
    and stands where the last line it got leaves it: that proves how far it got."""
    profile = load_profile(name)
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(zigzag(profile, tmp_path)) == []
        runner.start()
        harness.run_until(
            lambda: runner.done >= 8 and len(pen_down_moves(harness)) >= strokes_before, 60
        )
        fault(harness)
        run_as_the_api_does(harness, runner)
        assert runner.state is JobState.DONE, messages
        assert pen_down_moves(harness) == EXPECTED  # each stroke once, in order
        assert not any("sent again" in m for m in messages), messages
    finally:
        runner.deleteLater()
        harness.close()


@pytest.mark.parametrize("fault", [silent_line(5.4), pulled(4.6)], ids=["silent", "pulled"])
def test_a_plot_back_home_cut_before_it_began_is_not_taken_for_done(
    qtbot: QtBot, tmp_path: Path, fault: Fault
) -> None:
    """Relay grbl-plotter seed 11: the job's lines lost before one ran, the machine idle at
    home, where the file ends too.  The station said "every answered line ran, and 30 more
    whose answer was lost" and the job done: nothing was drawn.  Standing where the job
    began proves nothing ran as well: the job runs from its first line, or asks."""
    profile = load_profile("grbl-plotter")
    settings = profile.gcode
    assert settings is not None
    strokes = [(60.0, 5.0 + 3 * k) for k in range(4)]
    lines = ["G21 G90"]
    for x, y in strokes:
        lines += [settings.pen_up, f"G0 X10 Y{y:g}", settings.pen_down, f"G1 X{x:g} Y{y:g} F3000"]
    lines += [settings.pen_up, "G0 X0 Y0"]
    source = tmp_path / "plot.gcode"
    source.write_text("\n".join(lines) + "\n", encoding="utf-8")
    program = load_job(source, ["X", "Y"], JobOptions(gcode=settings))
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(program) == []
        runner.start()
        fault(harness)
        start = harness.clock.now()
        while runner.state not in (JobState.DONE, JobState.FAILED, JobState.ABORTED):
            assert harness.clock.now() - start < 120, (runner.state, messages)
            if runner.needs_operator:
                break
            harness.step()
            if (
                runner.state is JobState.PAUSED
                and not runner.needs_operator
                and harness.station.model.link_state is LinkState.CONNECTED
            ):
                runner.resume()
        drawn = pen_down_moves(harness)
        assert drawn == strokes[: len(drawn)], drawn  # none twice, none out of order
        if runner.state is JobState.DONE:
            assert drawn == strokes, messages  # "done" only with every stroke drawn
        else:
            choice = runner.resume_choice
            assert choice is not None and choice.first == 0, (runner.state, messages)
    finally:
        runner.deleteLater()
        harness.close()


def _streamed(tmp_path: Path, lines: list[str], answered: int, written: int) -> GcodeStream:
    """A GRBL job: ``answered`` lines came back ok, ``written`` went out."""
    profile = load_profile("grbl-plotter")
    source = tmp_path / "job.gcode"
    source.write_text("\n".join(lines) + "\n", encoding="utf-8")
    program = load_job(source, ["X", "Y"], JobOptions(gcode=profile.gcode))
    stream = GcodeStream(program, profile, 0)
    for index in range(written):
        stream.pending.append(index)
        stream.next_index = index + 1
        stream.note_written(index)
    for index in range(answered):
        assert stream.acknowledge(SentLine(index + 1, program[index].line, "job", index))
    return stream


SQUARE_LINES = [
    "G21 G90",
    "M5",
    "G0 X10 Y10",
    "M3 S1000",
    "G1 X20 Y10 F3000",
    "G1 X20 Y20",
    "G1 X10 Y20",
    "G1 X10 Y10",
    "M5",
    "G0 X30 Y30",
]


def test_one_place_proves_how_far_the_machine_ran_and_a_pen_change_goes_again(
    tmp_path: Path,
) -> None:
    stream = _streamed(tmp_path, SQUARE_LINES, answered=3, written=7)
    # Idle at the square's second corner: the lines up to it ran, the next did not.
    assert stream.stands_after((20.0, 20.0), 3, 7) == 6
    # At the first corner: the pen change after the move there is sent again, not skipped.
    assert stream.stands_after((10.0, 10.0), 2, 4) == 3


def test_a_path_back_over_the_same_place_proves_nothing(tmp_path: Path) -> None:
    stream = _streamed(tmp_path, SQUARE_LINES, answered=3, written=9)
    # The square starts and ends at 10, 10: before it or after it?  Only the paper says.
    assert stream.stands_after((10.0, 10.0), 3, 9) is None
    # Nowhere on any end: the board did not run them in order to the last (a reset).
    assert stream.stands_after((15.0, 10.0), 3, 9) is None


def test_before_the_first_move_the_place_is_not_known_so_it_proves_nothing(
    tmp_path: Path,
) -> None:
    """The station once took "stands where operation 0 leaves it" as true anywhere, and
    resumed from line 1: 31 operations sent again."""
    stream = _streamed(tmp_path, SQUARE_LINES, answered=0, written=3)
    assert stream.stands_after((55.0, 5.0), 0, 2) is None


def test_a_plot_that_ends_where_the_job_began_proves_nothing_there(tmp_path: Path) -> None:
    """Relay grbl-plotter seed 11: the port pulled before any line ran, the machine still at
    home, and the file's last move goes home too.  The station took "stands where the last
    line leaves it" for proof, said the job done, and nothing was drawn."""
    lines = [*SQUARE_LINES[:-1], "G0 X0 Y0"]
    stream = _streamed(tmp_path, lines, answered=0, written=10)
    # Home is both "nothing ran yet" and "all ran": only the operator can say.
    assert stream.stands_after((0.0, 0.0), 0, 10, start=(0.0, 0.0)) is None
    # A job that began elsewhere: home is only the end.
    assert stream.stands_after((0.0, 0.0), 0, 10, start=(50.0, 50.0)) == 10
    # Standing where it began, on a file that never comes back there: nothing ran yet.
    assert stream.stands_after((0.0, 0.0), 0, 9, start=(0.0, 0.0)) == 0


def test_only_pen_down_moves_count_as_drawing(tmp_path: Path) -> None:
    stream = _streamed(tmp_path, SQUARE_LINES, answered=0, written=10)
    assert not stream.draws_between(0, 4)  # set-up, pen up, travel, pen down
    assert stream.draws_between(3, 5)  # the first side
    assert not stream.draws_between(8, 10)  # pen up, travel home


@pytest.mark.parametrize("name", ["grbl-plotter", "corexy-plotter"])
def test_a_station_restarted_mid_job_resumes_from_its_checkpoint_drawing_each_stroke_once(
    qtbot: QtBot, tmp_path: Path, name: str
) -> None:
    """The station quits while the cable is out; the board runs on with what it got.  The
    checkpoint keeps how far the job was proven run and how far it was sent: the new run
    looks at the machine, and its place proves the rest."""
    profile = load_profile(name)
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    program = zigzag(profile, tmp_path)
    first = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        assert first.load(program) == []
        first.start()
        harness.run_until(lambda: len(pen_down_moves(harness)) >= 4, timeout=60)
        harness.loopback.sever("cable pulled")
        harness.run_until(lambda: first.state is JobState.PAUSED, timeout=5)
        first.abort()  # the station quits
    finally:
        first.deleteLater()
    record = next((tmp_path / "checkpoints").glob("*.json")).read_text(encoding="utf-8")
    assert '"sent"' in record
    harness.run(8.0)  # the board runs on alone
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED, 30)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(program) == []
        assert runner.resume_available is not None
        runner.resume_from_checkpoint()
        run_as_the_api_does(harness, runner)
        assert runner.state is JobState.DONE, messages
        assert pen_down_moves(harness) == EXPECTED
        assert any("every answered line ran" in m for m in messages), messages
    finally:
        runner.deleteLater()
        harness.close()


def test_moves_in_a_row_to_the_same_point_are_one_place(tmp_path: Path) -> None:
    lines = ["G21 G90", "G0 X10 Y10", "M3 S1000", "G1 X20 Y10 F3000", "G1 X20 Y10", "M5"]
    stream = _streamed(tmp_path, lines, answered=2, written=6)
    assert stream.stands_after((20.0, 10.0), 2, 6) == 4


def test_a_winders_plunges_are_work_its_travel_is_not() -> None:
    """Relay string-art seeds 41 and 59: after a reopened port the resume sent 13 operations
    again as "drawing nothing" (the winder has no pen) and drilled a nail twice."""
    from app.jobs.formats.string_art.program import build_program
    from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
    from app.jobs.program import OpKind

    profile = load_profile("string-art")
    program = build_program(StringArtJob(StringArtParams(0, 8, 8.0), (0, 3, 6, 1)), profile)
    stream = GcodeStream(program, profile, 0)
    ops = list(program)
    z = [i for i, op in enumerate(ops) if op.kind is OpKind.MOVE and "Z" in op.target]
    travel = [
        i
        for i, op in enumerate(ops[: program.wait_index])
        if op.kind is OpKind.MOVE and "Z" not in op.target
    ]
    assert z and travel and z[0] < program.wait_index
    assert stream.draws_between(z[0], z[0] + 1)  # a plunge drills
    assert not stream.draws_between(travel[0], travel[0] + 1)  # travel to a nail does not
