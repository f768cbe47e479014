"""The operator window: application-wide keys, the runaway-jog guard and the motion lock.

Everything runs against the emulated stage on a manual clock: time moves only
through the harness, and the assertions read what the operator would see.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QEvent, QSettings, Qt
from PySide6.QtGui import QFocusEvent, QKeyEvent
from PySide6.QtWidgets import QApplication, QComboBox, QFileDialog, QWidget
from pytestqt.qtbot import QtBot

from app.profiles import available_profiles, load_profile
from protocol.stage.codec import AxisStatus, CommandFrame, CommandId, CommandPacket, decode
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

# The offscreen platform warns whenever a shown window's layout sets its size limits.


def _open_window(
    qtbot: QtBot, harness: StationHarness, settings: QSettings | None = None
) -> MainWindow:
    window = MainWindow(harness.station, settings)
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    return window


@pytest.fixture
def window(qtbot: QtBot, harness: StationHarness) -> MainWindow:
    window = _open_window(qtbot, harness)
    harness.connect()
    # Let the parameter reads of the connection finish: while the session reads, the
    # echoes carry parameters instead of positions.
    harness.run(1.5)
    return window


def x_position(harness: StationHarness) -> float:
    return harness.station.model.axes[0].position


def status(window: MainWindow, axis: int) -> str:
    return window.info_panel.statuses[axis].text()


def position(window: MainWindow, axis: int) -> str:
    return window.info_panel.positions[axis].text()


def test_title_names_the_profile(window: MainWindow) -> None:
    assert window.windowTitle() == "StepDeck — XY positioning stage"


def test_holding_right_jogs_x_through_its_ramp(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    qtbot.keyPress(window, Qt.Key.Key_Right)
    harness.run_until(lambda: status(window, 0) == "accelerating", timeout=1)
    harness.run_until(lambda: status(window, 0) == "constant speed", timeout=2)
    assert x_position(harness) > 0
    assert status(window, 1) != "accelerating"  # Y is left alone

    qtbot.keyRelease(window, Qt.Key.Key_Right)
    harness.run_until(lambda: status(window, 0) == "decelerating", timeout=1)
    harness.run_until(lambda: not harness.station.model.axes[0].moving, timeout=2)
    assert status(window, 0) == "stopped"
    stopped_at = position(window, 0)
    harness.run(0.5)
    assert position(window, 0) == stopped_at


def test_right_and_up_jog_diagonally(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    qtbot.keyPress(window, Qt.Key.Key_Right)
    qtbot.keyPress(window, Qt.Key.Key_Up)
    harness.run(1.0)
    x, y = (axis.position for axis in harness.station.model.axes)
    assert x > 1 and y > 1
    qtbot.keyRelease(window, Qt.Key.Key_Up)
    harness.run_until(lambda: not harness.station.model.axes[1].moving, timeout=2)
    assert harness.station.model.axes[0].moving  # Right is still held
    qtbot.keyRelease(window, Qt.Key.Key_Right)
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)


def test_a_jog_key_reaches_the_wire_before_any_tick(qtbot: QtBot, harness: StationHarness) -> None:
    window = _open_window(qtbot, harness)
    harness.connect()  # no stepping from here on: no periodic frame can be sent
    sent_before = len(harness.written)
    qtbot.keyPress(window, Qt.Key.Key_Right)
    assert len(harness.written) > sent_before
    used, frame = decode(harness.written[-1])
    assert used == len(harness.written[-1])
    assert isinstance(frame, CommandFrame)
    assert frame.packets[0] == CommandPacket(CommandId.JOG, 1)
    qtbot.keyRelease(window, Qt.Key.Key_Right)
    _, frame = decode(harness.written[-1])
    assert isinstance(frame, CommandFrame)
    assert frame.packets[0] == CommandPacket(CommandId.JOG, 0)


def _hold_key(harness: StationHarness, key: Qt.Key, seconds: float) -> None:
    """Keep a key held: its auto-repeat presses arrive every 0.1 s, as a keyboard's do."""
    for _ in range(round(seconds / 0.1)):
        harness.run(0.1)
        target = QApplication.focusWidget()
        assert target is not None
        repeat = QKeyEvent(
            QEvent.Type.KeyPress, key, Qt.KeyboardModifier.NoModifier, "", autorep=True
        )
        QApplication.sendEvent(target, repeat)


def _jog_right_until_moving(qtbot: QtBot, harness: StationHarness, window: MainWindow) -> None:
    qtbot.keyPress(window, Qt.Key.Key_Right)
    harness.run_until(lambda: status(window, 0) == "constant speed", timeout=2)


def _assert_comes_to_rest(harness: StationHarness) -> None:
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    rest = harness.emulator.axes[0].position_um
    harness.run(1.0)
    assert harness.emulator.axes[0].position_um == rest
    assert harness.session.jog_vector == (0, 0)


def test_window_deactivation_stops_a_held_jog(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    _jog_right_until_moving(qtbot, harness, window)
    QApplication.sendEvent(window, QEvent(QEvent.Type.WindowDeactivate))
    # The key-up went to another window and never arrives here.
    _assert_comes_to_rest(harness)


def test_focus_leaving_the_window_stops_a_held_jog(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    _jog_right_until_moving(qtbot, harness, window)
    focus_out = QFocusEvent(QEvent.Type.FocusOut, Qt.FocusReason.ActiveWindowFocusReason)
    QApplication.sendEvent(window, focus_out)
    _assert_comes_to_rest(harness)


def test_another_window_taking_focus_stops_a_held_jog(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    _jog_right_until_moving(qtbot, harness, window)
    other = QWidget()
    qtbot.addWidget(other)
    other.show()
    other.activateWindow()
    qtbot.waitUntil(other.isActiveWindow)
    _assert_comes_to_rest(harness)


def test_application_going_inactive_stops_a_held_jog(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    _jog_right_until_moving(qtbot, harness, window)
    app = QApplication.instance()
    assert isinstance(app, QApplication)
    app.applicationStateChanged.emit(Qt.ApplicationState.ApplicationInactive)
    _assert_comes_to_rest(harness)


def test_focus_moving_inside_the_window_keeps_the_jog(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    window.menu_panel.set_page(1)
    _jog_right_until_moving(qtbot, harness, window)
    window.absolute_panel.targets[1].setFocus()
    qtbot.waitUntil(window.absolute_panel.targets[1].hasFocus)
    _hold_key(harness, Qt.Key.Key_Right, 0.6)  # longer than the device's jog watchdog
    assert status(window, 0) == "constant speed"
    qtbot.keyRelease(window.absolute_panel.targets[1], Qt.Key.Key_Right)
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)


def test_arrows_edit_inside_a_spin_box_instead_of_jogging(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    window.menu_panel.set_page(1)
    target = window.absolute_panel.targets[0]
    target.setFocus()
    qtbot.waitUntil(target.hasFocus)
    qtbot.keyClick(target, Qt.Key.Key_Up)
    harness.run(0.5)
    assert target.value() == pytest.approx(1.0)
    assert not harness.station.model.any_moving
    assert harness.session.jog_vector == (0, 0)


def test_escape_in_a_spin_box_stops_every_axis(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    window.menu_panel.set_page(1)
    absolute = window.absolute_panel
    absolute.targets[0].setValue(40.0)
    absolute.targets[1].setValue(40.0)
    qtbot.mouseClick(absolute.go_all_button, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: all(a.moving for a in harness.station.model.axes), timeout=1)
    absolute.targets[1].setFocus()
    qtbot.waitUntil(absolute.targets[1].hasFocus)

    qtbot.keyClick(absolute.targets[1], Qt.Key.Key_Escape)
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    assert [status(window, axis) for axis in (0, 1)] == ["stopped", "stopped"]
    assert x_position(harness) < 30
    assert absolute.targets[1].value() == pytest.approx(40.0)


def test_escape_stops_a_button_jog(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    button = window.manual_panel.jog_buttons[(0, 1)]
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: harness.station.model.axes[1].moving, timeout=1)
    qtbot.keyClick(window, Qt.Key.Key_Escape)
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    qtbot.mouseRelease(button, Qt.MouseButton.LeftButton)
    assert harness.session.jog_vector == (0, 0)


def test_auto_repeat_does_not_restart_a_stopped_jog(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    _jog_right_until_moving(qtbot, harness, window)
    qtbot.keyClick(window, Qt.Key.Key_Escape)
    harness.run(0.05)
    # The key is still down: the OS keeps sending auto-repeated presses.
    repeat = QKeyEvent(
        QEvent.Type.KeyPress, Qt.Key.Key_Right, Qt.KeyboardModifier.NoModifier, "", True
    )
    QApplication.sendEvent(window, repeat)
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    assert harness.session.jog_vector == (0, 0)


def _motion_controls(window: MainWindow) -> list[QWidget]:
    manual, absolute, relative = window.manual_panel, window.absolute_panel, window.relative_panel
    return [
        *manual.jog_buttons.values(),
        *manual.home_buttons,
        *absolute.go_buttons,
        absolute.go_all_button,
        *relative.minus_buttons,
        *relative.plus_buttons,
    ]


def test_charger_locks_motion_and_says_why(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    assert all(w.isEnabled() for w in _motion_controls(window))
    assert window.lock_label.isHidden()

    harness.emulator.charger_connected = True
    harness.run_until(lambda: window.lock_label.isVisible(), timeout=1)
    assert not any(w.isEnabled() for w in _motion_controls(window))
    assert "charger" in window.lock_label.text()
    assert window.lock_label.text().startswith("Motion locked:")
    assert window.static_panel.stop_button.isEnabled()
    qtbot.keyPress(window, Qt.Key.Key_Right)
    harness.run(0.5)
    assert harness.station.emulator is not None
    assert harness.emulator.axes[0].position_um == 0
    qtbot.keyRelease(window, Qt.Key.Key_Right)

    harness.emulator.charger_connected = False
    harness.run_until(lambda: window.lock_label.isHidden(), timeout=1)
    assert all(w.isEnabled() for w in _motion_controls(window))


def test_sleep_locks_motion_until_wake(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    sleep = window.static_panel.sleep_button
    assert sleep.text() == "Sleep"
    qtbot.mouseClick(sleep, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: window.lock_label.isVisible(), timeout=1)
    assert harness.emulator.snapshot().sleeping
    assert "sleeping" in window.lock_label.text()
    assert not any(w.isEnabled() for w in _motion_controls(window))
    assert sleep.text() == "Wake" and sleep.isEnabled()

    qtbot.mouseClick(sleep, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: window.lock_label.isHidden(), timeout=1)
    assert not harness.emulator.snapshot().sleeping
    assert sleep.text() == "Sleep"
    assert all(w.isEnabled() for w in _motion_controls(window))


def test_disconnected_window_is_locked(qtbot: QtBot, harness: StationHarness) -> None:
    window = _open_window(qtbot, harness)
    assert window.lock_label.text() == "Motion locked: not connected"
    assert not any(w.isEnabled() for w in _motion_controls(window))
    assert "disconnected" in window.link_status.text()


def test_status_bar_shows_link_messages_and_rejects(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    assert "connected" in window.link_status.text()
    assert window.rejected_label.text() == "rejected frames: 0"
    harness.station.model.message.emit("hello operator")
    assert window.message_label.text() == "hello operator"
    assert window.message_timer.isActive()  # and it goes, rather than standing for good
    window.message_timer.setInterval(20)
    window.message_timer.start()
    qtbot.waitUntil(lambda: window.message_label.text() == "")
    assert harness.station.link is not None
    harness.station.link.dataReceived.emit(b"<garbage\n")
    assert window.rejected_label.text() == "rejected frames: 1"


def test_geometry_and_page_survive_a_restart(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    first = _open_window(qtbot, harness, settings=settings)
    first.resize(first.minimumWidth() + 21, first.minimumHeight() + 13)
    size = first.size()
    first.menu_panel.set_page(2)
    first.close()

    again = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    second = _open_window(qtbot, harness, settings=again)
    assert second.size() == size
    assert second.stack.currentWidget() is second.relative_panel


def test_job_reading_options_survive_a_restart(qtbot: QtBot, tmp_path: Path) -> None:
    harness = StationHarness(load_profile("grbl-plotter"))  # a pen: the drill options show
    try:
        _options_survive_a_restart(qtbot, harness, tmp_path)
    finally:
        harness.close()


def test_drill_options_are_not_offered_without_a_drill_or_a_pen(
    qtbot: QtBot, window: MainWindow
) -> None:
    window.jobs_dock.show()
    assert not window.jobs_dock.draw_check.isVisible()
    assert not window.jobs_dock.step_combo.isVisible()


def _options_survive_a_restart(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> None:
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    first = _open_window(qtbot, harness, settings=settings)
    dock = first.jobs_dock
    dock.show()
    assert not dock.draw_check.isChecked() and dock.translate_pen_check.isChecked()
    qtbot.mouseClick(dock.draw_check, Qt.MouseButton.LeftButton)
    dock.translate_pen_check.setChecked(False)
    dock.step_combo.setCurrentIndex(dock.step_combo.findData(1e-3))
    first.close()

    again = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    window = _open_window(qtbot, harness, settings=again)
    second = window.jobs_dock
    assert second.draw_check.isChecked()
    assert not second.translate_pen_check.isChecked()
    assert second.options.excellon_step_inch == 1e-3


def test_closing_removes_the_key_filter_and_stops_the_station(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    qtbot.keyPress(window.manual_panel, Qt.Key.Key_Right)
    assert window.jog.is_held(Qt.Key.Key_Right)
    window.close()
    assert not window.jog.is_held(Qt.Key.Key_Right)
    assert harness.station.session is None

    QApplication.sendEvent(
        window.manual_panel,
        QKeyEvent(QEvent.Type.KeyPress, Qt.Key.Key_Left, Qt.KeyboardModifier.NoModifier),
    )
    assert not window.jog.is_held(Qt.Key.Key_Left)


def test_f1_lists_the_keys(qtbot: QtBot, window: MainWindow) -> None:
    dialog = window.show_shortcuts()
    qtbot.waitExposed(dialog)
    text = " ".join(label.text() for label in dialog.findChildren(type(window.lock_label)))
    assert "Esc" in text and "Shift" in text
    dialog.close()


def test_shift_held_jogs_at_the_other_speed(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    qtbot.keyPress(window, Qt.Key.Key_Shift)
    qtbot.keyPress(window, Qt.Key.Key_Right, Qt.KeyboardModifier.ShiftModifier)
    harness.run(0.2)
    assert not harness.emulator.snapshot().fast[0]
    assert window.static_panel.shift_note.text() == "Shift held: slow"
    qtbot.keyRelease(window, Qt.Key.Key_Right, Qt.KeyboardModifier.ShiftModifier)
    qtbot.keyRelease(window, Qt.Key.Key_Shift)
    harness.run(0.2)
    assert harness.emulator.snapshot().fast[0]


@pytest.mark.parametrize("focus", ["window", "spin box", "dynamics field"])
def test_shift_v_toggles_the_developer_pane_from_any_focus(
    qtbot: QtBot, harness: StationHarness, focus: str
) -> None:
    window = _open_window(qtbot, harness)
    targets = {
        "window": window.manual_panel,
        "spin box": window.absolute_panel.targets[0],
        "dynamics field": window.dynamics_panel,
    }
    target = targets[focus]
    if focus == "spin box":
        window.menu_panel.set_page(1)
    target.setFocus()
    assert not window.developer_pane.isVisible()
    qtbot.keyClick(target, Qt.Key.Key_V, Qt.KeyboardModifier.ShiftModifier)
    assert window.developer_pane.isVisible()
    qtbot.keyClick(target, Qt.Key.Key_V, Qt.KeyboardModifier.ShiftModifier)
    assert not window.developer_pane.isVisible()


def test_shift_v_in_a_free_text_field_types_a_capital_v(
    qtbot: QtBot, harness: StationHarness
) -> None:
    window = _open_window(qtbot, harness)
    window.developer_pane.show()
    field = window.developer_pane.log_view.filter_edit
    field.setFocus()
    qtbot.keyClick(field, Qt.Key.Key_V, Qt.KeyboardModifier.ShiftModifier)
    # QTest gives the key event the text "v"; what matters is that the field got it.
    assert field.text().lower() == "v"
    assert window.developer_pane.isVisible()


def test_an_injected_charger_echo_reaches_the_info_panel(
    qtbot: QtBot, harness: StationHarness
) -> None:
    window = _open_window(qtbot, harness)
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_V, Qt.KeyboardModifier.ShiftModifier)
    composer = window.developer_pane.composer
    charger = composer.status_combos[0].findData(AxisStatus.BLOCKED_CHARGER)
    assert charger >= 0
    composer.status_combos[0].setCurrentIndex(charger)
    composer.data_edits[0].setText("12345")
    qtbot.mouseClick(composer.inject_button, Qt.MouseButton.LeftButton)
    assert window.info_panel.positions[0].text() == "12.345 mm"
    assert window.info_panel.statuses[0].text() == "blocked: charger connected"
    composer.data_edits[0].setText("12.5")  # malformed: refused, nothing changes
    qtbot.mouseClick(composer.inject_button, Qt.MouseButton.LeftButton)
    assert "whole number" in composer.result_label.text()
    assert window.info_panel.positions[0].text() == "12.345 mm"


def test_ctrl_j_shows_the_jobs_dock_whose_checkpoints_go_where_asked(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    assert not window.jobs_dock.isVisible()
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_J, Qt.KeyboardModifier.ControlModifier)
    assert window.jobs_dock.isVisible()
    job = tmp_path / "route.csv"
    job.write_text("1, 1\n2, 2\n")
    harness.connect()
    harness.run(3.0)
    assert window.jobs_dock.open_path(job)
    window.job_runner.start()
    harness.run_until(lambda: window.job_runner.done == 1)
    assert list((tmp_path / "checkpoints").iterdir()), "no checkpoint written after an operation"


# --- the G-code machines ------------------------------------------------------------------


@pytest.mark.parametrize("name", ["corexy-plotter", "grbl-plotter", "string-art"])
def test_a_gcode_machine_gets_its_page_and_the_arrow_keys_jog_it(qtbot: QtBot, name: str) -> None:
    plotter = StationHarness(load_profile(name))
    try:
        window = _open_window(qtbot, plotter)
        plotter.connect()
        plotter.run(0.3)
        assert window.gcode_panel is not None
        page = window.stack.indexOf(window.gcode_panel)
        qtbot.mouseClick(window.menu_panel.button(page), Qt.MouseButton.LeftButton)
        assert window.stack.currentWidget() is window.gcode_panel
        window.setFocus()
        sent = len(plotter.written)
        qtbot.keyPress(window, Qt.Key.Key_Right)
        # At once, not at the next status tick: the first jog step is already on the wire.
        # A jog line ($J= where the board has it), never a switch to relative mode.
        line = b"$J=G91 " if name == "grbl-plotter" else b"G90 G1 "
        assert any(chunk.startswith(line) for chunk in plotter.written[sent:])
        assert not any(chunk.startswith(b"G91") for chunk in plotter.written)
        plotter.run(0.5)
        qtbot.keyRelease(window, Qt.Key.Key_Right)
        plotter.run_until(lambda: plotter.gcode_session.settled, timeout=5)
        axis = plotter.station.profile.axes[0]
        assert plotter.station.model.axes[0].position > 0, f"{axis.name} did not move"
    finally:
        plotter.close()


def _start_absolute_move(qtbot: QtBot, harness: StationHarness, window: MainWindow) -> None:
    """A move that goes on by itself (unlike a jog, it needs no held key or focus)."""
    window.menu_panel.set_page(1)
    absolute = window.absolute_panel
    absolute.targets[0].setValue(40.0)
    absolute.targets[1].setValue(40.0)
    qtbot.mouseClick(absolute.go_all_button, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: all(a.moving for a in harness.station.model.axes), timeout=1)


@pytest.mark.qt_log_ignore("does not support (raise|grabbing the keyboard)")  # offscreen popups
def test_escape_in_a_menu_closes_it_and_stops(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    _start_absolute_move(qtbot, harness, window)
    menu = window.view_menu
    menu.popup(window.mapToGlobal(window.rect().center()))
    qtbot.waitUntil(menu.isVisible)
    assert QApplication.activePopupWidget() is menu
    qtbot.keyClick(menu, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not menu.isVisible())
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    assert x_position(harness) < 30


@pytest.mark.qt_log_ignore("does not support (raise|grabbing the keyboard)")  # offscreen popups
def test_escape_in_a_file_dialog_closes_its_popup_then_the_dialog_and_never_stops(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    _start_absolute_move(qtbot, harness, window)
    dialog = QFileDialog(window.jobs_dock, "Open a job", "", "Jobs (*.csv);;All files (*)")
    dialog.setOption(QFileDialog.Option.DontUseNativeDialog)
    dialog.open()
    qtbot.waitUntil(dialog.isVisible)
    types = dialog.findChild(QComboBox, "fileTypeCombo")
    assert types is not None
    types.showPopup()
    popup = QApplication.activePopupWidget()
    assert popup is not None and popup.isVisible()
    target = popup.focusWidget() or popup
    qtbot.keyClick(target, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not popup.isVisible())
    assert dialog.isVisible()  # only the list closed
    harness.run(0.2)
    assert all(a.moving for a in harness.station.model.axes)  # and the machine went on

    qtbot.keyClick(dialog, Qt.Key.Key_Escape)
    qtbot.waitUntil(lambda: not dialog.isVisible())  # the dialog is cancelled …
    harness.run(0.2)
    assert all(a.moving for a in harness.station.model.axes)  # … the move goes on
    x_before = x_position(harness)
    qtbot.keyClick(dialog, Qt.Key.Key_Down)  # arrows in a dialog never jog
    assert x_position(harness) >= x_before

    window.activateWindow()
    qtbot.keyClick(window, Qt.Key.Key_Escape)  # from the window, Esc stops
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    assert x_position(harness) < 40


def test_a_message_that_repeats_the_link_status_is_not_shown_twice(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    """The lost link is said once, by the link status; its message does not stand beside it."""
    assert harness.station.link is not None
    harness.loopback.set_manipulator(lambda _direction, _data: b"")  # the device goes silent
    harness.run_until(lambda: "lost" in window.link_status.text(), timeout=5)
    detail = harness.station.model.link_detail
    harness.station.model.message.emit(f"Link lost: {detail}")
    assert window.message_label.text() == ""
    harness.station.model.message.emit("Job aborted after 3 of 9 operations")
    assert window.message_label.text() == "Job aborted after 3 of 9 operations"


def test_a_message_about_a_failing_link_goes_when_the_link_is_back(
    qtbot: QtBot, harness: StationHarness, window: MainWindow
) -> None:
    harness.loopback.set_manipulator(lambda _direction, _data: b"")
    harness.run_until(lambda: "lost" in window.link_status.text(), timeout=5)
    harness.station.model.message.emit("Stopped: 4 line(s) not run")
    assert window.message_label.text() == "Stopped: 4 line(s) not run"
    harness.loopback.set_manipulator(None)  # the device answers again, the port never closed
    harness.run_until(lambda: window.link_status.text().startswith("Link connected"), timeout=10)
    # Only the news that it is back stands, not the failure's.
    assert window.message_label.text().startswith("The device answers again")
    # A message said while the link is up stays its time.
    harness.station.model.message.emit("hello operator")
    harness.run(0.5)
    assert window.message_label.text() == "hello operator"


def test_the_first_window_imports_no_dock_and_no_plotting() -> None:
    """The jobs dock (job formats, preview), the plots (pyqtgraph), the developer pane, the
    emulators, the BLE transport (bleak, asyncio), the package metadata and the pages of
    other machines (drill, usb3, G-code with its overrides, stored settings) load on first
    use: a fresh interpreter that builds and shows the XY stage's window has none of them."""
    import subprocess
    import sys

    code = (
        "import sys; from PySide6.QtWidgets import QApplication; app = QApplication([]);"
        "from app.profiles import load_profile; from app.station import Station;"
        "from widgets.main_window import MainWindow;"
        "s = Station(load_profile('xy-stage')); w = MainWindow(s); w.show(); app.processEvents();"
        "print(' '.join(sorted(m for m in ('pyqtgraph', 'widgets.jobs.dock',"
        " 'widgets.telemetry_dock', 'widgets.developer.pane', 'app.jobs.run.runner',"
        " 'protocol.emulator.gcode_firmware', 'protocol.emulator.stage_firmware',"
        " 'protocol.transport.ble', 'importlib.metadata', 'widgets.panels.drill',"
        " 'widgets.panels.usb3', 'widgets.panels.gcode', 'widgets.panels.gcode_overrides',"
        " 'widgets.panels.stored_settings')"
        " if m in sys.modules))); s.shutdown()"
    )
    root = Path(__file__).resolve().parents[2]
    env = {**__import__("os").environ, "QT_QPA_PLATFORM": "offscreen"}
    result = subprocess.run(
        [sys.executable, "-c", code], cwd=root, env=env, capture_output=True, text=True, check=True
    )
    assert result.stdout.strip() == ""


def test_docks_are_built_when_first_shown_with_what_came_before(
    qtbot: QtBot, harness: StationHarness
) -> None:
    window = _open_window(qtbot, harness)
    assert window.docks.built() == [] and not window.docks.runner_built
    harness.connect()
    harness.session.move_absolute(0, 1.0)
    harness.run(2.0)
    qtbot.keyClick(window, Qt.Key.Key_T, Qt.KeyboardModifier.ControlModifier)
    dock = window.telemetry_dock
    assert dock.isVisible() and window.telemetry_action.isChecked()
    t, x = dock._curves["X position"].getData()
    assert len(t) > 10 and x[-1] == 1.0  # recorded before the dock existed
    qtbot.keyClick(window, Qt.Key.Key_V, Qt.KeyboardModifier.ShiftModifier)
    pane = window.developer_pane
    assert pane.isVisible() and window.developer_action.isChecked()
    assert len(pane.frame_log) > 10  # frames logged before the pane existed
    # Tabbed with the plots; its own toggle and the menu's entry agree.
    assert pane in window.tabifiedDockWidgets(dock)
    pane.toggleViewAction().trigger()
    assert not pane.isVisible() and not window.developer_action.isChecked()
    # Stop with no job runner built yet is only a stop.
    window.jog.stopRequested.emit()
    assert not window.docks.runner_built


def test_docks_shown_at_close_are_back_at_the_next_start(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    first = _open_window(qtbot, harness, settings=settings)
    first.telemetry_action.trigger()
    first.jobs_action.trigger()
    first.jobs_action.trigger()  # built, then hidden again
    assert first.telemetry_dock.isVisible() and not first.jobs_dock.isVisible()
    first.close()

    again = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    second = MainWindow(harness.station, again)
    qtbot.addWidget(second)
    # Built after the window's first paint, so the window shows as fast as a bare one.
    assert not second.docks.built() and second.docks_restored.pending
    second.show()
    qtbot.waitUntil(lambda: not second.docks_restored.pending)
    built = second.docks.built()  # the plots only: the jobs dock and the pane wait
    assert [dock.objectName() for dock in built] == ["telemetry_dock"] and built[0].isVisible()
    assert second.telemetry_action.isChecked()
    assert not second.jobs_action.isChecked()
    second.jobs_action.trigger()  # placed where the first window had it
    assert second.jobs_dock.isVisible()
    assert second.dockWidgetArea(second.jobs_dock) == Qt.DockWidgetArea.RightDockWidgetArea
    second.close()


def test_a_window_closed_before_its_first_paint_keeps_the_docks_it_was_given(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    """The docks wait for the first paint; saving before it must not forget them."""
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    first = _open_window(qtbot, harness, settings=settings)
    first.telemetry_action.trigger()
    first.close()
    unshown = MainWindow(
        harness.station, QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    )
    qtbot.addWidget(unshown)
    assert not unshown.docks.built()
    unshown.save_settings()
    third = MainWindow(
        harness.station, QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    )
    qtbot.addWidget(third)
    third.show()
    qtbot.waitUntil(lambda: bool(third.docks.built()))
    assert third.telemetry_dock.isVisible() and third.telemetry_action.isChecked()


@pytest.mark.parametrize("profile", available_profiles())
def test_a_dock_built_while_the_window_is_active_leaves_it_the_keyboard(
    qtbot: QtBot, profile: str
) -> None:
    """Options the machine does not offer were shown as windows of their own for a moment."""
    harness = StationHarness(load_profile(profile))
    try:
        window = _open_window(qtbot, harness)
        for action in (window.jobs_action, window.telemetry_action, window.developer_action):
            action.trigger()
            QApplication.processEvents()
            assert window.isActiveWindow(), action.text()
    finally:
        harness.close()
