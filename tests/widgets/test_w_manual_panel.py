"""Manual panel: hold-to-jog buttons, their sharing of the jog with keys, and Home."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QVBoxLayout, QWidget
from pytestqt.qtbot import QtBot

from tests.helpers.harness import StationHarness
from widgets.jog_input import JogInput
from widgets.panels.info import InfoPanel
from widgets.panels.manual import ManualPanel

# The offscreen platform warns whenever a shown window's layout sets its size limits.

LEFT = Qt.MouseButton.LeftButton


class Rig:
    """A manual panel under an info panel, on a connected emulated stage."""

    def __init__(self, qtbot: QtBot, harness: StationHarness) -> None:
        self.harness = harness
        self.jog = JogInput(harness.station)
        self.info = InfoPanel(harness.station.model)
        self.panel = ManualPanel(harness.station, self.jog)
        self.host = QWidget()
        layout = QVBoxLayout(self.host)
        layout.addWidget(self.info)
        layout.addWidget(self.panel)
        qtbot.addWidget(self.host)
        self.host.show()
        harness.connect()
        harness.run(1.5)

    def moving(self, axis: int) -> bool:
        return self.harness.station.model.axes[axis].moving

    def wait_until_still(self) -> None:
        self.harness.run_until(lambda: not self.harness.station.model.any_moving, timeout=3)


@pytest.fixture
def rig(qtbot: QtBot) -> Iterator[Rig]:
    harness = StationHarness()
    yield Rig(qtbot, harness)
    harness.close()


def test_holding_x_plus_jogs_until_released(qtbot: QtBot, rig: Rig) -> None:
    button = rig.panel.jog_buttons[(1, 0)]
    qtbot.mousePress(button, LEFT)
    rig.harness.run(1.0)
    assert rig.moving(0) and not rig.moving(1)
    assert rig.harness.station.model.axes[0].position > 1

    qtbot.mouseRelease(button, LEFT)
    rig.wait_until_still()
    assert rig.harness.session.jog_vector == (0, 0)


def test_diagonal_button_jogs_both_axes(qtbot: QtBot, rig: Rig) -> None:
    button = rig.panel.jog_buttons[(1, 1)]
    qtbot.mousePress(button, LEFT)
    rig.harness.run(1.0)
    assert rig.moving(0) and rig.moving(1)
    assert rig.harness.session.jog_vector == (1, 1)
    qtbot.mouseRelease(button, LEFT)
    rig.wait_until_still()


def test_releasing_a_button_keeps_a_held_key_jogging(qtbot: QtBot, rig: Rig) -> None:
    rig.jog.key_press(Qt.Key.Key_Right)
    button = rig.panel.jog_buttons[(0, 1)]
    qtbot.mousePress(button, LEFT)
    rig.harness.run(0.5)
    assert rig.harness.session.jog_vector == (1, 1)
    qtbot.mouseRelease(button, LEFT)
    rig.harness.run(1.0)
    assert rig.harness.session.jog_vector == (1, 0)
    assert rig.moving(0) and not rig.moving(1)
    rig.jog.key_release(Qt.Key.Key_Right)
    rig.wait_until_still()


def test_locking_while_a_button_is_held_stops_the_jog(qtbot: QtBot, rig: Rig) -> None:
    button = rig.panel.jog_buttons[(-1, 0)]
    rig.harness.session.move_absolute(0, 10.0)
    rig.harness.run_until(lambda: rig.info.statuses[0].text() == "target reached", timeout=3)
    qtbot.mousePress(button, LEFT)
    rig.harness.run(0.3)
    assert rig.moving(0)
    rig.panel.set_motion_enabled(False)  # the window does this when motion gets locked
    assert not button.isDown()
    rig.wait_until_still()
    assert rig.harness.session.jog_vector == (0, 0)


def test_centre_stop_stops_a_move(qtbot: QtBot, rig: Rig) -> None:
    rig.harness.session.move_absolute(0, 40.0)
    rig.harness.run(0.5)
    qtbot.mouseClick(rig.panel.stop_button, LEFT)
    rig.wait_until_still()
    assert rig.info.statuses[0].text() == "stopped"
    assert rig.harness.emulator.axes[0].position_um < 30_000


def test_home_x_shows_homing_and_ends_at_zero(qtbot: QtBot, rig: Rig) -> None:
    rig.harness.session.move_absolute(0, 3.0)
    rig.harness.run_until(lambda: rig.info.statuses[0].text() == "target reached", timeout=3)
    assert rig.info.positions[0].text() == "3.000 mm"

    qtbot.mouseClick(rig.panel.home_buttons[0], LEFT)
    rig.harness.run_until(lambda: rig.info.statuses[0].text() == "homing", timeout=1)
    assert rig.info.positions[0].text() != "0.000 mm"
    rig.wait_until_still()
    rig.harness.run(0.3)
    assert rig.info.positions[0].text() == "0.000 mm"
    assert rig.info.statuses[0].text() != "homing"


def test_buttons_name_their_keys(rig: Rig) -> None:
    assert "→" in rig.panel.jog_buttons[(1, 0)].toolTip()
    assert "Esc" in rig.panel.stop_button.toolTip()
