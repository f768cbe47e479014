"""GRBL's ``$$`` read and ``$N=value`` written through the session's stream, then read back.

GRBL 1.1 has no command that echoes one setting: a write is answered
``ok`` or ``error:n`` only, so every write ends with a ``$$`` whose list
is compared with what was asked for (:meth:`StoredSetting.same`: GRBL
keeps 32-bit floats).  The lines go through the session's one stream
(origin ``"settings"``), so the character counting and the ``ok`` per
line hold for them as for any line; a ``$N=value`` line is made only from
a row of :data:`~app.machines.gcode.grbl_settings.GRBL_SETTINGS` and a
value it passed.

A read asks ``$I`` first where the firmware has it: its ``[VER:…]``, like
the banner, gives the version a snapshot records (:mod:`.grbl_version`).

GRBL takes ``$$`` and writes while idle or in alarm (``error:8`` otherwise);
the station asks for more: the machine idle or in alarm by its last status
report, every line answered, no job and no axis moving.  A ``$$`` typed in
the console updates the values too.
"""

from __future__ import annotations

from collections.abc import Mapping

from PySide6.QtCore import QCoreApplication

from app.machines.gcode.grbl_settings import GRBL_SETTINGS, cross_check, parse_setting_line
from app.machines.gcode.grbl_version import kept, version_in
from app.machines.gcode.session import GcodeSession, SentLine
from app.machines.settings_access import SettingsAccess

#: The lines' origin in the session (the frame log and the console show it).
ORIGIN = "settings"
#: GRBL states in which it takes ``$$`` and ``$N=``, as the station allows them.
QUIET_STATES = ("Idle", "Alarm")


class GrblSettingsAccess(SettingsAccess):
    kind = "grbl"

    def __init__(self, session: GcodeSession) -> None:
        super().__init__(session.model, GRBL_SETTINGS, session)
        self.session = session
        #: ``$N=`` lines heard since the last ``$$`` sent (GRBL lists them before its ok).
        self._heard: dict[str, float] = {}
        #: The settings lines sent and not answered, oldest first.
        self._unanswered: list[str] = []
        #: The device's refusals of this write, by key.
        self._refused: dict[str, str] = {}
        session.replyText.connect(self._reply)
        session.lineAcknowledged.connect(self._acknowledged)
        session.lineFailed.connect(self._failed)
        session.reset.connect(self._board_reset)

    def why_not_now(self) -> str | None:
        reason = super().why_not_now()
        if reason is not None:
            return reason
        session = self.session
        state = session.machine_state
        if session.stopping:
            return QCoreApplication.translate("SettingsAccess", "the machine is stopping")
        if state not in QUIET_STATES:
            return QCoreApplication.translate(
                "SettingsAccess", "the board is {0}: settings wait until it stands idle"
            ).format(state or QCoreApplication.translate("SettingsAccess", "not heard from yet"))
        if not session.settled:
            return QCoreApplication.translate(
                "SettingsAccess", "lines sent before are still being run"
            )
        return None

    def cross_check(self, changes: Mapping[str, float]) -> list[str]:
        return cross_check(changes, self.values, self.model.profile)

    # --- the wire -------------------------------------------------------------------------

    def _send_read(self) -> bool:
        self._refused = {}
        if "$I" in self.session.settings.words and not self._send("$I"):
            return False
        return self._send("$$")

    def _send_writes(self, changes: Mapping[str, float]) -> bool:
        self._refused = {}
        for spec in self.specs:  # GRBL's order, whatever order they came in
            if spec.key in changes:
                value = changes[spec.key]
                held = self.values.get(spec.key)
                if held is not None and spec.same(value, held):
                    continue  # already there: the read back proves it
                if not self._send(f"{spec.key}={spec.wire_text(value)}"):
                    return False
        return self._send("$$")

    def _send(self, line: str) -> bool:
        if self.session.send_line(line, ORIGIN):
            self._unanswered.append(line)
            if line == "$$":
                self._heard = {}
            return True
        self._fail(QCoreApplication.translate("SettingsAccess", "{0} was not sent").format(line))
        return False

    # --- replies ----------------------------------------------------------------------------

    def _reply(self, text: str) -> None:
        version = version_in(text)
        if version is not None:
            self.firmware = kept(self.firmware, version)
            return
        parsed = parse_setting_line(text)
        if parsed is None or parsed[0] not in self.by_key:
            return
        key, value = parsed
        if self.busy is not None:
            self._heard[key] = value
        elif self.values.get(key) != value:  # a $$ from the console
            self.values[key] = value
            self.changed.emit()

    def _acknowledged(self, sent: SentLine) -> None:
        if sent.origin != ORIGIN or not self._unanswered:
            return
        line = self._unanswered.pop(0)
        if line != "$$" or self._unanswered:
            return
        heard, self._heard = self._heard, {}
        if self.busy == "read":
            self._finish_read(heard)
        elif self.busy == "write":
            self._finish_write(heard, self._refused)

    def _failed(self, sent: SentLine, code: int, meaning: str) -> None:
        if sent.origin != ORIGIN or not self._unanswered:
            return
        line = self._unanswered.pop(0)
        if line == "$$":
            self._fail(
                QCoreApplication.translate("SettingsAccess", "$$ refused: error {0}, {1}").format(
                    code, meaning
                )
            )
            return
        self._refused[line.partition("=")[0]] = QCoreApplication.translate(
            "SettingsAccess", "{0}: refused, error {1}, {2}"
        ).format(line, code, meaning)

    def _forget(self) -> None:
        self._unanswered.clear()
        self._heard = {}

    def _board_reset(self) -> None:
        self._unanswered.clear()
        self._fail(
            QCoreApplication.translate("SettingsAccess", "the board was reset before it answered")
        )
