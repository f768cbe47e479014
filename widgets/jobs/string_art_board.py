"""Asking the operator for the board of a bare nail list (no ``param.txt`` beside it).

Public string-art generators write only the nail order; the shape, the nail
count and the radius are the operator's to say.  The dialog starts from the
least nail count the list allows and refuses a board the checks would refuse.
"""

from __future__ import annotations

import html
from collections.abc import Callable

from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDoubleSpinBox,
    QFormLayout,
    QLabel,
    QSpinBox,
    QWidget,
)

from app.jobs.formats.string_art.reader import MAX_NAILS, NeedsNailCount, StringArtParams
from app.jobs.names import shown

DEFAULT_RADIUS_CM = 14.5


class BoardDialog(QDialog):
    def __init__(self, needs: NeedsNailCount, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setWindowTitle("String-art board")
        form = QFormLayout(self)
        form.addRow(
            QLabel(
                f"<b>{html.escape(shown(needs.path.name))}</b> lists {needs.entries} nail "
                "visits without a param.txt. Which board is it for?"
            )
        )
        self.shape = QComboBox()
        self.shape.setObjectName("board_shape")
        self.shape.addItem("circle", 0)
        for sides in range(3, 13):
            self.shape.addItem(f"{sides}-gon", sides)
        self.nails = QSpinBox()
        self.nails.setObjectName("board_nails")
        self.nails.setRange(max(3, needs.min_nails), MAX_NAILS)
        self.nails.setValue(max(3, needs.min_nails))
        highest = needs.min_nails - 1
        self.nails.setToolTip(f"At least {needs.min_nails}: the list names nail {highest}")
        self.radius = QDoubleSpinBox()
        self.radius.setObjectName("board_radius")
        self.radius.setRange(1.6, 100.0)
        self.radius.setDecimals(1)
        self.radius.setSuffix(" cm")
        self.radius.setValue(DEFAULT_RADIUS_CM)
        self.radius.setToolTip("Board radius; the nails sit 1.5 cm inside its edge")
        form.addRow("Shape", self.shape)
        form.addRow("Nails", self.nails)
        form.addRow("Board radius", self.radius)
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        form.addRow(buttons)

    def params(self) -> StringArtParams:
        return StringArtParams(
            int(self.shape.currentData()), self.nails.value(), round(self.radius.value(), 1)
        )


#: Asks for the board of a bare nail list; None when the operator cancels.
BoardAsker = Callable[[NeedsNailCount], StringArtParams | None]


def ask_board(parent: QWidget | None) -> BoardAsker:
    def ask(needs: NeedsNailCount) -> StringArtParams | None:
        dialog = BoardDialog(needs, parent)
        return dialog.params() if dialog.exec() == QDialog.DialogCode.Accepted else None

    return ask
