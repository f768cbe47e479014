"""Light and dark: View → Colours, the desktop's colour scheme, and what follows it.

The palette is the application's, so each test puts back the one it found.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtGui import QColor, QGuiApplication, QPalette
from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from tests.helpers.harness import StationHarness
from widgets import theme
from widgets.main_window import MainWindow


@pytest.fixture(autouse=True)
def palette_back(qapp: object) -> Iterator[None]:
    before = QApplication.palette()
    yield
    QApplication.setPalette(before)


def _window(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> MainWindow:
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    window = MainWindow(harness.station, settings, checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    window.show()
    return window


def _dark(colour: QColor) -> bool:
    return colour.lightness() < 128


def _window_colour() -> QColor:
    return QApplication.palette().color(QPalette.ColorRole.Window)


def _plots_dark(window: MainWindow) -> tuple[bool, bool]:
    preview = window.jobs_dock.preview.plot_widget.backgroundBrush().color()
    telemetry = window.telemetry_dock.graphics.backgroundBrush().color()
    return _dark(preview), _dark(telemetry)


def test_dark_from_the_view_menu_colours_window_and_plots_and_is_kept(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = _window(qtbot, harness, tmp_path)
    assert not _dark(_window_colour()) and _plots_dark(window) == (False, False)
    window.theme_actions["dark"].trigger()
    assert _dark(_window_colour())
    assert _plots_dark(window) == (True, True)
    assert window.telemetry_dock.cross.colours.dark
    window.close()
    qtbot.waitUntil(lambda: not window.isVisible())

    again = _window(qtbot, harness, tmp_path)
    assert again.theme_actions["dark"].isChecked()
    assert _dark(_window_colour()) and _plots_dark(again) == (True, True)
    again.theme_actions["light"].trigger()
    assert not _dark(_window_colour()) and _plots_dark(again) == (False, False)


def test_system_choice_follows_the_desktop_and_a_fixed_one_does_not(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    window = _window(qtbot, harness, tmp_path)
    assert window.theme_actions["system"].isChecked()
    hints = QGuiApplication.styleHints()
    monkeypatch.setattr(theme, "system_is_dark", lambda: True)
    hints.colorSchemeChanged.emit(Qt.ColorScheme.Dark)  # the desktop turned dark
    assert _dark(_window_colour()) and _plots_dark(window) == (True, True)

    window.theme_actions["light"].trigger()
    hints.colorSchemeChanged.emit(Qt.ColorScheme.Dark)
    assert not _dark(_window_colour()) and _plots_dark(window) == (False, False)

    window.theme_actions["system"].trigger()
    monkeypatch.setattr(theme, "system_is_dark", lambda: False)
    hints.colorSchemeChanged.emit(Qt.ColorScheme.Light)
    assert not _dark(_window_colour()) and _plots_dark(window) == (False, False)
