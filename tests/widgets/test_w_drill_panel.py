"""The drill's page driven as the operator drives it: clicks, typing, Up/Down, Enter.

Against the emulated plotter on a manual clock; asserting what goes on the
wire, what the columns and the terminal then show, and the main window's
pages on the pcb-drill profile.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QLabel, QListWidget, QPushButton, QWidget
from pytestqt.qtbot import QtBot

from app.jobs.estimate.drill import estimate_drill
from app.jobs.program import Operation, OpKind, Program, SourceRef
from app.machines.registry import dialect_for
from app.profiles import MACHINES_DIR as PROFILES
from app.profiles import ProfileError, load_profile
from protocol.clock import ManualClock
from protocol.drill.codec import Command
from protocol.drill.timing import DrillTiming
from protocol.emulator.drill_firmware import DrillFirmware
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.panels.drill import LONG_MOVE_S, DrillPanel


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    yield harness
    harness.close()


@pytest.fixture
def panel(qtbot: QtBot, drill: StationHarness) -> DrillPanel:
    drill.connect()
    drill.run(0.02)
    built = DrillPanel(drill.station)
    qtbot.addWidget(built)
    built.show()
    qtbot.waitExposed(built)
    return built


def click(qtbot: QtBot, button: QPushButton) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def items(widget: QListWidget) -> list[str]:
    return [widget.item(i).text() for i in range(widget.count())]


def type_line(qtbot: QtBot, panel: DrillPanel, text: str) -> None:
    qtbot.mouseClick(panel.entry, Qt.MouseButton.LeftButton)
    panel.entry.selectAll()
    qtbot.keyClicks(panel.entry, text)


def test_n_button_fills_received_then_done(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    mark = len(drill.written)
    click(qtbot, panel.command_buttons["N"])
    assert drill.written[mark:] == [b"N\r"]
    assert items(panel.received_list) == []
    drill.run_until(lambda: panel.received_list.count() == 1)
    assert items(panel.received_list) == ["N"]
    assert items(panel.done_list) == []  # homing takes seconds
    drill.run_until(lambda: panel.done_list.count() == 1)
    assert items(panel.done_list) == ["N"]
    assert drill.drill_emulator.homed
    lines = panel.output.toPlainText().splitlines()
    assert lines == ["> N", "< RN", "< DN"]


def test_axis_send_uses_the_microstep_box(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    box = panel.targets[0]
    qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    qtbot.keyClick(box, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(box, "248")
    assert box.value() == 248
    mark = len(drill.written)
    click(qtbot, panel.send_buttons[0])
    assert drill.written[mark:] == [b"X248\r"]
    drill.run_until(lambda: panel.done_list.count() == 1)
    assert drill.station.model.axes[0].position == pytest.approx(248 / 19.8)


def test_terminal_send_history_and_cls(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    mark = len(drill.written)
    type_line(qtbot, panel, "K")
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)
    assert panel.entry.text() == ""
    drill.run_until(lambda: panel.done_list.count() == 1)
    type_line(qtbot, panel, "Z")
    click(qtbot, panel.send_button)
    drill.run_until(lambda: panel.done_list.count() == 2)
    assert drill.written[mark:] == [b"K\r", b"Z\r"]
    assert items(panel.received_list) == ["K", "Z"]
    assert items(panel.done_list) == ["K", "Z"]
    assert panel.history == ("K", "Z")
    assert "< DK" in panel.output.toPlainText()

    # Garbage is refused before the wire and said in the terminal.
    type_line(qtbot, panel, "hello")
    click(qtbot, panel.send_button)
    assert drill.written[mark:] == [b"K\r", b"Z\r"]
    assert "! hello: not sent" in panel.output.toPlainText()
    assert drill.drill_session.refused_lines == 1

    # Up walks back through what was typed, Down forward and off the end.
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    assert panel.entry.text() == "hello"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    assert panel.entry.text() == "Z"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    assert panel.entry.text() == "K"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    assert panel.entry.text() == "Z"
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Down)
    assert panel.entry.text() == ""
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Up)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)  # resend Z from history
    assert drill.written[mark:] == [b"K\r", b"Z\r", b"Z\r"]

    click(qtbot, panel.clear_button)
    assert panel.output.toPlainText() == ""
    assert panel.received_list.count() == 0
    assert panel.done_list.count() == 0


def test_buttons_follow_the_motion_lock(qtbot: QtBot, drill: StationHarness) -> None:
    window = MainWindow(drill.station)
    qtbot.addWidget(window)
    assert not window.drill_panel.command_buttons["V"].isEnabled()
    drill.connect()
    drill.run(0.02)
    assert window.drill_panel.command_buttons["V"].isEnabled()
    assert window.drill_panel.send_buttons[1].isEnabled()


def test_main_window_has_a_drill_page_and_no_absolute_or_relative(
    qtbot: QtBot, drill: StationHarness
) -> None:
    window = MainWindow(drill.station)
    qtbot.addWidget(window)
    titles = [b.text() for b in window.menu_panel.findChildren(QPushButton)]
    assert "D&rill" in titles
    assert not any(t in titles for t in ("&Absolute", "&Relative", "&Dynamics"))
    assert not hasattr(window, "absolute_panel")


# --- what STOP and Esc do on a machine that cannot stop a move (issue 15, symptom 9) -------


def test_stop_button_says_it_drops_the_queue_and_esc_does_that(
    qtbot: QtBot, drill: StationHarness
) -> None:
    window = MainWindow(drill.station)
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitUntil(window.isActiveWindow)
    drill.connect()
    drill.run(0.02)
    stop = window.static_panel.stop_button
    assert stop.text() == "DROP QUEUE\nthis procedure\nfinishes (Esc)"
    assert "no stop command" in stop.toolTip()
    assert window.manual_panel.stop_button.text() == "■ Drop\nqueue"  # the jog pad's too
    help_text = window.show_shortcuts().findChild(QLabel).text()
    assert "Drop the queued commands" in help_text and "this procedure finishes" in help_text

    mark = len(drill.written)
    for letter in "KZK":
        click(qtbot, window.drill_panel.command_buttons[letter])
    assert drill.written[mark:] == [b"K\r"]  # one at a time: Z and K wait in the queue
    qtbot.keyClick(window, Qt.Key.Key_Escape)
    drill.run_until(lambda: window.drill_panel.done_list.count() == 1)
    drill.run(1.0)
    assert drill.written[mark:] == [b"K\r"]  # the queue was dropped, the running K finished
    assert items(window.drill_panel.done_list) == ["K"]


def test_stop_button_on_a_machine_that_stops_says_stop(
    qtbot: QtBot, harness: StationHarness
) -> None:
    window = MainWindow(harness.station)
    qtbot.addWidget(window)
    assert window.static_panel.stop_button.text() == "STOP"
    assert window.manual_panel.stop_button.text() == "■ Stop"


# --- long moves ask first: they cannot be stopped ------------------------------------------


def type_target(qtbot: QtBot, box: QWidget, text: str) -> None:
    qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    qtbot.keyClick(box, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(box, text)


def test_a_long_move_is_sent_only_after_send_anyway(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    # 3960 microsteps of X (200 mm) run 3960 x 1.3 ms ≈ 5.1 s: past LONG_MOVE_S.
    type_target(qtbot, panel.targets[0], "3960")
    mark = len(drill.written)
    click(qtbot, panel.send_buttons[0])
    assert drill.written[mark:] == []
    assert panel.long_move.isVisible()
    assert "X3960" in panel.long_move_label.text() and "5 s" in panel.long_move_label.text()
    assert "no stop command" in panel.long_move_label.text()
    click(qtbot, panel.long_move_cancel)
    assert not panel.long_move.isVisible()
    drill.run(0.5)
    assert drill.written[mark:] == []

    click(qtbot, panel.send_buttons[0])
    click(qtbot, panel.long_move_send)
    assert drill.written[mark:] == [b"X3960\r"]
    assert not panel.long_move.isVisible()


def test_a_long_move_typed_in_the_terminal_asks_too(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    assert LONG_MOVE_S < 2955 * 0.0015  # 150 mm of Y
    type_line(qtbot, panel, "Y2955")
    mark = len(drill.written)
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)
    assert drill.written[mark:] == [] and panel.long_move.isVisible()
    click(qtbot, panel.long_move_send)
    assert drill.written[mark:] == [b"Y2955\r"]
    # A short move goes at once (1000 microsteps of X: 1.3 s).
    drill.run_until(lambda: panel.done_list.count() == 1, timeout=20)
    type_line(qtbot, panel, "X1000")
    qtbot.keyClick(panel.entry, Qt.Key.Key_Return)
    assert drill.written[-1] == b"X1000\r" and not panel.long_move.isVisible()


def test_a_target_beyond_the_travel_is_shown_invalid_and_not_sent(
    qtbot: QtBot, drill: StationHarness, panel: DrillPanel
) -> None:
    type_target(qtbot, panel.targets[0], "5000")  # X travel: 210 mm = 4158 microsteps
    assert panel.targets[0].text() == "5000" and panel.targets[0].value() is None
    assert "5000 is outside 0…4158 µsteps" in panel.note.text()
    assert not panel.send_buttons[0].isEnabled()
    mark = len(drill.written)
    assert panel.send_axis(0) is False
    drill.run(0.3)
    assert drill.written[mark:] == []


# --- the timing constants, edited in the station (FIDELITY S2-06) ---------------------------


def test_s2_06_the_drill_page_edits_the_timing_constants_and_the_station_keeps_them(
    qtbot: QtBot, drill: StationHarness, tmp_path: Path
) -> None:
    drill.connect()
    drill.run(0.02)
    settings = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    window = MainWindow(drill.station, settings)
    qtbot.addWidget(window)
    box = window.drill_panel.timing_box
    assert not box.isVisibleTo(window.drill_panel)  # folded away until asked for
    click(qtbot, window.drill_panel.timing_toggle)
    assert box.isVisibleTo(window.drill_panel)
    assert box.fields["z_period_s"].text().startswith("2.50")  # ms, the reference 2.5
    where = SourceRef("t.drl", 1)
    program = Program("t", (Operation(OpKind.DRILL, where),))
    before = estimate_drill(program, drill.station.profile, overhead_s=0.0).total_s
    # Out of bounds: framed, named in the note, and Apply refuses.
    box.fields["bottom_wait_s"].setText("9000")
    assert not box.apply_button.isEnabled() and box.timing() is None
    box.fields["bottom_wait_s"].setText("300")  # the teacher's 300 ms at the bottom
    box.fields["z_period_s"].setText("5")
    click(qtbot, box.apply_button)
    timing = drill.station.profile.drill_timing
    assert timing.bottom_wait_s == pytest.approx(0.3) and timing.z_period_s == pytest.approx(0.005)
    # The estimate counts with them: 412 microsteps down at 5 ms instead of 2.5, 0.2 s
    # more at the bottom, and the 39 full steps back at 5 ms.
    after = estimate_drill(program, drill.station.profile, overhead_s=0.0).total_s
    assert after - before == pytest.approx(412 * 0.0025 + 0.2 + 39 * 0.0025)
    # The emulated drill runs them; the session's timeout waits for them.
    emulator = drill.drill_emulator
    assert emulator.config.dwell == pytest.approx(0.3)
    assert emulator.config.step_periods[2] == pytest.approx(0.005)
    assert drill.drill_session.expected_s(Command("V")) == pytest.approx(timing.first_cycle_s)
    # Kept across launches: a new window on the reference profile shows and applies them.
    window.close()
    fresh = StationHarness(load_profile("pcb-drill"))
    again = MainWindow(
        fresh.station, QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    )
    qtbot.addWidget(again)
    assert fresh.station.profile.drill_timing == timing
    assert again.drill_panel.timing_box.fields["bottom_wait_s"].value() == pytest.approx(300)
    # Profile values: the profile's constants again, and nothing kept.
    click(qtbot, again.drill_panel.timing_box.profile_button)
    assert fresh.station.profile.drill_timing == DrillTiming()
    stored = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    assert not any(key.startswith("drill_timing/") for key in stored.allKeys())
    fresh.close()


def test_s2_06_a_profiles_timing_table_sets_the_constants_within_their_bounds(
    tmp_path: Path,
) -> None:
    text = (PROFILES / "pcb-drill.toml").read_text(encoding="utf-8")
    path = tmp_path / "slow-drill.toml"
    path.write_text(text + "\n[timing]\nz_period_s = 0.005\nreturn_full_steps = 50\n")
    profile = load_profile(path)
    assert profile.drill_timing == DrillTiming(z_period_s=0.005, return_full_steps=50)
    emulator = dialect_for(profile).emulator(ManualClock(), profile)
    assert isinstance(emulator, DrillFirmware)
    assert emulator.config.step_periods[2] == 0.005 and emulator.config.return_full_steps == 50
    for bad in ("z_period_s = 1.0", "return_full_steps = 2.5", "nozzle_s = 1"):
        path.write_text(text + f"\n[timing]\n{bad}\n")
        with pytest.raises(ProfileError, match=r"\[timing\]"):
            load_profile(path)
