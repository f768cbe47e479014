"""Work zero on a GRBL board: zero here, choose G54…G59, go to the work zero.

GRBL keeps six work coordinate systems; a job's coordinates are work
coordinates in the one active.  The operator sets a zero where the pen stands
(``G10 L20 P0 X0``: P0 is the system in use, whichever the board has, so the
station's belief cannot make it zero another), chooses a system (``G55``), or
sends the pen there with it up (pen up, then ``G90 G0 X0 Y0``).

Each is judged before a byte goes: zeroing and choosing move nothing but
change what every later position means, so the motion gate takes them only at
rest — no job under way (waiting or paused included), no jog, nothing left to
run (:meth:`~app.machines.motion_gate.MotionGate.refuse_new_zero`); the travel
to the zero is a motion, refused where it would leave the travel, judged in
machine coordinates from the offset the board reported (``WCO:``).  Travel
checks and resume stay in machine coordinates: the board's ``WCO:`` is what
turns one into the other, as before.

The active system is known from the lines sent (``G54``…, and ``M2``/``M30``
and a reset, which select G54 again, as GRBL does) and from the board's own
``$G``; the stored offsets from ``$#`` (:meth:`WorkZero.read` asks for both).
Which machine has work systems is the dialect registry's word, handed in as
:attr:`WorkZero.available`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from PySide6.QtCore import QCoreApplication, SignalInstance

from app.local_numbers import local_number
from app.machines.gcode.hand_zeroing import ZeroingPort, not_at_rest
from app.machines.gcode.lines import SentLine
from app.machines.motion_gate import Refusal
from protocol.gcode.words import grbl_text, scan_words

#: GRBL 1.1's work coordinate systems (``N_COORDINATE_SYSTEM``).
SYSTEMS = ("G54", "G55", "G56", "G57", "G58", "G59")


class WorkZeroPort(ZeroingPort, Protocol):
    """What work zero uses of its session besides what zeroing by hand does."""

    @property
    def work_offset(self) -> tuple[float, ...] | None: ...
    @property
    def linesSent(self) -> SignalInstance: ...
    @property
    def replyText(self) -> SignalInstance: ...
    @property
    def reset(self) -> SignalInstance: ...
    def pen(self, down: bool) -> bool: ...


def system_in(text: str) -> str | None:
    """The coordinate system a line selects (``G55``), G54 for a program end, else None."""
    system: str | None = None
    for letter, value in scan_words(grbl_text(text)):
        if letter == "G" and value in (54.0, 55.0, 56.0, 57.0, 58.0, 59.0):
            system = f"G{round(value)}"
        elif letter == "M" and value in (2.0, 30.0):
            system = "G54"
    return system


class WorkZero:
    """One G-code session's work coordinate systems, and the operator's three actions."""

    def __init__(self, session: WorkZeroPort) -> None:
        self._session = session
        #: The firmware has GRBL's work systems (the registry says; False until it does).
        self.available = False
        #: The system in use as far as known (None before the board's first reset or $G).
        self.system: str | None = None
        #: Each system's stored offset, as the board's last ``$#`` listed it.
        self.stored: dict[str, tuple[float, ...]] = {}
        session.linesSent.connect(self._on_sent)
        session.replyText.connect(self._on_reply)
        session.reset.connect(self._on_reset)

    # --- what is known -----------------------------------------------------------------

    @property
    def offset(self) -> tuple[float, ...] | None:
        """The work offset in force (``WCO:``: the system's plus G92's), once reported."""
        return self._session.work_offset

    def _on_sent(self, lines: list[SentLine]) -> None:
        """One write's lines (a batch: a streaming job writes a thousand a second)."""
        if self.available:
            for sent in lines:
                system = system_in(sent.text)
                if system is not None:
                    self.system = system

    def _on_reply(self, text: str) -> None:
        if not self.available or not text.startswith("[") or not text.endswith("]"):
            return
        body = text[1:-1]
        if body.startswith("GC:"):
            chosen = [word for word in body[3:].split() if word in SYSTEMS]
            if chosen:
                self.system = chosen[0]
            return
        name, colon, values = body.partition(":")
        if colon and name in SYSTEMS:
            try:
                self.stored[name] = tuple(float(v) for v in values.split(","))
            except ValueError:
                return  # not a list of numbers: nothing learnt

    def _on_reset(self) -> None:
        """GRBL comes out of a reset in G54 (its gc_init), its stored systems kept."""
        if self.available:
            self.system = "G54"

    # --- the operator's actions --------------------------------------------------------

    def zero(self, axes: Sequence[str]) -> bool:
        """Here is the work zero of ``axes`` (names) in the system in use: ``G10 L20 P0``."""
        names = [a.name for a in self._session.model.profile.axes]
        named = [a for a in names if a in {n.upper() for n in axes}]
        if not named:
            return self._say(QCoreApplication.translate("WorkZero", "no axis to zero"))
        if self._refused():
            return False
        words = " ".join(f"{name}0" for name in named)
        return self._session.send_line(f"G10 L20 P0 {words}", "intent")

    def select(self, system: str) -> bool:
        """Work in ``system`` (``G54``…``G59``) from now on."""
        if system not in SYSTEMS:
            return self._say(
                QCoreApplication.translate("WorkZero", "{0} is none of G54…G59").format(system)
            )
        if self._refused():
            return False
        return self._session.send_line(system, "intent")

    def read(self) -> bool:
        """Ask the board for its system in use (``$G``) and its stored offsets (``$#``)."""
        if self._refused():
            return False
        return self._session.send_line("$G", "intent") and self._session.send_line("$#", "intent")

    def go_to_zero(self) -> bool:
        """Pen up, then travel to the work zero of every axis (``G90 G0 X0 Y0``).

        The target, in machine coordinates, is the reported work offset; each
        axis is judged by the motion gate before the pen is even lifted.
        """
        session = self._session
        model = session.model
        if self._refused(motion=True):
            return False
        offset = self.offset
        if offset is None:
            return self._say(
                QCoreApplication.translate(
                    "WorkZero", "not sent: the board has not reported its work offset yet"
                )
            )
        names = [a.name for a in model.profile.axes]
        for axis in range(min(len(names), len(offset))):
            if session.gate.refuse(session.gate.refuse_target(axis, offset[axis])):
                return False
        if model.profile.capabilities.pen and not session.pen(False):
            return False
        words = " ".join(f"{name}0" for name in names[: len(offset)])
        return session.send_line(f"G90 G0 {words}", "intent")

    def _refused(self, *, motion: bool = False) -> bool:
        session = self._session
        if not self.available:
            self._say(
                QCoreApplication.translate(
                    "WorkZero", "this machine's firmware has no work coordinate systems"
                )
            )
            return True
        busy = not_at_rest(session)
        if motion:  # a job under way (waiting or paused too) owns the machine, as for a jog
            model = session.model
            reason = model.motion_lock_reason() or model.jog_lock_reason or busy
            return session.gate.refuse(None if reason is None else Refusal(reason))
        refusal = session.gate.refuse_new_zero(busy)
        return refusal is not None and not self._say(str(refusal))

    def _say(self, reason: str) -> bool:
        self._session.model.message.emit(
            QCoreApplication.translate("WorkZero", "Work zero: {0}").format(reason)
        )
        return False

    def describe(self) -> str:
        """The DRO's line: the system in use and its offset (``G55  X 10.000  Y 20.000``)."""
        offset = self.offset
        names = [a.name for a in self._session.model.profile.axes]
        system = self.system or "G5?"
        if offset is None:
            return f"{system}  —"
        values = "  ".join(
            f"{n} {local_number(v, '.3f')}" for n, v in zip(names, offset, strict=False)
        )
        return f"{system}  {values}"
