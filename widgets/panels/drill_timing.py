"""The drill's timing constants, edited in the station (FIDELITY S2-06).

The original tool let the teacher change the machine's timing constants, "so
one can show in practice what happens when these important parameters
change".  Here they are the step periods, the pauses of the drill's way down
and the waits of its stroke, and the length of its return
(:class:`~protocol.drill.timing.DrillTiming`).  Each field takes only what
:data:`~protocol.drill.timing.TIMING_BOUNDS` allows; Apply hands them to the
station (the estimate and the session's timeouts count with them at once, an
emulated drill runs them from its next procedure step) and the main window
keeps them; "Profile values" goes back to the profile's.  A real drill keeps
its own constants in its firmware: the station can only count with the ones
given here.
"""

from __future__ import annotations

import dataclasses
from typing import Any

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Signal
from PySide6.QtWidgets import QGridLayout, QGroupBox, QHBoxLayout, QLabel, QWidget

from app.station import Station
from protocol.drill.timing import INTEGER_CONSTANTS, TIMING_BOUNDS, DrillTiming
from widgets.number_field import FieldGate, NumberField
from widgets.retranslate import Texts
from widgets.style import compact

#: Each constant: its name, its caption, its unit, the factor from the constant's unit to
#: the field's (seconds are shown in ms), and the field's decimals.
FIELDS: tuple[tuple[str, object, object, float, int], ...] = (
    ("x_period_s", QT_TRANSLATE_NOOP("DrillTiming", "X step period"), "ms", 1000.0, 2),
    ("y_period_s", QT_TRANSLATE_NOOP("DrillTiming", "Y step period"), "ms", 1000.0, 2),
    ("z_period_s", QT_TRANSLATE_NOOP("DrillTiming", "Z step period"), "ms", 1000.0, 2),
    ("down_pause_s", QT_TRANSLATE_NOOP("DrillTiming", "Pause going down"), "ms", 1000.0, 1),
    (
        "down_pause_every",
        QT_TRANSLATE_NOOP("DrillTiming", "… after every"),
        "µsteps",
        1.0,
        0,
    ),
    ("bottom_wait_s", QT_TRANSLATE_NOOP("DrillTiming", "Wait at the bottom"), "ms", 1000.0, 0),
    ("after_wait_s", QT_TRANSLATE_NOOP("DrillTiming", "Wait after the return"), "ms", 1000.0, 0),
    (
        "return_full_steps",
        QT_TRANSLATE_NOOP("DrillTiming", "Return stroke"),
        QT_TRANSLATE_NOOP("DrillTiming", "full steps"),
        1.0,
        0,
    ),
)


def _tr(text: object) -> str:
    return QCoreApplication.translate("DrillTiming", str(text))


class DrillTimingBox(QGroupBox):
    """The timing constants, one field each, with Apply and "Profile values"."""

    #: The operator applied constants (a DrillTiming), or went back to the profile's (None).
    applied = Signal(object)

    def __init__(
        self, station: Station, profile_timing: DrillTiming, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("drill_timing")
        self._station = station
        self._profile_timing = profile_timing
        t = self.texts = Texts(self)
        t.set(self.setTitle, lambda: self.tr("Timing constants (teaching)"))
        self.fields: dict[str, NumberField] = {}
        self.note = QLabel()
        self.gate = FieldGate(self.note, self)
        grid = QGridLayout(self)
        for index, (name, caption, unit, factor, decimals) in enumerate(FIELDS):
            low, high = TIMING_BOUNDS[name]
            field = NumberField(
                low * factor,
                high * factor,
                decimals=decimals,
                unit=_tr(unit),
                name=f"timing_{name}",
            )
            t.set(field.set_description, lambda c=caption: _tr(c))
            row, column = divmod(index, 2)
            grid.addWidget(t.label(lambda c=caption: _tr(c)), row, 2 * column)
            grid.addWidget(field, row, 2 * column + 1)
            self.gate.watch(field, lambda c=caption: _tr(c))
            self.fields[name] = field
        self.apply_button = t.button(
            lambda: self.tr("Apply"),
            lambda: self.tr("Count with these constants: the estimate, the timeouts, the emulator"),
        )
        self.apply_button.setObjectName("timing_apply")
        self.apply_button.clicked.connect(self.apply)
        self.gate.bind(self.apply_button, *self.fields.values())
        self.profile_button = t.button(
            lambda: self.tr("Profile values"),
            lambda: self.tr("Back to the machine profile's constants"),
        )
        self.profile_button.setObjectName("timing_profile")
        self.profile_button.clicked.connect(self.use_profile_values)
        buttons = QHBoxLayout()
        buttons.addWidget(self.note, 1)
        buttons.addWidget(compact(self.apply_button))
        buttons.addWidget(compact(self.profile_button))
        grid.addLayout(buttons, (len(FIELDS) + 1) // 2, 0, 1, 4)
        self.show_timing(station.profile.drill_timing)

    def show_timing(self, timing: DrillTiming) -> None:
        """Fill the fields with ``timing``'s constants."""
        for name, _caption, _unit, factor, _decimals in FIELDS:
            self.fields[name].setValue(getattr(timing, name) * factor)

    def timing(self) -> DrillTiming | None:
        """The constants the fields spell, or None while one of them is not acceptable."""
        values: dict[str, Any] = {}
        for name, _caption, _unit, factor, _decimals in FIELDS:
            value = self.fields[name].value()
            if value is None:
                return None
            scaled = value / factor
            values[name] = round(scaled) if name in INTEGER_CONSTANTS else scaled
        try:
            return dataclasses.replace(self._profile_timing, **values)
        except ValueError:  # a rounding at a bound's edge: the field said yes, the range no
            return None

    def apply(self) -> None:
        timing = self.timing()
        if timing is None:
            self.gate.refusal(*self.fields.values())
            return
        self._station.set_drill_timing(timing)
        self.applied.emit(timing)

    def use_profile_values(self) -> None:
        self._station.set_drill_timing(self._profile_timing)
        self.show_timing(self._profile_timing)
        self.applied.emit(None)
