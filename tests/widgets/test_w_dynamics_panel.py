"""Dynamics panel: parameters read into fields, edited values written and confirmed or refused."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel
from pytestqt.qtbot import QtBot

from app.machine import ParameterState
from app.machines.stage.parameters import STAGE_PARAMETERS
from protocol.stage.codec import CommandFrame, CommandId, EchoType, decode
from tests.helpers.harness import StationHarness
from widgets.number_field import NumberField
from widgets.panels.dynamics import DynamicsPanel

# The offscreen platform warns whenever a shown window's layout sets its size limits.

X, Y = 0, 1
ACCELERATION = int(EchoType.ACCELERATION)


@pytest.fixture
def panel(qtbot: QtBot, harness: StationHarness) -> DynamicsPanel:
    panel = DynamicsPanel(harness.station)
    qtbot.addWidget(panel)
    panel.show()
    harness.connect()
    harness.run(2.5)  # the session reads every parameter after connecting
    return panel


def field(panel: DynamicsPanel, axis: int, parameter: EchoType) -> NumberField:
    return panel.fields[(axis, int(parameter))]


def state(panel: DynamicsPanel, axis: int, parameter: EchoType) -> QLabel:
    return panel.states[(axis, int(parameter))]


def apply(qtbot: QtBot, panel: DynamicsPanel) -> None:
    qtbot.mouseClick(panel.apply_button, Qt.MouseButton.LeftButton)


def written_commands(harness: StationHarness, since: int) -> list[int]:
    commands = []
    for raw in harness.written[since:]:
        _, frame = decode(raw)
        assert isinstance(frame, CommandFrame)
        commands += [packet.command for packet in frame.packets]
    return commands


def test_every_parameter_of_every_axis_has_a_field(panel: DynamicsPanel) -> None:
    assert len(panel.fields) == 2 * len(STAGE_PARAMETERS)


def test_fields_show_the_device_values_in_display_units(panel: DynamicsPanel) -> None:
    assert field(panel, X, EchoType.FAST_SPEED).value() == pytest.approx(10.0)
    assert field(panel, Y, EchoType.ACCELERATION).value() == pytest.approx(20.0)
    assert field(panel, X, EchoType.MICROSTEPS).value() == 16
    assert field(panel, X, EchoType.TRAVEL).value() == pytest.approx(50.0)
    assert field(panel, X, EchoType.ENCODER).isReadOnly()


def test_acceleration_applied_is_stored_and_confirmed(
    qtbot: QtBot, harness: StationHarness, panel: DynamicsPanel
) -> None:
    # 20 mm/s² is the stage's default, so go to 30 first and then back to 20.
    for shown, wire in ((30.0, 30_000), (20.0, 20_000)):
        field(panel, X, EchoType.ACCELERATION).setValue(shown)
        assert state(panel, X, EchoType.ACCELERATION).text() == "• edited"
        apply(qtbot, panel)
        harness.run_until(
            lambda: state(panel, X, EchoType.ACCELERATION).text() == "✓ confirmed", timeout=1
        )
        assert harness.emulator.parameter(X, EchoType.ACCELERATION) == wire
        assert harness.emulator.fram.read(X, EchoType.ACCELERATION) == wire
        assert harness.emulator.parameter(Y, EchoType.ACCELERATION) == 20_000  # untouched
    assert "#2e9e44" in state(panel, X, EchoType.ACCELERATION).styleSheet()  # green


def test_apply_writes_only_edited_values(
    qtbot: QtBot, harness: StationHarness, panel: DynamicsPanel
) -> None:
    field(panel, Y, EchoType.SLOW_SPEED).setValue(3.5)
    since = len(harness.written)
    apply(qtbot, panel)
    writes = [c for c in written_commands(harness, since) if c >= CommandId.WRITE_FAST_SPEED]
    assert writes == [CommandId.WRITE_SLOW_SPEED]
    harness.run(0.5)
    assert harness.emulator.parameter(Y, EchoType.SLOW_SPEED) == 3_500
    assert harness.emulator.parameter(X, EchoType.SLOW_SPEED) == 2_000

    since = len(harness.written)
    apply(qtbot, panel)  # nothing edited since
    assert panel.summary.text() == "Nothing changed"
    assert not [c for c in written_commands(harness, since) if c >= CommandId.WRITE_FAST_SPEED]


def test_a_refused_write_shows_the_value_the_device_kept(
    qtbot: QtBot, harness: StationHarness, panel: DynamicsPanel
) -> None:
    harness.emulator.verification_fault = True
    field(panel, X, EchoType.ACCELERATION).setValue(25.0)
    apply(qtbot, panel)
    label = state(panel, X, EchoType.ACCELERATION)
    harness.run_until(lambda: label.text().startswith("✗"), timeout=1)
    assert label.text() == "✗ refused, kept 20.000"
    assert "#d03030" in label.styleSheet()
    assert field(panel, X, EchoType.ACCELERATION).value() == pytest.approx(20.0)
    entry = harness.station.model.parameter(X, ACCELERATION)
    assert entry.state is ParameterState.REFUSED
    assert harness.emulator.parameter(X, EchoType.ACCELERATION) == 20_000


def test_locally_invalid_values_are_not_sent(
    qtbot: QtBot, harness: StationHarness, panel: DynamicsPanel
) -> None:
    field(panel, X, EchoType.MICROSTEPS).setValue(12)
    since = len(harness.written)
    apply(qtbot, panel)
    assert CommandId.WRITE_MICROSTEPS not in written_commands(harness, since)
    assert state(panel, X, EchoType.MICROSTEPS).text() == "✗ not sent"
    assert "power of two" in state(panel, X, EchoType.MICROSTEPS).toolTip()
    assert "power of two" in panel.summary.text()
    harness.run(0.3)
    assert harness.emulator.parameter(X, EchoType.MICROSTEPS) == 16


def test_read_fills_the_fields_from_the_device(
    qtbot: QtBot, harness: StationHarness, panel: DynamicsPanel
) -> None:
    harness.emulator.fram.write(Y, EchoType.FAST_SPEED, 12_345)
    field(panel, Y, EchoType.FAST_SPEED).setValue(99.0)  # an edit that Read throws away
    qtbot.mouseClick(panel.read_button, Qt.MouseButton.LeftButton)
    harness.run(2.5)
    assert field(panel, Y, EchoType.FAST_SPEED).value() == pytest.approx(12.345)
    assert state(panel, Y, EchoType.FAST_SPEED).text() == ""


def test_read_and_apply_need_a_link(qtbot: QtBot, harness: StationHarness) -> None:
    panel = DynamicsPanel(harness.station)
    qtbot.addWidget(panel)
    assert not panel.apply_button.isEnabled()
    harness.connect()
    assert panel.apply_button.isEnabled() and panel.read_button.isEnabled()


def type_into(qtbot: QtBot, box: NumberField, text: str) -> None:
    qtbot.mouseClick(box, Qt.MouseButton.LeftButton)
    qtbot.keyClick(box, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClicks(box, text)


def test_travel_beyond_the_mechanical_travel_is_shown_invalid_and_not_written(
    qtbot: QtBot, harness: StationHarness, panel: DynamicsPanel
) -> None:
    """Symptom 4: 999.999 mm of travel on a 50 mm stage went out without a word."""
    travel = field(panel, X, EchoType.TRAVEL)
    type_into(qtbot, travel, "999.999")
    assert travel.text() == "999.999"  # kept as typed, not cut to another number
    assert travel.value() is None
    assert "outside 0.001…50 mm" in (travel.problem() or "")
    assert "mechanical travel, 50 mm" in travel.toolTip()
    assert "#d03030" in travel.styleSheet()
    since = len(harness.written)
    apply(qtbot, panel)
    assert CommandId.WRITE_TRAVEL not in written_commands(harness, since)
    assert state(panel, X, EchoType.TRAVEL).text() == "✗ not sent"
    assert "outside 0.001…50 mm" in panel.summary.text()
    harness.run(0.3)
    assert harness.emulator.parameter(X, EchoType.TRAVEL) == 50_000

    type_into(qtbot, travel, "40")
    assert travel.value() == 40.0 and travel.styleSheet() == ""
    apply(qtbot, panel)
    harness.run_until(lambda: state(panel, X, EchoType.TRAVEL).text() == "✓ confirmed", 1)
    assert harness.emulator.parameter(X, EchoType.TRAVEL) == 40_000


def test_the_session_refuses_a_travel_beyond_the_mechanics_whoever_asks(
    harness: StationHarness, panel: DynamicsPanel
) -> None:
    messages: list[str] = []
    harness.station.model.message.connect(messages.append)
    since = len(harness.written)
    assert harness.session.write_parameter(Y, EchoType.TRAVEL, 999_999) is False
    assert CommandId.WRITE_TRAVEL not in written_commands(harness, since)
    assert messages == [
        "Not written: Y Travel (soft limit) must not exceed the mechanical travel, 50 mm"
    ]


def test_s3_18_current_scales_show_the_rms_current_as_typed(panel: DynamicsPanel) -> None:
    """IRMS = (CS+1)/32 · 0.32 V/(0.11 Ω + 20 mΩ)/√2 (the xy-stage profile's [driver])."""
    irun, ihold = field(panel, X, EchoType.IRUN), field(panel, X, EchoType.IHOLD)
    assert irun.value() == 16 and irun.note() == "= 925 mA"  # 17/32 · 1.7406 A
    assert ihold.value() == 8 and ihold.note() == "= 490 mA"  # 9/32 · 1.7406 A
    irun.setText("31")
    assert irun.note() == "= 1.74 A"
    irun.setText("40")  # not a current scale: nothing to tell
    assert irun.note() == ""
    assert "VFS 0.32 V, Rsense 0.11 Ω" in irun.toolTip()


def test_s3_28_speeds_show_what_the_step_timer_really_runs(panel: DynamicsPanel) -> None:
    fast = field(panel, X, EchoType.FAST_SPEED)
    assert fast.value() == 10.0 and fast.note() == ""  # 2500 ticks: exact
    field(panel, X, EchoType.MICROSTEPS).setText("256")
    assert fast.note() == "→ 10.016"  # 156.25 ticks, 156 run
    fast.setText("50")
    assert fast.note() == "→ 50.403"  # 31.25 ticks, 31 run
    assert field(panel, Y, EchoType.FAST_SPEED).note() == ""  # Y keeps 16 microsteps
