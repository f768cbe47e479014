"""The developer pane, driven as a developer would: typing, clicking, reading the log.

The station runs on the harness's manual clock; the only real-time waits are
``qtbot.waitUntil`` for the log view's batched redraw.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QCheckBox, QFileDialog, QLineEdit
from pytestqt.qtbot import QtBot

from app.developer.stage import AxisFields, EchoFields, inject_echo
from app.machine import LinkState
from app.profiles import load_profile
from protocol.stage.codec import AxisStatus
from tests.helpers.fake_transport import SilentPort
from tests.helpers.harness import StationHarness
from widgets.developer.pane import DeveloperPane
from widgets.number_field import NumberField

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def pane(qtbot: QtBot, harness: StationHarness) -> DeveloperPane:
    pane = DeveloperPane(harness.station)
    qtbot.addWidget(pane)
    pane.resize(1100, 600)
    pane.show()
    qtbot.waitExposed(pane)
    return pane


@pytest.fixture
def connected(harness: StationHarness, pane: DeveloperPane) -> StationHarness:
    harness.connect()
    harness.run(1.5)
    return harness


def _type(qtbot: QtBot, edit: QLineEdit, text: str) -> None:
    edit.selectAll()
    qtbot.keyClick(edit, Qt.Key.Key_Delete)
    qtbot.keyClicks(edit, text)


def _tick(qtbot: QtBot, box: QCheckBox) -> None:
    """Click the box itself: a check box stretched across a column ignores clicks past its text."""
    qtbot.mouseClick(box, LEFT, pos=QPoint(8, box.height() // 2))


def _enter_value(qtbot: QtBot, field: NumberField, text: str) -> None:
    field.setFocus()
    field.selectAll()
    qtbot.keyClicks(field, text)
    qtbot.keyClick(field, Qt.Key.Key_Return)


# --- the echo composer ---------------------------------------------------------------


def test_an_injected_charger_echo_shows_in_the_model(
    qtbot: QtBot, harness: StationHarness, pane: DeveloperPane
) -> None:
    composer = pane.composer
    qtbot.keyClicks(composer.status_combos[0], "9")  # keyboard search: "9 blocked: charger…"
    assert composer.status_combos[0].currentData() == AxisStatus.BLOCKED_CHARGER
    _type(qtbot, composer.data_edits[0], "12345")
    qtbot.mouseClick(composer.inject_button, LEFT)
    model = harness.station.model
    assert model.axes[0].position == 12.345
    assert model.axes[0].status_text == "blocked: charger connected"
    assert model.block_reason == "blocked: charger connected"
    assert composer.result_label.text().startswith("Injected <09012345")
    qtbot.waitUntil(lambda: "INJ" in pane.log_view.text)
    assert "X pos 12.345 mm blocked: charger connected" in pane.log_view.text


def test_enter_in_a_data_field_injects(
    qtbot: QtBot, harness: StationHarness, pane: DeveloperPane
) -> None:
    _type(qtbot, pane.composer.data_edits[1], "-2500")
    qtbot.keyClick(pane.composer.data_edits[1], Qt.Key.Key_Return)
    assert harness.station.model.axes[1].position == -2.5


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("12.5", "X DATA: '12.5' is not a whole number"),
        ("abc", "X DATA: 'abc' is not a whole number"),
        ("1000000", "X DATA: 1000000 is outside -99999…999999"),
    ],
)
def test_malformed_data_is_explained_and_nothing_injected(
    qtbot: QtBot, harness: StationHarness, pane: DeveloperPane, text: str, message: str
) -> None:
    composer = pane.composer
    qtbot.keyClicks(composer.status_combos[0], "9")
    _type(qtbot, composer.data_edits[0], text)
    with qtbot.assertNotEmitted(harness.station.echoInjected):
        qtbot.mouseClick(composer.inject_button, LEFT)
    assert composer.result_label.text() == message
    model = harness.station.model
    assert model.axes[0].position == 0.0 and model.axes[0].status_text == "unknown"
    assert model.block_reason is None
    assert len(pane.frame_log) == 0


def test_a_typed_unknown_subscriber_id_is_injected(
    qtbot: QtBot, harness: StationHarness, pane: DeveloperPane
) -> None:
    combo = pane.composer.subscriber_combo
    line = combo.lineEdit()
    assert line is not None
    _type(qtbot, line, "3c")
    with qtbot.waitSignal(harness.station.echoInjected) as injected:
        qtbot.mouseClick(pane.composer.inject_button, LEFT)
    assert injected.args[0].subscriber == 0x3C


# --- the frame log ------------------------------------------------------------------


def test_the_log_shows_sent_frames_and_received_echoes(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    connected.session.set_jog([1, 0])
    connected.run(0.5)
    qtbot.waitUntil(lambda: "JOG +1" in pane.log_view.text)
    lines = pane.log_view.text.splitlines()
    assert any("  TX   >02" in line and "X JOG +1 | Y NOP" in line for line in lines)
    assert any(
        "  RX   <01" in line and "X pos" in line and "accelerating" in line for line in lines
    )
    # The count is shown on the view's throttled refresh, which may trail the log by a frame.
    qtbot.waitUntil(lambda: pane.log_view.status_label.text() == f"{len(pane.frame_log)} entries")


def test_the_filter_keeps_matching_lines(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    pane.emulator_box.corrupt_count.setValue(2)
    qtbot.mouseClick(pane.emulator_box.corrupt_button, LEFT)
    connected.run(0.5)
    qtbot.keyClicks(pane.log_view.filter_edit, "bad")
    qtbot.waitUntil(lambda: len(pane.log_view.text.splitlines()) == 2)
    assert all("rejected: checksum mismatch" in line for line in pane.log_view.text.splitlines())
    connected.run(0.3)  # new frames pass through the same filter
    pane.log_view.flush()
    assert len(pane.log_view.text.splitlines()) == 2
    pane.log_view.filter_edit.clear()
    qtbot.waitUntil(lambda: len(pane.log_view.text.splitlines()) == len(pane.frame_log))


def test_pause_freezes_the_view_and_resume_catches_up(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    view = pane.log_view
    qtbot.waitUntil(lambda: len(view.text.splitlines()) == len(pane.frame_log))
    qtbot.mouseClick(view.pause_button, LEFT)
    assert pane.frame_log.paused and view.pause_button.text() == "Resume"
    frozen = view.text
    connected.run(0.5)
    qtbot.waitUntil(lambda: "paused, 10 new not shown" in view.status_label.text())
    assert view.text == frozen
    qtbot.mouseClick(view.pause_button, LEFT)
    assert not pane.frame_log.paused and view.pause_button.text() == "Pause"
    qtbot.waitUntil(lambda: len(view.text.splitlines()) == len(pane.frame_log))
    assert view.text.startswith(frozen)


def test_a_filter_typed_while_paused_filters_the_frozen_view(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    view = pane.log_view
    qtbot.waitUntil(lambda: len(view.text.splitlines()) == len(pane.frame_log))
    qtbot.mouseClick(view.pause_button, LEFT)
    frozen = view.text.splitlines()
    connected.run(0.5)
    qtbot.keyClicks(view.filter_edit, "tx")
    qtbot.waitUntil(lambda: view.text.splitlines() == [x for x in frozen if "  TX  " in x])
    qtbot.mouseClick(view.pause_button, LEFT)
    tx = [e.line for e in pane.frame_log.entries if e.direction == "TX"]
    qtbot.waitUntil(lambda: view.text.splitlines() == tx)


def test_a_burst_is_drawn_in_one_batch(
    qtbot: QtBot, harness: StationHarness, pane: DeveloperPane, monkeypatch: pytest.MonkeyPatch
) -> None:
    view = pane.log_view
    view.flush()  # the first redraw after showing rebuilds the view; bursts are appended
    appends: list[str] = []
    monkeypatch.setattr(view.view, "appendPlainText", lambda text: appends.append(text))
    for position in range(1000):  # what a 1 kHz stream delivers in a second
        inject_echo(harness.station, EchoFields([AxisFields(data=position), AxisFields()]))
    qtbot.waitUntil(lambda: bool(appends))
    assert len(appends) == 1 and len(appends[0].splitlines()) == 1000


def test_entries_pushed_out_while_paused_are_reported(
    qtbot: QtBot, harness: StationHarness
) -> None:
    pane = DeveloperPane(harness.station, log_capacity=20)
    qtbot.addWidget(pane)
    pane.show()
    harness.connect()
    harness.run(0.3)
    shown = len(pane.frame_log)
    assert shown < 20
    qtbot.waitUntil(lambda: len(pane.log_view.text.splitlines()) == shown)
    qtbot.mouseClick(pane.log_view.pause_button, LEFT)
    harness.run(2.0)  # 40 more entries: 20 fall out of the log before they are shown
    lost = pane.frame_log.entries[0].seq - shown - 1
    assert lost > 0
    qtbot.mouseClick(pane.log_view.pause_button, LEFT)
    qtbot.waitUntil(lambda: "not shown" in pane.log_view.text)
    lines = pane.log_view.text.splitlines()
    assert lines[shown] == f"… {lost} entries not shown: the log keeps the last 20"
    assert lines[shown + 1 :] == [entry.line for entry in pane.frame_log.entries]


def test_clear_empties_log_and_view(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    qtbot.waitUntil(lambda: bool(pane.log_view.text))
    qtbot.mouseClick(pane.log_view.clear_button, LEFT)
    assert pane.log_view.text == "" and len(pane.frame_log) == 0
    connected.run(0.2)
    qtbot.waitUntil(lambda: len(pane.log_view.text.splitlines()) == len(pane.frame_log) > 0)


def test_save_writes_the_entries(
    qtbot: QtBot,
    tmp_path: Path,
    connected: StationHarness,
    pane: DeveloperPane,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    target = tmp_path / "frames.log"
    monkeypatch.setattr(
        QFileDialog, "getSaveFileName", staticmethod(lambda *args: (str(target), ""))
    )
    connected.session.set_jog([1, 0])
    connected.run(0.3)
    qtbot.mouseClick(pane.log_view.save_button, LEFT)
    lines = target.read_text(encoding="utf-8").splitlines()
    assert lines[2:] == [entry.line for entry in pane.frame_log.entries]
    assert any("JOG +1" in line for line in lines)
    assert pane.log_view.status_label.text() == f"Saved {len(lines) - 2} entries to {target}"


# --- emulator controls ------------------------------------------------------------------


def test_emulator_controls_wait_for_an_emulator(
    harness: StationHarness, pane: DeveloperPane
) -> None:
    box = pane.emulator_box
    assert not box.body.isEnabled() and box.note.isVisible()
    assert box.note.text().startswith("No emulator connected")  # the line itself, not a blank
    assert not box.field_note.isVisible()  # the fields' note says nothing until one is wrong
    harness.connect()
    assert box.body.isEnabled() and not box.note.isVisible()
    assert box.battery.value() == 80 and box.temperature.value() == 25.0
    harness.station.close_link()
    assert not box.body.isEnabled() and box.note.isVisible()
    assert box.note.text().startswith("No emulator connected")


def test_a_wrong_value_is_named_under_the_fields_not_in_the_no_emulator_line(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    box = pane.emulator_box
    box.corrupt_count.setFocus()
    box.corrupt_count.selectAll()
    qtbot.keyClicks(box.corrupt_count, "0")
    qtbot.waitUntil(box.field_note.isVisible)
    assert "Corrupt" in box.field_note.text() and not box.note.isVisible()
    assert box.body.isAncestorOf(box.field_note) and not box.body.isAncestorOf(box.note)


def test_the_charger_blocks_the_machine(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    _tick(qtbot, pane.emulator_box.charger)
    assert connected.emulator.charger_connected
    connected.run(0.3)
    model = connected.station.model
    assert model.block_reason == "blocked: charger connected"
    assert model.motion_lock_reason() == "blocked: charger connected"
    _tick(qtbot, pane.emulator_box.charger)
    connected.run(0.3)
    assert model.motion_lock_reason() is None


def test_usb_and_verification_fault_reach_the_emulator(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    _tick(qtbot, pane.emulator_box.usb)
    _tick(qtbot, pane.emulator_box.verification_fault)
    assert connected.emulator.usb_connected and connected.emulator.verification_fault
    connected.run(0.3)
    assert connected.station.model.block_reason == "blocked: USB connected"


def test_typed_battery_temperature_and_rotation_reach_the_emulator(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    box = pane.emulator_box
    _enter_value(qtbot, box.battery, "45")
    _enter_value(qtbot, box.temperature, "38.5")
    _enter_value(qtbot, box.rotation, "10")
    emulator = connected.emulator
    assert emulator.battery_charge == 45.0
    assert emulator.board_temperature_c == 38.5
    assert emulator.rotation_rate_dps == 10.0
    connected.run(1.0)
    assert emulator.yaw_deg == pytest.approx(10.0, abs=0.01)


def test_an_out_of_range_battery_is_shown_invalid_and_not_applied(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    box = pane.emulator_box
    _enter_value(qtbot, box.battery, "150")  # a spin box made this 15
    assert box.battery.text() == "150" and box.battery.value() is None
    assert "Battery: 150 is outside 0…100 %" in box.field_note.text()
    assert connected.emulator.battery_charge != 15.0 and connected.emulator.battery_charge <= 100
    _enter_value(qtbot, box.corrupt_count, "0")
    assert not box.corrupt_button.isEnabled()


def test_an_end_switch_button_stops_the_axis(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    connected.session.move_absolute(0, 40.0)
    connected.run(0.5)
    qtbot.mouseClick(pane.emulator_box.switch_buttons[(0, "high")], LEFT)
    connected.run(0.2)
    axis = connected.station.model.axes[0]
    assert axis.status_text == "end switch hit" and not axis.moving


def test_a_driver_fault_checkbox_faults_that_axis(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    _tick(qtbot, pane.emulator_box.driver_faults[1])
    assert (
        connected.emulator.snapshot().driver_faults[1]
        and not connected.emulator.snapshot().driver_faults[0]
    )
    connected.run(0.3)
    assert connected.station.model.axes[1].status_text == "driver fault"


def test_drop_link_loses_the_link_and_the_station_gets_it_back(
    qtbot: QtBot, connected: StationHarness, pane: DeveloperPane
) -> None:
    model = connected.station.model
    qtbot.mouseClick(pane.emulator_box.drop_button, LEFT)
    assert model.link_state is LinkState.LOST
    assert pane.emulator_box.body.isEnabled()  # still the emulator, behind a cut cable
    connected.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=2)


def test_corrupt_three_frames(qtbot: QtBot, connected: StationHarness, pane: DeveloperPane) -> None:
    decoder = connected.session.decoder
    before = decoder.rejected
    box = pane.emulator_box
    assert box.corrupt_count.value() == 3
    qtbot.mouseClick(box.corrupt_button, LEFT)
    connected.run(1.0)
    assert decoder.rejected == before + 3
    qtbot.waitUntil(lambda: pane.log_view.text.count("  BAD  ") == 3)


# --- simulation -----------------------------------------------------------------------


def test_simulation_answers_a_held_jog(
    qtbot: QtBot, harness: StationHarness, pane: DeveloperPane
) -> None:
    assert not pane.simulation.isChecked()
    _tick(qtbot, pane.simulation)
    assert harness.station.emulator is not None and harness.station.session is not None
    assert pane.simulation.isChecked() and pane.emulator_box.body.isEnabled()
    model = harness.station.model
    harness.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=1)
    harness.run(1.0)
    harness.session.set_jog([1, 0])
    harness.run(1.0)
    emulated = harness.emulator.axes[0].position_um / 1000
    assert emulated > 1.0
    assert model.axes[0].position == pytest.approx(emulated, abs=0.2)
    harness.session.set_jog([0, 0])
    _tick(qtbot, pane.simulation)
    assert harness.station.session is None and model.link_state is LinkState.DISCONNECTED
    assert not pane.emulator_box.body.isEnabled()


def test_simulation_is_refused_while_a_real_device_is_connected(
    qtbot: QtBot, harness: StationHarness, pane: DeveloperPane
) -> None:
    harness.station.connect_transport(SilentPort())
    _tick(qtbot, pane.simulation)
    assert not pane.simulation.isChecked()
    assert pane.simulation_note.isVisible()
    assert pane.simulation_note.text() == (
        "Simulation refused: /dev/ttyUSB0 @ 115200 is connected: disconnect it first"
    )
    assert harness.station.emulator is None and harness.station.link is not None
    harness.station.close_link()
    _tick(qtbot, pane.simulation)
    assert pane.simulation.isChecked() and not pane.simulation_note.isVisible()


def test_the_checkbox_follows_a_connection_made_elsewhere(
    harness: StationHarness, pane: DeveloperPane
) -> None:
    harness.connect()  # e.g. from the Link page
    assert pane.simulation.isChecked()
    harness.station.close_link()
    assert not pane.simulation.isChecked()


def test_usb3_joystick_sliders_drive_the_unit_and_spring_back(qtbot: QtBot) -> None:
    usb3 = StationHarness(load_profile("usb3"))
    try:
        usb3.connect()
        pane = DeveloperPane(usb3.station)
        qtbot.addWidget(pane)
        pane.show()
        assert pane.joystick_box.isVisible() and not pane.composer.isVisible()
        assert pane.joystick_box.isEnabled()
        # The connect asks each axis where it stands (a move of nothing); a stick pushed
        # within 0.25 s of the answers is stopped as a question run as a move (safe, and
        # said: app/machines/usb3/question_hold.py), so the operator's push comes after.
        usb3.run(0.5)
        x = pane.joystick_box.sliders[0]
        x.setValue(1023)  # full deflection: the X motor runs forwards
        usb3.run(1.0)
        assert usb3.usb3_emulator.moving(0)
        assert usb3.station.model.axes[0].position > 0
        x.sliderReleased.emit()  # the operator lets go: the stick centres
        assert x.value() == 512
        usb3.run(1.0)
        assert not usb3.usb3_emulator.moving(0)
        assert not usb3.usb3_emulator.moving(1)
    finally:
        usb3.close()


def test_s4_18_a_usb3_end_switch_closed_from_the_pane_stops_the_move_and_is_named(
    qtbot: QtBot,
) -> None:
    usb3 = StationHarness(load_profile("usb3"))
    try:
        usb3.connect()
        pane = DeveloperPane(usb3.station)
        qtbot.addWidget(pane)
        pane.show()
        said: list[str] = []
        usb3.station.model.message.connect(said.append)
        assert usb3.usb3_session.move_relative(0, 0.5)
        usb3.run(1.0)
        assert usb3.usb3_emulator.moving(0)
        qtbot.mouseClick(pane.joystick_box.switch_buttons[(0, "high")], Qt.MouseButton.LeftButton)
        usb3.run(1.0)
        assert not usb3.usb3_emulator.moving(0)
        assert any(m.startswith("X stopped at its high end switch at ") for m in said)
    finally:
        usb3.close()
