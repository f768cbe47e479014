"""The band that explains a GRBL alarm or error, with the buttons that clear it.

Shown above the G-code console when the board reports ``ALARM:n`` or
``error:n``: the code, GRBL's meaning in the operator's language, the action
that clears it, and buttons for what the station can do (unlock ``$X``, home
``$H``; homing goes through the session's motion gate like the Home button).
After a hard or soft limit GRBL answers nothing until a soft reset
(:mod:`~app.machines.gcode.limit_lock`): the band then offers Reset (0x18),
and Unlock and Home reset the board first, their line following its banner.
Each code is shown once (:class:`~app.machines.gcode.grbl_codes.Explainer`):
a board in alarm answers every line ``error:9`` and repeats its alarm, and
nothing of it is new.  The band goes when the board leaves its alarm, or a
line is accepted after an error.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QFrame, QHBoxLayout, QLabel, QVBoxLayout, QWidget

from app.machines.gcode.grbl_codes import Explainer, Explanation, Remedy, explain
from app.machines.gcode.session import GcodeSession
from protocol.gcode.codec import AlarmReply, ErrorReply, Ok, StatusReport
from widgets.retranslate import Texts


class GrblAlarmBand(QFrame):
    """One alarm or error explained, with its remedies as buttons (hidden when none)."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("grbl_alarm_band")
        self.setFrameShape(QFrame.Shape.StyledPanel)
        self.explainer = Explainer()
        self._session: GcodeSession | None = None
        t = self.texts = Texts(self)
        self.title = QLabel()
        self.title.setObjectName("grbl_alarm_title")
        font = self.title.font()
        font.setBold(True)
        self.title.setFont(font)
        self.meaning = QLabel()
        self.meaning.setWordWrap(True)
        self.action = QLabel()
        self.action.setWordWrap(True)
        self.unlock_button = t.button(lambda: self.tr("Unlock ($X)"))
        self.unlock_button.clicked.connect(self.unlock)
        self.home_button = t.button(lambda: self.tr("Home ($H)"))
        self.home_button.clicked.connect(self.home)
        self.reset_button = t.button(lambda: self.tr("Reset (Ctrl-X)"))
        self.reset_button.setObjectName("grbl_alarm_reset")
        self.reset_button.clicked.connect(self.reset)
        self.reset_button.hide()
        texts = QVBoxLayout()
        texts.addWidget(self.title)
        texts.addWidget(self.meaning)
        texts.addWidget(self.action)
        row = QHBoxLayout(self)
        row.addLayout(texts, 1)
        row.addWidget(self.reset_button)
        row.addWidget(self.home_button)
        row.addWidget(self.unlock_button)
        self.hide()

    def watch(self, session: GcodeSession | None) -> None:
        """Explain what ``session``'s board reports (None: nothing; the band is hidden)."""
        if self._session is not None:
            self._session.frameReceived.disconnect(self._reply)
        self._session = session
        self.explainer = Explainer()
        self.hide()
        if session is not None:
            session.frameReceived.connect(self._reply)

    def _reply(self, reply: object, _raw: bytes) -> None:
        locked = self._session is not None and self._session.limit_lock.waiting
        if self.reset_button.isVisibleTo(self) != locked:
            self.reset_button.setVisible(locked)
        if isinstance(reply, AlarmReply | ErrorReply):
            kind = "ALARM" if isinstance(reply, AlarmReply) else "error"
            shown = self.explainer.reply(kind, reply.code)
            if shown is not None:
                self._show(shown)
        elif isinstance(reply, Ok):
            if self.explainer.accepted():
                self.hide()
        elif isinstance(reply, StatusReport) and self.explainer.state(reply.state):
            self.hide()

    def _show(self, shown: Explanation) -> None:
        self.title.setText(shown.title)
        self.meaning.setText(shown.meaning)
        self.action.setText(shown.action)
        words = self._session.settings.words if self._session is not None else ()
        self.unlock_button.setVisible(Remedy.UNLOCK in shown.remedies and "$X" in words)
        self.home_button.setVisible(Remedy.HOME in shown.remedies and "$H" in words)
        self.show()

    def unlock(self) -> None:
        """``$X``: the board takes lines again, its position as it was (nothing moves); a
        board locked after a limit is reset first, ``$X`` goes after its banner."""
        if self._session is not None:
            self._session.limit_lock.unlock()

    def home(self) -> None:
        """``$H``, as the Home button sends it (refused by the motion gate where it must be);
        a board locked after a limit is reset first."""
        if self._session is not None:
            self._session.limit_lock.before_clearing()
            self._session.home(0)

    def reset(self) -> None:
        """0x18: ends GRBL's lock after a limit; the board restarts, still in alarm, and
        nothing moves."""
        if self._session is not None:
            self._session.limit_lock.reset()

    def changeEvent(self, event: QEvent) -> None:
        super().changeEvent(event)
        explainer = getattr(self, "explainer", None)  # Qt asks while the band is being built
        shown = explainer.shown if explainer is not None else None
        if event.type() is QEvent.Type.LanguageChange and shown is not None:
            self._show(explain(*shown.key))
