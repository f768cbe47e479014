"""GRBL 1.1's alarms and errors in words: what happened, and what clears it.

An operator who reads ``ALARM:1`` or ``error:9`` has to look the number up,
and then guess what to do; unlocking a board whose position was lost (a hard
limit) instead of homing it can drive an axis into its end.  So each code
carries its meaning (GRBL 1.1's own description, ``doc/csv/*_codes_en_US.csv``
in grbl 1.1h's sources), the action that clears it, and
the remedies the station can run for the operator (unlock ``$X``, home
``$H``).  A board that lost its position is offered homing only.

The texts are marked for translation here (context ``GrblCodes``) and
translated where they are shown (:func:`explain`).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

CONTEXT = "GrblCodes"


class Remedy(enum.Enum):
    """What the station can do for the operator about a code (a button)."""

    UNLOCK = "$X"
    HOME = "$H"


#: The actions, in words (each code says one).
HOME = QT_TRANSLATE_NOOP("GrblCodes", "Home the machine ($H): its position is likely lost.")
LIMITS = QT_TRANSLATE_NOOP(
    "GrblCodes", "Check the limit switches and their wiring, then home the machine ($H)."
)
#: After a hard or soft limit GRBL answers nothing until it is reset (limit_lock.py).
LIMIT_HIT = QT_TRANSLATE_NOOP(
    "GrblCodes",
    "Reset the board (Ctrl-X): it answers nothing until then. Check the limit switches, then "
    "home the machine ($H), or unlock it ($X) only if its position is surely right.",
)
SOFT_LIMIT = QT_TRANSLATE_NOOP(
    "GrblCodes",
    "Reset the board (Ctrl-X): it answers nothing until then. Then unlock it ($X): its "
    "position is kept; or home it ($H).",
)
PROBE = QT_TRANSLATE_NOOP("GrblCodes", "Check the probe and its wiring, then unlock ($X).")
DOOR = QT_TRANSLATE_NOOP("GrblCodes", "Close the safety door, then home the machine ($H).")
LINE = QT_TRANSLATE_NOOP("GrblCodes", "Correct the line: the board did not run it.")
SETTING = QT_TRANSLATE_NOOP("GrblCodes", "Check the board's settings ($$).")
IDLE = QT_TRANSLATE_NOOP("GrblCodes", "Wait until the machine stands idle, then send it again.")
ALARM_FIRST = QT_TRANSLATE_NOOP(
    "GrblCodes", "Clear the alarm first: home the machine ($H), or unlock it ($X)."
)
DOOR_OPEN = QT_TRANSLATE_NOOP("GrblCodes", "Close the safety door.")
TRAVEL = QT_TRANSLATE_NOOP("GrblCodes", "Jog within the machine's travel.")


@dataclass(frozen=True)
class CodeText:
    """A code's meaning and action (English, marked for translation) and its remedies."""

    meaning: object  # QT_TRANSLATE_NOOP's source text
    action: object
    remedies: tuple[Remedy, ...] = ()


_HOMING = (Remedy.HOME,)
_EITHER = (Remedy.HOME, Remedy.UNLOCK)

ALARMS: dict[int, CodeText] = {
    1: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Hard limit has been triggered. Machine position is likely lost due to sudden halt. Re-homing is highly recommended.",  # noqa: E501
        ),
        LIMIT_HIT,
        _HOMING,
    ),
    2: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Soft limit alarm. G-code motion target exceeds machine travel. Machine position retained. Alarm may be safely unlocked.",  # noqa: E501
        ),
        SOFT_LIMIT,
        _EITHER,
    ),
    3: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Reset while in motion. Machine position is likely lost due to sudden halt. Re-homing is highly recommended.",  # noqa: E501
        ),
        HOME,
        _HOMING,
    ),
    4: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Probe fail. Probe is not in the expected initial state before starting probe cycle.",
        ),
        PROBE,
        (Remedy.UNLOCK,),
    ),
    5: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Probe fail. Probe did not contact the workpiece within the programmed travel.",
        ),
        PROBE,
        (Remedy.UNLOCK,),
    ),
    6: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Homing fail. The active homing cycle was reset.",
        ),
        HOME,
        _HOMING,
    ),
    7: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Homing fail. Safety door was opened during homing cycle.",
        ),
        DOOR,
        _HOMING,
    ),
    8: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Homing fail. Pull off travel failed to clear limit switch. Try increasing pull-off setting or check wiring.",  # noqa: E501
        ),
        LIMITS,
        _HOMING,
    ),
    9: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Homing fail. Could not find limit switch within search distances. Try increasing max travel, decreasing pull-off distance, or check wiring.",  # noqa: E501
        ),
        LIMITS,
        _HOMING,
    ),
    10: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Homing fail. Second dual axis limit switch failed to trigger within configured search distance after first. Try increasing trigger fail distance or check wiring.",  # noqa: E501
        ),
        LIMITS,
        _HOMING,
    ),
}

ERRORS: dict[int, CodeText] = {
    1: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G-code words consist of a letter and a value. Letter was not found.",
        ),
        LINE,
    ),
    2: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Missing the expected G-code word value or numeric value format is not valid.",
        ),
        LINE,
    ),
    3: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Grbl '$' system command was not recognized or supported.",
        ),
        LINE,
    ),
    4: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Negative value received for an expected positive value.",
        ),
        LINE,
    ),
    5: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Homing cycle failure. Homing is not enabled via settings.",
        ),
        SETTING,
    ),
    6: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Minimum step pulse time must be greater than 3usec.",
        ),
        SETTING,
    ),
    7: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "An EEPROM read failed. Auto-restoring affected EEPROM to default values.",
        ),
        SETTING,
    ),
    8: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Grbl '$' command cannot be used unless Grbl is IDLE. Ensures smooth operation during a job.",  # noqa: E501
        ),
        IDLE,
    ),
    9: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G-code commands are locked out during alarm or jog state.",
        ),
        ALARM_FIRST,
        _EITHER,
    ),
    10: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Soft limits cannot be enabled without homing also enabled.",
        ),
        SETTING,
    ),
    11: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Max characters per line exceeded. Received command line was not executed.",
        ),
        LINE,
    ),
    12: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Grbl '$' setting value cause the step rate to exceed the maximum supported.",
        ),
        SETTING,
    ),
    13: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Safety door detected as opened and door state initiated.",
        ),
        DOOR_OPEN,
    ),
    14: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Build info or startup line exceeded EEPROM line length limit. Line not stored.",
        ),
        LINE,
    ),
    15: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Jog target exceeds machine travel. Jog command has been ignored.",
        ),
        TRAVEL,
    ),
    16: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Jog command has no '=' or contains prohibited g-code.",
        ),
        LINE,
    ),
    17: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Laser mode requires PWM output.",
        ),
        SETTING,
    ),
    20: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Unsupported or invalid g-code command found in block.",
        ),
        LINE,
    ),
    21: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "More than one g-code command from same modal group found in block.",
        ),
        LINE,
    ),
    22: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Feed rate has not yet been set or is undefined.",
        ),
        LINE,
    ),
    23: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G-code command in block requires an integer value.",
        ),
        LINE,
    ),
    24: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "More than one g-code command that requires axis words found in block.",
        ),
        LINE,
    ),
    25: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Repeated g-code word found in block.",
        ),
        LINE,
    ),
    26: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "No axis words found in block for g-code command or current modal state which requires them.",  # noqa: E501
        ),
        LINE,
    ),
    27: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Line number value is invalid.",
        ),
        LINE,
    ),
    28: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G-code command is missing a required value word.",
        ),
        LINE,
    ),
    29: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G59.x work coordinate systems are not supported.",
        ),
        LINE,
    ),
    30: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G53 only allowed with G0 and G1 motion modes.",
        ),
        LINE,
    ),
    31: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Axis words found in block when no command or current modal state uses them.",
        ),
        LINE,
    ),
    32: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G2 and G3 arcs require at least one in-plane axis word.",
        ),
        LINE,
    ),
    33: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Motion command target is invalid.",
        ),
        LINE,
    ),
    34: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Arc radius value is invalid.",
        ),
        LINE,
    ),
    35: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G2 and G3 arcs require at least one in-plane offset word.",
        ),
        LINE,
    ),
    36: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Unused value words found in block.",
        ),
        LINE,
    ),
    37: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "G43.1 dynamic tool length offset is not assigned to configured tool length axis.",
        ),
        LINE,
    ),
    38: CodeText(
        QT_TRANSLATE_NOOP(
            "GrblCodes",
            "Tool number greater than max supported value.",
        ),
        LINE,
    ),
}


@dataclass(frozen=True)
class Explanation:
    """One alarm or error as the operator is shown it (translated)."""

    key: tuple[str, int]
    title: str
    meaning: str
    action: str
    remedies: tuple[Remedy, ...]


def explain(kind: str, code: int) -> Explanation:
    """``kind`` "ALARM" or "error" and its code, in the language installed now."""
    table = ALARMS if kind == "ALARM" else ERRORS
    text = table.get(code)
    title = f"{kind}:{code}"
    if text is None:
        unknown = QCoreApplication.translate("GrblCodes", "A code GRBL 1.1 does not document.")
        return Explanation((kind, code), title, unknown, "", ())
    tr = QCoreApplication.translate
    return Explanation(
        (kind, code),
        title,
        tr(CONTEXT, str(text.meaning)),
        tr(CONTEXT, str(text.action)),
        text.remedies,
    )


class Explainer:
    """Which alarm or error is shown now: each once, nothing again while nothing changes.

    A board in alarm answers every line ``error:9`` and repeats its alarm on each
    reset; shown each time, the one thing the operator must read drowns.  An
    explanation is new when its code differs from the one shown; the one shown
    is done with when the board leaves its alarm (a status report not
    ``Alarm``) or, for an error, when a line is accepted again.
    """

    def __init__(self) -> None:
        self.shown: Explanation | None = None

    def reply(self, kind: str, code: int) -> Explanation | None:
        """An ``ALARM:n`` or ``error:n`` read: its explanation, None when it is already shown.

        While an alarm is shown, the errors it causes (error:9, locked out) add nothing.
        """
        shown = self.shown
        if shown is not None and shown.key == (kind, code):
            return None
        if shown is not None and shown.key[0] == "ALARM" and kind == "error" and code == 9:
            return None
        self.shown = explain(kind, code)
        return self.shown

    def accepted(self) -> bool:
        """A line was accepted (``ok``): an error shown is over. True when it was cleared."""
        if self.shown is not None and self.shown.key[0] == "error":
            self.shown = None
            return True
        return False

    def state(self, state: str) -> bool:
        """The board's state from a status report: out of alarm, the alarm shown is over."""
        if self.shown is not None and self.shown.key[0] == "ALARM" and state != "Alarm":
            self.shown = None
            return True
        return False
