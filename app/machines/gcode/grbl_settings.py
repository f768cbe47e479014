"""GRBL 1.1's ``$N`` settings: what each is, its unit and the range the station lets through.

From GRBL 1.1h's own documentation and source (``settings.md``, the
``setting_codes`` table, ``settings_store_global_setting``), said in the
project's words.  GRBL's own rules come first: the whole-number settings
are kept in one byte (0…255; ``$0`` at least 3 µs), masks hold one bit per
axis (``00000ZYX``), nothing may be negative, and it prints its decimal
settings with three decimals, so more are never kept.  GRBL takes any
positive float for a rate or a resolution; the station narrows those to
what a machine can have, and refuses what it knows would break this one:

- ``$13=1`` (positions in inches): the station reads millimetres.
- ``$20=1`` without ``$22=1``: GRBL itself refuses it (``error:10``).
- ``$31`` at or above ``$30``: GRBL divides by their difference for the PWM.
- ``$13x`` beyond the profile's mechanical travel: soft limits would let the
  machine drive into its frame believing it had room.
- ``$10x`` times ``$11x``: more than 30 000 steps a second, which GRBL cannot
  step (its documentation's figure for a 16 MHz board).

GRBL 1.1h compiled for three axes lists ``$100…$102`` and so on whatever
the machine has; all three are in the table.
"""

from __future__ import annotations

from collections.abc import Mapping

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.local_numbers import local_number
from app.machines.stored_settings import Kind, StoredSetting
from app.profiles import MachineProfile

CONTEXT = "GrblSetting"
#: GRBL 1.1h on a 328p: N_AXIS.
GRBL_AXES = ("X", "Y", "Z")
#: The most steps a second GRBL 1.1 generates on a 16 MHz board (its documentation).
MAX_STEP_RATE_HZ = 30_000
#: GRBL's uint8 settings keep one byte.
BYTE = 255
#: The station's ceiling for a rate, a resolution or a distance.  GRBL prints a setting
#: through a 32-bit integer of thousandths (4 294 967.295 at most): far below that.
LARGE = 100_000.0

_AXIS_BITS = (
    QT_TRANSLATE_NOOP("GrblSetting", "X"),
    QT_TRANSLATE_NOOP("GrblSetting", "Y"),
    QT_TRANSLATE_NOOP("GrblSetting", "Z"),
)
_STATUS_BITS = (
    QT_TRANSLATE_NOOP("GrblSetting", "machine position (off: work position)"),
    QT_TRANSLATE_NOOP("GrblSetting", "buffer state (Bf:)"),
)
_INCHES = QT_TRANSLATE_NOOP("GrblSetting", "the station reads positions in millimetres")


WHOLE, D, S, M = Kind.INTEGER, Kind.DECIMAL, Kind.SWITCH, Kind.MASK

# fmt: off
# number, kind, low, high, unit, label, description
_GLOBAL: tuple[tuple[int, Kind, float, float, str, object, object], ...] = (
    (0, WHOLE, 3, BYTE, "µs", QT_TRANSLATE_NOOP("GrblSetting", "Step pulse time"), QT_TRANSLATE_NOOP("GrblSetting", "How long each step pulse lasts. The stepper drivers name the least they need; GRBL takes no less than 3 µs.")),  # noqa: E501
    (1, WHOLE, 0, BYTE, "ms", QT_TRANSLATE_NOOP("GrblSetting", "Step idle delay"), QT_TRANSLATE_NOOP("GrblSetting", "How long the motors stay powered after a motion ends, so the axes settle before they are let go. 255 keeps them powered.")),  # noqa: E501
    (2, M, 0, 7, "", QT_TRANSLATE_NOOP("GrblSetting", "Step pulse invert"), QT_TRANSLATE_NOOP("GrblSetting", "Axes whose step signal is inverted, one bit each (X 1, Y 2, Z 4), for drivers that step on the other edge.")),  # noqa: E501
    (3, M, 0, 7, "", QT_TRANSLATE_NOOP("GrblSetting", "Direction invert"), QT_TRANSLATE_NOOP("GrblSetting", "Axes that move the other way, one bit each (X 1, Y 2, Z 4): the fix for an axis wired backwards.")),  # noqa: E501
    (4, S, 0, 1, "", QT_TRANSLATE_NOOP("GrblSetting", "Invert step enable"), QT_TRANSLATE_NOOP("GrblSetting", "Inverts the drivers' enable signal (takes effect after a reset).")),  # noqa: E501
    (5, S, 0, 1, "", QT_TRANSLATE_NOOP("GrblSetting", "Invert limit pins"), QT_TRANSLATE_NOOP("GrblSetting", "Inverts every limit switch input: for switches that are closed until hit.")),  # noqa: E501
    (6, S, 0, 1, "", QT_TRANSLATE_NOOP("GrblSetting", "Invert probe pin"), QT_TRANSLATE_NOOP("GrblSetting", "Inverts the probe input.")),  # noqa: E501
    (10, M, 0, 3, "", QT_TRANSLATE_NOOP("GrblSetting", "Status report options"), QT_TRANSLATE_NOOP("GrblSetting", "What a status report carries: value 1 the machine position (else the work position), value 2 the free buffer space.")),  # noqa: E501
    (11, D, 0, 10, "mm", QT_TRANSLATE_NOOP("GrblSetting", "Junction deviation"), QT_TRANSLATE_NOOP("GrblSetting", "How fast the machine may go through a corner between two moves: smaller is slower and gentler.")),  # noqa: E501
    (12, D, 0.001, 10, "mm", QT_TRANSLATE_NOOP("GrblSetting", "Arc tolerance"), QT_TRANSLATE_NOOP("GrblSetting", "How far the short lines GRBL draws an arc with may stray from the arc. Very small values cost speed.")),  # noqa: E501
    (13, S, 0, 0, "", QT_TRANSLATE_NOOP("GrblSetting", "Report in inches"), QT_TRANSLATE_NOOP("GrblSetting", "Positions and rates reported in inches instead of millimetres.")),  # noqa: E501
    (20, S, 0, 1, "", QT_TRANSLATE_NOOP("GrblSetting", "Soft limits"), QT_TRANSLATE_NOOP("GrblSetting", "Refuses, with an alarm, any motion past the maximum travel ($130…). Needs homing ($22=1).")),  # noqa: E501
    (21, S, 0, 1, "", QT_TRANSLATE_NOOP("GrblSetting", "Hard limits"), QT_TRANSLATE_NOOP("GrblSetting", "Stops at once with an alarm when a limit switch is hit.")),  # noqa: E501
    (22, S, 0, 1, "", QT_TRANSLATE_NOOP("GrblSetting", "Homing cycle"), QT_TRANSLATE_NOOP("GrblSetting", "Enables homing ($H). Needs a limit switch on every axis; the board then starts in alarm until homed.")),  # noqa: E501
    (23, M, 0, 7, "", QT_TRANSLATE_NOOP("GrblSetting", "Homing direction invert"), QT_TRANSLATE_NOOP("GrblSetting", "Axes that look for their switch in the negative direction, one bit each (X 1, Y 2, Z 4).")),  # noqa: E501
    (24, D, 0.001, LARGE, "mm/min", QT_TRANSLATE_NOOP("GrblSetting", "Homing locate feed rate"), QT_TRANSLATE_NOOP("GrblSetting", "The slow speed at which homing finds the switch's exact place.")),  # noqa: E501
    (25, D, 0.001, LARGE, "mm/min", QT_TRANSLATE_NOOP("GrblSetting", "Homing search seek rate"), QT_TRANSLATE_NOOP("GrblSetting", "The fast speed at which homing first looks for the switch.")),  # noqa: E501
    (26, WHOLE, 0, BYTE, "ms", QT_TRANSLATE_NOOP("GrblSetting", "Homing switch debounce"), QT_TRANSLATE_NOOP("GrblSetting", "A pause between the phases of homing while the switch stops bouncing.")),  # noqa: E501
    (27, D, 0, 1000, "mm", QT_TRANSLATE_NOOP("GrblSetting", "Homing pull-off"), QT_TRANSLATE_NOOP("GrblSetting", "How far homing backs off its switch. Homing fails if the switch is still pressed after it.")),  # noqa: E501
    (30, WHOLE, 1, LARGE, "RPM", QT_TRANSLATE_NOOP("GrblSetting", "Maximum spindle speed"), QT_TRANSLATE_NOOP("GrblSetting", "The S value that gives full PWM duty (on a servo pen plotter: the pen's full travel).")),  # noqa: E501
    (31, WHOLE, 0, LARGE, "RPM", QT_TRANSLATE_NOOP("GrblSetting", "Minimum spindle speed"), QT_TRANSLATE_NOOP("GrblSetting", "The S value that gives the least PWM duty; below $30.")),  # noqa: E501
    (32, S, 0, 1, "", QT_TRANSLATE_NOOP("GrblSetting", "Laser mode"), QT_TRANSLATE_NOOP("GrblSetting", "Moves go on through changes of S without stopping, as a laser needs; a spindle would need time to change speed.")),  # noqa: E501
)
# first number, low, high, unit, label ({0}: the axis), description
_PER_AXIS: tuple[tuple[int, float, float, str, object, object], ...] = (
    (100, 0.001, LARGE, "step/mm", QT_TRANSLATE_NOOP("GrblSetting", "{0} resolution"), QT_TRANSLATE_NOOP("GrblSetting", "Steps the axis's motor makes for one millimetre of travel.")),  # noqa: E501
    (110, 0.001, LARGE, "mm/min", QT_TRANSLATE_NOOP("GrblSetting", "{0} maximum rate"), QT_TRANSLATE_NOOP("GrblSetting", "The axis's top speed; rapid moves (G0) run at it.")),  # noqa: E501
    (120, 0.001, LARGE, "mm/s²", QT_TRANSLATE_NOOP("GrblSetting", "{0} acceleration"), QT_TRANSLATE_NOOP("GrblSetting", "How fast the axis may speed up and slow down, planned so that the motor loses no steps.")),  # noqa: E501
    (130, 0, LARGE, "mm", QT_TRANSLATE_NOOP("GrblSetting", "{0} maximum travel"), QT_TRANSLATE_NOOP("GrblSetting", "How far the axis can travel from its home switch: the space soft limits keep to, and how far homing searches.")),  # noqa: E501
)
# fmt: on
_BITS = {2: _AXIS_BITS, 3: _AXIS_BITS, 23: _AXIS_BITS, 10: _STATUS_BITS}


def _rows() -> tuple[StoredSetting, ...]:
    rows = [
        StoredSetting(
            key=f"${number}",
            label=str(label),
            unit=unit,
            description=str(description),
            kind=kind,
            low=low,
            high=high,
            decimals=3 if kind is Kind.DECIMAL else 0,
            bits=tuple(str(bit) for bit in _BITS.get(number, ())),
            narrowed=str(_INCHES) if number == 13 else "",
            context=CONTEXT,
            single_precision=True,
        )
        for number, kind, low, high, unit, label, description in _GLOBAL
    ]
    for first, low, high, unit, label, description in _PER_AXIS:
        rows += [
            StoredSetting(
                key=f"${first + index}",
                label=str(label),
                unit=unit,
                description=str(description),
                kind=Kind.DECIMAL,
                low=low,
                high=high,
                decimals=3,
                context=CONTEXT,
                single_precision=True,
                axis=axis,
            )
            for index, axis in enumerate(GRBL_AXES)
        ]
    return tuple(rows)


#: Every setting GRBL 1.1h lists in ``$$``, in its order.
GRBL_SETTINGS: tuple[StoredSetting, ...] = _rows()
BY_KEY: dict[str, StoredSetting] = {s.key: s for s in GRBL_SETTINGS}


def number_of(setting: StoredSetting) -> int:
    return int(setting.key[1:])


def parse_setting_line(text: str) -> tuple[str, float] | None:
    """``$110=500.000`` → (``"$110"``, 500.0); None for any other line."""
    key, sep, value = text.strip().partition("=")
    if not sep or not key.startswith("$") or not key[1:].isdigit():
        return None
    try:
        number = float(value)
    except ValueError:
        return None
    return key, number


def cross_check(
    changes: Mapping[str, float], held: Mapping[str, float], profile: MachineProfile
) -> list[str]:
    """Why the changes, with what the board holds, would be wrong together (each reason)."""
    after = {**held, **changes}
    reasons: list[str] = []

    touched = set(changes)
    if {"$20", "$22"} & touched and after.get("$20") == 1 and after.get("$22") != 1:
        reasons.append(
            QCoreApplication.translate("GrblSetting", "$20 (soft limits) needs homing: $22=1")
        )
    if {"$30", "$31"} & touched and "$30" in after and "$31" in after:
        if after["$31"] >= after["$30"]:
            reasons.append(
                QCoreApplication.translate(
                    "GrblSetting", "$31 (minimum spindle speed) must be below $30"
                )
            )
    for index, axis in enumerate(profile.axes[: len(GRBL_AXES)]):
        travel_key, steps_key, rate_key = f"${130 + index}", f"${100 + index}", f"${110 + index}"
        if travel_key in touched and after[travel_key] > axis.travel:
            reasons.append(
                QCoreApplication.translate(
                    "GrblSetting", "{0}: at most the mechanical travel, {1} mm"
                ).format(travel_key, local_number(axis.travel))
            )
        if {steps_key, rate_key} & touched and steps_key in after and rate_key in after:
            rate_hz = after[steps_key] * after[rate_key] / 60
            if rate_hz > MAX_STEP_RATE_HZ:
                reasons.append(
                    QCoreApplication.translate(
                        "GrblSetting", "{0} and {1}: {2} steps/s, more than GRBL steps ({3})"
                    ).format(
                        steps_key,
                        rate_key,
                        local_number(round(rate_hz)),
                        local_number(MAX_STEP_RATE_HZ),
                    )
                )
    return reasons
