"""Fonts and looks shared by the panels, so every panel reads the same way."""

from __future__ import annotations

from PySide6.QtGui import QFont, QFontDatabase
from PySide6.QtWidgets import QDoubleSpinBox

#: The typographic minus (U+2212) for button labels: wider and clearer than a hyphen.
MINUS = "\u2212"

#: Checked page and speed buttons must read as "selected" at a glance; set per button
#: so the rest of the window keeps the platform style.
CHECKED_BUTTON_STYLE = (
    "QPushButton:checked { background: #2f6fd0; color: white;"
    " border: 1px solid #24559f; border-radius: 3px; padding: 4px; }"
)


def monospace_font(point_delta: int = 0, *, bold: bool = False) -> QFont:
    """Fixed-width digits, so a changing number does not make the layout jitter."""
    font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
    if point_delta and font.pointSize() > 0:
        font.setPointSize(font.pointSize() + point_delta)
    font.setBold(bold)
    return font


def distance_box(name: str, unit: str, low: float, high: float, tooltip: str) -> QDoubleSpinBox:
    """A millimetre field as every motion panel shows it: three decimals, fixed-width digits."""
    box = QDoubleSpinBox()
    box.setObjectName(name)
    box.setRange(low, high)
    box.setDecimals(3)
    box.setSingleStep(1.0)
    box.setSuffix(f" {unit}")
    box.setFont(monospace_font())
    box.setMinimumWidth(130)
    box.setToolTip(tooltip)
    return box
