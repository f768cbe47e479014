"""Units as the operator reads them: "steps" and "mm/rev" are words, and words are translated.

Profiles, parameters and fields name their units in English ("deg", "µsteps",
"mm/rev"); the window shows each through here, so a Czech or Slovak operator
reads "°", "µkroky", "mm/ot".  Symbols (mm, mm/s, ms, V, °C) are the same in
every language and pass through unchanged.
"""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

#: The unit words the station shows, for lupdate; anything else is a symbol.
WORDS = (
    QT_TRANSLATE_NOOP("Unit", "deg"),
    QT_TRANSLATE_NOOP("Unit", "deg/s"),
    QT_TRANSLATE_NOOP("Unit", "steps"),
    QT_TRANSLATE_NOOP("Unit", "µsteps"),
    QT_TRANSLATE_NOOP("Unit", "mm/rev"),
    QT_TRANSLATE_NOOP("Unit", "frames"),
)


def shown_unit(unit: str) -> str:
    """``unit`` in the language installed (unchanged when it is a symbol)."""
    return QCoreApplication.translate("Unit", unit) if unit else unit
