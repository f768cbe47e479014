"""A terminal's line entry: the lines sent are kept and walked with Up/Down, as in a shell."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QLineEdit, QWidget

from widgets.style import monospace_font


class HistoryLineEdit(QLineEdit):
    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setFont(monospace_font())
        self._history: list[str] = []
        self._index = 0

    @property
    def history(self) -> tuple[str, ...]:
        return tuple(self._history)

    def take(self) -> str:
        """The stripped text, remembered (once, if repeated) and cleared from the entry."""
        text = self.text().strip()
        if text and (not self._history or self._history[-1] != text):
            self._history.append(text)
        self._index = len(self._history)
        self.clear()
        return text

    def keyPressEvent(self, event: QKeyEvent) -> None:
        if event.key() == Qt.Key.Key_Up:
            self._walk(-1)
        elif event.key() == Qt.Key.Key_Down:
            self._walk(1)
        else:
            super().keyPressEvent(event)

    def _walk(self, step: int) -> None:
        if not self._history:
            return
        self._index = max(0, min(len(self._history), self._index + step))
        if self._index == len(self._history):
            self.clear()
        else:
            self.setText(self._history[self._index])
