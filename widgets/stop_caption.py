"""What Stop and Esc say they do, per machine: a stop, or only dropping the queue.

The big Stop, the jog pad's Stop and the key help must promise the same
thing, and only what the machine can do: the PCB drill has no stop command,
so there they say that the queued commands are dropped and the running
procedure finishes.
"""

from __future__ import annotations

from app.profiles import MachineProfile


def stop_caption(profile: MachineProfile) -> tuple[str, str]:
    """What the Stop button (and Esc) will do on this machine: its caption and tooltip."""
    if profile.capabilities.stop_command:
        return "STOP", "Stop every axis now (Esc, from anywhere in the window)"
    running = "procedure" if profile.dialect == "drill" else "move"
    return (
        f"DROP QUEUE\nthis {running}\nfinishes (Esc)",
        f"The {profile.title} has no stop command: this button and Esc drop the commands "
        f"queued after the running one; the {running} it is running finishes",
    )


def stop_key_text(profile: MachineProfile) -> str:
    """Esc's line in the keyboard help, as true on this machine as on the button."""
    if profile.capabilities.stop_command:
        return "Stop everything, from anywhere in the window"
    running = "procedure" if profile.dialect == "drill" else "move"
    return f"Drop the queued commands, from anywhere (no stop command: this {running} finishes)"


def pad_stop_caption(profile: MachineProfile) -> str:
    """The jog pad's small Stop: the same promise in a square button."""
    return "■ Stop" if profile.capabilities.stop_command else "■ Drop\nqueue"
