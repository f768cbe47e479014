"""Absolute panel: targets limited to the travel, Go per axis and Go all."""

from __future__ import annotations

from typing import NamedTuple

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QVBoxLayout, QWidget
from pytestqt.qtbot import QtBot

from tests.helpers.harness import StationHarness
from widgets.panels.absolute import AbsolutePanel
from widgets.panels.info import InfoPanel


class Panels(NamedTuple):
    panel: AbsolutePanel
    info: InfoPanel
    host: QWidget  # keeps the panels alive


# The offscreen platform warns whenever a shown window's layout sets its size limits.


@pytest.fixture
def panels(qtbot: QtBot, harness: StationHarness) -> Panels:
    info = InfoPanel(harness.station.model)
    panel = AbsolutePanel(harness.station)
    host = QWidget()
    layout = QVBoxLayout(host)
    layout.addWidget(info)
    layout.addWidget(panel)
    qtbot.addWidget(host)
    host.show()
    harness.connect()
    harness.run(1.5)
    return Panels(panel, info, host)


def test_go_x_to_20_reaches_the_target(
    qtbot: QtBot, harness: StationHarness, panels: Panels
) -> None:
    panel, info, _ = panels
    panel.targets[0].setValue(20.0)
    qtbot.mouseClick(panel.go_buttons[0], Qt.MouseButton.LeftButton)
    harness.run_until(lambda: info.statuses[0].text() == "target reached", timeout=5)
    assert info.positions[0].text() == "20.000 mm"
    assert info.positions[1].text() == "0.000 mm"
    assert harness.emulator.axes[0].position_um == pytest.approx(20_000, abs=1)


def test_go_all_moves_every_axis(qtbot: QtBot, harness: StationHarness, panels: Panels) -> None:
    panel, info, _ = panels
    panel.targets[0].setValue(5.5)
    panel.targets[1].setValue(7.25)
    qtbot.mouseClick(panel.go_all_button, Qt.MouseButton.LeftButton)
    harness.run_until(
        lambda: [s.text() for s in info.statuses] == ["target reached"] * 2, timeout=5
    )
    assert [p.text() for p in info.positions] == ["5.500 mm", "7.250 mm"]


def test_targets_are_limited_to_the_travel(panels: Panels) -> None:
    panel = panels.panel
    panel.targets[0].setValue(80.0)
    panel.targets[1].setValue(-3.0)
    assert (panel.targets[0].value(), panel.targets[1].value()) == (50.0, 0.0)


def test_go_without_a_connection_is_refused(qtbot: QtBot, harness: StationHarness) -> None:
    panel = AbsolutePanel(harness.station)
    qtbot.addWidget(panel)
    assert panel.go(0) is False
