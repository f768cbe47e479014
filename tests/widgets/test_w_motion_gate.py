"""The motion gate as the operator meets it: the console's question, step jogs, axis labels."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import QSettings, Qt, QTimer
from PySide6.QtWidgets import QApplication, QMessageBox
from pytestqt.qtbot import QtBot

from app.machines.gcode.line_targets import line_motion
from app.profiles import load_profile
from protocol.stage.codec import CommandFrame, CommandId, decode
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.panels.gcode import GcodePanel

AXES = ("X", "Y", "Z")


def test_line_targets_follow_the_distance_mode_in_force() -> None:
    here = {"X": 100.0, "Y": 10.0}
    assert line_motion("G0 X5", False, here, AXES).targets == {"X": 5.0}
    assert line_motion("G0 X5", True, here, AXES).targets == {"X": 105.0}
    moved = line_motion("G91 G1 X250 F100", False, here, AXES)
    assert moved.targets == {"X": 350.0} and moved.relative_after
    assert line_motion("G90 X1 (X999)", True, here, AXES).targets == {"X": 1.0}
    assert line_motion("G20 G0 X2", False, here, AXES).targets == {"X": 50.8}
    jog = line_motion("$J=G91 X5 F100", False, here, AXES)
    assert jog.targets == {"X": 105.0} and not jog.relative_after  # modal state untouched
    assert line_motion("G92 X0", False, here, AXES).targets == {}
    assert line_motion("$H", False, here, AXES).targets == {}


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[tuple[StationHarness, GcodePanel]]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run(0.2)
    panel = GcodePanel(harness.station)
    qtbot.addWidget(panel)
    try:
        yield harness, panel
    finally:
        harness.close()


def _answer_next_box(button: QMessageBox.StandardButton, seen: list[str]) -> None:
    def answer() -> None:
        box = QApplication.activeModalWidget()
        assert isinstance(box, QMessageBox)
        seen.append(box.text())
        box.button(button).click()

    QTimer.singleShot(0, answer)


def _type(qtbot: QtBot, panel: GcodePanel, text: str) -> None:
    panel.entry.setFocus()
    qtbot.keyClicks(panel.entry, text)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)


def test_a_console_line_beyond_the_travel_asks_first_and_cancel_sends_nothing(
    qtbot: QtBot, plotter: tuple[StationHarness, GcodePanel]
) -> None:
    harness, panel = plotter
    session = harness.gcode_session
    assert session.move_absolute(0, 100.0)
    harness.run_until(lambda: session.settled, timeout=10)
    _type(qtbot, panel, "G91")  # a relative line is judged from where the machine stands
    harness.run_until(lambda: session.settled, timeout=5)
    seen: list[str] = []
    start = len(harness.written)
    _answer_next_box(QMessageBox.StandardButton.Cancel, seen)
    _type(qtbot, panel, "G1 X250 F3000")
    assert seen and "X 350.000 mm is outside the travel 0…300 mm" in seen[0]
    assert not any(b"X250" in chunk for chunk in harness.written[start:])
    assert "not sent (beyond the travel)" in panel.output.toPlainText()
    # Within the travel, the same kind of line goes without a question.
    _type(qtbot, panel, "G1 X50 F3000")
    harness.run_until(lambda: session.settled, timeout=10)
    assert harness.gcode_emulator.position()["X"] == pytest.approx(150.0)


def test_a_confirmed_console_line_goes_out_as_typed(
    qtbot: QtBot, plotter: tuple[StationHarness, GcodePanel]
) -> None:
    harness, panel = plotter
    seen: list[str] = []
    start = len(harness.written)
    _answer_next_box(QMessageBox.StandardButton.Yes, seen)
    _type(qtbot, panel, "G0 X400")
    assert seen
    assert any(chunk.startswith(b"G0 X400") for chunk in harness.written[start:])


def _stage_window(qtbot: QtBot, harness: StationHarness, tmp_path_ini: str) -> MainWindow:
    window = MainWindow(harness.station, QSettings(tmp_path_ini, QSettings.Format.IniFormat))
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    return window


def test_arrow_keys_in_step_mode_move_one_step_per_tap_and_the_choice_persists(
    qtbot: QtBot, tmp_path: object
) -> None:
    ini = f"{tmp_path}/stepdeck.ini"
    harness = StationHarness(load_profile("xy-stage"))
    try:
        window = _stage_window(qtbot, harness, ini)
        harness.connect()
        harness.run(2.5)
        combo = window.manual_panel.key_step
        combo.setCurrentIndex(combo.findData(1.0))
        assert window.jog.key_step == 1.0
        start = len(harness.written)
        window.setFocus()
        qtbot.keyPress(window, Qt.Key.Key_Right)
        harness.run(3.0)  # held: one step, not a jog
        qtbot.keyRelease(window, Qt.Key.Key_Right)
        harness.run(0.5)
        frames = [decode(raw)[1] for raw in harness.written[start:]]
        assert all(isinstance(f, CommandFrame) for f in frames)
        packets = [p for f in frames if isinstance(f, CommandFrame) for p in f.packets[:1]]
        assert [(p.command, p.data) for p in packets if p.command == CommandId.MOVE_REL] == [
            (CommandId.MOVE_REL, 1000)
        ]
        assert all(p.command != CommandId.JOG or p.data == 0 for p in packets)
        assert harness.emulator.axes[0].position_um == pytest.approx(1000, abs=1)
        window.close()
        again = _stage_window(qtbot, harness, ini)
        assert again.jog.key_step == 1.0  # remembered
        assert again.manual_panel.key_step.currentData() == 1.0
    finally:
        harness.close()


def test_the_jog_pad_names_the_machines_own_axes(qtbot: QtBot) -> None:
    harness = StationHarness(load_profile("string-art"))
    try:
        window = MainWindow(harness.station, None)
        qtbot.addWidget(window)
        labels = {key: b.text() for key, b in window.manual_panel.jog_buttons.items()}
        assert labels[(1, 0)] == "A+ →" and labels[(0, 1)] == "X+ ↑"
        assert labels[(0, 0, 1)] == "Z+"
        assert not any("Y" in text for text in labels.values())
    finally:
        harness.close()


def _held_button_jog(
    qtbot: QtBot, mouse_says_held: bool, monkeypatch: pytest.MonkeyPatch
) -> tuple[StationHarness, MainWindow]:
    """A jog button pressed and its release never delivered; the mouse's state as given."""
    import widgets.jog_input as jog_input

    buttons = Qt.MouseButton.LeftButton if mouse_says_held else Qt.MouseButton.NoButton

    class _Mouse:
        @staticmethod
        def mouseButtons() -> Qt.MouseButton:
            return buttons

    monkeypatch.setattr(jog_input, "QGuiApplication", _Mouse)
    harness = StationHarness(load_profile("xy-stage"))
    window = MainWindow(harness.station, None)
    qtbot.addWidget(window)
    window.show()
    harness.connect()
    harness.run(2.5)
    window.manual_panel.jog_buttons[(1, 0)].pressed.emit()  # pressed; no release follows
    assert harness.session.jog_vector == (1, 0)
    for _ in range(12):  # 1.2 s of station time, with the real-time button poll running
        harness.run(0.1)
        qtbot.wait(jog_input.BUTTON_POLL_MS // 2)
    return harness, window


def test_a_held_button_the_mouse_no_longer_holds_ends_its_jog(
    qtbot: QtBot, monkeypatch: pytest.MonkeyPatch
) -> None:
    harness, window = _held_button_jog(qtbot, False, monkeypatch)
    try:
        assert harness.session.jog_vector == (0, 0)  # the dead-man ended it
        assert window.jog.vector == (0, 0)  # and the window let go of the button
    finally:
        harness.close()


def test_a_button_the_mouse_still_holds_keeps_jogging(
    qtbot: QtBot, monkeypatch: pytest.MonkeyPatch
) -> None:
    harness, _ = _held_button_jog(qtbot, True, monkeypatch)
    try:
        assert harness.session.jog_vector == (1, 0)
    finally:
        harness.session.set_jog((0, 0))
        harness.close()
