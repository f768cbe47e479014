"""Jog feedback in the operator window: a locked jog says why, a held key shows its button.

During a job the machine is the job's: the jog buttons are disabled with the
reason beside them and an arrow key says it in the status bar, instead of
being silently ignored.  Outside a job, the on-screen button of the held
arrow keys' direction shows pressed, as if the mouse held it.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def window(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> MainWindow:
    window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    harness.connect()
    harness.run(1.5)  # the parameter reads after connecting
    return window


def down(window: MainWindow) -> set[tuple[int, ...]]:
    return {d for d, b in window.manual_panel.jog_buttons.items() if b.isDown()}


def test_during_a_job_the_jog_buttons_are_off_with_the_reason_and_keys_say_it(
    qtbot: QtBot, harness: StationHarness, window: MainWindow, tmp_path: Path
) -> None:
    panel = window.manual_panel
    assert all(b.isEnabled() for b in panel.jog_buttons.values())
    assert not panel.jog_note.isVisible()
    job = tmp_path / "job.csv"
    job.write_text("wait: put the probe on\n5, 5\n", encoding="utf-8")
    dock = window.jobs_dock
    dock.show()
    assert dock.open_path(job)
    qtbot.mouseClick(dock.run_button, LEFT)
    harness.run_until(lambda: dock.runner.state is JobState.WAITING, timeout=30)
    QApplication.processEvents()

    assert not any(b.isEnabled() for b in panel.jog_buttons.values())
    assert panel.jog_note.isVisible()
    assert panel.jog_note.text().startswith("Jogging locked: a job is under way")
    window.setFocus()
    qtbot.keyPress(window, Qt.Key.Key_Right)
    harness.run(0.3)
    assert window.jog.vector == (0, 0)
    assert not harness.station.model.axes[0].moving
    assert window.message_label.text().startswith("Jog refused: a job is under way")
    qtbot.keyRelease(window, Qt.Key.Key_Right)

    qtbot.mouseClick(dock.abort_button, LEFT)
    harness.run(0.5)
    QApplication.processEvents()
    assert all(b.isEnabled() for b in panel.jog_buttons.values())
    assert not panel.jog_note.isVisible()
    qtbot.keyPress(window, Qt.Key.Key_Right)
    assert window.jog.vector == (1, 0)  # jogging is back
    qtbot.keyRelease(window, Qt.Key.Key_Right)


def test_the_button_of_a_held_arrow_key_shows_pressed(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    assert down(window) == set()
    qtbot.keyPress(window, Qt.Key.Key_Right)
    assert down(window) == {(1, 0)}
    qtbot.keyPress(window, Qt.Key.Key_Up)
    assert down(window) == {(1, 1)}  # both keys: the diagonal, as the cross shows it
    qtbot.keyRelease(window, Qt.Key.Key_Right)
    assert down(window) == {(0, 1)}
    qtbot.keyRelease(window, Qt.Key.Key_Up)
    assert down(window) == set()
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=3)


def test_a_key_never_lets_up_a_button_the_mouse_holds(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    button = window.manual_panel.jog_buttons[(1, 0)]
    qtbot.mousePress(button, LEFT)
    assert window.jog.vector == (1, 0)
    qtbot.keyPress(window, Qt.Key.Key_Up)
    qtbot.keyRelease(window, Qt.Key.Key_Up)
    assert button.isDown()  # still the mouse's
    qtbot.mouseRelease(button, LEFT)
    assert window.jog.vector == (0, 0)  # and its release still ends the jog
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=3)


@pytest.mark.parametrize("profile", ["grbl-plotter", "xy-stage"])
def test_esc_during_a_job_ends_the_job_and_the_machine_stays_still(
    qtbot: QtBot, tmp_path: Path, profile: str
) -> None:
    """Stop means stop: the job ends (resumable) and nothing moves again by itself.

    A G-code job once took the stop's reset for a device reset and carried on.
    """
    harness = StationHarness(load_profile(profile))
    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        window.show()
        window.activateWindow()
        qtbot.waitUntil(window.isActiveWindow)
        harness.connect()
        harness.run(1.5)
        job = tmp_path / ("edges.gcode" if profile == "grbl-plotter" else "edges.csv")
        points = [(40 * (k % 2) + 5, 5 * k + 5) for k in range(9)]
        if profile == "grbl-plotter":
            text = "".join(f"G1 X{x} Y{y} F600\n" for x, y in points)
        else:
            text = "".join(f"{x}, {y}\n" for x, y in points)
        job.write_text(text, encoding="utf-8")
        dock = window.jobs_dock
        dock.show()
        assert dock.open_path(job)
        runner = dock.runner
        qtbot.mouseClick(dock.run_button, LEFT)
        harness.run_until(
            lambda: runner.progress.executed >= 2 and harness.station.model.any_moving
        )
        qtbot.keyPress(window, Qt.Key.Key_Escape)
        harness.run_until(lambda: not harness.station.model.any_moving, timeout=10)
        assert runner.state is JobState.ABORTED
        harness.run(1.0)  # the last position reports of the stop arrive
        executed = runner.progress.executed
        still = [a.position for a in harness.station.model.axes]
        harness.run(5.0)
        assert [a.position for a in harness.station.model.axes] == still
        assert runner.state is JobState.ABORTED and runner.progress.executed == executed
        # One figure everywhere: the dock's message, its count and its resume offer.
        assert f"Job aborted after {executed} of {len(points)}" in dock.messages.toPlainText()
        assert dock.count_label.text() == f"{executed} / {len(points)} ops"
        assert f"completed {executed} of" in dock.resume_offer_label.text()
        assert "line(s) not run" not in window.message_label.text()
    finally:
        harness.close()
