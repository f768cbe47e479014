"""The dry run's times, checked against trapezoids worked out by hand.

XY stage defaults (docs/protocols.md §1.4): fast 10 mm/s, slow 2 mm/s,
acceleration 20 mm/s², start speed 0.5 mm/s.  The driver jumps to the start
speed, ramps, cruises and ramps back down, jumping to a stop from 0.5 mm/s.
"""

from __future__ import annotations

import math

import pytest

from app.jobs.estimate import CONTROL_CYCLE_S, Estimate, estimate
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.profiles import load_profile
from protocol.stage.codec import EchoType

PERIOD_S = 0.1
OVERHEAD = PERIOD_S / 2 + CONTROL_CYCLE_S
HERE = SourceRef("test.txt", 1)


def ramp(v_from: float, v_to: float, accel: float) -> tuple[float, float]:
    """(time, distance) of a constant-acceleration speed change."""
    return abs(v_to - v_from) / accel, abs(v_to**2 - v_from**2) / (2 * accel)


def trapezoid_20mm() -> float:
    # 0.5 → 10 mm/s at 20 mm/s²: 0.475 s over 2.49375 mm, twice; the rest cruises at 10 mm/s.
    t_ramp, d_ramp = ramp(0.5, 10.0, 20.0)
    assert (t_ramp, d_ramp) == pytest.approx((0.475, 2.49375))
    return 2 * t_ramp + (20.0 - 2 * d_ramp) / 10.0  # 2.45125 s


def program(*ops: Operation) -> Program:
    return Program("test", ops)


def xy_estimate(prog: Program, **kwargs: object) -> Estimate:
    return estimate(prog, load_profile("xy-stage"), {}, PERIOD_S, **kwargs)  # type: ignore[arg-type]


def test_a_20_mm_move_is_the_hand_computed_trapezoid_plus_the_detection_overhead() -> None:
    result = xy_estimate(program(move(HERE, X=20.0)))
    assert trapezoid_20mm() == pytest.approx(2.45125)
    assert result.total_s == pytest.approx(2.45125 + OVERHEAD, abs=1e-9)
    assert result.cumulative_s == (result.total_s,)


def test_a_short_move_is_triangular() -> None:
    # 2 mm cannot reach 10 mm/s: the peak is where both ramps meet,
    # v² = a·d + (0.5² + 0.5²)/2 → v = √40.25 ≈ 6.344 mm/s.
    peak = math.sqrt(20.0 * 2.0 + 0.5 * (0.25 + 0.25))
    expected = 2 * (peak - 0.5) / 20.0
    result = xy_estimate(program(move(HERE, X=2.0)))
    assert result.total_s == pytest.approx(expected + OVERHEAD, abs=1e-9)
    assert expected == pytest.approx(0.58443, abs=1e-5)


def test_two_axes_move_together_so_the_longer_one_counts() -> None:
    both = xy_estimate(program(move(HERE, X=20.0, Y=2.0)))
    assert both.total_s == pytest.approx(2.45125 + OVERHEAD, abs=1e-9)


def test_moves_chain_from_where_the_last_one_ended_and_from_the_start_position() -> None:
    prog = program(move(HERE, X=20.0), move(HERE, X=40.0), move(HERE, X=40.0))
    result = xy_estimate(prog)
    step = 2.45125 + OVERHEAD
    assert result.cumulative_s == pytest.approx((step, 2 * step, 2 * step + OVERHEAD))
    from_30 = xy_estimate(program(move(HERE, X=10.0)), start={"X": 30.0})
    assert from_30.total_s == pytest.approx(2.45125 + OVERHEAD, abs=1e-9)


def test_wait_and_comment_cost_nothing() -> None:
    prog = program(
        Operation(OpKind.COMMENT, HERE, message="tool check"),
        move(HERE, X=20.0),
        Operation(OpKind.WAIT, HERE, message="swap the sample"),
    )
    result = xy_estimate(prog)
    assert result.cumulative_s[0] == 0.0
    assert result.cumulative_s[2] == result.cumulative_s[1] == result.total_s
    assert result.remaining_after(0) == result.total_s
    assert result.remaining_after(2) == 0.0


def test_slow_speed_and_the_device_parameters_are_used() -> None:
    prog = program(move(HERE, X=20.0))
    # Slow: 0.5 → 2 mm/s takes 0.075 s over 0.09375 mm each way, the rest at 2 mm/s.
    t_ramp, d_ramp = ramp(0.5, 2.0, 20.0)
    slow = xy_estimate(prog, fast=False)
    assert slow.total_s == pytest.approx(2 * t_ramp + (20 - 2 * d_ramp) / 2.0 + OVERHEAD)
    # A device that holds 5 mm/s fast and 50 mm/s² acceleration.
    held = {"X": {EchoType.FAST_SPEED: 5000, EchoType.ACCELERATION: 50_000}}
    t_ramp, d_ramp = ramp(0.5, 5.0, 50.0)
    result = estimate(prog, load_profile("xy-stage"), held, PERIOD_S)
    assert result.total_s == pytest.approx(2 * t_ramp + (20 - 2 * d_ramp) / 5.0 + OVERHEAD)


def test_the_overhead_follows_the_period() -> None:
    prog = program(move(HERE, X=20.0))
    slow_link = estimate(prog, load_profile("xy-stage"), {}, 0.5)
    assert slow_link.total_s - xy_estimate(prog).total_s == pytest.approx(0.2)


def test_s3_28_the_estimate_runs_the_speed_the_step_timer_gives_as_the_emulator_does() -> None:
    """At 256 microsteps 50 mm/s is 31.25 ticks of the 80 MHz timer; whole ticks make it
    31, i.e. 50.403 mm/s. The estimate times the move at that speed, and the emulated
    stage takes that long."""
    from protocol.clock import ManualClock
    from protocol.emulator.stage_firmware import StageConfig, StageFirmware
    from protocol.stage.codec import CommandFrame, CommandId, CommandPacket, encode_command

    held_values = {
        EchoType.MICROSTEPS: 256,
        EchoType.FAST_SPEED: 50_000,
        EchoType.ACCELERATION: 999_999,
    }
    held = {"X": held_values}
    prog = program(move(HERE, X=40.0))
    real = 80e6 / 31 / 51_200  # mm/s
    assert real == pytest.approx(50.4032, abs=1e-4)
    t_ramp, d_ramp = ramp(0.5, real, 999.999)
    expected = 2 * t_ramp + (40 - 2 * d_ramp) / real
    result = estimate(prog, load_profile("xy-stage"), held, PERIOD_S)
    assert result.total_s == pytest.approx(expected + OVERHEAD, abs=1e-9)
    exact = 2 * ramp(0.5, 50.0, 999.999)[0] + (40 - 2 * ramp(0.5, 50.0, 999.999)[1]) / 50.0
    assert expected < exact - 0.005  # the quantisation is visible: 6 ms over 40 mm

    clock = ManualClock()
    stage = StageFirmware(clock, StageConfig(parameters=held_values))
    nop = CommandPacket(CommandId.NOP)
    for packet in (CommandPacket(CommandId.SPEED, 1), CommandPacket(CommandId.MOVE_ABS, 40_000)):
        stage.receive(encode_command(CommandFrame((packet, nop), 0)))
        clock.advance(0.005)
        stage.run_until(clock.now())
    # The move began in the cycle its frame arrived in and has run that one cycle.
    remaining = stage.axes[0].time_to_idle()
    assert remaining is not None
    assert 0.005 + remaining == pytest.approx(expected, abs=1e-9)
