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
    QFormLayout,
    QLabel,
    QWidget,
)

from app.jobs.formats.string_art.reader import MAX_NAILS, NeedsNailCount, StringArtParams
from app.jobs.names import shown
from widgets.number_field import FieldGate, NumberField

DEFAULT_RADIUS_CM = 14.5


class BoardDialog(QDialog):
    def __init__(self, needs: NeedsNailCount, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("String-art board"))
        form = QFormLayout(self)
        form.addRow(
            QLabel(
                self.tr(
                    "<b>{0}</b> lists %n nail visit(s) without a param.txt. Which board is it for?",
                    "",
                    needs.entries,
                ).format(html.escape(shown(needs.path.name)))
            )
        )
        self.shape = QComboBox()
        self.shape.setObjectName("board_shape")
        self.shape.addItem(self.tr("circle"), 0)
        for sides in range(3, 13):
            self.shape.addItem(self.tr("{0}-gon").format(sides), sides)
        highest = needs.min_nails - 1
        least = max(3, needs.min_nails)
        self.nails = NumberField(
            least,
            MAX_NAILS,
            decimals=0,
            value=least,
            name="board_nails",
            tooltip=self.tr("At least {0}: the list names nail {1}").format(
                needs.min_nails, highest
            ),
        )
        self.radius = NumberField(
            1.6,
            100.0,
            decimals=1,
            unit="cm",
            value=DEFAULT_RADIUS_CM,
            name="board_radius",
            tooltip=self.tr("Board radius; the nails sit 1.5 cm inside its edge"),
        )
        form.addRow(self.tr("Shape"), self.shape)
        form.addRow(self.tr("Nails"), self.nails)
        form.addRow(self.tr("Board radius"), self.radius)
        self.note = QLabel()
        self.gate = FieldGate(self.note, self)
        self.gate.watch(self.nails, self.tr("Nails"))
        self.gate.watch(self.radius, self.tr("Board radius"))

        form.addRow(self.note)
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel
        )
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        self.ok_button = buttons.button(QDialogButtonBox.StandardButton.Ok)
        self.gate.bind(self.ok_button, self.nails, self.radius)
        form.addRow(buttons)

    def params(self) -> StringArtParams | None:
        """The board as set, or None while a field is not acceptable (OK is disabled then)."""
        nails, radius = self.nails.value(), self.radius.value()
        if nails is None or radius is None:
            return None
        return StringArtParams(int(self.shape.currentData()), round(nails), radius)

    def accept(self) -> None:
        if self.gate.refusal(self.nails, self.radius) is None:
            super().accept()


#: Asks for the board of a bare nail list; None when the operator cancels.
BoardAsker = Callable[[NeedsNailCount], StringArtParams | None]


def ask_board(parent: QWidget | None) -> BoardAsker:
    def ask(needs: NeedsNailCount) -> StringArtParams | None:
        dialog = BoardDialog(needs, parent)
        accepted = dialog.exec() == QDialog.DialogCode.Accepted
        return dialog.params() if accepted else None

    return ask
