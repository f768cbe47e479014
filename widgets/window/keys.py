"""The window's two safety rules for keys, which no single panel can enforce.

* Keys are routed application-wide, so arrows jog and Esc stops whatever
  widget of the window has focus — except that arrows keep editing inside
  text fields, Esc also closes an open menu or list, and a dialog (a file
  dialog, the list of keys…) keeps its keys: there Esc closes the dialog and
  never runs the stop.
* Whenever the window may stop seeing key releases (deactivated, focus gone,
  application inactive) every jog is released, so a jog can never run away
  because its key-up went to another window.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtGui import QFocusEvent, QKeyEvent
from PySide6.QtWidgets import (
    QAbstractSpinBox,
    QApplication,
    QDialog,
    QLineEdit,
    QMainWindow,
    QPlainTextEdit,
    QTextEdit,
    QWidget,
)

from widgets.jog_input import JogInput
from widgets.number_field import NumberField

#: Widgets in which arrow keys move a text cursor or step a value, so they must not jog.
TEXT_EDITING = (QLineEdit, QAbstractSpinBox, QTextEdit, QPlainTextEdit)


def is_text_editing(widget: QWidget | None) -> bool:
    """Whether ``widget`` or one of its ancestors edits text (a spin box's line edit…)."""
    while widget is not None:
        if isinstance(widget, TEXT_EDITING):
            return True
        widget = widget.parentWidget()
    return False


def is_free_text(widget: QWidget | None) -> bool:
    """A field where any character is input (not a number field, whose keys we may take)."""
    if isinstance(widget, (QTextEdit, QPlainTextEdit)):
        return True
    if not isinstance(widget, QLineEdit) or isinstance(widget, NumberField):
        return False
    parent = widget.parentWidget()
    return not isinstance(parent, QAbstractSpinBox)


def in_dialog(widget: QObject) -> bool:
    """Whether ``widget`` is in a dialog, or in a popup (a combo's list…) opened from one.

    A dialog owns its keys: Esc cancels it and arrows move in it.  Neither may reach
    the machine — Esc in a file dialog's type list once ran the stop, and arrows in
    its file list would have jogged.
    """
    current = widget if isinstance(widget, QWidget) else None
    while current is not None:
        if isinstance(current, QDialog):
            return True
        current = current.parentWidget()
    return False


def in_popup(widget: QWidget) -> bool:
    """Whether ``widget`` is in the popup (menu, combo list) that has the keyboard now."""
    popup = QApplication.activePopupWidget()
    return popup is not None and (widget is popup or popup.isAncestorOf(widget))


class KeyRouter(QObject):
    """The application's event filter while the window is shown: jog keys, Esc, Shift+V.

    ``toggle_developer`` shows or hides the developer pane: its shortcut, for the
    number fields that swallow the keystroke before the shortcut sees it.
    """

    def __init__(
        self, window: QMainWindow, jog: JogInput, toggle_developer: Callable[[], None]
    ) -> None:
        super().__init__(window)
        self._window = window
        self._jog = jog
        self._toggle_developer = toggle_developer
        self._filtering = False

    def install(self) -> None:
        app = QApplication.instance()
        if self._filtering or not isinstance(app, QApplication):
            return
        app.installEventFilter(self)
        app.applicationStateChanged.connect(self._on_application_state)
        self._filtering = True

    def remove(self) -> None:
        app = QApplication.instance()
        if not self._filtering or not isinstance(app, QApplication):
            return
        app.removeEventFilter(self)
        app.applicationStateChanged.disconnect(self._on_application_state)
        self._filtering = False

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        kind = event.type()
        if kind in (QEvent.Type.KeyPress, QEvent.Type.KeyRelease):
            if isinstance(event, QKeyEvent) and self._owns(watched) and not in_dialog(watched):
                assert isinstance(watched, QWidget)
                return self._route_key(watched, event)
        elif kind == QEvent.Type.WindowDeactivate:
            if watched is self._window:
                self._jog.release_all()
        elif kind == QEvent.Type.FocusOut:
            if isinstance(event, QFocusEvent) and self._owns(watched) and self._focus_left(event):
                self._jog.release_all()
        elif kind == QEvent.Type.ApplicationDeactivate:
            self._jog.release_all()
        return False

    def _owns(self, watched: QObject) -> bool:
        """Whether ``watched`` belongs to the window, floating docks included."""
        widget = watched if isinstance(watched, QWidget) else None
        while widget is not None:
            if widget is self._window:
                return True
            widget = widget.parentWidget()
        return False

    def _focus_left(self, event: QFocusEvent) -> bool:
        """Whether keyboard focus left the window (not just moved inside it)."""
        if event.reason() in (
            Qt.FocusReason.ActiveWindowFocusReason,
            Qt.FocusReason.PopupFocusReason,
        ):
            return True
        now = QApplication.focusWidget()
        return now is None or now.window() is not self._window

    def _route_key(self, receiver: QWidget, event: QKeyEvent) -> bool:
        """Handle jog keys and Esc; returns True when the event is consumed."""
        jog = self._jog
        key = event.key()
        press = event.type() == QEvent.Type.KeyPress
        if key == Qt.Key.Key_Escape:
            if press and not event.isAutoRepeat():
                jog.stop_all()
            # A menu or combo list of this window that is open closes too: the stop is
            # never a reason to leave it hanging over the window.
            return not in_popup(receiver)
        if key == Qt.Key.Key_Shift:
            if not event.isAutoRepeat():
                jog.set_shift(press)
            return False
        if key == Qt.Key.Key_V and event.modifiers() == Qt.KeyboardModifier.ShiftModifier:
            # The action's shortcut handles most of the window; number fields swallow the
            # keystroke first, so it is routed here. Free text keeps its capital V.
            if not press or event.isAutoRepeat() or is_free_text(QApplication.focusWidget()):
                return False
            self._toggle_developer()
            return True
        if not jog.is_jog_key(key):
            return False
        if event.isAutoRepeat():
            # The key is already held: its repeats feed the dead-man and reach no widget.
            if press:
                return jog.key_repeat(key)
            return jog.is_held(key)
        if not press:
            return jog.key_release(key)
        if is_text_editing(receiver) or is_text_editing(QApplication.focusWidget()):
            return False
        jog.set_shift(bool(event.modifiers() & Qt.KeyboardModifier.ShiftModifier))
        jog.key_press(key)
        return True

    def _on_application_state(self, state: Qt.ApplicationState) -> None:
        if state != Qt.ApplicationState.ApplicationActive:
            self._jog.release_all()
