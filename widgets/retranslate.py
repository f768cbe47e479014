"""Texts that follow a language switch, made again in the new language without a restart.

A widget's text is fixed when it is set: installing another translator later
changes nothing on screen.  Qt's answer is a ``retranslateUi`` that repeats
every ``setText``; kept apart from the code that builds the widget, that list
drifts (a new button stays English after a switch).  Here the text is bound
where the widget is built, as the function that makes it, and made again on
the ``LanguageChange`` event Qt sends through the widget tree when a
translator is installed.  Nothing is rebuilt, so no state (the link, a job,
what the operator typed) is touched by a switch.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QComboBox, QGroupBox, QLabel, QPushButton, QWidget

#: Makes a text in the current language (a lambda around ``self.tr(...)``); called with no
#: arguments (a lambda may bind loop variables as defaults, hence the ``...``).
Maker = Callable[..., str]


class Texts(QObject):
    """The texts of one widget (and what it holds), made again on each language change.

    Qt forwards ``LanguageChange`` from a widget to all its children, this object
    included, so the owner needs no ``changeEvent`` of its own.
    """

    def __init__(self, owner: QWidget) -> None:
        super().__init__(owner)
        self._bound: list[tuple[Callable[[str], object], Maker]] = []
        self._hooks: list[Callable[[], object]] = []

    def set(self, setter: Callable[[str], object], make: Maker) -> None:
        """Call ``setter`` with ``make()`` now and after every language change."""
        setter(make())
        self._bound.append((setter, make))

    def also(self, hook: Callable[[], object]) -> None:
        """Run ``hook`` after a language change: texts made from state (a status, a count)."""
        self._hooks.append(hook)

    def label(self, make: Maker, tip: Maker | None = None) -> QLabel:
        """A label whose text (and tooltip) follow the language."""
        label = QLabel()
        self.set(label.setText, make)
        if tip is not None:
            self.set(label.setToolTip, tip)
        return label

    def button(self, make: Maker, tip: Maker | None = None) -> QPushButton:
        """A push button whose caption (and tooltip) follow the language."""
        button = QPushButton()
        self.set(button.setText, make)
        if tip is not None:
            self.set(button.setToolTip, tip)
        return button

    def group(self, make: Maker) -> QGroupBox:
        """A group box whose title follows the language."""
        box = QGroupBox()
        self.set(box.setTitle, make)
        return box

    def item(self, combo: QComboBox, index: int, make: Maker) -> None:
        """Item ``index`` of ``combo`` follows the language (its data stays the key)."""
        self.set(lambda text: combo.setItemText(index, text), make)

    def retranslate(self) -> None:
        """Make every bound text again, then run the hooks; a deleted widget is dropped."""
        kept: list[tuple[Callable[[str], object], Maker]] = []
        for setter, make in self._bound:
            try:
                setter(make())
            except RuntimeError:  # the widget is gone (its C++ side was deleted)
                continue
            kept.append((setter, make))
        self._bound = kept
        for hook in list(self._hooks):
            try:
                hook()
            except RuntimeError:
                self._hooks.remove(hook)

    def event(self, event: QEvent) -> bool:
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        return super().event(event)


def bold(text: str) -> str:
    """A title as the pages show it (rich text, so ``text`` must not hold markup)."""
    return f"<b>{text}</b>"
