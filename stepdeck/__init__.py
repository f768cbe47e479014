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
    SettingRefused,
    StepdeckError,
    Unsupported,
    WrongMachine,
)
from app.scripting.job import JobResult, Progress
from app.scripting.machine import AxisStatus, Machine, Status, connect
from app.scripting.parameters import Difference
from app.scripting.settings import MachineSettings
from app.scripting.settings_snapshot import SettingDifference

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
    "MachineSettings",
    "MotionFailed",
    "MotionRefused",
    "MotionTimeout",
    "ParameterRefused",
    "Progress",
    "SettingDifference",
    "SettingRefused",
    "Status",
    "StepdeckError",
    "Unsupported",
    "WrongMachine",
    "aio",
    "connect",
]
