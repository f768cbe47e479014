"""Menu panel: the buttons that choose what the dynamic panel shows.

Like the stage's original tool, the middle of the window is one stacked area
whose page is picked by a column of buttons, so the window stays small while
offering manual, absolute, relative and dynamics controls.
"""

from __future__ import annotations

from PySide6.QtCore import Signal
from PySide6.QtWidgets import QButtonGroup, QPushButton, QStackedWidget, QVBoxLayout, QWidget

from widgets.style import CHECKED_BUTTON_STYLE


class MenuPanel(QWidget):
    """A column of exclusive page buttons driving a :class:`QStackedWidget`."""

    pageChanged = Signal(int)

    def __init__(self, stack: QStackedWidget, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._stack = stack
        self._group = QButtonGroup(self)
        self._group.setExclusive(True)
        self._group.idClicked.connect(self.set_page)
        self._layout = QVBoxLayout(self)
        self._layout.setContentsMargins(0, 0, 0, 0)
        self._layout.setSpacing(6)
        self._layout.addStretch(1)

    def add_page(self, title: str, page: QWidget, tooltip: str = "") -> QPushButton:
        """Add ``page`` to the stack with a button titled ``title`` (``&`` marks Alt+letter)."""
        index = self._stack.addWidget(page)
        button = QPushButton(title)
        button.setCheckable(True)
        button.setStyleSheet(CHECKED_BUTTON_STYLE)
        button.setMinimumWidth(110)
        button.setMinimumHeight(34)
        button.setToolTip(tooltip)
        self._group.addButton(button, index)
        self._layout.insertWidget(self._layout.count() - 1, button)
        if index == self._stack.currentIndex():
            button.setChecked(True)
        return button

    def button(self, index: int) -> QPushButton:
        found = self._group.button(index)
        assert isinstance(found, QPushButton)
        return found

    @property
    def current(self) -> int:
        return self._stack.currentIndex()

    def set_page(self, index: int) -> None:
        if not 0 <= index < self._stack.count():
            return
        self._stack.setCurrentIndex(index)
        self.button(index).setChecked(True)
        self.pageChanged.emit(index)
