"""The G-code page explains a GRBL alarm once, with the buttons that clear it."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.panels.gcode import GcodePanel

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[tuple[StationHarness, GcodePanel]]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    panel = GcodePanel(harness.station)
    qtbot.addWidget(panel)
    panel.show()
    try:
        yield harness, panel
    finally:
        harness.close()


def test_a_soft_limit_alarm_is_explained_once_and_unlock_clears_it(
    plotter: tuple[StationHarness, GcodePanel],
) -> None:
    harness, panel = plotter
    band = panel.alarm_band
    assert not band.isVisible()
    harness.gcode_emulator.trigger_alarm(2)
    harness.run_until(lambda: band.isVisible(), timeout=2)
    assert band.title.text() == "ALARM:2"
    assert "exceeds machine travel" in band.meaning.text()
    assert "$X" in band.action.text()
    assert band.unlock_button.isVisible() and band.home_button.isVisible()
    shown = band.explainer.shown
    # The board refuses every line while in alarm (error:9): nothing new is shown.
    harness.gcode_session.send_line("G0 X1", "console")
    harness.run(0.5)
    assert band.explainer.shown is shown and band.title.text() == "ALARM:2"
    band.unlock_button.click()
    harness.run_until(lambda: not band.isVisible(), timeout=3)
    lines = [e["text"] for e in harness.gcode_emulator.event_log if e["event"] == "line"]
    assert lines[-1] == "$X"
    assert harness.gcode_session.machine_state != "Alarm"


def test_a_hard_limit_offers_homing_only(plotter: tuple[StationHarness, GcodePanel]) -> None:
    harness, panel = plotter
    band = panel.alarm_band
    harness.gcode_emulator.trigger_alarm(1)
    harness.run_until(lambda: band.isVisible(), timeout=2)
    assert band.home_button.isVisible() and not band.unlock_button.isVisible()
    assert "limit switches" in band.action.text()
    band.home_button.click()
    harness.run(0.2)
    lines = [e["text"] for e in harness.gcode_emulator.event_log if e["event"] == "line"]
    assert lines[-1] == "$H"
