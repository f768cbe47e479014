"""The window's pages, in a column that scrolls up and down when the screen is short.

A page's height must never set the window's: the tallest page (the winder's
G-code console, the drill's terminal) under the info panel and above the
telemetry dock made the window taller than an 800 px screen, and the status
bar and the dock tabs went below its edge.  So the pages sit in a scroll area
whose minimum height is small; where there is room (the usual case) the page
fills it and no scroll bar shows.  Sideways the area never scrolls: it is as
wide as the widest page needs, so no field or button is cut at the right.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, QSize, Qt
from PySide6.QtWidgets import QFrame, QScrollArea, QStackedWidget, QStyle, QWidget


class PageStack(QStackedWidget):
    """Pages on top of each other: as wide as the widest, as tall as the one shown.

    Qt's stack asks for the tallest page's height whichever page is shown, so a
    short page (Link) would scroll for the sake of a tall one it hides.
    """

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.currentChanged.connect(lambda _index: self.updateGeometry())

    def _shown_height(self, size: QSize, page_size: QSize) -> QSize:
        margins = self.contentsMargins()
        return QSize(size.width(), page_size.height() + margins.top() + margins.bottom())

    def minimumSizeHint(self) -> QSize:
        hint = super().minimumSizeHint()
        page = self.currentWidget()
        if page is None:
            return hint
        return self._shown_height(hint, _smart_minimum(page))

    def sizeHint(self) -> QSize:
        hint = super().sizeHint()
        page = self.currentWidget()
        if page is None:
            return hint
        return self._shown_height(hint, page.sizeHint().expandedTo(_smart_minimum(page)))

    def hasHeightForWidth(self) -> bool:
        page = self.currentWidget()
        return page is not None and page.hasHeightForWidth()

    def heightForWidth(self, width: int) -> int:
        """The page shown's (Qt's stack takes the tallest page's, shown or not)."""
        page = self.currentWidget()
        if page is None:
            return -1
        margins = self.contentsMargins()
        height = page.heightForWidth(width - margins.left() - margins.right())
        if height < 0:
            return -1
        return max(height, _smart_minimum(page).height()) + margins.top() + margins.bottom()


def _smart_minimum(widget: QWidget) -> QSize:
    """The least a layout gives ``widget``: its explicit minimum where set, else its hint."""
    hint = widget.minimumSizeHint()
    explicit = widget.minimumSize()
    return QSize(
        explicit.width() or max(hint.width(), 0), explicit.height() or max(hint.height(), 0)
    )


class PageArea(QScrollArea):
    """The scroll area around a :class:`PageStack`: vertical only, as wide as the pages."""

    def __init__(self, stack: PageStack, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("page_area")
        self.setFrameShape(QFrame.Shape.NoFrame)
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.setWidgetResizable(True)
        self.setWidget(stack)
        self.stack = stack
        stack.currentChanged.connect(self._page_changed)

    def _page_changed(self, _index: int) -> None:
        """Size the stack to the page now shown: Qt's scroll area looks again only when its
        own size or its scroll bar changes, so a short page kept a tall one's scroll range."""
        QCoreApplication.postEvent(self, QEvent(QEvent.Type.LayoutRequest))

    def event(self, event: QEvent) -> bool:
        """A page grown wider (a usb3 page once its values came) asks its stack to lay out
        again, and that request lands here: the window's layout kept the area's old
        minimum, cached, and cut the page's right edge by the difference."""
        if event.type() == QEvent.Type.LayoutRequest:
            self.updateGeometry()
        return super().event(event)

    def minimumSizeHint(self) -> QSize:
        """The pages' width and a scroll bar's; a few lines of height, the rest scrolls."""
        bar = self.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent, None, self)
        width = _smart_minimum(self.stack).width() + bar + 2 * self.frameWidth()
        return QSize(width, super().minimumSizeHint().height())
