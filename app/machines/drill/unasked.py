"""Replies the drill owes for nothing the station sent: a command repeated or changed on the way.

The drill's wire has no checksum and no echo (docs/link-faults.md): a line
repeated on the way is run twice, a flipped letter runs another procedure,
and the drill acknowledges either as its own.  What the station can still
see is an ``R`` or a ``D`` it did not ask for.  Most of them are harmless —
a reply repeated on the way back, or a repeated absolute move (``X594``
twice ends where once does) — but a second drill cycle enlarges a hole, and
a procedure the station never sent puts the tool somewhere the job does not
know.  This ledger tells them apart so a job never ends "done" past one
(the relay's pcb-drill seed 55: ``V`` repeated, acknowledged twice, a hole
drilled twice and the job said done).

A flipped digit (``X594`` arriving as ``X514``) is acknowledged like the
command sent: nothing the drill says shows it.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from PySide6.QtCore import QT_TRANSLATE_NOOP

from protocol.drill.codec import ReplyKind

#: Procedures whose second run leaves the machine where one run does (absolute positions,
#: a pen position, homing, parking): repeating them changes nothing on the board.
HARMLESS_AGAIN = frozenset("XYKZNP")


@dataclass
class ReplyLedger:
    """What the drill acknowledged beyond the command in flight, until it finished it."""

    #: ``R`` heard once more than sent, per letter: their ``D`` is still to come.
    _extra: Counter[str] = field(default_factory=Counter)
    #: The letter of the last procedure the station saw finish (a ``D`` repeated on the way).
    _last_done: str | None = None

    #: Commands in flight when the link went or fell silent: their R and D may still come.
    _abandoned: Counter[str] = field(default_factory=Counter)

    def abandoned(self, letter: str) -> None:
        """The station dropped the command in flight (link lost): the drill may still answer it."""
        self._abandoned[letter] += 1

    def done(self, letter: str) -> None:
        """The command in flight finished (its own ``D``)."""
        self._last_done = letter

    def again(self, letter: str) -> str | None:
        """A second ``R`` for the command in flight: why it matters, or None (harmless).

        Either the reply was repeated on the way back or the command on the way
        there; the station cannot tell which, so a repeat that would harm is
        taken as run.
        """
        self._extra[letter] += 1
        if letter in HARMLESS_AGAIN:
            return None
        return str(
            QT_TRANSLATE_NOOP(
                "DrillSession",
                "acknowledged twice: the command or its answer was repeated on the way",
            )
        )

    def unasked(self, kind: ReplyKind, letter: str, in_flight: str | None) -> str | None:
        """An ``R``/``D`` for another command than the one in flight (or none): why, or None."""
        if self._abandoned[letter] > 0:
            if kind is ReplyKind.DONE:
                self._abandoned[letter] -= 1  # the end of what it had when the link went
            return None
        if kind is ReplyKind.DONE:
            if self._extra[letter] > 0:
                self._extra[letter] -= 1  # the end of a repeat already judged at its R
                return None
            if letter == self._last_done:
                return None  # the last D, repeated on the way back
            return str(
                QT_TRANSLATE_NOOP("DrillSession", "finished a procedure the station did not send")
            )
        if kind is ReplyKind.RECEIVED:
            if letter in HARMLESS_AGAIN and letter == self._last_done and in_flight is None:
                self._extra[letter] += 1  # a repeat of the last command, received late
                return None
            return str(
                QT_TRANSLATE_NOOP(
                    "DrillSession",
                    "received a command the station did not send (a line changed on the way)",
                )
            )
        return None
