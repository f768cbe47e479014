"""Fonts and looks shared by the panels, so every panel reads the same way."""

from __future__ import annotations

from PySide6.QtGui import QFont, QFontDatabase
from PySide6.QtWidgets import QPushButton, QStyle

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


def compact(button: QPushButton) -> QPushButton:
    """Let a button shrink to its caption instead of the style's wide default.

    Styles give every text button a minimum of about 80 px; a row of five short
    commands then outgrows a 1280 px screen beside the docks.
    """
    margin = button.style().pixelMetric(QStyle.PixelMetric.PM_ButtonMargin, None, button)
    width = button.fontMetrics().horizontalAdvance(button.text().replace("&", "")) + 2 * margin
    button.setMinimumWidth(width + 2)
    return button
