"""Absolute panel: a target per axis and Go, the way the stage's own tool positions it.

Targets are judged against the axis travel from the profile as they are
typed: one outside it is framed red, named under the fields, and its Go is
disabled — never clamped or cut to another number the machine would then go
to.  The device still has the last word on its soft limits.
"""

from __future__ import annotations

from PySide6.QtWidgets import QGridLayout, QLabel, QPushButton, QWidget

from app.station import Station
from widgets.number_field import FieldGate, NumberField, distance_box
from widgets.retranslate import Texts, bold
from widgets.units import shown_unit


class AbsolutePanel(QWidget):
    """Target per axis in the axis unit, Go per axis and Go all."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self.targets: list[NumberField] = []
        self.note = QLabel()
        self.gate = FieldGate(self.note, self)
        self.go_buttons: list[QPushButton] = []
        t = self.texts = Texts(self)

        grid = QGridLayout(self)
        grid.setHorizontalSpacing(10)
        grid.setVerticalSpacing(8)
        grid.addWidget(t.label(lambda: bold(self.tr("Move to"))), 0, 0, 1, 3)
        for index, axis in enumerate(station.profile.axes):
            target = distance_box(
                f"target_{axis.name}",
                axis.unit,
                0.0,
                axis.travel,
                "",
            )
            t.set(
                target.set_description,
                lambda a=axis: self.tr("{0} target, 0…{1} {2} (Esc stops)").format(
                    a.name, f"{a.travel:g}", shown_unit(a.unit)
                ),
            )
            go = t.button(
                lambda a=axis: self.tr("Go {0}").format(a.name),
                lambda a=axis: self.tr("Move {0} to the target").format(a.name),
            )
            go.clicked.connect(lambda _=False, i=index: self.go(i))
            grid.addWidget(QLabel(axis.name), index + 1, 0)
            grid.addWidget(target, index + 1, 1)
            grid.addWidget(go, index + 1, 2)
            self.targets.append(target)
            self.go_buttons.append(go)
            self.gate.watch(target, lambda a=axis: self.tr("{0} target").format(a.name))
            self.gate.bind(go, target)
        self.go_all_button = t.button(
            lambda: self.tr("Go all"), lambda: self.tr("Move every axis to its target at once")
        )

        self.go_all_button.clicked.connect(self.go_all)
        self.gate.bind(self.go_all_button, *self.targets)
        grid.addWidget(self.go_all_button, len(self.targets) + 1, 2)
        grid.addWidget(self.note, len(self.targets) + 2, 0, 1, 4)
        grid.setColumnStretch(3, 1)
        grid.setRowStretch(len(self.targets) + 3, 1)

    def go(self, axis: int) -> bool:
        """Send axis ``axis`` to its target; False when refused (bad target, locked)."""
        target = self.targets[axis].value()
        if target is None:
            self.gate.refusal(self.targets[axis])
            return False
        session = self._station.session
        # The target is a work position, as the DRO shows and a G90 line means (GRBL's G92
        # offset added): the session takes machine positions.
        offset = self._station.model.axes[axis].offset
        return session is not None and session.move_absolute(axis, target + offset)

    def go_all(self) -> None:
        """Every axis or none: one bad target holds them all back."""
        if self.gate.refusal(*self.targets) is not None:
            return
        for axis in range(len(self.targets)):
            if not self.go(axis):
                break

    def set_motion_enabled(self, enabled: bool) -> None:
        self.gate.set_enabled(enabled)
