"""Drill jobs home first and park at the end, as the original tool did (FIDELITY S2-26).

The drill cannot say whether it has homed, so the station homes before a job
unless it saw an ``N`` finish on this link; after the last operation it goes
to the profile's park position through the motion gate and, that being where
``P`` parks anyway, sends ``P`` to switch the motors off.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.checkpoint import CheckpointStore
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import ProfileError, load_profile
from protocol.drill.codec import Command
from tests.helpers.harness import StationHarness

WHERE = SourceRef("t.drl", 1)
PARK_Y = round(150 * 19.7)  # the profile's park: X 0, Y 150 mm (2955 microsteps)


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    harness.connect()
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED)
    # The machine homed itself at power-on (FIDELITY S2-19), unseen by the station.
    harness.run_until(lambda: harness.drill_emulator.homed, timeout=10)
    assert not harness.drill_emulator.busy
    yield harness
    harness.close()


def two_holes() -> Program:
    return Program(
        "two",
        (
            Operation(OpKind.WAIT, WHERE, message="insert T01, 0.80 mm, 2 holes"),
            move(WHERE, X=10.0, Y=20.0),
            Operation(OpKind.DRILL, WHERE),
            move(WHERE, X=30.0, Y=5.0),
            Operation(OpKind.DRILL, WHERE),
        ),
    )


def sent_commands(drill: StationHarness) -> list[str]:
    """What the station put on the wire, as the terminal shows it."""
    sent: list[str] = []

    def keep(command: object, _raw: bytes) -> None:
        if isinstance(command, Command):
            sent.append(command.letter + ("" if command.value is None else str(command.value)))

    drill.drill_session.frameSent.connect(keep)
    return sent


def run_to_end(drill: StationHarness, runner: JobRunner) -> None:
    def over() -> bool:
        if runner.state is JobState.WAITING:
            runner.confirm()
        return runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED, JobState.PAUSED)

    drill.run_until(over, timeout=120)


def test_a_job_on_a_link_that_saw_no_homing_homes_first_then_parks_and_switches_off(
    drill: StationHarness, tmp_path: Path
) -> None:
    session = drill.drill_session
    assert session.homes_before_job  # the drill cannot tell; nothing seen on this link
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    notes: list[str] = []
    runner.message.connect(notes.append)
    sent = sent_commands(drill)
    prompted_at: list[int] = []
    runner.waitingForOperator.connect(lambda _message: prompted_at.append(len(sent)))
    assert runner.load(two_holes()) == []
    assert runner.progress.estimate is not None
    eta = runner.progress.estimate.total_s
    runner.start()
    run_to_end(drill, runner)

    assert runner.state is JobState.DONE
    assert sent == ["N", "X198", "Y394", "V", "X594", "Y99", "V", "X0", f"Y{PARK_Y}", "P"]
    assert prompted_at == [1]  # the bit prompt came once the N was done, not before
    assert any("cannot report whether it has homed" in n for n in notes)
    fw = drill.drill_emulator
    assert [h.position for h in fw.drill_log] == [(198, 394), (594, 99)]
    assert fw.positions[:2] == (0, PARK_Y) and not fw.motors_on
    model = drill.station.model
    assert model.axes[0].position == 0.0 and model.axes[1].position == pytest.approx(150.0)
    # Homing and park are in the estimate: the run takes what it said, within 5 %.
    assert runner.progress.running_s == pytest.approx(eta, rel=0.05)

    # The station saw the N: the next job on this link does not home again.
    assert not session.homes_before_job
    sent.clear()
    assert runner.load(two_holes()) == []
    runner.start()
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE and sent[0] == "X198" and "N" not in sent


def test_the_job_is_done_only_once_the_park_is(drill: StationHarness, tmp_path: Path) -> None:
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    states: list[JobState] = []
    runner.stateChanged.connect(states.append)
    assert runner.load(two_holes()) == []
    runner.start()

    def last_hole_drilled() -> bool:
        if runner.state is JobState.WAITING:
            runner.confirm()
        return runner.done == len(two_holes())

    drill.run_until(last_hole_drilled, timeout=60)
    assert runner.state is JobState.RUNNING  # parking still
    assert drill.drill_emulator.positions[:2] == (594, 99)
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE and states[-1] is JobState.DONE
    assert drill.drill_emulator.positions[:2] == (0, PARK_Y)


def test_a_resume_on_a_new_link_with_the_pen_down_lifts_it_homes_and_comes_back(
    drill: StationHarness, tmp_path: Path
) -> None:
    """Homing with the pen down would draw a line to the switches: up, N, back, down."""
    program = Program(
        "stroke",
        (
            move(WHERE, X=10.0, Y=10.0),
            Operation(OpKind.PEN_DOWN, WHERE),
            move(WHERE, X=20.0),
            Operation(OpKind.PEN_UP, WHERE),
        ),
    )
    checkpoints = tmp_path / "checkpoints"
    CheckpointStore(checkpoints).write(program, 1)  # the pen went down, then the station died
    runner = JobRunner(drill.station, checkpoints)
    sent = sent_commands(drill)
    assert runner.load(program) == [] and runner.resume_available == 2
    runner.resume_from_checkpoint()
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE
    assert sent[:6] == ["Z", "N", "X198", "Y197", "K", "X396"]
    fw = drill.drill_emulator
    downs = [(e.x, e.y) for e in fw.pen_log if e.down]
    assert downs == [(198, 197)]  # down again where it was, not at the switches


@pytest.mark.parametrize(
    ("park", "reason"),
    [
        ("X = 0.0\nY = 151.0", "outside the travel"),
        ("Z = 1.0", "no axis"),
        ("X = 'back'", "must be a number"),
    ],
)
def test_a_park_position_off_the_machine_is_refused_when_the_profile_is_read(
    tmp_path: Path, park: str, reason: str
) -> None:
    shipped = load_profile("pcb-drill").source
    assert shipped is not None
    text = shipped.read_text(encoding="utf-8").split("[park]")[0] + "[park]\n" + park + "\n"
    path = tmp_path / "drill.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ProfileError, match=reason):
        load_profile(path)


def test_the_shipped_drill_parks_where_the_originals_p_does() -> None:
    profile = load_profile("pcb-drill")
    assert profile.park is not None and dict(profile.park) == {"X": 0.0, "Y": 150.0}
    assert load_profile("xy-stage").park is None


def test_a_pause_while_homing_before_the_first_prompt_holds_the_prompt_until_resumed(
    drill: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    prompts: list[str] = []
    runner.waitingForOperator.connect(prompts.append)
    assert runner.load(two_holes()) == []
    runner.start()
    assert drill.drill_session.busy  # homing
    runner.pause()
    assert runner.state is JobState.PAUSING
    drill.run_until(lambda: runner.state is JobState.PAUSED, timeout=10)
    assert prompts == [] and drill.drill_emulator.homed and not drill.drill_session.busy
    runner.resume()
    assert runner.state is JobState.WAITING and prompts == ["insert T01, 0.80 mm, 2 holes"]
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE
    assert [h.position for h in drill.drill_emulator.drill_log] == [(198, 394), (594, 99)]


def test_a_link_cut_while_parking_parks_again_on_resume_and_then_ends(
    drill: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    assert runner.load(two_holes()) == []
    runner.start()

    def parking() -> bool:
        if runner.state is JobState.WAITING:
            runner.confirm()
        return runner.done == len(two_holes()) and drill.drill_emulator.busy

    drill.run_until(parking, timeout=60)
    drill.loopback.sever("cable pulled")
    drill.run_until(lambda: runner.state is JobState.PAUSED, timeout=10)
    assert runner.done == len(two_holes())  # every hole counted; only the park is left
    drill.loopback.set_manipulator(None)
    drill.run_until(lambda: drill.station.model.link_state is LinkState.CONNECTED, timeout=60)
    sent = sent_commands(drill)
    runner.resume()
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE
    assert sent == ["X0", f"Y{PARK_Y}", "P"]  # no homing for a park: absolute moves
    assert drill.drill_emulator.positions[:2] == (0, PARK_Y)
    assert len(drill.drill_emulator.drill_log) == 2
