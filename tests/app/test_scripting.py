"""The scripting API (``stepdeck``) against the in-process emulator on a simulated clock.

Each test drives the real station, sessions and emulator; the simulated
clock only makes time run as fast as the computer, so moves, jogs, writes
and jobs behave as they do in real time.
"""

from __future__ import annotations

import asyncio
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

import stepdeck
from app.scripting.machine import Machine
from protocol.stage.codec import StageDecoder
from tests.conftest import ROOT


@pytest.fixture
def stage(qapp: object) -> Iterator[Machine]:
    machine = stepdeck.connect("xy-stage", emulator=True, simulated=True)
    yield machine
    machine.close()


@pytest.fixture
def usb3(qapp: object) -> Iterator[Machine]:
    machine = stepdeck.connect("usb3", emulator=True, simulated=True)
    yield machine
    machine.close()


def emulated_position(machine: Machine) -> tuple[float, ...]:
    emulator = machine.station.stage_emulator
    assert emulator is not None
    return tuple(axis.position_um / 1000 for axis in emulator.axes)


def sent_commands(machine: Machine) -> list[int]:
    """The command IDs the station put on the wire since the list was started."""
    return machine.sent  # type: ignore[attr-defined,no-any-return]


def record_commands(machine: Machine) -> None:
    decoder = StageDecoder(len(machine.axes))
    sent: list[int] = []
    machine.sent = sent  # type: ignore[attr-defined]

    def frames(raw: bytes) -> None:
        for frame in decoder.feed(raw):
            packets = getattr(frame, "packets", ())
            sent.extend(int(p.command) for p in packets if int(p.command))

    assert machine.station.link is not None
    machine.station.link.dataSent.connect(frames)


# --- motion ----------------------------------------------------------------------------


def test_moves_end_where_asked_and_the_device_agrees(stage: Machine) -> None:
    assert stage.status.link == "connected"
    assert stage.move_to(X=10, Y=5) == pytest.approx({"X": 10.0, "Y": 5.0}, abs=0.002)
    assert stage.move_by({"x": -2.5}) == pytest.approx({"X": 7.5, "Y": 5.0}, abs=0.002)
    assert emulated_position(stage)[:2] == pytest.approx((7.5, 5.0), abs=0.002)
    assert not stage.status.moving


def test_a_move_outside_the_travel_is_refused_by_the_gate_and_moves_nothing(
    stage: Machine,
) -> None:
    stage.move_to(X=5, Y=5)
    with pytest.raises(stepdeck.MotionRefused, match=r"outside the travel 0…50 mm"):
        stage.move_to(Y=20, X=60)  # Y alone would be fine: nothing at all is sent
    with pytest.raises(stepdeck.MotionRefused, match=r"from 5\.000"):
        stage.move_by(X=-6)
    with pytest.raises(stepdeck.MotionRefused, match="no axis 'Q'"):
        stage.move_to(Q=1)
    stage.move_by(X=0.5)  # the machine is still usable, and stood where it was
    assert emulated_position(stage)[:2] == pytest.approx((5.5, 5.0), abs=0.002)


def test_a_jog_ends_inside_the_travel_and_the_call_returns_once_still(stage: Machine) -> None:
    stage.move_to(X=45)
    end = stage.jog("+X", 5.0)
    assert 45 < end["X"] < 50
    assert emulated_position(stage)[0] < 50
    with pytest.raises(stepdeck.MotionRefused, match="not a direction"):
        stage.jog("sideways!", 1.0)


def test_home_returns_the_axis_to_its_origin(stage: Machine) -> None:
    stage.move_to(X=12)
    assert stage.home("X")["X"] == pytest.approx(0.0, abs=0.002)


def test_a_move_that_runs_out_of_time_stops_the_machine(stage: Machine) -> None:
    with pytest.raises(stepdeck.MotionTimeout, match=r"not done within 0\.2 s; stopped"):
        stage.move_to(X=40, timeout=0.2)
    assert stage.stop()
    here = emulated_position(stage)[0]
    assert 0 < here < 40
    assert stage.position["X"] == pytest.approx(here, abs=0.002)


def test_a_sleeping_stage_refuses_motion_until_woken(stage: Machine) -> None:
    stage.sleep()
    with pytest.raises(stepdeck.MotionRefused, match="sleeping"):
        stage.move_to(X=3)
    stage.wake()
    assert stage.move_to(X=3)["X"] == pytest.approx(3.0, abs=0.002)


def test_the_usb3_unit_is_moved_by_distances_and_has_no_sleep(usb3: Machine) -> None:
    assert usb3.move_to(X=3, Y=2)["X"] == pytest.approx(3.0, abs=0.01)
    assert usb3.move_by(X=-1)["X"] == pytest.approx(2.0, abs=0.01)
    with pytest.raises(stepdeck.Unsupported, match="has no sleep"):
        usb3.sleep()
    with pytest.raises(stepdeck.Unsupported):
        usb3.read_parameters()


def test_connect_names_exactly_one_link(qapp: object) -> None:
    with pytest.raises(stepdeck.ConnectionFailed, match="exactly one"):
        stepdeck.connect("xy-stage")
    with pytest.raises(stepdeck.ConnectionFailed, match="exactly one"):
        stepdeck.connect("xy-stage", emulator=True, port="/dev/null")
    with pytest.raises(stepdeck.ConnectionFailed, match="no-such"):
        stepdeck.connect("no-such-machine", emulator=True)


# --- parameters and snapshots ----------------------------------------------------------


def test_writes_are_verified_refusals_carry_the_device_reason_and_undo_restores(
    stage: Machine,
) -> None:
    before = stage.read_parameters()
    assert before["X"]["fast_speed"] == 10.0
    assert stage.write_parameters({"X": {"fast_speed": 12.5}}) == {"X": {"fast_speed": 12.5}}
    with pytest.raises(stepdeck.ParameterRefused) as refused:
        stage.write_parameters({"X": {"irun": 40, "slow_speed": 3}, "Y": {"travel": 80}})
    text = str(refused.value)
    assert "device refused 40 and keeps 16" in text
    assert "mechanical travel" in text  # the station's own check: the device cannot know
    now = stage.read_parameters()
    assert now["X"]["irun"] == 16 and now["X"]["slow_speed"] == 3.0
    assert now["Y"]["travel"] == 50.0
    stage.undo_last_write()  # the last write that went through: slow_speed
    assert stage.read_parameters()["X"]["slow_speed"] == 2.0
    with pytest.raises(stepdeck.StepdeckError, match="no parameter write to undo"):
        stage.undo_last_write()


def test_a_snapshot_restores_only_what_differs(stage: Machine, tmp_path: Path) -> None:
    snapshot = stage.save_parameters(tmp_path / "stage.toml")
    text = snapshot.read_text(encoding="utf-8")
    assert 'profile = "xy-stage"' in text and 'firmware = "1.2.0"' in text and "date = " in text
    assert "encoder" not in text  # a position, not a setting
    stage.write_parameters({"Y": {"acceleration": 30, "ihold": 4}})
    diff = stage.parameter_diff(snapshot)
    assert [str(d) for d in diff] == [
        "Y Acceleration: 30 → 20 mm/s²",
        "Y Hold current (IHOLD): 4 → 8",
    ]
    record_commands(stage)
    written = stage.load_parameters(snapshot)
    assert [(d.axis, d.name) for d in written] == [("Y", "acceleration"), ("Y", "ihold")]
    writes = [c for c in sent_commands(stage) if 0x10 <= c <= 0x19]
    assert len(writes) == 2  # only what differed went out
    assert stage.parameter_diff(snapshot) == []
    stage.undo_last_write()
    assert len(stage.parameter_diff(snapshot)) == 2


def test_another_machines_snapshot_is_refused_unless_confirmed(
    stage: Machine, tmp_path: Path
) -> None:
    snapshot = stage.save_parameters(tmp_path / "stage.toml")
    other = tmp_path / "other.toml"
    text = snapshot.read_text(encoding="utf-8").replace('"xy-stage"', '"xy-stage-2"')
    other.write_text(text.replace("fast_speed = 10.0", "fast_speed = 9.0", 1), encoding="utf-8")
    with pytest.raises(stepdeck.WrongMachine, match="other_machine=True"):
        stage.load_parameters(other)
    assert stage.read_parameters()["X"]["fast_speed"] == 10.0
    assert [d.name for d in stage.load_parameters(other, other_machine=True)] == ["fast_speed"]
    assert stage.read_parameters()["X"]["fast_speed"] == 9.0


def test_a_file_that_is_no_snapshot_is_refused_with_the_reason(
    stage: Machine, tmp_path: Path
) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text('format = 1\n[machine]\nprofile = "xy-stage"\n[axes.X]\nfast_speed = "x"\n')
    with pytest.raises(stepdeck.StepdeckError, match="is not a number"):
        stage.load_parameters(bad)
    bad.write_text("not toml [")
    with pytest.raises(stepdeck.StepdeckError, match="not a readable snapshot"):
        stage.parameter_diff(bad)


# --- jobs -------------------------------------------------------------------------------


ROUTE = "1, 1\n5, 1\nwait: turn the sample\n5, 5\n1, 5\n2, 2\n"


def test_a_job_runs_to_its_end_with_progress_and_the_operator_prompt(
    stage: Machine, tmp_path: Path
) -> None:
    job = tmp_path / "route.txt"
    job.write_text(ROUTE, encoding="utf-8")
    seen: list[int] = []
    prompts: list[str] = []

    def prompt(text: str) -> bool:
        prompts.append(text)
        return True

    result = stage.run(
        job,
        on_progress=lambda p: seen.append(p.done),
        on_prompt=prompt,
        checkpoint_dir=tmp_path / "ck",
    )
    assert result.operations == 6 and result.resumed_from is None
    assert prompts == ["turn the sample"]
    assert seen == sorted(seen) and seen[-1] == 6
    assert stage.position == pytest.approx({"X": 2.0, "Y": 2.0}, abs=0.002)


def test_an_aborted_job_keeps_its_checkpoint_and_resumes_after_what_was_done(
    stage: Machine, tmp_path: Path
) -> None:
    job = tmp_path / "route.txt"
    job.write_text(ROUTE, encoding="utf-8")
    checkpoints = tmp_path / "ck"

    def abort_after_two(progress: stepdeck.Progress) -> None:
        if progress.done >= 2:
            progress.abort()

    with pytest.raises(stepdeck.JobAborted) as aborted:
        stage.run(job, on_progress=abort_after_two, checkpoint_dir=checkpoints)
    assert (aborted.value.done, aborted.value.total) == (2, 6)
    assert list(checkpoints.glob("*.json"))
    with pytest.raises(stepdeck.CheckpointWaiting, match="2 of 6"):
        stage.run(job, checkpoint_dir=checkpoints)
    result = stage.run(job, on_prompt=lambda _: True, resume=True, checkpoint_dir=checkpoints)
    assert result.resumed_from == 2
    assert not list(checkpoints.glob("*.json"))


def test_a_prompt_nobody_answers_aborts_the_job(stage: Machine, tmp_path: Path) -> None:
    job = tmp_path / "route.txt"
    job.write_text(ROUTE, encoding="utf-8")
    with pytest.raises(stepdeck.JobAborted, match="no one answered"):
        stage.run(job, checkpoint_dir=tmp_path / "ck")
    assert not stage.status.moving


def test_a_job_leaving_the_travel_is_refused_with_its_line(stage: Machine, tmp_path: Path) -> None:
    job = tmp_path / "far.txt"
    job.write_text("1, 1\n80, 1\n", encoding="utf-8")
    with pytest.raises(stepdeck.JobRefused, match=r"far.txt:2"):
        stage.run(job, checkpoint_dir=tmp_path / "ck")
    assert stage.position == pytest.approx({"X": 0.0, "Y": 0.0}, abs=0.002)


# --- asyncio ----------------------------------------------------------------------------


def test_the_asyncio_form_moves_while_other_tasks_run(qapp: object, tmp_path: Path) -> None:
    async def scenario() -> tuple[dict[str, float], int]:
        machine = await stepdeck.aio.connect("xy-stage", emulator=True, simulated=True)
        beats = 0

        async def heartbeat() -> None:
            nonlocal beats
            while True:
                beats += 1
                await asyncio.sleep(0)

        task = asyncio.create_task(heartbeat())
        try:
            where = await machine.move_to(X=8, Y=3)
            with pytest.raises(stepdeck.MotionRefused):
                await machine.move_by(Y=-4)
        finally:
            task.cancel()
            machine.close()
        return where, beats

    where, beats = asyncio.run(scenario())
    assert where == pytest.approx({"X": 8.0, "Y": 3.0}, abs=0.002)
    assert beats > 10  # the loop ran other tasks while the machine moved


# --- packaging ------------------------------------------------------------------------


def test_stepdeck_imports_without_a_display_and_without_widgets() -> None:
    code = (
        "import sys, stepdeck\n"
        "bad = [m for m in sys.modules if m.startswith(('widgets', 'PySide6.QtWidgets',"
        " 'PySide6.QtGui', 'pyqtgraph'))]\n"
        "print(bad)\n"
    )
    env = {"PATH": "/usr/bin:/bin"}
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"


# --- the other machines ----------------------------------------------------------------


DRILL_FILE = "M48\nMETRIC,TZ\nT01C0.8\n%\nT01\nX5.0Y5.0\nX10.0Y5.0\nX10.0Y12.0\nM30\n"


def test_the_drill_moves_in_whole_microsteps_and_runs_a_drill_file(
    qapp: object, tmp_path: Path
) -> None:
    job = tmp_path / "holes.drl"
    job.write_text(DRILL_FILE, encoding="utf-8")
    with stepdeck.connect("pcb-drill", emulator=True, simulated=True) as drill:
        where = drill.move_to(X=10, Y=5)  # 19.7 microsteps to the mm: Y ends at 5.025
        assert where["X"] == pytest.approx(10.0, abs=0.06)
        assert where["Y"] == pytest.approx(5.0, abs=0.06)
        assert drill.home() == pytest.approx({"X": 0.0, "Y": 0.0})
        done: list[int] = []
        asked: list[str] = []
        result = drill.run(
            job,
            on_progress=lambda p: done.append(p.done),
            on_prompt=lambda text: asked.append(text) is None,
            checkpoint_dir=tmp_path / "ck",
        )
    assert result.operations == 7  # pen/tool operations around the three holes
    assert done == sorted(done) and done[-1] == 7
    assert asked == ["insert T01, 0.80 mm, 3 holes"]


def test_a_gcode_board_moves_through_the_gate_and_homes(qapp: object) -> None:
    with stepdeck.connect("grbl-plotter", emulator=True, simulated=True) as plotter:
        assert plotter.move_to(X=10, Y=5) == pytest.approx({"X": 10.0, "Y": 5.0}, abs=0.01)
        with pytest.raises(stepdeck.MotionRefused, match="outside the travel"):
            plotter.move_by(X=-20)
        assert plotter.home() == pytest.approx({"X": 0.0, "Y": 0.0}, abs=0.01)
        with pytest.raises(stepdeck.Unsupported, match="has no sleep"):
            plotter.sleep()


def test_a_job_paused_from_the_progress_callback_waits_until_resumed(
    stage: Machine, tmp_path: Path
) -> None:
    job = tmp_path / "route.txt"
    job.write_text("1, 1\n5, 1\n5, 5\n1, 5\n", encoding="utf-8")
    states: list[tuple[int, str]] = []

    def progress(p: stepdeck.Progress) -> None:
        states.append((p.done, p.state))
        if p.done == 2 and p.state == "running":
            p.pause()
        elif p.state == "paused" and sum(s == "paused" for _, s in states) == 3:
            p.resume()

    result = stage.run(job, on_progress=progress, checkpoint_dir=tmp_path / "ck")
    assert result.operations == 4
    paused = [done for done, state in states if state == "paused"]
    # The operation under way when the pause was asked finished; nothing ran while paused.
    assert paused == [3, 3, 3]
    assert states[-1] == (4, "done")


def test_an_error_in_a_callback_stops_the_job_and_reaches_the_script(
    stage: Machine, tmp_path: Path
) -> None:
    job = tmp_path / "route.txt"
    job.write_text("1, 1\n30, 1\n30, 30\n", encoding="utf-8")

    def progress(p: stepdeck.Progress) -> None:
        if p.done == 1:
            raise RuntimeError("the camera is gone")

    with pytest.raises(RuntimeError, match="camera"):
        stage.run(job, on_progress=progress, checkpoint_dir=tmp_path / "ck")
    assert not stage.status.moving
    with pytest.raises(stepdeck.CheckpointWaiting):  # the checkpoint was kept
        stage.run(job, checkpoint_dir=tmp_path / "ck")


def test_cancelling_an_awaited_move_stops_the_machine(qapp: object) -> None:
    async def scenario() -> tuple[float, bool]:
        machine = await stepdeck.aio.connect("xy-stage", emulator=True, simulated=True)
        try:
            task = asyncio.create_task(machine.move_to(X=40))
            while not machine.status.moving:
                await asyncio.sleep(0)
            task.cancel()
            with pytest.raises(asyncio.CancelledError):
                await task
            for _ in range(1000):  # five emulated seconds: 40 mm at 10 mm/s would be reached
                machine.machine._pump.step()
            return machine.position["X"], machine.status.moving
        finally:
            machine.close()

    where, moving = asyncio.run(scenario())
    assert not moving
    assert 0 < where < 40


def test_an_alarm_mid_job_is_said_once_and_fails_the_job_with_progress_saying_so(
    qapp: object, tmp_path: Path
) -> None:
    """Real GRBL after a reset in motion: ALARM:3, its banner, and no line taken until
    unlocked.  The API once resumed into it ~30 times a second (271 messages in 15 s),
    its progress saying "running", the job never ending."""
    plotter = stepdeck.connect("grbl-plotter", emulator=True, simulated=True)
    try:
        job = tmp_path / "zigzag.gcode"
        job.write_text(
            "G21 G90\nM3 S1000\n"
            + "".join(f"G1 X{40 * (k % 2)} Y{k} F3000\n" for k in range(1, 30))
            + "M5\n",
            encoding="utf-8",
        )
        emulator = plotter.station.gcode_emulator
        assert emulator is not None
        said: list[str] = []
        states: list[str] = []

        def progress(p: stepdeck.Progress) -> None:
            states.append(p.state)
            if p.done >= 6 and "reset" not in states:
                states.append("reset")
                emulator.soft_reset()  # its reset button in mid-motion
                emulator.trigger_alarm(3)

        with pytest.raises(stepdeck.JobFailed) as failed:
            plotter.run(
                job, on_progress=progress, on_message=said.append, checkpoint_dir=tmp_path / "ck"
            )
        about_it = [m for m in said if "restarted" in m or "alarm" in m]
        assert len(about_it) == 1, said  # said once
        assert "restarted" in str(failed.value)
        assert states[-1] == "failed"  # the progress says how the job stands
        # Nothing was streamed into the alarm: the board refused no line.
        assert plotter.station.gcode_session is not None
        assert plotter.station.gcode_session.errors == 0
    finally:
        plotter.close()


def test_a_resume_line_only_the_operator_can_pick_is_asked_of_on_decision(
    qapp: object, tmp_path: Path
) -> None:
    """The board reset mid-stroke while the cable was out (its banner lost): where it stands
    proves nothing, and a stroke is among the lines not proven run.  The script answers
    for the operator: True resumes from the first line not proven run."""
    plotter = stepdeck.connect("grbl-plotter", emulator=True, simulated=True)
    try:
        job = tmp_path / "zigzag.gcode"
        job.write_text(
            "G21 G90\nM3 S1000\n"
            + "".join(f"G1 X{40 * (k % 2)} Y{k} F3000\n" for k in range(1, 20))
            + "M5\n",
            encoding="utf-8",
        )
        station = plotter.station
        emulator = station.gcode_emulator
        assert emulator is not None and station.loopback is not None
        loopback = station.loopback
        asked: list[tuple[str, str, str]] = []
        cut: list[bool] = []

        def progress(p: stepdeck.Progress) -> None:
            if p.done >= 4 and emulator.state == "Run" and not cut:
                cut.append(True)
                loopback.sever("cable pulled")
                emulator.soft_reset()  # mid-stroke; its banner goes nowhere

        def decide(question: str, again: str, done: str) -> bool:
            asked.append((question, again, done))
            return True

        result = plotter.run(
            job, on_progress=progress, on_decision=decide, checkpoint_dir=tmp_path / "ck"
        )
        assert result.operations == 22
        assert len(asked) == 1, asked
        assert "not proven" in asked[0][0] and "first not proven" in asked[0][1]
        drawn = [
            (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
            for e in emulator.event_log
            if e["event"] == "move" and e["pen"]
        ]
        for k in range(1, 20):  # none skipped
            assert (40.0 * (k % 2), float(k)) in drawn
    finally:
        plotter.close()
