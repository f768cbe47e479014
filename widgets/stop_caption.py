"""What Stop and Esc say they do, per machine: a stop, or only dropping the queue.

The big Stop, the jog pad's Stop and the key help must promise the same
thing, and only what the machine can do: the PCB drill has no stop command,
so there they say that the queued commands are dropped and the running
procedure finishes.  The texts are made in the current language on each call.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from app.profiles import MachineProfile
from widgets.dialects import DropCaption, window_dialect


def stop_caption(profile: MachineProfile) -> tuple[str, str]:
    """What the Stop button (and Esc) will do on this machine: its caption and tooltip."""
    if profile.capabilities.stop_command:
        return (
            QCoreApplication.translate("StopCaption", "STOP"),
            QCoreApplication.translate(
                "StopCaption", "Stop every axis now (Esc, from anywhere in the window)"
            ),
        )
    if window_dialect(profile).drop_caption is DropCaption.PROCEDURE:
        return (
            QCoreApplication.translate("StopCaption", "DROP QUEUE\nthis procedure\nfinishes (Esc)"),
            QCoreApplication.translate(
                "StopCaption",
                "The {0} has no stop command: this button and Esc drop the commands "
                "queued after the running one; the procedure it is running finishes",
            ).format(profile.shown_title),
        )
    return (
        QCoreApplication.translate("StopCaption", "DROP QUEUE\nthis move\nfinishes (Esc)"),
        QCoreApplication.translate(
            "StopCaption",
            "The {0} has no stop command: this button and Esc drop the commands "
            "queued after the running one; the move it is running finishes",
        ).format(profile.shown_title),
    )


def stop_key_text(profile: MachineProfile) -> str:
    """Esc's line in the keyboard help, as true on this machine as on the button."""
    if profile.capabilities.stop_command:
        return QCoreApplication.translate(
            "StopCaption", "Stop everything, from anywhere in the window"
        )
    if window_dialect(profile).drop_caption is DropCaption.PROCEDURE:
        return QCoreApplication.translate(
            "StopCaption",
            "Drop the queued commands, from anywhere (no stop command: this procedure finishes)",
        )
    return QCoreApplication.translate(
        "StopCaption",
        "Drop the queued commands, from anywhere (no stop command: this move finishes)",
    )


def pad_stop_caption(profile: MachineProfile) -> str:
    """The jog pad's small Stop: the same promise in a square button."""
    if profile.capabilities.stop_command:
        return QCoreApplication.translate("StopCaption", "■ Stop")
    return QCoreApplication.translate("StopCaption", "■ Drop\nqueue")
