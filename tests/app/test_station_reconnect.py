"""Losing and regaining the link: back-off, re-reading the device, no resent jog."""

from __future__ import annotations

import itertools

import pytest

from app.machine import LinkState, ParameterState
from protocol.stage.codec import PARAMETERS, CommandFrame, CommandId, decode
from tests.helpers.fake_transport import SilentPort
from tests.helpers.harness import StationHarness


@pytest.fixture
def harness(harness: StationHarness) -> StationHarness:
    """The shared harness, connected."""
    harness.connect()
    return harness


def _commands_since(harness: StationHarness, start: int) -> list[tuple[int, int]]:
    out = []
    for raw in harness.written[start:]:
        _, frame = decode(raw)
        assert isinstance(frame, CommandFrame)
        out.extend((p.command, p.data) for p in frame.packets)
    return out


def test_a_dropped_link_is_reopened_after_the_back_off_and_the_device_re_read(
    harness: StationHarness,
) -> None:
    harness.run(3.0)
    model = harness.station.model
    for axis in range(2):
        for parameter in PARAMETERS:
            model.set_parameter(axis, parameter, None, ParameterState.UNKNOWN)
    harness.loopback.sever("cable pulled")
    assert model.link_state is LinkState.LOST
    assert "retrying in 0.5 s" in model.link_detail
    waited = harness.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=2)
    assert waited == pytest.approx(0.5, abs=0.011)
    harness.run(3.0)
    assert all(
        model.parameter(axis, p).state is ParameterState.READ
        for axis in range(2)
        for p in PARAMETERS
    )


def test_a_jog_held_before_the_loss_is_not_resent(harness: StationHarness) -> None:
    harness.run(3.0)
    harness.session.set_jog([1, 0])
    harness.run(0.5)
    harness.loopback.sever("cable pulled")
    start = len(harness.written)
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED)
    harness.run(1.0)
    sent = _commands_since(harness, start)
    assert sent, "nothing was sent after reconnecting"
    assert (CommandId.JOG, 1) not in sent
    # The device's watchdog stopped the jog while the station was away.
    assert not harness.emulator.axes[0].moving


def test_failed_reopens_back_off_longer_each_time(harness: StationHarness) -> None:
    harness.station.close_link()
    transport = SilentPort("flaky port", failures=3)
    harness.station.connect_transport(transport)
    model = harness.station.model
    times = []
    last = 0
    while transport.opens < 4:
        harness.step()
        if transport.opens != last:
            last = transport.opens
            times.append(harness.clock.now())
    gaps = [round(b - a, 2) for a, b in itertools.pairwise(times)]
    assert gaps == [0.5, 1.0, 2.0]
    # Open at last, but a silent port proves no device: waiting for one, motion locked.
    assert model.link_state is LinkState.CONNECTING
    assert model.motion_lock_reason() == "not connected"
    harness.station.close_link()
    assert harness.station.reconnect_due is None


def test_closing_on_purpose_does_not_reconnect(harness: StationHarness) -> None:
    harness.run(1.0)
    harness.station.close_link()
    harness.run(6.0)
    assert harness.station.model.link_state is LinkState.DISCONNECTED
    assert harness.station.link is None
