"""Developer pane on a G-code machine: replies in words, injected replies, the board's buttons."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.developer.gcode import describe_gcode, parse_reply
from app.profiles import load_profile
from protocol.gcode.codec import ErrorReply, StatusReport
from tests.helpers.harness import StationHarness
from widgets.developer.pane import DeveloperPane

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[tuple[StationHarness, DeveloperPane]]:
    harness = StationHarness(load_profile("corexy-plotter"))
    pane = DeveloperPane(harness.station)
    qtbot.addWidget(pane)
    pane.show()
    harness.connect()
    harness.run(0.3)
    try:
        yield harness, pane
    finally:
        harness.close()


def log_text(pane: DeveloperPane) -> str:
    pane.log_view.flush()
    return pane.log_view.text


def test_the_frame_log_says_lines_and_replies_in_words(
    plotter: tuple[StationHarness, DeveloperPane],
) -> None:
    harness, pane = plotter
    assert pane.reply_box.isVisible() and not pane.composer.isVisible()
    harness.gcode_session.send_line("G0 X10")
    harness.run_until(lambda: harness.gcode_session.settled, timeout=5)
    text = log_text(pane)
    assert "G0 X10" in text
    assert "ok: the oldest unanswered line was accepted" in text
    assert "Idle at (10.000, 0.000, 0.000)" in text


def test_an_injected_reply_acts_as_the_devices_own(
    qtbot: QtBot, plotter: tuple[StationHarness, DeveloperPane]
) -> None:
    harness, pane = plotter
    messages: list[str] = []
    harness.station.model.message.connect(messages.append)
    pane.reply_box.entry.setFocus()
    qtbot.keyClicks(pane.reply_box.entry, "<Hold:0|MPos:5.000,6.000,0.000|FS:0,0>")
    qtbot.keyClick(pane.reply_box.entry, Qt.Key.Key_Return)
    assert [axis.position for axis in harness.station.model.axes] == [5.0, 6.0]
    assert harness.gcode_session.machine_state == "Hold"
    qtbot.mouseClick(pane.reply_box.quick_buttons["ALARM:1"], LEFT)
    assert any("alarm 1" in m.lower() for m in messages)
    assert "alarm 1: hard limit" in log_text(pane).lower()


def test_a_typo_is_refused_not_injected_as_garbage(
    qtbot: QtBot, plotter: tuple[StationHarness, DeveloperPane]
) -> None:
    harness, pane = plotter
    before = harness.gcode_session.rejected
    assert not pane.reply_box.inject_text("okk")
    assert pane.reply_box.error.isVisible() and "drop" in pane.reply_box.error.text()
    assert harness.gcode_session.rejected == before


def test_the_boards_alarm_button_locks_it_until_unlocked(
    qtbot: QtBot, plotter: tuple[StationHarness, DeveloperPane]
) -> None:
    harness, pane = plotter
    assert pane.board_box.alarm_button.isEnabled()
    qtbot.mouseClick(pane.board_box.alarm_button, LEFT)
    harness.run(0.5)
    assert harness.gcode_session.machine_state == "Alarm"
    harness.gcode_session.send_line("$X")
    harness.run(0.5)
    assert harness.gcode_session.machine_state == "Idle"


def test_replies_parse_and_read_as_the_station_takes_them() -> None:
    assert parse_reply(" error:9 ") == ErrorReply(9)
    report = parse_reply("<Run|MPos:1.5,2,0|FS:1200,0|Bf:12,100>")
    assert isinstance(report, StatusReport)
    assert (
        describe_gcode(report) == "Run at (1.500, 2.000, 0.000), feed 1200, 12 planner blocks free"
    )
    with pytest.raises(ValueError, match="ASCII"):
        parse_reply("ök")
    with pytest.raises(ValueError):
        parse_reply("")


def test_s0_24_the_winders_white_button_and_hand_turning_from_the_pane(
    qtbot: QtBot,
) -> None:
    """FIDELITY S0-24: the developer presses the emulated winder's white button (drivers
    off), turns an axis by hand, presses again (zero here, X = board radius)."""
    harness = StationHarness(load_profile("string-art"))
    pane = DeveloperPane(harness.station)
    qtbot.addWidget(pane)
    pane.show()
    harness.connect()
    harness.run(0.3)
    try:
        box, emulator = pane.board_box, harness.gcode_emulator
        assert box.white_button.isVisible() and box.white_button.isEnabled()
        qtbot.mouseClick(box.hand_buttons[("A", 1)], LEFT)
        assert emulator.position()["A"] == 0.0  # the driver holds
        assert "A holds" in box.white_note.text()
        qtbot.mouseClick(box.white_button, LEFT)
        assert emulator.drivers_off == {"A", "X", "Z"}
        qtbot.mouseClick(box.hand_buttons[("A", 1)], LEFT)
        qtbot.mouseClick(box.hand_buttons[("X", 1)], LEFT)
        assert emulator.position() == {"A": 5.0, "X": 1.0, "Z": 0.0}
        harness.run(0.5)
        assert [a.position for a in harness.station.model.axes] == [5.0, 1.0, 0.0]
        qtbot.mouseClick(box.white_button, LEFT)
        assert emulator.position() == {"A": 0.0, "X": 120.0, "Z": 0.0}
        assert "zero set" in box.white_note.text()
    finally:
        harness.close()


def test_the_plotters_pane_has_no_white_button(
    plotter: tuple[StationHarness, DeveloperPane],
) -> None:
    _harness, pane = plotter
    assert not pane.board_box.white_button.isVisible()
