"""Which stored settings a session's device keeps: the dialects' halves joined.

The dialects must not import each other (an import-linter contract), so
the one place that knows both GRBL's ``$$`` and the usb3 unit's EEPROM sits
above them, as the station does.
"""

from __future__ import annotations

import weakref

from PySide6.QtCore import QObject

from app.machines.gcode.grbl_settings import GRBL_SETTINGS
from app.machines.gcode.grbl_settings_access import GrblSettingsAccess
from app.machines.gcode.session import GcodeSession
from app.machines.settings_access import SettingsAccess
from app.machines.stored_settings import StoredSetting
from app.machines.usb3.eeprom_access import Usb3EepromAccess, eeprom_settings
from app.machines.usb3.session import Usb3Session
from app.profiles import MachineProfile

#: One access per session, made when first asked for (it lives as long as its session).
_MADE: weakref.WeakKeyDictionary[QObject, SettingsAccess] = weakref.WeakKeyDictionary()


def settings_access(session: QObject | None) -> SettingsAccess | None:
    """The stored settings of ``session``, or None when its device keeps none the station edits.

    (The stage's parameters have their own page and calls: Dynamics, ``read_parameters``.)
    """
    if session is None:
        return None
    made = _MADE.get(session)
    if made is None:
        if isinstance(session, GcodeSession) and "$$" in session.settings.words:
            made = GrblSettingsAccess(session)
        elif isinstance(session, Usb3Session):
            made = Usb3EepromAccess(session)
        else:
            return None
        _MADE[session] = made
    return made


def specs_for(session_type: type, profile: MachineProfile) -> tuple[StoredSetting, ...] | None:
    """The settings a machine of this session type and profile keeps (before it connects:
    the window builds its page from them), or None."""
    if issubclass(session_type, GcodeSession):
        words = profile.gcode.words if profile.gcode is not None else ()
        return GRBL_SETTINGS if "$$" in words else None
    if issubclass(session_type, Usb3Session):
        return eeprom_settings(tuple(axis.name for axis in profile.axes))
    return None
