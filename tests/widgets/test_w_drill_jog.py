"""The drill jogs: arrow keys, the jog pad and step taps become absolute moves in whole
microsteps, inside the travel, judged by what reaches the emulated drill.

The drill has no stop command, so a held jog is a chain of short steps; these
tests hold keys as a keyboard does (auto-repeat presses), let go, lose the
focus, or never send the release, and read the drill's own step counters and
the lines it received.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QEvent, Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from app.jobs.registration import Registration, hole_positions
from app.machines.drill.session import JOG_STEP_S
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow

RIGHT, LEFT, UP, DOWN = Qt.Key.Key_Right, Qt.Key.Key_Left, Qt.Key.Key_Up, Qt.Key.Key_Down
X, Y = 0, 1
#: The reference drill: 19.8 microsteps a mm on X (210 mm), 19.7 on Y (150 mm).
X_END, Y_END = 4158, 2955


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    yield harness
    harness.close()


@pytest.fixture
def window(qtbot: QtBot, drill: StationHarness) -> MainWindow:
    built = MainWindow(drill.station)
    qtbot.addWidget(built)
    built.show()
    built.activateWindow()
    qtbot.waitUntil(built.isActiveWindow)
    drill.connect()
    # The emulated drill homes by itself at power-on; wait until it stands at its zero.
    drill.run_until(lambda: drill.drill_emulator.homed and not drill.drill_emulator.busy, 30)
    return built


def moves(drill: StationHarness, since: int = 0) -> list[tuple[str, int]]:
    """The X/Y lines the drill received after ``since``, as (letter, microsteps)."""
    found = []
    for raw in drill.written[since:]:
        match = re.fullmatch(rb"([XY])(\d+)\r", raw)
        if match:
            found.append((match.group(1).decode(), int(match.group(2))))
    return found


def repeat(key: Qt.Key) -> None:
    """One auto-repeat press of a held key, where the keyboard focus is (else the window)."""
    target = QApplication.focusWidget() or QApplication.activeWindow()
    if target is None:
        target = next(w for w in QApplication.topLevelWidgets() if isinstance(w, MainWindow))
    event = QKeyEvent(QEvent.Type.KeyPress, key, Qt.KeyboardModifier.NoModifier, "", True)
    QApplication.sendEvent(target, event)


def hold(drill: StationHarness, key: Qt.Key, seconds: float, every: float = 0.05) -> None:
    """Keep ``key`` held for ``seconds`` of emulated time, repeating as a keyboard does."""
    for _ in range(round(seconds / every)):
        drill.run(every)
        repeat(key)


def settle(drill: StationHarness) -> None:
    drill.run_until(lambda: not drill.drill_session.busy, timeout=30)
    drill.run(0.2)


def x_steps(drill: StationHarness) -> int:
    return drill.drill_emulator.positions[0]


def test_a_held_arrow_moves_the_drill_in_whole_microsteps_and_the_release_stops_it(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    said: list[str] = []
    drill.station.model.message.connect(said.append)
    mark = len(drill.written)
    qtbot.keyPress(window, RIGHT)
    hold(drill, RIGHT, 1.0)
    assert window.manual_panel.jog_buttons[(1, 0)].isDown()  # the held key shows
    qtbot.keyRelease(window, RIGHT)
    released_at = x_steps(drill)
    settle(drill)
    sent = moves(drill, mark)
    assert sent and all(letter == "X" for letter, _ in sent)
    targets = [value for _, value in sent]
    assert targets == sorted(targets) and 0 < targets[-1] <= X_END
    # About a second of motion at 1.3 ms a microstep, less the time between steps.
    assert 300 < x_steps(drill) < 1000
    # The release lets at most the step under way finish, and nothing follows it.
    assert x_steps(drill) - released_at <= drill.drill_session.jog_step_microsteps(X)
    assert x_steps(drill) == targets[-1]
    assert drill.station.model.axes[X].position == pytest.approx(targets[-1] / 19.8)
    stopped = len(drill.written)
    drill.run(2.0)
    assert len(drill.written) == stopped
    assert not any("no jogging" in m or "no relative" in m for m in said)


def test_a_release_that_never_comes_ends_the_jog_by_the_dead_man(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    """The key-up is lost (a remote desktop, a grab) and no repeats come: it stops anyway."""
    said: list[str] = []
    drill.station.model.message.connect(said.append)
    qtbot.keyPress(window, UP)
    drill.run(3.0)  # neither a repeat nor a release
    settle(drill)
    ran = drill.drill_emulator.positions[1]
    # The dead-man gives a silent key 1 s: about that much motion, and one step more at most.
    period_y = 0.0015
    assert 0 < ran * period_y < 1.0 + 2 * JOG_STEP_S
    assert drill.drill_session.jog_vector == (0, 0)
    assert any("no sign" in m for m in said)
    drill.run(2.0)
    assert drill.drill_emulator.positions[1] == ran
    assert not window.manual_panel.jog_buttons[(0, 1)].isDown()


def test_the_window_losing_the_focus_stops_a_held_jog(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    qtbot.keyPress(window, RIGHT)
    hold(drill, RIGHT, 0.5)
    QApplication.sendEvent(window, QEvent(QEvent.Type.WindowDeactivate))
    at_deactivation = x_steps(drill)
    # The key-up went to another window; repeats no longer come here either.
    settle(drill)
    assert drill.drill_session.jog_vector == (0, 0)
    assert x_steps(drill) - at_deactivation <= drill.drill_session.jog_step_microsteps(X)
    rest = x_steps(drill)
    drill.run(2.0)
    assert x_steps(drill) == rest


def test_a_held_jog_ends_exactly_at_the_travel_end_and_never_past_it(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    session = drill.drill_session
    assert session.move_absolute(X, 205.0)
    settle(drill)
    mark = len(drill.written)
    qtbot.keyPress(window, RIGHT)
    hold(drill, RIGHT, 1.5)
    qtbot.keyRelease(window, RIGHT)
    settle(drill)
    assert x_steps(drill) == X_END
    assert all(value <= X_END for _, value in moves(drill, mark))
    assert "end of the travel" in window.statusBar().currentMessage() or any(
        value == X_END for _, value in moves(drill, mark)
    )
    # And down at the other end: Left runs to 0, never below (the wire has no negatives).
    assert session.move_absolute(X, 3.0)
    settle(drill)
    mark = len(drill.written)
    qtbot.keyPress(window, LEFT)
    hold(drill, LEFT, 0.8)
    qtbot.keyRelease(window, LEFT)
    settle(drill)
    assert x_steps(drill) == 0
    assert moves(drill, mark)[-1] == ("X", 0)


def test_step_taps_move_one_step_each_in_whole_microsteps(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    combo = window.manual_panel.key_step
    combo.setCurrentIndex(combo.findData(1.0))
    assert combo.currentText() == "1 mm per tap"
    mark = len(drill.written)
    for _ in range(3):
        qtbot.keyPress(window, UP)
        qtbot.keyRelease(window, UP)
    settle(drill)
    # 1 mm on Y is 19.7 microsteps: each tap is 20, and the three queue one after another.
    assert moves(drill, mark) == [("Y", 20), ("Y", 40), ("Y", 60)]
    assert drill.drill_emulator.positions[1] == 60
    qtbot.keyPress(window, DOWN)
    qtbot.keyRelease(window, DOWN)
    settle(drill)
    assert drill.drill_emulator.positions[1] == 40


def test_the_pad_button_held_with_the_mouse_jogs_and_its_release_stops(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    window.menu_panel.set_page(0)
    button = window.manual_panel.jog_buttons[(0, 1)]
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    drill.run(0.5)
    qtbot.mouseRelease(button, Qt.MouseButton.LeftButton)
    settle(drill)
    ran = drill.drill_emulator.positions[1]
    assert ran > 0 and drill.drill_session.jog_vector == (0, 0)
    drill.run(1.5)
    assert drill.drill_emulator.positions[1] == ran


def test_no_jog_while_a_procedure_runs_is_queued_behind_it(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    """A held jog waits for the drill to be free, then steps; its release sends nothing more."""
    session = drill.drill_session
    assert session.move_absolute(Y, 100.0)
    qtbot.keyPress(window, RIGHT)
    repeat(RIGHT)
    assert [letter for letter, _ in moves(drill)][-1:] == ["Y"]  # nothing queued behind Y
    qtbot.keyRelease(window, RIGHT)
    settle(drill)
    assert x_steps(drill) == 0


# --- registration by jogging, as the manual's recipe says ----------------------------------

EXCELLON = (
    "M48\nMETRIC\nT01C0.8\nT02C1.0\n%\nT01\nX10.0Y10.0\nX60.0Y10.0\nX30.0Y40.0\n"
    "T02\nX45.0Y25.0\nX15.0Y35.0\nM30\n"
)
TRUTH = Registration(math.radians(2.0), (20.0, 15.0))
TAPS = (10.0, 1.0, 0.1)


def jog_over(
    qtbot: QtBot, drill: StationHarness, window: MainWindow, axis: int, target: float
) -> None:
    """What an operator does: hold the arrow to get near, then tap, watching the position."""
    model = drill.station.model
    plus, minus = (RIGHT, LEFT) if axis == X else (UP, DOWN)
    combo = window.manual_panel.key_step
    combo.setCurrentIndex(combo.findData(0.0))
    error = target - model.axes[axis].position
    if abs(error) > 8.0:
        key = plus if error > 0 else minus
        qtbot.keyPress(window, key)
        for _ in range(200):
            if abs(target - model.axes[axis].position) <= 6.0:
                break
            hold(drill, key, 0.05)
        else:
            raise AssertionError(f"the held jog did not bring axis {axis} near {target}")
        qtbot.keyRelease(window, key)
        settle(drill)
    for _ in range(100):
        error = target - model.axes[axis].position
        if abs(error) < 0.06:  # within a microstep (0.05 mm): as close as the drill goes
            return
        step = next((s for s in TAPS if s <= abs(error) + 0.03), TAPS[-1])
        combo.setCurrentIndex(combo.findData(step))
        key = plus if error > 0 else minus
        qtbot.keyPress(window, key)
        qtbot.keyRelease(window, key)
        settle(drill)
    raise AssertionError(f"axis {axis} never came within a microstep of {target}")


def test_registration_works_by_jogging_three_reference_holes(
    qtbot: QtBot, drill: StationHarness, window: MainWindow, tmp_path: Path
) -> None:
    path = tmp_path / "board.drl"
    path.write_text(EXCELLON, encoding="utf-8")
    dock = window.jobs_dock
    dock.show()
    assert dock.open_path(path)
    original = dock.runner.program
    assert original is not None
    bar = dock.registration
    qtbot.mouseClick(bar.three_check, Qt.MouseButton.LeftButton)
    # The offscreen platform takes the activation away once the dock has laid itself out;
    # an operator's window is active when they press arrows in it.
    drill.run(0.1)
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    holes = hole_positions(original)
    mark = len(drill.written)
    for k in range(3):
        x, y = TRUTH.apply(*holes[bar.hole_spins[k].value() - 1])
        jog_over(qtbot, drill, window, X, x)
        jog_over(qtbot, drill, window, Y, y)
        qtbot.mouseClick(bar.here_buttons[k], Qt.MouseButton.LeftButton)
    qtbot.mouseClick(bar.register_button, Qt.MouseButton.LeftButton)
    # Only jogs moved the drill: X/Y lines, nothing typed on the Drill page.
    assert moves(drill, mark) and all(
        re.fullmatch(rb"[XY]\d+\r", raw) for raw in drill.written[mark:]
    )
    text = dock.messages.toPlainText()
    rotation = re.search(r"registered: rotation ([+-][\d.]+)°", text)
    assert rotation is not None, text
    assert float(rotation.group(1)) == pytest.approx(2.0, abs=0.1)
    assert "three points agree within" in text
    moved = dock.runner.program
    assert moved is not None and moved is not original
    for hole, where in zip(hole_positions(original), hole_positions(moved), strict=True):
        assert math.dist(TRUTH.apply(*hole), where) < 0.15  # jogged to within a microstep


# --- a machine that cannot jog shows no pad ---------------------------------------------


def test_every_shipped_machine_jogs_and_shows_its_pad(qtbot: QtBot) -> None:
    for name in ("pcb-drill", "xy-stage", "usb3", "string-art"):
        harness = StationHarness(load_profile(name))
        try:
            built = MainWindow(harness.station)
            qtbot.addWidget(built)
            assert harness.station.dialect.jogs
            assert not built.manual_panel.jog_pad.isHidden()
            assert built.jog.is_jog_key(RIGHT)
        finally:
            harness.close()


def test_a_machine_that_cannot_jog_shows_no_pad_and_leaves_the_arrows_alone(
    qtbot: QtBot, drill: StationHarness
) -> None:
    drill.station.dialect = dataclasses.replace(drill.station.dialect, jogs=False)
    built = MainWindow(drill.station)
    qtbot.addWidget(built)
    built.show()
    built.activateWindow()
    qtbot.waitUntil(built.isActiveWindow)
    drill.connect()
    drill.run(0.5)
    panel = built.manual_panel
    assert panel.jog_pad.isHidden() and not panel.key_step.isVisible()
    assert panel.stop_button.isVisible()  # Stop stays in sight without the pad
    mark = len(drill.written)
    qtbot.keyPress(built, RIGHT)
    drill.run(0.5)
    qtbot.keyRelease(built, RIGHT)
    assert drill.written[mark:] == []
    assert "jog" not in built.statusBar().currentMessage().lower()


def test_esc_during_a_held_jog_ends_it_and_sends_nothing_more(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    qtbot.keyPress(window, RIGHT)
    hold(drill, RIGHT, 0.5)
    qtbot.keyClick(window, Qt.Key.Key_Escape)
    at_stop = x_steps(drill)
    stopped = len(drill.written)
    hold(drill, RIGHT, 0.5)  # the key is still down: its repeats do not start it again
    settle(drill)
    assert drill.drill_session.jog_vector == (0, 0)
    assert len(drill.written) == stopped
    assert x_steps(drill) - at_stop <= drill.drill_session.jog_step_microsteps(X)


def test_shift_held_jogs_the_drill_in_short_steps_for_fine_positioning(
    qtbot: QtBot, drill: StationHarness, window: MainWindow
) -> None:
    mark = len(drill.written)
    qtbot.keyPress(window, Qt.Key.Key_Shift)
    qtbot.keyPress(window, RIGHT, Qt.KeyboardModifier.ShiftModifier)
    hold(drill, RIGHT, 0.5)
    qtbot.keyRelease(window, RIGHT, Qt.KeyboardModifier.ShiftModifier)
    qtbot.keyRelease(window, Qt.Key.Key_Shift)
    settle(drill)
    targets = [value for _, value in moves(drill, mark)]
    steps = [b - a for a, b in zip([0, *targets], targets, strict=False)]
    assert len(steps) >= 5 and set(steps) == {8}  # 0.01 s at 1.3 ms a microstep
    # Shift let go: the next held jog is at the usual step again.
    mark = len(drill.written)
    qtbot.keyPress(window, RIGHT)
    qtbot.keyRelease(window, RIGHT)
    settle(drill)
    assert moves(drill, mark) == [("X", targets[-1] + 77)]
