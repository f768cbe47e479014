""" "Connected" only once the device has answered in the profile's dialect.

A port that opens proves a cable, not a machine: until the first valid reply
the station says it is waiting and keeps motion locked; after a few seconds
of silence, or of another dialect's replies, it says which machine it sounds
like instead.
"""

from __future__ import annotations

import pytest

from app.machine import LinkState
from app.machines.registry import dialect_for
from app.machines.session import ANSWER_WAIT_S
from app.profiles import load_profile
from protocol.transport.loopback import Direction, LoopbackTransport
from tests.helpers.harness import StationHarness

PROFILES = {"stage": "xy-stage", "usb3": "usb3", "drill": "pcb-drill", "gcode": "grbl-plotter"}


@pytest.mark.parametrize("dialect", sorted(PROFILES))
def test_a_device_that_answers_is_connected_and_a_silent_one_never_is(dialect: str) -> None:
    unit = StationHarness(load_profile(PROFILES[dialect]))
    messages: list[str] = []
    unit.station.model.message.connect(messages.append)
    try:
        unit.connect(wait_for_answer=False)
        model = unit.station.model
        assert model.link_state is LinkState.CONNECTING
        assert "waiting for the device" in model.link_detail
        assert model.motion_lock_reason() == "not connected"
        unit.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=2.0)

        unit.station.close_link()
        unit.connect(wait_for_answer=False)

        def mute(direction: Direction, data: bytes) -> bytes:
            return b"" if direction is Direction.TO_HOST else data

        unit.loopback.set_manipulator(mute)
        unit.run(ANSWER_WAIT_S + 1.0)
        assert model.link_state is LinkState.CONNECTING  # never "connected", motion locked
        assert model.motion_lock_reason() == "not connected"
        title = unit.station.profile.title
        assert f"no answer: is this a {title}?" in model.link_detail
        assert sum("no answer" in m for m in messages) == 1  # said once, not every tick
    finally:
        unit.close()


@pytest.mark.parametrize(
    ("profile", "other", "sounds"),
    [
        ("xy-stage", "grbl-plotter", "a G-code board"),
        ("usb3", "grbl-plotter", "a G-code board"),
        ("grbl-plotter", "xy-stage", None),  # a stage answers nothing it cannot parse
    ],
)
def test_a_machine_of_another_kind_is_named_and_never_connected(
    profile: str, other: str, sounds: str | None
) -> None:
    """The README's --port example once sent G-code to the XY stage, shown as connected."""
    unit = StationHarness(load_profile(profile))
    try:
        station = unit.station
        wrong = dialect_for(load_profile(other)).emulator(unit.clock, load_profile(other))
        station.connect_transport(LoopbackTransport(wrong, unit.clock, realtime=False))
        unit.run(ANSWER_WAIT_S + 1.0)
        assert station.model.link_state is LinkState.CONNECTING
        assert station.model.motion_lock_reason() == "not connected"
        detail = station.model.link_detail
        assert f"no answer: is this a {station.profile.title}?" in detail
        if sounds is None:
            assert "sound like" not in detail
        else:
            assert f"its replies sound like {sounds}" in detail
    finally:
        unit.close()
