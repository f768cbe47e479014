"""Light and dark: the window's palette and the colours the plots draw with.

The choice is "system" (follow the desktop's colour scheme, Qt 6.5+
``QStyleHints.colorScheme``, and change when it changes), "light" or
"dark"; the window stores it through :mod:`app.settings`.  Qt widgets take
their colours from the application palette; pyqtgraph plots and hand-painted
widgets do not, so they get a :class:`PlotColours` from
:attr:`ThemeController.colours` whenever it changes.
"""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QObject, Qt, Signal
from PySide6.QtGui import QColor, QGuiApplication, QPalette
from PySide6.QtWidgets import QApplication, QWidget


@dataclass(frozen=True)
class PlotColours:
    """What a plot or painted widget draws that is not data."""

    dark: bool
    background: str
    axis: str
    text: str
    #: Legend boxes over the data: the background, mostly opaque.
    legend: QColor
    legend_border: str
    #: The rotation cross's face, its rim and its reference lines.
    face: str
    rim: str
    reference: str


LIGHT = PlotColours(
    dark=False,
    background="#ffffff",
    axis="#909090",
    text="#404040",
    legend=QColor(255, 255, 255, 210),
    legend_border="#d0d0d0",
    face="#fafafa",
    rim="#c8c8c8",
    reference="#b0b0b0",
)
DARK = PlotColours(
    dark=True,
    background="#1c1d20",
    axis="#7c7c80",
    text="#d4d4d8",
    legend=QColor(40, 41, 45, 220),
    legend_border="#505055",
    face="#26272b",
    rim="#55555a",
    reference="#6a6a70",
)


def system_is_dark() -> bool:
    """Whether the desktop asks for dark colours (Unknown counts as light)."""
    return QGuiApplication.styleHints().colorScheme() == Qt.ColorScheme.Dark


def dark_palette() -> QPalette:
    """A dark palette for every style: the platform's may have none."""
    palette = QPalette()
    roles = {
        QPalette.ColorRole.Window: "#2b2c30",
        QPalette.ColorRole.WindowText: "#e6e6e8",
        QPalette.ColorRole.Base: "#1f2023",
        QPalette.ColorRole.AlternateBase: "#2b2c30",
        QPalette.ColorRole.ToolTipBase: "#3a3b40",
        QPalette.ColorRole.ToolTipText: "#f0f0f0",
        QPalette.ColorRole.PlaceholderText: "#8a8a90",
        QPalette.ColorRole.Text: "#e6e6e8",
        QPalette.ColorRole.Button: "#35363b",
        QPalette.ColorRole.ButtonText: "#e6e6e8",
        QPalette.ColorRole.BrightText: "#ff6b6b",
        QPalette.ColorRole.Light: "#4a4b50",
        QPalette.ColorRole.Midlight: "#3f4045",
        QPalette.ColorRole.Mid: "#2f3034",
        QPalette.ColorRole.Dark: "#1a1b1e",
        QPalette.ColorRole.Shadow: "#000000",
        QPalette.ColorRole.Highlight: "#3d74d6",
        QPalette.ColorRole.HighlightedText: "#ffffff",
        QPalette.ColorRole.Link: "#7aa7ff",
        QPalette.ColorRole.LinkVisited: "#b39ddb",
    }
    for role, colour in roles.items():
        palette.setColor(role, QColor(colour))
    disabled = QPalette.ColorGroup.Disabled
    for role in (
        QPalette.ColorRole.WindowText,
        QPalette.ColorRole.Text,
        QPalette.ColorRole.ButtonText,
    ):
        palette.setColor(disabled, role, QColor("#77777c"))
    palette.setColor(disabled, QPalette.ColorRole.Button, QColor("#2f3034"))
    return palette


#: Widgets whose box or circle the dark palette drew as dark on dark: barely visible.
INDICATOR_CLASSES = ("QCheckBox", "QRadioButton")


def indicator_palette(palette: QPalette) -> QPalette:
    """``palette`` with a box fill that stands out from a dark window (Fusion fills with Base)."""
    lighter = QPalette(palette)
    lighter.setColor(QPalette.ColorRole.Base, QColor("#4a4c54"))
    lighter.setColor(QPalette.ColorRole.Window, QColor("#5a5c66"))  # Fusion's box outline
    lighter.setColor(QPalette.ColorGroup.Disabled, QPalette.ColorRole.Base, QColor("#393a40"))
    return lighter


def _is_dark(palette: QPalette) -> bool:
    return palette.color(QPalette.ColorRole.Window).lightness() < 128


def _repolish_style_sheets() -> None:
    """Polish again every shown window's widgets that carry a style sheet.

    A widget with a style sheet took its colours when it was polished, so its
    buttons would stay light in the dark.  Only live windows are walked (a widget
    waiting for deletion must not be touched), and only when light and dark swap.
    """
    for window in QApplication.topLevelWidgets():
        for widget in (window, *window.findChildren(QWidget)):
            sheet = widget.styleSheet()
            if sheet:
                widget.setStyleSheet("")
                widget.setStyleSheet(sheet)


class ThemeController(QObject):
    """Keeps the application palette and the plot colours on the operator's choice."""

    #: The plot colours changed (light ↔ dark).
    coloursChanged = Signal(object)

    def __init__(self, choice: str = "system", parent: QObject | None = None) -> None:
        super().__init__(parent)
        app = QApplication.instance()
        assert isinstance(app, QApplication)
        #: The palette the platform gave, restored when the choice matches it.
        self._platform = QApplication.palette()
        self._choice = choice
        self.colours = LIGHT
        QGuiApplication.styleHints().colorSchemeChanged.connect(self._scheme_changed)
        self._following = True
        self.apply()

    @property
    def choice(self) -> str:
        return self._choice

    def set_choice(self, choice: str) -> None:
        self._choice = choice
        self.apply()

    def wants_dark(self) -> bool:
        if self._choice == "dark":
            return True
        if self._choice == "light":
            return False
        return system_is_dark()

    def apply(self) -> None:
        dark = self.wants_dark()
        if dark == _is_dark(self._platform):
            palette = self._platform
        else:
            palette = dark_palette() if dark else QApplication.style().standardPalette()
        repolish = _is_dark(QApplication.palette()) != dark
        QApplication.setPalette(palette)
        boxes = indicator_palette(palette) if dark else palette
        for name in INDICATOR_CLASSES:
            QApplication.setPalette(boxes, name)  # type: ignore[arg-type]  # str at run time
        if repolish:
            _repolish_style_sheets()
        colours = DARK if dark else LIGHT
        changed = colours is not self.colours
        self.colours = colours
        if changed:
            self.coloursChanged.emit(colours)

    def _scheme_changed(self, _scheme: Qt.ColorScheme) -> None:
        if self._choice == "system":
            self.apply()

    def release(self) -> None:
        """Stop following the desktop (the window closes; the palette stays as it is)."""
        if self._following:
            self._following = False
            QGuiApplication.styleHints().colorSchemeChanged.disconnect(self._scheme_changed)
