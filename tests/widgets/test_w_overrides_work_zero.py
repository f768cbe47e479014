"""Overrides and work zero in the window, as the operator clicks and types them.

On the GRBL plotter the G-code page shows both boxes; F5…F8 press the override
buttons from anywhere in the window (Help → Keys lists them).  The outcome is read
from the emulated board (its overrides, position and offsets) and the labels the
operator reads, never from the buttons themselves.  The CoreXY plotter's firmware
has neither: the boxes are hidden and the keys do nothing.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow


@pytest.fixture
def plotter(qapp: object) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.settled, timeout=5)
    try:
        yield harness
    finally:
        harness.close()


def window_for(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> MainWindow:
    window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitExposed(window)
    return window


def click(qtbot: QtBot, button: object) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)  # type: ignore[arg-type]


def test_feed_buttons_and_keys_set_the_boards_override_and_the_label_shows_ov(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    window = window_for(qtbot, plotter, tmp_path)
    panel = window.pages.gcode
    assert panel is not None
    box, emulator, session = panel.overrides, plotter.gcode_emulator, plotter.gcode_session
    assert not box.isHidden()
    click(qtbot, box.feed_minus_10)
    click(qtbot, box.feed_minus_10)  # from what was asked: 80 %
    plotter.run_until(lambda: session.overrides.wanted is None, timeout=10)
    assert emulator.overrides == (80, 100)
    assert box.feed_label.text().strip() == "80 %"
    # The keys, with focus on another page's widget: F6 +10, Shift+F5 -1, F8 rapid 50 %.
    focus = window.manual_panel  # another page's widget: the keys are the window's
    qtbot.keyClick(focus, Qt.Key.Key_F6)
    plotter.run_until(lambda: session.overrides.wanted is None, timeout=10)
    qtbot.keyClick(focus, Qt.Key.Key_F5, Qt.KeyboardModifier.ShiftModifier)
    plotter.run_until(lambda: session.overrides.wanted is None, timeout=10)
    qtbot.keyClick(focus, Qt.Key.Key_F8)
    plotter.run_until(lambda: session.overrides.wanted is None, timeout=10)
    assert emulator.overrides == (89, 50)
    assert box.rapid_buttons[50].isChecked() and box.rapid_label.text().strip() == "50 %"
    qtbot.keyClick(focus, Qt.Key.Key_F7)
    plotter.run_until(lambda: session.overrides.wanted is None, timeout=10)
    assert emulator.overrides == (100, 50)


def test_help_keys_lists_the_override_keys(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    window = window_for(qtbot, plotter, tmp_path)
    dialog = window.show_shortcuts()
    text = " ".join(label.text() for label in dialog.findChildren(QLabel))
    assert "F5 / F6" in text and "Feed override -10 % / +10 %" in text and "F8" in text


def test_zero_here_select_and_go_to_zero_with_clicks_and_the_dro_shows_the_offset(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    window = window_for(qtbot, plotter, tmp_path)
    panel = window.pages.gcode
    assert panel is not None
    box, emulator, session = panel.work_zero, plotter.gcode_emulator, plotter.gcode_session
    assert session.move_absolute(0, 30.0) and session.move_absolute(1, 40.0)
    plotter.run_until(lambda: session.settled, timeout=10)
    click(qtbot, box.zero_buttons["X"])
    plotter.run_until(lambda: session.settled and (session.work.offset or (0,))[0] == 30, 5)
    assert emulator.work_offset()["X"] == 30.0 and emulator.work_offset()["Y"] == 0.0
    click(qtbot, box.zero_all_button)
    plotter.run_until(lambda: session.settled and (session.work.offset or (0, 0))[1] == 40, 5)
    assert box.work_label.text().split() == ["G54", "X", "30.000", "Y", "40.000"]
    assert panel.position_label.text().split() == ["X", "0.000", "Y", "0.000"]
    assert session.move_absolute(0, 120.0)
    plotter.run_until(lambda: session.settled, timeout=10)
    click(qtbot, box.go_button)
    plotter.run_until(lambda: session.settled, timeout=10)
    assert emulator.position()["X"] == pytest.approx(30.0)
    # Choose G55: its own (zero) offset.
    click(qtbot, box.system_buttons["G55"])
    plotter.run_until(lambda: session.settled and session.work.system == "G55", 5)
    plotter.run_until(lambda: session.work.offset == (0.0, 0.0, 0.0), 5)
    assert box.work_label.text().split()[0] == "G55" and box.system_buttons["G55"].isChecked()
    assert not box.system_buttons["G54"].isChecked()
    assert emulator.work_offset() == {"X": 0.0, "Y": 0.0, "Z": 0.0}


def test_work_zero_is_refused_while_a_job_holds_the_machine(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    window = window_for(qtbot, plotter, tmp_path)
    panel = window.pages.gcode
    assert panel is not None
    said: list[str] = []
    plotter.station.model.message.connect(said.append)
    plotter.station.model.set_jog_lock("a job is under way")
    mark = len(plotter.written)
    box = panel.work_zero
    # The buttons may be off while the job runs; the session refuses them anyway.
    for action in (lambda: box.zero(["X"]), box.go_to_zero):
        assert not action()
    assert [w for w in plotter.written[mark:] if w != b"?"] == []
    assert any("a job is under way" in s for s in said)


def test_the_corexy_plotter_shows_neither_box_and_f5_does_nothing(
    qtbot: QtBot, qapp: object, tmp_path: Path
) -> None:
    harness = StationHarness(load_profile("corexy-plotter"))
    harness.connect()
    try:
        harness.run(0.5)
        window = window_for(qtbot, harness, tmp_path)
        panel = window.pages.gcode
        assert panel is not None
        assert panel.overrides.isHidden() and panel.work_zero.isHidden()
        mark = len(harness.written)
        qtbot.keyClick(window.manual_panel, Qt.Key.Key_F5)
        harness.run(0.3)
        assert [w for w in harness.written[mark:] if w != b"?"] == []
    finally:
        harness.close()
