"""Relative panel: stepping an axis by its increment, forward and back."""

from __future__ import annotations

from typing import NamedTuple

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QVBoxLayout, QWidget
from pytestqt.qtbot import QtBot

from tests.helpers.harness import StationHarness
from widgets.panels.info import InfoPanel
from widgets.panels.relative import RelativePanel


class Panels(NamedTuple):
    panel: RelativePanel
    info: InfoPanel
    host: QWidget  # keeps the panels alive


# The offscreen platform warns whenever a shown window's layout sets its size limits.


@pytest.fixture
def panels(qtbot: QtBot, harness: StationHarness) -> Panels:
    info = InfoPanel(harness.station.model)
    panel = RelativePanel(harness.station)
    host = QWidget()
    layout = QVBoxLayout(host)
    layout.addWidget(info)
    layout.addWidget(panel)
    qtbot.addWidget(host)
    host.show()
    harness.connect()
    harness.run(1.5)
    return Panels(panel, info, host)


def _step_and_settle(
    qtbot: QtBot, harness: StationHarness, info: InfoPanel, button: QWidget
) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)
    harness.run_until(lambda: harness.station.model.axes[0].moving, timeout=1)
    harness.run_until(lambda: info.statuses[0].text() == "target reached", timeout=5)


def test_plus_one_and_a_half_twice_gives_three(
    qtbot: QtBot, harness: StationHarness, panels: Panels
) -> None:
    panel, info, _ = panels
    panel.increments[0].setValue(1.5)
    _step_and_settle(qtbot, harness, info, panel.plus_buttons[0])
    assert info.positions[0].text() == "1.500 mm"
    _step_and_settle(qtbot, harness, info, panel.plus_buttons[0])
    assert info.positions[0].text() == "3.000 mm"
    assert info.positions[1].text() == "0.000 mm"


def test_minus_moves_back(qtbot: QtBot, harness: StationHarness, panels: Panels) -> None:
    panel, info, _ = panels
    panel.increments[0].setValue(4.0)
    _step_and_settle(qtbot, harness, info, panel.plus_buttons[0])
    panel.increments[0].setValue(1.25)
    _step_and_settle(qtbot, harness, info, panel.minus_buttons[0])
    assert info.positions[0].text() == "2.750 mm"


def test_an_increment_beyond_the_travel_stays_as_typed_and_moves_nothing(
    qtbot: QtBot, harness: StationHarness, panels: Panels
) -> None:
    panel = panels.panel
    box = panel.increments[0]
    qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    qtbot.keyClick(box, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(box, "80")
    assert box.text() == "80" and box.value() is None
    assert "X increment: 80 is outside 0.001…50 mm" in panel.note.text()
    assert not panel.plus_buttons[0].isEnabled() and not panel.minus_buttons[0].isEnabled()
    assert panel.step(0, +1) is False
    harness.run(1.0)
    assert not harness.station.model.any_moving
    assert harness.emulator.axes[0].position_um == 0
