"""The "From photo…" dialog: photo in, generate with progress, cancel, export, load as a job.

Real clicks and keys on the dialog the jobs dock opens; only the two file
choosers are replaced (by the photo and folder the test made).  The worker
threads are real, so the tests wait for them with ``qtbot.waitUntil``.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from PySide6.QtCore import QStandardPaths, Qt
from PySide6.QtWidgets import QAbstractSpinBox
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.formats.string_art.reader import StringArtParams, read_string_art
from app.jobs.run.runner import JobRunner
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.string_art_images import face
from widgets.jobs import string_art_generator_dialog as dialog_module
from widgets.jobs.dock import JobsDock
from widgets.jobs.string_art_generator_dialog import StringArtGeneratorDialog

LEFT = Qt.MouseButton.LeftButton
WAIT_MS = 20_000


@pytest.fixture
def winder(qapp: object) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("string-art"))
    yield harness
    harness.close()


@pytest.fixture
def dock(qtbot: QtBot, winder: StationHarness, tmp_path: Path) -> Iterator[JobsDock]:
    runner = JobRunner(winder.station, tmp_path / "checkpoints")
    dock = JobsDock(winder.station, runner, confirm=lambda _text: False, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.show()
    yield dock
    if dock.string_art.dialog is not None:
        dock.string_art.dialog.close()
    runner.deleteLater()


@pytest.fixture
def photo(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    path = tmp_path / "portrait.png"
    Image.fromarray(np.round(face(160) * 255).astype(np.uint8)).save(path)
    monkeypatch.setattr(dialog_module, "ask_image", lambda _parent: path)
    return path


def generated_root() -> Path:
    base = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppDataLocation)
    return Path(base) / "string-art"


def generated_folders() -> set[Path]:
    root = generated_root()
    return set(root.iterdir()) if root.is_dir() else set()


def type_value(qtbot: QtBot, spin: QAbstractSpinBox, text: str) -> None:
    """Select the field's text and type a new value, as the operator would."""
    spin.setFocus()
    qtbot.keyClick(spin, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(spin, text)
    qtbot.keyClick(spin, Qt.Key.Key_Tab)


def opened(qtbot: QtBot, dock: JobsDock) -> StringArtGeneratorDialog:
    qtbot.mouseClick(dock.photo_button, LEFT)
    dialog = dock.string_art.dialog
    assert dialog is not None and dialog.isVisible()
    qtbot.mouseClick(dialog.image_button, LEFT)
    qtbot.waitUntil(lambda: dialog.generate_button.isEnabled(), timeout=WAIT_MS)
    return dialog


def small_board(qtbot: QtBot, dialog: StringArtGeneratorDialog, lines: int) -> None:
    type_value(qtbot, dialog.nails, "40")
    type_value(qtbot, dialog.resolution, "64")
    type_value(qtbot, dialog.lines, str(lines))


def test_the_button_is_the_winders_only(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    stage_dock = JobsDock(harness.station, runner, confirm=lambda _text: False)
    qtbot.addWidget(stage_dock)
    stage_dock.show()
    assert not stage_dock.photo_button.isVisible()
    runner.deleteLater()


def test_generate_on_a_small_photo_then_load_it_as_a_job(
    qtbot: QtBot, dock: JobsDock, photo: Path
) -> None:
    dialog = opened(qtbot, dock)
    assert "portrait.png" in dialog.image_label.text()
    assert not dialog.photo_view.pixmap().isNull()
    assert not dialog.export_button.isEnabled() and not dialog.load_button.isEnabled()
    small_board(qtbot, dialog, 150)
    assert dialog.params() == StringArtParams(0, 40, 14.5)
    assert dialog.skip.value() == 2  # the default skip follows the nail count

    grown: list[int] = []
    dialog.threadsShown.connect(grown.append)
    qtbot.mouseClick(dialog.generate_button, LEFT)
    assert dialog.running and dialog.cancel_button.isEnabled()
    assert not dialog.generate_button.isEnabled() and not dialog.nails.isEnabled()
    qtbot.waitUntil(lambda: dialog.finished_result is not None, timeout=WAIT_MS)
    job = dialog.job()
    assert job is not None and 2 <= len(job.sequence) <= 151
    # The picture was shown part-wound before the end, and only ever grew.
    assert grown and grown[0] < len(job.sequence) - 1 and grown == sorted(grown)
    assert not dialog.thread_view.pixmap().isNull()
    assert "MAE" in dialog.status.text() and "SSIM" in dialog.status.text()
    assert dialog.progress.value() == len(job.sequence) - 1
    assert dialog.load_button.isEnabled() and dialog.generate_button.isEnabled()

    qtbot.mouseClick(dialog.load_button, LEFT)
    program = dock.runner.program
    assert isinstance(program, StringArtProgram)
    assert program.job.sequence == job.sequence and program.job.params == job.params
    assert program.source is not None and program.source.parent.parent == generated_root()
    assert (program.source.parent / "string-art.png").is_file()
    assert not dialog.isVisible()
    qtbot.waitUntil(lambda: dock.string_art.dialog is None)
    assert f"poradi.txt: {len(program)} operations loaded" in dock.messages.toPlainText()
    # The dialog's threads are the dock's connections: one fewer than the nails visited.
    threads = len(job.sequence) - 1
    assert dialog.status.text().startswith(f"{threads} thread")
    assert f", {threads} connections," in dock.messages.toPlainText()


def test_cancel_keeps_nothing_and_export_writes_the_pair_the_dock_loads(
    qtbot: QtBot,
    dock: JobsDock,
    photo: Path,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    before = generated_folders()
    dialog = opened(qtbot, dock)
    # A large board: preparing its lines takes seconds, so Cancel comes in the middle.
    type_value(qtbot, dialog.nails, "300")
    type_value(qtbot, dialog.resolution, "300")
    qtbot.mouseClick(dialog.generate_button, LEFT)
    assert dialog.running
    qtbot.mouseClick(dialog.cancel_button, LEFT)
    qtbot.waitUntil(lambda: not dialog.running, timeout=WAIT_MS)
    assert dialog.status.text() == "Cancelled: nothing kept"
    assert dialog.finished_result is None and dialog.job() is None
    assert not dialog.export_button.isEnabled() and not dialog.load_button.isEnabled()
    assert dialog.thread_view.pixmap().isNull()
    assert generated_folders() == before
    assert dock.runner.program is None

    small_board(qtbot, dialog, 80)
    qtbot.mouseClick(dialog.generate_button, LEFT)
    qtbot.waitUntil(lambda: dialog.finished_result is not None, timeout=WAIT_MS)
    folder = tmp_path / "sd"
    monkeypatch.setattr(dialog_module, "ask_folder", lambda _parent: folder)
    qtbot.mouseClick(dialog.export_button, LEFT)
    names = sorted(p.name for p in folder.iterdir())
    assert names == ["param.txt", "poradi.txt", "string-art.png"]
    job = dialog.job()
    assert job is not None and read_string_art(folder / "param.txt") == job

    qtbot.mouseClick(dialog.load_button, LEFT)  # the exported pair is the one loaded
    program = dock.runner.program
    assert isinstance(program, StringArtProgram) and program.source == folder / "poradi.txt"


def test_closing_while_it_generates_stops_the_worker(
    qtbot: QtBot, dock: JobsDock, photo: Path
) -> None:
    dialog = opened(qtbot, dock)
    type_value(qtbot, dialog.nails, "300")
    type_value(qtbot, dialog.resolution, "300")
    qtbot.mouseClick(dialog.generate_button, LEFT)
    assert dialog.running
    qtbot.mouseClick(dialog.close_button, LEFT)
    assert not dialog.running and not dialog.isVisible()
    assert dock.runner.program is None  # the no-leftover-threads fixture checks the rest


def test_an_unreadable_photo_is_named_and_nothing_can_be_generated(
    qtbot: QtBot, dock: JobsDock, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    bad = tmp_path / "scan.jpg"
    bad.write_text("this is no JPEG")
    monkeypatch.setattr(dialog_module, "ask_image", lambda _parent: bad)
    qtbot.mouseClick(dock.photo_button, LEFT)
    dialog = dock.string_art.dialog
    assert dialog is not None
    qtbot.mouseClick(dialog.image_button, LEFT)
    qtbot.waitUntil(lambda: dialog.status.text().startswith("Not opened"), timeout=WAIT_MS)
    assert "scan.jpg" in dialog.status.text()
    assert not dialog.generate_button.isEnabled()


def test_a_board_too_big_for_memory_cannot_be_generated_and_says_why(
    qtbot: QtBot, dock: JobsDock, photo: Path
) -> None:
    dialog = opened(qtbot, dock)
    type_value(qtbot, dialog.nails, "2000")
    type_value(qtbot, dialog.resolution, "600")
    assert not dialog.generate_button.isEnabled()
    assert "Cannot generate" in dialog.scale_label.text()
    assert "fewer nails or a smaller raster" in dialog.scale_label.text()
    type_value(qtbot, dialog.nails, "200")
    assert dialog.generate_button.isEnabled()


def test_many_nails_take_a_coarser_raster_instead_of_a_refusal(
    qtbot: QtBot, dock: JobsDock, photo: Path
) -> None:
    dialog = opened(qtbot, dock)
    assert dialog.resolution.value() == 520
    type_value(qtbot, dialog.nails, "500")
    assert 200 <= dialog.resolution.value() < 520
    assert "Cannot generate" not in dialog.scale_label.text()
    assert dialog.generate_button.isEnabled()


def test_a_board_the_winder_cannot_reach_is_named_but_can_still_be_exported(
    qtbot: QtBot, dock: JobsDock, photo: Path
) -> None:
    """X travel 250 mm; the winding starts 2 cm beyond the board's edge (the firmware's
    ``polomer_matrice_cm + 2.0``, FIDELITY S0-19): 23 cm."""
    dialog = opened(qtbot, dock)
    assert "reaches" not in dialog.scale_label.text()
    type_value(qtbot, dialog.radius, "23")
    assert "reaches" not in dialog.scale_label.text()
    type_value(qtbot, dialog.radius, "23.5")
    assert "needle reaches 250 mm from the centre: boards up to 23.0 cm" in (
        dialog.scale_label.text()
    )
    assert dialog.generate_button.isEnabled()
