"""The gamepad's mapping (app/gamepad/mapping.py): sticks and the enable button to a jog."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from app.gamepad.mapping import (
    DEAD_ZONE,
    IDLE,
    MIN_SPEED_SHARE,
    RELEASE_ZONE,
    PadReading,
    axis_direction,
    intent,
    speed_share,
)

stick = st.floats(min_value=-1.0, max_value=1.0)
any_number = st.floats(allow_nan=True, allow_infinity=True)
held = st.tuples(*(st.sampled_from((-1, 0, 1)),) * 3)


@given(x=any_number, y=any_number, z=any_number, was=held)
def test_nothing_jogs_without_the_enable_button(
    x: float, y: float, z: float, was: tuple[int, int, int]
) -> None:
    assert intent(PadReading(x, y, z, enable=False), was) == IDLE


@given(x=stick, y=stick, z=stick)
def test_a_stick_inside_the_dead_zone_never_starts_a_jog(x: float, y: float, z: float) -> None:
    inside = [max(-DEAD_ZONE, min(DEAD_ZONE, v)) for v in (x, y, z)]
    assert intent(PadReading(*inside, enable=True)) == IDLE


@given(
    value=st.floats(min_value=DEAD_ZONE, max_value=1.0, exclude_min=True), axis=st.integers(0, 2)
)
def test_past_the_dead_zone_each_axis_jogs_its_own_way(value: float, axis: int) -> None:
    for sign in (1, -1):
        sticks = [0.0, 0.0, 0.0]
        sticks[axis] = sign * value
        asked = intent(PadReading(*sticks, enable=True))
        expected = [0, 0, 0]
        expected[axis] = sign
        assert asked.directions == tuple(expected)
        assert MIN_SPEED_SHARE <= asked.speed <= 1.0


@given(value=st.floats(min_value=0.0, max_value=1.0), was=st.sampled_from((-1, 0, 1)))
def test_hysteresis_a_jogging_axis_stops_only_under_the_release_zone(
    value: float, was: int
) -> None:
    for sign in (1, -1):
        got = axis_direction(sign * value, was)
        if value > DEAD_ZONE:
            assert got == sign  # past the dead zone: that way, whatever it did before
        elif was == sign and value > RELEASE_ZONE:
            assert got == sign  # between the zones: goes on the way it went
        else:
            assert got == 0


@given(a=stick, b=stick)
def test_speed_grows_with_the_deflection_from_slow_to_the_keys_speed(a: float, b: float) -> None:
    low, high = sorted((abs(a), abs(b)))
    assert MIN_SPEED_SHARE <= speed_share(low) <= speed_share(high) <= 1.0
    assert speed_share(1.0) == 1.0 and speed_share(-1.0) == 1.0
    assert speed_share(DEAD_ZONE) == MIN_SPEED_SHARE


def test_the_speed_grows_slowly_at_small_deflections_as_the_usb3_joystick_does() -> None:
    halfway = DEAD_ZONE + (1 - DEAD_ZONE) / 2
    assert speed_share(halfway) < (MIN_SPEED_SHARE + 1) / 2  # below the straight line


@given(x=any_number, y=any_number, z=any_number, was=held)
def test_a_reading_that_is_no_number_moves_nothing_on_its_axis(
    x: float, y: float, z: float, was: tuple[int, int, int]
) -> None:
    asked = intent(PadReading(x, y, z, enable=True), was)
    for value, direction in zip((x, y, z), asked.directions, strict=True):
        if not math.isfinite(value):
            assert direction == 0
        else:
            assert direction in (-1, 0, 1)
    assert MIN_SPEED_SHARE <= asked.speed <= 1.0 and math.isfinite(asked.speed)


@given(x=stick, y=stick)
def test_the_speed_follows_the_axis_pushed_furthest(x: float, y: float) -> None:
    asked = intent(PadReading(x, y, enable=True))
    if asked.jogs:
        pushed = [abs(v) for v, d in zip((x, y), asked.directions, strict=False) if d]
        assert asked.speed == speed_share(max(pushed))
