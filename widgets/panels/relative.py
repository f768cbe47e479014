"""Relative panel: an increment per axis and minus / plus buttons, for stepping by known amounts.

Each press is one relative move of the increment, so the operator can step
an axis by exact amounts without working out the absolute target.
"""

from __future__ import annotations

from PySide6.QtWidgets import QDoubleSpinBox, QGridLayout, QLabel, QPushButton, QWidget

from app.station import Station
from widgets.style import MINUS, distance_box


class RelativePanel(QWidget):
    """Increment per axis; minus moves back by it, + moves forward by it."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self.increments: list[QDoubleSpinBox] = []
        self.minus_buttons: list[QPushButton] = []
        self.plus_buttons: list[QPushButton] = []

        grid = QGridLayout(self)
        grid.setHorizontalSpacing(10)
        grid.setVerticalSpacing(8)
        grid.addWidget(QLabel("<b>Move by</b>"), 0, 0, 1, 4)
        for index, axis in enumerate(station.profile.axes):
            increment = distance_box(
                f"increment_{axis.name}",
                axis.unit,
                0.001,
                axis.travel,
                f"{axis.name} increment (Esc stops)",
            )
            increment.setValue(1.0)
            minus = QPushButton(f"{MINUS} {axis.name}")
            minus.setToolTip(f"Move {axis.name} back by the increment")
            minus.clicked.connect(lambda _=False, i=index: self.step(i, -1))
            plus = QPushButton(f"+ {axis.name}")
            plus.setToolTip(f"Move {axis.name} forward by the increment")
            plus.clicked.connect(lambda _=False, i=index: self.step(i, +1))
            grid.addWidget(QLabel(axis.name), index + 1, 0)
            grid.addWidget(minus, index + 1, 1)
            grid.addWidget(increment, index + 1, 2)
            grid.addWidget(plus, index + 1, 3)
            self.increments.append(increment)
            self.minus_buttons.append(minus)
            self.plus_buttons.append(plus)
        grid.setColumnStretch(4, 1)
        grid.setRowStretch(len(self.increments) + 1, 1)

    def step(self, axis: int, sign: int) -> bool:
        """Move ``axis`` by ``sign`` times its increment; False when the session refused."""
        session = self._station.session
        delta = sign * self.increments[axis].value()
        return session is not None and session.move_relative(axis, delta)

    def set_motion_enabled(self, enabled: bool) -> None:
        for button in (*self.minus_buttons, *self.plus_buttons):
            button.setEnabled(enabled)
