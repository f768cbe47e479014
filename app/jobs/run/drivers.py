"""Which job driver runs programs on which dialect."""

from __future__ import annotations

from collections.abc import Callable, Mapping

from app.jobs.run.drill import DrillDriver
from app.jobs.run.driver import JobDriver, RunnerPort
from app.jobs.run.gcode import GcodeDriver
from app.jobs.run.stage import StageDriver
from app.jobs.run.usb3 import Usb3Driver

DriverFactory = Callable[[RunnerPort], JobDriver]

#: Dialect name (a profile's ``dialect``) → its driver.
DRIVERS: Mapping[str, DriverFactory] = {
    "stage": StageDriver,
    "usb3": Usb3Driver,
    "drill": DrillDriver,
    "gcode": GcodeDriver,
}


def driver_for(dialect: str) -> DriverFactory:
    """Every dialect a profile can name has a driver (a test holds the two lists together)."""
    return DRIVERS[dialect]
