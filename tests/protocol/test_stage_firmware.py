"""The emulated stage firmware against docs/protocols.md §1.2-1.6, driven through encoded frames.

Every number asserted here is worked out by hand from the XY-stage defaults
(fast 10000 µm/s, slow 2000 µm/s, acceleration 20000 µm/s², start speed
500 µm/s, 1000 µm lead / 200 steps / 16 microsteps = 0.3125 µm per microstep,
travel 50000 µm) or from the parameters a test writes first.
"""

from __future__ import annotations

from collections.abc import Callable

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from protocol.clock import ManualClock
from protocol.emulator.fram import DEFAULT_IHOLDDELAY
from protocol.emulator.stage_firmware import Led, StageConfig, StageFirmware
from protocol.stage.codec import (
    AxisStatus,
    CommandFrame,
    CommandId,
    CommandPacket,
    DeviceFlag,
    EchoFrame,
    EchoPacket,
    EchoType,
    StageDecoder,
    Subscriber,
    encode_command,
    encode_echo,
)

NOP = CommandPacket(CommandId.NOP)
CYCLE = 0.005


def cmd(command: int, data: int = 0) -> CommandPacket:
    return CommandPacket(command, data)


class Bench:
    """The host's side of the wire, on a manual clock one control cycle at a time."""

    def __init__(self, config: StageConfig | None = None) -> None:
        # A start far from 0 catches code that confuses absolute and elapsed time.
        self.clock = ManualClock(start=100.0)
        self.fw = StageFirmware(self.clock, config)
        self._out = bytearray()
        self.last_bytes = b""
        self.fw.set_output(self._out.extend)
        self._decoder = StageDecoder(self.fw.config.axes)

    @property
    def now(self) -> float:
        return self.fw.time

    def send(self, x: CommandPacket = NOP, y: CommandPacket = NOP, ss: int = 0) -> None:
        self.fw.receive(encode_command(CommandFrame((x, y), ss)))

    def step(self, cycles: int = 1) -> list[EchoFrame]:
        """Run whole control cycles and return the echoes they sent."""
        for _ in range(cycles):
            self.clock.advance(CYCLE)
            self.fw.run_until(self.clock.now())
        return self.echoes()

    def echoes(self) -> list[EchoFrame]:
        self.last_bytes = bytes(self._out)
        frames = self._decoder.feed(self.last_bytes)
        self._out.clear()
        assert all(isinstance(f, EchoFrame) for f in frames), frames
        return [f for f in frames if isinstance(f, EchoFrame)]

    def exchange(self, x: CommandPacket = NOP, y: CommandPacket = NOP, ss: int = 0) -> EchoFrame:
        """One command frame, one cycle, its one echo."""
        self.send(x, y, ss)
        echoes = self.step()
        assert len(echoes) == 1
        return echoes[0]

    def idle(self, seconds: float) -> None:
        """Let time pass with no frames on the wire."""
        assert self.step(round(seconds / CYCLE)) == []

    def watch(self, seconds: float) -> list[tuple[float, EchoFrame]]:
        """Poll with NOP frames every cycle: (end-of-cycle time, echo) pairs."""
        seen = []
        for _ in range(round(seconds / CYCLE)):
            echo = self.exchange()
            seen.append((self.now, echo))
        return seen

    def until(
        self, done: Callable[[EchoFrame], bool], timeout: float
    ) -> tuple[float, EchoFrame, list[EchoFrame]]:
        """Poll until ``done(echo)``: (time, that echo, every echo before it)."""
        before: list[EchoFrame] = []
        for _ in range(round(timeout / CYCLE)):
            echo = self.exchange()
            if done(echo):
                return self.now, echo, before
            before.append(echo)
        raise AssertionError(f"not done within {timeout} s; last echo {before[-1]}")

    def write(self, parameter: int, value: int, axis: int = 0) -> EchoPacket:
        packet = cmd(parameter + 0x0E, value)
        echo = self.exchange(packet, NOP) if axis == 0 else self.exchange(NOP, packet)
        return echo.packets[axis]

    def read(self, parameter: int, axis: int = 0) -> EchoPacket:
        packet = cmd(CommandId.READ, parameter)
        echo = self.exchange(packet, NOP) if axis == 0 else self.exchange(NOP, packet)
        return echo.packets[axis]

    def subscribe(self, ss: int) -> int:
        echo = self.exchange(ss=ss)
        assert echo.subscriber == ss
        return echo.sdata


@pytest.fixture
def bench() -> Bench:
    return Bench()


def x_status(echo: EchoFrame) -> int:
    return echo.packets[0].status


def x_position(echo: EchoFrame) -> int:
    assert echo.packets[0].type == EchoType.POSITION
    return echo.packets[0].data


# -- framing: one echo per accepted frame -------------------------------------------------


def test_each_accepted_frame_gets_one_echo_at_the_end_of_the_cycle(bench: Bench) -> None:
    for ss in (Subscriber.BATTERY_CHARGE, Subscriber.FIRMWARE_VERSION, Subscriber.NONE):
        bench.send(ss=ss)
    bench.clock.advance(CYCLE / 2)
    bench.fw.run_until(bench.clock.now())
    assert bench.echoes() == []  # the cycle has not ended yet
    echoes = bench.step()
    assert [e.subscriber for e in echoes] == [0x02, 0x0A, 0x00]
    assert [e.sdata for e in echoes] == [80, 10200, 0]
    assert bench.step() == []


def test_a_frame_fed_one_byte_at_a_time_is_answered_once(bench: Bench) -> None:
    for byte in encode_command(CommandFrame((NOP, NOP), Subscriber.BATTERY_CHARGE)):
        bench.fw.receive(bytes([byte]))
    assert len(bench.step()) == 1


def _corrupt_checksum(frame: bytes) -> bytes:
    return frame[:-3] + (b"00" if frame[-3:-1] != b"00" else b"01") + b"\n"


def test_malformed_frames_are_dropped_counted_and_never_answered(bench: Bench) -> None:
    good = encode_command(CommandFrame((NOP, NOP)))
    host_echo = encode_echo(EchoFrame((EchoPacket(0, 0, 0), EchoPacket(0, 0, 0))))
    three_axes = encode_command(CommandFrame((NOP, NOP, NOP)))
    bad = [
        _corrupt_checksum(good),
        good[:5] + b"x" + good[6:],
        b"garbage\n",
        host_echo,
        three_axes,
    ]
    for line in bad:
        bench.fw.receive(line)
    assert bench.step() == []
    assert bench.fw.snapshot().rejected_frames == 5
    assert bench.subscribe(Subscriber.REJECTED_FRAMES) == 5
    # the reader resynchronised: a good frame after the noise is answered
    bench.fw.receive(b"noise\n" + good)
    assert len(bench.step()) == 1
    assert bench.fw.snapshot().rejected_frames == 6


@settings(max_examples=40, deadline=None)
@given(
    frames=st.lists(
        st.tuples(
            st.integers(0, 0x20), st.integers(-2, 60_000), st.integers(0, 0x20), st.integers(0, 12)
        ),
        min_size=1,
        max_size=8,
    )
)
def test_any_command_frames_get_exactly_one_well_formed_echo_each(
    frames: list[tuple[int, int, int, int]],
) -> None:
    bench = Bench()
    for x_id, data, y_id, ss in frames:
        bench.send(cmd(x_id, data), cmd(y_id, data), ss)
    echoes = bench.step()
    assert len(echoes) == len(frames)
    echoes += bench.step(40)  # nothing more, whatever the commands started
    assert len(echoes) == len(frames)
    statuses = {s.value for s in AxisStatus}
    assert all(p.status in statuses for e in echoes for p in e.packets)


# -- unknown IDs and subscribers --------------------------------------------------------


@pytest.mark.parametrize(
    "packet",
    [
        cmd(0x0A),
        cmd(0x0E),
        cmd(0x1A),
        cmd(0xFF),
        cmd(CommandId.JOG, 2),
        cmd(CommandId.SPEED, 3),
        cmd(CommandId.SLEEP, -1),
        cmd(CommandId.READ, 1),
        cmd(CommandId.READ, 13),
    ],
)
def test_unknown_or_malformed_commands_answer_status_f_in_their_packet(
    bench: Bench, packet: CommandPacket
) -> None:
    echo = bench.exchange(NOP, packet)
    assert echo.packets[0] == EchoPacket(EchoType.POSITION, AxisStatus.IDLE, 0)
    assert echo.packets[1].status == AxisStatus.UNKNOWN_COMMAND
    assert not bench.fw.snapshot().sleeping
    assert not bench.fw.axes[1].moving


@pytest.mark.parametrize("ss", [0x0C, 0x42, 0xFE])
def test_unknown_subscriber_answers_ff_with_the_id_asked(bench: Bench, ss: int) -> None:
    echo = bench.exchange(ss=ss)
    assert (echo.subscriber, echo.sdata) == (0xFF, ss)


# -- motion ----------------------------------------------------------------------------


def _set_dynamics(bench: Bench, fast: int, acceleration: int, start: int) -> None:
    assert bench.write(EchoType.FAST_SPEED, fast).data == fast
    assert bench.write(EchoType.ACCELERATION, acceleration).data == acceleration
    assert bench.write(EchoType.START_SPEED, start).data == start
    bench.exchange(cmd(CommandId.SPEED, 1))


def test_triangular_20_mm_move_takes_4_s(bench: Bench) -> None:
    # 10 mm/s at 5 mm/s² from standstill: 2 s and 10 mm up, 2 s and 10 mm down.
    _set_dynamics(bench, fast=10_000, acceleration=5_000, start=0)
    start = bench.now
    echo = bench.exchange(cmd(CommandId.MOVE_ABS, 20_000))
    assert x_status(echo) == AxisStatus.ACCELERATING
    track = dict(bench.watch(4.2))
    at_1s = _at(track, start + 1.0)
    assert (x_status(at_1s), x_position(at_1s)) == (AxisStatus.ACCELERATING, 2500)
    at_3s = _at(track, start + 3.0)
    assert (x_status(at_3s), x_position(at_3s)) == (AxisStatus.DECELERATING, 17500)
    done = min(t for t, e in track.items() if x_status(e) == AxisStatus.TARGET_REACHED)
    assert abs(done - start - 4.0) <= CYCLE + 1e-9
    final = _at(track, start + 4.2)
    assert (x_status(final), x_position(final)) == (AxisStatus.TARGET_REACHED, 20_000)
    assert final.packets[1] == EchoPacket(EchoType.POSITION, AxisStatus.IDLE, 0)


def test_trapezoidal_20_mm_move_takes_2_5_s(bench: Bench) -> None:
    # 0.5 s and 2.5 mm up, 1.5 s cruising 15 mm, 0.5 s and 2.5 mm down.
    _set_dynamics(bench, fast=10_000, acceleration=20_000, start=0)
    start = bench.now
    bench.exchange(cmd(CommandId.MOVE_ABS, 20_000))
    track = dict(bench.watch(2.7))
    cruising = _at(track, start + 1.0)
    assert (x_status(cruising), x_position(cruising)) == (AxisStatus.CONSTANT_SPEED, 7500)
    done = min(t for t, e in track.items() if x_status(e) == AxisStatus.TARGET_REACHED)
    assert abs(done - start - 2.5) <= CYCLE + 1e-9
    assert x_position(track[done]) == 20_000


def _at(track: dict[float, EchoFrame], t: float) -> EchoFrame:
    return next(echo for when, echo in track.items() if abs(when - t) < 1e-6)


def test_move_rel_moves_by_the_increment_from_where_the_axis_is(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.MOVE_ABS, 1000))
    bench.until(lambda e: x_status(e) == AxisStatus.TARGET_REACHED, 2.0)
    bench.exchange(cmd(CommandId.MOVE_REL, -400))
    _, echo, _ = bench.until(lambda e: x_status(e) == AxisStatus.TARGET_REACHED, 2.0)
    assert x_position(echo) == 600


def test_jog_without_repeats_stops_after_the_watchdog_and_deceleration(bench: Bench) -> None:
    # Slow jog: 500 -> 2000 µm/s in 0.075 s (93.75 µm), cruise; the watchdog fires
    # 0.5 s after the last JOG, then 0.075 s (93.75 µm) of braking to start speed.
    start = bench.now
    bench.exchange(cmd(CommandId.JOG, 1))
    track = bench.watch(0.7)  # NOP frames keep the link alive but are no JOG
    status = {round(t - start, 3): x_status(e) for t, e in track}
    assert status[0.07] == AxisStatus.ACCELERATING
    assert status[0.495] == AxisStatus.CONSTANT_SPEED
    assert status[0.505] == AxisStatus.DECELERATING
    stopped = min(t for t, e in track if x_status(e) == AxisStatus.STOPPED)
    assert 0.575 - 1e-9 <= stopped - start <= 0.575 + CYCLE + 1e-9
    assert abs(x_position(track[-1][1]) - 1037.5) <= 0.5


def test_silence_stops_a_jog_just_as_well(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.JOG, -1))  # from 0 towards the low switch...
    bench.exchange(cmd(CommandId.SET_POS, 10_000))  # ...so first move the zero away
    bench.exchange(cmd(CommandId.JOG, 1))
    bench.idle(0.49)
    assert bench.fw.axes[0].moving
    bench.idle(0.1)
    assert not bench.fw.axes[0].moving
    assert x_status(bench.exchange()) == AxisStatus.STOPPED


def test_a_repeated_jog_keeps_running(bench: Bench) -> None:
    start = bench.now
    for _ in range(10):
        bench.exchange(cmd(CommandId.JOG, 1))
        bench.idle(0.095)
    echo = bench.exchange()
    assert x_status(echo) == AxisStatus.CONSTANT_SPEED
    # 93.75 µm ramp + 2000 µm/s for the rest of the time since the first JOG
    expected = 93.75 + 2000 * (bench.now - start - 0.075)
    assert abs(x_position(echo) - expected) <= 0.5


def test_jog_zero_brakes_a_jog_to_a_stop(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.JOG, 1))
    bench.idle(0.2)
    assert x_status(bench.exchange(cmd(CommandId.JOG, 0))) == AxisStatus.DECELERATING
    _, echo, _ = bench.until(lambda e: x_status(e) != AxisStatus.DECELERATING, 0.2)
    assert x_status(echo) == AxisStatus.STOPPED


def test_jog_reversal_decelerates_before_reversing(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.JOG, 1))
    bench.idle(0.195)
    # at 0.2 s: 93.75 µm of ramp + 0.125 s at 2000 µm/s
    reversal = bench.exchange(cmd(CommandId.JOG, -1))
    start = bench.now - CYCLE
    track = [(bench.now, reversal)]
    for _ in range(40):
        track.append((bench.now + CYCLE, bench.exchange(cmd(CommandId.JOG, -1))))
    statuses = [x_status(e) for _, e in track]
    positions = [x_position(e) for _, e in track]
    # braking 0.075 s to the start speed while still going forward (+93.75 µm)...
    assert statuses[:14] == [AxisStatus.DECELERATING] * 14
    assert positions[:14] == sorted(positions[:14])
    peak = max(positions)
    assert abs(peak - (343.75 + 93.75)) <= 0.5
    # ...then backwards, accelerating to 2000 µm/s over another 0.075 s
    after = [(t - start, s, p) for (t, _), s, p in zip(track, statuses, positions, strict=True)]
    assert all(s == AxisStatus.ACCELERATING for t, s, _ in after if 0.08 <= t <= 0.145)
    assert all(s == AxisStatus.CONSTANT_SPEED for t, s, _ in after if t >= 0.155)
    assert positions[16:] == sorted(positions[16:], reverse=True)
    assert abs(positions[-1] - (437.5 - 93.75 - 2000 * (track[-1][0] - start - 0.15))) <= 0.5


def test_move_past_travel_stops_on_the_end_switch_without_overshoot(bench: Bench) -> None:
    # travel 5000; fast jog-like run: 500 -> 10000 µm/s over 0.475 s (2493.75 µm),
    # then 2506.25 µm at 10000 µm/s: the switch at 0.725625 s.
    assert bench.write(EchoType.TRAVEL, 5000).data == 5000
    bench.exchange(cmd(CommandId.SPEED, 1))
    start = bench.now
    bench.exchange(cmd(CommandId.MOVE_ABS, 8000))
    track = bench.watch(1.0)
    assert max(x_position(e) for _, e in track) == 5000
    hit = min(t for t, e in track if x_status(e) == AxisStatus.END_SWITCH)
    assert 0.725625 <= hit - start <= 0.725625 + CYCLE
    assert (x_status(track[-1][1]), x_position(track[-1][1])) == (AxisStatus.END_SWITCH, 5000)
    assert bench.fw.axes[0].end_switch_high


def test_home_shows_homing_then_idle_at_zero(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.MOVE_ABS, 1000))
    bench.until(lambda e: x_status(e) == AxisStatus.TARGET_REACHED, 2.0)
    start = bench.now
    echo = bench.exchange(cmd(CommandId.HOME))
    assert x_status(echo) == AxisStatus.HOMING
    # slow seek: 0.075 s ramp (93.75 µm) + 906.25 µm at 2000 µm/s = 0.528125 s to the
    # switch, then one 0.3125 µm microstep at 500 µm/s to release it: 0.52875 s.
    done, echo, before = bench.until(lambda e: x_status(e) != AxisStatus.HOMING, 1.0)
    assert (x_status(echo), x_position(echo)) == (AxisStatus.IDLE, 0)
    assert 0.52875 <= done - start <= 0.52875 + CYCLE
    assert x_position(before[0]) < 1000
    assert bench.subscribe(Subscriber.X_ENCODER) == 0


def test_stop_decelerates_and_estop_stops_at_once(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.MOVE_ABS, 5000), cmd(CommandId.MOVE_ABS, 5000))
    bench.idle(0.2)
    echo = bench.exchange(cmd(CommandId.STOP), cmd(CommandId.ESTOP))
    assert echo.packets[0].status == AxisStatus.DECELERATING
    assert echo.packets[1].status == AxisStatus.STOPPED
    y_stopped_at = echo.packets[1].data
    _, echo, _ = bench.until(lambda e: x_status(e) == AxisStatus.STOPPED, 0.2)
    assert echo.packets[1].data == y_stopped_at


def test_set_pos_renames_the_position(bench: Bench) -> None:
    echo = bench.exchange(cmd(CommandId.SET_POS, 12_345), cmd(CommandId.SET_POS, -500))
    assert [p.data for p in echo.packets] == [12_345, -500]


def test_speed_selects_the_stored_speed(bench: Bench) -> None:
    # 1 s of cruising after a 0.075 s (slow) or 0.475 s (fast) ramp from 500 µm/s.
    bench.exchange(cmd(CommandId.SPEED, 1), cmd(CommandId.SPEED, 0))
    bench.exchange(cmd(CommandId.MOVE_ABS, 40_000), cmd(CommandId.MOVE_ABS, 40_000))
    bench.idle(0.995)
    v_fast, v_slow = (axis.velocity for axis in bench.fw.axes)
    assert (v_fast, v_slow) == (10_000, 2_000)


def test_microstep_parameters_change_the_position_resolution(bench: Bench) -> None:
    # full steps: 1000 µm / 200 steps = 5 µm per count
    assert bench.write(EchoType.MICROSTEPS, 1).data == 1
    assert bench.fw.axes[0].limits.microstep_um == 5.0
    bench.exchange(cmd(CommandId.MOVE_ABS, 1002))
    _, echo, _ = bench.until(lambda e: x_status(e) == AxisStatus.TARGET_REACHED, 2.0)
    assert x_position(echo) == 1000  # the counter holds whole steps
    assert bench.subscribe(Subscriber.X_ENCODER) == 1002  # the encoder sees where it is
    assert bench.read(EchoType.ENCODER).data == 1002
    bench.write(EchoType.LEAD, 4000)
    bench.write(EchoType.STEPS_PER_REV, 400)
    bench.write(EchoType.MICROSTEPS, 256)
    assert bench.fw.axes[0].limits.microstep_um == 4000 / (400 * 256)


def test_end_switch_pressed_by_hand_stops_a_jog(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.JOG, 1))
    bench.idle(0.1)
    bench.fw.press_end_switch(0, "high")
    assert x_status(bench.exchange(cmd(CommandId.JOG, 1))) == AxisStatus.END_SWITCH


# -- parameters ------------------------------------------------------------------------


def test_every_parameter_reads_back_its_default(bench: Bench) -> None:
    defaults = {2: 10_000, 3: 2_000, 4: 20_000, 5: 500, 6: 16, 7: 8, 8: 16, 9: 1000, 10: 200}
    defaults |= {11: 50_000, 12: 0}
    for parameter, value in defaults.items():
        for axis in (0, 1):
            packet = bench.read(parameter, axis)
            assert (packet.type, packet.data) == (parameter, value)
            assert packet.status == AxisStatus.IDLE


def test_written_acceleration_lands_in_fram_lsb_first_and_is_confirmed(bench: Bench) -> None:
    address = bench.fw.fram.address_of(0, EchoType.ACCELERATION)
    assert bench.write(EchoType.ACCELERATION, 12_345) == EchoPacket(4, AxisStatus.IDLE, 12_345)
    assert bench.fw.fram.dump(address, 4) == bytes([0x39, 0x30, 0x00, 0x00])
    assert bench.write(EchoType.ACCELERATION, 20_000) == EchoPacket(4, AxisStatus.IDLE, 20_000)
    assert bench.fw.fram.dump(address, 4) == bytes([0x20, 0x4E, 0x00, 0x00])
    assert bench.fw.axes[0].acceleration == 20_000
    assert bench.write(EchoType.ACCELERATION, 7_000, axis=1).data == 7_000
    assert bench.fw.axes[1].acceleration == 7_000
    assert bench.read(EchoType.ACCELERATION, axis=0).data == 20_000


def test_verification_fault_rejects_the_write_and_keeps_the_old_value(bench: Bench) -> None:
    address = bench.fw.fram.address_of(0, EchoType.ACCELERATION)
    bench.fw.verification_fault = True
    packet = bench.write(EchoType.ACCELERATION, 5_000)
    assert packet == EchoPacket(EchoType.ACCELERATION, AxisStatus.PARAMETER_REJECTED, 20_000)
    assert bench.fw.fram.dump(address, 4) == bytes([0x20, 0x4E, 0x00, 0x00])
    assert bench.fw.axes[0].acceleration == 20_000
    assert bench.read(EchoType.ACCELERATION).data == 20_000
    bench.fw.verification_fault = False
    assert bench.write(EchoType.ACCELERATION, 5_000).status == AxisStatus.IDLE
    assert bench.fw.parameter(0, EchoType.ACCELERATION) == 5_000


@pytest.mark.parametrize(
    ("parameter", "value", "kept"),
    [
        (EchoType.FAST_SPEED, 0, 10_000),
        (EchoType.FAST_SPEED, -5, 10_000),
        (EchoType.ACCELERATION, 0, 20_000),
        (EchoType.START_SPEED, 100_000, 500),
        (EchoType.IRUN, 32, 16),
        (EchoType.IHOLD, -1, 8),
        (EchoType.MICROSTEPS, 3, 16),
        (EchoType.MICROSTEPS, 0, 16),
        (EchoType.MICROSTEPS, 512, 16),
        (EchoType.LEAD, 100_000, 1000),
        (EchoType.STEPS_PER_REV, 10_000, 200),
        (EchoType.TRAVEL, 0, 50_000),
    ],
)
def test_out_of_range_writes_are_rejected_with_the_value_kept(
    bench: Bench, parameter: EchoType, value: int, kept: int
) -> None:
    before = bench.fw.fram.dump(0, 0x80)
    packet = bench.write(parameter, value)
    assert packet == EchoPacket(parameter, AxisStatus.PARAMETER_REJECTED, kept)
    assert bench.fw.fram.dump(0, 0x80) == before


@given(exponent=st.integers(0, 8))
def test_every_power_of_two_microstep_setting_is_accepted(exponent: int) -> None:
    bench = Bench()
    packet = bench.write(EchoType.MICROSTEPS, 2**exponent)
    assert packet == EchoPacket(EchoType.MICROSTEPS, AxisStatus.IDLE, 2**exponent)
    assert bench.fw.axes[0].limits.microstep_um == 1000 / (200 * 2**exponent)


def test_irun_write_keeps_ihold(bench: Bench) -> None:
    assert bench.write(EchoType.IHOLD, 5).data == 5
    assert bench.write(EchoType.IRUN, 12).data == 12
    assert bench.read(EchoType.IRUN).data == 12
    assert bench.read(EchoType.IHOLD).data == 5
    register = bench.fw.fram.ihold_irun(0)
    assert register & 0x1F == 5
    assert (register >> 8) & 0x1F == 12
    assert (register >> 16) & 0xF == DEFAULT_IHOLDDELAY
    assert bench.fw.fram.ihold_irun(1) == 8 | 16 << 8 | DEFAULT_IHOLDDELAY << 16


# -- blocks, sleep and faults -----------------------------------------------------------

MOTION = [
    cmd(CommandId.MOVE_ABS, 3000),
    cmd(CommandId.MOVE_REL, 3000),
    cmd(CommandId.JOG, 1),
    cmd(CommandId.HOME),
]


def _charger(fw: StageFirmware, on: bool) -> None:
    fw.charger_connected = on


def _usb(fw: StageFirmware, on: bool) -> None:
    fw.usb_connected = on


def _flat_battery(fw: StageFirmware, on: bool) -> None:
    fw.battery_charge = 3.0 if on else 80.0


@pytest.mark.parametrize(
    ("cause", "status"),
    [
        (_charger, AxisStatus.BLOCKED_CHARGER),
        (_usb, AxisStatus.BLOCKED_USB),
        (_flat_battery, AxisStatus.BLOCKED_BATTERY),
    ],
)
def test_a_block_stops_motion_refuses_it_and_clears_by_itself(
    bench: Bench, cause: Callable[[StageFirmware, bool], None], status: AxisStatus
) -> None:
    bench.exchange(cmd(CommandId.MOVE_ABS, 5000))
    bench.idle(0.2)
    cause(bench.fw, True)
    assert not bench.fw.axes[0].moving  # stopped at once, no deceleration
    assert not bench.fw.snapshot().motors_enabled
    held = bench.fw.axes[0].position_um
    for packet in MOTION:
        echo = bench.exchange(packet, packet)
        assert [p.status for p in echo.packets] == [status, status]
        bench.idle(0.1)
    assert bench.fw.axes[0].position_um == held
    assert not any(axis.moving for axis in bench.fw.axes)
    assert [c.accepted for c in bench.fw.command_log][-8:] == [False] * 8
    cause(bench.fw, False)
    assert bench.fw.snapshot().motors_enabled
    echo = bench.exchange(cmd(CommandId.MOVE_ABS, 0), cmd(CommandId.MOVE_ABS, 3000))
    assert [p.status for p in echo.packets] == [AxisStatus.ACCELERATING] * 2


def test_block_priority_is_battery_then_charger_then_usb(bench: Bench) -> None:
    bench.fw.usb_connected = True
    assert x_status(bench.exchange()) == AxisStatus.BLOCKED_USB
    bench.fw.charger_connected = True
    assert x_status(bench.exchange()) == AxisStatus.BLOCKED_CHARGER
    bench.fw.battery_charge = 4.0
    assert x_status(bench.exchange()) == AxisStatus.BLOCKED_BATTERY


def test_the_battery_running_flat_blocks_the_stage_while_it_moves() -> None:
    bench = Bench(StageConfig(battery_charge=5.0005))
    # 40 + 2 x 120 + 350 mA = 630 mA drains 0.0005 % of 2000 mAh in 0.0571 s
    bench.exchange(cmd(CommandId.MOVE_ABS, 5000))
    bench.idle(0.05)
    assert bench.fw.axes[0].moving
    bench.idle(0.01)
    assert not bench.fw.axes[0].moving
    assert x_status(bench.exchange()) == AxisStatus.BLOCKED_BATTERY


def test_the_led_ring_shows_the_originals_states(bench: Bench) -> None:
    """FIDELITY S3-33, table 7-4: charger red on, low battery red fast blink, standby green,
    pairing blue slow blink, talking blue on."""
    assert bench.fw.snapshot().led is Led.PAIRING  # no host yet: advertising
    bench.exchange()
    assert bench.fw.snapshot().led is Led.TALKING
    bench.exchange(cmd(CommandId.SLEEP, 1), cmd(CommandId.SLEEP, 1))
    assert bench.fw.snapshot().led is Led.STANDBY
    bench.fw.battery_charge = 10.0  # below the 15 % low mark
    assert bench.fw.snapshot().led is Led.LOW_BATTERY
    bench.fw.charger_connected = True
    assert bench.fw.snapshot().led is Led.CHARGING
    bench.fw.press_button()
    assert bench.fw.snapshot().led is Led.OFF


def test_the_button_switches_off_stopping_everything_and_on_afresh(bench: Bench) -> None:
    """FIDELITY S3-36: the user button switches the stage off (the shutdown sequence: axes
    stop, drivers off, parameters kept in FRAM) and on again."""
    bench.exchange(cmd(CommandId.WRITE_ACCELERATION, 12_345))
    bench.exchange(cmd(CommandId.JOG, 1))
    bench.idle(0.2)
    assert bench.fw.axes[0].moving
    bench.fw.press_button()
    assert not bench.fw.snapshot().powered and not bench.fw.snapshot().motors_enabled
    assert not any(axis.moving for axis in bench.fw.axes)
    bench.send(cmd(CommandId.JOG, 1))
    assert bench.step(20) == []  # off: nothing heard, nothing answered
    assert not bench.fw.axes[0].moving
    stopped_at = bench.fw.axes[0].physical_um
    bench.fw.press_button()
    assert bench.fw.snapshot().powered and bench.fw.snapshot().motors_enabled
    # The counters start afresh from the absolute encoder (S3-30): where the axis stands.
    assert bench.fw.axes[0].position_um == pytest.approx(stopped_at)
    assert bench.fw.parameter(0, EchoType.ACCELERATION) == 12_345  # FRAM kept it
    assert len(bench.step()) == 0 and len([bench.exchange()]) == 1


def test_sleep_refuses_motion_until_woken(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.JOG, 1))
    echo = bench.exchange(cmd(CommandId.SLEEP, 1), cmd(CommandId.NOP))
    assert [p.status for p in echo.packets] == [AxisStatus.SLEEPING] * 2
    assert bench.fw.snapshot().sleeping and not bench.fw.axes[0].moving
    assert bench.subscribe(Subscriber.DEVICE_FLAGS) & DeviceFlag.SLEEPING
    for packet in MOTION:
        assert bench.exchange(packet, packet).packets[1].status == AxisStatus.SLEEPING
    bench.idle(0.2)
    assert not any(axis.moving for axis in bench.fw.axes)
    echo = bench.exchange(cmd(CommandId.NOP), cmd(CommandId.SLEEP, 0))
    assert not bench.fw.snapshot().sleeping
    assert echo.packets[0].status != AxisStatus.SLEEPING
    echo = bench.exchange(cmd(CommandId.MOVE_ABS, 3000))
    assert x_status(echo) == AxisStatus.ACCELERATING


def test_driver_fault_disables_only_its_axis(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.MOVE_ABS, 3000), cmd(CommandId.MOVE_ABS, 3000))
    bench.fw.set_driver_fault(1, True)
    assert not bench.fw.axes[1].moving
    echo = bench.exchange(NOP, cmd(CommandId.MOVE_ABS, 0))
    assert [p.status for p in echo.packets] == [AxisStatus.ACCELERATING, AxisStatus.DRIVER_FAULT]
    assert not bench.fw.axes[1].moving
    bench.fw.set_driver_fault(1, False)
    echo = bench.exchange(NOP, cmd(CommandId.MOVE_ABS, 3000))
    assert echo.packets[1].status == AxisStatus.ACCELERATING


# -- subscribers and the environment ------------------------------------------------------


def test_battery_subscribers(bench: Bench) -> None:
    # 80 % on a 3300...4200 mV cell; the drain over a few cycles is far below 1 mV
    assert bench.subscribe(Subscriber.BATTERY_VOLTAGE) == 4020
    assert bench.subscribe(Subscriber.BATTERY_CHARGE) == 80
    assert bench.subscribe(Subscriber.CHARGING_CURRENT) == 0
    bench.fw.battery_charge = 50.0
    bench.fw.charger_connected = True
    assert bench.subscribe(Subscriber.BATTERY_VOLTAGE) == 3750
    assert bench.subscribe(Subscriber.CHARGING_CURRENT) == 800
    bench.fw.battery_charge = 95.0  # tapering above 90 %
    assert bench.subscribe(Subscriber.CHARGING_CURRENT) == 400


def test_battery_drains_faster_while_moving_and_charges_on_the_charger(bench: Bench) -> None:
    start = bench.fw.battery_charge
    bench.idle(10.0)
    idle_drop = start - bench.fw.battery_charge
    # 40 mA + 2 x 120 mA holding for 10 s out of 2000 mAh
    assert idle_drop == pytest.approx(280 * 10 / 3600 / 2000 * 100, rel=1e-6)
    bench.exchange(cmd(CommandId.MOVE_ABS, 40_000))  # 20 s at slow speed
    start = bench.fw.battery_charge
    bench.idle(10.0)
    moving_drop = start - bench.fw.battery_charge
    assert moving_drop == pytest.approx(630 * 10 / 3600 / 2000 * 100, rel=1e-3)
    bench.fw.charger_connected = True  # blocked: motors off, 40 mA load, 800 mA in
    start = bench.fw.battery_charge
    bench.idle(60.0)
    assert bench.fw.battery_charge - start == pytest.approx(760 * 60 / 3600 / 2000 * 100)


def test_temperature_subscriber(bench: Bench) -> None:
    assert bench.subscribe(Subscriber.BOARD_TEMPERATURE) == 2500
    bench.fw.board_temperature_c = 31.25
    assert bench.subscribe(Subscriber.BOARD_TEMPERATURE) == 3125
    bench.fw.board_temperature_c = -5.5
    assert bench.subscribe(Subscriber.BOARD_TEMPERATURE) == -550


def test_rotation_integrates_the_rate(bench: Bench) -> None:
    bench.fw.rotation_rate_dps = 10.0
    bench.idle(2.0 - CYCLE)
    assert bench.subscribe(Subscriber.ROTATION) == 2000  # that cycle ends at 2 s
    assert bench.subscribe(Subscriber.YAW_RATE) == 1000


def test_rotation_wraps_into_plus_minus_180(bench: Bench) -> None:
    bench.fw.rotation_rate_dps = -100.0
    bench.idle(2.0 - CYCLE)
    assert bench.subscribe(Subscriber.ROTATION) == 16000  # -200 deg is +160 deg
    assert bench.subscribe(Subscriber.YAW_RATE) == -10000
    bench.fw.yaw_deg = 180.0
    bench.fw.rotation_rate_dps = 0.0
    assert bench.subscribe(Subscriber.ROTATION) == -18000


def test_device_flags(bench: Bench) -> None:
    assert bench.subscribe(Subscriber.DEVICE_FLAGS) == DeviceFlag.DATA_SESSION
    bench.fw.charger_connected = True
    bench.fw.usb_connected = True
    bench.fw.battery_charge = 10.0  # low (below 15 %) but not critical (5 %)
    expected = DeviceFlag.CHARGER | DeviceFlag.USB | DeviceFlag.LOW_BATTERY
    assert bench.subscribe(Subscriber.DEVICE_FLAGS) == expected | DeviceFlag.DATA_SESSION


def test_data_session_closes_after_2_s_without_frames(bench: Bench) -> None:
    assert not bench.fw.snapshot().session_open
    bench.exchange()
    bench.idle(1.99)
    assert bench.fw.snapshot().session_open
    bench.idle(0.02)
    assert not bench.fw.snapshot().session_open


def test_encoder_and_version_subscribers(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.MOVE_ABS, 1000), cmd(CommandId.MOVE_ABS, 2000))
    bench.idle(2.0)
    assert bench.subscribe(Subscriber.X_ENCODER) == 1000
    assert bench.subscribe(Subscriber.Y_ENCODER) == 2000
    assert bench.subscribe(Subscriber.FIRMWARE_VERSION) == 10200
    assert bench.last_bytes[17:25] == b"0A010200"
    assert bench.subscribe(Subscriber.NONE) == 0


def test_command_log_records_what_was_executed(bench: Bench) -> None:
    bench.exchange(cmd(CommandId.MOVE_ABS, 1000), cmd(0x0A, 7))
    log = list(bench.fw.command_log)
    assert [(c.axis, c.command, c.data, c.accepted) for c in log] == [
        (0, CommandId.MOVE_ABS, 1000, True),
        (1, 0x0A, 7, False),
    ]
    assert log[0].time == pytest.approx(100.0)


# -- FIDELITY S3-28, S3-30, S3-31, S3-36: step timer, power-on, shutdown, reset ------------


def test_s3_28_the_step_rate_is_what_whole_psc_and_arr_give(bench: Bench) -> None:
    """At 256 microsteps (1000 µm / 51200 = 0.01953125 µm) 50 mm/s asks 2.56 MHz: 31.25
    ticks of the 80 MHz timer. ARR + 1 = 31 (truncated): 2 580 645.16 Hz, 50.403 mm/s."""
    bench.write(EchoType.MICROSTEPS, 256)
    bench.write(EchoType.ACCELERATION, 999_999)
    bench.write(EchoType.FAST_SPEED, 50_000)
    bench.exchange(cmd(CommandId.SPEED, 1))
    bench.exchange(cmd(CommandId.MOVE_ABS, 40_000))
    bench.idle(0.2)  # ramp over after 0.05 s, cruising
    assert bench.fw.axes[0].velocity == pytest.approx(80e6 / 31 * 1000 / 51200)
    assert bench.fw.axes[0].velocity == pytest.approx(50_403.2258, abs=1e-3)
    # The defaults are exact periods (10 mm/s: 2500 ticks), so nothing changes there.
    bench.write(EchoType.MICROSTEPS, 16)
    bench.write(EchoType.FAST_SPEED, 10_000)
    bench.exchange(cmd(CommandId.MOVE_ABS, 0))
    bench.idle(0.5)
    assert bench.fw.axes[0].velocity == -10_000


def test_s3_30_power_on_counts_from_the_absolute_encoder() -> None:
    """The stage is switched on where it was left: the encoder's reading is the position."""
    bench = Bench(StageConfig(encoder_positions_um=(12_345.0, 30_000.0)))
    echo = bench.exchange()
    assert [p.data for p in echo.packets] == [12_345, 30_000]
    assert bench.subscribe(Subscriber.X_ENCODER) == 12_345
    # A zero set by the operator is the station's frame, not the machine's: after a
    # power cycle the counter is the encoder's absolute position again.
    bench.exchange(cmd(CommandId.SET_POS, 0))
    assert x_position(bench.exchange()) == 0
    bench.fw.press_button()
    bench.fw.press_button()
    assert x_position(bench.exchange()) == 12_345


def test_s3_30_an_encoder_position_off_the_travel_is_refused() -> None:
    with pytest.raises(ValueError, match="off its travel"):
        StageFirmware(ManualClock(), StageConfig(encoder_positions_um=(60_000.0,)))


def test_s3_31_the_shutdown_sequence_saves_the_step_count_and_power_on_restores_it() -> None:
    bench = Bench(StageConfig(encoder_positions_um=(10_000.0,), save_steps_at_shutdown=True))
    bench.exchange(cmd(CommandId.SET_POS, 0))  # the operator's zero at 10 mm from the switch
    bench.exchange(cmd(CommandId.MOVE_ABS, 1_000))
    bench.until(lambda e: x_status(e) == AxisStatus.TARGET_REACHED, 2.0)
    bench.fw.press_button()  # a short press: the shutdown sequence
    base = 0x28  # axis 0's saved count, then its mark (fram.py's map)
    assert bench.fw.fram.dump(base, 8) == (3_200).to_bytes(4, "little") + bytes.fromhex("FE5AE957")
    bench.fw.press_button()
    assert x_position(bench.exchange()) == 1_000  # the operator's frame survived
    # The count is used up: a power cut by the KillSwitch (no sequence) cannot bring it
    # back, the encoder's reading counts then.
    bench.fw.kill_switch()
    bench.fw.press_button()
    assert x_position(bench.exchange()) == 11_000


def test_s3_31_without_the_option_nothing_is_saved_and_the_encoder_counts() -> None:
    bench = Bench(StageConfig(encoder_positions_um=(10_000.0,)))
    bench.exchange(cmd(CommandId.SET_POS, 0))
    bench.fw.press_button()
    assert bench.fw.fram.dump(0x28, 8) == bytes(8)
    bench.fw.press_button()
    assert x_position(bench.exchange()) == 10_000


def test_s3_36_the_kill_switch_cuts_the_power_without_the_shutdown_sequence() -> None:
    bench = Bench(StageConfig(save_steps_at_shutdown=True))
    bench.exchange(cmd(CommandId.JOG, 1))
    bench.idle(0.2)
    bench.fw.kill_switch()
    assert not bench.fw.snapshot().powered and not bench.fw.snapshot().motors_enabled
    assert not any(axis.moving for axis in bench.fw.axes)
    assert bench.fw.snapshot().led is Led.OFF
    assert bench.fw.fram.dump(0x28, 8) == bytes(8)  # nothing saved
    bench.send(cmd(CommandId.JOG, 1))
    assert bench.step(20) == []  # silent
    bench.fw.kill_switch()  # already off: nothing more to cut
    assert not bench.fw.snapshot().powered


def test_s3_36_a_long_press_resets_the_board_at_once() -> None:
    """Held for the reset time the button restarts the firmware: axes stop dead, nothing is
    saved, the board is on again at once, counting from the encoder, awake, slow speed
    selected, and a host must open its session anew."""
    bench = Bench(StageConfig(save_steps_at_shutdown=True))
    bench.exchange(cmd(CommandId.SLEEP, 1), cmd(CommandId.SLEEP, 1))
    bench.fw.press_button(held_s=bench.fw.config.reset_press_s)
    assert bench.fw.snapshot().powered and not bench.fw.snapshot().sleeping
    bench.exchange(cmd(CommandId.SPEED, 1), cmd(CommandId.SET_POS, 5_000))
    bench.exchange(cmd(CommandId.JOG, 1))
    bench.idle(0.2)
    assert bench.fw.axes[0].moving
    bench.send(cmd(CommandId.JOG, 1))  # arrived, not yet handled: the reset drops it
    bench.fw.press_button(held_s=bench.fw.config.reset_press_s)
    assert bench.fw.snapshot().powered and bench.fw.snapshot().motors_enabled
    assert not bench.fw.axes[0].moving
    assert not bench.fw.snapshot().fast[0]
    assert bench.fw.snapshot().led is Led.PAIRING  # no session until the host speaks again
    assert bench.fw.fram.dump(0x28, 8) == bytes(8)  # nothing saved
    assert bench.step(5) == []
    stood = bench.fw.axes[0].physical_um
    echo = bench.exchange()
    assert stood > 100 and x_position(echo) == pytest.approx(stood, abs=1)
    assert echo.packets[1].data == 0  # Y's SET_POS 5000 is forgotten: the encoder says 0
    # A shorter press is the ordinary switch-off.
    bench.fw.press_button(held_s=bench.fw.config.reset_press_s - 0.1)
    assert not bench.fw.snapshot().powered
