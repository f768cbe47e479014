"""The motion gate: nothing leaves the station that would move a machine past its travel.

Each entry point (absolute, relative, jog) on each dialect, against the
emulated machines; the property tests put the machine anywhere and ask for
anything, and read what went out on the wire.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pytestqt.qtbot import QtBot

from app.jobs.loaders import load_job
from app.jobs.run.runner import JobRunner, JobState
from app.machine import MachineModel
from app.machines.motion_gate import EPSILON, MotionGate
from app.profiles import load_profile
from protocol.gcode.codec import JOG_CANCEL
from protocol.stage.codec import CommandFrame, CommandId, decode
from tests.helpers.harness import StationHarness

FINITE = st.floats(min_value=-1e4, max_value=1e4, allow_nan=False)


def _harness(name: str) -> StationHarness:
    harness = StationHarness(load_profile(name))
    harness.connect()
    harness.run(0.5)
    return harness


@pytest.fixture
def stage(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = _harness("xy-stage")
    harness.run(2.5)  # the connect-time parameter reads
    yield harness
    harness.close()


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = _harness("grbl-plotter")
    yield harness
    harness.close()


def _stage_frames(harness: StationHarness, start: int) -> list[CommandFrame]:
    frames = []
    for raw in harness.written[start:]:
        _, frame = decode(raw)
        assert isinstance(frame, CommandFrame), raw
        frames.append(frame)
    return frames


def _lines(harness: StationHarness, start: int = 0) -> list[str]:
    return [c.decode("ascii", "replace").strip() for c in harness.written[start:]]


# --- the gate alone -----------------------------------------------------------------------


@settings(
    max_examples=300,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(position=FINITE, delta=FINITE, target=FINITE)
def test_the_gate_refuses_exactly_what_leaves_the_travel(
    qtbot: QtBot, position: float, delta: float, target: float
) -> None:
    model = MachineModel(load_profile("xy-stage"))
    gate = MotionGate(model)
    model.update_axis(0, position=position)
    # Past an end by less than EPSILON is rounding (a move to exactly the end), not a refusal.
    inside = -EPSILON <= target <= 50 + EPSILON
    assert (gate.refuse_target(0, target) is None) == inside
    assert (gate.refuse_relative(0, delta) is None) == (
        -EPSILON <= position + delta <= 50 + EPSILON
    )
    assert 0 <= gate.clamp(0, target) <= 50
    assert gate.room(0, +1) == max(0.0, 50 - position)
    assert gate.refuse_target(0, float("nan")) is not None


def test_a_rotary_axis_turns_freely() -> None:
    model = MachineModel(load_profile("string-art"))
    gate = MotionGate(model)
    assert gate.refuse_target(0, 7200.0) is None
    assert gate.refuse_target(1, 251.0) is not None


# --- the stage ----------------------------------------------------------------------------


def test_stage_relative_move_past_the_travel_is_refused_and_nothing_sent(
    stage: StationHarness,
) -> None:
    stage.session.move_absolute(0, 13.0)
    stage.run_until(lambda: abs(stage.station.model.axes[0].position - 13.0) < 1e-3, timeout=5)
    messages: list[str] = []
    stage.station.model.message.connect(messages.append)
    start = len(stage.written)
    assert not stage.session.move_relative(0, 45.0)
    stage.run(0.3)
    frames = _stage_frames(stage, start)
    assert frames  # the stage kept being talked to: just not told to move
    sent = [p.command for f in frames for p in f.packets]
    assert CommandId.MOVE_REL not in sent and CommandId.MOVE_ABS not in sent
    assert any("outside the travel 0…50 mm" in m for m in messages)
    assert stage.session.move_relative(0, 37.0)  # to exactly the end is allowed


def test_a_lost_key_release_ends_the_stage_jog_before_its_end_switch(
    stage: StationHarness,
) -> None:
    """The release never comes while the key's repeats keep arriving: the travel bounds it."""
    stage.session.move_absolute(0, 30.0)
    stage.run_until(lambda: abs(stage.station.model.axes[0].position - 30.0) < 1e-3, timeout=5)
    stage.session.set_jog((1, 0))
    for _ in range(80):  # 8 s held, more than enough to reach the end at 10 mm/s
        stage.hold(0.1)
        assert not stage.emulator.axes[0].end_switch_high
    axis = stage.emulator.axes[0]
    assert not axis.moving
    assert 49.0 < axis.position_um / 1000 < 50.0  # stopped just inside the travel, braked
    stage.session.set_jog((0, 0))
    stage.run(0.5)
    assert not stage.emulator.axes[0].end_switch_high


def test_a_held_jog_with_no_sign_of_life_ends_within_the_dead_man_time(
    stage: StationHarness,
) -> None:
    ended: list[str] = []
    stage.session.jogEnded.connect(ended.append)
    stage.session.set_jog((1, 0))
    stage.run(0.9)
    assert stage.session.jog_vector == (1, 0) and not ended
    stage.run(0.3)  # past JOG_DEADMAN_S without a key repeat
    assert stage.session.jog_vector == (0, 0)
    assert ended and "still held" in ended[0]
    stage.run_until(lambda: not stage.emulator.axes[0].moving, timeout=2)
    assert stage.emulator.axes[0].position_um / 1000 < 15


# --- GRBL ---------------------------------------------------------------------------------


def test_grbl_jogs_with_dollar_j_cancels_on_release_and_keeps_g90(grbl: StationHarness) -> None:
    session = grbl.gcode_session
    start = len(grbl.written)
    session.set_jog((1, 0))
    grbl.hold(1.0)
    session.set_jog((0, 0))
    assert JOG_CANCEL in grbl.written[-3:] or JOG_CANCEL in b"".join(grbl.written[-3:])
    released_at = grbl.gcode_emulator.position()["X"]
    grbl.run_until(lambda: grbl.gcode_emulator.state == "Idle", timeout=2)
    stopped = grbl.gcode_emulator.position()["X"]
    assert 0 < released_at <= stopped < released_at + 5  # braked, not run on for seconds
    jog_lines = [line for line in _lines(grbl, start) if line.startswith("$J=")]
    assert jog_lines and all(line.startswith("$J=G91 G21 X") for line in jog_lines)
    assert not any(line.startswith(("G91", "G90 G91")) for line in _lines(grbl))
    session.send_line("$G", "console")
    grbl.run(0.2)
    assert "G90" in grbl.gcode_emulator._interpreter.modes()


def test_a_jog_step_still_on_its_way_at_the_release_is_cancelled_too(
    grbl: StationHarness,
) -> None:
    """G7-01: GRBL reads a jog line that came behind the 0x85 afterwards and runs it."""
    session = grbl.gcode_session
    session.set_jog((1, 0))
    session.set_jog((0, 0))  # at once: the step is on the wire, not yet answered
    grbl.run_until(lambda: session.settled and grbl.gcode_emulator.state == "Idle", timeout=2)
    stopped = grbl.gcode_emulator.position()["X"]
    assert 0 < stopped < 2.5  # braked early in the 5 mm step, not run to its end
    assert b"".join(grbl.written).count(JOG_CANCEL) >= 1


def test_grbl_jog_ends_at_the_travel_end(grbl: StationHarness) -> None:
    session = grbl.gcode_session
    assert session.move_absolute(0, 297.0)
    grbl.run_until(lambda: grbl.gcode_emulator.state == "Idle" and session.settled, timeout=10)
    session.set_jog((1, 0))
    grbl.hold(2.0)
    session.set_jog((0, 0))
    grbl.run(1.0)
    assert grbl.gcode_emulator.position()["X"] == pytest.approx(300.0, abs=1e-3)


@pytest.mark.parametrize("name", ["grbl-plotter", "corexy-plotter"])
def test_a_square_without_g90_after_a_jog_is_drawn_where_the_file_says(
    qtbot: QtBot, tmp_path: Path, name: str
) -> None:
    """The probe of the issue: a tap of → then a 30 mm square with no G90 line."""
    harness = _harness(name)
    try:
        session = harness.gcode_session
        session.set_jog((1, 0))
        harness.run(0.2)
        session.set_jog((0, 0))
        harness.run_until(lambda: session.settled and not session.stopping, timeout=5)
        session.send_line("G91", "console")  # and an operator's console line, for good measure
        harness.run(0.3)
        job = tmp_path / "square.gcode"
        job.write_text("G0 X10 Y10\nG1 X40 Y10 F3000\nG1 X40 Y40\nG1 X10 Y40\nG1 X10 Y10\n")
        program = load_job(job, [a.name for a in harness.station.profile.axes])
        runner = JobRunner(harness.station, tmp_path / "checkpoints")
        assert runner.load(program) == []
        runner.start()
        harness.run_until(lambda: runner.state in (JobState.DONE, JobState.FAILED), timeout=60)
        assert runner.state is JobState.DONE
        harness.run(0.5)
        where = harness.gcode_emulator.position()
        assert (where["X"], where["Y"]) == pytest.approx((10.0, 10.0), abs=1e-3)
    finally:
        harness.close()


def test_a_g92_job_starts_only_where_it_was_checked_from(
    grbl: StationHarness, tmp_path: Path
) -> None:
    session = grbl.gcode_session
    assert session.move_absolute(0, 100.0)
    grbl.run_until(lambda: session.settled, timeout=10)
    job = tmp_path / "here.gcode"
    job.write_text("G92 X0 Y0\nG1 X250 Y10 F3000\nG1 X0 Y0\n")
    program = load_job(job, ["X", "Y", "Z"])
    assert program.start_relative == ("X", "Y")
    runner = JobRunner(grbl.station, tmp_path / "checkpoints")
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(program) == []
    start = len(grbl.written)
    runner.start()
    grbl.run(0.5)
    assert runner.state is JobState.READY
    assert "X100.000" in messages[-1] and "checked from 0" in messages[-1]
    assert not any("X250" in line for line in _lines(grbl, start))
    assert grbl.gcode_emulator.position()["X"] == pytest.approx(100.0)
    # From the origin it runs, and ends where the file says.
    assert session.move_absolute(0, 0.0)
    grbl.run_until(lambda: session.settled, timeout=10)
    runner.start()
    grbl.run_until(lambda: runner.state is JobState.DONE, timeout=60)
    assert grbl.gcode_emulator.position()["X"] == pytest.approx(0.0, abs=1e-3)


@settings(
    max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(start=st.floats(0, 300), delta=FINITE, target=FINITE)
def test_no_gcode_line_from_a_panel_moves_past_the_travel(
    grbl: StationHarness, start: float, delta: float, target: float
) -> None:
    session = grbl.gcode_session
    grbl.station.model.update_axis(0, position=start)
    before = len(grbl.written)
    session.move_relative(0, delta)
    session.move_absolute(0, target)
    for line in _lines(grbl, before):
        if line.startswith("G90 G0 X"):
            assert 0 <= float(line.removeprefix("G90 G0 X")) <= 300
    session.streamer.clear()


# --- usb3 ---------------------------------------------------------------------------------


def test_usb3_relative_move_past_the_travel_is_refused(qtbot: QtBot) -> None:
    harness = _harness("usb3")
    try:
        travel = harness.station.profile.axes[0].travel
        before = len(harness.written)
        assert not harness.usb3_session.move_relative(0, travel + 25.0)
        assert harness.written[before:] == []
        assert harness.usb3_session.move_relative(0, 10.0)
    finally:
        harness.close()


def test_no_jog_while_a_job_owns_the_machine(stage: StationHarness, tmp_path: Path) -> None:
    """A jog under a running (or paused) job would move the machine beneath it."""
    job = tmp_path / "route.csv"
    job.write_text("10, 10\n20, 20\n30, 30\n")
    runner = JobRunner(stage.station, tmp_path / "checkpoints")
    assert runner.load(load_job(job, ["X", "Y"])) == []
    messages: list[str] = []
    stage.station.model.message.connect(messages.append)
    runner.start()
    stage.run(0.2)
    stage.session.set_jog((1, 0))
    assert stage.session.jog_vector == (0, 0)
    assert not stage.session.step_jog(0, +1, 1.0)
    assert any(m.startswith("Jog refused: a job is under way") for m in messages)
    runner.pause()
    stage.run_until(lambda: runner.state is JobState.PAUSED, timeout=10)
    stage.session.set_jog((1, 0))
    assert stage.session.jog_vector == (0, 0)  # paused: it resumes from where the machine is
    runner.abort()
    stage.run(0.2)
    stage.session.set_jog((1, 0))
    assert stage.session.jog_vector == (1, 0)  # the job ended: the machine is the operator's
    stage.session.set_jog((0, 0))


# --- every entry point, any position, any input: nothing past the travel on the wire -----

MOVES = st.sampled_from(["absolute", "relative", "step"])


@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(entry=MOVES, start=st.floats(0, 50), value=FINITE, axis=st.integers(0, 1))
def test_no_stage_frame_moves_past_the_travel(
    stage: StationHarness, entry: str, start: float, value: float, axis: int
) -> None:
    session = stage.session
    stage.station.model.update_axis(axis, position=start)
    before = len(stage.written)
    if entry == "absolute":
        session.move_absolute(axis, value)
    elif entry == "relative":
        session.move_relative(axis, value)
    else:
        session.step_jog(axis, 1 if value >= 0 else -1, min(abs(value), 10.0) or 0.1)
    for frame in _stage_frames(stage, before):
        packet = frame.packets[axis]
        if packet.command == CommandId.MOVE_ABS:
            assert 0 <= packet.data <= 50_000
        elif packet.command == CommandId.MOVE_REL:
            assert -1 <= start * 1000 + packet.data <= 50_001  # µm rounding
    session.stop_all()
    stage.run(0.05)


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = _harness("pcb-drill")
    yield harness
    harness.close()


@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(
    letter=st.sampled_from("XY"),
    microsteps=st.integers(0, 99_999),
    mm=FINITE,
)
def test_no_drill_command_moves_past_the_travel(
    drill: StationHarness, letter: str, microsteps: int, mm: float
) -> None:
    session = drill.drill_session
    axis = "XY".index(letter)
    travel = drill.station.profile.axes[axis].travel
    before = len(drill.written)
    session.send_line(f"{letter}{microsteps}")  # the terminal
    session.move_absolute(axis, mm)  # the Drill page
    for chunk in drill.written[before:]:
        text = chunk.decode("ascii").strip()
        if text[:1] in "XY" and text[1:].isdigit():
            index = "XY".index(text[0])
            assert session.to_mm(index, int(text[1:])) <= travel + 1e-9
    session.stop_all()
