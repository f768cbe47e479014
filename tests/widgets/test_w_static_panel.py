"""Static panel: speed selection, Sleep/Wake and the big Stop."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from tests.helpers.harness import StationHarness
from widgets.jog_input import JogInput
from widgets.panels.static import StaticPanel

# The offscreen platform warns whenever a shown window's layout sets its size limits.

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def jog(harness: StationHarness) -> JogInput:
    return JogInput(harness.station)


@pytest.fixture
def panel(qtbot: QtBot, harness: StationHarness, jog: JogInput) -> StaticPanel:
    panel = StaticPanel(harness.station, jog)
    qtbot.addWidget(panel)
    panel.show()
    harness.connect()
    harness.run(1.5)
    return panel


def test_slow_and_fast_reach_the_device(
    qtbot: QtBot, harness: StationHarness, panel: StaticPanel
) -> None:
    assert panel.fast_button.isChecked() and harness.emulator.snapshot().fast[0]
    qtbot.mouseClick(panel.slow_button, LEFT)
    harness.run(0.1)
    assert not harness.emulator.snapshot().fast[0] and not harness.emulator.snapshot().fast[1]
    assert not harness.session.fast_selected
    qtbot.mouseClick(panel.fast_button, LEFT)
    harness.run(0.1)
    assert harness.emulator.snapshot().fast[0]


def test_shift_is_announced(panel: StaticPanel, jog: JogInput) -> None:
    jog.set_shift(True)
    assert panel.shift_note.text() == "Shift held: slow"
    jog.set_shift(False)
    assert panel.shift_note.text() == ""


def test_the_speed_choice_survives_a_reconnect(
    qtbot: QtBot, harness: StationHarness, panel: StaticPanel
) -> None:
    qtbot.mouseClick(panel.slow_button, LEFT)
    harness.station.close_link()
    harness.connect()
    harness.run(0.3)
    assert not harness.session.fast_selected
    assert not harness.emulator.snapshot().fast[0]


def test_stop_stops_every_axis(qtbot: QtBot, harness: StationHarness, panel: StaticPanel) -> None:
    harness.session.move_absolute(0, 40.0)
    harness.session.move_absolute(1, 40.0)
    harness.run(0.8)
    qtbot.mouseClick(panel.stop_button, LEFT)
    harness.run_until(lambda: not harness.station.model.any_moving, timeout=2)
    assert [a.status_text for a in harness.station.model.axes] == ["stopped", "stopped"]


def test_sleep_button_follows_the_device(
    qtbot: QtBot, harness: StationHarness, panel: StaticPanel
) -> None:
    qtbot.mouseClick(panel.sleep_button, LEFT)
    assert panel.sleep_button.text() == "Wake"  # shown at once
    harness.run(0.3)
    assert harness.emulator.snapshot().sleeping and harness.station.model.sleeping
    # A charger outranks "sleeping" in the statuses; the device flags still say asleep,
    # so the model and the button keep offering Wake.
    harness.emulator.charger_connected = True
    harness.run(1.5)
    assert harness.station.model.block_reason == "blocked: charger connected"
    assert harness.station.model.sleeping
    assert panel.sleep_button.text() == "Wake"
    harness.emulator.charger_connected = False
    qtbot.mouseClick(panel.sleep_button, LEFT)
    harness.run(0.3)
    assert not harness.emulator.snapshot().sleeping
    assert panel.sleep_button.text() == "Sleep"
