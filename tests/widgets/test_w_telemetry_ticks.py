"""The telemetry plots' value labels: a line apart on a squeezed plot, in the language's form.

At 1280x800 with every dock open a plot is some 60 px high; pyqtgraph put five
labels on it and drew "0.6" over "0.4", and wrote them with a decimal point
in Czech and Slovak (issue 32).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtGui import QFontMetrics
from pytestqt.qtbot import QtBot

from app import i18n
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.telemetry_axis import LocaleAxis, wider_step


@pytest.fixture(autouse=True)
def english_after(qapp: object, i18n_cache: Path) -> Iterator[None]:
    """The language this test installs does not follow the tests that come after it."""
    yield
    i18n.install("en", i18n_cache)


def test_the_steps_widen_one_two_five() -> None:
    assert [wider_step(s) for s in (0.1, 0.2, 0.5, 1.0, 2.5, 5.0)] == pytest.approx(
        [0.2, 0.5, 1.0, 2.0, 5.0, 10.0]
    )


@pytest.mark.parametrize(("language", "point"), [("en", "."), ("cs", ","), ("sk", ",")])
@pytest.mark.parametrize("height", [40, 60, 90, 200])
def test_value_labels_stand_a_line_apart_and_use_the_languages_point(
    qtbot: QtBot, i18n_cache: Path, language: str, point: str, height: int
) -> None:
    i18n.install(language, i18n_cache)
    harness = StationHarness(load_profile("string-art"))
    try:
        window = MainWindow(harness.station)
        qtbot.addWidget(window)
        window.show()
        window.telemetry_action.trigger()
        plot = window.telemetry_dock.variable_plot
        axis = plot.getAxis("left")
        assert isinstance(axis, LocaleAxis)
        line = QFontMetrics(axis.style.get("tickFont") or axis.font()).height()
        (spacing, values), *_ = axis.tickValues(0.0, 0.8, height)
        assert len(values) >= 2 or height < 2 * line  # still labelled where two fit
        pixels = spacing / 0.8 * height
        assert pixels >= line, (height, spacing, values)  # no label on another
        labels = axis.tickStrings(values, 1.0, spacing)
        fractional = [label for label in labels if "." in label or "," in label]
        assert fractional, labels
        assert all(point in label for label in fractional), labels
    finally:
        harness.close()
