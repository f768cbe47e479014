"""Jobs dock: opening, refusals, Run / Pause / Resume / Step / Abort, ETA, WAIT, resume offer."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFileDialog
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JOB_LOADERS, load_job, sniff_point_list
from app.jobs.program import JobFileError, OpKind
from app.jobs.registration import Registration
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.dock import JobsDock
from widgets.jobs.registration_bar import reference_holes
from widgets.jobs.run_controls import clock_text

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def runner(harness: StationHarness, tmp_path: Path) -> Iterator[JobRunner]:
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    yield runner
    runner.deleteLater()


@pytest.fixture
def dock(qtbot: QtBot, harness: StationHarness, runner: JobRunner) -> Iterator[JobsDock]:
    dock = JobsDock(harness.station, runner, confirm=lambda _text: False, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.resize(820, 640)
    dock.show()
    yield dock


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def square(tmp_path: Path, name: str = "square.csv", extra: str = "") -> Path:
    """Twelve stops round a square, 5 mm apart, after a comment: 13 operations."""
    points = [(5 + 5 * k, 5) for k in range(4)] + [(20, 5 + 5 * k) for k in range(1, 4)]
    points += [(20 - 5 * k, 20) for k in range(1, 4)] + [(5, 15), (5, 10)]
    lines = ["# a square of stops"] + [f"{x}, {y}" for x, y in points]
    return write(tmp_path, name, "\n".join(lines) + "\n" + extra)


def buttons(dock: JobsDock) -> dict[str, bool]:
    return {
        "run": dock.run_button.isEnabled(),
        "pause": dock.pause_button.isEnabled(),
        "resume": dock.resume_button.isEnabled(),
        "step": dock.step_button.isEnabled(),
        "abort": dock.abort_button.isEnabled(),
    }


def messages(dock: JobsDock) -> str:
    return dock.messages.toPlainText()


def connected(harness: StationHarness) -> None:
    harness.connect()
    harness.run(1.0)


def test_loader_registry_chooses_by_extension_then_content(tmp_path: Path) -> None:
    assert {".csv", ".txt"} <= set(JOB_LOADERS)
    odd = write(tmp_path, "route.points", "1, 2\n3; 4\n")
    program = load_job(odd, ["X", "Y"])
    assert [dict(op.target) for op in program] == [{"X": 1, "Y": 2}, {"X": 3, "Y": 4}]
    three = write(tmp_path, "xyz.csv", "1, 2\n")
    assert dict(load_job(three, ["X", "Y", "Z"])[0].target) == {"X": 1, "Y": 2}
    assert not sniff_point_list("M48\nMETRIC\nT01C0.8\n%\n")
    with pytest.raises(JobFileError, match=r"unknown\.bin:0: .*unknown type"):
        load_job(write(tmp_path, "unknown.bin", "M48\n%\n"), ["X", "Y"])


def test_opening_a_point_list_shows_it_and_enables_run(
    harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    connected(harness)
    assert not any(buttons(dock).values())
    assert dock.open_path(square(tmp_path))
    assert dock.runner.state is JobState.READY
    assert dock.preview.program is dock.runner.program
    assert "square" in dock.file_label.text() and "13 operations" in dock.file_label.text()
    assert len(dock.preview.work_markers.getData()[0]) == 12  # every stop, as a marker
    assert buttons(dock) == {
        "run": True,
        "pause": False,
        "resume": False,
        "step": True,
        "abort": False,
    }
    assert dock.progress.maximum() == 13 and dock.progress.value() == 0
    assert dock.eta_label.text() != "left --:--"  # the dry run's estimate


def test_run_waits_for_a_link(harness: StationHarness, dock: JobsDock, tmp_path: Path) -> None:
    assert dock.open_path(square(tmp_path))
    assert not dock.run_button.isEnabled() and "not connected" in dock.run_button.toolTip()
    connected(harness)
    assert dock.run_button.isEnabled()


def test_open_button_uses_the_file_dialog(
    qtbot: QtBot, dock: JobsDock, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = square(tmp_path)
    asked: list[str] = []

    def fake_dialog(*args: object) -> tuple[str, str]:
        asked.append(str(args[-1]))
        return str(path), ""

    monkeypatch.setattr(QFileDialog, "getOpenFileName", fake_dialog)
    qtbot.mouseClick(dock.open_button, LEFT)
    assert "*.csv" in asked[0]
    # Read on a worker thread: the bar is busy and Open is off until it arrives.
    assert dock.progress.maximum() == 0 and not dock.open_button.isEnabled()
    qtbot.waitUntil(lambda: dock.runner.program is not None)
    assert dock.runner.program is not None and dock.runner.program.name == "square"
    assert dock.progress.maximum() > 0 and dock.open_button.isEnabled()


def test_a_malformed_file_names_its_line_and_loads_nothing(dock: JobsDock, tmp_path: Path) -> None:
    bad = write(tmp_path, "bad.csv", "1, 2\n3, 4\n5, five\n")
    assert not dock.open_path(bad)
    assert "bad.csv:3: not a number" in messages(dock)
    assert dock.runner.program is None and dock.runner.state is JobState.IDLE
    assert dock.preview.program is None and not dock.run_button.isEnabled()
    # A good job stays loaded when the next file is broken.
    assert dock.open_path(square(tmp_path))
    assert not dock.open_path(bad)
    assert dock.runner.program is not None and dock.runner.program.name == "square"


def test_a_program_outside_the_travel_is_refused_naming_the_line(
    harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    connected(harness)
    far = write(tmp_path, "far.csv", "10, 10\n20, 20\n# too far\n60, 5\n30, -1\n")
    assert not dock.open_path(far)
    text = messages(dock)
    assert "far.csv:4" in text and "X 60 is outside 0…50" in text
    assert "far.csv:5" in text and "Y -1 is outside 0…50" in text
    assert "far.csv:1" not in text
    assert dock.runner.program is None and not dock.run_button.isEnabled()
    harness.run(0.5)
    assert [a.position_um for a in harness.emulator.axes] == [0.0, 0.0]


def test_run_shows_progress_eta_and_the_current_operation(
    qtbot: QtBot, harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    connected(harness)
    dock.open_path(square(tmp_path))
    eta_before = dock.eta_label.text()
    qtbot.mouseClick(dock.run_button, LEFT)
    assert dock.runner.state is JobState.RUNNING
    assert buttons(dock) == {
        "run": False,
        "pause": True,
        "resume": False,
        "step": False,
        "abort": True,
    }
    assert not dock.open_button.isEnabled()
    harness.run_until(lambda: dock.runner.done >= 5)
    assert dock.progress.value() == dock.runner.done
    assert dock.count_label.text() == f"{dock.runner.done} / 13 ops"
    assert dock.eta_label.text() != eta_before
    assert dock.elapsed_label.text() != "elapsed 00:00" or dock.runner.progress.elapsed_s < 0.5
    assert dock.operation_label.text().startswith("square.csv:")
    assert "move to X" in dock.operation_label.text()
    done_x = dock.preview.done_travel_curve.getData()[0]
    assert done_x is not None and np.isfinite(done_x).sum() >= 4  # the done path grows
    harness.run_until(lambda: dock.runner.state is JobState.DONE, timeout=60)
    assert dock.progress.value() == dock.progress.maximum() == 13
    assert dock.eta_label.text() == "left 00:00"
    # The operation, then its source line as written in the file.
    assert dock.operation_label.text().splitlines() == [
        "square.csv:13  move to X5.000 Y10.000",
        "    file: 5, 10",
    ]
    assert dock.run_button.isEnabled() and not dock.abort_button.isEnabled()


def test_pause_resume_step_and_abort_act_on_the_runner(
    qtbot: QtBot, harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    connected(harness)
    dock.open_path(square(tmp_path))
    runner = dock.runner
    qtbot.mouseClick(dock.run_button, LEFT)
    harness.run_until(lambda: runner.done >= 3)
    qtbot.mouseClick(dock.pause_button, LEFT)
    assert runner.state in (JobState.PAUSING, JobState.PAUSED)
    harness.run_until(lambda: runner.state is JobState.PAUSED)
    paused_at = runner.done
    harness.run(2.0)
    assert runner.done == paused_at  # nothing moves on while paused
    assert buttons(dock) == {
        "run": False,
        "pause": False,
        "resume": True,
        "step": True,
        "abort": True,
    }

    qtbot.mouseClick(dock.step_button, LEFT)
    harness.run_until(lambda: runner.state is JobState.PAUSED and runner.done == paused_at + 1)
    harness.run(1.0)
    assert runner.done == paused_at + 1  # one operation, then paused again

    qtbot.mouseClick(dock.resume_button, LEFT)
    assert runner.state is JobState.RUNNING
    harness.run_until(lambda: runner.done >= paused_at + 3)

    qtbot.mouseClick(dock.abort_button, LEFT)
    assert runner.state is JobState.ABORTED
    stopped_at = runner.done
    harness.run(1.0)
    assert runner.done == stopped_at
    assert not any(a.moving for a in harness.emulator.axes)
    assert "aborted" in messages(dock)
    # The checkpoint stays: the dock offers to resume after the last completed operation.
    assert dock.resume_offer.isVisible()
    assert dock.resume_checkpoint_button.text() == f"Resume from op {stopped_at + 1}"
    assert not dock.run_button.isEnabled()  # choose Resume or Discard first


def test_resume_offer_continues_without_repeating(
    qtbot: QtBot, harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    connected(harness)
    dock.open_path(square(tmp_path))
    qtbot.mouseClick(dock.run_button, LEFT)
    harness.run_until(lambda: dock.runner.done >= 6)
    qtbot.mouseClick(dock.abort_button, LEFT)
    stopped_at = dock.runner.done
    assert dock.resume_offer.isVisible()
    qtbot.mouseClick(dock.resume_checkpoint_button, LEFT)
    assert dock.runner.state is JobState.RUNNING and not dock.resume_offer.isVisible()
    harness.run_until(lambda: dock.runner.state is JobState.DONE, timeout=60)
    assert dock.runner.done == 13 and stopped_at < 13


def test_discard_offers_a_fresh_start(
    qtbot: QtBot, harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    connected(harness)
    dock.open_path(square(tmp_path))
    qtbot.mouseClick(dock.run_button, LEFT)
    harness.run_until(lambda: dock.runner.done >= 4)
    qtbot.mouseClick(dock.abort_button, LEFT)
    qtbot.mouseClick(dock.discard_checkpoint_button, LEFT)
    assert not dock.resume_offer.isVisible()
    assert dock.run_button.isEnabled()


def test_wait_shows_the_prompt_and_continue_resumes(
    qtbot: QtBot, harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    connected(harness)
    path = square(tmp_path, "pause.csv", "wait: swap the probe\n40, 40\n")
    dock.open_path(path)
    runner = dock.runner
    assert runner.program is not None and runner.program[13].kind is OpKind.WAIT
    qtbot.mouseClick(dock.run_button, LEFT)
    harness.run_until(lambda: runner.state is JobState.WAITING, timeout=60)
    assert dock.prompt.isVisible()
    assert "swap the probe" in dock.prompt_label.text()
    assert dock.operation_label.text().splitlines()[0] == "pause.csv:14  wait: swap the probe"
    harness.run(2.0)
    assert runner.state is JobState.WAITING and runner.done == 13  # it waits, however long
    qtbot.mouseClick(dock.continue_button, LEFT)
    assert not dock.prompt.isVisible()
    harness.run_until(lambda: runner.state is JobState.DONE, timeout=60)
    assert [a.position_um for a in harness.emulator.axes] == [40_000.0, 40_000.0]


def test_elapsed_and_done_in_count_the_prompt_and_tell_the_waiting_apart(
    qtbot: QtBot, harness: StationHarness, dock: JobsDock, tmp_path: Path
) -> None:
    """A job that stood 10 s at a prompt took 10 s longer: "elapsed" and "done in" are the
    wall clock's, and the waiting is said apart; "left" stays the machine's time."""
    connected(harness)
    dock.open_path(write(tmp_path, "probe.csv", "5, 5\nwait: swap the probe\n7.5, 5\n"))
    runner = dock.runner
    qtbot.mouseClick(dock.run_button, LEFT)
    harness.run_until(lambda: runner.state is JobState.WAITING, timeout=60)
    harness.run(10.0)
    running = runner.progress.running_s
    assert runner.progress.waiting_s >= 10.0
    qtbot.mouseClick(dock.continue_button, LEFT)
    harness.run_until(lambda: runner.state is JobState.DONE, timeout=60)
    harness.run(1.0)
    assert runner.state is JobState.DONE
    waited = runner.progress.waiting_s
    assert 10.0 <= waited < 10.5
    assert runner.progress.elapsed_s == pytest.approx(runner.progress.running_s + waited)
    assert runner.progress.running_s > running  # the last move ran after the prompt
    shown = dock.elapsed_label.text()
    elapsed = runner.progress.elapsed_s
    assert shown == (
        f"elapsed {clock_text(elapsed)} (of which {clock_text(waited)} waiting for you)"
    ), shown
    done = [line for line in messages(dock).splitlines() if "done:" in line][-1]
    assert done.endswith(
        f"in {runner.progress.elapsed_s:.1f} s, of which {waited:.1f} s waiting for you"
    ), done
    assert dock.eta_label.text() == "left 00:00"
    harness.run(5.0)  # the clock stops with the job
    assert dock.elapsed_label.text() == shown


def test_clock_text() -> None:
    assert clock_text(0) == "00:00"
    assert clock_text(75.4) == "01:15"
    assert clock_text(3725) == "1:02:05"
    assert clock_text(None) == "--:--" and clock_text(float("nan")) == "--:--"


def test_draw_mode_reloads_a_drill_file_as_a_pen_drawing(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path, data_dir: Path
) -> None:
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dock = JobsDock(harness.station, runner)
    qtbot.addWidget(dock)
    drill_file = data_dir / "realdata/excellon/tracespace_kicad_mchck.drl"
    assert dock.open_path(drill_file) is False  # the XY stage cannot drill: refused, listed
    # The stage has no pen: the option is not offered, and a choice kept from a machine
    # with a pen does not apply here.
    assert not dock.draw_check.isVisibleTo(dock)
    dock.draw_check.setChecked(True)
    qtbot.waitUntil(dock.open_button.isEnabled)  # the file re-read on the worker
    options = dock.options
    assert not options.draw and options.excellon_step_inch == 1e-4
    # Where it applies, the loader builds a pen drawing, which a machine with a pen runs.
    program = load_job(drill_file, ["X", "Y"], dataclasses.replace(options, draw=True))
    kinds = {op.kind for op in program}
    assert OpKind.PEN_DOWN in kinds and OpKind.DRILL not in kinds


def test_a_drill_job_on_the_drill_shows_its_travel_saving_and_microsteps(
    qtbot: QtBot, tmp_path: Path, data_dir: Path
) -> None:
    drill = StationHarness(load_profile("pcb-drill"))
    try:
        drill.connect()
        runner = JobRunner(drill.station, tmp_path / "checkpoints")
        dock = JobsDock(drill.station, runner)
        qtbot.addWidget(dock)
        assert dock.open_path(data_dir / "samples/pcb-driver/driver")
        log = dock.messages.toPlainText()
        assert "mm in file order" in log and "mm optimised" in log
        runner.step()  # the first tool's WAIT, once the drill homed (FIDELITY S2-26)
        drill.run_until(lambda: runner.state is JobState.WAITING)
        runner.confirm()
        drill.run_until(lambda: runner.state is JobState.PAUSED)
        # The next Step sends the first hole: its file line as written and its microsteps.
        first, line = dock.operation_label.text().splitlines()
        assert first.startswith("driver:") and "move to X" in first
        assert line.lstrip().startswith("file: X")
        session = drill.drill_session
        op = runner.program[runner.done] if runner.program else None
        assert op is not None
        x, y = session.to_microsteps(0, op.target["X"]), session.to_microsteps(1, op.target["Y"])
        assert line.endswith(f"machine: X{x} Y{y} microsteps")
    finally:
        drill.close()


def test_a_hole_perhaps_drilled_is_asked_with_it_marked_and_again_drills_it_once(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """The drill's V went out, the link went before RV: the dock asks; Again drills it."""
    drill = StationHarness(load_profile("pcb-drill"))
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    dock = JobsDock(drill.station, runner, confirm=lambda _text: False, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.resize(820, 640)
    dock.show()
    try:
        drill.connect()
        drill.run(0.5)
        excellon = "M48\nMETRIC\nT01C0.8\n%\nT01\nX10.0Y10.0\nX20.0Y15.0\nM30\n"
        job = write(tmp_path, "holes.drl", excellon)
        assert dock.open_path(job)
        program = runner.program
        assert program is not None
        drills = [i for i, op in enumerate(program) if op.kind is OpKind.DRILL]

        def gone(_direction: object, _data: bytes) -> bytes:
            return b""

        cut: list[int] = []

        def cut_at_second_hole(index: int) -> None:
            if index == drills[1] and not cut:
                cut.append(index)
                drill.loopback.set_manipulator(gone)  # the V leaves, nothing comes back

        runner.operationStarted.connect(cut_at_second_hole)
        qtbot.mouseClick(dock.run_button, LEFT)

        def at_the_question() -> bool:
            if runner.state is JobState.WAITING:
                qtbot.mouseClick(dock.continue_button, LEFT)
            return bool(cut) and runner.current_index == drills[1]

        drill.run_until(at_the_question, timeout=120)
        drill.run(0.1)
        drill.loopback.sever("cable pulled")
        drill.run_until(lambda: runner.state is JobState.PAUSED)
        drill.loopback.set_manipulator(None)
        drill.run_until(lambda: drill.station.model.link_state.value == "connected", timeout=60)
        qtbot.mouseClick(dock.resume_button, LEFT)

        assert runner.question == drills[1] and dock.prompt.isVisible()
        assert dock.again_button.isVisible() and not dock.continue_button.isVisible()
        assert not dock.resume_button.isEnabled()  # the question first
        marked = dock.preview.question_marker.getData()
        assert (list(marked[0]), list(marked[1])) == ([20.0], [15.0])
        holes = len(drill.drill_emulator.drill_log)
        assert holes == 1  # the lost V never reached the drill

        qtbot.mouseClick(dock.again_button, LEFT)
        drill.run_until(lambda: runner.state is JobState.DONE, timeout=120)
        assert len(drill.drill_emulator.drill_log) == 2
        assert not dock.prompt.isVisible()
        assert len(dock.preview.question_marker.getData()[0]) == 0
    finally:
        drill.close()


def test_the_open_dialog_names_each_pattern_once() -> None:
    from app.jobs.loaders import file_dialog_filter

    first = file_dialog_filter().split(";;")[0]
    patterns = first[first.index("(") + 1 : first.index(")")].split()
    assert "*.txt" in patterns and len(patterns) == len(set(patterns))


def test_no_lone_dash_under_the_progress_bar(dock: JobsDock, tmp_path: Path) -> None:
    assert dock.operation_label.text() == ""
    dock.open_path(square(tmp_path))
    assert dock.operation_label.text().startswith("square.csv:1")  # ready: the first shown


def test_smallest_bit_first_reloads_the_drill_job_with_the_prompts_by_size(
    qtbot: QtBot, tmp_path: Path
) -> None:
    drill = StationHarness(load_profile("pcb-drill"))
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    dock = JobsDock(drill.station, runner, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.show()
    try:
        drill.connect()
        excellon = (
            "M48\nMETRIC\nT01C1.2\nT02C0.6\nT03C1.2\n%\n"
            "T01\nX10.0Y10.0\nT02\nX20.0Y15.0\nX30.0Y15.0\nT03\nX40.0Y20.0\nM30\n"
        )
        assert dock.open_path(write(tmp_path, "bits.drl", excellon))

        def prompts() -> list[str]:
            program = runner.program
            return [op.message for op in program or () if op.kind is OpKind.WAIT]

        assert prompts() == [
            "insert T01, 1.20 mm, 2 holes (also T03)",
            "insert T02, 0.60 mm, 2 holes",
        ]
        assert "T03 is 1.20 mm like T01" in dock.messages.toPlainText()
        qtbot.mouseClick(dock.smallest_check, LEFT)
        qtbot.waitUntil(lambda: prompts()[0].startswith("insert T02"))
        assert prompts() == [
            "insert T02, 0.60 mm, 2 holes",
            "insert T01, 1.20 mm, 2 holes (also T03)",
        ]
        assert dock.option_values()["smallest_first"] is True
    finally:
        drill.close()


def test_registering_on_two_jogged_holes_loads_the_job_moved_onto_the_board(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """Jog over two holes, press Here for each, Register: every hole moves with the board."""
    drill = StationHarness(load_profile("pcb-drill"))
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    dock = JobsDock(drill.station, runner, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.show()
    try:
        drill.connect()
        session = drill.drill_session
        for axis in (0, 1):
            assert session.home(axis)
            drill.run_until(lambda: not session.busy, timeout=60)
        excellon = "M48\nMETRIC\nT01C0.8\n%\nT01\nX10.0Y10.0\nX60.0Y10.0\nX30.0Y40.0\nM30\n"
        assert dock.open_path(write(tmp_path, "reg.drl", excellon))
        original = runner.program
        assert original is not None and dock.registration.isVisible()
        assert not dock.registration.register_button.isEnabled()
        holes = reference_holes(original)
        refs = [holes[spin.value() - 1] for spin in dock.registration.hole_spins]
        truth = Registration(math.radians(2.0), (20.0, 15.0))
        for k, hole in enumerate(refs):
            x, y = truth.apply(*hole)
            assert session.move_absolute(0, x) and session.move_absolute(1, y)
            drill.run_until(lambda: not session.busy, timeout=60)
            qtbot.mouseClick(dock.registration.here_buttons[k], LEFT)
        qtbot.mouseClick(dock.registration.register_button, LEFT)

        moved = runner.program
        assert moved is not None and moved is not original
        assert "registered: rotation +2.0" in dock.messages.toPlainText()
        # Jogging lands on whole microsteps (~0.05 mm): every hole within that of the truth.
        for hole, where in zip(reference_holes(original), reference_holes(moved), strict=True):
            assert math.dist(truth.apply(*hole), where) < 0.1
        qtbot.mouseClick(dock.registration.clear_button, LEFT)
        assert runner.program is original
    finally:
        drill.close()


def test_the_bottom_side_loads_the_job_mirrored_about_its_extent_and_back(
    qtbot: QtBot, tmp_path: Path
) -> None:
    drill = StationHarness(load_profile("pcb-drill"))
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    dock = JobsDock(drill.station, runner, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.show()
    try:
        drill.connect()
        excellon = "M48\nMETRIC\nT01C0.8\n%\nT01\nX10.0Y10.0\nX60.0Y10.0\nX30.0Y40.0\nM30\n"
        assert dock.open_path(write(tmp_path, "side.drl", excellon))
        original = runner.program
        assert original is not None
        combo = dock.registration.side_combo
        combo.setFocus()
        qtbot.keyClick(combo, Qt.Key.Key_Down)  # "Bottom, mirrored in X"
        flipped = runner.program
        assert flipped is not None and combo.currentData() == "X"
        assert sorted(reference_holes(flipped)) == sorted(
            [(60.0, 10.0), (10.0, 10.0), (40.0, 40.0)]
        )
        qtbot.keyClick(combo, Qt.Key.Key_Up)  # back to the top side
        assert runner.program is original
        runner.start()  # home, then the first bit's prompt: the job is under way
        drill.run_until(lambda: runner.state is JobState.WAITING)
        assert not dock.registration.isEnabled()
        runner.abort()
        qtbot.waitUntil(lambda: dock.registration.isEnabled())
    finally:
        drill.close()


def test_a_drill_file_on_the_winder_is_refused_at_load_naming_file_and_reason(
    qtbot: QtBot, tmp_path: Path, data_dir: Path
) -> None:
    """The winder drills with its own Z moves: a drill file once loaded and failed at run time."""
    winder = StationHarness(load_profile("string-art"))
    try:
        runner = JobRunner(winder.station, tmp_path / "checkpoints")
        dock = JobsDock(winder.station, runner)
        qtbot.addWidget(dock)
        drill_file = data_dir / "realdata/excellon/tracespace_kicad_mchck.drl"
        assert dock.open_path(drill_file) is False
        assert runner.program is None
        said = messages(dock)
        assert "tracespace_kicad_mchck.drl:" in said
        assert "G-code has no drill cycle" in said
    finally:
        winder.close()
