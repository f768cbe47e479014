"""Board registration in the jobs dock: reference holes picked in the preview, three points,
and the registration kept when the file is read again and when an interrupted job resumes."""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from pytestqt.qtbot import QtBot

from app.jobs.program import OpKind, Program
from app.jobs.registration import Registration, hole_positions
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.dock import JobsDock
from widgets.jobs.preview import JobPreview

LEFT = Qt.MouseButton.LeftButton
EXCELLON = (
    "M48\nMETRIC\nT01C0.8\nT02C1.0\n%\nT01\nX10.0Y10.0\nX60.0Y10.0\nX30.0Y40.0\n"
    "T02\nX45.0Y25.0\nX15.0Y35.0\nM30\n"
)
TRUTH = Registration(math.radians(2.0), (20.0, 15.0))


@pytest.fixture
def drill() -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    try:
        harness.connect()
        yield harness
    finally:
        harness.close()


def make_dock(qtbot: QtBot, drill: StationHarness, checkpoints: Path) -> JobsDock:
    runner = JobRunner(drill.station, checkpoints)
    moves: list[str] = []
    dock = JobsDock(drill.station, runner, confirm=lambda text: moves.append(text) or False)
    dock.asked_moves = moves  # type: ignore[attr-defined]
    qtbot.addWidget(dock)
    dock.resize(900, 700)
    dock.show()
    qtbot.waitExposed(dock)
    return dock


def click_at(qtbot: QtBot, preview: JobPreview, x: float, y: float) -> None:
    """A real left click on the plot where (x, y) is drawn."""
    view = preview.plot.getViewBox()
    pixel: QPoint = preview.plot_widget.mapFromScene(view.mapViewToScene(QPointF(x, y)))
    qtbot.mouseClick(preview.plot_widget.viewport(), LEFT, pos=pixel)


def jog_and_register(drill: StationHarness, dock: JobsDock, qtbot: QtBot) -> None:
    """Jog over each chosen reference hole of the board lying at TRUTH, Here, Register."""
    bar = dock.registration
    assert bar.original is not None
    holes = hole_positions(bar.original)
    session = drill.drill_session
    for k in range(bar.count):
        x, y = TRUTH.apply(*holes[bar.hole_spins[k].value() - 1])
        assert session.move_absolute(0, x) and session.move_absolute(1, y)
        drill.run_until(lambda: not session.busy, timeout=60)
        qtbot.mouseClick(bar.here_buttons[k], LEFT)
    qtbot.mouseClick(bar.register_button, LEFT)


def test_clicking_holes_in_the_preview_picks_them_as_references_and_moves_nothing(
    qtbot: QtBot, drill: StationHarness, tmp_path: Path
) -> None:
    dock = make_dock(qtbot, drill, tmp_path / "checkpoints")
    path = tmp_path / "board.drl"
    path.write_text(EXCELLON, encoding="utf-8")
    assert dock.open_path(path)
    program = dock.runner.program
    assert program is not None
    holes = hole_positions(program)
    bar = dock.registration
    dock.preview.fit()
    sent: list[object] = []
    drill.drill_session.frameSent.connect(lambda command, _raw: sent.append(command))

    qtbot.mouseClick(bar.three_check, LEFT)
    assert bar.count == 3 and bar.hole_spins[2].isVisible()
    for k, hole in ((1, 3), (0, 4), (2, 1)):
        qtbot.mouseClick(bar.pick_buttons[k], LEFT)
        assert bar.pick_buttons[k].isChecked() and dock.preview.picking == k
        click_at(qtbot, dock.preview, *holes[hole])
        assert bar.hole_spins[k].value() == hole + 1
        assert not bar.pick_buttons[k].isChecked() and dock.preview.picking is None
    # Away from every hole a pick is refused and stays armed; still nothing moves.
    qtbot.mouseClick(bar.pick_buttons[0], LEFT)
    click_at(qtbot, dock.preview, 100.0, 100.0)
    assert dock.preview.picking == 0 and bar.hole_spins[0].value() == 5
    assert "No hole there" in dock.messages.toPlainText()
    qtbot.mouseClick(bar.pick_buttons[0], LEFT)  # stop picking: a click asks to move again
    assert dock.preview.picking is None
    drill.run(0.5)
    assert sent == [] and dock.asked_moves == []  # type: ignore[attr-defined]
    click_at(qtbot, dock.preview, 100.0, 100.0)
    assert len(dock.asked_moves) == 1  # type: ignore[attr-defined]


def test_three_points_register_with_their_agreement_shown(
    qtbot: QtBot, drill: StationHarness, tmp_path: Path
) -> None:
    dock = make_dock(qtbot, drill, tmp_path / "checkpoints")
    path = tmp_path / "board.drl"
    path.write_text(EXCELLON, encoding="utf-8")
    assert dock.open_path(path)
    original = dock.runner.program
    assert original is not None
    qtbot.mouseClick(dock.registration.three_check, LEFT)
    spins = [spin.value() for spin in dock.registration.hole_spins]
    assert len(set(spins)) == 3  # three different holes chosen, far apart
    jog_and_register(drill, dock, qtbot)
    moved = dock.runner.program
    assert moved is not None and moved is not original
    text = dock.messages.toPlainText()
    assert "registered: rotation +2.0" in text and "three points agree within" in text
    for hole, where in zip(hole_positions(original), hole_positions(moved), strict=True):
        assert math.dist(TRUTH.apply(*hole), where) < 0.1  # jogs land on microsteps


def drilled(drill: StationHarness) -> Counter[tuple[int, int]]:
    return Counter(h.position for h in drill.drill_emulator.drill_log)


def expected_holes(drill: StationHarness, program: Program) -> Counter[tuple[int, int]]:
    session = drill.drill_session
    return Counter(
        (session.to_microsteps(0, x), session.to_microsteps(1, y))
        for x, y in hole_positions(program)
    )


def test_an_interrupted_registered_job_resumes_on_the_board_after_a_restart_and_a_reread(
    qtbot: QtBot, drill: StationHarness, tmp_path: Path
) -> None:
    """The checkpoint keeps the registration: the file read again by a new station is moved
    onto the board as before, offered for resume, and finishes every hole once there."""
    checkpoints = tmp_path / "checkpoints"
    path = tmp_path / "board.drl"
    path.write_text(EXCELLON, encoding="utf-8")
    dock = make_dock(qtbot, drill, checkpoints)
    assert dock.open_path(path)
    original = dock.runner.program
    assert original is not None
    jog_and_register(drill, dock, qtbot)
    registered = dock.runner.program
    assert registered is not None and registered is not original

    # Read again (the same file): still on the board, not back at the file's coordinates.
    assert dock.open_path(path)
    again = dock.runner.program
    assert again is not None and again.fingerprint() == registered.fingerprint()
    assert dock.registration.placement.registration is not None

    runner = dock.runner
    runner.waitingForOperator.connect(lambda _message: runner.confirm())
    runner.start()
    drill.run_until(lambda: len(drill.drill_emulator.drill_log) >= 2, timeout=120)
    runner.abort()
    drill.run(5.0)  # the V under way runs to its end
    assert runner.state is JobState.ABORTED
    done_before = Counter(drilled(drill))
    dock.close()
    dock.deleteLater()

    # A new station reads the file: the checkpoint's registration puts it on the board again.
    restarted = make_dock(qtbot, drill, checkpoints)
    assert restarted.open_path(path)
    resumed = restarted.runner.program
    assert resumed is not None and resumed.fingerprint() == registered.fingerprint()
    assert "kept on the board as before" in restarted.messages.toPlainText()
    assert restarted.registration.placement.registration is not None
    assert restarted.runner.resume_available is not None
    restarted.runner.waitingForOperator.connect(lambda _m: restarted.runner.confirm())
    restarted.runner.decisionNeeded.connect(lambda *_: restarted.runner.decide(again=False))
    restarted.runner.resume_from_checkpoint()
    drill.run_until(lambda: restarted.runner.state is JobState.DONE, timeout=120)

    assert sum(1 for op in registered if op.kind is OpKind.DRILL) == 5
    assert drilled(drill) == expected_holes(drill, registered)
    assert set(drilled(drill).values()) == {1}
    assert sum(done_before.values()) >= 2
