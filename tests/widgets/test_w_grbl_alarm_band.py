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
    assert band.reset_button.isVisible()  # GRBL's lock: it answers nothing until a reset
    shown = band.explainer.shown
    # The board takes nothing while locked, then refuses lines in alarm: nothing new shown.
    harness.gcode_session.send_line("G0 X1", "console")
    harness.run(0.5)
    assert band.explainer.shown is shown and band.title.text() == "ALARM:2"
    band.unlock_button.click()  # resets first, $X after the banner
    harness.run_until(lambda: not band.isVisible(), timeout=3)
    read = lines(harness)
    assert read[-2:] == ["reset", "$X"] and "G0 X1" not in read
    assert harness.gcode_session.machine_state != "Alarm"


def test_reset_ends_the_lock_after_a_limit_and_leaves_unlock_and_home(
    plotter: tuple[StationHarness, GcodePanel], qtbot: QtBot
) -> None:
    harness, panel = plotter
    band = panel.alarm_band
    harness.gcode_emulator.trigger_alarm(2)
    harness.run_until(lambda: band.reset_button.isVisible(), timeout=2)
    moves = len([e for e in harness.gcode_emulator.event_log if e["event"] == "move"])
    written = len(harness.written)
    qtbot.mouseClick(band.reset_button, LEFT)
    harness.run_until(lambda: not band.reset_button.isVisible(), timeout=3)
    assert [w for w in harness.written[written:] if w != b"?"] == [b"\x18"]
    harness.run_until(lambda: harness.gcode_session.machine_state == "Alarm", timeout=2)
    assert band.isVisible() and band.unlock_button.isVisible() and band.home_button.isVisible()
    assert "reset" not in harness.station.model.link_detail
    assert len([e for e in harness.gcode_emulator.event_log if e["event"] == "move"]) == moves


def test_a_hard_limit_offers_homing_only(plotter: tuple[StationHarness, GcodePanel]) -> None:
    harness, panel = plotter
    band = panel.alarm_band
    harness.gcode_emulator.trigger_alarm(1)
    harness.run_until(lambda: band.isVisible(), timeout=2)
    assert band.home_button.isVisible() and not band.unlock_button.isVisible()
    assert "limit switches" in band.action.text()
    band.home_button.click()  # the board is reset first: $H follows its banner
    harness.run_until(lambda: bool(lines(harness)) and lines(harness)[-1] == "$H", timeout=3)
    assert lines(harness)[-2:] == ["reset", "$H"]


def lines(harness: StationHarness) -> list[str]:
    """The lines the board read and its resets, in order."""
    return [
        str(e.get("text", e["event"]))
        for e in harness.gcode_emulator.event_log
        if e["event"] in ("line", "reset")
    ]
