"""The board question for a bare nail list: what the operator sets is what the loader gets."""

from __future__ import annotations

from pathlib import Path

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
    assert dialog.params().check() is None  # a board the loader accepts
    dialog.radius.setValue(0.5)  # below the range: held at the least radius that has nails
    assert dialog.params().radius_cm > 1.5
