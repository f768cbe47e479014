"""The envelope of the moves in flight: reports on the path pass, reports off it trip.

Property tests over random paths (2 and 3 coordinates, straight legs and arc
boxes): a machine that follows the path it was sent, with noise inside the
tolerance, is never stopped; a report farther than the tolerance from every
leg still ahead always is, and says how.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from app.machines.envelope import Envelope, Fault, arc_box

TRAVEL = 200.0
TOL = 0.5

coordinate = st.floats(0.0, TRAVEL, allow_nan=False, allow_infinity=False)


def points(dims: int) -> st.SearchStrategy[tuple[float, ...]]:
    return st.tuples(*[coordinate] * dims)


@st.composite
def paths(draw: st.DrawFn) -> tuple[int, list[tuple[float, ...]]]:
    dims = draw(st.sampled_from([1, 2, 3]))
    return dims, draw(st.lists(points(dims), min_size=2, max_size=12))


def envelope_for(dims: int, path: list[tuple[float, ...]]) -> Envelope:
    envelope = Envelope([(0.0, TRAVEL)] * dims, TOL)
    envelope.anchor(path[0])
    for i, target in enumerate(path[1:], start=1):
        envelope.add_line(target, f"line {i}", i)
    return envelope


def along(a: tuple[float, ...], b: tuple[float, ...], t: float) -> tuple[float, ...]:
    return tuple(x + t * (y - x) for x, y in zip(a, b, strict=True))


@settings(max_examples=300, deadline=None)
@given(
    paths(),
    st.lists(st.floats(0.0, 1.0), min_size=1, max_size=6),
    st.lists(st.floats(-0.99, 0.99), min_size=3, max_size=3),
)
def test_reports_along_the_path_in_order_never_trip(
    path_of: tuple[int, list[tuple[float, ...]]], stops: list[float], noise: list[float]
) -> None:
    dims, path = path_of
    envelope = envelope_for(dims, path)
    shift = [n * TOL / math.sqrt(dims) for n in noise[:dims]]
    for leg in range(1, len(path)):
        for t in sorted(stops):
            seen = along(path[leg - 1], path[leg], t)
            noisy = tuple(min(TRAVEL, max(0.0, s + d)) for s, d in zip(seen, shift, strict=True))
            assert envelope.check(noisy) is None, (leg, t, noisy)
    assert envelope.check(path[-1]) is None


@settings(max_examples=300, deadline=None)
@given(paths(), points(3), st.integers(0, 11))
def test_a_report_beyond_the_tolerance_of_every_leg_ahead_always_trips(
    path_of: tuple[int, list[tuple[float, ...]]], where: tuple[float, ...], progress: int
) -> None:
    dims, path = path_of
    envelope = envelope_for(dims, path)
    # The machine has gone some way along the path first.
    for leg in range(1, min(progress, len(path) - 1) + 1):
        assert envelope.check(path[leg]) is None
    ahead = envelope.legs
    seen = where[:dims]
    assume(all(leg.distance(seen) > TOL * 1.001 for leg in ahead))
    deviation = envelope.check(seen)
    assert deviation is not None
    assert deviation.seen == seen
    assert deviation.distance > TOL
    assert deviation.label.startswith("line ")
    # A report that trips changes nothing: the same report trips again.
    assert envelope.check(seen) is not None


@settings(max_examples=200, deadline=None)
@given(paths(), st.floats(1.01, 50.0))
def test_running_on_past_the_last_target_is_past_the_target(
    path_of: tuple[int, list[tuple[float, ...]]], beyond: float
) -> None:
    dims, path = path_of
    start, end = path[-2], path[-1]
    length = math.dist(start, end)
    assume(length > 1.0)
    envelope = envelope_for(dims, path)
    direction = tuple((e - s) / length for s, e in zip(start, end, strict=True))
    seen = tuple(e + beyond * TOL * d for e, d in zip(end, direction, strict=True))
    assume(all(0.0 <= c <= TRAVEL for c in seen))
    assume(all(leg.distance(seen) > TOL for leg in envelope.legs))
    deviation = envelope.check(seen)
    assert deviation is not None
    assert deviation.fault is Fault.PAST_TARGET
    assert deviation.expected == end
    assert deviation.label == f"line {len(path) - 1}"


def test_the_corrupted_usb3_count_is_outside_the_travel_and_names_the_move() -> None:
    # X000000000019200; arrived as 1 000 019 200 counts: 3 mm sent, 156 m run.
    envelope = Envelope([(0.0, 200.0)], TOL, hold_at_rest=False)
    envelope.anchor((0.0,))
    envelope.add_line((3.0,), "X +3.000 mm", "move")
    assert envelope.check((1.2,)) is None
    assert envelope.check((3.0,)) is None
    deviation = envelope.check((3.6,))
    assert deviation is not None and deviation.fault is Fault.PAST_TARGET
    assert deviation.expected == (3.0,) and deviation.label == "X +3.000 mm"
    deviation = envelope.check((156_253.0,))
    assert deviation is not None and deviation.fault is Fault.OUTSIDE_TRAVEL


def test_a_path_that_turns_back_on_itself_is_followed_past_the_turn() -> None:
    """Relay usb3 seed 103: Y 0 → 3200, then back to 1600, that move arriving twice (the unit
    adds it): Y ran on to 0 along the first leg's stretch, every report passing, and the
    job said done."""
    envelope = Envelope([(-1e6, 1e6)], 64.0, hold_at_rest=False)
    envelope.anchor((0.0,))
    envelope.add_line((3200.0,), "Y +0.500 mm", "first")
    envelope.add_line((1600.0,), "Y -0.250 mm", "back")
    for count in (1000.0, 3200.0, 2500.0, 1600.0):
        assert envelope.check((count,)) is None, count
    deviation = envelope.check((1484.0,))
    assert deviation is not None and deviation.fault is Fault.PAST_TARGET
    assert deviation.label == "Y -0.250 mm"


def test_at_rest_a_usb3_axis_follows_its_joystick_but_not_out_of_the_travel() -> None:
    """Relay usb3 seed 134: a move nobody sent (its count changed on the wire) ran at rest,
    each report taken for the joystick's, to 3125 mm on a 200 mm travel."""
    envelope = Envelope([(0.0, 200.0)], TOL, hold_at_rest=False, travel_at_rest=True)
    envelope.anchor((10.0,))
    assert envelope.check((40.0,)) is None  # the joystick: it rests there now
    assert envelope.check((199.0,)) is None
    deviation = envelope.check((203.0,))
    assert deviation is not None and deviation.fault is Fault.OUTSIDE_TRAVEL
    loose = Envelope([(0.0, 200.0)], TOL, hold_at_rest=False)
    loose.anchor((10.0,))
    assert loose.check((203.0,)) is None  # the G-code boards' way: not judged at rest


def test_a_mangled_line_that_leaves_the_path_trips_and_names_the_line_sent() -> None:
    # "G1 X18.000 Y18.000 F3000" arrived as "G1 X18.F3000": the pen runs along Y = 5.
    envelope = Envelope([(0.0, 300.0), (0.0, 200.0)], TOL)
    envelope.anchor((5.0, 5.0))
    envelope.add_line((18.0, 18.0), "G1 X18.000 Y18.000 F3000", 7)
    assert envelope.check((5.3, 5.0)) is None  # not yet told apart
    deviation = envelope.check((9.0, 5.0))
    assert deviation is not None and deviation.fault is Fault.OFF_PATH
    assert deviation.tag == 7 and deviation.label == "G1 X18.000 Y18.000 F3000"
    assert deviation.expected == pytest.approx((7.0, 7.0))


def test_arcs_are_judged_by_their_box_and_the_path_goes_on_after_them() -> None:
    envelope = Envelope([(0.0, 300.0), (0.0, 200.0)], TOL)
    envelope.anchor((10.0, 0.0))
    # A half circle about (0, 0) would leave the travel: about (20, 0), radius 10, up and over.
    low, high = arc_box((10.0, 0.0), (30.0, 0.0), (20.0, 0.0), (0, 1))
    assert low == (10.0, -10.0) and high == (30.0, 10.0)
    envelope.add_box(low, high, (30.0, 0.0), "G2 X30 Y0 I10 J0")
    envelope.add_line((30.0, 20.0), "G1 Y20")
    for angle in range(0, 181, 15):
        a = math.radians(180 - angle)
        assert envelope.check((20.0 + 10.0 * math.cos(a), 10.0 * math.sin(a))) is None
    assert envelope.check((30.0, 12.0)) is None
    deviation = envelope.check((20.0, 9.0))  # back inside the arc's box: behind the machine
    assert deviation is not None and deviation.label == "G1 Y20"


def test_at_rest_a_machine_with_controls_of_its_own_may_move_one_without_may_not() -> None:
    held = Envelope([(0.0, 50.0)], TOL)
    free = Envelope([(0.0, 50.0)], TOL, hold_at_rest=False)
    for envelope in (held, free):
        envelope.anchor((10.0,))
    deviation = held.check((12.0,))
    assert deviation is not None and deviation.fault is Fault.MOVED_AT_REST
    assert free.check((12.0,)) is None and free.end == (12.0,)
    free.add_line((20.0,), "X 20")
    assert free.check((11.0,)) is not None  # from its new rest, not the old one


def test_nothing_is_judged_while_the_path_is_unknown_and_legs_behind_are_dropped() -> None:
    envelope = Envelope([(0.0, 50.0), (0.0, 50.0)], TOL)
    assert envelope.check((99.0, 99.0)) is None  # before any anchor
    assert envelope.add_line((1.0, 1.0), "G1") is None
    envelope.anchor((0.0, 0.0))
    first = envelope.add_line((10.0, 0.0), "a")
    second = envelope.add_line((10.0, 10.0), "b")
    assert (first, second) == (0, 1)
    envelope.behind(1)
    assert envelope.in_flight == 1
    assert envelope.check((5.0, 0.0)) is not None  # leg a is done: not there any more
    envelope.release()  # homing
    assert envelope.check((40.0, 40.0)) is None


def test_a_loosened_path_allows_its_box_and_nothing_outside() -> None:
    envelope = Envelope([(0.0, 50.0), (0.0, 50.0)], TOL)
    envelope.anchor((0.0, 0.0))
    envelope.add_line((10.0, 0.0), "a")
    envelope.add_line((10.0, 10.0), "b (refused)")
    envelope.add_line((0.0, 10.0), "c")
    envelope.loosen("after a refused line")
    assert envelope.in_flight == 1
    assert envelope.check((5.0, 5.0)) is None  # a straight cut across: allowed now
    deviation = envelope.check((15.0, 5.0))
    assert deviation is not None and deviation.label == "after a refused line"


def test_a_tolerance_that_is_no_length_is_refused() -> None:
    for bad in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(ValueError):
            Envelope([(0.0, 1.0)], bad)
