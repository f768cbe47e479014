"""The job preview with the bands that come and go above it, in a height that does not change.

The registration row, the offer to resume an interrupted run and the
operator's prompt ("insert T01…", Continue) appear while a job is loaded or
runs.  Stacked on the preview they used to add their height to the dock's
minimum, so a prompt made the window grow (a drill at 1206 x 839 on an 800 px
screen, and still 839 high after the job).  Here they take their room from
the preview instead: the column asks for the same minimum height whichever
bands are shown, enough for the preview at its least under the tallest of
them.
"""

from __future__ import annotations

from collections.abc import Sequence

from PySide6.QtCore import QSize
from PySide6.QtWidgets import QVBoxLayout, QWidget

#: Space between the bands and the preview (px).
SPACING = 4
#: Lines of text a wrapped band may take beyond its hint (which counts its text as it is now,
#: often none while it is hidden) before it eats into the preview's least height.
LINES = 2


class PreviewColumn(QWidget):
    """``rows`` of bands (each a list shown together at most) above ``preview``.

    ``rows`` says which bands can be shown at the same moment: the column's
    minimum height is the preview's plus the tallest such set, each band at its
    least, and a wrapped band's text LINES lines longer.
    """

    def __init__(
        self,
        bands: Sequence[QWidget],
        together: Sequence[Sequence[QWidget]],
        preview: QWidget,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self._together = together
        self._preview = preview
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(SPACING)
        for band in bands:
            layout.addWidget(band)
        layout.addWidget(preview, 1)

    def reserved_height(self) -> int:
        """The preview's least height under the tallest set of bands that may show together."""
        line = self.fontMetrics().lineSpacing()
        tallest = max(
            sum(
                band.minimumSizeHint().height()
                + SPACING
                + (LINES * line if band.hasHeightForWidth() else 0)
                for band in bands
            )
            for bands in self._together
        )
        return self._preview.minimumSizeHint().height() + tallest

    def minimumSizeHint(self) -> QSize:
        hint = super().minimumSizeHint()
        return QSize(hint.width(), max(hint.height(), self.reserved_height()))

    def hasHeightForWidth(self) -> bool:
        """No: the dock gives the column its (constant) minimum; inside, the bands wrap."""
        return False
