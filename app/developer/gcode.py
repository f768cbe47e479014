"""The developer pane's G-code half: replies in words, injected replies, the emulator's buttons.

A developer testing a sender wants to see what the station does with an
``error:9`` in the middle of a job, an ``ALARM:1``, a board that reports
``Hold``, or garbage — without a board that misbehaves on cue.  Injected
text goes through the session exactly as bytes from the device would (so
it answers the oldest unanswered line, moves the model, counts as a
reject), and the frame log shows it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject

from app.local_numbers import local_number
from app.machine import LinkState
from app.machines.gcode.meanings import alarm_meaning, error_meaning
from app.machines.gcode.session import GcodeSession
from app.station import Station
from protocol.gcode.codec import (
    AlarmReply,
    Banner,
    ErrorReply,
    Feedback,
    GcodeReply,
    Ok,
    Rejected,
    StatusReport,
    decode,
)

if TYPE_CHECKING:
    from protocol.emulator.gcode_firmware import GcodeFirmware

#: Replies a developer reaches for most, for the pane's quick buttons.
QUICK_REPLIES = (
    ("ok", "ok"),
    ("error:20", "error:20"),
    ("ALARM:1", "ALARM:1"),
    ("Hold", "<Hold:0|MPos:0.000,0.000,0.000|FS:0,0>"),
    (str(QT_TRANSLATE_NOOP("GcodeReplyBox", "banner")), "Grbl 1.1h ['$' for help]"),
)


def describe_gcode(message: object) -> str | None:
    """A G-code line or reply in words for the frame log; None when it is none of them."""
    if isinstance(message, str):
        return message
    if isinstance(message, Ok):
        return QCoreApplication.translate(
            "FrameWords", "ok: the oldest unanswered line was accepted"
        )
    if isinstance(message, ErrorReply):
        return QCoreApplication.translate("FrameWords", "error {0}: {1}").format(
            message.code, error_meaning(message.code)
        )
    if isinstance(message, AlarmReply):
        return QCoreApplication.translate("FrameWords", "alarm {0}: {1}").format(
            message.code, alarm_meaning(message.code)
        )
    if isinstance(message, StatusReport):
        where = ", ".join(local_number(v, ".3f") for v in message.mpos)
        report = QCoreApplication.translate("FrameWords", "{0} at ({1}), feed {2}").format(
            message.state, where, local_number(message.feed)
        )
        if message.planner_free:
            report += QCoreApplication.translate("FrameWords", ", {0} planner blocks free").format(
                message.planner_free
            )
        return report
    if isinstance(message, Banner):
        return QCoreApplication.translate("FrameWords", 'the board (re)started: "{0}"').format(
            message.text
        )
    if isinstance(message, Feedback):
        # Quoted as the banner is: the board's own words, in its language, not the station's.
        return QCoreApplication.translate("FrameWords", 'message: "{0}"').format(message.text)
    return None


def parse_reply(text: str) -> GcodeReply:
    """The reply ``text`` is, as the station would decode it; ValueError says why not."""
    line = text.strip()
    if not line:
        raise ValueError("type a reply, e.g. ok, error:20, ALARM:1 or <Idle|MPos:0,0,0|FS:0,0>")
    try:
        raw = line.encode("ascii") + b"\n"
    except UnicodeEncodeError:
        raise ValueError("replies are ASCII") from None
    used, reply = decode(raw)
    if isinstance(reply, Rejected):
        raise ValueError(f"the station would drop this: {reply.reason}")
    if reply is None or used != len(raw):
        raise ValueError("not one reply line")
    return reply


def inject_reply(station: Station, text: str) -> GcodeReply:
    """Hand ``text`` to the G-code session as if the device had sent it.

    Checked first (ValueError with the reason) so a developer's typo is not
    mistaken for a device's garbage; deliberate garbage is what
    :func:`inject_raw` is for.
    """
    reply = parse_reply(text)
    inject_raw(station, text.strip().encode("ascii") + b"\n")
    return reply


def inject_raw(station: Station, data: bytes) -> None:
    session = _session(station)
    session.receive_injected(data)


def _session(station: Station) -> GcodeSession:
    session = station.session_as(GcodeSession)
    if session is None or station.model.link_state is not LinkState.CONNECTED:
        raise ValueError("connect a G-code machine first")
    return session


class GcodeEmulatorButtons(QObject):
    """The emulated board's own buttons (hold, resume, an alarm), with no protocol import."""

    def __init__(self, station: Station, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._station = station

    @property
    def available(self) -> bool:
        return self._emulator() is not None and self._station.loopback is not None

    def _emulator(self) -> GcodeFirmware | None:
        """The emulated G-code board, when this station's dialect has one and it is made."""
        if not issubclass(self._station.dialect.session_type, GcodeSession):
            return None  # another dialect's emulator; the G-code board's module stays unloaded
        from protocol.emulator.gcode_firmware import GcodeFirmware

        return self._station.emulator_as(GcodeFirmware)

    def hold(self) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.feed_hold()

    def resume(self) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.cycle_start()

    def alarm(self, code: int = 1) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.trigger_alarm(code)

    def white_button(self) -> str:
        """The winder's white button (S0-24): "drivers off", "zero set" or "ignored"."""
        if (emulator := self._emulator()) is not None:
            return emulator.white_button()
        return "ignored"

    def turn_by_hand(self, axis: str, delta: float) -> bool:
        """Turn an axis whose driver is off by hand; False when it holds (or no emulator)."""
        if (emulator := self._emulator()) is not None:
            return emulator.turn_by_hand(axis, delta)
        return False
