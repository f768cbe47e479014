"""GRBL 1.1's motion planner as pure arithmetic: junction speeds, look-ahead, speed profiles.

A GRBL board does not stop between blocks.  Each block keeps the largest
speed at which it may be entered (``max_entry_sqr``): the lower of its own
and the previous block's nominal speed, and the junction speed of the
corner between them (``$11``, the junction deviation: the corner is taken
as if on a circle that far inside it, at the acceleration the axes allow
across it).  Whenever a block is added, the blocks in the planner are
planned again: backwards from the newest, which must be able to stop at its
end (nothing is known after it), then forwards from the one being executed,
so that no block needs more than its acceleration.  Each block then runs a
trapezoid from its entry speed to the next one's (its exit speed).

Speeds here are mm/s and accelerations mm/s² (GRBL works in mm/min and
mm/min², which changes no result); squared speeds are kept squared as GRBL
keeps them.  The emulator plans block by block as lines arrive
(:func:`replan`); the station's estimate plans a whole file at once with
numpy (:func:`lookahead_entries`, :func:`profile_seconds`), assuming the
sender keeps the planner full, and both time a block with the same
:func:`profile`.  Written from GRBL's documented behaviour and the
arithmetic of its planner; no GRBL source is used.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

#: GRBL's "no limit" (a straight junction, or an axis that does not move).
UNLIMITED = 1e38
#: GRBL's ``$11`` default: 0.010 mm.
DEFAULT_JUNCTION_DEVIATION = 0.010
#: GRBL 1.1 on an ATmega328p: 16 blocks, one of which is always left free.
GRBL_PLANNER_BLOCKS = 15
#: |cos| past which a junction is taken as straight on or as a full reversal (GRBL's bound).
_STRAIGHT = 0.999999

FloatArray = npt.NDArray[np.float64]


def unit_vector(delta: Sequence[float]) -> tuple[float, tuple[float, ...]]:
    """The length of ``delta`` and its direction (all zeros for a zero vector)."""
    length = math.sqrt(sum(d * d for d in delta))
    if length == 0.0:
        return 0.0, tuple(0.0 for _ in delta)
    return length, tuple(d / length for d in delta)


def axis_limited(limits: Sequence[float], unit: Sequence[float]) -> float:
    """The largest value along ``unit`` that keeps every axis within its own limit.

    An axis doing a share ``|u|`` of the motion reaches its limit when the
    motion's value is ``limit / |u|``; the least of those bounds the block.
    """
    value = UNLIMITED
    for limit, u in zip(limits, unit, strict=True):
        if u != 0.0:
            value = min(value, abs(limit / u))
    return value


def junction_speed_sqr(
    previous_unit: Sequence[float],
    unit: Sequence[float],
    accelerations: Sequence[float],
    deviation: float,
) -> float:
    """The squared speed (mm²/s²) at which a block may enter from the previous block.

    The corner is rounded by a circle touching both blocks whose edge lies
    ``deviation`` mm from the corner; the speed is the one at which that
    circle's centripetal acceleration is the acceleration the axes allow in
    the direction of the change of velocity.  Straight on is unlimited; a
    reversal is zero.
    """
    cos_theta = -sum(p * u for p, u in zip(previous_unit, unit, strict=True))
    if cos_theta > _STRAIGHT:
        return 0.0  # back the way it came: stop first
    if cos_theta < -_STRAIGHT:
        return UNLIMITED  # straight on
    _, change = unit_vector([u - p for p, u in zip(previous_unit, unit, strict=True)])
    acceleration = axis_limited(accelerations, change)
    sin_half = math.sqrt(0.5 * (1.0 - cos_theta))
    return max(0.0, acceleration * deviation * sin_half / (1.0 - sin_half))


def max_entry_sqr(junction_sqr: float, nominal: float, previous_nominal: float) -> float:
    """The most a block may be entered at: neither block's nominal speed, nor the corner's."""
    slower = min(nominal, previous_nominal)
    return min(slower * slower, junction_sqr)


def replan(
    first_entry_sqr: float,
    lengths: Sequence[float],
    accelerations: Sequence[float],
    max_entries_sqr: Sequence[float],
) -> list[float]:
    """Entry speeds² of consecutive blocks, the first entered at ``first_entry_sqr``.

    The last block must be able to stop at its end.  Reverse pass: each block
    is entered no faster than it can brake from to the next one's entry over
    its length; forward pass: no faster than the block before can reach from
    its own entry.  The first block's entry is given (the block under way,
    from its present speed over what is left of it).
    """
    count = len(lengths)
    entries = [0.0] * count
    if count == 0:
        return entries
    entries[0] = first_entry_sqr
    after = 0.0  # the last block stops at its end
    for k in range(count - 1, 0, -1):
        after = min(max_entries_sqr[k], after + 2.0 * accelerations[k] * lengths[k])
        entries[k] = after
    for k in range(1, count):
        reachable = entries[k - 1] + 2.0 * accelerations[k - 1] * lengths[k - 1]
        if reachable < entries[k]:
            entries[k] = reachable
    return entries


def profile(
    distance: float, entry: float, exit_speed: float, nominal: float, acceleration: float
) -> tuple[tuple[float, float, float], ...]:
    """A block's motion as phases ``(start speed, acceleration, seconds)``.

    Accelerate from ``entry`` towards ``nominal``, cruise, decelerate to
    ``exit_speed`` (GRBL's trapezoid); a triangle when the block is too short
    to reach ``nominal``; only one ramp when its ends are as far apart as the
    acceleration allows over the block.
    """
    if distance <= 0.0:
        return ()
    a = acceleration
    entry_sqr, exit_sqr, nominal_sqr = entry * entry, exit_speed * exit_speed, nominal * nominal
    # Where, counted back from the end, accelerating from the entry meets decelerating to the exit.
    meet = 0.5 * (distance + (entry_sqr - exit_sqr) / (2.0 * a))
    if meet <= 0.0:  # accelerating all the way
        top = math.sqrt(entry_sqr + 2.0 * a * distance)
        return ((entry, a, (top - entry) / a),)
    if meet >= distance:  # decelerating all the way
        low = math.sqrt(max(entry_sqr - 2.0 * a * distance, 0.0))
        return ((entry, -a, (entry - low) / a),)
    braking = (nominal_sqr - exit_sqr) / (2.0 * a)
    if braking < meet:  # reaches its nominal speed
        speeding = (nominal_sqr - entry_sqr) / (2.0 * a)
        cruise = distance - speeding - braking
        phases = []
        if nominal > entry:
            phases.append((entry, a, (nominal - entry) / a))
        if cruise > 0.0:
            phases.append((nominal, 0.0, cruise / nominal))
        if nominal > exit_speed:
            phases.append((nominal, -a, (nominal - exit_speed) / a))
        return tuple(phases)
    peak = math.sqrt(2.0 * a * meet + exit_sqr)
    return ((entry, a, (peak - entry) / a), (peak, -a, (peak - exit_speed) / a))


# -- the whole file at once (the station's estimate) ----------------------------------------


def lookahead_entries(
    lengths: FloatArray,
    accelerations: FloatArray,
    max_entries_sqr: FloatArray,
    planner_blocks: int = GRBL_PLANNER_BLOCKS,
) -> FloatArray:
    """Entry speeds² of every block of a stream planned as GRBL plans it while kept full.

    A block ``j`` is entered when the block before it ends; by then the
    planner holds that block and the ``planner_blocks - 1`` after it, the last
    of which must be able to stop: so ``j``'s entry is at most what a reverse
    pass over ``j … j + planner_blocks - 2`` gives.  A block whose
    ``max_entries_sqr`` is 0 starts from rest (the first, and each after a
    stop such as a dwell or a pen change, where GRBL empties its planner),
    and nothing is planned across it.  The forward pass is the running
    minimum ``e[j] = min(r[j], e[j-1] + 2·a·L)``, solved in closed form over
    prefix sums.  A whole file of a million blocks takes a few numpy passes.
    """
    count = len(lengths)
    if count == 0:
        return np.zeros(0)
    window = max(planner_blocks - 1, 1)
    # Past the last block: blocks that stop at once and go nowhere (the planner's end).
    gain = np.concatenate((2.0 * accelerations * lengths, np.zeros(window)))
    limit = np.concatenate((max_entries_sqr, np.zeros(window)))
    # Reverse pass over each block's window.  A stop inside the window needs no care of
    # its own: its limit is 0, so the blocks before it brake to a standstill there.
    reverse = np.zeros(count)
    for k in range(window - 1, -1, -1):
        reverse = np.minimum(limit[k : k + count], reverse + gain[k : k + count])
    # Forward: e[j] = min over i <= j of r[i] + sum(gain[i:j]), a running minimum over
    # prefix sums.  A stop has r = 0, so nothing before it can win after it.
    before = np.concatenate(([0.0], np.cumsum(gain[: count - 1])))
    entries: FloatArray = np.minimum.accumulate(reverse - before) + before
    return np.maximum(entries, 0.0)


def profile_seconds(
    lengths: FloatArray,
    entries: FloatArray,
    exits: FloatArray,
    nominals: FloatArray,
    accelerations: FloatArray,
) -> FloatArray:
    """Seconds of each block's :func:`profile`, for arrays of blocks."""
    a = accelerations
    entry_sqr, exit_sqr, nominal_sqr = entries * entries, exits * exits, nominals * nominals
    meet = 0.5 * (lengths + (entry_sqr - exit_sqr) / (2.0 * a))
    with np.errstate(invalid="ignore", divide="ignore"):
        top = np.sqrt(entry_sqr + 2.0 * a * lengths)
        low = np.sqrt(np.maximum(entry_sqr - 2.0 * a * lengths, 0.0))
        braking = (nominal_sqr - exit_sqr) / (2.0 * a)
        speeding = (nominal_sqr - entry_sqr) / (2.0 * a)
        cruise = np.maximum(lengths - speeding - braking, 0.0)
        trapezoid = (
            np.maximum(nominals - entries, 0.0) / a
            + cruise / nominals
            + np.maximum(nominals - exits, 0.0) / a
        )
        peak = np.sqrt(np.maximum(2.0 * a * meet + exit_sqr, 0.0))
        triangle = (peak - entries) / a + (peak - exits) / a
        seconds = np.where(
            meet <= 0.0,
            (top - entries) / a,
            np.where(
                meet >= lengths,
                (entries - low) / a,
                np.where(braking < meet, trapezoid, triangle),
            ),
        )
    timed: FloatArray = np.where(lengths > 0.0, seconds, 0.0)
    return timed
