"""The G-code page: the console as an operator types into it, and the machine buttons."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.panels.gcode import GcodePanel


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[tuple[StationHarness, GcodePanel]]:
    harness = StationHarness(load_profile("corexy-plotter"))
    harness.connect()
    harness.run(0.05)
    panel = GcodePanel(harness.station)
    qtbot.addWidget(panel)
    try:
        yield harness, panel
    finally:
        harness.close()


def type_line(qtbot: QtBot, panel: GcodePanel, text: str) -> None:
    panel.entry.setFocus()
    qtbot.keyClicks(panel.entry, text)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)


def test_a_typed_line_is_sent_answered_and_kept_in_the_history(
    qtbot: QtBot, plotter: tuple[StationHarness, GcodePanel]
) -> None:
    harness, panel = plotter
    type_line(qtbot, panel, "G0 X12 Y3")
    harness.run_until(lambda: "< ok" in panel.output.toPlainText(), timeout=2)
    assert panel.output.toPlainText().splitlines()[:2] == ["> G0 X12 Y3", "< ok  ← G0 X12 Y3"]
    harness.run_until(lambda: harness.gcode_session.settled, timeout=5)
    harness.run(0.3)
    assert panel.state_label.text().startswith("Idle")
    assert "X    12.000" in panel.position_label.text()
    type_line(qtbot, panel, "G7")
    harness.run_until(lambda: "error:20" in panel.output.toPlainText(), timeout=2)
    assert panel.history == ("G0 X12 Y3", "G7")
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    assert panel.entry.text() == "G0 X12 Y3"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    assert panel.entry.text() == ""


def test_a_line_the_device_could_never_take_is_refused_before_the_wire(
    qtbot: QtBot, plotter: tuple[StationHarness, GcodePanel]
) -> None:
    harness, panel = plotter
    before = len(harness.written)
    type_line(qtbot, panel, "G1 X" + "1" * 90)
    assert "not sent" in panel.output.toPlainText()
    assert not any(b"G1 X111" in chunk for chunk in harness.written[before:])


def test_pen_buttons_send_the_plotters_own_commands(
    qtbot: QtBot, plotter: tuple[StationHarness, GcodePanel]
) -> None:
    harness, panel = plotter
    qtbot.mouseClick(panel.pen_down_button, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: harness.gcode_session.settled, timeout=5)
    assert harness.gcode_emulator.pen_down
    qtbot.mouseClick(panel.pen_up_button, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: harness.gcode_session.settled, timeout=5)
    assert not harness.gcode_emulator.pen_down
    assert b"M4\n" in b"".join(harness.written) and b"M3\n" in b"".join(harness.written)
