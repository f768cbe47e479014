"""Absolute panel: targets judged against the travel as typed, Go per axis and Go all."""

from __future__ import annotations

from typing import NamedTuple

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QVBoxLayout, QWidget
from pytestqt.qtbot import QtBot

from protocol.stage.codec import CommandFrame, CommandId, CommandPacket, decode
from tests.helpers.harness import StationHarness
from widgets.panels.absolute import AbsolutePanel
from widgets.panels.info import InfoPanel

MOVES = {CommandId.MOVE_ABS, CommandId.MOVE_REL, CommandId.HOME, CommandId.JOG}


class Panels(NamedTuple):
    panel: AbsolutePanel
    info: InfoPanel
    host: QWidget  # keeps the panels alive


# The offscreen platform warns whenever a shown window's layout sets its size limits.


@pytest.fixture
def panels(qtbot: QtBot, harness: StationHarness) -> Panels:
    info = InfoPanel(harness.station.model)
    panel = AbsolutePanel(harness.station)
    host = QWidget()
    layout = QVBoxLayout(host)
    layout.addWidget(info)
    layout.addWidget(panel)
    qtbot.addWidget(host)
    host.show()
    harness.connect()
    harness.run(1.5)
    return Panels(panel, info, host)


def test_go_x_to_20_reaches_the_target(
    qtbot: QtBot, harness: StationHarness, panels: Panels
) -> None:
    panel, info, _ = panels
    panel.targets[0].setValue(20.0)
    qtbot.mouseClick(panel.go_buttons[0], Qt.MouseButton.LeftButton)
    harness.run_until(lambda: info.statuses[0].text() == "target reached", timeout=5)
    assert info.positions[0].text() == "20.000 mm"
    assert info.positions[1].text() == "0.000 mm"
    assert harness.emulator.axes[0].position_um == pytest.approx(20_000, abs=1)


def test_go_all_moves_every_axis(qtbot: QtBot, harness: StationHarness, panels: Panels) -> None:
    panel, info, _ = panels
    panel.targets[0].setValue(5.5)
    panel.targets[1].setValue(7.25)
    qtbot.mouseClick(panel.go_all_button, Qt.MouseButton.LeftButton)
    harness.run_until(
        lambda: [s.text() for s in info.statuses] == ["target reached"] * 2, timeout=5
    )
    assert [p.text() for p in info.positions] == ["5.500 mm", "7.250 mm"]


def move_commands(harness: StationHarness, since: int) -> list[CommandPacket]:
    packets: list[CommandPacket] = []
    for raw in harness.written[since:]:
        _, frame = decode(raw)
        assert isinstance(frame, CommandFrame)
        packets += [p for p in frame.packets if p.command in MOVES]
    return packets


def type_into(qtbot: QtBot, box: QWidget, text: str) -> None:
    qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    qtbot.keyClick(box, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(box, text)


def test_80_typed_into_the_0_to_50_field_stays_80_is_invalid_and_moves_nothing(
    qtbot: QtBot, harness: StationHarness, panels: Panels
) -> None:
    """Symptom 7: typing 80 into a 0…50 mm field silently became 8, and the stage went to 8."""
    panel = panels.panel
    target = panel.targets[0]
    type_into(qtbot, target, "80")
    assert target.text() == "80"  # never turned into another number
    assert target.value() is None and not target.is_acceptable()
    assert "#d03030" in target.styleSheet()  # framed red while typed
    assert "0…50 mm" in target.toolTip() and "80 is outside" in target.toolTip()
    assert panel.note.isVisible() and "X target: 80 is outside 0…50 mm" in panel.note.text()
    assert not panel.go_buttons[0].isEnabled() and not panel.go_all_button.isEnabled()
    assert panel.go_buttons[1].isEnabled()  # Y's target is fine

    since = len(harness.written)
    qtbot.mouseClick(panel.go_buttons[0], Qt.MouseButton.LeftButton)
    qtbot.mouseClick(panel.go_all_button, Qt.MouseButton.LeftButton)
    qtbot.keyClick(target, Qt.Key.Key_Return)
    assert panel.go(0) is False  # a Go from anywhere else refuses too, and says why
    assert "Not sent" in panel.note.text() and "80 is outside" in panel.note.text()
    harness.run(1.0)
    assert move_commands(harness, since) == []
    assert not harness.station.model.any_moving
    assert harness.emulator.axes[0].position_um == 0

    qtbot.keyClick(target, Qt.Key.Key_Backspace)  # "8": in range again
    assert target.value() == 8.0 and target.styleSheet() == "" and not panel.note.isVisible()
    assert panel.go_buttons[0].isEnabled()


def test_a_target_set_from_code_is_not_clamped(panels: Panels) -> None:
    panel = panels.panel
    panel.targets[0].setValue(80.0)
    panel.targets[1].setValue(-3.0)
    assert [t.text() for t in panel.targets] == ["80.000", "-3.000"]
    assert [t.value() for t in panel.targets] == [None, None]
    assert panel.go(0) is False and panel.go(1) is False


@pytest.mark.parametrize(
    ("typed", "why"),
    [("12.3456", "At most 3 decimals"), ("-", "Not a number"), ("", "Empty")],
)
def test_malformed_targets_are_refused_with_the_reason(
    qtbot: QtBot, harness: StationHarness, panels: Panels, typed: str, why: str
) -> None:
    panel = panels.panel
    type_into(qtbot, panel.targets[1], typed)
    if not typed:
        qtbot.keyClick(panel.targets[1], Qt.Key.Key_Delete)
    assert panel.targets[1].text() == typed
    assert why in (panel.targets[1].problem() or "")
    since = len(harness.written)
    assert panel.go(1) is False
    harness.run(0.3)
    assert move_commands(harness, since) == []


def test_letters_are_refused_as_typed_and_up_steps_within_the_range(
    qtbot: QtBot, panels: Panels
) -> None:
    target = panels.panel.targets[0]
    type_into(qtbot, target, "4x9e")
    assert target.text() == "49"
    qtbot.keyClick(target, Qt.Key.Key_Up)
    assert target.value() == 50.0
    qtbot.keyClick(target, Qt.Key.Key_Up)
    assert target.value() == 50.0  # a step never leaves the range


def test_go_without_a_connection_is_refused(qtbot: QtBot, harness: StationHarness) -> None:
    panel = AbsolutePanel(harness.station)
    qtbot.addWidget(panel)
    assert panel.go(0) is False
