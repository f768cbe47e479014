"""StepDeck's scripting API: ``import stepdeck; m = stepdeck.connect("xy-stage", emulator=True)``.

A thin top-level package so scripts import one short name; the
implementation lives in :mod:`app.scripting` beside the station it drives,
and nothing here (or there) imports a widget, so it runs with no display.
"""

from __future__ import annotations

from app.scripting import aio
from app.scripting.errors import (
    CheckpointWaiting,
    ConnectionFailed,
    JobAborted,
    JobFailed,
    JobRefused,
    LinkLost,
    MotionFailed,
    MotionRefused,
    MotionTimeout,
    ParameterRefused,
    StepdeckError,
    Unsupported,
    WrongMachine,
)
from app.scripting.job import JobResult, Progress
from app.scripting.machine import AxisStatus, Machine, Status, connect
from app.scripting.parameters import Difference

__all__ = [
    "AxisStatus",
    "CheckpointWaiting",
    "ConnectionFailed",
    "Difference",
    "JobAborted",
    "JobFailed",
    "JobRefused",
    "JobResult",
    "LinkLost",
    "Machine",
    "MotionFailed",
    "MotionRefused",
    "MotionTimeout",
    "ParameterRefused",
    "Progress",
    "Status",
    "StepdeckError",
    "Unsupported",
    "WrongMachine",
    "aio",
    "connect",
]
