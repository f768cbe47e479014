"""The job's life cycle, shared by the runner and every dialect's driver."""

from __future__ import annotations

import enum


class JobState(enum.Enum):
    IDLE = "idle"  # no program
    READY = "ready"  # loaded, not started
    RUNNING = "running"
    PAUSING = "pausing"  # the current operation finishes, then PAUSED
    PAUSED = "paused"
    WAITING = "waiting"  # for the operator to confirm a WAIT
    DONE = "done"
    ABORTED = "aborted"
    FAILED = "failed"


#: A job that still owns the machine: nothing else may be loaded or started.
ACTIVE = (JobState.RUNNING, JobState.PAUSING, JobState.PAUSED, JobState.WAITING)
#: States in which operations are sent and the job's clock runs.
CLOCK_RUNS = (JobState.RUNNING, JobState.PAUSING)
#: States a job ends in; it can be started (or resumed from its checkpoint) again.
FINISHED = (JobState.DONE, JobState.ABORTED, JobState.FAILED)
