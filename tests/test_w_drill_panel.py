"""The drill's page driven as the operator drives it: clicks, typing, Up/Down, Enter.

Against the emulated plotter on a manual clock; asserting what goes on the
wire, what the columns and the terminal then show, and the main window's
pages on the pcb-drill profile.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QListWidget, QPushButton
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.panels.drill import DrillPanel


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    yield harness
    harness.close()


@pytest.fixture
def panel(qtbot: QtBot, drill: StationHarness) -> DrillPanel:
    drill.connect()
    drill.run(0.02)
    built = DrillPanel(drill.station)
    qtbot.addWidget(built)
    built.show()
    qtbot.waitExposed(built)
    return built


def click(qtbot: QtBot, button: QPushButton) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def items(widget: QListWidget) -> list[str]:
    return [widget.item(i).text() for i in range(widget.count())]


def type_line(qtbot: QtBot, panel: DrillPanel, text: str) -> None:
    qtbot.mouseClick(panel.entry, Qt.MouseButton.LeftButton)
    panel.entry.selectAll()
    qtbot.keyClicks(panel.entry, text)


def test_n_button_fills_received_then_done(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    mark = len(drill.written)
    click(qtbot, panel.command_buttons["N"])
    assert drill.written[mark:] == [b"N\r"]
    assert items(panel.received_list) == []
    drill.run_until(lambda: panel.received_list.count() == 1)
    assert items(panel.received_list) == ["N"]
    assert items(panel.done_list) == []  # homing takes seconds
    drill.run_until(lambda: panel.done_list.count() == 1)
    assert items(panel.done_list) == ["N"]
    assert drill.drill_emulator.homed
    lines = panel.output.toPlainText().splitlines()
    assert lines == ["> N", "< RN", "< DN"]


def test_axis_send_uses_the_microstep_box(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    box = panel.targets[0]
    qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    qtbot.keyClick(box, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(box, "248")
    assert box.value() == 248
    mark = len(drill.written)
    click(qtbot, panel.send_buttons[0])
    assert drill.written[mark:] == [b"X248\r"]
    drill.run_until(lambda: panel.done_list.count() == 1)
    assert drill.station.model.axes[0].position == pytest.approx(248 / 19.8)


def test_terminal_send_history_and_cls(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    mark = len(drill.written)
    type_line(qtbot, panel, "K")
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)
    assert panel.entry.text() == ""
    drill.run_until(lambda: panel.done_list.count() == 1)
    type_line(qtbot, panel, "Z")
    click(qtbot, panel.send_button)
    drill.run_until(lambda: panel.done_list.count() == 2)
    assert drill.written[mark:] == [b"K\r", b"Z\r"]
    assert items(panel.received_list) == ["K", "Z"]
    assert items(panel.done_list) == ["K", "Z"]
    assert panel.history == ("K", "Z")
    assert "< DK" in panel.output.toPlainText()

    # Garbage is refused before the wire and said in the terminal.
    type_line(qtbot, panel, "hello")
    click(qtbot, panel.send_button)
    assert drill.written[mark:] == [b"K\r", b"Z\r"]
    assert "! hello: not sent" in panel.output.toPlainText()
    assert drill.drill_session.refused_lines == 1

    # Up walks back through what was typed, Down forward and off the end.
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    assert panel.entry.text() == "hello"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    assert panel.entry.text() == "Z"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    assert panel.entry.text() == "K"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    assert panel.entry.text() == "Z"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    assert panel.entry.text() == ""
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)  # resend Z from history
    assert drill.written[mark:] == [b"K\r", b"Z\r", b"Z\r"]

    click(qtbot, panel.clear_button)
    assert panel.output.toPlainText() == ""
    assert panel.received_list.count() == 0
    assert panel.done_list.count() == 0


def test_buttons_follow_the_motion_lock(qtbot: QtBot, drill: StationHarness) -> None:
    window = MainWindow(drill.station)
    qtbot.addWidget(window)
    assert not window.drill_panel.command_buttons["V"].isEnabled()
    drill.connect()
    drill.run(0.02)
    assert window.drill_panel.command_buttons["V"].isEnabled()
    assert window.drill_panel.send_buttons[1].isEnabled()


def test_main_window_has_a_drill_page_and_no_absolute_or_relative(
    qtbot: QtBot, drill: StationHarness
) -> None:
    window = MainWindow(drill.station)
    qtbot.addWidget(window)
    titles = [b.text() for b in window.menu_panel.findChildren(QPushButton)]
    assert "D&rill" in titles
    assert not any(t in titles for t in ("&Absolute", "&Relative", "&Dynamics"))
    assert not hasattr(window, "absolute_panel")
