"""The developer pane's frame log: every frame sent and received, injected and dropped.

Kept as a Qt model, no widgets, so that the pane stays a thin view and the
log is tested without clicking.
"""

from __future__ import annotations

import enum
from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass, field, fields, is_dataclass
from pathlib import Path

from PySide6.QtCore import QObject, Signal

from app.developer.gcode import describe_gcode
from app.developer.raw_text import escape_raw
from app.developer.stage import describe_command, describe_echo
from app.developer.words import describe_drill, describe_usb3
from app.machines.session import MachineSession
from app.station import Station
from protocol.stage.codec import (
    CommandFrame,
    EchoFrame,
    Rejected,
    echo_frame_length,
    encode_echo,
)


def describe_message(message: object) -> str:
    """Other dialects' messages are small dataclasses: their fields read well enough."""
    for describe in (describe_gcode, describe_drill, describe_usb3):
        words = describe(message)
        if words is not None:
            return words
    if is_dataclass(message) and not isinstance(message, type):
        values = ", ".join(f"{f.name}={_plain(getattr(message, f.name))}" for f in fields(message))
        return f"{type(message).__name__}({values})"
    return repr(message)


def _plain(value: object) -> str:
    if isinstance(value, enum.Enum):
        return value.name
    if isinstance(value, tuple):
        return "(" + ", ".join(_plain(v) for v in value) + ")"
    return str(value)


# --- the frame log --------------------------------------------------------------------


class LogDirection(enum.StrEnum):
    TX = "TX"  # a command frame the station sent
    RX = "RX"  # an echo the station received
    INJ = "INJ"  # an echo the developer injected
    BAD = "BAD"  # bytes that did not decode (dropped and counted)


@dataclass(frozen=True, slots=True)
class LogEntry:
    seq: int
    time: float  # station clock time
    direction: LogDirection
    raw: str  # escaped, one line
    decoded: str
    line: str = field(compare=False)


#: Entries kept; a 1 kHz stream fills it in 10 s (TX and RX), a 100 ms one in 17 minutes.
LOG_CAPACITY = 20_000


class FrameLog(QObject):
    """Every frame the station sends and receives, injected echoes and rejected bytes.

    Fed by the current session's ``frameSent``/``frameReceived`` (re-attached
    on ``station.sessionChanged``) and by ``station.echoInjected``; bounded to
    the last ``capacity`` entries.

    **Pause** freezes the *view*, not the recording: entries keep arriving in
    the log while paused, but ``entriesAdded`` is held back until resume, so a
    view that follows the signal stands still and then catches up with
    everything that came meanwhile (bar what the capacity pushed out — see
    :meth:`entries_since`).  Dropping frames while paused would make the log lie
    about what crossed the wire exactly when someone is studying it.

    ``entriesAdded`` fires once per entry: views should only mark themselves
    dirty on it and redraw on a timer, pulling :meth:`entries_since`.
    """

    entriesAdded = Signal()
    cleared = Signal()
    pausedChanged = Signal(bool)

    def __init__(
        self, station: Station, capacity: int = LOG_CAPACITY, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._clock = station.clock
        self.origin = self._clock.now()
        self._entries: deque[LogEntry] = deque(maxlen=capacity)
        self._seq = 0
        self._paused = False
        self._held = False
        self._session: MachineSession | None = None
        self._axis_names = [axis.name for axis in station.model.axes]
        self._units = [axis.unit for axis in station.model.axes]
        self._raw_width = echo_frame_length(len(self._axis_names)) + 1
        station.sessionChanged.connect(self._attach)
        station.echoInjected.connect(self._on_injected)
        self._attach()

    # --- reading ------------------------------------------------------------------

    @property
    def capacity(self) -> int:
        return self._entries.maxlen or 0

    @property
    def entries(self) -> list[LogEntry]:
        """Everything recorded, oldest first (held entries of a pause included)."""
        return list(self._entries)

    @property
    def last_seq(self) -> int:
        """Sequence number of the newest entry (0 before the first)."""
        return self._seq

    def __len__(self) -> int:
        return len(self._entries)

    def entries_since(self, seq: int) -> list[LogEntry]:
        """Entries newer than ``seq``.  If the first returned is not ``seq + 1`` the
        capacity pushed some out before they were read."""
        if not self._entries or self._entries[-1].seq <= seq:
            return []
        first = self._entries[0].seq
        if seq < first:
            return list(self._entries)
        out: list[LogEntry] = []
        for entry in reversed(self._entries):
            if entry.seq <= seq:
                break
            out.append(entry)
        out.reverse()
        return out

    @staticmethod
    def matches(entry: LogEntry, text: str) -> bool:
        """The filter: every whitespace-separated word occurs in the line, any case.

        ``"rx charger"`` keeps received echoes that mention the charger; an empty
        filter keeps everything.
        """
        line = entry.line.casefold()
        return all(word in line for word in text.casefold().split())

    def filtered(self, text: str, entries: Iterable[LogEntry] | None = None) -> list[LogEntry]:
        pool = self._entries if entries is None else entries
        if not text.split():
            return list(pool)
        return [e for e in pool if self.matches(e, text)]

    # --- pause, clear, save ---------------------------------------------------------

    @property
    def paused(self) -> bool:
        return self._paused

    def set_paused(self, paused: bool) -> None:
        if paused == self._paused:
            return
        self._paused = paused
        self.pausedChanged.emit(paused)
        if not paused and self._held:
            self._held = False
            self.entriesAdded.emit()

    def clear(self) -> None:
        self._entries.clear()
        self._held = False
        self.cleared.emit()

    def save(self, path: str | Path, filter_text: str = "") -> int:
        """Write the entries that pass ``filter_text`` (all by default), oldest first.

        Entries held by a pause are written too: the file is the record, the
        pause only concerns the view.  Returns the number of entries written.
        """
        chosen = self.filtered(filter_text)
        title = self._station.profile.name
        what = f", filter {filter_text.strip()!r}" if filter_text.strip() else ""
        lines = [
            f"# StepDeck frame log, {title}: {len(chosen)} entries{what}",
            "# time (s since the log started)  dir  raw frame  decoded",
            *(entry.line for entry in chosen),
        ]
        Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")
        return len(chosen)

    # --- recording ----------------------------------------------------------------------

    def _attach(self) -> None:
        session = self._station.session
        if session is self._session:
            return
        self._detach()
        self._session = session
        if session is not None:
            session.frameSent.connect(self._on_sent)
            session.frameReceived.connect(self._on_received)

    def _detach(self) -> None:
        old, self._session = self._session, None
        if old is None:
            return
        try:
            old.frameSent.disconnect(self._on_sent)
            old.frameReceived.disconnect(self._on_received)
        except RuntimeError:
            pass  # already deleted by the station (close_link → deleteLater)

    def _on_sent(self, frame: object, raw: bytes) -> None:
        if isinstance(frame, CommandFrame):
            words = describe_command(frame, self._axis_names, self._units)
        else:
            words = describe_message(frame)
        self._add(LogDirection.TX, raw, words)

    def _on_received(self, frame: object, raw: bytes) -> None:
        if isinstance(frame, EchoFrame):
            self._add(LogDirection.RX, raw, describe_echo(frame, self._axis_names, self._units))
        elif isinstance(frame, Rejected):  # every dialect shares one Rejected
            self._add(LogDirection.BAD, raw, f"rejected: {frame.reason}")
        else:
            self._add(LogDirection.RX, raw, describe_message(frame))

    def _on_injected(self, echo: object) -> None:
        if isinstance(echo, EchoFrame):
            words = describe_echo(echo, self._axis_names, self._units)
            self._add(LogDirection.INJ, encode_echo(echo), words)

    def _add(self, direction: LogDirection, raw: bytes, decoded: str) -> None:
        now = self._clock.now()
        self._seq += 1
        text = escape_raw(raw)
        line = f"{now - self.origin:9.3f}  {direction:<3}  {text:<{self._raw_width}}  {decoded}"
        self._entries.append(LogEntry(self._seq, now, direction, text, decoded, line))
        if self._paused:
            self._held = True
        else:
            self.entriesAdded.emit()
