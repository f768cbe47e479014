"""FIDELITY S2-29: the drill has one sensor per axis, at home; its far ends are the frame.

The emulated drill now does what the mechanism would past the far end of the
travel (stall at the frame, steps lost, logged).  What keeps an operator from
getting there is the station's motion gate: every way a position reaches the
wire (the terminal, the Drill page's fields, a held jog, taps) is judged
against the profile's travel, which lies inside the frame.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from app.profiles import load_profile
from protocol.emulator.drill_firmware import StalledAtFrame
from tests.helpers.harness import StationHarness


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    harness.connect()
    harness.run_until(lambda: harness.drill_emulator.homed, timeout=10.0)  # power-on homing
    yield harness
    harness.close()


def _stalls(drill: StationHarness) -> list[StalledAtFrame]:
    return [e for e in drill.drill_emulator.event_log if isinstance(e, StalledAtFrame)]


def _idle(drill: StationHarness) -> None:
    drill.run_until(lambda: not drill.drill_session.busy, timeout=60.0)


def test_s2_29_the_profiles_travel_lies_inside_the_frame(drill: StationHarness) -> None:
    session = drill.drill_session
    config = drill.drill_emulator.config
    for axis in (0, 1):
        first, last = session.travel_microsteps(axis)
        assert first == 0 and last <= config.travel[axis]


def test_s2_29_no_way_through_the_station_runs_the_carriage_into_the_frame(
    drill: StationHarness,
) -> None:
    session = drill.drill_session
    said: list[str] = []
    drill.station.model.message.connect(said.append)
    before = len(drill.written)
    # The terminal: a raw X99999 would crash the real drill into its frame.
    assert not session.send_line("X99999")
    assert not session.send_line("Y4000")
    # The Drill page's absolute fields, past the far end.
    assert not session.move_absolute(0, 250.0)
    assert not session.move_absolute(1, 160.0)
    assert drill.written[before:] == []  # nothing of it reached the wire
    assert said  # and the operator was told why
    # A held jog towards the far corner stops at the end of the travel.
    session.set_jog((1, 1))
    drill.hold(12.0)
    session.set_jog((0, 0))
    _idle(drill)
    # Taps at the end go nowhere.
    assert not session.step_jog(0, 1, 5.0)
    _idle(drill)
    emulator = drill.drill_emulator
    x, y, _ = emulator.positions
    assert (x, y) == (session.travel_microsteps(0)[1], session.travel_microsteps(1)[1])
    assert _stalls(drill) == []
    # Where it stands, the carriage is where its counter says: no step was lost.
    config = emulator.config
    for index, axis in enumerate(emulator.axes[:2]):
        assert axis.physical_um == emulator.positions[index] + config.zero_offsets[index] + 1


def test_s2_29_a_raw_line_past_the_gate_would_stall_at_the_frame(drill: StationHarness) -> None:
    """What the gate prevents: a line past the travel straight to the emulated drill."""
    emulator = drill.drill_emulator
    emulator.receive(b"X4500\r")
    drill.run_until(lambda: bool(_stalls(drill)), timeout=10.0)
    (stall,) = _stalls(drill)
    far = emulator.config.travel[0]  # the station's emulated drill: the profile's travel
    assert (stall.axis, stall.end, stall.lost) == ("X", "far", 4500 - far)
