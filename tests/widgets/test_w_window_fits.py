"""The operator window fits a 1280x800 screen with every dock open, on every profile.

A laptop screen of 1280x800 is what the workshop machines have.  The window's
minimum size must fit it with the jobs dock, the telemetry plots and the
developer pane all open, and at that size every run control — and the
Continue of an operator prompt — must be on screen, not clipped and not
under another dock.  What depends on the font runs under each common family
(tests/helpers/fonts.py); languages and the moments of a job are walked in
test_w_window_fits_everywhere.py.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QPoint, QRect, QSize, Qt
from PySide6.QtWidgets import QApplication, QWidget
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobState
from app.machines.stage.parameters import STAGE_PARAMETERS
from app.profiles import available_profiles, load_profile
from tests.helpers.fonts import FAMILIES, application_font
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

SCREEN = QSize(1280, 800)
LEFT = Qt.MouseButton.LeftButton


@pytest.fixture(params=FAMILIES)
def family(request: pytest.FixtureRequest, qapp: object) -> Iterator[str]:
    """Under each font family: their metrics differ by tens of pixels.  (The minimum size
    at every moment, in every language, is walked in test_w_window_fits_everywhere.py.)"""
    with application_font(request.param):
        yield request.param


@pytest.fixture(params=available_profiles())
def profile_harness(request: pytest.FixtureRequest, qapp: object) -> Iterator[StationHarness]:
    h = StationHarness(load_profile(request.param))
    yield h
    h.close()


def _every_dock_open(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> MainWindow:
    window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
    qtbot.addWidget(window)
    window.show()
    for dock in (window.jobs_dock, window.telemetry_dock, window.developer_pane):
        dock.show()
    QApplication.processEvents()
    return window


def _rect_in(window: QWidget, widget: QWidget) -> QRect:
    return QRect(widget.mapTo(window, QPoint(0, 0)), widget.size())


def _fully_shown(window: QWidget, widget: QWidget) -> bool:
    """On the window, wholly inside it, and not clipped by the widgets it sits in."""
    if not widget.isVisible() or widget.width() <= 0 or widget.height() <= 0:
        return False
    if not window.rect().contains(_rect_in(window, widget)):
        return False
    return widget.visibleRegion().boundingRect().size() == widget.size()


def test_minimum_size_fits_1280_by_800_with_every_dock(
    qtbot: QtBot, profile_harness: StationHarness, tmp_path: Path
) -> None:
    window = _every_dock_open(qtbot, profile_harness, tmp_path)
    hint = window.minimumSizeHint()
    assert hint.width() <= SCREEN.width() and hint.height() <= SCREEN.height(), (
        f"{profile_harness.station.profile.title}: {hint.width()}x{hint.height()}"
    )


def test_at_1280_by_800_every_run_control_is_on_screen_and_docks_do_not_overlap(
    qtbot: QtBot, family: str, profile_harness: StationHarness, tmp_path: Path
) -> None:
    window = _every_dock_open(qtbot, profile_harness, tmp_path)
    window.resize(SCREEN)
    QApplication.processEvents()
    assert window.size() == SCREEN  # the docks did not force it wider or taller
    dock = window.jobs_dock
    for button in (
        dock.open_button,
        dock.run_button,
        dock.pause_button,
        dock.resume_button,
        dock.step_button,
        dock.abort_button,
    ):
        assert _fully_shown(window, button), button.objectName()
    assert _fully_shown(window, window.static_panel.stop_button)
    parts = [window.centralWidget(), dock]
    parts += [d for d in (window.telemetry_dock, window.developer_pane) if d.isVisible()]
    shown = [p for p in parts if not p.visibleRegion().isEmpty()]
    assert len(shown) == 3  # the central widget, the jobs dock and one bottom tab
    for i, first in enumerate(shown):
        for second in shown[i + 1 :]:
            assert not _rect_in(window, first).intersects(_rect_in(window, second))


def test_opening_and_closing_docks_keeps_the_size_the_user_chose(
    qtbot: QtBot, family: str, profile_harness: StationHarness, tmp_path: Path
) -> None:
    window = _every_dock_open(qtbot, profile_harness, tmp_path)
    window.resize(SCREEN)
    QApplication.processEvents()
    docks = (window.jobs_dock, window.telemetry_dock, window.developer_pane)
    for dock in docks:
        dock.toggleViewAction().trigger()
        QApplication.processEvents()
    for dock in docks:
        dock.toggleViewAction().trigger()
        QApplication.processEvents()
    assert all(dock.isVisible() for dock in docks)
    assert window.size() == SCREEN


def test_continue_of_a_wait_is_on_screen_at_1280_by_800(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    window = _every_dock_open(qtbot, harness, tmp_path)
    window.resize(SCREEN)
    harness.connect()
    harness.run(1.0)
    job = tmp_path / "probe.csv"
    long_prompt = "swap the probe for the 0.8 mm drill, tighten the chuck and close the guard"
    job.write_text(f"wait: {long_prompt}\n5, 5\n", encoding="utf-8")
    dock = window.jobs_dock
    assert dock.open_path(job)
    qtbot.mouseClick(dock.run_button, LEFT)
    harness.run_until(lambda: dock.runner.state is JobState.WAITING, timeout=30)
    QApplication.processEvents()
    assert window.size() == SCREEN
    assert _fully_shown(window, dock.continue_button)
    assert _fully_shown(window, dock.prompt_label)
    qtbot.mouseClick(dock.continue_button, LEFT)
    harness.run_until(lambda: dock.runner.state is JobState.DONE, timeout=30)


def test_the_dynamics_page_reflows_instead_of_scrolling_sideways(
    qtbot: QtBot, family: str, harness: StationHarness, tmp_path: Path
) -> None:
    """At 1280x800 with every dock the page is a third of the window: the axes stack."""
    window = _every_dock_open(qtbot, harness, tmp_path)
    window.resize(SCREEN)
    page = window.dynamics_page
    index = window.stack.indexOf(page)
    qtbot.mouseClick(window.menu_panel.button(index), LEFT)
    QApplication.processEvents()
    assert window.stack.currentWidget() is page
    assert window.size() == SCREEN
    panel = window.dynamics_panel
    assert panel.stacked
    assert not page.horizontalScrollBar().isVisible()
    assert panel.width() <= page.viewport().width()
    # Every field and its state, of both axes, lies inside the page's width (scrolling
    # down reaches it); none is cut at the right edge.
    for key, field in panel.fields.items():
        for widget in (field, panel.states[key]):
            left = widget.mapTo(panel, QPoint(0, 0)).x()
            assert left >= 0 and left + widget.width() <= page.viewport().width(), key
    # With the docks closed there is room: the axes go back side by side.
    for dock in (window.jobs_dock, window.telemetry_dock, window.developer_pane):
        dock.toggleViewAction().trigger()
    # Two turns of the event loop: docks built after the window was shown (they are built
    # on first use) hand their room back one layout pass later.
    QApplication.processEvents()
    QApplication.processEvents()
    assert window.size() == SCREEN
    assert not panel.stacked
    first = int(STAGE_PARAMETERS[0].type)
    x_field = panel.fields[(0, first)]
    y_field = panel.fields[(1, first)]
    assert y_field.mapTo(panel, QPoint(0, 0)).x() > x_field.mapTo(panel, QPoint(0, 0)).x()
    assert y_field.mapTo(panel, QPoint(0, 0)).y() == x_field.mapTo(panel, QPoint(0, 0)).y()
    assert not page.horizontalScrollBar().isVisible()


@pytest.mark.parametrize(
    ("profile", "offered"),
    [
        ("xy-stage", []),
        ("usb3", []),
        ("pcb-drill", ["job_draw", "job_draw_crosses", "step", "job_smallest_first"]),
        ("string-art", ["step", "job_smallest_first", "job_skip_unsupported"]),
        (
            "grbl-plotter",
            ["job_draw", "job_draw_crosses", "step", "job_translate_pen", "job_skip_unsupported"],
        ),
        (
            "corexy-plotter",
            ["job_draw", "job_draw_crosses", "step", "job_translate_pen", "job_skip_unsupported"],
        ),
    ],
)
def test_the_jobs_dock_offers_only_this_machines_options_packed_two_a_row(
    qtbot: QtBot, family: str, tmp_path: Path, profile: str, offered: list[str]
) -> None:
    """No "Draw holes with the pen" without a pen, no drill options without a tool for
    holes, and no gap left where a hidden option would have stood."""
    harness = StationHarness(load_profile(profile))
    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        window.show()
        window.jobs_dock.toggleViewAction().trigger()
        QApplication.processEvents()
        dock = window.jobs_dock
        options = {
            "job_draw": dock.draw_check,
            "job_draw_crosses": dock.crosses_check,
            "step": dock.step_combo,
            "job_smallest_first": dock.smallest_check,
            "job_translate_pen": dock.translate_pen_check,
            "job_skip_unsupported": dock.skip_check,
        }
        shown = [name for name, widget in options.items() if widget.isVisible()]
        assert shown == offered
        # Row by row, two to a row, in order: the n-th shown option sits in cell n.
        centres = []
        for name in shown:
            widget = options[name]
            centre = widget.mapTo(dock, widget.rect().center())
            centres.append((centre.y(), centre.x()))
        for index, (y, x) in enumerate(centres):
            if index % 2:
                left_y, left_x = centres[index - 1]
                assert abs(y - left_y) <= 4 and x > left_x  # beside the one before
            elif index:
                assert y > centres[index - 1][0] + 8  # a new row, under the last
        if "job_draw" not in shown:
            dock.draw_check.setChecked(True)  # as a setting kept from a pen machine would
            assert not dock.options.draw
    finally:
        harness.close()


def test_a_drill_job_with_three_reference_holes_still_fits_1280_by_800(
    qtbot: QtBot, qapp: object, tmp_path: Path
) -> None:
    """The registration row of a loaded drill job (three references shown) kept within 1280 px.

    In one row its side choice, three references with Pick and Here, and the
    buttons ran the jobs dock 6 px past a 1280 px screen beside the Drill page.
    """
    harness = StationHarness(load_profile("pcb-drill"))
    try:
        window = _every_dock_open(qtbot, harness, tmp_path)
        window.resize(SCREEN)
        job = tmp_path / "board.drl"
        job.write_text(
            "M48\nMETRIC\nT1C0.8\n%\nT1\nX10.0Y10.0\nX40.0Y10.0\nX40.0Y30.0\nM30\n",
            encoding="utf-8",
        )
        dock = window.jobs_dock
        assert dock.open_path(job)
        bar = dock.registration
        assert bar.isVisible()
        qtbot.mouseClick(bar.three_check, LEFT)
        assert bar.count == 3 and bar.here_buttons[2].isVisible()
        QApplication.processEvents()
        hint = window.minimumSizeHint()
        assert hint.width() <= SCREEN.width(), hint.width()
        assert window.size() == SCREEN
        for button in (*bar.pick_buttons, *bar.here_buttons, bar.register_button):
            assert _fully_shown(window, button), button.objectName()
    finally:
        harness.close()
