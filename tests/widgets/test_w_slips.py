"""Small slips a newcomer noticed (issue 32), each held where a test can see it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

#: Two bits, so two prompts, and a park at the end that the drill reports after the holes.
BOARD = "M48\nMETRIC\nT1C0.8\nT2C1.0\n%\nT1\nX10.0Y10.0\nX40.0Y10.0\nT2\nX40.0Y30.0\nM30\n"


def test_a_finished_drill_job_has_no_time_left(qtbot: QtBot, tmp_path: Path) -> None:
    """It said "left 00:04" after "done": the park came after the last hole's report."""
    harness = StationHarness(load_profile("pcb-drill"))
    try:
        window = MainWindow(harness.station)
        qtbot.addWidget(window)
        window.show()
        dock = window.jobs_dock
        harness.connect()
        job = tmp_path / "board.drl"
        job.write_text(BOARD, encoding="utf-8")
        assert dock.open_path(job)
        dock.run_button.click()
        prompts = 0
        while dock.runner.state is not JobState.DONE:
            harness.run_until(
                lambda: dock.runner.state in (JobState.DONE, JobState.WAITING), timeout=120
            )
            if dock.runner.state is JobState.WAITING:
                prompts += 1
                assert dock.eta_label.text() != "left 00:00"  # the holes are still to come
                dock.continue_button.click()
        assert prompts == 2
        harness.run(2.0)
        assert dock.runner.progress.remaining_s == 0.0
        assert dock.eta_label.text() == "left 00:00"
    finally:
        harness.close()


@pytest.mark.parametrize(
    ("profile", "dial"),
    [("xy-stage", True), ("usb3", False), ("pcb-drill", False), ("corexy-plotter", False)],
)
def test_the_rotation_dial_is_shown_only_where_rotation_is_reported(
    qtbot: QtBot, profile: str, dial: bool
) -> None:
    """The stage's IMU reports its rotation; the other machines have nothing to turn it."""
    harness = StationHarness(load_profile(profile))
    try:
        window = MainWindow(harness.station)
        qtbot.addWidget(window)
        window.show()
        window.telemetry_action.trigger()
        dock = window.telemetry_dock
        assert dock.isVisible()
        assert dock.rotation_panel.isVisible() is dial
        assert dock.cross.isVisible() is dial
    finally:
        harness.close()


def test_the_drills_link_check_is_not_shown_as_a_failure(qtbot: QtBot) -> None:
    """The probe's "< EI" read as a refusal; it is the drill saying it is there."""
    harness = StationHarness(load_profile("pcb-drill"))
    try:
        window = MainWindow(harness.station)
        qtbot.addWidget(window)
        harness.connect()
        harness.run(0.5)
        lines = window.drill_panel.output.toPlainText().splitlines()
        answers = [line for line in lines if line.startswith("< EI")]
        assert answers, lines
        assert all("link check answered" in line for line in answers)
        assert any(line.startswith("> I ") and "link check" in line for line in lines), lines
    finally:
        harness.close()


def test_a_flat_curve_is_not_zoomed_into_float_noise(qtbot: QtBot) -> None:
    """A still axis's velocity, a few 1e-16 apart, had ticks reading "5e-16"."""
    harness = StationHarness(load_profile("xy-stage"))
    try:
        window = MainWindow(harness.station)
        qtbot.addWidget(window)
        window.show()
        window.telemetry_action.trigger()
        dock = window.telemetry_dock
        plot = dock.velocity_plot
        curve = next(c for name, c in dock._curves.items() if name.endswith("velocity"))
        t = np.linspace(-10.0, 0.0, 50)
        curve.set_points(t, 2.0 + np.where(np.arange(50) % 2, 5e-16, 0.0))
        plot.getViewBox().autoRange()
        low, high = plot.viewRange()[1]
        assert high - low >= 0.01 and low <= 2.0 <= high
        axis = plot.getAxis("left")
        ticks = axis.tickValues(low, high, plot.height())
        labels = [s for spacing, values in ticks for s in axis.tickStrings(values, 1.0, spacing)]
        assert labels and not any("e" in label for label in labels), labels
    finally:
        harness.close()


def test_check_boxes_stand_out_in_the_dark_theme(qtbot: QtBot) -> None:
    """The dark palette filled a check box as dark as the window around it."""
    from PySide6.QtGui import QPalette
    from PySide6.QtWidgets import QApplication, QCheckBox, QWidget

    from widgets.theme import ThemeController

    original = QApplication.palette()
    theme = ThemeController("dark")
    try:
        page = QWidget()
        box = QCheckBox("skip", page)
        qtbot.addWidget(page)
        page.show()
        QApplication.processEvents()
        fill = box.palette().color(QPalette.ColorRole.Base).lightness()
        window = page.palette().color(QPalette.ColorRole.Window).lightness()
        assert window < 128 and fill - window >= 25
        theme.set_choice("light")
        QApplication.processEvents()
        assert box.palette().color(QPalette.ColorRole.Base).lightness() > 200
    finally:
        theme.release()
        QApplication.setPalette(original)
        for name in ("QCheckBox", "QRadioButton"):
            QApplication.setPalette(original, name)
