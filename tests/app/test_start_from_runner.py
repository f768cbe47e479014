"""The runner's start at a chosen operation, on the emulated plotters (manual clock).

Judged by the emulator's own event log (its pen-down moves), never by what
the station says.  A start is a resume at a chosen point: what comes before
counts as run in the checkpoint, and a refused start sends nothing.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path

import pytest

import stepdeck
from app.jobs.formats.excellon.reader import build_drill_program, read_drill_file
from app.jobs.formats.string_art.program import build_program
from app.jobs.formats.string_art.reader import read_string_art
from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import OpKind, Program
from app.jobs.run.gcode_stream import resume_state
from app.jobs.run.runner import JobRunner, JobState
from app.jobs.run.start_point import operation_at_line, operation_numbered
from app.machine import LinkState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness

#: Four strokes, one per line 4…7 (lines 5 and 6 relative), then back home with the pen up.
FILE = [
    "G21 G90 F3000",  # 1
    "G0 X10 Y10",  # 2
    "M3 S1000",  # 3
    "G1 X40 Y10",  # 4
    "G91",  # 5
    "X0 Y30",  # 6
    "X-30 Y0",  # 7
    "G90",  # 8
    "X10 Y10",  # 9
    "M5",  # 10
    "G0 X0 Y0",  # 11
]
ENDS = {4: (40.0, 10.0), 6: (40.0, 40.0), 7: (10.0, 40.0), 9: (10.0, 10.0)}
PROFILE = load_profile("grbl-plotter")


def job(tmp_path: Path, lines: list[str] = FILE) -> Path:
    path = tmp_path / "square.gcode"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def program(path: Path) -> Program:
    return load_job(path, [a.name for a in PROFILE.axes], JobOptions(gcode=PROFILE.gcode))


@pytest.fixture
def harness(qapp: object) -> Iterator[StationHarness]:
    built = StationHarness(PROFILE)
    built.connect()
    try:
        yield built
    finally:
        built.close()


def pen_down_ends(harness: StationHarness) -> list[tuple[float, float]]:
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
        for e in harness.gcode_emulator.event_log
        if e["event"] == "move" and e["pen"]
    ]


def finish(harness: StationHarness, runner: JobRunner) -> None:
    harness.run_until(
        lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED), 60
    )


@pytest.mark.parametrize("line", [4, 6, 7, 9])
def test_a_start_at_a_line_draws_that_line_and_the_rest_only(
    harness: StationHarness, tmp_path: Path, line: int
) -> None:
    loaded = program(job(tmp_path))
    runner = JobRunner(harness.station, tmp_path / "ck")
    assert runner.load(loaded) == []
    runner.start_from(operation_at_line(loaded, line))
    finish(harness, runner)
    assert runner.state is JobState.DONE
    assert pen_down_ends(harness) == [end for n, end in ENDS.items() if n >= line]


def test_a_refused_start_says_file_line_and_why_and_sends_nothing(
    harness: StationHarness, tmp_path: Path
) -> None:
    lines = ["G21 G90 F3000", "G0 X10 Y10", "G55", "G1 X20 Y20"]
    gcode = PROFILE.gcode
    assert gcode is not None
    loaded = load_job(
        job(tmp_path, lines),
        [a.name for a in PROFILE.axes],
        JobOptions(gcode=replace(gcode, words=(*gcode.words, "G55"))),
    )
    runner = JobRunner(harness.station, tmp_path / "ck")
    said: list[str] = []
    runner.message.connect(said.append)
    assert runner.load(loaded) == []
    sent = len(harness.written)
    runner.start_from(operation_at_line(loaded, 4))
    harness.run(0.5)
    assert runner.state is JobState.READY
    assert "square.gcode:3: G55 before the start" in said[-1]
    assert harness.written[sent:] == [b"?"] * len(harness.written[sent:])  # status only


def test_what_comes_before_the_start_counts_as_run_in_the_checkpoint(
    harness: StationHarness, tmp_path: Path
) -> None:
    loaded = program(job(tmp_path))
    runner = JobRunner(harness.station, tmp_path / "ck")
    runner.load(loaded)
    start = operation_at_line(loaded, 7)
    runner.start_from(start)
    harness.run_until(lambda: runner.progress.executed > start, 30)
    runner.abort()
    again = JobRunner(harness.station, tmp_path / "ck")
    again.load(loaded)
    assert again.resume_available is not None and again.resume_available > start
    # And with the checkpoint waiting, a new start part-way is refused until it is dealt with.
    said: list[str] = []
    again.message.connect(said.append)
    again.start_from(start)
    assert again.state is JobState.READY
    assert "Resume from the checkpoint or discard it first" in said[-1]


def test_the_scripting_api_starts_at_a_line(qapp: object, tmp_path: Path) -> None:
    machine = stepdeck.connect("grbl-plotter", emulator=True, simulated=True)
    try:
        result = machine.run(job(tmp_path), from_line=7, checkpoint_dir=tmp_path / "ck")
        emulator = machine.station.gcode_emulator
        assert emulator is not None
        ends = [
            (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
            for e in emulator.event_log
            if e["event"] == "move" and e["pen"]
        ]
        assert ends == [ENDS[7], ENDS[9]]
        assert result.resumed_from == operation_at_line(program(job(tmp_path)), 7)
        with pytest.raises(stepdeck.JobRefused, match=r"square\.gcode:40: beyond the end"):
            machine.run(job(tmp_path), from_line=40, checkpoint_dir=tmp_path / "ck")
        with pytest.raises(stepdeck.JobRefused, match="takes no from_line"):
            machine.run(job(tmp_path), from_line=4, resume=True, checkpoint_dir=tmp_path / "ck")
    finally:
        machine.close()


def test_a_resume_inside_an_inch_stretch_goes_back_in_mm_and_on_in_inches(
    harness: StationHarness, tmp_path: Path
) -> None:
    """The resume's way back is in mm; before, a board left in G20 read it as inches (the
    supervision caught the move and failed the job).  The file's units come back after it."""
    strokes = [(1 + (k % 2) * 3, round(0.5 + 0.1 * k, 1)) for k in range(30)]
    lines = ["G20 G90 F100", "G0 X0.5 Y0.5", "M3 S1000"]
    lines += [f"G1 X{x} Y{y}" for x, y in strokes] + ["M5"]
    loaded = program(job(tmp_path, lines))
    runner = JobRunner(harness.station, tmp_path / "ck")
    assert runner.load(loaded) == []
    runner.start()
    harness.run_until(lambda: runner.progress.executed > 8, 60)
    harness.loopback.sever("cable pulled")
    harness.run_until(lambda: runner.state is JobState.PAUSED, 10)
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED, 30)
    runner.resume()
    harness.run_until(lambda: runner.state in (JobState.DONE, JobState.FAILED), 120)
    assert runner.state is JobState.DONE
    expected = [(round(x * 25.4, 3), round(y * 25.4, 3)) for x, y in strokes]
    assert pen_down_ends(harness) == expected


def test_a_drill_job_started_at_a_hole_drills_that_hole_and_the_rest_once(
    qapp: object, tmp_path: Path, data_dir: Path
) -> None:
    """From operation N: a drill cycle starts with the move to its hole; nothing before it."""
    drill = StationHarness(load_profile("pcb-drill"))
    try:
        drill.connect()
        drill.run_until(lambda: drill.station.model.link_state is LinkState.CONNECTED)
        session = drill.drill_session
        assert session.home(0)
        drill.run_until(lambda: not session.busy, timeout=60)
        loaded = build_drill_program(read_drill_file(data_dir / "samples/pcb-driver/driver"))
        runner = JobRunner(drill.station, tmp_path / "ck")
        assert runner.load(loaded) == []
        cycles = [i for i, op in enumerate(loaded) if op.kind is OpKind.DRILL]
        picked = cycles[len(cycles) // 2]  # a hole in the middle, given by its drill cycle
        start = operation_numbered(loaded, picked + 1)
        assert start == picked - 1 and loaded[start].kind is OpKind.MOVE
        runner.start_from(start)

        def over() -> bool:
            if runner.state is JobState.WAITING:
                runner.confirm()
            return runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED)

        drill.run_until(over, timeout=400)
        assert runner.state is JobState.DONE
        expected = Counter(
            (
                session.to_microsteps(0, loaded[i - 1].target["X"]),
                session.to_microsteps(1, loaded[i - 1].target["Y"]),
            )
            for i in cycles
            if i >= picked
        )
        made = Counter((hole.x, hole.y) for hole in drill.drill_emulator.drill_log)
        assert made == expected
    finally:
        drill.close()


def test_a_winder_job_started_part_way_goes_there_tool_first_then_radius_then_turn(
    qapp: object, tmp_path: Path, data_dir: Path
) -> None:
    """From operation N of the winding: the needle is taken out first, then the radius, then
    the base turns (never through the nail ring), and the job goes on from N to its end."""
    job = read_string_art(data_dir / "samples" / "string-art-hexagon" / "poradi.txt")
    job = replace(job, sequence=job.sequence[:7], entry_lines=job.entry_lines[:7])
    winder = StationHarness(load_profile("string-art"))
    try:
        winder.connect()
        winder.run_until(lambda: winder.gcode_session.planner_size > 0, timeout=1)
        loaded = build_program(job, winder.station.profile)
        runner = JobRunner(winder.station, tmp_path / "ck")
        assert runner.load(loaded) == []
        wait = next(i for i, op in enumerate(loaded) if op.kind is OpKind.WAIT)
        moves = [i for i, op in enumerate(loaded) if op.kind is OpKind.MOVE and i > wait]
        start = moves[len(moves) // 2]
        runner.start_from(operation_numbered(loaded, start + 1))
        winder.run_until(lambda: runner.state in (JobState.DONE, JobState.FAILED), 1500)
        assert runner.state is JobState.DONE
        log = [e["pos"] for e in winder.gcode_emulator.event_log if e["event"] == "move"]
        names = [a.name for a in winder.station.profile.axes]
        there = resume_state(loaded, start, names).position
        # The way there: one axis a move, in the order Z, X, A, ending where the file stood.
        way, here = [], dict.fromkeys(names, 0.0)
        for pos in log:
            moved = [a for a in names if abs(pos[a] - here[a]) > 1e-6]
            here = dict(pos)
            way.append(moved)
            if all(abs(pos[a] - v) <= 1e-3 for a, v in there.items()):
                break
        assert all(abs(here[a] - v) <= 1e-3 for a, v in there.items()), "never got there"
        assert all(len(axes) == 1 for axes in way), way
        order = [axes[0] for axes in way]
        assert order == sorted(order, key="ZXA".index), order
        assert 2 <= len(way) <= 3, way  # the start stands off home on the radius and the turn
    finally:
        winder.close()
