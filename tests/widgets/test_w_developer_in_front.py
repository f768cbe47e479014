"""Shift+V shows the developer pane in front, and hides it again, as the original's did.

With the plots open the two share the bottom as tabs; a pane shown behind the
Telemetry tab looked as if the key had done nothing.
"""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget, QTabBar
from pytestqt.qtbot import QtBot

from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

SHIFT = Qt.KeyboardModifier.ShiftModifier


@pytest.fixture
def window(qtbot: QtBot, harness: StationHarness) -> MainWindow:
    built = MainWindow(harness.station)
    qtbot.addWidget(built)
    built.resize(1280, 800)
    built.show()
    built.activateWindow()
    qtbot.waitUntil(built.isActiveWindow)
    harness.connect()
    return built


def in_front(dock: QDockWidget) -> bool:
    """Shown and not covered by another dock's tab: some of it is on the screen."""
    return dock.isVisible() and not dock.visibleRegion().isEmpty()


def bottom_tabs(window: MainWindow) -> QTabBar:
    for bar in window.findChildren(QTabBar):
        titles = {bar.tabText(i) for i in range(bar.count())}
        if {"Telemetry", "Developer"} <= titles and bar.isVisible():
            return bar
    raise AssertionError("no tab bar holds Telemetry and Developer")


def shift_v(qtbot: QtBot, window: MainWindow) -> None:
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_V, SHIFT)
    qtbot.wait(1)  # let the dock area lay itself out


def test_shift_v_shows_the_pane_in_front_of_the_plots_and_hides_it_again(
    qtbot: QtBot, window: MainWindow
) -> None:
    qtbot.keyClick(window.manual_panel, Qt.Key.Key_T, Qt.KeyboardModifier.ControlModifier)
    telemetry = window.telemetry_dock
    qtbot.waitUntil(lambda: in_front(telemetry))
    shift_v(qtbot, window)
    pane = window.developer_pane
    qtbot.waitUntil(lambda: in_front(pane))
    assert not in_front(telemetry)
    bar = bottom_tabs(window)
    assert bar.tabText(bar.currentIndex()) == "Developer"
    assert window.developer_action.isChecked()

    shift_v(qtbot, window)
    qtbot.waitUntil(lambda: pane.isHidden())
    assert in_front(telemetry)
    assert not window.developer_action.isChecked()

    shift_v(qtbot, window)
    qtbot.waitUntil(lambda: in_front(pane))


def test_shift_v_brings_a_pane_behind_the_telemetry_tab_forward_instead_of_hiding_it(
    qtbot: QtBot, window: MainWindow
) -> None:
    window.telemetry_action.trigger()
    shift_v(qtbot, window)
    pane, telemetry = window.developer_pane, window.telemetry_dock
    qtbot.waitUntil(lambda: in_front(pane))
    bar = bottom_tabs(window)
    telemetry_tab = next(i for i in range(bar.count()) if bar.tabText(i) == "Telemetry")
    qtbot.mouseClick(bar, Qt.MouseButton.LeftButton, pos=bar.tabRect(telemetry_tab).center())
    qtbot.waitUntil(lambda: in_front(telemetry) and not in_front(pane))
    shift_v(qtbot, window)
    qtbot.waitUntil(lambda: in_front(pane))
    assert not pane.isHidden() and window.developer_action.isChecked()
    shift_v(qtbot, window)
    qtbot.waitUntil(lambda: pane.isHidden())


def test_shift_v_alone_shows_and_hides_the_pane(qtbot: QtBot, window: MainWindow) -> None:
    shift_v(qtbot, window)
    pane = window.developer_pane
    qtbot.waitUntil(lambda: in_front(pane))
    shift_v(qtbot, window)
    qtbot.waitUntil(lambda: pane.isHidden())
