"""The driver shape of machines that run one operation at a time (stage, usb3, drill).

These machines take one procedure, run it and report it done; nothing else
is sent meanwhile.  The loop is the same for all of them: comments are shown
and counted, a WAIT asks the operator, anything else becomes the operation in
flight until the dialect's replies say it is done.  After a lost link the
operation in flight is *re-examined* (``verify``) before anything is sent:
each dialect says how it finds out whether the machine finished it.
"""

from __future__ import annotations

from abc import ABC, abstractmethod

from app.jobs.program import Operation, OpKind
from app.jobs.run.driver import JobDriver, RunnerPort, unsupported_on
from app.jobs.run.states import CLOCK_RUNS, JobState


class SequentialDriver(JobDriver, ABC):
    def __init__(self, runner: RunnerPort) -> None:
        super().__init__(runner)
        self._in_flight: int | None = None
        self._verify = False  # re-examine the operation in flight before sending it

    @property
    def in_flight(self) -> int | None:
        return self._in_flight

    @property
    def verifying(self) -> bool:
        return self._verify

    def begin(self, index: int, *, verify: bool) -> None:
        program = self.runner.program
        assert program is not None
        self._clear()
        resumes_move = index < len(program) and program[index].kind is OpKind.MOVE
        if verify and resumes_move:
            self._in_flight = index
            self._verify = True

    def proceed(self) -> None:
        runner = self.runner
        program = runner.program
        assert program is not None
        while runner.state is JobState.RUNNING:
            if self._in_flight is not None:
                if self._verify:
                    self._start_verify(self._in_flight)
                else:
                    self._dispatch(self._in_flight)
                return
            if runner.done >= len(program):
                if self.wind_up():
                    runner.finish()
                return
            index = runner.done
            op = program[index]
            runner.announce(index)
            if op.kind is OpKind.COMMENT:
                runner.note(f"{op.source}: {op.message}")
                if not runner.mark_done(index):
                    return
                continue
            self._in_flight = index
            self._dispatch(index)
            return

    def confirmed(self, index: int) -> None:
        self._clear()

    def decided(self, index: int, *, again: bool) -> None:
        if again:
            self._verify = False
            self._in_flight = index
            self.proceed()
        else:
            self._done(index)

    def forget(self) -> None:
        self._clear()

    def link_lost(self) -> None:
        if self._in_flight is not None:
            self._verify = True

    # --- for the dialects -------------------------------------------------------

    def _dispatch(self, index: int) -> None:
        """Send operation ``index`` (it is in flight)."""
        program = self.runner.program
        assert program is not None
        op = program[index]
        if op.kind is OpKind.WAIT:
            self.runner.wait_for_operator(index)
            return
        if self.station.session is None or not self.link_up():
            self.runner.link_pause()
            return
        self._send(index, op)

    @abstractmethod
    def _send(self, index: int, op: Operation) -> None:
        """Put ``op`` on the wire; the dialect's replies later call :meth:`_done`."""

    def _start_verify(self, index: int) -> None:
        """Find out whether the operation in flight was completed; by default send it again."""
        self._verify = False
        self._dispatch(index)

    def _done(self, index: int) -> None:
        """The machine reported operation ``index`` done."""
        self._clear()
        self.runner.complete(index)

    def _judging(self) -> bool:
        """Whether replies may end the operation in flight now."""
        return self._in_flight is not None and self.runner.state in CLOCK_RUNS

    def _unsupported(self, index: int, op: Operation) -> None:
        """Refused at load already; a program changed underneath would still not run."""
        self.runner.fail(index, unsupported_on(op, self.station.profile))

    def _refused_send(self, index: int, what: str) -> None:
        """A session method returned False: the link went, or the machine is locked."""
        if not self.link_up():
            self.runner.link_pause()
        else:
            reason = self.station.model.motion_lock_reason() or what
            self.runner.fail(index, reason)

    def _clear(self) -> None:
        self._in_flight = None
        self._verify = False
