"""A job refused for operations the machine cannot run names them in the window's language.

The usb3 unit has no pen: a plotter file's M3/M5 are refused before anything is
sent, each line listed.  The list said "pen down" / "pen up" in English in a
Czech or Slovak window (the operation's own description), while the Run from…
list and the jobs dock said "pero dolů".
"""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QCoreApplication
from pytestqt.qtbot import QtBot

from app import i18n
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

PLOT = "G0 X10 Y10\nM3 S1000\nG1 X20 F600\nM5\n"


@pytest.mark.parametrize("language", ["cs", "sk"])
def test_the_refused_operations_are_named_in_the_language(
    qtbot: QtBot, i18n_cache: Path, tmp_path: Path, language: str
) -> None:
    i18n.install(language, i18n_cache)
    harness = StationHarness(load_profile("usb3"))
    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        job = tmp_path / "plot.gcode"
        job.write_text(PLOT, encoding="utf-8")
        dock = window.jobs_dock
        dock.open_path(job)
        text = dock.messages.toPlainText()
        pen_down = QCoreApplication.translate("Operation", "pen down")
        pen_up = QCoreApplication.translate("Operation", "pen up")
        assert pen_down != "pen down" and pen_up != "pen up"  # the language has its own words
        assert f"plot.gcode:2: {pen_down} —" in text, text
        assert f"plot.gcode:4: {pen_up} —" in text, text
        assert "pen down" not in text and "pen up" not in text
    finally:
        harness.close()
        i18n.install("en", i18n_cache)
