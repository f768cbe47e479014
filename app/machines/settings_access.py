"""Reading and writing a device's stored settings, each write verified by reading back.

One interface for GRBL's ``$N`` (:mod:`app.machines.gcode.grbl_settings_access`)
and the usb3 unit's EEPROM (:mod:`app.machines.usb3.eeprom_access`), so the
Settings page, the scripting API and the snapshots do not care which.

A write is judged whole before a byte goes out: every value against its
row (:meth:`~app.machines.stored_settings.StoredSetting.check`), the values
together against what the device holds (the subclass's rules), and the
moment (:meth:`SettingsAccess.why_not_now`: never while a job runs or an
axis moves).  One refusal refuses the whole write, with every reason, and
nothing is sent.  A write sent is then read back; only values the device
reads back as written count as written, the others are refusals naming
what the device keeps.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.machine import LinkState, MachineModel
from app.machines.stored_settings import StoredSetting


@dataclass(frozen=True)
class Outcome:
    """How a read or a write ended."""

    #: "read" or "write".
    kind: str
    #: The values the device read back as written (a write), or every value read.
    values: dict[str, float] = field(default_factory=dict)
    #: Why a value was not written, or why the read failed (empty: all went well).
    refusals: tuple[str, ...] = ()

    @property
    def ok(self) -> bool:
        return not self.refusals


class SettingsAccess(QObject):
    """The stored settings of one session; subclasses speak the wire."""

    #: :attr:`values` changed (a read, a verified write, a report nobody asked for).
    changed = Signal()
    #: A read or write ended: its :class:`Outcome`.
    finished = Signal(object)

    #: What the settings are called in the window and in snapshots ("grbl", "usb3-eeprom").
    kind = ""

    def __init__(self, model: MachineModel, specs: tuple[StoredSetting, ...], parent: QObject):
        super().__init__(parent)
        self.model = model
        self.specs = specs
        self.by_key = {spec.key: spec for spec in specs}
        #: What the device last said it holds, by key.
        self.values: dict[str, float] = {}
        #: The last read or write's outcome (None before any).
        self.last: Outcome | None = None
        #: A read or write under way ("read"/"write"), None when idle.
        self.busy: str | None = None
        #: What a write under way asked for.
        self._wanted: dict[str, float] = {}
        #: The firmware version the device said it runs (a snapshot records it), None until
        #: it says, and for a device with no way to say it (the usb3 unit's wire has none).
        self.firmware: str | None = None
        model.linkStateChanged.connect(self._link_changed)

    # --- the subclass's part --------------------------------------------------------

    def why_not_now(self) -> str | None:
        """Why nothing may be read or written now (in the operator's language), or None."""
        if self.model.link_state not in (LinkState.CONNECTED, LinkState.STALE):
            return QCoreApplication.translate("SettingsAccess", "not connected")
        if self.model.jog_lock_reason is not None:
            return QCoreApplication.translate("SettingsAccess", "a job is running")
        if self.model.any_moving:
            return QCoreApplication.translate("SettingsAccess", "the machine is moving")
        return None

    def cross_check(self, changes: Mapping[str, float]) -> list[str]:
        """Why ``changes`` would be wrong together with what the device holds."""
        return []

    def _send_read(self) -> bool:
        raise NotImplementedError

    def _send_writes(self, changes: Mapping[str, float]) -> bool:
        raise NotImplementedError

    # --- the operations -----------------------------------------------------------------

    def validate(self, changes: Mapping[str, object]) -> list[str]:
        """Every reason the write must not go (empty: it may), the moment aside."""
        reasons: list[str] = []
        for key, value in changes.items():
            spec = self.by_key.get(key)
            if spec is None:
                reasons.append(
                    QCoreApplication.translate("SettingsAccess", "{0}: no such setting").format(key)
                )
                continue
            problem = spec.check(value)
            if problem is not None:
                reasons.append(problem)
        if not reasons:
            reasons += self.cross_check({k: float(v) for k, v in changes.items()})  # type: ignore[arg-type]
        return reasons

    def read(self) -> str | None:
        """Ask the device for every setting; the reason when it cannot be done now."""
        refusal = self.busy_reason() or self.why_not_now()
        if refusal is not None:
            return refusal
        self.busy = "read"
        if not self._send_read():
            self.busy = None
            return QCoreApplication.translate("SettingsAccess", "not sent")
        return None

    def write(self, changes: Mapping[str, object]) -> str | None:
        """Write ``changes`` and read them back; the reason when nothing was sent.

        The values that differ from what the device holds are sent; the rest are
        counted written once read back like the others.
        """
        if not changes:
            return QCoreApplication.translate("SettingsAccess", "nothing to write")
        reasons = self.validate(changes)
        refusal = self.busy_reason() or self.why_not_now()
        if refusal is not None:
            reasons.insert(0, refusal)
        if reasons:
            return "; ".join(reasons)
        self._wanted = {key: float(value) for key, value in changes.items()}  # type: ignore[arg-type]
        self.busy = "write"
        if not self._send_writes(self._wanted):
            self.busy = None
            return QCoreApplication.translate("SettingsAccess", "not sent")
        return None

    def busy_reason(self) -> str | None:
        if self.busy == "read":
            return QCoreApplication.translate("SettingsAccess", "a read is under way")
        if self.busy == "write":
            return QCoreApplication.translate("SettingsAccess", "a write is under way")
        return None

    # --- endings -----------------------------------------------------------------------

    def _finish_read(self, values: Mapping[str, float]) -> None:
        self.values.update(values)
        self._end(Outcome("read", dict(values)))
        self.changed.emit()

    def _finish_write(self, read_back: Mapping[str, float], refused: Mapping[str, str]) -> None:
        """Judge the write by what the device read back after it (``refused``: the device's
        own refusals, by key)."""
        self.values.update(read_back)
        written: dict[str, float] = {}
        refusals = list(refused.values())
        for key, wanted in self._wanted.items():
            spec = self.by_key[key]
            held = read_back.get(key)
            if held is not None and spec.same(wanted, held):
                written[key] = wanted
            elif key not in refused:
                kept = "?" if held is None else spec.shown_value(held)
                refusals.append(
                    QCoreApplication.translate(
                        "SettingsAccess", "{0}: {1} was written, the device keeps {2}"
                    ).format(key, spec.shown_value(wanted), kept)
                )
        self._wanted = {}
        self._end(Outcome("write", written, tuple(refusals)))
        self.changed.emit()

    def _fail(self, reason: str) -> None:
        """The operation under way cannot end (a lost link, a reset board)."""
        if self.busy is None:
            return
        kind = self.busy
        self._wanted = {}
        self._forget()
        self._end(Outcome(kind, {}, (reason,)))

    def _forget(self) -> None:
        """What the subclass awaited will not come (its lines or reports are lost)."""

    def _end(self, outcome: Outcome) -> None:
        self.busy = None
        self.last = outcome
        self.finished.emit(outcome)

    def _link_changed(self, state: LinkState) -> None:
        if state is LinkState.DISCONNECTED:
            self.firmware = None  # the next link may be to another board
        if state in (LinkState.LOST, LinkState.DISCONNECTED):
            self._fail(
                QCoreApplication.translate(
                    "SettingsAccess", "the link went down before the device answered"
                )
            )
