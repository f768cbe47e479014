"""Number fields keep what the operator typed and show a value outside the range invalid.

Issue 15, symptom 7: typing 80 into a 0…50 mm spin box left 8, and Go moved
there.  The property: whatever number is typed, key by key, the field shows
exactly that text, and its value is that number when it is in range (and
not more precise than the field), otherwise None — never another number.
The same holds for every number field of every machine's window.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.profiles import available_profiles, load_profile
from app.station import Station
from widgets.main_window import MainWindow
from widgets.number_field import NumberField


def type_over(qtbot: QtBot, field: NumberField, text: str) -> None:
    field.setFocus()
    field.selectAll()
    qtbot.keyClick(field, Qt.Key.Key_Delete)
    qtbot.keyClicks(field, text)


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(
    low=st.integers(-1000, 1000),
    span=st.integers(1, 2000),
    decimals=st.integers(0, 3),
    whole=st.integers(-5000, 5000),
    fraction=st.text("0123456789", max_size=5),
)
def test_what_is_typed_is_kept_and_judged_never_replaced(
    qtbot: QtBot, low: int, span: int, decimals: int, whole: int, fraction: str
) -> None:
    field = NumberField(low, low + span, decimals=decimals, unit="mm")
    qtbot.addWidget(field)
    typed = f"{whole}.{fraction}" if fraction else str(whole)
    type_over(qtbot, field, typed)
    assert field.text() == typed
    number = float(typed)
    precise_enough = len(fraction.rstrip("0")) <= decimals
    if low <= number <= low + span and precise_enough:
        assert field.value() == number and field.is_acceptable()
        assert field.styleSheet() == ""
    else:
        assert field.value() is None and not field.is_acceptable()
        assert "#d03030" in field.styleSheet()
        assert field.problem() is not None and field.problem() in field.toolTip()


def test_letters_never_enter_and_steps_stay_in_range(qtbot: QtBot) -> None:
    field = NumberField(0, 50, decimals=3, unit="mm")
    qtbot.addWidget(field)
    type_over(qtbot, field, "8a0;e")
    assert field.text() == "80" and field.value() is None
    qtbot.keyClick(field, Qt.Key.Key_Down)  # from 80, one step down is 79: still out
    assert field.value() == 50.0  # …so the step lands on the range's end
    qtbot.keyClick(field, Qt.Key.Key_PageDown)
    assert field.value() == 40.0


@pytest.mark.parametrize("profile", available_profiles())
def test_every_number_field_of_every_window_keeps_a_value_beyond_its_range(
    qtbot: QtBot, profile: str
) -> None:
    station = Station(load_profile(profile), realtime=False)
    window = MainWindow(station)
    qtbot.addWidget(window)
    station.connect_emulator()  # the developer pane's emulator knobs are live with one
    # The developer pane's boxes for another kind of emulator stay disabled: they are
    # typed into on that machine's window.
    fields = [f for f in window.findChildren(NumberField) if f.isEnabled() and not f.isReadOnly()]
    assert len(fields) >= 2  # at least the targets or distances
    for field in fields:
        beyond = f"{int(field.maximum()) + 1}"
        type_over(qtbot, field, beyond)
        assert field.text() == beyond, field.objectName()
        assert field.value() is None and "outside" in (field.problem() or "")
    station.shutdown()
