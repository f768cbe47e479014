"""Board registration: where a job's holes really are on a board taped to the bed.

A board is never exactly at the origin or square to the axes.  The operator
jogs the tool over two (or three) reference holes of the job; from the job's
points and the measured machine points this module computes the rigid
transform (rotation + offset) that maps the job onto the board, and the
scale error the measurement shows.  A rigid fit, not an affine one: a board
does not stretch, so a scale far from 1 means a wrong hole was picked or the
jog missed it, which the operator must be told rather than have the job
silently distorted.

Two points determine rotation and offset exactly; a third is averaged in by
a least-squares (Kabsch/Umeyama) fit, and its residual says how well the
points agree.  The bottom side of a double-sided board is handled by
mirroring the job about its own extent before registration.

Everything here is pure: no Qt, no machine; the transformed :class:`Program`
goes through the runner's travel check like any other.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import Any, Literal

import numpy as np

from app.jobs.program import Operation, OpKind, Program

Point = tuple[float, float]

#: Beyond this relative scale error (0.2 %: 0.2 mm over 100 mm) the station warns.
SCALE_TOLERANCE = 0.002
#: Reference points closer than this (mm) say nothing about rotation.
MIN_SPAN_MM = 1.0


class RegistrationError(ValueError):
    """Reference points that cannot register a board (too few, coincident, mismatched)."""


@dataclass(frozen=True)
class Registration:
    """The rigid transform job → machine: rotate by ``angle_rad`` about the origin, then offset.

    ``scale`` is what a similarity fit would have used (measured span over
    job span); it is reported, never applied.  ``residual_mm`` is the largest
    distance between a measured point and where the transform puts its job
    point (0 for two points up to the scale error).
    """

    angle_rad: float
    offset: Point
    scale: float = 1.0
    residual_mm: float = 0.0

    @property
    def angle_deg(self) -> float:
        return math.degrees(self.angle_rad)

    @property
    def scale_error(self) -> float:
        """Relative: +0.001 means the board measured 0.1 % larger than the job."""
        return self.scale - 1.0

    def scale_ok(self, tolerance: float = SCALE_TOLERANCE) -> bool:
        return abs(self.scale_error) <= tolerance

    def warning(self, tolerance: float = SCALE_TOLERANCE) -> str:
        """What the operator must read before drilling, or "" when the points agree."""
        if self.scale_ok(tolerance):
            return ""
        return (
            f"measured scale error {self.scale_error * 100:+.3f} % "
            f"(tolerance ±{tolerance * 100:.3f} %): check the reference holes and the jog"
        )

    def apply(self, x: float, y: float) -> Point:
        c, s = math.cos(self.angle_rad), math.sin(self.angle_rad)
        return (c * x - s * y + self.offset[0], s * x + c * y + self.offset[1])

    def inverse(self, x: float, y: float) -> Point:
        c, s = math.cos(self.angle_rad), math.sin(self.angle_rad)
        dx, dy = x - self.offset[0], y - self.offset[1]
        return (c * dx + s * dy, -s * dx + c * dy)

    def describe(self) -> str:
        return (
            f"rotation {self.angle_deg:+.4f}°, offset X{self.offset[0]:+.3f} "
            f"Y{self.offset[1]:+.3f} mm, scale error {self.scale_error * 100:+.3f} %"
        )


def register(job_points: Sequence[Point], machine_points: Sequence[Point]) -> Registration:
    """The rigid transform that best puts ``job_points`` on ``machine_points`` (2 or 3 pairs).

    Least squares over the pairs (exact for two up to their span): the
    rotation is the angle of the cross-covariance, the offset moves the
    job centroid onto the measured one.
    """
    if len(job_points) != len(machine_points):
        raise RegistrationError(
            f"{len(job_points)} job point(s) but {len(machine_points)} measured point(s)"
        )
    if not 2 <= len(job_points) <= 3:
        raise RegistrationError(f"registration takes 2 or 3 points, not {len(job_points)}")
    job = np.asarray(job_points, dtype=np.float64)
    machine = np.asarray(machine_points, dtype=np.float64)
    if not (np.isfinite(job).all() and np.isfinite(machine).all()):
        raise RegistrationError("a reference point is not a number")
    job_c = job.mean(axis=0)
    machine_c = machine.mean(axis=0)
    a = job - job_c
    b = machine - machine_c
    job_spread = float(np.sqrt((a**2).sum(axis=1)).max()) * 2
    machine_spread = float(np.sqrt((b**2).sum(axis=1)).max()) * 2
    if job_spread < MIN_SPAN_MM or machine_spread < MIN_SPAN_MM:
        raise RegistrationError(
            f"the reference points are closer than {MIN_SPAN_MM:g} mm: pick holes far apart"
        )
    # 2-D Kabsch: maximise sum of b . R(a); the optimal angle is atan2(sum a x b, sum a . b).
    dot = float((a * b).sum())
    cross = float((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum())
    angle = math.atan2(cross, dot)
    scale = math.sqrt(float((b**2).sum()) / float((a**2).sum()))
    c, s = math.cos(angle), math.sin(angle)
    rotated_c = (c * job_c[0] - s * job_c[1], s * job_c[0] + c * job_c[1])
    offset = (float(machine_c[0] - rotated_c[0]), float(machine_c[1] - rotated_c[1]))
    reg = Registration(angle, offset, scale)
    residual = max(
        math.dist(reg.apply(float(x), float(y)), (float(u), float(v)))
        for (x, y), (u, v) in zip(job, machine, strict=True)
    )
    return replace(reg, residual_mm=residual)


def hole_positions(program: Program, axes: tuple[str, str] = ("X", "Y")) -> list[Point]:
    """Where each DRILL happens (X, Y of the MOVE before it), in drilling order.

    The numbering the operator picks reference holes by: the same for the job
    as its file says and for the job mirrored or registered, since those keep
    every operation in its place.
    """
    if OpKind.DRILL not in program.kinds():
        return []  # a 2-million-entry string-art job costs nothing here
    ax, ay = axes
    holes: list[Point] = []
    for index, where, _pen in program.positions():
        after = index + 1
        if after < len(program) and program[after].kind is OpKind.DRILL:
            if ax in where and ay in where:
                holes.append((where[ax], where[ay]))
    return holes


def extent(program: Program, axes: tuple[str, str] = ("X", "Y")) -> tuple[Point, Point]:
    """(min x, min y), (max x, max y) of the program's moves on ``axes``."""
    xs: list[float] = []
    ys: list[float] = []
    ax, ay = axes
    for op in program.operations:
        if op.kind is OpKind.MOVE:
            if ax in op.target:
                xs.append(op.target[ax])
            if ay in op.target:
                ys.append(op.target[ay])
    if not xs or not ys:
        raise RegistrationError(f"the job does not move on {ax} and {ay}")
    return (min(xs), min(ys)), (max(xs), max(ys))


def _mapped(
    program: Program,
    axes: tuple[str, str],
    to: Callable[[float, float], Point],
    note: str,
) -> Program:
    """``program`` with every MOVE's (x, y) passed through ``to`` (both axes written).

    A move that sets only one of the two axes is completed from the last
    known other axis, since a rotation mixes them; before both are known the
    move is kept as is only if it moves neither.
    """
    ax, ay = axes
    where: dict[str, float] = {}
    ops: list[Operation] = []
    for op in program.operations:
        if op.kind is not OpKind.MOVE or (ax not in op.target and ay not in op.target):
            ops.append(op)
            continue
        where.update({k: v for k, v in op.target.items() if k in axes})
        if ax not in where or ay not in where:
            raise RegistrationError(
                f"{op.source}: {op.describe()} sets {ax} or {ay} before both are known"
            )
        x, y = to(where[ax], where[ay])
        target = dict(op.target)
        target[ax], target[ay] = float(x), float(y)
        ops.append(replace(op, target=MappingProxyType(target), line=""))
    return Program(
        program.name,
        tuple(ops),
        program.source,
        notes=(*program.notes, note),
        start_relative=program.start_relative,
    )


def registered(
    program: Program, registration: Registration, axes: tuple[str, str] = ("X", "Y")
) -> Program:
    """The job moved onto the board: every MOVE target through ``registration``."""
    note = f"registered on the board: {registration.describe()}"
    if warning := registration.warning():
        note += f" — warning: {warning}"
    return _mapped(program, axes, registration.apply, note)


def mirrored(
    program: Program,
    about: Literal["X", "Y"],
    axes: tuple[str, str] = ("X", "Y"),
) -> Program:
    """The bottom side: the job mirrored in X (x -> min + max - x) or Y about its own extent.

    Mirroring about the extent keeps the board where it was on the bed, so
    the same alignment pins hold it after the flip.  Mirroring twice gives
    the job back.
    """
    (x0, y0), (x1, y1) = extent(program, axes)
    if about == "X":
        return _mapped(program, axes, lambda x, y: (x0 + x1 - x, y), "mirrored in X (bottom side)")
    return _mapped(program, axes, lambda x, y: (x, y0 + y1 - y), "mirrored in Y (bottom side)")


Side = Literal["", "X", "Y"]


@dataclass(frozen=True)
class Placement:
    """How a job file is put on the board: its side (mirrored for the bottom) and registration.

    What a checkpoint keeps next to the operation count, so that a job
    resumed after a restart, read again from the same file, is moved onto the
    board exactly as it was when it ran (its operations, and so its
    fingerprint, are the same again).
    """

    side: Side = ""
    registration: Registration | None = None

    def __bool__(self) -> bool:
        return bool(self.side) or self.registration is not None

    def apply(self, program: Program) -> Program:
        """``program`` (as its file says) on the chosen side, moved onto the board."""
        placed = mirrored(program, self.side) if self.side else program
        if self.registration is not None:
            placed = registered(placed, self.registration)
        return placed

    def to_record(self) -> dict[str, Any]:
        reg = self.registration
        return {
            "side": self.side,
            "registration": None
            if reg is None
            else {
                "angle_rad": reg.angle_rad,
                "offset": list(reg.offset),
                "scale": reg.scale,
                "residual_mm": reg.residual_mm,
            },
        }

    @classmethod
    def from_record(cls, record: object) -> Placement | None:
        """The placement a checkpoint recorded, or None when the record is not one."""
        if not isinstance(record, dict) or record.get("side") not in ("", "X", "Y"):
            return None
        side: Side = record["side"]
        raw = record.get("registration")
        if raw is None:
            return cls(side)
        try:
            x, y = (float(v) for v in raw["offset"])
            reg = Registration(
                float(raw["angle_rad"]),
                (x, y),
                float(raw["scale"]),
                float(raw["residual_mm"]),
            )
        except (KeyError, TypeError, ValueError):
            return None
        numbers = (reg.angle_rad, x, y, reg.scale, reg.residual_mm)
        if not all(math.isfinite(v) for v in numbers):
            return None
        return cls(side, reg)
