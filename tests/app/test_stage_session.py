"""The stage session against the emulator on a test clock: pacing, subscribers, health, reads."""

from __future__ import annotations

import pytest

from app.machine import LinkState, ParameterState
from app.machines.stage.session import INFO_SUBSCRIBERS, SubscriberScheduler
from protocol.stage.codec import (
    PARAMETERS,
    CommandFrame,
    CommandId,
    EchoType,
    Subscriber,
    decode,
)
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness


@pytest.fixture
def harness(harness: StationHarness) -> StationHarness:
    """The shared harness, connected."""
    harness.connect()
    return harness


def _frames(raw: list[bytes]) -> list[CommandFrame]:
    frames = []
    for chunk in raw:
        _, frame = decode(chunk)
        assert isinstance(frame, CommandFrame)
        frames.append(frame)
    return frames


def test_connect_reads_every_parameter_of_every_axis(harness: StationHarness) -> None:
    harness.run(3.0)
    for axis in range(2):
        for parameter in PARAMETERS:
            entry = harness.station.model.parameter(axis, parameter)
            assert entry.state is ParameterState.READ, (axis, parameter)
            assert entry.value == harness.emulator.parameter(axis, parameter)


def test_positions_keep_updating_while_parameters_are_read(harness: StationHarness) -> None:
    # Right after connect the reads are running; a move started now must still be followed.
    harness.session.move_absolute(0, 5.0)
    seen: list[float] = []
    harness.station.model.axisChanged.connect(
        lambda i: seen.append(harness.station.model.axes[0].position) if i == 0 else None
    )
    harness.run(1.0)
    assert len(set(seen)) >= 5


def test_intent_change_sends_a_frame_at_once_without_a_tick(harness: StationHarness) -> None:
    harness.run(1.0)
    before = len(harness.written)
    harness.session.set_jog([1, 1])  # no step: no tick, no emulated time
    sent = _frames(harness.written[before:])
    assert sent, "the jog did not reach the transport"
    assert [(p.command, p.data) for p in sent[-1].packets] == [
        (CommandId.JOG, 1),
        (CommandId.JOG, 1),
    ]
    before = len(harness.written)
    harness.session.set_jog([0, 0])
    released = _frames(harness.written[before:])
    assert [(p.command, p.data) for p in released[-1].packets] == [
        (CommandId.JOG, 0),
        (CommandId.JOG, 0),
    ]


def test_held_jog_repeats_every_period_and_release_is_repeated_then_nop(
    harness: StationHarness,
) -> None:
    harness.run(3.0)  # let the connect-time reads finish
    harness.session.set_jog([1, 0])
    start = len(harness.written)
    harness.run(1.0)
    held = _frames(harness.written[start:])
    assert len(held) == 10  # one per 100 ms period
    assert all(f.packets[0].command == CommandId.JOG and f.packets[0].data == 1 for f in held)
    start = len(harness.written)
    harness.session.set_jog([0, 0])  # the first JOG 0 goes out at once, two more follow
    harness.run(0.5)
    after = [f.packets[0] for f in _frames(harness.written[start:])]
    assert [(p.command, p.data) for p in after[:3]] == [(CommandId.JOG, 0)] * 3
    assert all(p.command == CommandId.NOP for p in after[3:])


def test_shift_switches_speed_before_the_jog_in_the_same_burst(harness: StationHarness) -> None:
    harness.run(3.0)
    assert harness.emulator.snapshot().fast[0]
    start = len(harness.written)
    harness.session.set_shift(True)
    harness.session.set_jog([1, 0])
    frames = _frames(harness.written[start:])
    commands = [p.command for f in frames for p in f.packets[:1]]
    assert commands.index(CommandId.SPEED) < commands.index(CommandId.JOG)
    harness.run(0.05)
    assert not harness.emulator.snapshot().fast[0]
    harness.hold(2.0)
    slow = harness.emulator.parameter(0, EchoType.SLOW_SPEED)
    assert harness.station.model.axes[0].velocity == pytest.approx(slow / 1000, rel=0.05)


def test_info_variables_are_asked_at_least_once_a_second_with_a_plotted_variable(
    harness: StationHarness,
) -> None:
    harness.session.set_plotted_subscriber(Subscriber.ROTATION)
    start = len(harness.written)
    harness.run(3.0)
    frames = _frames(harness.written[start:])
    subscribers = [f.subscriber for f in frames]
    for info in INFO_SUBSCRIBERS:
        gaps = [i for i, s in enumerate(subscribers) if s == info]
        assert gaps, info
        assert max(b - a for a, b in zip([0, *gaps], [*gaps, len(subscribers)], strict=True)) <= 10
    assert subscribers.count(Subscriber.ROTATION) >= len(subscribers) // 3


def test_scheduler_without_plot_cycles_through_info_values() -> None:
    scheduler = SubscriberScheduler(0.1)
    picks = [scheduler.next(i * 0.1) for i in range(20)]
    assert set(picks) == set(INFO_SUBSCRIBERS)


def test_telemetry_reaches_the_model_in_display_units(harness: StationHarness) -> None:
    harness.emulator.board_temperature_c = 31.25
    harness.run(2.0)
    model = harness.station.model
    assert model.telemetry["board_temperature"] == pytest.approx(31.25)
    assert 3.3 <= model.telemetry["battery_voltage"] <= 4.2
    assert model.telemetry["battery_charge"] == pytest.approx(
        harness.emulator.battery_charge, abs=1
    )


def test_silence_makes_the_link_stale_then_lost_and_replies_restore_it(
    harness: StationHarness,
) -> None:
    harness.run(1.0)
    harness.loopback.set_manipulator(lambda d, data: b"" if d is Direction.TO_HOST else data)
    model = harness.station.model
    stale_after = harness.run_until(lambda: model.link_state is LinkState.STALE, timeout=3)
    assert 0.3 <= stale_after <= 0.45  # three 100 ms periods without an echo
    lost_after = harness.run_until(lambda: model.link_state is LinkState.LOST, timeout=3)
    assert 2.0 <= stale_after + lost_after <= 2.15
    assert model.motion_lock_reason() == "link lost"
    # The station reopens the link with back-off; once replies flow again it stays up.
    harness.loopback.set_manipulator(None)
    harness.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=5)
    harness.run(3.0)
    assert model.link_state is LinkState.CONNECTED


def test_lost_link_drops_the_held_jog(harness: StationHarness) -> None:
    harness.run(2.5)
    harness.session.set_jog([1, 0])
    harness.run(0.5)
    harness.loopback.set_manipulator(lambda d, data: b"" if d is Direction.TO_HOST else data)
    harness.run(2.2)
    assert harness.session.jog_vector == (0, 0)
    harness.loopback.set_manipulator(None)
    start = len(harness.written)
    harness.run(0.3)
    assert all(
        p.command != CommandId.JOG or p.data == 0
        for f in _frames(harness.written[start:])
        for p in f.packets
    )


def test_corrupted_replies_are_counted_and_the_next_ones_still_apply(
    harness: StationHarness,
) -> None:
    harness.run(1.0)
    flips = iter(range(3))

    def corrupt(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_HOST and next(flips, None) is not None:
            return data[:5] + b"Z" + data[6:]
        return data

    harness.loopback.set_manipulator(corrupt)
    harness.session.move_absolute(0, 2.0)
    harness.run(1.5)
    assert harness.session.decoder.rejected == 3
    assert harness.station.model.axes[0].position == pytest.approx(2.0)


def test_write_confirmed_and_refused(harness: StationHarness) -> None:
    harness.run(3.0)
    model = harness.station.model
    harness.session.write_parameter(0, EchoType.FAST_SPEED, 12_000)
    harness.run(0.2)
    assert model.parameter(0, EchoType.FAST_SPEED).state is ParameterState.CONFIRMED
    assert model.parameter(0, EchoType.FAST_SPEED).value == 12_000
    messages: list[str] = []
    model.message.connect(messages.append)
    harness.session.write_parameter(1, EchoType.IRUN, 40)  # the device allows 0…31
    harness.run(0.2)
    entry = model.parameter(1, EchoType.IRUN)
    assert entry.state is ParameterState.REFUSED
    assert entry.value == harness.emulator.parameter(1, EchoType.IRUN) == 16
    assert any("refused" in m and "16" in m for m in messages)


def test_motion_is_refused_by_the_station_while_blocked(harness: StationHarness) -> None:
    harness.emulator.charger_connected = True
    harness.run(0.3)
    assert harness.station.model.motion_lock_reason() == "blocked: charger connected"
    before = len(harness.written)
    assert harness.session.move_absolute(0, 10.0) is False
    assert all(
        p.command != CommandId.MOVE_ABS
        for f in _frames(harness.written[before:])
        for p in f.packets
    )
