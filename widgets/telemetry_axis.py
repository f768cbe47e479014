"""The telemetry plots' axes: ticks no closer than a line of their text, numbers as the
language writes them.

pyqtgraph picks a tick count from the axis length alone (about its logarithm),
so a plot squeezed to 60 px at 1280x800 got five value labels drawn over each
other ("0.6" on "0.4"), and wrote them with a decimal point in Czech and
Slovak.  This axis widens the spacing until the labels stand a line apart and
writes them with the default locale's decimal separator.
"""

from __future__ import annotations

import math
from typing import Any

import pyqtgraph as pg
from PySide6.QtCore import QLocale
from PySide6.QtGui import QFontMetrics

#: Room between two labels, beyond the text's own height (pixels).
LABEL_GAP_PX = 4
#: The nice steps after which pyqtgraph's spacing is widened: 1, 2, 5 times 10^n.
_STEPS = (1.0, 2.0, 5.0, 10.0)


def wider_step(step: float) -> float:
    """The next 1-2-5 step above ``step``."""
    if step <= 0 or not math.isfinite(step):
        return step
    power = float(10 ** math.floor(math.log10(step)))
    mantissa = step / power
    for nice in _STEPS:
        if nice > mantissa * (1 + 1e-9):
            return nice * power
    return 20 * power


class LocaleAxis(pg.AxisItem):  # type: ignore[misc]
    """A pyqtgraph axis whose ticks keep a line apart and read in the language's form."""

    def min_label_px(self) -> float:
        """The least distance between two labels along this axis (pixels)."""
        metrics = QFontMetrics(self.style.get("tickFont") or self.font())
        if self.orientation in ("left", "right"):
            return metrics.height() + LABEL_GAP_PX
        return metrics.horizontalAdvance("-00.0") + 2 * LABEL_GAP_PX

    def tickSpacing(self, minVal: float, maxVal: float, size: float) -> Any:
        levels = super().tickSpacing(minVal, maxVal, size)
        if not levels or size <= 0 or maxVal <= minVal:
            return levels
        spacing, offset = levels[0]
        least = self.min_label_px()
        while spacing > 0 and spacing / (maxVal - minVal) * size < least:
            wider = wider_step(spacing)
            if wider <= spacing:
                break
            spacing = wider
        return [(spacing, offset), *[level for level in levels[1:] if level[0] < spacing]]

    def tickStrings(self, values: list[float], scale: float, spacing: float) -> list[str]:
        point = QLocale().decimalPoint()
        strings = super().tickStrings(values, scale, spacing)
        return [text.replace(".", point) if point != "." else text for text in strings]
