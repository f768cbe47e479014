"""What a script is told when the station or the device says no: exceptions carrying the reason.

The station reports refusals as one-line messages (the status bar's news);
a script gets the same words in an exception, so ``except MotionRefused as
e: print(e)`` shows what the operator would have read.
"""

from __future__ import annotations


class StepdeckError(Exception):
    """Anything the station or the device refused or could not do."""


class ConnectionFailed(StepdeckError):
    """The link did not open, or the device did not answer in its dialect."""


class LinkLost(StepdeckError):
    """The link went while waiting for the device."""


class Unsupported(StepdeckError):
    """This machine cannot do that (absolute moves on the usb3 unit, sleep on a plotter)."""


class MotionRefused(StepdeckError):
    """The motion gate (or the machine's state) refused the motion: nothing was sent."""


class MotionFailed(StepdeckError):
    """The device reported a motion ended short: an end switch, a driver fault, a block."""


class MotionTimeout(StepdeckError):
    """The device did not report the motion done in time; the machine was stopped."""


class ParameterRefused(StepdeckError):
    """A parameter write was refused, by the station (the mechanics) or by the device.

    ``written`` holds the writes of the same call that the device confirmed.
    """

    def __init__(self, message: str, written: dict[str, dict[str, float]] | None = None) -> None:
        super().__init__(message)
        self.written = written or {}


class SettingRefused(StepdeckError):
    """A stored setting (GRBL's ``$N``, the usb3 unit's EEPROM) was not written: refused by
    the station before anything was sent, refused by the device, or read back otherwise.

    ``written`` holds the values of the same call the device read back as written.
    """

    def __init__(self, message: str, written: dict[str, float] | None = None) -> None:
        super().__init__(message)
        self.written = written or {}


class WrongMachine(StepdeckError):
    """A parameter snapshot of another machine (pass ``other_machine=True`` to load it anyway)."""


class JobRefused(StepdeckError):
    """The job was not started: an unreadable file, an operation out of travel, a checkpoint
    waiting for a decision."""


class CheckpointWaiting(JobRefused):
    """An interrupted run of this job left a checkpoint: resume from it or start over."""

    def __init__(self, message: str, done: int, total: int) -> None:
        super().__init__(message)
        self.done = done
        self.total = total


class JobAborted(StepdeckError):
    """The job was stopped before its end; its checkpoint is kept for ``resume=True``."""

    def __init__(self, message: str, done: int, total: int) -> None:
        super().__init__(message)
        self.done = done
        self.total = total


class JobFailed(JobAborted):
    """The job failed (the device refused an operation, the link went for good)."""
