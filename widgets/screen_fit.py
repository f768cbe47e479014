"""A window put back where it was, but wholly on the screen it opens on.

Saved geometry is restored as saved: a window closed at (1, 25) with 800 px of
height reopened with its status bar below the edge of an 800 px screen, since
the title bar and the panel above it take their share too.  So the restored
rectangle is moved, and shrunk only where it cannot fit, into the screen's
available area less the frame the window manager draws around it.
"""

from __future__ import annotations

from PySide6.QtCore import QMargins, QRect


def fitted(rect: QRect, frame: QMargins, available: QRect) -> QRect:
    """``rect`` (the client area) moved, then shrunk if need be, so that it and ``frame``
    around it lie inside ``available``."""
    inner = available.marginsRemoved(frame)
    width = max(1, min(rect.width(), inner.width()))
    height = max(1, min(rect.height(), inner.height()))
    x = min(max(rect.x(), inner.x()), inner.x() + inner.width() - width)
    y = min(max(rect.y(), inner.y()), inner.y() + inner.height() - height)
    return QRect(x, y, width, height)
