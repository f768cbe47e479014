"""The usb3 unit's Axes page, and the operator window on the usb3 profile.

Driven as the operator drives them: typing into the fields, keys on the
combo boxes, clicks on the buttons, key presses on the window; against the
emulated unit on a manual clock, asserting what goes on the wire and what
the operator then sees.  Defaults of the unit: M6 thread (6400 counts a mm)
and 1/8 step (4 counts a pulse, 0.000625 mm).
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QComboBox, QLineEdit, QPushButton, QWidget
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from protocol.transport.loopback import Direction
from protocol.usb3.codec import AxisId, StepSize, Thread
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.panels.usb3 import Usb3Panel

X, Y, Z = 0, 1, 2


@pytest.fixture
def usb3(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("usb3"))
    yield harness
    harness.close()


@pytest.fixture
def panel(qtbot: QtBot, usb3: StationHarness) -> Usb3Panel:
    """The page on a connected station, settings read, shown."""
    usb3.connect()
    usb3.run(0.05)
    built = Usb3Panel(usb3.station)
    qtbot.addWidget(built)
    built.show()
    qtbot.waitExposed(built)
    return built


def type_distance(qtbot: QtBot, box: QWidget, text: str) -> None:
    """Click into the field, select what is there and type over it."""
    qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    qtbot.keyClick(box, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(box, text)


def key_on(qtbot: QtBot, combo: QComboBox, key: Qt.Key, times: int = 1) -> None:
    """Choose in a combo box from the keyboard, as the operator does with it focused."""
    combo.setFocus()
    for _ in range(times):
        qtbot.keyClick(combo, key)


def click(qtbot: QtBot, button: QPushButton) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def sent_since(harness: StationHarness, mark: int) -> bytes:
    return b"".join(harness.written[mark:])


def wait_idle(harness: StationHarness, axis: int, timeout: float = 30.0) -> None:
    model = harness.station.model
    harness.step()  # the unit takes commands at its next control cycle
    harness.run_until(
        lambda: (
            not harness.usb3_emulator.moving(AxisId(axis))
            and model.axes[axis].status_text == "idle"
        ),
        timeout=timeout,
    )


# --- the Axes page -------------------------------------------------------------------


def test_typing_a_distance_shows_the_reachable_one(qtbot: QtBot, panel: Usb3Panel) -> None:
    type_distance(qtbot, panel.distances[X], "12.5")
    assert panel.distances[X].value() == 12.5
    assert panel.reachable[X].text() == "+12.5000 mm"  # 80000 counts: whole eighth steps

    type_distance(qtbot, panel.distances[X], "0.012")
    # 76.8 counts are 19.2 pulses of 4 counts: 19 pulses = 76 counts = 0.011875 mm.
    assert panel.reachable[X].text() == "+0.0119 mm"
    assert panel.reachable[Y].text() == "+0.0000 mm"  # the other rows are their own


def test_changing_the_step_size_sends_it_and_the_reachable_distance_follows(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    type_distance(qtbot, panel.distances[X], "0.012")
    assert panel.reachable[X].text() == "+0.0119 mm"

    mark = len(usb3.written)
    key_on(qtbot, panel.step_combos[X], Qt.Key.Key_Home)  # full steps

    assert sent_since(usb3, mark) == b"M033;G;"
    assert usb3.usb3_session.step_sizes[X] is StepSize.FULL
    # A full step is 32 counts, 0.005 mm: 0.012 mm reaches 2 steps.
    assert panel.reachable[X].text() == "+0.0100 mm"
    usb3.run(0.05)
    assert usb3.usb3_emulator.step_sizes == (StepSize.FULL, StepSize.EIGHTH, StepSize.EIGHTH)
    assert panel.step_combos[X].currentText() == "full"  # the unit's reply left it so


def test_changing_the_thread_sends_it_and_the_reachable_distance_follows(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    type_distance(qtbot, panel.distances[Y], "12.5")
    mark = len(usb3.written)
    key_on(qtbot, panel.thread_combos[Y], Qt.Key.Key_Up, times=2)  # M6 → M5 → M4

    assert panel.thread_combos[Y].currentText() == "M4 (0.7 mm)"
    assert sent_since(usb3, mark) == b"T434;G;T424;G;"
    # 12.5 mm on 0.7 mm is 114285.7 counts: 28571 pulses of 4 = 114284 counts.
    assert panel.reachable[Y].text() == "+12.4998 mm"


def test_send_moves_the_axis_by_the_reachable_distance(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    type_distance(qtbot, panel.distances[Z], "1.5")
    mark = len(usb3.written)
    click(qtbot, panel.send_buttons[Z])

    assert sent_since(usb3, mark) == b"D+++;Z000000000009600;"
    wait_idle(usb3, Z)
    assert usb3.station.model.axes[Z].position == 1.5
    assert usb3.usb3_emulator.positions == (0, 0, 9600)
    # Back below the zero the unit counts from would leave the travel: nothing is sent.
    type_distance(qtbot, panel.distances[Z], "-2")
    mark = len(usb3.written)
    click(qtbot, panel.send_buttons[Z])
    assert sent_since(usb3, mark) == b""


def test_zero_button_zeroes_every_axis(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    type_distance(qtbot, panel.distances[X], "0.25")
    click(qtbot, panel.send_buttons[X])
    wait_idle(usb3, X)
    assert usb3.station.model.axes[X].position == 0.25

    mark = len(usb3.written)
    click(qtbot, panel.zero_button)
    assert sent_since(usb3, mark) == b"C;"
    usb3.run(0.5)
    assert [a.position for a in usb3.station.model.axes] == [0.0, 0.0, 0.0]
    assert usb3.usb3_emulator.positions == (0, 0, 0)


def test_the_units_menu_change_updates_the_combos_and_the_reachable_distance(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    type_distance(qtbot, panel.distances[X], "12.5")
    assert panel.reachable[X].text() == "+12.5000 mm"
    mark = len(usb3.written)

    usb3.usb3_emulator.menu_set(
        step_sizes=(StepSize.FULL, StepSize.EIGHTH, StepSize.HALF),
        threads=(Thread.M4, Thread.M6, Thread.M10),
    )
    usb3.run(0.05)

    assert [c.currentText() for c in panel.step_combos] == ["full", "1/8", "1/2"]
    assert [c.currentText() for c in panel.thread_combos] == [
        "M4 (0.7 mm)",
        "M6 (1 mm)",
        "M10 (1.5 mm)",
    ]
    # 114285.7 counts on 0.7 mm at 32 counts a full step: 3571 steps = 114272 counts.
    assert panel.reachable[X].text() == "+12.4985 mm"
    assert usb3.written[mark:] == []  # following the unit sends it nothing


def test_garbage_typed_into_a_distance_is_ignored(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    type_distance(qtbot, panel.distances[X], "1.5")
    mark = len(usb3.written)
    qtbot.keyClicks(panel.distances[X], "abc;G;")
    assert panel.distances[X].value() == 1.5
    assert usb3.written[mark:] == []
    click(qtbot, panel.send_buttons[X])
    assert sent_since(usb3, mark) == b"D+++;X000000000009600;"


def test_a_distance_beyond_the_travel_stays_as_typed_and_sends_nothing(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    """Issue 15: the unit was driven to 225…338 mm on a 200 mm axis."""
    type_distance(qtbot, panel.distances[X], "338")
    assert panel.distances[X].text() == "338"  # not cut to 33 or clamped to 200
    assert panel.distances[X].value() is None
    assert "X distance: 338 is outside \u2212200…200 mm" in panel.note.text()
    assert not panel.send_buttons[X].isEnabled()
    assert panel.reachable[X].text() == "—"
    mark = len(usb3.written)
    click(qtbot, panel.send_buttons[X])
    qtbot.keyClick(panel.distances[X], Qt.Key.Key_Return)
    assert panel.send(X) is False
    usb3.run(0.5)
    assert sent_since(usb3, mark) == b""
    assert usb3.usb3_emulator.positions[X] == 0


# --- the operator window on the usb3 profile -----------------------------------------


@pytest.fixture
def window(qtbot: QtBot, usb3: StationHarness) -> MainWindow:
    built = MainWindow(usb3.station)
    qtbot.addWidget(built)
    built.show()
    built.activateWindow()
    qtbot.waitUntil(built.isActiveWindow)
    usb3.connect()
    usb3.run(0.05)
    return built


def page_titles(window: MainWindow) -> list[str]:
    return [b.text() for b in window.menu_panel.findChildren(QPushButton)]


def test_the_window_has_the_axes_page_and_none_of_the_stage_only_parts(
    window: MainWindow,
) -> None:
    titles = page_titles(window)
    assert "A&xes" in titles
    assert not any("Dynamics" in t for t in titles)
    assert not any(t in ("&Absolute", "&Relative") for t in titles)
    assert not hasattr(window, "dynamics_panel")
    axes_page = window.usb3_panel
    window.menu_panel.button(window.stack.indexOf(axes_page)).click()
    assert axes_page.isVisible()
    assert not window.info_panel.battery.isVisible()
    assert not window.info_panel.temperature.isVisible()
    assert len(window.info_panel.positions) == 3


def test_page_up_and_page_down_jog_z(
    qtbot: QtBot, usb3: StationHarness, window: MainWindow
) -> None:
    z = usb3.station.model.axes[Z]
    focus = QWidget.focusWidget(window)
    assert not isinstance(focus, QLineEdit)  # keys go to the window, not a field

    mark = len(usb3.written)
    qtbot.keyPress(window, Qt.Key.Key_PageUp)
    sent = usb3.written[mark:]
    assert sent[0] == b"D+++;"
    assert sent[1].startswith(b"Z") and len(sent) == 2
    usb3.run(1.0)
    assert z.position > 0 and z.status_text == "moving"
    assert usb3.station.model.axes[X].position == 0.0

    mark = len(usb3.written)
    qtbot.keyRelease(window, Qt.Key.Key_PageUp)
    assert usb3.written[mark:] == [b"S;"]
    wait_idle(usb3, Z, timeout=2.0)
    top = z.position

    mark = len(usb3.written)
    qtbot.keyPress(window, Qt.Key.Key_PageDown)
    assert usb3.written[mark] == b"D++-;"
    usb3.run(1.0)
    assert z.position < top
    qtbot.keyRelease(window, Qt.Key.Key_PageDown)
    wait_idle(usb3, Z, timeout=2.0)
    assert usb3.usb3_emulator.positions[:2] == (0, 0)


def test_garbage_from_the_unit_and_what_it_could_not_parse_are_counted_in_the_status_bar(
    usb3: StationHarness, window: MainWindow
) -> None:
    assert window.rejected_label.text() == "rejected frames: 0"
    injected: list[bytes] = []

    def inject(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_HOST and not injected:
            injected.append(data)
            return data + b"garbage;"
        return data

    usb3.loopback.set_manipulator(inject)
    usb3.usb3_session.request_settings()
    usb3.run(0.05)
    assert injected
    assert window.rejected_label.text() == "rejected frames: 1"
    assert "Garbage from the unit dropped" in window.message_label.text()

    assert usb3.station.link is not None
    usb3.station.link.write(b"hello;")  # the unit answers ?;
    usb3.run(0.05)
    assert window.rejected_label.text() == "rejected frames: 2"
    assert window.message_label.text() == "The unit did not understand a command (?;)"


def test_send_all_moves_every_axis_in_one_command_and_refuses_all_or_nothing(
    qtbot: QtBot, usb3: StationHarness, panel: Usb3Panel
) -> None:
    """FIDELITY S4-22: the unit's own tool had one Send for all three axes."""
    type_distance(qtbot, panel.distances[X], "2.5")
    type_distance(qtbot, panel.distances[Y], "0")
    type_distance(qtbot, panel.distances[Z], "1.5")
    mark = len(usb3.written)
    click(qtbot, panel.send_all_button)
    # One direction command for all three, then X and Z (Y stays): they start together.
    assert sent_since(usb3, mark) == b"D+++;X000000000016000;Z000000000009600;"
    wait_idle(usb3, X)
    wait_idle(usb3, Z)
    assert usb3.usb3_emulator.positions == (16000, 0, 9600)
    assert [a.position for a in usb3.station.model.axes] == [2.5, 0.0, 1.5]

    # Z back by 2 mm would leave the travel below the zero: X's move does not go either.
    type_distance(qtbot, panel.distances[X], "-1")
    type_distance(qtbot, panel.distances[Z], "-2")
    mark = len(usb3.written)
    click(qtbot, panel.send_all_button)
    assert panel.send_all() is False
    usb3.run(0.5)
    assert sent_since(usb3, mark) == b""
    assert usb3.usb3_emulator.positions == (16000, 0, 9600)
