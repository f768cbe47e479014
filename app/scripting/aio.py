"""The asyncio form: ``m = await stepdeck.aio.connect(...)``, then ``await m.move_to(X=5)``.

The same operations as the blocking :class:`~app.scripting.machine.Machine`
(one implementation, :mod:`app.scripting.waits`), awaited instead of
blocked on: between two looks at the device the coroutine yields to the
asyncio loop, so other tasks (a camera, a measurement) run while the
machine moves.  Qt still runs in the loop's thread, pumped without blocking,
so the machine must be used from the thread that runs the asyncio loop.
Cancelling a task that waits for a motion stops the machine.
"""

from __future__ import annotations

import asyncio
from collections.abc import Mapping
from pathlib import Path
from typing import Any, TypeVar

from app.profiles import MachineProfile
from app.scripting import settings as stored
from app.scripting.job import run_job
from app.scripting.machine import Machine, Status
from app.scripting.machine import connect as connect_blocking
from app.scripting.pump import SimulatedPump
from app.scripting.waits import Operation
from app.scripting.work import override

T = TypeVar("T")

#: Seconds the loop is given between two pumps in real time.
POLL_S = 0.005


class AsyncMachine:
    """A :class:`Machine` whose waits are awaited; ``.machine`` is the blocking one."""

    def __init__(self, machine: Machine) -> None:
        self.machine = machine

    @property
    def position(self) -> dict[str, float]:
        return self.machine.position

    @property
    def status(self) -> Status:
        return self.machine.status

    async def move_to(
        self,
        target: Mapping[str, float] | None = None,
        *,
        timeout: float | None = None,
        **axes: float,
    ) -> dict[str, float]:
        return await self._drive(
            self.machine.operations.move(dict(target or {}, **axes), False, timeout)
        )

    async def move_by(
        self,
        delta: Mapping[str, float] | None = None,
        *,
        timeout: float | None = None,
        **axes: float,
    ) -> dict[str, float]:
        return await self._drive(
            self.machine.operations.move(dict(delta or {}, **axes), True, timeout)
        )

    async def jog(self, direction: str | Mapping[str, int], seconds: float) -> dict[str, float]:
        return await self._drive(self.machine.operations.jog(direction, seconds))

    async def home(
        self, axis: str | None = None, *, timeout: float | None = None
    ) -> dict[str, float]:
        return await self._drive(self.machine.operations.home(axis, timeout))

    async def stop(self) -> bool:
        return await self._drive(self.machine.operations.stop())

    async def sleep(self, asleep: bool = True, *, timeout: float = 5.0) -> None:
        await self._drive(self.machine.operations.sleep(asleep, timeout))

    async def wake(self, *, timeout: float = 5.0) -> None:
        await self._drive(self.machine.operations.sleep(False, timeout))

    async def read_parameters(self, *, timeout: float = 10.0) -> dict[str, dict[str, float]]:
        return await self._drive(self.machine.operations.read_parameters(timeout))

    async def write_parameters(
        self, values: Mapping[str, Mapping[str, float]], *, timeout: float = 10.0
    ) -> dict[str, dict[str, float]]:
        return await self._drive(self.machine.operations.write_parameters(values, timeout))

    async def read_settings(self, *, timeout: float = 10.0) -> dict[str, float]:
        """The stored settings (GRBL's ``$$``, the usb3 unit's EEPROM), freshly read."""
        return await self._drive(stored.read(self.machine, timeout))

    async def write_settings(
        self, changes: Mapping[str, float], *, timeout: float = 10.0
    ) -> dict[str, float]:
        """As :meth:`MachineSettings.write <app.scripting.settings.MachineSettings.write>`."""
        return await self._drive(stored.write(self.machine, changes, timeout))

    async def override(
        self, *, feed: int | None = None, rapid: int | None = None
    ) -> tuple[int, int]:
        """As :meth:`Machine.override`; awaited beside a running :meth:`run`, it changes the
        speed of the job under way."""
        return await self._drive(override(self.machine, feed, rapid))

    async def run(self, job_path: str | Path, **options: Any) -> Any:
        return await self._drive(run_job(self.machine, Path(job_path), **options))

    def close(self) -> None:
        self.machine.close()

    async def _drive(self, operation: Operation[T]) -> T:
        machine = self.machine
        operations = machine.operations
        clock = machine.station.clock
        pump = operations.pump  # the same station, pumped without blocking
        simulated = isinstance(pump, SimulatedPump)
        try:
            wait = next(operation)
            while True:
                deadline = clock.now() + wait.timeout
                while not wait.until():
                    if clock.now() > deadline:
                        operation.close()
                        raise operations.timed_out(wait)
                    pump.step(block=False)
                    await asyncio.sleep(0 if simulated else POLL_S)
                wait = operation.send(None)
        except StopIteration as stop:
            value: T = stop.value
            return value
        except (asyncio.CancelledError, KeyboardInterrupt):
            operation.close()
            operations.stop_after_interrupt()
            raise


async def connect(profile: str | MachineProfile, **link: Any) -> AsyncMachine:
    """As :func:`stepdeck.connect`; the wait for the device's first answer blocks briefly."""
    return AsyncMachine(connect_blocking(profile, **link))
