"""A running job's jog lock, said again after a language switch.

The lock's reason ("a job is under way — abort it or let it finish") is the
runner's text at the job's start, kept by the machine model; the Manual
page's lock line and the macros dock read it from there, so a switch to
Czech mid-job left it in English until the job ended.
"""

from __future__ import annotations

from app.jobs.run.runner import JobRunner
from app.jobs.run.states import ACTIVE


def retranslate_jog_lock(runner: JobRunner) -> None:
    """The lock ``runner`` holds, in the language now installed (nothing when it holds none)."""
    if runner.state in ACTIVE:
        runner.station.model.set_jog_lock(runner.busy_text())
