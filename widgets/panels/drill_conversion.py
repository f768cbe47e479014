"""The drill's conversion constants, edited for teaching (FIDELITY S2-42).

The original tool let the teacher change "Krok excelon" (1/10000 inch a count)
and "Mikrokroky X 19,8 / Y 19,7 na mm", "to show what happens when these
important parameters change".  Here: the Excellon step as 1/N inch and the
microsteps a millimetre of X and Y, each within its bounds
(:mod:`app.machines.drill.conversion`), a standing warning that the drill then
goes where these send it and not where the file means, Apply, and "Profile
values" to go back.  The station refuses a change while a job is under way;
a loaded job is read again with the new constants (its preview, its travel
check and its microstep targets follow).  The machine profile's values stay
the machine's truth: the travel and the position shown count with them.
Kept per machine profile when the window remembers settings
(:meth:`remember_in`).
"""

from __future__ import annotations

import dataclasses

from PySide6.QtWidgets import QGridLayout, QGroupBox, QHBoxLayout, QLabel, QWidget

from app.machines.drill.conversion import (
    EXCELLON_STEP_BOUNDS,
    MICROSTEPS_PER_MM_BOUNDS,
    DrillConversion,
)
from app.settings import MachineSettings
from app.station import Station
from widgets.number_field import FieldGate, NumberField
from widgets.retranslate import Texts
from widgets.style import compact


class DrillConversionBox(QGroupBox):
    """Excellon step and microsteps a mm, with a warning, Apply and "Profile values"."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("drill_conversion")
        self._station = station
        self._settings: MachineSettings | None = None
        self._axes = tuple(axis.name for axis in station.profile.axes)
        self._profile = DrillConversion.of_profile(station.profile.axes)
        t = self.texts = Texts(self)
        t.set(self.setTitle, lambda: self.tr("Conversion constants (teaching)"))
        self.note = QLabel()
        self.note.setObjectName("conversion_note")
        self.note.setWordWrap(True)
        self.gate = FieldGate(self.note, self)
        low, high = EXCELLON_STEP_BOUNDS
        self.step_field = NumberField(
            round(1 / high), round(1 / low), decimals=0, unit="", name="conversion_step"
        )
        t.set(self.step_field.set_description, lambda: self.tr("Excellon step, 1/… inch"))
        self.gate.watch(self.step_field, lambda: self.tr("Excellon step"))
        self.per_mm_fields: list[NumberField] = []
        grid = QGridLayout(self)
        grid.addWidget(t.label(lambda: self.tr("Excellon step 1/… inch")), 0, 0)
        grid.addWidget(self.step_field, 0, 1)
        low, high = MICROSTEPS_PER_MM_BOUNDS
        for index, name in enumerate(self._axes):
            field = NumberField(
                low, high, decimals=3, unit="µsteps/mm", name=f"conversion_per_mm_{name}"
            )
            t.set(field.set_description, lambda a=name: self.tr("{0} microsteps a mm").format(a))
            self.gate.watch(field, lambda a=name: self.tr("{0} microsteps a mm").format(a))
            row, column = divmod(index + 1, 2)
            grid.addWidget(
                t.label(lambda a=name: self.tr("{0} microsteps a mm").format(a)), row, 2 * column
            )
            grid.addWidget(field, row, 2 * column + 1)
            self.per_mm_fields.append(field)
        self.warning = QLabel()
        self.warning.setObjectName("conversion_warning")
        self.warning.setWordWrap(True)
        self.warning.setStyleSheet("QLabel { background: #fff3cd; color: #1d1d1d; padding: 3px; }")
        t.set(
            self.warning.setText,
            lambda: self.tr(
                "Teaching only: with other values than the profile's the drill goes where these "
                "send it, not where the file means (the travel is still checked)."
            ),
        )
        rows = (len(self._axes) + 2) // 2
        grid.addWidget(self.warning, rows, 0, 1, 4)
        self.apply_button = t.button(
            lambda: self.tr("Apply"),
            lambda: self.tr("Read the loaded job again with these constants"),
        )
        self.apply_button.setObjectName("conversion_apply")
        self.apply_button.clicked.connect(self.apply)
        self.gate.bind(self.apply_button, self.step_field, *self.per_mm_fields)
        self.profile_button = t.button(
            lambda: self.tr("Profile values"),
            lambda: self.tr("Back to the machine profile's constants"),
        )
        self.profile_button.setObjectName("conversion_profile")
        self.profile_button.clicked.connect(self.use_profile_values)
        buttons = QHBoxLayout()
        buttons.addWidget(self.note, 1)
        buttons.addWidget(compact(self.apply_button))
        buttons.addWidget(compact(self.profile_button))
        grid.addLayout(buttons, rows + 1, 0, 1, 4)
        self.show_conversion(station.drill_conversion)

    def remember_in(self, settings: MachineSettings | None) -> None:
        """Take the constants ``settings`` kept for this machine, and keep each change there."""
        self._settings = settings
        if settings is None:
            return
        kept = settings.drill_conversion(self._profile, self._axes)
        if kept != self._station.drill_conversion and self._station.set_drill_conversion(kept):
            self.show_conversion(kept)

    def show_conversion(self, conversion: DrillConversion) -> None:
        self.step_field.setValue(round(1 / conversion.excellon_step_inch))
        for field, value in zip(self.per_mm_fields, conversion.microsteps_per_mm, strict=False):
            field.setValue(value)

    def conversion(self) -> DrillConversion | None:
        """The constants the fields spell, or None while one of them is not acceptable."""
        denominator = self.step_field.value()
        per_mm = [field.value() for field in self.per_mm_fields]
        if denominator is None or not denominator > 0 or any(v is None for v in per_mm):
            return None
        try:
            return dataclasses.replace(
                self._profile,
                excellon_step_inch=1 / denominator,
                microsteps_per_mm=tuple(float(v) for v in per_mm if v is not None),
            )
        except ValueError:
            return None

    def apply(self) -> bool:
        conversion = self.conversion()
        if conversion is None:
            self.gate.refusal(self.step_field, *self.per_mm_fields)
            return False
        return self._set(conversion)

    def use_profile_values(self) -> bool:
        if not self._set(self._profile):
            return False
        self.show_conversion(self._profile)
        return True

    def _set(self, conversion: DrillConversion) -> bool:
        busy = self._station.model.jog_lock_reason
        if not self._station.set_drill_conversion(conversion):
            self.note.setText(self.tr("Not changed: {0}").format(busy or "—"))
            return False
        self.note.setText("")
        if self._settings is not None:
            self._settings.set_drill_conversion(
                None if conversion.is_profiles else conversion, self._axes
            )
            self._settings.settings.sync()
        return True
