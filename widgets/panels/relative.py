"""Relative panel: an increment per axis and minus / plus buttons, for stepping by known amounts.

Each press is one relative move of the increment, so the operator can step
an axis by exact amounts without working out the absolute target.
"""

from __future__ import annotations

from PySide6.QtWidgets import QGridLayout, QLabel, QPushButton, QWidget

from app.station import Station
from widgets.number_field import FieldGate, NumberField, distance_box
from widgets.retranslate import Texts, bold
from widgets.style import MINUS


class RelativePanel(QWidget):
    """Increment per axis; minus moves back by it, + moves forward by it."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self.increments: list[NumberField] = []
        self.note = QLabel()
        self.gate = FieldGate(self.note, self)
        self.minus_buttons: list[QPushButton] = []
        self.plus_buttons: list[QPushButton] = []
        t = self.texts = Texts(self)

        grid = QGridLayout(self)
        grid.setHorizontalSpacing(10)
        grid.setVerticalSpacing(8)
        grid.addWidget(t.label(lambda: bold(self.tr("Move by"))), 0, 0, 1, 4)
        for index, axis in enumerate(station.profile.axes):
            increment = distance_box(
                f"increment_{axis.name}",
                axis.unit,
                0.001,
                axis.travel,
                "",
            )
            t.set(
                increment.set_description,
                lambda a=axis: self.tr("{0} increment (Esc stops)").format(a.name),
            )
            increment.setValue(1.0)
            minus = QPushButton(f"{MINUS} {axis.name}")
            t.set(
                minus.setToolTip,
                lambda a=axis: self.tr("Move {0} back by the increment").format(a.name),
            )
            minus.clicked.connect(lambda _=False, i=index: self.step(i, -1))
            plus = QPushButton(f"+ {axis.name}")
            t.set(
                plus.setToolTip,
                lambda a=axis: self.tr("Move {0} forward by the increment").format(a.name),
            )
            plus.clicked.connect(lambda _=False, i=index: self.step(i, +1))
            grid.addWidget(QLabel(axis.name), index + 1, 0)
            grid.addWidget(minus, index + 1, 1)
            grid.addWidget(increment, index + 1, 2)
            grid.addWidget(plus, index + 1, 3)
            self.increments.append(increment)
            self.minus_buttons.append(minus)
            self.plus_buttons.append(plus)
            self.gate.watch(increment, lambda a=axis: self.tr("{0} increment").format(a.name))

            self.gate.bind(minus, increment)
            self.gate.bind(plus, increment)
        grid.addWidget(self.note, len(self.increments) + 1, 0, 1, 5)
        grid.setColumnStretch(4, 1)
        grid.setRowStretch(len(self.increments) + 2, 1)

    def step(self, axis: int, sign: int) -> bool:
        """Move ``axis`` by ``sign`` times its increment; False when refused."""
        increment = self.increments[axis].value()
        if increment is None:
            self.gate.refusal(self.increments[axis])
            return False
        session = self._station.session
        return session is not None and session.move_relative(axis, sign * increment)

    def set_motion_enabled(self, enabled: bool) -> None:
        self.gate.set_enabled(enabled)
