"""The font families the window must fit under, set for the whole application.

The layout was once checked only with the fonts of the machine it was written
on; on a machine with Debian's DejaVu fonts the window outgrew 1280 x 800.
These are the families common desktops use; ``.ci/run`` installs them
(Debian: fonts-dejavu-core, fonts-noto-core, fonts-liberation2).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import pytest
from PySide6.QtGui import QFont, QFontDatabase, QFontInfo
from PySide6.QtWidgets import QApplication

FAMILIES = ("DejaVu Sans", "Noto Sans", "Liberation Sans")
PACKAGES = "fonts-dejavu-core fonts-noto-core fonts-liberation2"


@contextmanager
def application_font(family: str) -> Iterator[QFont]:
    """The application's font in ``family`` (its size kept) while the block runs.

    Fails, saying what to install, when the family is missing: a fallback font
    would make the test pass or fail for another font than the one it names.
    """
    app = QApplication.instance()
    assert isinstance(app, QApplication)
    if not QFontDatabase.hasFamily(family):
        pytest.fail(
            f"font family {family!r} is not installed (Debian: apt-get install {PACKAGES}; "
            ".ci/run does it)",
            pytrace=False,
        )
    before = QFont(app.font())
    font = QFont(before)
    font.setFamily(family)
    app.setFont(font)
    resolved = QFontInfo(app.font()).family()
    try:
        assert resolved == family, f"asked for {family!r}, Qt uses {resolved!r}"
        yield font
    finally:
        app.setFont(before)
