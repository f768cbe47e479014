"""How long a G-code program takes: per move a trapezoid from its feed and the axes' limits.

The stage's estimate replays every move on the emulator's mechanism, which is
exact for a machine that runs one move at a time but would take far too long
for a plotter file of a million lines, and a G-code board plans on its own
anyway.  Here every quantity is a numpy column, so a million moves are timed
in a fraction of a second:

* each move runs at its feed (F, mm/min, modal) but never faster than the
  slowest of its axes allows (``max_speed`` in mm/s, scaled by how much of
  the move the axis does); G0 and homing run at that limit;
* it accelerates and decelerates at the axes' ``max_acceleration`` (mm/s²,
  likewise scaled);
* on a machine whose profile gives a junction deviation (GRBL's ``$11``)
  the moves join at speed as GRBL plans them
  (:mod:`protocol.gcode.junctions`, the planner the emulated GRBL board
  runs): every segment of the path, arcs flattened as GRBL flattens them,
  is a planner block; consecutive blocks meet at their junction speed and
  each is planned with the ``planner_blocks`` GRBL holds, the last of them
  able to stop, as when the station keeps the board's planner full.  A pen
  change or a dwell stops the motion first (GRBL empties its planner);
* elsewhere every move starts and ends at rest: a trapezoid, or a triangle
  when the move is too short to reach its speed, and an arc is one move
  over the length of its flattened path, at the limit of its most
  demanding segment;
* on a firmware that ignores F (the profile's ``step_interval_us``, the
  CoreXY plotter: FIDELITY S1-01) every move, G0 or G1, is its lead motor's
  whole steps at the step interval of the last ``M98`` before it, as that
  firmware steps without ramps;
* ``G4`` dwells add their time; pen commands and other lines cost nothing
  here (the file's own dwells after pen moves are what the servo needs).

A string-art program moves one axis per operation, millions of them: it is
timed from its own columns (the same trapezoids, without building the path).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

import numpy as np

from app.jobs.estimate.model import Estimate
from app.jobs.formats.gcode.loader import HOME, LINEAR, NO_MOTION, RAPID, GcodeProgram
from app.jobs.formats.gcode.program import PEN_DOWN, PEN_UP, WAIT
from app.jobs.formats.string_art.program import AXES as WINDER_AXES
from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.program import Program, ProgramPath
from app.profiles import MachineProfile
from protocol.gcode.junctions import lookahead_entries, profile_seconds

#: Operations of a string-art program timed at a time (see :func:`_one_axis_moves`).
ESTIMATE_CHUNK = 1 << 18


def estimate_gcode(
    program: Program,
    profile: MachineProfile,
    *,
    start: Mapping[str, float] | None = None,
) -> Estimate:
    """Time ``program`` on ``profile`` from ``start`` (mm per axis name; 0 when unknown).

    Any program can be timed (a point list on a plotter runs at the axes'
    top speed); a :class:`GcodeProgram` brings its feeds, motion modes and
    dwells.
    """
    n = len(program)
    if n == 0:
        return Estimate(0.0, np.zeros(0))
    if isinstance(program, StringArtProgram):
        return _one_axis_moves(program, profile, start or {})
    axes = tuple(axis.name for axis in profile.axes)
    top_speed = np.array([axis.max_speed for axis in profile.axes], dtype=np.float64)
    top_accel = np.array([axis.max_acceleration for axis in profile.axes], dtype=np.float64)
    origin = np.array([(start or {}).get(axis, 0.0) for axis in axes], dtype=np.float64)

    path = program.path(axes)
    coords = np.where(np.isnan(path.coords), origin, path.coords)
    previous = np.vstack([origin[None, :], coords[:-1]])

    if isinstance(program, GcodeProgram):
        data = program.data
        motion, feed = data.motion, data.feed
        dwell_ops, dwell_s = data.dwell_ops, data.dwell_s
    else:
        motion = np.full(n, LINEAR, dtype=np.uint8)
        feed = np.full(n, np.nan)
        dwell_ops, dwell_s = np.zeros(0, dtype=np.int64), np.zeros(0)
    fed = (motion != RAPID) & (motion != HOME) & (motion != NO_MOTION) & (feed > 0)

    settings = profile.gcode
    if settings is not None and settings.step_interval_us is not None:
        texts = program.data.sent if isinstance(program, GcodeProgram) else []
        seconds = _stepped(
            path, coords, previous, profile, _step_intervals(texts, n, settings.step_interval_us)
        )
        np.add.at(seconds, dwell_ops, dwell_s)
        cumulative = np.cumsum(seconds)
        return Estimate(float(cumulative[-1]), cumulative)
    if settings is not None and settings.junction_deviation is not None:
        stops = np.zeros(n, dtype=bool)
        stops[dwell_ops] = True
        if isinstance(program, GcodeProgram):
            kinds, pen = program.data.kinds, program.data.pen
            # A pen command that changes nothing moves nothing (the board skips it too).
            changes = np.concatenate(([True], pen[1:] != pen[:-1]))
            stops |= (kinds == WAIT) | (np.isin(kinds, (PEN_UP, PEN_DOWN)) & changes)
        seconds = _planned(
            path, coords - previous, np.where(fed, feed / 60.0, np.inf), stops, profile
        )
        np.add.at(seconds, dwell_ops, dwell_s)
        cumulative = np.cumsum(seconds)
        return Estimate(float(cumulative[-1]), cumulative)

    delta = np.abs(coords - previous)
    length = np.sqrt((delta * delta).sum(axis=1))
    moving = length > 0
    # The time each segment needs at its axes' limits gives the speed and acceleration
    # along the path that no axis exceeds.
    with np.errstate(divide="ignore", invalid="ignore"):
        speed_cap = np.where(moving, length / (delta / top_speed).max(axis=1, initial=0.0), np.inf)
        accel_cap = np.where(moving, length / (delta / top_accel).max(axis=1, initial=0.0), np.inf)

    op_length = np.bincount(path.ops, weights=length, minlength=n)
    op_speed = np.full(n, np.inf)
    op_accel = np.full(n, np.inf)
    if len(path.ops):
        first = np.flatnonzero(np.r_[True, path.ops[1:] != path.ops[:-1]])
        op_speed[path.ops[first]] = np.minimum.reduceat(speed_cap, first)
        op_accel[path.ops[first]] = np.minimum.reduceat(accel_cap, first)
    speed = np.where(fed, np.minimum(feed / 60.0, op_speed), op_speed)

    seconds = np.zeros(n)
    go = op_length > 0
    v, a, s = speed[go], op_accel[go], op_length[go]
    reaches = s >= v * v / a
    seconds[go] = np.where(reaches, s / v + v / a, 2.0 * np.sqrt(s / a))
    np.add.at(seconds, dwell_ops, dwell_s)
    cumulative = np.cumsum(seconds)
    return Estimate(float(cumulative[-1]), cumulative)


def _planned(
    path: ProgramPath,
    delta: np.ndarray,
    fed_speed: np.ndarray,
    stops: np.ndarray,
    profile: MachineProfile,
) -> np.ndarray:
    """Seconds per operation with GRBL's planner: each path segment one block.

    ``delta`` is each segment's signed displacement, ``fed_speed`` each
    operation's feed in mm/s (inf for rapids), ``stops`` the operations
    before which the motion stops (pen changes, dwells, pauses).
    """
    settings = profile.gcode
    assert settings is not None and settings.junction_deviation is not None
    n = len(stops)
    columns = range(delta.shape[1])
    length = np.sqrt(sum(delta[:, c] * delta[:, c] for c in columns))
    moving = np.flatnonzero(length > 0)
    seconds = np.zeros(n)
    if not len(moving):
        return seconds
    ops = path.ops[moving]
    lengths = length[moving]
    unit = delta[moving] / lengths[:, None]
    # What the axes allow along each block and across each corner (GRBL: the least of
    # each axis' limit over its share of the direction); columns, as there are two or three.
    rapid, accel = _axis_limited(profile, unit)
    nominal = np.minimum(fed_speed[ops], rapid)
    # The corner before each block (the first has none: it starts from rest).
    before = np.vstack([unit[:1], unit[:-1]])
    cos_theta = -sum(before[:, c] * unit[:, c] for c in columns)
    change = unit - before
    with np.errstate(divide="ignore", invalid="ignore"):
        change /= np.sqrt(sum(change[:, c] * change[:, c] for c in columns))[:, None]
        _, corner_accel = _axis_limited(profile, change)
        sin_half = np.sqrt(np.maximum(0.5 * (1.0 - cos_theta), 0.0))
        junction = corner_accel * settings.junction_deviation * sin_half / (1.0 - sin_half)
    junction = np.where(cos_theta < -0.999999, np.inf, junction)
    junction = np.where(cos_theta > 0.999999, 0.0, junction)
    slower = np.minimum(nominal, np.concatenate(([0.0], nominal[:-1])))
    limit = np.minimum(slower * slower, junction)
    # From rest at the first block and after anything GRBL waits for the motion to end.
    waited = np.cumsum(stops)
    after_stop = np.concatenate(([True], waited[ops[1:]] != waited[ops[:-1]]))
    limit[after_stop] = 0.0
    entries = lookahead_entries(lengths, accel, limit, settings.planner_blocks)
    exits = np.concatenate((entries[1:], [0.0]))
    block_s = profile_seconds(lengths, np.sqrt(entries), np.sqrt(exits), nominal, accel)
    seconds += np.bincount(ops, weights=block_s, minlength=n)
    return seconds


#: ``M98 <µs>`` or ``M98 P<µs>``: the CoreXY plotter's step interval.
_M98 = re.compile(r"^\s*M0*98\s*P?\s*([0-9]*\.?[0-9]+)", re.IGNORECASE)


def _step_intervals(texts: Sequence[str], n: int, power_on_us: float) -> np.ndarray:
    """Each operation's step interval in seconds: the last ``M98`` before it, else power-on."""
    intervals = np.full(n, power_on_us * 1e-6)
    for index, text in enumerate(texts):
        if text and (match := _M98.match(text)) is not None and float(match.group(1)) > 0:
            intervals[index:] = float(match.group(1)) * 1e-6
    return intervals


def _stepped(
    path: ProgramPath,
    coords: np.ndarray,
    previous: np.ndarray,
    profile: MachineProfile,
    intervals: np.ndarray,
) -> np.ndarray:
    """A firmware without ramps that ignores F (FIDELITY S1-01, S1-04): every move, G0 or
    G1, steps its lead motor at the operation's interval from its first step to its last.

    Positions become whole steps by truncation (S1-03), then the CoreXY motors mix them
    (a = x - y, b = x + y), as the firmware counts them.
    """
    per_mm = np.array([axis.steps_per_rev * axis.microsteps / axis.lead for axis in profile.axes])
    steps = np.trunc(coords * per_mm)
    before = np.trunc(previous * per_mm)
    settings = profile.gcode
    if settings is not None and settings.kinematics == "corexy" and steps.shape[1] >= 2:
        for counts in (steps, before):
            x, y = counts[:, 0].copy(), counts[:, 1].copy()
            counts[:, 0], counts[:, 1] = x - y, x + y
    lead = np.abs(steps - before).max(axis=1, initial=0.0)
    seconds = np.zeros(len(intervals))
    np.add.at(seconds, path.ops, lead * intervals[path.ops])
    return seconds


def _axis_limited(profile: MachineProfile, directions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Top speed and acceleration along each direction (unit rows) that no axis exceeds."""
    speed = np.full(len(directions), np.inf)
    accel = np.full(len(directions), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for c, axis in enumerate(profile.axes):
            share = np.abs(directions[:, c])
            speed = np.fmin(speed, axis.max_speed / share)
            accel = np.fmin(accel, axis.max_acceleration / share)
    return speed, accel


def _one_axis_moves(
    program: StringArtProgram, profile: MachineProfile, start: Mapping[str, float]
) -> Estimate:
    """Each move a trapezoid on its one axis at that axis' limits, from the axis' last value.

    A chunk of operations at a time, carrying each axis' last value: numpy's
    passes over 8 million operations at once held the interpreter lock a tenth
    of a second each, and the window (this runs on the loading thread) waited.
    """
    count = len(program)
    seconds = np.zeros(count)
    axes = [
        (WINDER_AXES.index(axis.name), axis) for axis in profile.axes if axis.name in WINDER_AXES
    ]
    last = {column: start.get(axis.name, 0.0) for column, axis in axes}
    for first in range(0, count, ESTIMATE_CHUNK):
        moved = program.move_axis[first : first + ESTIMATE_CHUNK]
        for column, axis in axes:
            ops = np.flatnonzero(moved == column)
            if not len(ops):
                continue
            values = program.move_values[first + ops]
            previous = np.concatenate(([last[column]], values[:-1]))
            last[column] = float(values[-1])
            distance = np.abs(values - previous)
            v, a = axis.max_speed, axis.max_acceleration
            with np.errstate(invalid="ignore"):
                seconds[first + ops] = np.where(
                    distance >= v * v / a, distance / v + v / a, 2.0 * np.sqrt(distance / a)
                )
    seconds[~np.isfinite(seconds)] = 0.0
    seconds[program.dwell_ops] += program.dwell_s  # the drill's 250 ms at each hole's bottom
    cumulative = seconds  # summed in place, a chunk at a time, carrying the total
    total = 0.0
    for first in range(0, count, ESTIMATE_CHUNK):
        piece = cumulative[first : first + ESTIMATE_CHUNK]
        np.cumsum(piece, out=piece)
        piece += total
        total = float(piece[-1])
    return Estimate(float(cumulative[-1]) if len(cumulative) else 0.0, cumulative)
