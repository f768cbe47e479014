"""GRBL's error and alarm meanings in the operator's language.

The codec (:mod:`protocol.gcode.codec`) keeps GRBL 1.1's tables in English, free of
Qt; the operator reads them in the status bar, the console and the developer
pane, so they are said here through Qt's translations (unknown codes stay as the
codec words them).
"""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from protocol.gcode.codec import ALARM_MESSAGES, ERROR_MESSAGES

#: The codec's texts, marked for translation (the same English: lupdate reads these).
_MARKED = (
    QT_TRANSLATE_NOOP("GrblMeaning", "expected command letter: a G-code word needs a letter"),
    QT_TRANSLATE_NOOP("GrblMeaning", "bad number format: a word's value is missing or malformed"),
    QT_TRANSLATE_NOOP("GrblMeaning", "invalid statement: '$' system command not recognised"),
    QT_TRANSLATE_NOOP("GrblMeaning", "negative value where a positive one is expected"),
    QT_TRANSLATE_NOOP("GrblMeaning", "setting disabled: homing is not enabled"),
    QT_TRANSLATE_NOOP("GrblMeaning", "step pulse time must be at least 3 microseconds"),
    QT_TRANSLATE_NOOP("GrblMeaning", "EEPROM read failed, defaults restored"),
    QT_TRANSLATE_NOOP("GrblMeaning", "not idle: this '$' command needs the machine idle"),
    QT_TRANSLATE_NOOP("GrblMeaning", "G-code locked out during alarm or jog"),
    QT_TRANSLATE_NOOP("GrblMeaning", "soft limits need homing enabled"),
    QT_TRANSLATE_NOOP(
        "GrblMeaning", "line overflow: too many characters in the line, not executed"
    ),
    QT_TRANSLATE_NOOP("GrblMeaning", "setting would exceed the maximum step rate"),
    QT_TRANSLATE_NOOP("GrblMeaning", "safety door open"),
    QT_TRANSLATE_NOOP(
        "GrblMeaning", "line length exceeded: build info or startup line too long to store"
    ),
    QT_TRANSLATE_NOOP(
        "GrblMeaning", "travel exceeded: target beyond the machine's travel, ignored"
    ),
    QT_TRANSLATE_NOOP("GrblMeaning", "invalid jog command"),
    QT_TRANSLATE_NOOP("GrblMeaning", "laser mode requires PWM output"),
    QT_TRANSLATE_NOOP("GrblMeaning", "unsupported or invalid G-code command"),
    QT_TRANSLATE_NOOP(
        "GrblMeaning", "modal group violation: two commands of one modal group in a line"
    ),
    QT_TRANSLATE_NOOP("GrblMeaning", "undefined feed rate"),
    QT_TRANSLATE_NOOP("GrblMeaning", "command requires an integer value"),
    QT_TRANSLATE_NOOP("GrblMeaning", "more than one command in the line needs axis words"),
    QT_TRANSLATE_NOOP("GrblMeaning", "repeated word in the line"),
    QT_TRANSLATE_NOOP("GrblMeaning", "no axis words for a command that needs them"),
    QT_TRANSLATE_NOOP("GrblMeaning", "invalid line number"),
    QT_TRANSLATE_NOOP("GrblMeaning", "command is missing a required value word"),
    QT_TRANSLATE_NOOP("GrblMeaning", "G59.x work coordinate systems are not supported"),
    QT_TRANSLATE_NOOP("GrblMeaning", "G53 only with G0 and G1"),
    QT_TRANSLATE_NOOP("GrblMeaning", "axis words that no command uses"),
    QT_TRANSLATE_NOOP("GrblMeaning", "G2/G3 arcs need at least one in-plane axis word"),
    QT_TRANSLATE_NOOP("GrblMeaning", "motion target is invalid"),
    QT_TRANSLATE_NOOP("GrblMeaning", "arc radius is invalid"),
    QT_TRANSLATE_NOOP("GrblMeaning", "G2/G3 arcs need at least one in-plane offset word"),
    QT_TRANSLATE_NOOP("GrblMeaning", "unused value words in the line"),
    QT_TRANSLATE_NOOP("GrblMeaning", "dynamic tool length offset not on the tool length axis"),
    QT_TRANSLATE_NOOP("GrblMeaning", "tool number greater than supported"),
    QT_TRANSLATE_NOOP(
        "GrblMeaning", "hard limit triggered: position likely lost; reset, then home"
    ),
    QT_TRANSLATE_NOOP(
        "GrblMeaning", "soft limit: target beyond the travel; reset, then unlock or home"
    ),
    QT_TRANSLATE_NOOP("GrblMeaning", "reset while in motion: position likely lost, re-home"),
    QT_TRANSLATE_NOOP("GrblMeaning", "probe fail: probe not in the expected initial state"),
    QT_TRANSLATE_NOOP("GrblMeaning", "probe fail: no contact within the programmed travel"),
    QT_TRANSLATE_NOOP("GrblMeaning", "homing fail: the homing cycle was reset"),
    QT_TRANSLATE_NOOP("GrblMeaning", "homing fail: safety door opened while homing"),
    QT_TRANSLATE_NOOP("GrblMeaning", "homing fail: pull-off did not clear the limit switch"),
    QT_TRANSLATE_NOOP(
        "GrblMeaning", "homing fail: limit switch not found within the search distance"
    ),
    QT_TRANSLATE_NOOP(
        "GrblMeaning",
        "homing fail: the second switch of a dual axis did not trigger after the first",
    ),
)


def error_meaning(code: int) -> str:
    """What ``error:<code>`` means, translated."""
    text = ERROR_MESSAGES.get(code)
    if text is None:
        return QCoreApplication.translate("GrblMeaning", "unknown error {0}").format(code)
    return QCoreApplication.translate("GrblMeaning", text)


def alarm_meaning(code: int) -> str:
    """What ``ALARM:<code>`` means, translated."""
    text = ALARM_MESSAGES.get(code)
    if text is None:
        return QCoreApplication.translate("GrblMeaning", "unknown alarm {0}").format(code)
    return QCoreApplication.translate("GrblMeaning", text)
