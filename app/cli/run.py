"""``stepdeck run JOB --profile P [--port DEV | --ble [ADDR] | --emulator]``: a job, no window.

For a machine in a lab corner or a headless computer: the job runs through
the scripting API (the same runner, gate and checkpoints as the jobs dock)
with a progress bar and ETA on the terminal, and the job's ``wait:`` prompts
asked there.  Ctrl+C stops the machine and keeps the checkpoint; ``--resume``
carries on from it, ``--restart`` discards it.  ``--from-line N`` starts a
G-code job at line N of its file, ``--from-op N`` any job at its operation N
(see docs/manual/jobs.md, "Starting part-way").

Exit status: 0 done, 2 refused (unreadable job, outside the travel, no
answer from the device, a checkpoint waiting without --resume/--restart),
3 failed or aborted, 130 interrupted (Ctrl+C).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TextIO

from tqdm import tqdm

from app.cli.usage import UsageError, UsageParser
from app.profiles import available_profiles
from app.scripting.errors import (
    CheckpointWaiting,
    ConnectionFailed,
    JobAborted,
    JobFailed,
    JobRefused,
    StepdeckError,
)
from app.scripting.job import Progress
from app.scripting.machine import Machine, connect

DONE, USAGE, REFUSED, FAILED, INTERRUPTED = 0, 1, 2, 3, 130


def build_parser() -> argparse.ArgumentParser:
    parser = UsageParser(
        prog="stepdeck run",
        description="Run a job file on a machine without a window.",
        epilog="Exit status: 0 done, 2 refused, 3 failed or aborted, 130 interrupted (Ctrl+C).",
    )
    parser.add_argument("job", type=Path, metavar="JOB", help="the job file to run")
    parser.add_argument(
        "--profile", required=True, help=f"machine profile ({', '.join(available_profiles())})"
    )
    link = parser.add_mutually_exclusive_group(required=True)
    link.add_argument("--port", metavar="DEVICE", help="the machine's serial port")
    link.add_argument(
        "--ble", nargs="?", const="", metavar="ADDRESS", help="Bluetooth LE (the strongest found)"
    )
    link.add_argument("--emulator", action="store_true", help="the built-in emulator")
    parser.add_argument("--baud", type=int, help="serial baud rate (default: the profile's)")
    parser.add_argument(
        "--simulate",
        action="store_true",
        help="with --emulator: run on a simulated clock, as fast as the computer goes",
    )
    resume = parser.add_mutually_exclusive_group()
    resume.add_argument(
        "--resume", action="store_true", help="carry on an interrupted run from its checkpoint"
    )
    resume.add_argument(
        "--restart", action="store_true", help="discard an interrupted run's checkpoint"
    )
    start = parser.add_mutually_exclusive_group()
    start.add_argument(
        "--from-line",
        type=int,
        metavar="N",
        help="start a G-code job at line N of its file, set up as the file had it there",
    )
    start.add_argument(
        "--from-op",
        type=int,
        metavar="N",
        help="start at operation N (from 1; drill and string-art jobs count operations)",
    )
    parser.add_argument(
        "--checkpoints",
        type=Path,
        metavar="DIR",
        help="checkpoint directory (default: the window's)",
    )
    parser.add_argument(
        "--yes", action="store_true", help="answer every wait: prompt with Enter (unattended)"
    )
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    return parser


class Terminal:
    """The progress bar, the ETA and the operator's prompts on the terminal."""

    def __init__(self, out: TextIO, *, bar: bool, yes: bool) -> None:
        self.out = out
        self.yes = yes
        self._bar: tqdm[None] | None = None
        self._show_bar = bar
        #: How far the job got, for a stop no one at the terminal could answer.
        self._last: Progress | None = None
        self._said: str | None = None

    def progress(self, progress: Progress) -> None:
        self._last = progress
        if not self._show_bar:
            return
        if self._bar is None:
            self._bar = tqdm(total=progress.total, unit="op", file=self.out, dynamic_ncols=True)
        self._bar.n = progress.done
        self._bar.set_postfix_str(f"ETA {_clock(progress.remaining_s)} {progress.state}")

    def say(self, text: str) -> None:
        self._said = text
        if self._bar is not None:
            self._bar.write(text, file=self.out)
        else:
            print(text, file=self.out, flush=True)

    def prompt(self, message: str) -> bool:
        self.say(f"WAIT: {message}")
        if self.yes:
            return True
        try:
            answer = input("Enter when done, 'a' to abort: ")
        except EOFError:
            self.say("no one at the terminal: aborting")
            return False
        return not answer.strip().lower().startswith("a")

    def decide(self, question: str, again: str, done: str) -> bool:
        if question != self._said:  # the job's own message often is the question
            self.say(question)
        try:
            answer = input(f"[a] {again} / [d] {done}: ")
        except EOFError:
            last = self._last
            done_ops, total = (last.done, last.total) if last is not None else (0, 0)
            raise JobAborted("no one at the terminal to decide", done_ops, total) from None
        return not answer.strip().lower().startswith("d")

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def _clock(seconds: float) -> str:
    whole = max(0, round(seconds))
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes:02d}:{secs:02d}"


def main(argv: Sequence[str], out: TextIO | None = None, err: TextIO | None = None) -> int:
    out = out or sys.stdout
    err = err or sys.stderr
    try:
        args = build_parser().parse_args(list(argv))
        if args.simulate and not args.emulator:
            raise UsageError("--simulate runs the built-in emulator only (with --emulator)")
        if args.resume and (args.from_line is not None or args.from_op is not None):
            raise UsageError("--resume goes on from the checkpoint: not with --from-line/--from-op")
    except UsageError as exc:
        print(f"stepdeck run: {exc}", file=err)
        return USAGE
    terminal = Terminal(err, bar=not args.no_progress, yes=args.yes)
    machine: Machine | None = None
    try:
        machine = connect(
            args.profile,
            port=args.port,
            ble=args.ble if args.ble is None else (args.ble or True),
            emulator=args.emulator,
            baud=args.baud,
            simulated=args.simulate,
        )
        resume = True if args.resume else (False if args.restart else None)
        result = machine.run(
            args.job,
            on_progress=terminal.progress,
            on_prompt=terminal.prompt,
            on_decision=terminal.decide,
            on_message=terminal.say,
            resume=resume,
            checkpoint_dir=args.checkpoints,
            from_line=args.from_line,
            from_op=args.from_op,
        )
        terminal.close()
        print(
            f"done: {result.name}, {result.operations} operations in {result.elapsed_s:.1f} s",
            file=out,
        )
        return DONE
    except KeyboardInterrupt:
        terminal.close()
        print(
            "stepdeck run: interrupted; the machine was stopped, the checkpoint kept "
            "(--resume carries on)",
            file=err,
        )
        return INTERRUPTED
    except CheckpointWaiting as exc:
        terminal.close()
        print(
            f"stepdeck run: refused: an interrupted run of {args.job} has {exc.done} of "
            f"{exc.total} operations done; --resume carries on there, --restart starts over",
            file=err,
        )
        return REFUSED
    except (JobRefused, ConnectionFailed) as exc:
        terminal.close()
        print(f"stepdeck run: refused: {exc}", file=err)
        return REFUSED
    except (JobFailed, JobAborted) as exc:
        terminal.close()
        print(f"stepdeck run: stopped after {exc.done} of {exc.total}: {exc}", file=err)
        return FAILED
    except StepdeckError as exc:
        terminal.close()
        print(f"stepdeck run: failed: {exc}", file=err)
        return FAILED
    finally:
        if machine is not None:
            try:
                machine.close()
            except KeyboardInterrupt:
                machine.station.shutdown()
