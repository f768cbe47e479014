"""The job preview with the bands that come and go above it, in a height that does not change.

The registration row, the offer to resume an interrupted run and the
operator's prompt ("insert T01…", Continue) appear while a job is loaded or
runs.  Stacked on the preview they used to add their height to the dock's
minimum, so a prompt made the window grow (a drill at 1206 x 839 on an 800 px
screen, and still 839 high after the job).  Here they take their room from
the preview instead: the column asks for the same minimum height whichever
bands are shown, the preview's least plus room for the tallest set of bands,
and when bands are shown the preview gives up that room (down to its own
least, which is small).
"""

from __future__ import annotations

from collections.abc import Sequence

from PySide6.QtCore import QEvent, QSize
from PySide6.QtGui import QResizeEvent
from PySide6.QtWidgets import QVBoxLayout, QWidget

# Space between the bands and the preview (px).
SPACING = 4
# Lines of text a wrapped band may take beyond its hint (which counts its text as it is
# now, often none while it is hidden) within the room kept for it.
LINES = 2
# What the preview has beyond its own least height when no band is shown (px).
PREVIEW_ROOM = 90


class PreviewColumn(QWidget):
    """``bands`` above ``preview``; ``together`` says which bands may show at the same time."""

    def __init__(
        self,
        bands: Sequence[QWidget],
        together: Sequence[Sequence[QWidget]],
        preview: QWidget,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self._bands = bands
        self._together = together
        self._preview = preview
        self._reserved: int | None = None
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(SPACING)
        for band in bands:
            layout.addWidget(band)
        layout.addWidget(preview, 1)

    def reserved_height(self) -> int:
        """The preview's least height and room, plus the tallest set of bands at their least
        (a wrapped band's text LINES lines longer).

        Measured once (again after a change of font, style or language), with the bands as
        they are then: a band's hint follows the text it shows, and the reserve must not.
        """
        if self._reserved is None:
            self._reserved = self._measure_reserve()
        return self._reserved

    def changeEvent(self, event: QEvent) -> None:
        if event.type() in (
            QEvent.Type.FontChange,
            QEvent.Type.StyleChange,
            QEvent.Type.LanguageChange,
        ):
            self._reserved = None
            self.updateGeometry()
        super().changeEvent(event)

    def _measure_reserve(self) -> int:
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
        return self._preview.minimumSizeHint().height() + PREVIEW_ROOM + tallest

    def needed_height(self) -> int:
        """What the bands shown now take at this width (wrapped text counted), and the
        preview's least: more than the room kept only for a very long text."""
        width = self.width()
        needed = self._preview.minimumSizeHint().height()
        for band in self._bands:
            if band.isHidden():
                continue
            height = band.heightForWidth(width) if band.hasHeightForWidth() else -1
            needed += max(height, band.minimumSizeHint().height()) + SPACING
        return needed

    def minimumSizeHint(self) -> QSize:
        hint = super().minimumSizeHint()
        return QSize(hint.width(), max(self.reserved_height(), self.needed_height()))

    def hasHeightForWidth(self) -> bool:
        """No: the dock gives the column its (constant) minimum; inside, the bands wrap."""
        return False

    def resizeEvent(self, event: QResizeEvent) -> None:
        super().resizeEvent(event)
        if event.size().width() != event.oldSize().width():
            self.updateGeometry()  # a wrapped band's height follows the width
