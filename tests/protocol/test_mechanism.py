"""Behaviour of the emulated stepper axis, against numbers worked out by hand.

The reference profile below is written from the textbook trapezoid, not from
the module, so a planning mistake in the module cannot hide in both.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from protocol.mechanism import Axis, AxisLimits, AxisState

TRAVEL = 50_000.0
MICROSTEP = 0.3125  # 1000 µm lead / (200 steps * 16)
MS = 1e-3


def make_axis(
    *, acceleration: float = 20_000.0, start_speed: float = 500.0, position: float = 0.0
) -> Axis:
    return Axis(
        AxisLimits(travel_um=TRAVEL, microstep_um=MICROSTEP),
        acceleration=acceleration,
        start_speed=start_speed,
        position_um=position,
    )


@dataclass(frozen=True)
class Sample:
    t: float
    x: float
    v: float
    state: AxisState


def record(axis: Axis, *, step: float, until: float) -> list[Sample]:
    """Samples every ``step`` seconds (starting now) for ``until`` seconds."""
    samples = [Sample(0.0, axis.position_um, axis.velocity, axis.state)]
    count = round(until / step)
    for i in range(1, count + 1):
        axis.advance(step)
        samples.append(Sample(i * step, axis.position_um, axis.velocity, axis.state))
    return samples


def record_until_idle(axis: Axis, *, step: float = MS, limit: float = 200.0) -> list[Sample]:
    samples = [Sample(0.0, axis.position_um, axis.velocity, axis.state)]
    t = 0.0
    while axis.moving:
        assert t < limit, "axis never came to rest"
        axis.advance(step)
        t += step
        samples.append(Sample(t, axis.position_um, axis.velocity, axis.state))
    return samples


def reference_profile(
    distance: float, speed: float, accel: float, start: float
) -> tuple[float, Callable[[float], tuple[float, float]]]:
    """Textbook move from rest: jump to start speed, ramp, cruise, ramp, jump to 0.

    Returns the duration and (position, speed) as a function of time.
    """
    s = min(start, speed)
    ramp_distance = (speed**2 - s**2) / (2 * accel)
    if 2 * ramp_distance <= distance:
        peak = speed
        t_ramp = (speed - s) / accel
        t_cruise = (distance - 2 * ramp_distance) / speed
    else:
        peak = math.sqrt(s**2 + accel * distance)
        t_ramp = (peak - s) / accel
        t_cruise = 0.0
        ramp_distance = distance / 2
    total = 2 * t_ramp + t_cruise

    def at(t: float) -> tuple[float, float]:
        if t <= t_ramp:
            return s * t + accel * t * t / 2, s + accel * t
        if t <= t_ramp + t_cruise:
            return ramp_distance + peak * (t - t_ramp), peak
        if t < total:
            r = total - t
            return distance - (s * r + accel * r * r / 2), s + accel * r
        return distance, 0.0

    return total, at


# --- the two textbook profiles --------------------------------------------------------


def test_20mm_at_5mm_s2_is_a_triangle_peaking_at_10mm_s_after_2s() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=0.0)
    axis.move_to(20_000.0, 10_000.0)

    assert axis.time_to_idle() == pytest.approx(4.0, abs=1e-9)
    expected = {  # t: (position µm, speed µm/s), from x = a t²/2 and its mirror image
        1.0: (2_500.0, 5_000.0),
        2.0: (10_000.0, 10_000.0),
        3.0: (17_500.0, 5_000.0),
        3.5: (19_375.0, 2_500.0),
    }
    now = 0.0
    for t, (x, v) in expected.items():
        axis.advance(t - now)
        now = t
        assert axis.position_um == pytest.approx(x, abs=1e-6)
        assert axis.velocity == pytest.approx(v, abs=1e-6)
    axis.advance(0.5 - MS)
    assert axis.moving
    axis.advance(2 * MS)
    assert not axis.moving
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 20_000.0


def test_20mm_at_20mm_s2_ramps_half_a_second_and_cruises_one_and_a_half() -> None:
    axis = make_axis(acceleration=20_000.0, start_speed=0.0)
    axis.move_to(20_000.0, 10_000.0)

    assert axis.time_to_idle() == pytest.approx(2.5, abs=1e-9)
    expected = {
        0.25: (625.0, 5_000.0, AxisState.ACCELERATING),
        0.75: (5_000.0, 10_000.0, AxisState.CRUISING),  # 2.5 mm ramp + 0.25 s cruise
        1.25: (10_000.0, 10_000.0, AxisState.CRUISING),
        1.9: (16_500.0, 10_000.0, AxisState.CRUISING),
        2.25: (19_375.0, 5_000.0, AxisState.DECELERATING),
    }
    now = 0.0
    for t, (x, v, state) in expected.items():
        axis.advance(t - now)
        now = t
        assert axis.position_um == pytest.approx(x, abs=1e-6)
        assert axis.velocity == pytest.approx(v, abs=1e-6)
        assert axis.state is state
    axis.advance(0.25 - MS)
    assert axis.moving
    axis.advance(2 * MS)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 20_000.0


@pytest.mark.parametrize(
    ("accel", "start", "duration"),
    [
        (5_000.0, 0.0, 4.0),
        (20_000.0, 0.0, 2.5),
        # start 2 mm/s: ramps of (10² - 2²)/(2a) mm, the rest cruised at 10 mm/s
        (5_000.0, 2_000.0, 1.6 + 0.08 + 1.6),
        (20_000.0, 2_000.0, 0.4 + 1.52 + 0.4),
    ],
)
def test_move_follows_the_textbook_profile_at_every_instant(
    accel: float, start: float, duration: float
) -> None:
    axis = make_axis(acceleration=accel, start_speed=start)
    axis.move_to(20_000.0, 10_000.0)
    total, at = reference_profile(20_000.0, 10_000.0, accel, start)
    assert total == pytest.approx(duration, abs=1e-12)
    assert axis.time_to_idle() == pytest.approx(duration, abs=1e-9)

    for sample in record(axis, step=0.01, until=duration + 0.1):
        if abs(sample.t - duration) < 1e-9:
            continue  # the final jump to 0: which side a sample falls is rounding
        x, v = at(sample.t)
        assert sample.x == pytest.approx(x, abs=1e-6), sample
        assert sample.v == pytest.approx(v, abs=1e-6), sample
    assert axis.microsteps == round(20_000.0 / MICROSTEP)


def test_start_speed_is_jumped_to_at_once_and_left_from_at_the_target() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=2_000.0)
    axis.move_to(20_000.0, 10_000.0)
    assert axis.velocity == 2_000.0
    axis.advance(1.0)
    assert axis.position_um == pytest.approx(2_000.0 + 2_500.0)
    assert axis.velocity == pytest.approx(7_000.0)
    axis.advance(3.28 - 1.0 - MS)
    assert axis.velocity == pytest.approx(2_000.0 + 5_000.0 * MS)
    axis.advance(2 * MS)
    assert axis.velocity == 0.0
    assert axis.position_um == 20_000.0


def test_short_move_is_triangular_and_long_move_trapezoidal() -> None:
    # At 20 mm/s², reaching 10 mm/s from 0.5 mm/s takes (10² - 0.5²)/40 = 2.49375 mm each way.
    short = make_axis()
    short.move_to(4_000.0, 10_000.0)
    short_samples = record_until_idle(short, step=0.1 * MS)
    assert AxisState.CRUISING not in {s.state for s in short_samples}
    peak = max(s.v for s in short_samples)
    assert peak == pytest.approx(math.sqrt(500.0**2 + 20_000.0 * 4_000.0), abs=5.0)

    long = make_axis()
    long.move_to(6_000.0, 10_000.0)
    long_samples = record_until_idle(long, step=0.1 * MS)
    cruising = [s for s in long_samples if s.state is AxisState.CRUISING]
    assert cruising and all(s.v == pytest.approx(10_000.0) for s in cruising)
    assert max(s.v for s in long_samples) == pytest.approx(10_000.0)


def test_commanded_speed_below_start_speed_runs_without_ramps() -> None:
    axis = make_axis(start_speed=2_000.0)
    axis.move_to(1_000.0, 1_000.0)
    assert axis.state is AxisState.CRUISING
    assert axis.velocity == 1_000.0
    assert axis.time_to_idle() == pytest.approx(1.0)
    axis.advance(1.0)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 1_000.0


# --- jogs, stops, re-planning ----------------------------------------------------------


def test_jog_reversal_brakes_to_start_speed_before_turning() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=500.0)
    axis.jog(+1, 10_000.0)
    axis.advance(3.0)
    # 1.9 s ramp from 0.5 to 10 mm/s covers 9.975 mm, then 1.1 s at 10 mm/s
    assert axis.position_um == pytest.approx(20_975.0)
    assert axis.state is AxisState.CRUISING

    axis.jog(-1, 10_000.0)
    assert axis.state is AxisState.DECELERATING
    samples = record(axis, step=MS, until=4.0)

    # Between 1 ms samples the speed changes by at most a * 1 ms = 5 µm/s.
    slack = 5_000.0 * MS + 1e-6
    for before, after in itertools.pairwise(samples):
        if before.v * after.v < 0:
            assert abs(before.v) <= 500.0 + slack
            assert abs(after.v) <= 500.0 + slack
    # turning point: 20.975 mm + (10² - 0.5²) / (2 * 5) mm
    assert max(s.x for s in samples) == pytest.approx(30_950.0, abs=1e-3)
    assert samples[-1].v == pytest.approx(-10_000.0)
    assert samples[-1].state is AxisState.CRUISING


def test_jog_reversal_turns_from_plus_to_minus_start_speed_exactly() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=500.0)
    axis.jog(+1, 10_000.0)
    axis.advance(3.0)
    axis.jog(-1, 10_000.0)
    axis.advance(1.9 - 1e-9)  # (10 - 0.5) mm/s at 5 mm/s²
    assert axis.velocity == pytest.approx(500.0)
    assert axis.state is AxisState.DECELERATING
    axis.advance(2e-9)
    assert axis.velocity == pytest.approx(-500.0)
    assert axis.state is AxisState.ACCELERATING
    assert axis.position_um == pytest.approx(30_950.0)


def test_stop_after_jog_decelerates_over_v_squared_over_2a() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=0.0)
    axis.jog(+1, 10_000.0)
    axis.advance(3.0)
    assert axis.position_um == pytest.approx(20_000.0)

    axis.stop()
    assert axis.state is AxisState.DECELERATING
    assert axis.time_to_idle() == pytest.approx(2.0)
    axis.advance(1.0)
    assert axis.velocity == pytest.approx(5_000.0)
    axis.advance(1.0 + MS)
    assert axis.state is AxisState.STOPPED
    assert axis.position_um == pytest.approx(20_000.0 + 10_000.0**2 / (2 * 5_000.0))


def test_jog_zero_with_start_speed_brakes_down_to_it_then_stops() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=500.0)
    axis.jog(+1, 10_000.0)
    axis.advance(3.0)
    axis.jog(0, 10_000.0)
    assert axis.time_to_idle() == pytest.approx(1.9)
    axis.advance(5.0)
    assert axis.state is AxisState.STOPPED
    assert axis.position_um == pytest.approx(20_975.0 + (10_000.0**2 - 500.0**2) / 10_000.0)


def test_new_target_behind_decelerates_reverses_and_arrives() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=500.0)
    axis.move_to(45_000.0, 10_000.0)
    axis.advance(3.0)  # cruising at 10 mm/s at 20.975 mm
    axis.move_to(10_000.0, 10_000.0)
    assert axis.state is AxisState.DECELERATING
    assert axis.velocity == pytest.approx(10_000.0)

    samples = record_until_idle(axis)
    assert max(s.x for s in samples) == pytest.approx(30_950.0, abs=1e-3)
    for before, after in itertools.pairwise(samples):
        if before.v * after.v < 0:
            assert abs(before.v) <= 500.0 + 5_000.0 * MS + 1e-6
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 10_000.0


def test_target_too_close_to_stop_for_is_overshot_then_reached() -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=500.0)
    axis.move_to(45_000.0, 10_000.0)
    axis.advance(3.0)  # at 20.975 mm; braking to 0.5 mm/s needs 9.975 mm
    axis.move_to(21_000.0, 10_000.0)
    samples = record_until_idle(axis)
    assert max(s.x for s in samples) == pytest.approx(30_950.0, abs=1e-3)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 21_000.0


@pytest.mark.parametrize(
    ("new_speed", "state_after", "duration_of_change"),
    [(15_000.0, AxisState.ACCELERATING, 1.0), (5_000.0, AxisState.DECELERATING, 1.0)],
)
def test_new_speed_while_cruising_ramps_to_it(
    new_speed: float, state_after: AxisState, duration_of_change: float
) -> None:
    axis = make_axis(acceleration=5_000.0, start_speed=500.0)
    axis.move_to(48_000.0, 10_000.0)
    axis.advance(2.0)  # cruising at 10 mm/s
    axis.move_to(48_000.0, new_speed)
    assert axis.state is state_after
    axis.advance(duration_of_change / 2)
    assert axis.velocity == pytest.approx((10_000.0 + new_speed) / 2)
    axis.advance(duration_of_change / 2 + MS)
    assert axis.state is AxisState.CRUISING
    assert axis.velocity == pytest.approx(new_speed)
    axis.advance(100.0)
    assert axis.position_um == 48_000.0


def test_repeating_a_command_every_frame_does_not_disturb_the_motion() -> None:
    # The stage's host repeats JOG in every frame and may repeat MOVE_ABS; each
    # repetition re-plans from the present state and must continue the same profile.
    once, repeated = make_axis(start_speed=0.0), make_axis(start_speed=0.0)
    once.move_to(20_000.0, 10_000.0)
    for _ in range(260):
        repeated.move_to(20_000.0, 10_000.0)
        repeated.advance(0.01)
        once.advance(0.01)
        assert repeated.position_um == pytest.approx(once.position_um, abs=1e-6)
        assert repeated.state is once.state
    assert repeated.state is AxisState.TARGET_REACHED

    jogged, held = make_axis(), make_axis()
    jogged.jog(+1, 10_000.0)
    for _ in range(100):
        held.jog(+1, 10_000.0)
        held.advance(0.02)
        jogged.advance(0.02)
        assert held.position_um == pytest.approx(jogged.position_um, abs=1e-6)
        assert held.velocity == pytest.approx(jogged.velocity, abs=1e-6)


def test_move_by_is_relative_to_the_present_position() -> None:
    axis = make_axis(position=1_000.0)
    axis.move_by(2_500.0, 5_000.0)
    assert axis.target_um == 3_500.0
    axis.advance(10.0)
    assert axis.position_um == 3_500.0
    axis.move_by(-500.0, 5_000.0)
    axis.advance(10.0)
    assert axis.position_um == 3_000.0


def test_estop_stops_dead_and_stop_while_idle_changes_nothing() -> None:
    axis = make_axis()
    axis.stop()
    axis.estop()
    assert axis.state is AxisState.IDLE

    axis.jog(+1, 10_000.0)
    axis.advance(1.0)
    where = axis.position_um
    axis.estop()
    assert axis.velocity == 0.0
    assert not axis.moving
    assert axis.state is AxisState.STOPPED
    assert axis.position_um == where

    axis.move_to(0.0, 10_000.0)
    axis.advance(10.0)
    axis.stop()
    assert axis.state is AxisState.TARGET_REACHED


# --- end switches, homing, frames -----------------------------------------------------


def test_move_past_travel_runs_into_high_switch_without_braking() -> None:
    axis = make_axis(position=40_000.0)
    axis.move_to(60_000.0, 10_000.0)
    assert axis.target_um == TRAVEL
    # ramp 0.475 s over 2.49375 mm, then 7.50625 mm at 10 mm/s
    assert axis.time_to_idle() == pytest.approx(0.475 + 0.750625)

    samples = record_until_idle(axis, step=0.1 * MS)
    assert all(s.x <= TRAVEL for s in samples)
    assert samples[-2].v == pytest.approx(10_000.0)  # full speed until the switch
    assert samples[-1].t == pytest.approx(0.475 + 0.750625, abs=0.1 * MS)
    assert axis.state is AxisState.END_SWITCH
    assert axis.position_um == TRAVEL
    assert axis.velocity == 0.0
    assert axis.end_switch_high


def test_move_to_exactly_travel_arrives_rather_than_crashes() -> None:
    axis = make_axis(position=40_000.0)
    axis.move_to(TRAVEL, 10_000.0)
    samples = record_until_idle(axis)
    assert all(s.x <= TRAVEL for s in samples)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == TRAVEL
    assert axis.end_switch_high

    axis.move_to(0.0, 10_000.0)
    axis.advance(20.0)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 0.0
    assert axis.end_switch_low


def test_axis_on_a_switch_refuses_to_push_into_it_but_may_leave() -> None:
    axis = make_axis(position=40_000.0)
    axis.move_to(TRAVEL, 10_000.0)
    axis.advance(10.0)

    axis.jog(+1, 10_000.0)
    assert axis.state is AxisState.END_SWITCH
    assert not axis.moving
    assert axis.position_um == TRAVEL

    axis.jog(-1, 10_000.0)
    assert axis.moving
    axis.advance(1.0)
    assert axis.position_um < TRAVEL
    assert not axis.end_switch_high


def test_home_from_30mm_seeks_backs_off_one_microstep_and_calls_it_zero() -> None:
    axis = make_axis(position=30_000.0)
    axis.home(2_000.0)
    # seek: 0.075 s ramp 0.5 -> 2 mm/s (93.75 µm), 29 906.25 µm at 2 mm/s;
    # back off one microstep at the 0.5 mm/s start speed
    seek = 0.075 + 29_906.25 / 2_000.0
    duration = seek + MICROSTEP / 500.0
    assert axis.time_to_idle() == pytest.approx(duration)

    axis.advance(seek - MS)
    assert axis.state is AxisState.HOMING
    assert axis.velocity == pytest.approx(-2_000.0)
    axis.advance(MS + 0.0001)
    assert axis.state is AxisState.HOMING
    assert axis.end_switch_low
    assert axis.velocity == pytest.approx(500.0)
    assert axis.position_um == pytest.approx(0.05)

    axis.advance(0.001)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 0.0
    assert not axis.end_switch_low

    # the switch is one microstep below the new zero
    axis.jog(-1, 1_000.0)
    axis.advance(1.0)
    assert axis.state is AxisState.END_SWITCH
    assert axis.position_um == pytest.approx(-MICROSTEP)


def test_homing_shows_homing_throughout() -> None:
    axis = make_axis(position=30_000.0)
    axis.home(2_000.0)
    samples = record_until_idle(axis, step=10 * MS)
    assert all(s.state is AxisState.HOMING for s in samples[:-1])
    assert min(s.x for s in samples) >= 0.0
    assert samples[-1].state is AxisState.TARGET_REACHED


def test_home_with_zero_start_speed_backs_off_at_homing_speed() -> None:
    axis = make_axis(start_speed=0.0, position=1_000.0)
    axis.home(2_000.0)
    axis.advance(10.0)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == 0.0


def test_set_position_shifts_the_frame_but_switches_stay_put() -> None:
    axis = make_axis(position=10_000.0)
    axis.set_position(0.0)
    assert axis.position_um == 0.0
    assert axis.microsteps == 0

    axis.jog(-1, 5_000.0)
    axis.advance(10.0)
    assert axis.state is AxisState.END_SWITCH
    assert axis.position_um == pytest.approx(-10_000.0)
    assert axis.end_switch_low

    # Travel is a logical soft limit, the high switch a physical one: in this
    # frame 50 mm logical is 60 mm physical, beyond the switch at 50 mm.
    axis.move_to(TRAVEL, 10_000.0)
    axis.advance(20.0)
    assert axis.state is AxisState.END_SWITCH
    assert axis.position_um == pytest.approx(TRAVEL - 10_000.0)


def test_set_position_during_a_move_keeps_the_physical_destination() -> None:
    axis = make_axis()
    axis.move_to(20_000.0, 10_000.0)
    axis.advance(1.0)
    before = axis.position_um
    axis.set_position(before + 1_000.0)
    assert axis.target_um == 21_000.0
    axis.advance(10.0)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == pytest.approx(21_000.0)


def test_triggered_switch_stops_a_motion_towards_it_at_once() -> None:
    axis = make_axis()
    axis.jog(+1, 10_000.0)
    axis.advance(1.0)
    where = axis.position_um
    axis.trigger_end_switch("high")
    assert axis.state is AxisState.END_SWITCH
    assert axis.velocity == 0.0
    assert axis.position_um == where
    assert axis.end_switch_high

    axis.jog(+1, 10_000.0)
    assert not axis.moving
    axis.jog(-1, 10_000.0)
    axis.advance(0.1)
    assert axis.moving
    assert not axis.end_switch_high


def test_shrinking_the_travel_moves_the_high_switch() -> None:
    axis = make_axis(position=30_000.0)
    axis.limits = AxisLimits(travel_um=20_000.0, microstep_um=MICROSTEP)
    assert axis.end_switch_high
    axis.jog(+1, 1_000.0)
    assert axis.state is AxisState.END_SWITCH


def test_travel_shrinking_under_a_moving_axis_stops_it_on_the_switch() -> None:
    axis = make_axis(position=25_000.0)
    axis.jog(+1, 2_000.0)
    axis.advance(0.5)
    axis.limits = AxisLimits(travel_um=20_000.0, microstep_um=MICROSTEP)
    assert axis.state is AxisState.END_SWITCH
    assert not axis.moving


def test_stop_during_homing_abandons_it() -> None:
    axis = make_axis(position=30_000.0)
    axis.home(2_000.0)
    axis.advance(1.0)
    axis.stop()
    axis.advance(1.0)
    assert axis.state is AxisState.STOPPED
    assert axis.position_um > 20_000.0


def test_position_is_quantised_to_the_nearest_microstep() -> None:
    axis = make_axis(position=0.47)  # 1.504 microsteps
    assert axis.microsteps == 2
    assert axis.position_quantised_um == 0.625
    assert make_axis(position=0.15625).microsteps == 1  # exactly half: rounds up
    assert make_axis(position=0.15).microsteps == 0


def test_time_to_idle_is_none_for_a_jog_and_zero_at_rest() -> None:
    axis = make_axis()
    assert axis.time_to_idle() == 0.0
    axis.jog(+1, 1_000.0)
    assert axis.time_to_idle() is None


def test_rejects_nonsense_commands() -> None:
    axis = make_axis()
    with pytest.raises(ValueError):
        axis.move_to(1_000.0, 0.0)
    with pytest.raises(ValueError):
        axis.jog(2, 1_000.0)
    with pytest.raises(ValueError):
        axis.advance(-1.0)
    with pytest.raises(ValueError):
        axis.acceleration = 0.0


# --- properties over many scenarios ---------------------------------------------------

Command = tuple[str, float, float]

speeds = st.floats(min_value=100.0, max_value=30_000.0)
commands: st.SearchStrategy[Command] = st.one_of(
    st.tuples(st.just("move"), st.floats(min_value=-10_000.0, max_value=60_000.0), speeds),
    st.tuples(st.just("jog"), st.sampled_from([-1.0, 1.0]), speeds),
    st.tuples(st.just("home"), st.just(0.0), speeds),
    st.tuples(st.just("stop"), st.just(0.0), speeds),
)
# The firmware stores start speed as whole µm/s; a start speed of 1e-300 would make
# homing's back-off take longer than the age of the universe.
start_speeds = st.one_of(st.just(0.0), st.floats(min_value=1.0, max_value=3_000.0))
dynamics = st.tuples(
    st.floats(min_value=1_000.0, max_value=100_000.0),  # acceleration
    start_speeds,
    st.floats(min_value=0.0, max_value=TRAVEL),  # initial position
)


def apply(axis: Axis, command: Command) -> None:
    kind, value, speed = command
    if kind == "move":
        axis.move_to(value, speed)
    elif kind == "jog":
        axis.jog(int(value), speed)
    elif kind == "home":
        axis.home(speed)
    else:
        axis.stop()


def axis_with(dyn: tuple[float, float, float]) -> Axis:
    accel, start, position = dyn
    return make_axis(acceleration=accel, start_speed=start, position=position)


@settings(max_examples=300, deadline=None)
@given(
    dyn=dynamics,
    first=commands,
    second=commands,
    pieces=st.lists(st.floats(min_value=0.0, max_value=2.0), min_size=1, max_size=40),
    split=st.integers(min_value=0, max_value=40),
)
def test_one_big_step_equals_many_small_ones(
    dyn: tuple[float, float, float],
    first: Command,
    second: Command,
    pieces: list[float],
    split: int,
) -> None:
    split = min(split, len(pieces))
    stepped, leaped = axis_with(dyn), axis_with(dyn)
    for axis in (stepped, leaped):
        apply(axis, first)

    for piece in pieces[:split]:
        stepped.advance(piece)
    leaped.advance(sum(pieces[:split]))
    for axis in (stepped, leaped):
        apply(axis, second)
    for piece in pieces[split:]:
        stepped.advance(piece)
    leaped.advance(sum(pieces[split:]))

    assert stepped.position_um == pytest.approx(leaped.position_um, abs=1e-6)
    assert stepped.velocity == pytest.approx(leaped.velocity, abs=1e-6)
    assert stepped.moving == leaped.moving
    if not stepped.moving:
        assert stepped.state is leaped.state


@settings(max_examples=200, deadline=None)
@given(dyn=dynamics, command=commands, head_start=st.floats(min_value=0.0, max_value=3.0))
def test_time_to_idle_is_when_the_axis_actually_comes_to_rest(
    dyn: tuple[float, float, float], command: Command, head_start: float
) -> None:
    axis = axis_with(dyn)
    apply(axis, command)
    axis.advance(head_start)
    remaining = axis.time_to_idle()
    if remaining is None:  # a jog: only the operator ends it
        assert command[0] == "jog"
        return
    if remaining > 1e-6:
        axis.advance(remaining - 1e-6)
        assert axis.moving
    axis.advance(2e-6)
    assert not axis.moving


@settings(max_examples=200, deadline=None)
@given(
    accel=st.floats(min_value=1_000.0, max_value=100_000.0),
    start_speed=start_speeds,
    origin=st.floats(min_value=0.0, max_value=TRAVEL),
    target=st.floats(min_value=0.0, max_value=TRAVEL),
    speed=speeds,
)
def test_move_from_rest_never_overshoots_nor_exceeds_its_speed(
    accel: float, start_speed: float, origin: float, target: float, speed: float
) -> None:
    axis = make_axis(acceleration=accel, start_speed=start_speed, position=origin)
    axis.move_to(target, speed)
    duration = axis.time_to_idle()
    assert duration is not None
    direction = 1.0 if target >= origin else -1.0
    samples = record(axis, step=max(duration, 1e-3) / 400, until=max(duration, 1e-3) * 1.01)
    for before, after in itertools.pairwise(samples):
        assert (after.x - before.x) * direction >= -1e-9  # monotonic
    assert all((s.x - target) * direction <= 1e-9 for s in samples)
    assert all(abs(s.v) <= speed * (1 + 1e-12) for s in samples)
    assert axis.state is AxisState.TARGET_REACHED
    assert axis.position_um == target
