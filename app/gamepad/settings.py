"""The gamepad's two remembered values: whether it jogs, and which device (by name).

Global, not per machine profile: the pad belongs to the person at the desk, and it jogs
whichever machine the window drives.  Read through :class:`app.settings.StationSettings`,
so a hand-edited or stale value gives the default and a warning, never a failed start.
"""

from __future__ import annotations

from app.settings import BadValue, Spec

#: Longest device name kept (SDL's names are well under this).
NAME_LIMIT = 128


def _truth(value: object) -> bool:
    if isinstance(value, bool):
        return value
    if isinstance(value, str) and value.strip().lower() in ("true", "false"):
        return value.strip().lower() == "true"
    raise BadValue("not true or false")


def _name(value: object) -> str:
    if not isinstance(value, str):
        raise BadValue(f"a {type(value).__name__}")
    if len(value) > NAME_LIMIT or not value.isprintable():
        raise BadValue("not a short printable name")
    return value


GAMEPAD_ENABLED = Spec("gamepad/enabled", False, "true or false", _truth)
#: "" : the first device found.
GAMEPAD_DEVICE = Spec("gamepad/device", "", "a device name", _name)
