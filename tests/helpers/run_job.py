"""A station process that runs one point-list job, for the kill-and-restart test.

    python -m tests.helpers.run_job --link PATH --job FILE --checkpoints DIR

It connects over the serial link in real time (MonotonicClock), loads the
job, resumes from the checkpoint if one is there (the operator's "yes",
given up front) or starts it, and prints one line per event on standard
output, flushed, so the test can follow it and kill it at any point::

    connected
    resume 7          (or: start)
    done 8/24
    DONE

Exit status 0 when the job is done, 1 when it failed, 3 on the time limit.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QTimer

from app.jobs.formats.points.reader import load_point_list
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from app.station import Station


def say(line: str) -> None:
    print(line, flush=True)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--link", required=True)
    parser.add_argument("--job", type=Path, required=True)
    parser.add_argument("--checkpoints", type=Path, required=True)
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--profile", default="xy-stage")
    args = parser.parse_args(argv)

    app = QCoreApplication([])
    profile = load_profile(args.profile)
    station = Station(profile)
    runner = JobRunner(station, args.checkpoints)
    program = load_point_list(args.job)
    status = [3]

    def on_link(state: object) -> None:
        if state is not LinkState.CONNECTED or runner.state is not JobState.IDLE:
            return
        say("connected")
        refused = runner.load(program)
        if refused:
            say(f"refused {refused[0]}")
            status[0] = 1
            app.quit()
        elif runner.resume_available is not None:
            say(f"resume {runner.resume_available}")
            runner.resume_from_checkpoint()
        else:
            say("start")
            runner.start()

    def on_state(state: object) -> None:
        if state is JobState.DONE:
            say("DONE")
            status[0] = 0
            app.quit()
        elif state is JobState.FAILED:
            say("FAILED")
            status[0] = 1
            app.quit()
        elif state is JobState.PAUSED:
            say("paused")
            QTimer.singleShot(200, runner.resume)  # the link came back: carry on

    runner.stateChanged.connect(on_state)
    runner.progressChanged.connect(lambda done, total: say(f"done {done}/{total}"))
    runner.message.connect(lambda text: print(text, file=sys.stderr, flush=True))
    station.model.linkStateChanged.connect(on_link)
    QTimer.singleShot(round(args.timeout * 1000), app.quit)
    station.connect_serial(args.link, profile.link.baud)
    app.exec()
    station.shutdown()
    return status[0]


if __name__ == "__main__":
    sys.exit(main())
