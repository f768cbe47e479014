"""The board question for a bare nail list: what the operator sets is what the loader gets."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art.reader import NeedsNailCount, StringArtParams
from widgets.jobs.string_art_board import BoardDialog


def test_the_dialog_starts_at_the_least_nail_count_and_returns_the_board(qtbot: QtBot) -> None:
    needs = NeedsNailCount(Path("cat.txt"), min_nails=160, entries=4001)
    dialog = BoardDialog(needs)
    qtbot.addWidget(dialog)
    assert dialog.nails.value() == 160 and dialog.nails.minimum() == 160  # fewer cannot hold it
    assert dialog.params() == StringArtParams(0, 160, 14.5)
    dialog.shape.setCurrentIndex(dialog.shape.findData(6))
    dialog.nails.setValue(200)
    dialog.radius.setValue(20.04)
    assert dialog.params() == StringArtParams(6, 200, 20.0)
    params = dialog.params()
    assert params is not None and params.check() is None  # a board the loader accepts


def test_a_board_outside_the_ranges_is_shown_invalid_and_cannot_be_accepted(
    qtbot: QtBot,
) -> None:
    needs = NeedsNailCount(Path("cat.txt"), min_nails=160, entries=4001)
    dialog = BoardDialog(needs)
    qtbot.addWidget(dialog)
    dialog.show()
    qtbot.mouseClick(dialog.radius, Qt.MouseButton.LeftButton)
    qtbot.keyClick(dialog.radius, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(dialog.radius, "0.5")
    assert dialog.radius.text() == "0.5"  # kept as typed, not raised to the least radius
    assert "0.5 is outside 1.6…100 cm" in dialog.note.text()
    assert dialog.params() is None and not dialog.ok_button.isEnabled()
    qtbot.keyClick(dialog.radius, Qt.Key.Key_Return)
    assert dialog.result() != dialog.DialogCode.Accepted and dialog.isVisible()
