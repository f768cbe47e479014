"""The window's status bar: the link, the last message (for a while), the rejected frames.

Texts keep the ``MainWindow`` translation context they had when the window
made them itself.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QObject, QTimer
from PySide6.QtWidgets import QLabel, QStatusBar

from app.machine import LinkState
from app.station import Station
from widgets.link_text import link_detail_text, link_state_text
from widgets.retranslate import Texts

#: How long a status-bar message stays (ms): long enough to read twice.
MESSAGE_SHOWN_MS = 15_000


class StatusLine(QObject):
    """What the status bar says, kept true as the link and the session change."""

    def __init__(
        self,
        station: Station,
        bar: QStatusBar,
        texts: Texts,
        rejected_text: Callable[[int], str],
    ) -> None:
        """``rejected_text``: "rejected frames: %n" for a count, made where lupdate sees its
        plural forms (a ``tr`` in the window's own class)."""
        super().__init__(bar)
        self._rejected_text = rejected_text
        self._station = station
        self._model = station.model
        self.link_status = QLabel()
        self.message_label = QLabel()
        self.message_timer = QTimer(self)
        self.message_timer.setSingleShot(True)
        self.message_timer.setInterval(MESSAGE_SHOWN_MS)
        self.message_timer.timeout.connect(self._expire_message)
        #: The link state when the message shown was said (a link failure's message goes
        #: when the link is back).
        self._message_link_state = LinkState.DISCONNECTED
        self.rejected_label = QLabel()
        texts.set(
            self.rejected_label.setToolTip,
            lambda: QCoreApplication.translate(
                "MainWindow", "Frames from the device that failed to decode"
            ),
        )
        bar.addWidget(self.link_status)
        bar.addWidget(self.message_label, 1)
        bar.addPermanentWidget(self.rejected_label)
        self.show_rejected()
        self._model.linkStateChanged.connect(self.show_link_status)
        self._model.message.connect(self.show_message)
        self._model.linkStateChanged.connect(self._clear_link_message)
        station.sessionChanged.connect(self._attach_session)
        self._attach_session()

    def show_link_status(self, _state: object = None) -> None:
        state = self._model.link_state
        detail = (
            f" — {link_detail_text(self._model.link_detail)}" if self._model.link_detail else ""
        )
        session = self._station.session
        period = (
            f" · {session.period_ms} ms"
            if session is not None and state in (LinkState.CONNECTED, LinkState.STALE)
            else ""
        )
        self.link_status.setText(
            QCoreApplication.translate("MainWindow", "Link {0}").format(link_state_text(state))
            + detail
            + period
        )

    def show_message(self, text: str) -> None:
        """Show ``text`` until the next message or for MESSAGE_SHOWN_MS, whichever comes first.

        A message left standing reads as the current state long after it stopped being
        true ("stopping…" an hour later).  The same text again only restarts the clock.
        """
        if self._repeats_link_status(text):
            return
        self.message_label.setText(text)
        self.message_label.setToolTip(text)
        self._message_link_state = self._model.link_state
        self.message_timer.start()

    def _repeats_link_status(self, text: str) -> bool:
        """Whether ``text`` only says again what the link status beside it says now.

        "Link lost: no reply" next to "Link lost — no reply" read as two events.
        """
        state = self._model.link_state
        detail = self._model.link_detail
        if state in (LinkState.CONNECTED, LinkState.DISCONNECTED) or not detail:
            return False
        link = self._station.link
        if link is not None and detail == link.describe():
            return False  # only the port's name: the message says more
        return detail in text

    def _expire_message(self) -> None:
        self.message_label.clear()
        self.message_label.setToolTip("")

    def _clear_link_message(self, state: object) -> None:
        """A message from while the link was failing is wrong once it is back ("no answer…")."""
        if state is LinkState.CONNECTED and self._message_link_state in (
            LinkState.CONNECTING,
            LinkState.STALE,
            LinkState.LOST,
        ):
            self.message_timer.stop()
            self._expire_message()

    def show_rejected(self, *_args: object) -> None:
        session = self._station.session
        count = session.rejected if session is not None else 0
        self.rejected_label.setText(self._rejected_text(count))

    def _attach_session(self) -> None:
        # The count changes with what arrives: refresh on every received frame.
        session = self._station.session
        if session is not None:
            session.frameReceived.connect(self.show_rejected)
        self.show_rejected()
        self.show_link_status()
