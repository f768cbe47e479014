"""The usb3 unit's and the drill's frames in words, in the operator's language, for the log.

The frame log showed these as Python reprs (``Reply(kind=ERROR, letter=I)``),
which a developer decodes by reading the codec and an operator not at all;
each frame is said here as the wire contract (docs/protocols.md) means it.
"""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.local_numbers import local_number
from protocol.drill import codec as drill
from protocol.usb3 import codec as usb3

CONTEXT = "FrameWords"

#: What each drill command letter does (docs/protocols.md, the drill).
DRILL_COMMANDS: dict[str, str] = {
    "N": str(QT_TRANSLATE_NOOP("FrameWords", "home both axes")),
    "X": str(QT_TRANSLATE_NOOP("FrameWords", "move X to {0} µsteps")),
    "Y": str(QT_TRANSLATE_NOOP("FrameWords", "move Y to {0} µsteps")),
    "V": str(QT_TRANSLATE_NOOP("FrameWords", "drill a hole")),
    "K": str(QT_TRANSLATE_NOOP("FrameWords", "pen down")),
    "Z": str(QT_TRANSLATE_NOOP("FrameWords", "pen up")),
    "P": str(QT_TRANSLATE_NOOP("FrameWords", "park")),
}
DRILL_REPLIES: dict[drill.ReplyKind, str] = {
    drill.ReplyKind.RECEIVED: str(QT_TRANSLATE_NOOP("FrameWords", "{0} received")),
    drill.ReplyKind.DONE: str(QT_TRANSLATE_NOOP("FrameWords", "{0} done")),
    drill.ReplyKind.ERROR: str(QT_TRANSLATE_NOOP("FrameWords", "{0} refused (error)")),
}


def _tr(text: str) -> str:
    return QCoreApplication.translate(CONTEXT, text)


def describe_drill(message: object) -> str | None:
    """A drill command or reply in words; None when it is neither."""
    if isinstance(message, drill.Command):
        return _tr(DRILL_COMMANDS[message.letter]).format(message.value)
    if isinstance(message, drill.Reply):
        return _tr(DRILL_REPLIES[message.kind]).format(message.letter)
    return None


def _per_axis(values: tuple[str, ...]) -> str:
    return ", ".join(
        f"{axis.name} {value}" for axis, value in zip(usb3.AxisId, values, strict=False)
    )


def describe_usb3(message: object) -> str | None:
    """A usb3 unit's command or reply in words; None when it is neither."""
    if isinstance(message, usb3.SetDirection):
        signs = tuple("+" if sign > 0 else "-" for sign in message.signs)
        return QCoreApplication.translate("FrameWords", "directions {0}").format(_per_axis(signs))
    if isinstance(message, usb3.Move):
        return QCoreApplication.translate("FrameWords", "move {0} by {1} counts").format(
            message.axis.name, message.count
        )
    if isinstance(message, usb3.StepSizes):
        return QCoreApplication.translate("FrameWords", "step sizes {0}").format(
            _per_axis(tuple(s.label for s in message.sizes))
        )
    if isinstance(message, usb3.Threads):
        threads = tuple(f"{t.name} ({local_number(t.pitch_mm)} mm)" for t in message.threads)
        return QCoreApplication.translate("FrameWords", "threads {0}").format(_per_axis(threads))
    if isinstance(message, usb3.ZeroAll):
        return QCoreApplication.translate("FrameWords", "every axis is zero where it stands")
    if isinstance(message, usb3.GetSettings):
        return QCoreApplication.translate("FrameWords", "ask for the step sizes and threads")
    if isinstance(message, usb3.StopAll):
        return QCoreApplication.translate("FrameWords", "stop every axis")
    if isinstance(message, usb3.Position):
        return QCoreApplication.translate("FrameWords", "{0} stands at {1} counts").format(
            message.axis.name, message.count
        )
    if isinstance(message, usb3.NotUnderstood):
        return QCoreApplication.translate("FrameWords", "the unit did not understand a command")
    return None
