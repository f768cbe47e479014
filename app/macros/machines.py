"""Which machines run macros: those sent G-code text as written (the registry says which).

The others — the stage, the usb3 unit, the drill — speak in frames or
commands the station composes from moves; a snippet of their wire language
typed by hand would bypass the composing that keeps them safe, and a list
of moves for them is what a points file already is.  So they have no
macros, and the window shows none.
"""

from __future__ import annotations

from app.machines.registry import dialect_for
from app.profiles import MachineProfile


def macros_available(profile: MachineProfile) -> bool:
    """Macros are G-code text: only machines sent G-code text as written run them."""
    try:
        return dialect_for(profile).takes_gcode_text
    except ValueError:
        return False
