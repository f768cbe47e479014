"""The usb3 unit's EEPROM values, read with ``G;`` and written with ``M`` / ``T``, then read back.

What the unit keeps across power cycles is each axis's step size and lead
screw thread (docs/protocols.md §2, FIDELITY S4-19): the wire has no other
stored value.  ``M`` and ``T`` set all three axes at once and the unit
answers nothing to them, so the session follows each with a ``G;``, and
the write is judged by the report of the last one: the unit handles its
messages in order, so that report holds every change sent before it.  A
report the operator's menu on the unit makes counts too: it is what the
unit holds.

A value is a CHOICE row: the wire digit (step size 0…5 = full…1/32, thread
0…6 = M2…M10), shown by its label.  The unit refuses a digit out of range
with ``?;``; the station never sends one.
"""

from __future__ import annotations

from collections.abc import Mapping

from PySide6.QtCore import QT_TRANSLATE_NOOP

from app.machines.settings_access import SettingsAccess
from app.machines.stored_settings import Kind, StoredSetting
from app.machines.usb3.session import Usb3Session
from protocol.usb3.codec import StepSize, StepSizes, Thread, Threads

CONTEXT = "Usb3Setting"
STEP_CHOICES = tuple(
    (int(size), label)
    for size, label in zip(
        StepSize,
        (
            QT_TRANSLATE_NOOP("Usb3Setting", "full step"),
            QT_TRANSLATE_NOOP("Usb3Setting", "1/2 step"),
            QT_TRANSLATE_NOOP("Usb3Setting", "1/4 step"),
            QT_TRANSLATE_NOOP("Usb3Setting", "1/8 step"),
            QT_TRANSLATE_NOOP("Usb3Setting", "1/16 step"),
            QT_TRANSLATE_NOOP("Usb3Setting", "1/32 step"),
        ),
        strict=True,
    )
)
THREAD_CHOICES = tuple(
    (int(thread), f"{thread.name} ({thread.pitch_mm:g} mm)") for thread in Thread
)
_STEP_LABEL = QT_TRANSLATE_NOOP("Usb3Setting", "{0} step size")
_STEP_TEXT = QT_TRANSLATE_NOOP(
    "Usb3Setting",
    "The driver's microstep: finer steps move more smoothly and more slowly (the pulse rate "
    "stays the same).",
)
_THREAD_LABEL = QT_TRANSLATE_NOOP("Usb3Setting", "{0} thread")
_THREAD_TEXT = QT_TRANSLATE_NOOP(
    "Usb3Setting",
    "The axis's lead screw: how far one turn moves it. It decides how the unit's counts "
    "become millimetres.",
)


def eeprom_settings(axes: tuple[str, ...]) -> tuple[StoredSetting, ...]:
    """Each axis's step size, then each axis's thread."""
    steps = tuple(
        StoredSetting(
            key=f"{axis}.step_size",
            label=str(_STEP_LABEL),
            unit="",
            description=str(_STEP_TEXT),
            kind=Kind.CHOICE,
            low=0,
            high=len(STEP_CHOICES) - 1,
            choices=tuple((number, str(label)) for number, label in STEP_CHOICES),
            context=CONTEXT,
            axis=axis,
        )
        for axis in axes
    )
    threads = tuple(
        StoredSetting(
            key=f"{axis}.thread",
            label=str(_THREAD_LABEL),
            unit="",
            description=str(_THREAD_TEXT),
            kind=Kind.CHOICE,
            low=0,
            high=len(THREAD_CHOICES) - 1,
            choices=THREAD_CHOICES,
            context=CONTEXT,
            axis=axis,
        )
        for axis in axes
    )
    return steps + threads


class Usb3EepromAccess(SettingsAccess):
    kind = "usb3-eeprom"

    def __init__(self, session: Usb3Session) -> None:
        axes = tuple(axis.name for axis in session.model.profile.axes)
        super().__init__(session.model, eeprom_settings(axes), session)
        self.session = session
        self.axes = axes
        #: Complete settings reports (a ``T`` after its ``M``) still awaited.
        self._reports_due = 0
        self._heard: dict[str, float] = {}
        session.frameReceived.connect(self._frame)

    def _send_read(self) -> bool:
        self._reports_due = 1
        self.session.request_settings()
        return True

    def _send_writes(self, changes: Mapping[str, float]) -> bool:
        session = self.session
        sent = 0
        for index, axis in enumerate(self.axes):
            size = changes.get(f"{axis}.step_size")
            if size is not None and StepSize(int(size)) != session.step_sizes[index]:
                session.set_step_size(index, StepSize(int(size)))
                sent += 1
            thread = changes.get(f"{axis}.thread")
            if thread is not None and Thread(int(thread)) != session.threads[index]:
                session.set_thread(index, Thread(int(thread)))
                sent += 1
        if not sent:  # nothing differs from what the session holds: read it back to be sure
            session.request_settings()
            sent = 1
        self._reports_due = sent  # each set_* asks G; once
        return True

    def _forget(self) -> None:
        self._reports_due = 0

    def _frame(self, reply: object, _raw: bytes) -> None:
        if isinstance(reply, StepSizes):
            for axis, size in zip(self.axes, reply.sizes, strict=False):
                self._heard[f"{axis}.step_size"] = float(int(size))
        elif isinstance(reply, Threads):
            for axis, thread in zip(self.axes, reply.threads, strict=False):
                self._heard[f"{axis}.thread"] = float(int(thread))
            self._report_complete()

    def _report_complete(self) -> None:
        heard = dict(self._heard)
        if self.busy is None:
            if any(self.values.get(k) != v for k, v in heard.items()):
                self.values.update(heard)  # the unit's menu, or a report asked by the panel
                self.changed.emit()
            return
        self._reports_due -= 1
        if self._reports_due > 0:
            return
        if self.busy == "read":
            self._finish_read(heard)
        else:
            self._finish_write(heard, {})
