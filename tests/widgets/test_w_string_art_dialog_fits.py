"""The "From photo…" dialog after Generate: no caption over the pictures, nothing clipped.

The caption under the two pictures and the status (which grows to two lines
after Generate) took their room from the fixed-size pictures when the dialog
stood at the screen's height: the caption was drawn over both pictures.  This
generates on a small board in English, Czech and Slovak and looks at where
each widget ended up.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from PySide6.QtCore import QRect, Qt
from PySide6.QtWidgets import QLabel, QWidget
from pytestqt.qtbot import QtBot

from app import i18n
from app.jobs.run.runner import JobRunner
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.string_art_images import face
from widgets.jobs import string_art_generator_dialog as dialog_module
from widgets.jobs.dock import JobsDock

LEFT = Qt.MouseButton.LeftButton
WAIT_MS = 20_000


@pytest.fixture(autouse=True)
def english_after(qapp: object, i18n_cache: Path) -> Iterator[None]:
    """The language this test installs does not follow the tests that come after it."""
    yield
    i18n.install("en", i18n_cache)


def _rect(widget: QWidget, top: QWidget) -> QRect:
    return QRect(widget.mapTo(top, widget.rect().topLeft()), widget.size())


@pytest.fixture
def dock(qtbot: QtBot, tmp_path: Path) -> Iterator[JobsDock]:
    harness = StationHarness(load_profile("string-art"))
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dock = JobsDock(harness.station, runner, confirm=lambda _text: False, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.show()
    yield dock
    if dock.string_art.dialog is not None:
        dock.string_art.dialog.close()
    runner.deleteLater()
    harness.close()


@pytest.mark.parametrize("language", ["en", "cs", "sk"])
def test_after_generate_the_caption_and_status_stay_off_the_pictures(
    qtbot: QtBot,
    dock: JobsDock,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    i18n_cache: Path,
    language: str,
) -> None:
    i18n.install(language, i18n_cache)
    path = tmp_path / "portrait.png"
    Image.fromarray(np.round(face(160) * 255).astype(np.uint8)).save(path)
    monkeypatch.setattr(dialog_module, "ask_image", lambda _parent: path)
    qtbot.mouseClick(dock.photo_button, LEFT)
    dialog = dock.string_art.dialog
    assert dialog is not None
    qtbot.mouseClick(dialog.image_button, LEFT)
    qtbot.waitUntil(lambda: dialog.generate_button.isEnabled(), timeout=WAIT_MS)
    # A budget it stops short of: the status then takes two lines ("stopped before…").
    dialog.nails.setValue(40)
    dialog.resolution.setValue(64)
    dialog.lines.setValue(4000)
    qtbot.mouseClick(dialog.generate_button, LEFT)
    qtbot.waitUntil(lambda: dialog.finished_result is not None, timeout=WAIT_MS)
    qtbot.wait(50)  # the layout settles on the new texts
    assert dialog.finished_result.result.stopped_early
    screen = dialog.screen().availableGeometry()
    assert dialog.frameGeometry().height() <= max(screen.height(), 800)
    pictures = [_rect(dialog.photo_view, dialog), _rect(dialog.thread_view, dialog)]
    for label in (dialog.scale_label, dialog.status):
        where = _rect(label, dialog)
        for picture in pictures:
            assert not where.intersects(picture), (label.objectName(), where, picture)
    # Every label gets the height its text needs at its width: nothing cut off.
    for label in dialog.findChildren(QLabel):
        if label.isVisible() and label.wordWrap() and label.text():
            need = label.heightForWidth(label.width())
            assert label.height() >= need, (label.objectName(), label.text(), label.height())
