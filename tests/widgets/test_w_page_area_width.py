"""The page area is as wide as the widest page, also after a page grew (the usb3 unit's).

The window's layout keeps each widget's minimum, cached; a page that grew wider
once the device answered asked only its scroll area to lay out again, so the
area kept its old minimum and the page's right edge (the Settings table's State
column, the Axes page's buttons) was cut by 26 px at 1280x800 with the docks open.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QSize
from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

SCREEN = QSize(1280, 800)


@pytest.mark.parametrize("profile", ["usb3", "grbl-plotter"])
def test_no_page_is_cut_at_the_right_beside_the_docks(
    qtbot: QtBot, tmp_path: Path, profile: str
) -> None:
    harness = StationHarness(load_profile(profile))
    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        window.show()
        window.resize(SCREEN)
        harness.connect()
        harness.run(2.0)
        window.jobs_dock.show()
        window.telemetry_dock.show()
        area = window.page_area
        for index in range(window.stack.count()):
            window.menu_panel.button(index).click()
            title = window.menu_panel.button(index).text()
            QApplication.processEvents()
            page = window.stack.currentWidget()
            assert page is not None
            assert window.minimumSizeHint().width() <= SCREEN.width(), title
            assert area.viewport().width() >= window.stack.minimumSizeHint().width(), title
            assert area.viewport().width() >= page.width(), title  # nothing past the edge
    finally:
        harness.close()
