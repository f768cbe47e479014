"""The window fits 1280x800 at every moment: every profile, page, language and font family.

One window per profile, language and font family, walked through what an
operator sees: each page, the developer pane in front of the plots, a job
loaded with three reference holes, the job running into its operator prompt
("insert T01…", "pen for T01…", a wait) and the job ended.  At each moment
the window's minimum size must fit 1280x800 and the window must not have
grown.  A prompt takes its room from the preview, so it never raises the
jobs dock's minimum.  And a window restored where it was saved reopens
wholly on the screen.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QMargins, QPoint, QRect, QSettings, QSize
from PySide6.QtWidgets import QApplication, QWidget
from pytestqt.qtbot import QtBot

from app import i18n
from app.jobs.run.runner import JobState
from app.profiles import available_profiles, load_profile
from app.settings import GEOMETRY, StationSettings
from tests.helpers.fonts import FAMILIES, application_font
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.screen_fit import fitted

SCREEN = QSize(1280, 800)
LANGUAGES = ("en", "cs", "sk")

#: A drill file with two bits (so a bit-change prompt) and three holes (three references).
BOARD = "M48\nMETRIC\nT1C0.8\nT2C1.0\n%\nT1\nX10.0Y10.0\nX40.0Y10.0\nT2\nX40.0Y30.0\nM30\n"
#: A point list that waits for the operator first (machines without holes to drill or draw).
WAIT = "wait: swap the probe for the 0.8 mm drill, tighten the chuck and close the guard\n5, 5\n"


def _job(profile: str, folder: Path) -> tuple[Path, bool]:
    """The job each machine runs into a prompt, and whether its holes are drawn with the pen."""
    if profile in ("xy-stage", "usb3", "string-art"):
        path = folder / "probe.csv"
        path.write_text(WAIT, encoding="utf-8")
        return path, False
    path = folder / "board.drl"
    path.write_text(BOARD, encoding="utf-8")
    return path, profile.endswith("plotter")


def _fully_shown(window: QWidget, widget: QWidget) -> bool:
    if not widget.isVisible() or widget.width() <= 0 or widget.height() <= 0:
        return False
    rect = QRect(widget.mapTo(window, QPoint(0, 0)), widget.size())
    if not window.rect().contains(rect):
        return False
    return widget.visibleRegion().boundingRect().size() == widget.size()


def _page_shown_whole_width(window: MainWindow, title: str) -> None:
    """The page is as wide as it needs (nothing cut at the right), and it scrolls up and
    down only when it is taller than the room it has, not for a taller page it hides."""
    QApplication.processEvents()
    page = window.stack.currentWidget()
    assert page is not None
    area = window.page_area
    assert page.width() >= page.minimumSizeHint().width(), title
    assert not area.horizontalScrollBar().isVisible(), title
    needs = max(page.minimumSizeHint().height(), page.minimumSize().height())
    frame = window.stack.frameWidth() * 2
    if needs + frame <= area.viewport().height():
        assert not area.verticalScrollBar().isVisible(), title


@pytest.fixture(params=FAMILIES)
def family(request: pytest.FixtureRequest, qapp: object) -> Iterator[str]:
    with application_font(request.param):
        yield request.param


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("profile", available_profiles())
def test_the_window_fits_1280_by_800_at_every_moment(
    qtbot: QtBot,
    i18n_cache: Path,
    tmp_path: Path,
    family: str,
    profile: str,
    language: str,
) -> None:
    i18n.install(language, i18n_cache)
    harness = StationHarness(load_profile(profile))
    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        window.show()
        for dock in (window.jobs_dock, window.telemetry_dock, window.developer_pane):
            dock.show()
        window.resize(SCREEN)
        QApplication.processEvents()

        def fits(moment: str) -> None:
            QApplication.processEvents()
            hint = window.minimumSizeHint()
            where = f"{profile}, {language}, {family}, {moment}"
            assert hint.width() <= SCREEN.width() and hint.height() <= SCREEN.height(), (
                f"{where}: the window needs {hint.width()}x{hint.height()}"
            )
            size = window.size()
            assert size == SCREEN, f"{where}: the window grew to {size.width()}x{size.height()}"

        for index in range(window.stack.count()):
            window.menu_panel.button(index).click()
            title = window.menu_panel.button(index).text()
            fits(f"page {title!r}")
            _page_shown_whole_width(window, title)
        window.developer_pane.raise_()
        fits("the developer pane in front")
        window.telemetry_dock.raise_()

        dock = window.jobs_dock
        path, draw = _job(profile, tmp_path)
        dock.draw_check.setChecked(draw)
        assert dock.open_path(path), dock.messages.toPlainText()
        if dock.registration.isVisible():
            dock.registration.three_check.click()
            assert dock.registration.here_buttons[2].isVisible()
            fits("a job loaded, three reference holes")
            for button in (*dock.registration.pick_buttons, *dock.registration.here_buttons):
                assert _fully_shown(window, button), button.objectName()
        else:
            fits("a job loaded")
        dock_minimum = dock.minimumSizeHint().height()

        harness.connect()
        dock.run_button.click()
        harness.run_until(lambda: dock.runner.state is JobState.WAITING, timeout=60)
        fits(f"the prompt {dock.prompt_label.text()!r}")
        assert _fully_shown(window, dock.prompt_label)
        assert _fully_shown(window, dock.continue_button)
        # The prompt took its room from the preview, not from the screen.
        assert dock.minimumSizeHint().height() <= dock_minimum
        # Past the prompt and a little way into the job, then stopped: the offer to resume
        # the interrupted run comes, with the registration row back beside it.
        dock.continue_button.click()
        harness.run(1.0)
        if dock.runner.state is not JobState.DONE:
            dock.abort_button.click()
        harness.run_until(
            lambda: dock.runner.state in (JobState.ABORTED, JobState.DONE), timeout=30
        )
        fits("after the job")
        if dock.resume_offer.isVisible():
            assert _fully_shown(window, dock.resume_checkpoint_button)
            assert _fully_shown(window, dock.discard_checkpoint_button)
            assert dock.minimumSizeHint().height() <= dock_minimum
    finally:
        harness.close()


def test_a_prompt_does_not_grow_a_window_at_its_minimum_size(
    qtbot: QtBot, qapp: object, tmp_path: Path
) -> None:
    """Not only at 1280x800: at its smallest the window still does not grow for a prompt."""
    harness = StationHarness(load_profile("pcb-drill"))
    try:
        window = MainWindow(harness.station, checkpoint_dir=tmp_path / "checkpoints")
        qtbot.addWidget(window)
        window.show()
        for dock in (window.jobs_dock, window.telemetry_dock, window.developer_pane):
            dock.show()
        dock = window.jobs_dock
        path, _ = _job("pcb-drill", tmp_path)
        assert dock.open_path(path)
        QApplication.processEvents()
        smallest = window.minimumSizeHint()
        window.resize(smallest)
        QApplication.processEvents()
        assert window.size() == smallest
        harness.connect()
        dock.run_button.click()
        harness.run_until(lambda: dock.runner.state is JobState.WAITING, timeout=60)
        QApplication.processEvents()
        assert dock.prompt.isVisible()
        assert window.size() == smallest
        assert _fully_shown(window, dock.continue_button)
        dock.abort_button.click()
        harness.run_until(lambda: dock.runner.state is JobState.ABORTED, timeout=30)
        QApplication.processEvents()
        assert window.size() == smallest
    finally:
        harness.close()


@pytest.mark.parametrize(
    ("saved", "frame", "screen", "expected"),
    [
        # The case seen: saved at (1, 25) 800 high, a 28 px title bar, an 800 px screen.
        (QRect(1, 25, 1200, 776), QMargins(1, 28, 1, 1), QRect(0, 0, 1280, 800),
         QRect(1, 28, 1200, 771)),
        # Off the right and bottom edges: moved back, size kept.
        (QRect(900, 500, 600, 400), QMargins(0, 0, 0, 0), QRect(0, 0, 1280, 800),
         QRect(680, 400, 600, 400)),
        # On a second screen to the left, above its panel: moved below the panel.
        (QRect(-1900, 0, 800, 600), QMargins(0, 20, 0, 0), QRect(-1920, 32, 1920, 1048),
         QRect(-1900, 52, 800, 600)),
        # Already on the screen: left alone.
        (QRect(100, 100, 800, 600), QMargins(2, 24, 2, 2), QRect(0, 0, 1280, 800),
         QRect(100, 100, 800, 600)),
    ],
)  # fmt: skip
def test_a_restored_rectangle_is_put_wholly_on_the_screen(
    saved: QRect, frame: QMargins, screen: QRect, expected: QRect
) -> None:
    placed = fitted(saved, frame, screen)
    assert placed == expected
    assert screen.contains(placed.marginsAdded(frame))


def test_the_window_reopens_wholly_on_the_screen(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    """Saved partly off the screen (another monitor, a bigger screen): it comes back on it."""
    ini = str(tmp_path / "stepdeck.ini")
    first = MainWindow(harness.station)  # remembers nothing: only to make the saved geometry
    qtbot.addWidget(first)
    screen = first.screen()
    assert screen is not None
    available = screen.availableGeometry()
    size = QSize(min(700, available.width() - 40), min(500, available.height() - 40))
    first.setGeometry(QRect(available.topLeft() + QPoint(300, 350), size))
    assert not available.contains(first.geometry())  # the premise: it hangs off the edge
    settings = StationSettings(QSettings(ini, QSettings.Format.IniFormat))
    settings.write(GEOMETRY, first.saveGeometry())
    settings.sync()

    second = MainWindow(harness.station, QSettings(ini, QSettings.Format.IniFormat))
    qtbot.addWidget(second)
    assert available.contains(second.geometry())  # already as restored, before it shows
    second.show()
    QApplication.processEvents()
    assert available.contains(second.frameGeometry())
    assert second.size() == size  # moved, not shrunk: it fits
